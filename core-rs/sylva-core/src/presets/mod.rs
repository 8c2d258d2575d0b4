//! # Named presets
//!
//! Sets of parameter values applied on top of the defaults, so the registry stays the one place
//! that knows ranges and defaults. Each preset writes its values as typed assignments on the
//! stage structs with [`param_values!`](crate::param_values) (`skeleton.shape = CrownShape::Conical`,
//! `skeleton.level[1].length = 0.32`): an unknown id, a field of another stage or a value of the
//! wrong type does not compile. The same values, as wire numbers by id in the order written, are
//! what the presets' JSON and share links carry ([`Preset::all_values`]).
//!
//! | file | holds |
//! |---|---|
//! | `species.rs` | Weber & Penn's four species, with the paper's values |
//! | `shapes.rs` | five trees that illustrate one crown shape each |
//! | `fruit.rs` | two flowering fruit trees, cherry and apple |
//! | `grown.rs` | the space-colonization trees |

mod fruit;
mod grown;
mod shapes;
mod species;

use crate::error::SylvaError;
use crate::params::{ParamValues, TreeParams};

/// A named set of parameter values.
#[derive(Clone, Debug)]
pub struct Preset {
    /// Id used in URLs and the CLI (`--preset`).
    pub name: &'static str,
    /// Display name.
    pub label: &'static str,
    /// One line about the tree.
    pub description: &'static str,
    /// The leaf preset it wears ([`crate::leaf::presets`]): its values come first, the
    /// tree's own values after them.
    pub leaf: &'static str,
    /// The tree's own values (mostly ones that differ from the defaults).
    pub values: ParamValues,
}

/// All presets, the default tree first. The four Weber & Penn species use the paper's values (Weber
/// & Penn 1995, *Creation and Rendering of Realistic Trees*); the next five illustrate one crown
/// shape each; then two flowering fruit trees; the `grown_*` presets use space-colonization
/// growth.
pub const PRESETS: &[Preset] = &[
    DEFAULT,
    species::QUAKING_ASPEN,
    species::BLACK_TUPELO,
    species::WEEPING_WILLOW,
    species::CA_BLACK_OAK,
    shapes::FIR,
    shapes::OAK,
    shapes::CYPRESS,
    shapes::UMBRELLA,
    shapes::WEEPING,
    fruit::CHERRY,
    fruit::APPLE,
    grown::GROWN_BROADLEAF,
    grown::GROWN_SHRUB,
    grown::GROWN_HEDGEROW,
    grown::GROWN_BESIDE_WALL,
    grown::GROWN_BUSHY,
];

/// The default tree: the registry's defaults.
const DEFAULT: Preset = Preset {
    name: "default",
    label: "Default (Cylindrical)",
    description: "Aspen-like broadleaf with the Cylindrical crown, the starting point of Mtree's Crown Shape guide.",
    leaf: "aspen",
    values: ParamValues::NONE,
};

/// Find a preset by name.
pub fn find(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

impl Preset {
    /// The preset's full parameters: the defaults, the leaf preset's values, then the tree's own.
    pub fn params(&self) -> Result<TreeParams, SylvaError> {
        let mut params = TreeParams::default();
        self.leaf_values().apply(&mut params);
        self.values.apply(&mut params);
        params.validate()?;
        Ok(params)
    }

    /// The leaf preset's values, then the tree's own, as wire numbers by id (so a share link or
    /// the panel gets both).
    pub fn all_values(&self) -> Vec<(&'static str, f64)> {
        let mut values = self.leaf_values().wire();
        values.extend(self.values.wire());
        values
    }

    /// The values of the leaf preset it wears (none for an unknown name).
    fn leaf_values(&self) -> ParamValues {
        crate::leaf::presets::find(self.leaf).map_or(ParamValues::NONE, |l| l.values)
    }
}

/// All presets as JSON: `[{name, label, description, leaf, values: {id: number}}]` (the values
/// include the leaf preset's).
pub fn presets_json() -> String {
    let list: Vec<serde_json::Value> = PRESETS
        .iter()
        .map(|p| {
            let values: serde_json::Map<String, serde_json::Value> =
                p.all_values().into_iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect();
            serde_json::json!({"name": p.name, "label": p.label, "description": p.description, "leaf": p.leaf, "values": values})
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}

#[cfg(test)]
mod tests;
