//! The space-colonization presets (Runions, Lane & Prusinkiewicz 2007, *Modeling Trees with a
//! Space Colonization Algorithm*): crown
//! volumes, start points, walls and light competition, and the SCA add-on's bushy reference tree.

use super::Preset;
use crate::param_values;
use crate::params::{BarkType, GrowthMode};

pub(super) const GROWN_BROADLEAF: Preset = Preset {
    name: "grown_broadleaf",
    label: "Grown: Broadleaf",
    description: "Space colonization in an ellipsoid crown: a round broadleaf.",
    leaf: "maple",
    values: param_values! {
        skeleton.maturity = 35.0,
        skeleton.age = 35.0,
        skeleton.growth_mode = GrowthMode::SpaceColonization,
        skeleton.markers = 3000,
        skeleton.crown_base = 2.5,
        skeleton.crown_height = 6.0,
        skeleton.crown_radius = 3.5,
        skeleton.internode = 0.25,
        skeleton.influence_radius = 2.5,
        skeleton.kill_distance = 0.5,
        skeleton.tip_radius = 0.007,
        skeleton.apical_control = 0.2,
        skeleton.marker_surface_bias = 0.3,
    },
};

pub(super) const GROWN_SHRUB: Preset = Preset {
    name: "grown_shrub",
    label: "Grown: Shrub",
    description: "Space colonization from several stems low to the ground: a shrub.",
    leaf: "birch",
    values: param_values! {
        skeleton.maturity = 12.0,
        skeleton.age = 12.0,
        mesh.bark_type = BarkType::SmoothBanded,
        skeleton.growth_mode = GrowthMode::SpaceColonization,
        skeleton.markers = 2500,
        skeleton.crown_base = 0.1,
        skeleton.crown_height = 2.2,
        skeleton.crown_radius = 1.8,
        skeleton.internode = 0.12,
        skeleton.influence_radius = 1.2,
        skeleton.kill_distance = 0.25,
        skeleton.tip_radius = 0.004,
        skeleton.start_points = 3,
        skeleton.start_spacing = 0.25,
        skeleton.tropism = 0.05,
        skeleton.apical_control = 0.1,
        skeleton.marker_top_bias = -0.3,
    },
};

pub(super) const GROWN_HEDGEROW: Preset = Preset {
    name: "grown_hedgerow",
    label: "Grown: Hedgerow",
    description: "Seven trunks in a row sharing one long crown: a hedgerow.",
    leaf: "birch",
    values: param_values! {
        skeleton.maturity = 15.0,
        skeleton.age = 15.0,
        skeleton.growth_mode = GrowthMode::SpaceColonization,
        skeleton.markers = 6000,
        skeleton.start_points = 7,
        skeleton.start_spacing = 1.4,
        skeleton.crown_base = 0.8,
        skeleton.crown_height = 3.0,
        skeleton.crown_radius = 1.6,
        skeleton.internode = 0.15,
        skeleton.influence_radius = 1.5,
        skeleton.kill_distance = 0.3,
        skeleton.tip_radius = 0.004,
        skeleton.apical_control = 0.2,
    },
};

pub(super) const GROWN_BESIDE_WALL: Preset = Preset {
    name: "grown_beside_wall",
    label: "Grown: Beside a Wall",
    description: "A tree 1.5 m from a wall: the wall shades the markers near it and the crown leans away.",
    leaf: "aspen",
    values: param_values! {
        skeleton.maturity = 30.0,
        skeleton.age = 30.0,
        skeleton.growth_mode = GrowthMode::SpaceColonization,
        skeleton.markers = 3000,
        skeleton.wall = true,
        skeleton.wall_distance = 1.5,
        skeleton.wall_height = 7.0,
        skeleton.wall_width = 14.0,
        skeleton.crown_base = 2.0,
        skeleton.crown_height = 6.0,
        skeleton.crown_radius = 4.0,
        skeleton.internode = 0.25,
        skeleton.influence_radius = 2.5,
        skeleton.kill_distance = 0.5,
        skeleton.tip_radius = 0.007,
        skeleton.light_competition = true,
    },
};

pub(super) const GROWN_BUSHY: Preset = Preset {
    name: "grown_bushy",
    label: "Grown: Bushy (reference)",
    description: "The SCA add-on's bushy tree: 400 end points, internode 0.5, kill distance 2.5 internodes, 3,000 extra markers per 1,000 iterations, in the add-on's default crown.",
    leaf: "oak",
    values: param_values! {
        skeleton.maturity = 20.0,
        skeleton.age = 20.0,
        mesh.bark_type = BarkType::SmoothBanded,
        skeleton.growth_mode = GrowthMode::SpaceColonization,
        skeleton.markers = 400,
        skeleton.internode = 0.5,
        // The add-on gives Kill Distance and Influence Range in internode lengths: "reduced to
        // 2.5" is 1.25 m, and its default influence of 15 internodes is 7.5 m.
        skeleton.kill_distance = 1.25,
        skeleton.influence_radius = 7.5,
        skeleton.extra_markers = 3000,
        skeleton.iterations = 1000,
        // The add-on's default crown: Crown Size 5 (an ellipsoid of radius 5) above a 3 m bole.
        skeleton.crown_base = 3.0,
        skeleton.crown_height = 10.0,
        skeleton.crown_radius = 5.0,
        skeleton.tip_radius = 0.01,
        skeleton.apical_control = 0.0,
        skeleton.growth_jitter = 0.05,
        // Three-leaf twigs of larger leaves in loose clumps: the add-on hangs a 0.5-unit leaf on
        // most outer internodes, which reads as a full crown at this scale.
        foliage.leaves = 40,
        foliage.foliage_twigs3 = true,
        foliage.foliage_scale = 0.25,
        foliage.foliage_clumping = 0.5,
    },
};
