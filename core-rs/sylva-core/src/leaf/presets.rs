//! Leaf presets with the Mtree species values (ANCHORS §5; Leaf Generation guide, "Species
//! Presets"): data over the registry's defaults, like the tree presets.

use crate::error::SylvaError;
use crate::params::TreeParams;
use serde::Serialize;

/// A named set of leaf parameter values.
#[derive(Clone, Debug, Serialize)]
pub struct LeafPreset {
    /// Id for the CLI (`sylva leaf --preset`).
    pub name: &'static str,
    /// Display name.
    pub label: &'static str,
    /// One line about the leaf.
    pub description: &'static str,
    /// Values that differ from the defaults, by parameter id (enums by option index).
    pub values: &'static [(&'static str, f64)],
}

impl LeafPreset {
    /// The defaults with this preset's values.
    pub fn params(&self) -> Result<TreeParams, SylvaError> {
        TreeParams::from_values(self.values.iter().copied())
    }
}

/// The five species of the guide.
pub const LEAF_PRESETS: &[LeafPreset] = &[
    LeafPreset {
        name: "oak",
        label: "Oak",
        description: "Wide, seven rounded lobes, dense open venation, moderate curvature.",
        values: &[
            ("leaf_m", 7.0),
            ("leaf_a", 1.0),
            ("leaf_b", 1.0),
            ("leaf_n1", 2.0),
            ("leaf_n2", 4.0),
            ("leaf_n3", 4.0),
            ("leaf_aspect", 0.7),
            ("leaf_margin", 4.0),
            ("leaf_teeth", 7.0),
            ("leaf_tooth_depth", 0.3),
            ("leaf_venation", 1.0),
            ("leaf_vein_density", 1500.0),
            ("leaf_attraction", 0.06),
            ("leaf_kill", 0.02),
            ("leaf_growth_step", 0.01),
            ("leaf_vein_width", 0.018),
            ("leaf_midrib_curvature", 0.15),
            ("leaf_cross_curvature", 0.2),
            ("leaf_edge_curl", 0.05),
        ],
    },
    LeafPreset {
        name: "maple",
        label: "Maple",
        description: "Palmate star with five lobes and closed, net-like fine venation.",
        values: &[
            ("leaf_m", 5.0),
            ("leaf_a", 1.0),
            ("leaf_b", 1.0),
            ("leaf_n1", 1.5),
            ("leaf_n2", 3.0),
            ("leaf_n3", 3.0),
            ("leaf_aspect", 0.95),
            ("leaf_margin", 4.0),
            ("leaf_teeth", 5.0),
            ("leaf_tooth_depth", 0.5),
            ("leaf_venation", 2.0),
            ("leaf_vein_density", 2000.0),
            ("leaf_attraction", 0.06),
            ("leaf_kill", 0.024),
            ("leaf_growth_step", 0.012),
            ("leaf_vein_width", 0.016),
            ("leaf_midrib_curvature", 0.05),
            ("leaf_cross_curvature", 0.1),
            ("leaf_edge_curl", 0.1),
        ],
    },
    LeafPreset {
        name: "birch",
        label: "Birch",
        description: "Elongated oval with small sharp serrate teeth, open venation, gentle curl.",
        values: &[
            ("leaf_m", 2.0),
            ("leaf_a", 1.0),
            ("leaf_b", 0.6),
            ("leaf_n1", 2.5),
            ("leaf_n2", 8.0),
            ("leaf_n3", 8.0),
            ("leaf_aspect", 0.6),
            ("leaf_margin", 1.0),
            ("leaf_teeth", 24.0),
            ("leaf_tooth_depth", 0.05),
            ("leaf_tooth_sharpness", 0.6),
            ("leaf_venation", 1.0),
            ("leaf_vein_density", 900.0),
            ("leaf_vein_width", 0.015),
            ("leaf_midrib_curvature", 0.1),
            ("leaf_cross_curvature", 0.12),
            ("leaf_edge_curl", 0.08),
        ],
    },
    LeafPreset {
        name: "willow",
        label: "Willow",
        description: "Narrow and long with a smooth edge and sparse open venation.",
        values: &[
            ("leaf_m", 2.0),
            ("leaf_a", 1.0),
            ("leaf_b", 0.3),
            ("leaf_n1", 3.0),
            ("leaf_n2", 10.0),
            ("leaf_n3", 10.0),
            ("leaf_aspect", 0.35),
            ("leaf_margin", 0.0),
            ("leaf_venation", 1.0),
            ("leaf_vein_density", 250.0),
            ("leaf_attraction", 0.1),
            ("leaf_kill", 0.025),
            ("leaf_growth_step", 0.012),
            ("leaf_vein_width", 0.012),
            ("leaf_midrib_curvature", 0.25),
            ("leaf_cross_curvature", 0.15),
        ],
    },
    LeafPreset {
        name: "pine",
        label: "Pine needle",
        description: "A needle: tiny width, smooth edge, no veins.",
        values: &[
            ("leaf_m", 2.0),
            ("leaf_a", 1.0),
            ("leaf_b", 0.05),
            ("leaf_n1", 4.0),
            ("leaf_n2", 20.0),
            ("leaf_n3", 20.0),
            ("leaf_aspect", 0.05),
            ("leaf_margin", 0.0),
            ("leaf_venation", 0.0),
            ("leaf_midrib_curvature", 0.05),
            ("leaf_cross_curvature", 0.0),
            ("leaf_rings", 2.0),
        ],
    },
];

/// The preset called `name` (case-insensitive).
pub fn find(name: &str) -> Option<&'static LeafPreset> {
    LEAF_PRESETS.iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

/// The presets as JSON (`[{name, label, description, values: {id: number}}]`).
pub fn presets_json() -> String {
    let list: Vec<serde_json::Value> = LEAF_PRESETS
        .iter()
        .map(|p| {
            let values: serde_json::Map<String, serde_json::Value> =
                p.values.iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect();
            serde_json::json!({"name": p.name, "label": p.label, "description": p.description, "values": values})
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}
