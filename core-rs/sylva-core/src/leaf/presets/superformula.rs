//! The five superformula presets of Mtree's *Leaf Generation Guide* ("Species Presets"), kept
//! as examples of the superformula outline.

use super::LeafPreset;
use crate::param_values;
use crate::params::{LeafMargin, LeafOutline, LeafPhenology, LeafPrimaries, LeafVenation};

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

pub(super) const SUPERFORMULA_OAK: LeafPreset = LeafPreset {
    name: "superformula_oak",
    label: "Superformula: Oak (guide)",
    description:
        "The Leaf Generation guide's Oak: a superformula with m = 7 (a seven-pointed star), dense open venation.",
    values: superformula! {
        foliage.leaf_phenology = LeafPhenology::Oak,
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
};

pub(super) const SUPERFORMULA_MAPLE: LeafPreset = LeafPreset {
    name: "superformula_maple",
    label: "Superformula: Maple (guide)",
    description: "The guide's Maple: a five-pointed superformula star with closed, net-like fine venation.",
    values: superformula! {
        foliage.leaf_phenology = LeafPhenology::Maple,
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
};

pub(super) const SUPERFORMULA_BIRCH: LeafPreset = LeafPreset {
    name: "superformula_birch",
    label: "Superformula: Birch (guide)",
    description: "The guide's Birch: an elongated superformula oval with small serrate teeth, open venation.",
    values: superformula! {
        foliage.leaf_phenology = LeafPhenology::Birch,
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
};

pub(super) const SUPERFORMULA_WILLOW: LeafPreset = LeafPreset {
    name: "superformula_willow",
    label: "Superformula: Willow (guide)",
    description: "The guide's Willow: a narrow superformula with a smooth edge and sparse open venation.",
    values: superformula! {
        foliage.leaf_phenology = LeafPhenology::Willow,
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
};

pub(super) const SUPERFORMULA_PINE: LeafPreset = LeafPreset {
    name: "superformula_pine",
    label: "Superformula: Pine needle (guide)",
    description: "The guide's Pine: a flat superformula needle, tiny width, smooth edge, no veins.",
    values: superformula! {
        foliage.leaf_phenology = LeafPhenology::Conifer,
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
};
