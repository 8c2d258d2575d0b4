//! Gravity bending past the Mature Age: main branches sink as their load grows, and their outer
//! part turns up again. A branch is a cantilever under a load spread along it (its own wood and
//! what it carries); its slope then turns by `1 - (1 - s)³` of the tip's (`s` the fraction of
//! its length), and the tip's angle grows with `L³ / r²` (load ∝ L r², stiffness ∝ r⁴; Alméras
//! & Fournier 2009, *Biomechanical design and long-term stability of trees: morphological and
//! wood traits involved in the balance between weight increase and the gravitropic reaction*).
//! The Droop parameter is the angle, per decade, of a main branch of the tree's median `L³ / r²`
//! (long slender ones sink more, short stout ones less, never more than [`MAX_DROOP`]). The
//! gravitropic reaction turns the last [`UPTURN_FROM`] of the length back up by [`UPTURN`] of
//! the sag, so old limbs sweep down and out with their tips raised. Segments turn, never
//! stretch (the length is kept), about the horizontal axis across the branch; the children ride
//! along, each subtree turned rigidly with its attachment point.

use crate::edits::bend::resampled;
use crate::edits::stems::{carry_children, Children};
use crate::math::{self, rad};
use crate::skeleton::{Points, Skeleton, StemKind};
use glam::Vec3;

/// Largest sag of a branch's tip (degrees).
pub const MAX_DROOP: f32 = 60.0;
/// The fraction of the sag the tip turns back up.
pub const UPTURN: f32 = 0.8;
/// Where along the branch the turn back up starts (fraction of its length).
pub const UPTURN_FROM: f32 = 0.6;

/// The slope change at fraction `s` of a branch whose tip sags by `sag` radians.
fn turn(s: f32, sag: f32) -> f32 {
    let load = 1.0 - (1.0 - s) * (1.0 - s) * (1.0 - s);
    let u = ((s - UPTURN_FROM) / (1.0 - UPTURN_FROM)).clamp(0.0, 1.0);
    sag * (load - UPTURN * u * u * (3.0 - 2.0 * u))
}

/// The main branches (on the trunk or a trunk's split clone): index, `L³ / r²`.
fn main_branches(skeleton: &Skeleton) -> Vec<(usize, f32)> {
    skeleton
        .stems
        .iter()
        .enumerate()
        .filter(|(_, s)| s.level == 1 && s.kind == StemKind::Branch && s.length > 0.0)
        .map(|(i, s)| (i, s.length * s.length * s.length / (s.radius * s.radius).max(1e-8)))
        .collect()
}

/// Sags every main branch by `degrees` (that of a branch of median slenderness; see the module
/// doc).
pub fn droop(skeleton: &mut Skeleton, degrees: f32) {
    if degrees <= 0.0 {
        return;
    }
    let branches = main_branches(skeleton);
    if branches.is_empty() {
        return;
    }
    let mut k: Vec<f32> = branches.iter().map(|&(_, k)| k).collect();
    k.sort_by(f32::total_cmp);
    let median = k[k.len() / 2].max(1e-8);
    let children = Children::of_skeleton(skeleton);
    for &(i, slender) in &branches {
        let sag = rad((degrees * slender / median).min(MAX_DROOP));
        sag_branch(skeleton, &children, i, sag);
    }
}

/// Turns stem `i`'s segments down by [`turn`] and carries its children along.
fn sag_branch(skeleton: &mut Skeleton, children: &Children, i: usize, sag: f32) {
    let old = resampled(&skeleton.stems[i]);
    let dir = (old.tip() - old.base()).normalize_or_zero();
    let across = Vec3::Y.cross(dir);
    if across.length_squared() < 1e-6 {
        return; // Upright: no sideways lever.
    }
    // Turning about `up × dir` by a positive angle takes `dir` downward.
    let axis = across.normalize();
    let segs = old.points.len() - 1;
    let rotation = |s: f32| math::quat_axis_angle(axis, turn(s, sag));
    let mut points = Points::with_capacity(segs + 1);
    let mut p = old.points[0];
    points.push(p);
    for k in 0..segs {
        p += rotation((k as f32 + 0.5) / segs as f32) * (old.points[k + 1] - old.points[k]);
        points.push(p);
    }
    let mut stem = old.clone();
    stem.points = points;
    stem.base_normal = (rotation(0.5 / segs as f32) * old.base_normal).normalize_or(old.base_normal);
    skeleton.stems[i] = stem;
    carry_children(skeleton, children, i, old.length.max(1e-6), &rotation);
}
