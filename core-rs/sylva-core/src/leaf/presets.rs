//! Leaf presets: values over the registry's defaults, typed like the tree presets'
//! ([`param_values!`](crate::param_values)). The species leaves
//! follow the botany of real leaves (Ellis et al. 2009, *Manual of Leaf Architecture*: outline,
//! margin, venation and petiole of the real leaf, see `docs/leaves.md`); the `superformula_*`
//! presets keep the Leaf Generation guide's "Species Presets" (Mtree's values) as examples of the
//! superformula.

use crate::error::SylvaError;
use crate::param_values;
use crate::params::{LeafMargin, LeafOutline, LeafPrimaries, LeafVenation, ParamValues, TreeParams};

/// A named set of leaf parameter values.
#[derive(Clone, Debug)]
pub struct LeafPreset {
    /// Id for the CLI (`sylva leaf --preset`).
    pub name: &'static str,
    /// Display name.
    pub label: &'static str,
    /// One line about the leaf.
    pub description: &'static str,
    /// The leaf's values (mostly ones that differ from the defaults), typed on the stage structs
    /// ([`param_values!`](crate::param_values)).
    pub values: ParamValues,
}

impl LeafPreset {
    /// The defaults with this preset's values.
    pub fn params(&self) -> Result<TreeParams, SylvaError> {
        let mut params = TreeParams::default();
        self.values.apply(&mut params);
        params.validate()?;
        Ok(params)
    }
}

/// The *Leaf Generation Guide*'s superformula settings, reset to the superformula outline without primary veins
/// or petiole (the registry's default leaf is the aspen's).
macro_rules! superformula {
    ($($v:tt)*) => {
        param_values! {
            leaf.leaf_outline = LeafOutline::Superformula,
            leaf.leaf_primary_veins = LeafPrimaries::None,
            foliage.leaf_petiole = 0.0,
            leaf.leaf_petiole_flat = false,
            $($v)*
        }
    };
}

/// The species leaves (`docs/leaves.md`), then the five superformula presets of Mtree's
/// *Leaf Generation Guide* ("Species Presets").
pub const LEAF_PRESETS: &[LeafPreset] = &[
    LeafPreset {
        name: "oak",
        label: "English oak (Quercus robur)",
        description: "Obovate, five rounded lobes per side along the midrib, leaning to the tip, with rounded sinuses over halfway in, one secondary vein per lobe, very short petiole.",
        values: param_values! {
            leaf.leaf_asymmetry_seed = 11,
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.56,
            leaf.leaf_base_shape = 1.5,
            leaf.leaf_tip_shape = 0.7,
            leaf.leaf_lobes = 5,
            leaf.leaf_lobe_depth = 0.6,
            leaf.leaf_lobe_point = 0.0,
            leaf.leaf_margin = LeafMargin::Entire,
            foliage.leaf_petiole = 0.05,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Pinnate,
            leaf.leaf_secondary_angle = 50.0,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 1500.0,
            leaf.leaf_attraction = 0.06,
            leaf.leaf_kill = 0.02,
            leaf.leaf_growth_step = 0.01,
            leaf.leaf_vein_width = 0.018,
            leaf.leaf_midrib_curvature = 0.15,
            leaf.leaf_cross_curvature = 0.2,
            leaf.leaf_edge_curl = 0.05,
        },
    },
    LeafPreset {
        name: "black_oak",
        label: "California black oak (Quercus kelloggii)",
        description: "Deeply cut into three or four pointed, bristle-tipped lobes per side; pinnate veins, one per lobe.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.72,
            leaf.leaf_base_shape = 0.9,
            leaf.leaf_tip_shape = 0.8,
            leaf.leaf_lobes = 3,
            leaf.leaf_lobe_depth = 0.7,
            leaf.leaf_lobe_point = 0.85,
            leaf.leaf_margin = LeafMargin::Dentate,
            leaf.leaf_teeth = 30,
            leaf.leaf_tooth_depth = 0.08,
            foliage.leaf_petiole = 0.15,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Pinnate,
            leaf.leaf_secondary_angle = 55.0,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 1500.0,
            leaf.leaf_attraction = 0.06,
            leaf.leaf_kill = 0.02,
            leaf.leaf_vein_width = 0.018,
            leaf.leaf_midrib_curvature = 0.1,
            leaf.leaf_cross_curvature = 0.15,
        },
    },
    LeafPreset {
        name: "maple",
        label: "Norway maple (Acer platanoides)",
        description: "Palmate: five pointed lobes with a few large teeth, five primary veins from the petiole junction, closed net venation, long petiole.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Palmate,
            leaf.leaf_aspect = 1.2,
            leaf.leaf_lobes = 5,
            leaf.leaf_lobe_depth = 0.5,
            leaf.leaf_lobe_point = 0.9,
            leaf.leaf_lobe_spread = 118.0,
            leaf.leaf_lobe_teeth = 2,
            leaf.leaf_margin = LeafMargin::Entire,
            foliage.leaf_petiole = 0.9,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Palmate,
            leaf.leaf_venation = LeafVenation::Closed,
            leaf.leaf_vein_density = 2000.0,
            leaf.leaf_attraction = 0.06,
            leaf.leaf_kill = 0.024,
            leaf.leaf_growth_step = 0.012,
            leaf.leaf_vein_width = 0.016,
            leaf.leaf_midrib_curvature = 0.05,
            leaf.leaf_cross_curvature = 0.1,
            leaf.leaf_edge_curl = 0.1,
        },
    },
    LeafPreset {
        name: "birch",
        label: "Silver birch (Betula pendula)",
        description: "Triangular-ovate with a drawn-out tip, doubly serrate; straight secondary veins each ending in a large tooth.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.7,
            leaf.leaf_base_shape = 0.35,
            leaf.leaf_tip_shape = 1.5,
            leaf.leaf_lobes = 7,
            leaf.leaf_lobe_depth = 0.1,
            leaf.leaf_lobe_point = 0.7,
            leaf.leaf_margin = LeafMargin::Serrate,
            leaf.leaf_teeth = 64,
            leaf.leaf_tooth_depth = 0.045,
            leaf.leaf_tooth_sharpness = 0.6,
            foliage.leaf_petiole = 0.45,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Pinnate,
            leaf.leaf_secondary_angle = 40.0,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 900.0,
            leaf.leaf_vein_width = 0.015,
            leaf.leaf_midrib_curvature = 0.1,
            leaf.leaf_cross_curvature = 0.12,
            leaf.leaf_edge_curl = 0.08,
        },
    },
    LeafPreset {
        name: "aspen",
        label: "Quaking aspen (Populus tremuloides)",
        description: "Nearly round with a short pointed tip, finely crenate, pinnate veins; a long petiole flattened sideways, which makes the leaf quake.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 1.0,
            leaf.leaf_base_shape = 0.7,
            leaf.leaf_tip_shape = 0.95,
            leaf.leaf_lobes = 0,
            leaf.leaf_margin = LeafMargin::Crenate,
            leaf.leaf_teeth = 44,
            leaf.leaf_tooth_depth = 0.035,
            foliage.leaf_petiole = 0.6,
            leaf.leaf_petiole_flat = true,
            leaf.leaf_primary_veins = LeafPrimaries::Pinnate,
            leaf.leaf_secondaries = 6,
            leaf.leaf_secondary_angle = 45.0,
            leaf.leaf_venation = LeafVenation::Open,
        },
    },
    LeafPreset {
        name: "willow",
        label: "White willow (Salix alba)",
        description: "Lanceolate, about 7:1, finely serrate, pinnate with many secondary veins, short petiole.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.14,
            leaf.leaf_base_shape = 1.0,
            leaf.leaf_tip_shape = 1.4,
            leaf.leaf_lobes = 0,
            leaf.leaf_margin = LeafMargin::Serrate,
            leaf.leaf_teeth = 90,
            leaf.leaf_tooth_depth = 0.06,
            leaf.leaf_tooth_sharpness = 0.5,
            foliage.leaf_petiole = 0.06,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Pinnate,
            leaf.leaf_secondaries = 12,
            leaf.leaf_secondary_angle = 60.0,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 600.0,
            leaf.leaf_attraction = 0.05,
            leaf.leaf_kill = 0.012,
            leaf.leaf_growth_step = 0.008,
            leaf.leaf_vein_width = 0.012,
            leaf.leaf_midrib_curvature = 0.25,
            leaf.leaf_cross_curvature = 0.15,
        },
    },
    LeafPreset {
        name: "tupelo",
        label: "Black tupelo (Nyssa sylvatica)",
        description: "Elliptic to obovate with an entire margin and pinnate veins looping before the edge.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.5,
            leaf.leaf_base_shape = 1.1,
            leaf.leaf_tip_shape = 0.85,
            leaf.leaf_lobes = 0,
            leaf.leaf_margin = LeafMargin::Entire,
            foliage.leaf_petiole = 0.15,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Pinnate,
            leaf.leaf_secondaries = 6,
            leaf.leaf_secondary_angle = 50.0,
            leaf.leaf_venation = LeafVenation::Closed,
            leaf.leaf_vein_density = 1200.0,
            leaf.leaf_kill = 0.02,
            leaf.leaf_attraction = 0.06,
        },
    },
    LeafPreset {
        name: "ginkgo",
        label: "Ginkgo (Ginkgo biloba)",
        description: "A fan notched in the middle, its veins forking again and again in two from the petiole (dichotomous), no midrib.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Palmate,
            leaf.leaf_aspect = 1.35,
            leaf.leaf_lobes = 2,
            leaf.leaf_lobe_depth = 0.25,
            leaf.leaf_lobe_point = 0.0,
            leaf.leaf_lobe_spread = 33.0,
            leaf.leaf_margin = LeafMargin::Crenate,
            leaf.leaf_teeth = 40,
            leaf.leaf_tooth_depth = 0.015,
            foliage.leaf_petiole = 0.8,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::Dichotomous,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 0.0,
            leaf.leaf_kill = 0.009,
            leaf.leaf_growth_step = 0.008,
            leaf.leaf_vein_width = 0.006,
            leaf.leaf_midrib_curvature = 0.05,
            leaf.leaf_cross_curvature = 0.15,
        },
    },
    LeafPreset {
        name: "pine",
        label: "Scots pine (Pinus sylvestris)",
        description: "Needles in fascicles of two from one sheath, each long, narrow and pointed, no veins, 30 fascicles all around a shoot.",
        values: param_values! {
            leaf.leaf_shoot = 30,
            leaf.leaf_shoot_angle = 40.0,
            leaf.leaf_shoot_needle = 0.4,
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.035,
            leaf.leaf_base_shape = 0.15,
            leaf.leaf_tip_shape = 0.6,
            leaf.leaf_lobes = 0,
            leaf.leaf_margin = LeafMargin::Entire,
            leaf.leaf_fascicle = 2,
            foliage.leaf_petiole = 0.0,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::None,
            leaf.leaf_venation = LeafVenation::None,
            leaf.leaf_midrib_curvature = 0.1,
            leaf.leaf_cross_curvature = 0.0,
            leaf.leaf_rings = 2,
        },
    },
    LeafPreset {
        name: "fir",
        label: "Silver fir (Abies alba)",
        description: "Single flat needles with rounded tips, set one by one along the twig and twisted into two flat ranks, 56 to a shoot.",
        values: param_values! {
            leaf.leaf_shoot = 56,
            leaf.leaf_shoot_flat = true,
            leaf.leaf_shoot_angle = 66.0,
            leaf.leaf_shoot_needle = 0.21,
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.09,
            leaf.leaf_base_shape = 0.2,
            leaf.leaf_tip_shape = 0.3,
            leaf.leaf_lobes = 0,
            leaf.leaf_margin = LeafMargin::Entire,
            foliage.leaf_petiole = 0.04,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::None,
            leaf.leaf_venation = LeafVenation::None,
            leaf.leaf_midrib_curvature = 0.05,
            leaf.leaf_cross_curvature = -0.1,
            leaf.leaf_rings = 2,
        },
    },
    LeafPreset {
        name: "cypress",
        label: "Italian cypress (Cupressus sempervirens)",
        description: "Tiny scale leaves pressed flat around thin cord-like branchlets, which stand all around the shoot close to it; the edge of each cord shows the scales.",
        values: param_values! {
            leaf.leaf_outline = LeafOutline::Pinnate,
            leaf.leaf_aspect = 0.1,
            leaf.leaf_base_shape = 0.35,
            leaf.leaf_tip_shape = 0.3,
            leaf.leaf_lobes = 0,
            leaf.leaf_margin = LeafMargin::Crenate,
            leaf.leaf_teeth = 24,
            leaf.leaf_tooth_depth = 0.25,
            foliage.leaf_petiole = 0.02,
            leaf.leaf_petiole_flat = false,
            leaf.leaf_primary_veins = LeafPrimaries::None,
            leaf.leaf_venation = LeafVenation::None,
            leaf.leaf_midrib_curvature = 0.05,
            leaf.leaf_cross_curvature = 0.0,
            leaf.leaf_rings = 2,
            leaf.leaf_shoot = 36,
            leaf.leaf_shoot_angle = 30.0,
            leaf.leaf_shoot_needle = 0.32,
        },
    },
    LeafPreset {
        name: "superformula_oak",
        label: "Superformula: Oak (guide)",
        description: "The Leaf Generation guide's Oak: a superformula with m = 7 (a seven-pointed star), dense open venation.",
        values: superformula! {
            leaf.leaf_m = 7.0,
            leaf.leaf_a = 1.0,
            leaf.leaf_b = 1.0,
            leaf.leaf_n1 = 2.0,
            leaf.leaf_n2 = 4.0,
            leaf.leaf_n3 = 4.0,
            leaf.leaf_aspect = 0.7,
            leaf.leaf_margin = LeafMargin::Lobed,
            leaf.leaf_teeth = 7,
            leaf.leaf_tooth_depth = 0.3,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 1500.0,
            leaf.leaf_attraction = 0.06,
            leaf.leaf_kill = 0.02,
            leaf.leaf_growth_step = 0.01,
            leaf.leaf_vein_width = 0.018,
            leaf.leaf_midrib_curvature = 0.15,
            leaf.leaf_cross_curvature = 0.2,
            leaf.leaf_edge_curl = 0.05,
        },
    },
    LeafPreset {
        name: "superformula_maple",
        label: "Superformula: Maple (guide)",
        description: "The guide's Maple: a five-pointed superformula star with closed, net-like fine venation.",
        values: superformula! {
            leaf.leaf_m = 5.0,
            leaf.leaf_a = 1.0,
            leaf.leaf_b = 1.0,
            leaf.leaf_n1 = 1.5,
            leaf.leaf_n2 = 3.0,
            leaf.leaf_n3 = 3.0,
            leaf.leaf_aspect = 0.95,
            leaf.leaf_margin = LeafMargin::Lobed,
            leaf.leaf_teeth = 5,
            leaf.leaf_tooth_depth = 0.5,
            leaf.leaf_venation = LeafVenation::Closed,
            leaf.leaf_vein_density = 2000.0,
            leaf.leaf_attraction = 0.06,
            leaf.leaf_kill = 0.024,
            leaf.leaf_growth_step = 0.012,
            leaf.leaf_vein_width = 0.016,
            leaf.leaf_midrib_curvature = 0.05,
            leaf.leaf_cross_curvature = 0.1,
            leaf.leaf_edge_curl = 0.1,
        },
    },
    LeafPreset {
        name: "superformula_birch",
        label: "Superformula: Birch (guide)",
        description: "The guide's Birch: an elongated superformula oval with small serrate teeth, open venation.",
        values: superformula! {
            leaf.leaf_m = 2.0,
            leaf.leaf_a = 1.0,
            leaf.leaf_b = 0.6,
            leaf.leaf_n1 = 2.5,
            leaf.leaf_n2 = 8.0,
            leaf.leaf_n3 = 8.0,
            leaf.leaf_aspect = 0.6,
            leaf.leaf_margin = LeafMargin::Serrate,
            leaf.leaf_teeth = 24,
            leaf.leaf_tooth_depth = 0.05,
            leaf.leaf_tooth_sharpness = 0.6,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 900.0,
            leaf.leaf_vein_width = 0.015,
            leaf.leaf_midrib_curvature = 0.1,
            leaf.leaf_cross_curvature = 0.12,
            leaf.leaf_edge_curl = 0.08,
        },
    },
    LeafPreset {
        name: "superformula_willow",
        label: "Superformula: Willow (guide)",
        description: "The guide's Willow: a narrow superformula with a smooth edge and sparse open venation.",
        values: superformula! {
            leaf.leaf_m = 2.0,
            leaf.leaf_a = 1.0,
            leaf.leaf_b = 0.3,
            leaf.leaf_n1 = 3.0,
            leaf.leaf_n2 = 10.0,
            leaf.leaf_n3 = 10.0,
            leaf.leaf_aspect = 0.35,
            leaf.leaf_margin = LeafMargin::Entire,
            leaf.leaf_venation = LeafVenation::Open,
            leaf.leaf_vein_density = 250.0,
            leaf.leaf_attraction = 0.1,
            leaf.leaf_kill = 0.025,
            leaf.leaf_growth_step = 0.012,
            leaf.leaf_vein_width = 0.012,
            leaf.leaf_midrib_curvature = 0.25,
            leaf.leaf_cross_curvature = 0.15,
        },
    },
    LeafPreset {
        name: "superformula_pine",
        label: "Superformula: Pine needle (guide)",
        description: "The guide's Pine: a flat superformula needle, tiny width, smooth edge, no veins.",
        values: superformula! {
            leaf.leaf_m = 2.0,
            leaf.leaf_a = 1.0,
            leaf.leaf_b = 0.05,
            leaf.leaf_n1 = 4.0,
            leaf.leaf_n2 = 20.0,
            leaf.leaf_n3 = 20.0,
            leaf.leaf_aspect = 0.05,
            leaf.leaf_margin = LeafMargin::Entire,
            leaf.leaf_venation = LeafVenation::None,
            leaf.leaf_midrib_curvature = 0.05,
            leaf.leaf_cross_curvature = 0.0,
            leaf.leaf_rings = 2,
        },
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
                p.values.wire().into_iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect();
            serde_json::json!({"name": p.name, "label": p.label, "description": p.description, "values": values})
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}
