//! The growth animation of a tree past its Mature Age: the years of life after it
//! ([`crate::life`]: thickening, shedding, drooping) played too.
//!
//! The tree as built keeps the record of its life ([`Skeleton::life`]), which gives its stems in
//! any year from the Mature Age on ([`LifeRecord::at`]), stem for stem the same as built: the
//! branches shed by the Age are stubs in every one of them (the animation has no wood for a
//! branch the tree as built has lost). A vertex placed on its stem as built ([`Place`]) is
//! carried to the same distance along the same stem in that year: its ring centre moves with
//! the (sinking) stem, its offset turns with the stem's direction there (the shortest turn from
//! one tangent to the other) and scales with the radius (thinner in earlier years). The years
//! before the Mature Age are the growth replay ([`YearShape`]) on the stems at the Mature Age,
//! each vertex first carried there. A hand-edited tree (whose stems no longer match its
//! record) keeps its form as built past the Mature Age.

use super::life::Lives;
use super::morph::{Place, YearShape};
use crate::skeleton::LifeRecord;
use crate::skeleton::Skeleton;
use glam::{Quat, Vec3};

/// Added to both radii of a vertex's offset scale (m), as in [`super::morph`].
const RADIUS_EPS: f32 = 1e-4;

/// A tree past its Mature Age with the record of its life.
pub struct Aged<'a> {
    built: &'a Skeleton,
    record: &'a LifeRecord,
    /// The stems at the Mature Age (as the record gives them, stem for stem as built).
    pub mature: Skeleton,
}

impl<'a> Aged<'a> {
    /// `built`'s life, when it has one and its stems still match it (no hand edit added,
    /// removed or moved a stem).
    pub fn new(built: &'a Skeleton) -> Option<Aged<'a>> {
        let record = built.life.as_deref()?;
        let mature = record.at(record.years.0);
        let same = mature.stems.len() == built.stems.len()
            && mature
                .stems
                .iter()
                .zip(&built.stems)
                .all(|(m, b)| m.parent == b.parent && m.kind == b.kind && m.level == b.level);
        same.then_some(Aged { built, record, mature })
    }

    /// The stems in `year` (Mature Age to Age).
    pub fn stems_in(&self, year: f32) -> Skeleton {
        self.record.at(year)
    }

    /// `place` (on the tree as built) carried onto `to` (the same stems in another year), and
    /// the turn that took its stem's direction there.
    pub fn carry(&self, to: &Skeleton, place: &Place) -> (Place, Quat) {
        let i = place.stem as usize;
        let (from, onto) = (&self.built.stems[i], &to.stems[i]);
        let along = place.along.min(onto.length);
        let (tb, to_t) = (place.along / from.length.max(1e-6), along / onto.length.max(1e-6));
        let (_, a) = from.sample(tb.clamp(0.0, 1.0));
        let (centre, b) = onto.sample(to_t.clamp(0.0, 1.0));
        let turn = match (a.try_normalize(), b.try_normalize()) {
            (Some(a), Some(b)) => Quat::from_rotation_arc(a, b),
            _ => Quat::IDENTITY,
        };
        let radius = onto.radius_at(to_t).max(0.0);
        let k = (radius + RADIUS_EPS) / (place.radius + RADIUS_EPS);
        (Place { stem: place.stem, along, centre, offset: turn * place.offset * k, radius }, turn)
    }
}

/// Where the vertex at `place` is in `year`: before the Mature Age by the growth replay on
/// the mature stems (`shape`, with `at_mature` the place carried there), from it on on
/// `stems`, that year's stems.
pub fn bark_at(aged: &Aged<'_>, year: Year<'_>, place: &Place, at_mature: &Place) -> Vec3 {
    match year {
        Year::Young(shape) => shape.bark(at_mature),
        Year::Old(stems) => {
            let (p, _) = aged.carry(stems, place);
            p.centre + p.offset
        }
    }
}

/// One key year of an aged tree's animation.
#[derive(Clone, Copy)]
pub enum Year<'a> {
    /// Before the Mature Age: the growth replay on the mature stems.
    Young(&'a YearShape<'a>),
    /// From the Mature Age on: that year's stems.
    Old(&'a Skeleton),
}

/// The baked leaves' target in `year`: leaf `k` (vertices `per_leaf` at a time in
/// `positions`) hangs at `places[k]` (carried to the Mature Age: `at_mature[k]`) and moves with
/// its twig, turned as the twig turns; before the Mature Age a leaf whose twig has not yet
/// grown to it shrinks to the point the twig has reached.
pub fn leaves_at(
    aged: &Aged<'_>,
    year: Year<'_>,
    positions: &[f32],
    per_leaf: usize,
    places: &[Place],
    at_mature: &[(Place, Quat)],
) -> Vec<f32> {
    let mut out = vec![0.0; positions.len()];
    for (k, place) in places.iter().enumerate() {
        let anchor = place.centre + place.offset;
        // `None`: the leaf is not there yet and collapses onto `to`.
        let (to, turn) = match year {
            Year::Young(shape) => {
                let (m, turn) = &at_mature[k];
                match shape.leaf(m) {
                    Some(q) => (q, None),
                    None => (m.centre + m.offset, Some(*turn)),
                }
            }
            Year::Old(stems) => {
                let (p, turn) = aged.carry(stems, place);
                (p.centre + p.offset, Some(turn))
            }
        };
        let r = 3 * k * per_leaf..3 * (k + 1) * per_leaf;
        for (d, p) in out[r.clone()].chunks_exact_mut(3).zip(positions[r].chunks_exact(3)) {
            let v = Vec3::from_slice(p);
            let q = turn.map_or(to, |t| to + t * (v - anchor));
            d.copy_from_slice(&(q - v).to_array());
        }
    }
    out
}

/// The lives of the mature stems: every stem at its full form at the Mature Age.
pub fn mature_lives(aged: &Aged<'_>) -> Lives {
    let m = aged.record.years.0;
    Lives::new(&aged.mature, m, m)
}
