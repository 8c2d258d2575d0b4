//! Cutting a stem at a fraction of its length: the stem keeps its centre curve and radius
//! profile up to the cut (resampled, so the stump ends with the radius it had there, not with a
//! tip) and is marked [`Stem::cut_end`](crate::skeleton::Stem::cut_end), which the mesh stage
//! closes with a cut face; every child attached beyond the cut (its footprint reaching past it)
//! goes, with all its descendants, and so with their leaves. A cut so near a branch's base that
//! the stump would sit inside its parent removes the whole branch. A cut made years before the
//! tree's Age (a dated cut, [`crate::params::Cut::year`]) carries woundwood: [`Stem::callus`]
//! ([`callus`]), which the mesh stage rolls over the face.
//!
//! [`Stem::callus`]: crate::skeleton::Stem::callus

use super::stems::{remove, subtree, transform, Children};
use crate::skeleton::{Points, Skeleton};
use glam::Quat;

/// A child whose base lies within this many of its radii of the cut goes too: its footprint on
/// the stump (about a radius over the sine of its angle) would reach past the cut face.
pub const FOOTPRINT: f32 = 3.0;
/// Fewest segments a stump's centre polyline gets.
const MIN_SEGMENTS: usize = 4;

/// Woundwood closing over a cut (m a year, from the bark rim inward): a vigorous tree's callus
/// closes a wound by about 1–2 cm of its width a year, from both sides (Neely 1988, *Closure of
/// branch pruning wounds*), so about 1 cm of radius.
pub const CALLUS_RATE: f32 = 0.01;

/// How far woundwood has closed over a cut of radius `radius` (m) `years` after it was made, as
/// a fraction of the radius.
pub fn callus(years: f32, radius: f32) -> f32 {
    (CALLUS_RATE * years.max(0.0) / radius.max(1e-3)).min(1.0)
}

/// What a cut takes away, decided on one skeleton and applicable to another with the same
/// stems (the same tree thinner, in an earlier year: [`crate::skeleton::LifeRecord::at`]).
#[derive(Clone, Debug)]
pub struct CutPlan {
    /// The stump would sit inside its parent: the whole branch goes.
    whole: bool,
    /// The children (with their descendants) that go.
    gone: Vec<bool>,
}

/// What cutting stem `i` at fraction `t` of its length takes away (see the module doc).
pub fn plan(skeleton: &Skeleton, i: usize, t: f32) -> CutPlan {
    let s = &skeleton.stems[i];
    let along = t.clamp(0.0, 1.0) * s.length;
    let n = skeleton.stems.len();
    if s.parent.is_some() && along < 2.0 * s.radius {
        return CutPlan { whole: true, gone: Vec::new() };
    }
    // Children whose footprint reaches past the cut go, with their descendants.
    let mut gone = vec![false; n];
    for c in i + 1..n {
        let child = &skeleton.stems[c];
        match child.parent {
            Some(p) if p as usize == i => gone[c] = child.offset + FOOTPRINT * child.radius > along,
            Some(p) => gone[c] = gone[p as usize],
            None => {}
        }
    }
    CutPlan { whole: false, gone }
}

/// Cut stem `i` at fraction `t` of its length, `years` ago (0: a fresh cut; older cuts carry
/// woundwood, [`callus`]).
pub fn cut(skeleton: &mut Skeleton, i: usize, t: f32, years: f32) {
    let plan = plan(skeleton, i, t);
    cut_by(skeleton, i, t, years, &plan);
}

/// [`cut`] by a plan made on this skeleton or on one with the same stems.
pub fn cut_by(skeleton: &mut Skeleton, i: usize, t: f32, years: f32, plan: &CutPlan) {
    if plan.whole {
        remove(skeleton, &subtree(skeleton, i));
        return;
    }
    let t = t.clamp(0.0, 1.0);
    let along = t * skeleton.stems[i].length;
    let old = skeleton.stems[i].clone();
    let segs = (old.points.len() - 1).max(MIN_SEGMENTS) * if old.flare > 0.0 { 4 } else { 1 };
    let mut cursor = old.points();
    let points: Points = (0..=segs).map(|k| cursor.at(t * k as f32 / segs as f32)).collect();
    let radii: Vec<f32> = (0..=segs).map(|k| old.radius_at(t * k as f32 / segs as f32)).collect();
    let stem = &mut skeleton.stems[i];
    stem.points = points;
    stem.radii = Some(radii);
    stem.length = along.max(1e-3);
    stem.cut_end = true;
    stem.callus = callus(years, stem.radius_at(1.0));
    // The kept children sit on the resampled curve exactly (it differs from the old one by
    // rounding between the samples).
    reattach_children(skeleton, &Children::of_skeleton(skeleton), i, &plan.gone);
    remove(skeleton, &plan.gone);
}

/// Moves each kept child of stem `i` (with its subtree) so that its base lies on `i`'s curve at
/// its offset. `children` is the skeleton's [`Children`] index.
pub(crate) fn reattach_children(skeleton: &mut Skeleton, children: &Children, i: usize, gone: &[bool]) {
    let mut moved = Vec::new();
    for &c in children.of(i) {
        let c = c as usize;
        if gone.get(c) == Some(&true) {
            continue;
        }
        let (on, _) = skeleton.stems[i].point_at(skeleton.stems[c].offset);
        let base = skeleton.stems[c].base();
        if on != base {
            children.subtree(c, &mut moved);
            transform(skeleton, &moved, Quat::IDENTITY, base, on);
        }
    }
}
