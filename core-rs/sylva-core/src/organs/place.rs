//! Where the parts hang: on the shoots that carry the leaves (every stem of the last level of a
//! Weber & Penn tree, every grown shoot), a **Fruit Load** fraction of them bearing one
//! cluster each, between halfway and near the tip (blossom on [`BLOSSOM`] times as many: the
//! fruiting shoots and more); catkins at the tips; a bud at every tip.
//!
//! Each shoot draws the same random numbers (stream `"organs"`) whatever the month, so a part
//! stays where it is from bud to fruit: the cherries hang where the blossom was. A hanging
//! part (fruit, catkins, pine cones) points down within a cone of its own spread, on a stalk;
//! blossom looks out sideways, nodding (cherry) or lifted (apple); a fir's cones stand upright
//! on the top of its upper branches; a bud continues its shoot.

use super::calendar::{Part, Show};
use super::meshes;
use super::set::{OrganKind, OrganSet};
use crate::math;
use crate::params::{FoliageParams, Fruit, GrowthMode};
use crate::rng::Rng;
use crate::skeleton::Skeleton;
use glam::Vec3;

/// Random numbers per shoot: bearing, place along it, cluster size, then [`PER`] per member.
const HEAD: usize = 3;
/// Random numbers per member of a cluster: azimuth, tilt, spin, size, fall (and hue).
const PER: usize = 5;
/// The largest cluster.
const MEMBERS: usize = 5;
const DRAWS: usize = HEAD + PER * MEMBERS;
/// Shoots in flower, as a multiple of the Fruit Load: most blossom never sets fruit.
const BLOSSOM: f32 = 2.5;
/// Blossom clusters along a flowering shoot.
const CLUSTERS: usize = 4;
/// The turn (of a whole) from one blossom cluster's place and numbers to the next's.
const GOLDEN_TURN: f32 = 0.618_034;

/// One shoot that may bear: the stem and its random numbers.
struct Shoot {
    stem: usize,
    dice: [f32; DRAWS],
}

/// How a part hangs: cluster sizes, spread, stalk, size variation.
struct Habit {
    /// Members of a cluster: `min + ⌊d · extra⌋`.
    members: (usize, usize),
    /// Angle from straight down (degrees) of the part's axis: `from + d · spread`.
    tilt: (f32, f32),
    /// Stalk length (m; 0: none).
    stalk: f32,
    /// Where along the shoot the cluster sits: `from + d · span`.
    along: (f32, f32),
}

fn habit(part: Part) -> Habit {
    let h = |members, tilt, stalk, along| Habit { members, tilt, stalk, along };
    match part {
        Part::CherryBlossom => h((2, 3), (70.0, 60.0), 0.025, (0.5, 0.45)),
        Part::AppleBlossom => h((4, 3), (95.0, 60.0), 0.015, (0.5, 0.45)),
        Part::BirchCatkin | Part::AspenCatkin => h((1, 3), (0.0, 25.0), 0.0, (0.97, 0.0)),
        Part::WillowCatkin => h((1, 2), (10.0, 50.0), 0.0, (0.6, 0.35)),
        Part::Bud => h((1, 1), (0.0, 0.0), 0.0, (1.0, 0.0)),
        Part::Fruit(Fruit::Cherries) => h((1, 3), (0.0, 35.0), 0.035, (0.5, 0.45)),
        Part::Fruit(Fruit::Apples) => h((1, 2), (0.0, 25.0), 0.02, (0.5, 0.45)),
        Part::Fruit(Fruit::Acorns) => h((1, 2), (0.0, 40.0), 0.015, (0.6, 0.35)),
        Part::Fruit(Fruit::Samaras) => h((2, 3), (0.0, 30.0), 0.03, (0.5, 0.45)),
        Part::Fruit(Fruit::HangingCones) => h((1, 2), (0.0, 20.0), 0.0, (0.7, 0.25)),
        Part::Fruit(_) => h((1, 2), (180.0, 12.0), 0.0, (0.4, 0.5)),
    }
}

/// Name, colour (sRGB) and roughness of the `kind` set of `part` showing `show`.
fn look(part: Part, kind: OrganKind, show: &Show) -> (&'static str, [f32; 3], f32) {
    let c = show.color[0];
    let yellow = [0.95, 0.82, 0.36];
    let green_stalk = [0.42, 0.52, 0.22];
    let woody = [0.45, 0.37, 0.22];
    match (part, kind) {
        (Part::CherryBlossom, OrganKind::Petals) => ("cherry blossom petals", c, 0.6),
        (Part::CherryBlossom, OrganKind::FlowerCentre) => ("cherry blossom centres", yellow, 0.8),
        (Part::CherryBlossom, _) => ("cherry blossom stalks", green_stalk, 0.8),
        (Part::AppleBlossom, OrganKind::Petals) => ("apple blossom petals", c, 0.6),
        (Part::AppleBlossom, OrganKind::FlowerCentre) => ("apple blossom centres", yellow, 0.8),
        (Part::AppleBlossom, _) => ("apple blossom stalks", green_stalk, 0.8),
        (Part::BirchCatkin, _) => ("birch catkins", c, 0.9),
        (Part::AspenCatkin, _) => ("aspen catkins", c, 0.95),
        (Part::WillowCatkin, _) => ("willow catkins", c, 0.9),
        (Part::Bud, _) => ("buds", c, 0.7),
        (Part::Fruit(Fruit::Cherries), OrganKind::Fruit) => ("cherries", c, 0.3),
        (Part::Fruit(Fruit::Cherries), _) => ("cherry stalks", green_stalk, 0.8),
        (Part::Fruit(Fruit::Apples), OrganKind::Fruit) => ("apples", c, 0.45),
        (Part::Fruit(Fruit::Apples), _) => ("apple stalks", woody, 0.8),
        (Part::Fruit(Fruit::Acorns), OrganKind::Fruit) => ("acorns", c, 0.5),
        (Part::Fruit(Fruit::Acorns), OrganKind::FruitPart) => ("acorn cups", [0.55, 0.47, 0.32], 0.95),
        (Part::Fruit(Fruit::Acorns), _) => ("acorn stalks", woody, 0.8),
        (Part::Fruit(Fruit::Samaras), OrganKind::Fruit) => ("samara seeds", c.map(|v| v * 0.8), 0.8),
        (Part::Fruit(Fruit::Samaras), OrganKind::FruitPart) => ("samara wings", c, 0.7),
        (Part::Fruit(Fruit::Samaras), _) => ("samara stalks", woody, 0.8),
        (Part::Fruit(Fruit::HangingCones), _) => ("pine cones", c, 0.9),
        (Part::Fruit(_), _) => ("fir cones", c, 0.9),
    }
}

/// sRGB to linear light.
fn linear(c: f32) -> f32 {
    if c <= 0.040_45 {
        c / 12.92
    } else {
        math::pow((c + 0.055) / 1.055, 2.4)
    }
}

/// The shoots that carry leaves, as [`crate::foliage`] finds them.
fn shoots(skeleton: &Skeleton) -> Vec<usize> {
    let stems = &skeleton.stems;
    let last = stems.iter().map(|s| s.level).max().unwrap_or(0);
    let grown = skeleton.mode == GrowthMode::SpaceColonization;
    stems
        .iter()
        .enumerate()
        .filter(|(_, s)| s.points.len() >= 2 && s.length > 0.0 && !s.cut_end)
        .filter(|(_, s)| if grown { s.level > 0 } else { s.level == last })
        .map(|(i, _)| i)
        .collect()
}

/// A right-handed frame whose `y` is `dir`, turned `spin` (0..1 of a turn) about it.
fn frame(dir: Vec3, spin: f32) -> [Vec3; 3] {
    let helper = if dir.y.abs() < 0.9 { Vec3::Y } else { Vec3::X };
    let x0 = helper.cross(dir).normalize();
    let z0 = x0.cross(dir);
    let a = std::f32::consts::TAU * spin;
    let (s, c) = (math::sin(a), math::cos(a));
    let x = x0 * c + z0 * s;
    [x, dir, x.cross(dir)]
}

/// Column-major 4×4 of `basis` scaled by `scale` at `origin`.
fn push(matrices: &mut Vec<f32>, basis: &[Vec3; 3], scale: Vec3, origin: Vec3) {
    for (axis, s) in basis.iter().zip(scale.to_array()) {
        matrices.extend_from_slice(&[axis.x * s, axis.y * s, axis.z * s, 0.0]);
    }
    matrices.extend_from_slice(&[origin.x, origin.y, origin.z, 1.0]);
}

/// The parts of `skeleton` at the Season of `p` (none when **Flowers & Fruit** is off or the
/// month shows none).
pub fn place(skeleton: &Skeleton, p: &FoliageParams) -> Vec<OrganSet> {
    let shows = if p.organs { super::calendar::shows(p.leaf_phenology, p.fruit, p.season) } else { Vec::new() };
    if shows.is_empty() || p.leaves == 0 {
        return Vec::new();
    }
    let mut rng = Rng::new(u64::from(skeleton.seed), "organs");
    let list: Vec<Shoot> = shoots(skeleton)
        .into_iter()
        .map(|stem| {
            let mut dice = [0.0; DRAWS];
            dice.iter_mut().for_each(|d| *d = rng.next_f32());
            Shoot { stem, dice }
        })
        .collect();
    let top = list.iter().map(|s| tip(skeleton, s.stem).y).fold(0.0f32, f32::max);
    let mut sets = Vec::new();
    for show in &shows {
        let part = show.part;
        let kinds = part.kinds();
        let mut out: Vec<OrganSet> = kinds
            .iter()
            .map(|&kind| {
                let (name, color, roughness) = look(part, kind, show);
                let mesh = (*meshes::mesh(part, kind)).clone();
                OrganSet { kind, name, mesh, color, roughness, matrices: Vec::new(), colors: Vec::new() }
            })
            .collect();
        let base = show.color[0].map(linear);
        let hab = habit(part);
        let upright = part == Part::Fruit(Fruit::UprightCones);
        for shoot in &list {
            let d = &shoot.dice;
            let bears = if part == Part::Bud {
                true
            } else if upright {
                d[0] < 1.5 * p.fruit_load && tip(skeleton, shoot.stem).y > 0.7 * top
            } else if part.is_blossom() {
                // A tree in flower is white all over: most shoots blossom, a few set fruit.
                d[0] < (BLOSSOM * p.fruit_load).min(1.0)
            } else {
                d[0] < p.fruit_load
            };
            if !bears {
                continue;
            }
            let stem = &skeleton.stems[shoot.stem];
            let n = (hab.members.0 + (d[2] * hab.members.1 as f32) as usize).min(MEMBERS);
            // Blossom comes in clusters all along the shoot's spurs; the first is where the
            // fruit hangs later.
            let clusters = if part.is_blossom() { CLUSTERS } else { 1 };
            for j in 0..clusters {
                let turn = j as f32 * GOLDEN_TURN;
                let u = if j == 0 { d[1] } else { (d[1] + turn).fract() };
                let (pos, tangent) = stem.points().sample(hab.along.0 + hab.along.1 * u);
                for k in 0..n {
                    let m = &d[HEAD + PER * k..HEAD + PER * k + PER];
                    if m[4] < show.present {
                        let m = [(m[0] + turn).fract(), m[1], (m[2] + turn).fract(), m[3], m[4]];
                        hang(&mut out, (part, show, &hab), (pos, tangent), &m, base);
                    }
                }
            }
        }
        sets.extend(out.into_iter().filter(|s| !s.matrices.is_empty()));
    }
    sets
}

/// Adds one part hanging at `pos` on a shoot running along `tangent` to every set of `out`,
/// by its random numbers `m` (azimuth, tilt, spin, size, fall); `base`: the show's first
/// colour in linear light, which the sets' tints are relative to.
fn hang(
    out: &mut [OrganSet],
    (part, show, hab): (Part, &Show, &Habit),
    (pos, tangent): (Vec3, Vec3),
    m: &[f32; PER],
    base: [f32; 3],
) {
    let dir = if part == Part::Bud {
        tangent
    } else {
        let tilt = math::rad(hab.tilt.0 + hab.tilt.1 * m[1]);
        let az = std::f32::consts::TAU * m[0];
        let (st, ct) = (math::sin(tilt), math::cos(tilt));
        Vec3::new(st * math::cos(az), -ct, st * math::sin(az))
    };
    let basis = frame(dir, m[2]);
    let hue = (m[4] * 7.31).fract();
    let c = [0, 1, 2].map(|i| show.color[0][i] + (show.color[1][i] - show.color[0][i]) * hue);
    let bright = 0.9 + 0.2 * m[3];
    let tint = [0, 1, 2].map(|i| bright * linear(c[i]) / base[i].max(1e-4));
    let size = show.size * (0.85 + 0.3 * m[3]);
    let at = pos + dir * hab.stalk;
    for set in out {
        if set.kind == OrganKind::Stalk {
            push(&mut set.matrices, &basis, Vec3::new(1.0, hab.stalk, 1.0), pos);
            set.colors.extend_from_slice(&[bright; 3]);
            continue;
        }
        // A closed flower is narrow: its petals gather about the axis.
        let across = if set.kind == OrganKind::Petals { size * (0.35 + 0.65 * show.open) } else { size };
        push(&mut set.matrices, &basis, Vec3::new(across, size, across), at);
        let own = set.kind == OrganKind::FlowerCentre
            || set.kind == OrganKind::FruitPart && part == Part::Fruit(Fruit::Acorns);
        set.colors.extend_from_slice(&if own { [bright; 3] } else { tint });
    }
}

/// The tip of stem `i`.
fn tip(skeleton: &Skeleton, i: usize) -> Vec3 {
    *skeleton.stems[i].points.last().expect("a shoot has points")
}
