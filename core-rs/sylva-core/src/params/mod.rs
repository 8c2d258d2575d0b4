//! # Parameters: the one source of truth
//!
//! Every parameter is declared once (id, type, default, range, step, unit, group, label, first
//! stage, description); the web panel, share links, preset files, validation, the CLI's `--set`
//! and `docs/parameters.md` all come from that declaration.
//!
//! | file | holds |
//! |---|---|
//! | `registry.rs` | the table: one entry per parameter |
//! | `macros.rs` | `define_params!` (the table → [`TreeParams`], the specs) and `param_enum!` |
//! | `enums.rs` | the enum parameters ([`CrownShape`], [`GrowthMode`], the leaf's options, ...) |
//! | `volumes.rs` | the growth volume primitives, structured data beside the table |
//! | `edits.rs` | the hand edit list (paint, crown, cut, bend), structured data beside the table |
//! | `spec.rs` | what the registry says of one parameter ([`ParamSpec`]) and the pipeline [`Stage`]s |
//! | `stages.rs` | [`TreeParams`]: one struct per stage ([`SkeletonParams`], ...), the flat get / set by id |
//! | `values.rs` | [`param_values!`](crate::param_values): a preset's values as typed assignments ([`ParamValues`]) |
//!
//! ## Wire values
//!
//! Every value is a number on the wire: floats and ints as themselves, booleans as 0/1, enums as
//! their option index. Per-level parameters (Weber & Penn's `nLength`, ...) get ids `l{n}_{name}`
//! (e.g. `l1_length`) and live in `TreeParams::skeleton.level[n]`.

use crate::error::SylvaError;
use std::collections::BTreeMap;
use std::sync::OnceLock;

pub mod edits;
mod enums;
mod macros;
mod registry;
mod spec;
mod stages;
pub mod values;
pub mod volumes;

pub use edits::{Bend, Crown, Cut, Edit, Paint};
pub use enums::{
    BarkType, CrownShape, CrownVolumeKind, Fruit, GrowthMode, LeafLod, LeafMargin, LeafOutline, LeafPhenology,
    LeafPrimaries, LeafVenation, TwigDetail,
};
pub use registry::{FoliageParams, LeafParams, LevelParams, MeshParams, SkeletonParams, ViewerParams};
pub use spec::{ParamKind, ParamSpec, ParamValue, Stage, GROUPS};
pub use stages::TreeParams;
pub use values::{ParamValues, Written};
pub use volumes::{Primitive, VolumeGroup, VolumePrimitive};

/// Lower-case ASCII letters and digits only: enum labels compare without case or separators.
#[doc(hidden)]
pub fn norm(s: &str) -> String {
    s.chars().filter(|c| c.is_ascii_alphanumeric()).collect::<String>().to_ascii_lowercase()
}

/// `l{n}_{name}` as `(n, name)` for a per-level id.
fn split_level_id(id: &str) -> Option<(usize, &str)> {
    let rest = id.strip_prefix('l')?;
    let (n, name) = rest.split_once('_')?;
    let n: usize = n.parse().ok()?;
    (n < 4).then_some((n, name))
}

static REGISTRY: OnceLock<Vec<ParamSpec>> = OnceLock::new();

/// All parameters in panel order. Built once from the table (`params/registry.rs`).
pub fn registry() -> &'static [ParamSpec] {
    REGISTRY.get_or_init(registry::build_registry)
}

/// The spec of parameter `id`.
pub fn spec(id: &str) -> Option<&'static ParamSpec> {
    registry().iter().find(|s| s.id == id)
}

/// The registry as JSON (what `registry_json()` in wasm and `sylva params` print).
pub fn registry_json() -> String {
    serde_json::to_string(registry()).expect("registry serialises")
}

impl TreeParams {
    /// Set parameter `id` to the wire value `v` after checking it against its spec.
    ///
    /// ```
    /// use sylva_core::TreeParams;
    ///
    /// let mut params = TreeParams::default();
    /// params.set("l1_branches", 40.0)?;
    /// assert_eq!(params.get("l1_branches"), Some(40.0));
    /// // Out of range: the message names the field and the allowed range.
    /// let error = params.set("l1_length", 3.0).unwrap_err();
    /// assert_eq!(error.to_string(), "l1_length (Length) is 3: allowed range is 0 to 2");
    /// # Ok::<(), sylva_core::SylvaError>(())
    /// ```
    pub fn set(&mut self, id: &str, v: f64) -> Result<(), SylvaError> {
        let spec = spec(id).ok_or_else(|| unknown(id))?;
        spec.check(v)?;
        self.set_unchecked(id, v);
        Ok(())
    }

    /// Defaults overridden by `values` (wire numbers by id). Unknown ids and invalid values are errors.
    pub fn from_values<'a>(values: impl IntoIterator<Item = (&'a str, f64)>) -> Result<TreeParams, SylvaError> {
        let mut p = TreeParams::default();
        for (id, v) in values {
            p.set(id, v)?;
        }
        Ok(p)
    }

    /// Parse a JSON object `{"id": number, ...}`; booleans are accepted as 0/1.
    pub fn from_json(json: &str) -> Result<TreeParams, SylvaError> {
        if json.len() > edits::MAX_JSON_BYTES {
            return Err(edits::too_long("the parameters' text", json.len()));
        }
        let map: BTreeMap<String, serde_json::Value> = serde_json::from_str(json)
            .map_err(|e| SylvaError::Input { message: format!("parameters must be a JSON object of numbers: {e}") })?;
        let mut p = TreeParams::default();
        for (id, value) in &map {
            if id == "volumes" {
                p.skeleton.volumes = volumes::from_json_value(value)?;
                continue;
            }
            if id == "edits" {
                p.skeleton.edits = edits::from_json_value(value)?;
                continue;
            }
            let v = match value {
                serde_json::Value::Number(n) => n.as_f64().unwrap_or(f64::NAN),
                serde_json::Value::Bool(b) => f64::from(u8::from(*b)),
                _ => {
                    let spec = spec(id).ok_or_else(|| unknown(id))?;
                    return Err(SylvaError::InvalidParam {
                        param: id.clone(),
                        message: format!("{} ({}) must be a number, got {}", id, spec.label, value),
                    });
                }
            };
            p.set(id, v)?;
        }
        Ok(p)
    }

    /// Check every field (fields are public, so a struct built in code is checked here too).
    pub fn validate(&self) -> Result<(), SylvaError> {
        for spec in registry() {
            let v = self.get(&spec.id).expect("every registry id is gettable");
            spec.check(v)?;
        }
        volumes::validate(&self.skeleton.volumes)?;
        edits::validate(&self.skeleton.edits)
    }

    /// The values that differ from the defaults, by id in registry order. Compared by their
    /// bits, as the stage structs compare (so `-0` where the default is `0` is listed, and
    /// [`TreeParams::from_values`] of the list rebuilds equal parameters).
    pub fn non_defaults(&self) -> Vec<(&'static str, f64)> {
        registry()
            .iter()
            .filter_map(|s| {
                let v = self.get(&s.id)?;
                (v.to_bits() != s.default.to_bits()).then_some((s.id.as_str(), v))
            })
            .collect()
    }

    /// The crown shape as an enum.
    pub fn crown(&self) -> CrownShape {
        self.skeleton.shape
    }
}

fn unknown(id: &str) -> SylvaError {
    let shown: String = id.chars().take(64).collect();
    SylvaError::UnknownParam {
        param: shown.clone(),
        message: format!("unknown parameter '{shown}' (see `sylva params`)"),
    }
}

#[cfg(test)]
mod tests;
