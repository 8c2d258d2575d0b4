//! The space-colonization presets (Runions, Lane & Prusinkiewicz 2007, *Modeling Trees with a
//! Space Colonization Algorithm*): crown
//! volumes, start points, walls and light competition, and the SCA add-on's bushy reference tree.

use super::Preset;

pub(super) const GROWN_BROADLEAF: Preset = Preset {
    name: "grown_broadleaf",
    label: "Grown: Broadleaf",
    description: "Space colonization in an ellipsoid crown: a round broadleaf.",
    leaf: "maple",
    values: &[
        ("growth_mode", 1.0),
        ("markers", 3000.0),
        ("crown_base", 2.5),
        ("crown_height", 6.0),
        ("crown_radius", 3.5),
        ("internode", 0.25),
        ("influence_radius", 2.5),
        ("kill_distance", 0.5),
        ("tip_radius", 0.007),
        ("apical_control", 0.2),
        ("marker_surface_bias", 0.3),
    ],
};

pub(super) const GROWN_SHRUB: Preset = Preset {
    name: "grown_shrub",
    label: "Grown: Shrub",
    description: "Space colonization from several stems low to the ground: a shrub.",
    leaf: "birch",
    values: &[
        ("bark_type", 2.0),
        ("growth_mode", 1.0),
        ("markers", 2500.0),
        ("crown_base", 0.1),
        ("crown_height", 2.2),
        ("crown_radius", 1.8),
        ("internode", 0.12),
        ("influence_radius", 1.2),
        ("kill_distance", 0.25),
        ("tip_radius", 0.004),
        ("start_points", 3.0),
        ("start_spacing", 0.25),
        ("tropism", 0.05),
        ("apical_control", 0.1),
        ("marker_top_bias", -0.3),
    ],
};

pub(super) const GROWN_HEDGEROW: Preset = Preset {
    name: "grown_hedgerow",
    label: "Grown: Hedgerow",
    description: "Seven trunks in a row sharing one long crown: a hedgerow.",
    leaf: "birch",
    values: &[
        ("growth_mode", 1.0),
        ("markers", 6000.0),
        ("start_points", 7.0),
        ("start_spacing", 1.4),
        ("crown_base", 0.8),
        ("crown_height", 3.0),
        ("crown_radius", 1.6),
        ("internode", 0.15),
        ("influence_radius", 1.5),
        ("kill_distance", 0.3),
        ("tip_radius", 0.004),
        ("apical_control", 0.2),
    ],
};

pub(super) const GROWN_BESIDE_WALL: Preset = Preset {
    name: "grown_beside_wall",
    label: "Grown: Beside a Wall",
    description: "A tree 1.5 m from a wall: the wall shades the markers near it and the crown leans away.",
    leaf: "aspen",
    values: &[
        ("growth_mode", 1.0),
        ("markers", 3000.0),
        ("wall", 1.0),
        ("wall_distance", 1.5),
        ("wall_height", 7.0),
        ("wall_width", 14.0),
        ("crown_base", 2.0),
        ("crown_height", 6.0),
        ("crown_radius", 4.0),
        ("internode", 0.25),
        ("influence_radius", 2.5),
        ("kill_distance", 0.5),
        ("tip_radius", 0.007),
        ("light_competition", 1.0),
    ],
};

pub(super) const GROWN_BUSHY: Preset = Preset {
    name: "grown_bushy",
    label: "Grown: Bushy (reference)",
    description: "The SCA add-on's bushy tree: 400 end points, internode 0.5, kill distance 2.5 internodes, 3,000 extra markers per 1,000 iterations, in the add-on's default crown.",
    leaf: "oak",
    values: &[
        ("bark_type", 2.0),
        ("growth_mode", 1.0),
        ("markers", 400.0),
        ("internode", 0.5),
        // The add-on gives Kill Distance and Influence Range in internode lengths: "reduced to
        // 2.5" is 1.25 m, and its default influence of 15 internodes is 7.5 m.
        ("kill_distance", 1.25),
        ("influence_radius", 7.5),
        ("extra_markers", 3000.0),
        ("iterations", 1000.0),
        // The add-on's default crown: Crown Size 5 (an ellipsoid of radius 5) above a 3 m bole.
        ("crown_base", 3.0),
        ("crown_height", 10.0),
        ("crown_radius", 5.0),
        ("tip_radius", 0.01),
        ("apical_control", 0.0),
        ("growth_jitter", 0.05),
        // Three-leaf twigs of larger leaves in loose clumps: the add-on hangs a 0.5-unit leaf on
        // most outer internodes, which reads as a full crown at this scale.
        ("leaves", 40.0),
        ("foliage_twigs3", 1.0),
        ("foliage_scale", 0.25),
        ("foliage_clumping", 0.5),
    ],
};
