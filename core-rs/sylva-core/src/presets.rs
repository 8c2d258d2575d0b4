//! Named presets: sets of non-default parameter values. A preset is data, applied on top of the
//! defaults, so the registry stays the one place that knows ranges and defaults.

use crate::error::SylvaError;
use crate::params::TreeParams;
use serde::Serialize;

/// A named set of parameter values.
#[derive(Clone, Debug, Serialize)]
pub struct Preset {
    /// Id used in URLs and the CLI (`--preset`).
    pub name: &'static str,
    /// Display name.
    pub label: &'static str,
    /// One line about the tree.
    pub description: &'static str,
    /// Values that differ from the defaults, by parameter id.
    pub values: &'static [(&'static str, f64)],
}

/// All presets, the default tree first.
pub const PRESETS: &[Preset] = &[Preset {
    name: "default",
    label: "Default (Cylindrical)",
    description: "An aspen-like broadleaf with the Cylindrical crown: the starting point of the guide.",
    values: &[],
}];

/// Find a preset by name.
pub fn find(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

impl Preset {
    /// The preset's full parameters (defaults + its values).
    pub fn params(&self) -> Result<TreeParams, SylvaError> {
        TreeParams::from_values(self.values.iter().copied())
    }
}

/// All presets as JSON: `[{name, label, description, values: {id: number}}]`.
pub fn presets_json() -> String {
    let list: Vec<serde_json::Value> = PRESETS
        .iter()
        .map(|p| {
            let values: serde_json::Map<String, serde_json::Value> =
                p.values.iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect();
            serde_json::json!({"name": p.name, "label": p.label, "description": p.description, "values": values})
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}
