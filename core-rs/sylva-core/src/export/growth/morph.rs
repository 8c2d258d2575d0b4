//! Where each vertex of a generated tree was in an earlier year: the morph targets of the growth
//! animation.
//!
//! **Bark.** Each bark vertex is placed on its stem from its wind record (`TreeMesh::wind`):
//! the pivot and level name the stem (its base point, [`crate::mesh::tube::stem_winds`]), the
//! distance from the root less the stem's base distance is how far along the stem its ring
//! lies. That gives the vertex's ring centre on the stem's centre curve and its radial offset
//! from it. In year `Y` a vertex whose place the young stem has reached keeps its centre (grown
//! wood never moves) with its offset scaled to the young radius there over the radius as
//! built; a vertex past the young tip goes to the tip, at the young tip's radius; a vertex of a
//! stem not there yet goes to the point where the stem will grow from (on the nearest ancestor
//! that is there, at most at its tip; the trunk's base for the trunk before year 0's first
//! shoot).
//!
//! **Leaves** (baked, one copy of the leaf mesh per leaf): a leaf whose twig has grown past the
//! place it hangs at stays; otherwise all its vertices go to the point its twig has grown to
//! (or would grow from), so the leaf is drawn at zero size there.

use super::life::{Lives, Young};
use crate::mesh::tube::stem_winds;
use crate::mesh::{TreeMesh, WIND_DISTANCE, WIND_STRIDE};
use crate::skeleton::Skeleton;
use glam::Vec3;
use std::collections::BTreeMap;

/// Added to both radii of the scale a vertex's offset takes (m): the ratio of two vanishing
/// radii at a stem's closing tip is 1, not whatever their roundings make it.
const RADIUS_EPS: f32 = 1e-4;

/// A vertex's place on its stem as built.
#[derive(Clone, Copy, Debug)]
pub struct Place {
    /// Stem index.
    pub stem: u32,
    /// Distance from the stem's base along it (m).
    pub along: f32,
    /// The ring centre on the stem's centre curve.
    pub centre: Vec3,
    /// The vertex less its centre.
    pub offset: Vec3,
    /// The stem's radius there as built (m).
    pub radius: f32,
}

/// Finds stems by the pivot and level of a wind record.
pub struct StemIndex<'a> {
    skeleton: &'a Skeleton,
    /// Stems by the bits of their base point and level, with their base distance from the root.
    by_key: BTreeMap<[u32; 4], Vec<(u32, f32)>>,
}

impl<'a> StemIndex<'a> {
    /// The index of `skeleton`'s stems.
    pub fn new(skeleton: &'a Skeleton) -> StemIndex<'a> {
        let mut by_key: BTreeMap<[u32; 4], Vec<(u32, f32)>> = BTreeMap::new();
        for (i, w) in stem_winds(skeleton, skeleton.seed).iter().enumerate() {
            by_key.entry(key(&w.pivot.to_array(), w.level)).or_default().push((i as u32, w.distance));
        }
        StemIndex { skeleton, by_key }
    }

    /// The place of point `p` with wind record `w` (8 values): the stem the record names (of
    /// several with the same base and level, the one whose centre passes nearest), stem 0 at
    /// its base when none does.
    pub fn place(&self, p: Vec3, w: &[f32]) -> Place {
        let stems = &self.skeleton.stems;
        let on = |i: u32, base: f32| {
            let s = &stems[i as usize];
            let along = (w[WIND_DISTANCE] - base).clamp(0.0, s.length);
            let t = along / s.length.max(1e-6);
            let centre = s.point(t);
            Place { stem: i, along, centre, offset: p - centre, radius: s.radius_at(t).max(0.0) }
        };
        match self.by_key.get(&key(&w[..3], w[3])).map(Vec::as_slice) {
            Some([(i, base)]) => on(*i, *base),
            Some(list) if !list.is_empty() => list
                .iter()
                .map(|&(i, base)| on(i, base))
                .min_by(|a, b| a.offset.length_squared().total_cmp(&b.offset.length_squared()))
                .expect("a stem"),
            _ => on(0, 0.0),
        }
    }
}

/// The bits of a pivot and level.
fn key(pivot: &[f32], level: f32) -> [u32; 4] {
    [pivot[0].to_bits(), pivot[1].to_bits(), pivot[2].to_bits(), level.to_bits()]
}

/// The places of the bark's vertices (the mesh must carry wind data).
pub fn bark_places(mesh: &TreeMesh, index: &StemIndex<'_>) -> Vec<Place> {
    mesh.positions
        .chunks_exact(3)
        .zip(mesh.wind.chunks_exact(WIND_STRIDE))
        .map(|(p, w)| index.place(Vec3::from_slice(p), w))
        .collect()
}

/// The tree in one year, as the morphs need it: each stem's young state, its tip and radius
/// there, and, for a stem not there, where it will grow from.
pub struct YearShape<'a> {
    skeleton: &'a Skeleton,
    lives: &'a Lives,
    young: Vec<Option<Young>>,
    /// Per stem: its young tip (present) or where it will grow from (absent).
    ends: Vec<Vec3>,
    /// Per present stem: its radius at its young tip.
    tip_radius: Vec<f32>,
}

impl<'a> YearShape<'a> {
    /// The tree of `skeleton` (with `lives`) in year `year`.
    pub fn new(skeleton: &'a Skeleton, lives: &'a Lives, year: f32) -> YearShape<'a> {
        let young = lives.year(skeleton, year);
        let stems = &skeleton.stems;
        let mut ends: Vec<Vec3> = Vec::with_capacity(stems.len());
        let mut tip_radius = vec![0.0; stems.len()];
        for (i, s) in stems.iter().enumerate() {
            let end = match (young[i], s.parent) {
                (Some(y), _) => {
                    tip_radius[i] = lives.radius(i, s, &y, y.length);
                    s.point(y.length / s.length.max(1e-6))
                }
                (None, Some(p)) => match young[p as usize] {
                    Some(py) => {
                        let parent = &stems[p as usize];
                        parent.point(s.offset.min(py.length) / parent.length.max(1e-6))
                    }
                    None => ends[p as usize],
                },
                (None, None) => s.base(),
            };
            ends.push(end);
        }
        YearShape { skeleton, lives, young, ends, tip_radius }
    }

    /// Where a vertex at `place` is in this year.
    pub fn bark(&self, place: &Place) -> Vec3 {
        let i = place.stem as usize;
        let Some(y) = self.young[i] else { return self.ends[i] };
        if place.along <= y.length {
            let s = &self.skeleton.stems[i];
            // Where both radii vanish (a closing tip) the offset stays.
            let r = self.lives.radius(i, s, &y, place.along);
            let k = ((r + RADIUS_EPS) / (place.radius + RADIUS_EPS)).clamp(0.0, 1.0);
            place.centre + place.offset * k
        } else {
            let k = (self.tip_radius[i] / place.offset.length().max(1e-6)).clamp(0.0, 1.0);
            self.ends[i] + place.offset * k
        }
    }

    /// Where the vertices of a leaf hanging at `place` go in this year: `None` when the leaf
    /// is there (its twig has grown past it), else the point they all go to.
    pub fn leaf(&self, place: &Place) -> Option<Vec3> {
        let i = place.stem as usize;
        match self.young[i] {
            Some(y) if place.along <= y.length + 1e-4 => None,
            _ => Some(self.ends[i]),
        }
    }

    /// How many stems are there this year.
    pub fn stems(&self) -> usize {
        self.young.iter().filter(|y| y.is_some()).count()
    }
}

/// The bark's morph target for `year`: each vertex's position then less its position as
/// built (3 floats per vertex).
pub fn bark_target(mesh: &TreeMesh, places: &[Place], year: &YearShape<'_>) -> Vec<f32> {
    let mut out = Vec::with_capacity(places.len() * 3);
    for (p, place) in mesh.positions.chunks_exact(3).zip(places) {
        let d = year.bark(place) - Vec3::from_slice(p);
        out.extend_from_slice(&d.to_array());
    }
    out
}

/// The baked leaves' morph target for `year`: `per_leaf` vertices per leaf, leaf `k` hanging
/// at `places[k]`.
pub fn leaf_target(positions: &[f32], per_leaf: usize, places: &[Place], year: &YearShape<'_>) -> Vec<f32> {
    let mut out = vec![0.0; positions.len()];
    for (k, place) in places.iter().enumerate() {
        if let Some(q) = year.leaf(place) {
            let r = 3 * k * per_leaf..3 * (k + 1) * per_leaf;
            for (d, p) in out[r.clone()].chunks_exact_mut(3).zip(positions[r].chunks_exact(3)) {
                d.copy_from_slice(&(q - Vec3::from_slice(p)).to_array());
            }
        }
    }
    out
}
