//! Paint growth: a stroke scatters markers in the tube of its brush radius ([`markers`]) and the
//! tree grows toward them by space colonization **from its existing stems** (Runions, Lane &
//! Prusinkiewicz 2007, *Modeling Trees with a Space Colonization Algorithm*; [`colonize`]), with
//! the stroke's own internode (`segment`) and kill distance, so a bushy section and a sparse one
//! can sit in the same tree. The new nodes become new stems ([`shoots`]) that sprout from the
//! nearest existing stems, inserted before the roots.
//!
//! * **Nodes**: points every `segment` (arc length) along every stem of the tree but the roots,
//!   Weber & Penn twigs included, on the stems' centre curves, so a new stem starts exactly on
//!   its parent. Every sampled node may sprout, except where the stem is thinner than 1 mm (the
//!   tapered tips of Weber & Penn twigs): a shoot is never thicker than its parent there.
//! * **Influence distance**: [`INFLUENCE_SEGMENTS`] internodes (and always one internode more
//!   than the kill distance), as the SCA add-on's Influence Range is a multiple of its branch
//!   length: a marker further than that from every node waits until growth comes near.
//! * **Caps**: [`MAX_MARKERS`] markers per stroke, its tube's volume times its density, and
//!   [`MAX_CANDIDATES`] candidates drawn (more is an error naming the stroke's `density`); [`iteration_cap`] iterations per brush point; the vertex budget (`max_vertices`,
//!   estimated with [`crate::skeleton::min_vertices`] for the tree's stems and the new ones).
//! * **Levels, bark and leaves**: a new stem's level is its parent's plus one, capped at the
//!   deepest level the tree has, so a shoot off the finest twigs is a finest twig itself: the
//!   foliage stage hangs leaves on it (Weber & Penn: leaves on the deepest level; grown trees:
//!   on every branch's last internodes) and the mesh sweeps it with the tree's bark. Radii follow
//!   the pipe model with Δ = [`PIPE_POWER`] from the tree's thinnest tip radius (at least 1 mm),
//!   never thicker than the parent where the shoot sprouts.
//!
//! **Incremental rule.** The stroke grows brush point by brush point: the markers of the region
//! of point `k` (the capsule from point `k - 1`, seeded by the tree's seed, the edit's index and
//! `k`) are added only after the markers of the points before have grown to convergence. So the
//! growth of a stroke's first `n` points is a prefix of the growth of the whole stroke, and a
//! [`PaintGrowth`] extended with more points ([`PaintGrowth::extend`]) ends exactly where one
//! made for the whole stroke does: [`paint`] is `new`, one `extend` with every point, `apply`.
//! Cost: `new` samples the tree's nodes (linear in the tree's stem length / `segment`); each
//! `extend` costs only the new points' markers and growth (grid queries, nothing all-pairs);
//! `apply` rebuilds the new stems from all new nodes (linear in them).

mod colonize;
mod markers;
mod shoots;

use crate::error::SylvaError;
use crate::params::Paint;
use crate::skeleton::{budget_error, min_vertices, Skeleton, Stem, StemKind};
use colonize::{Colony, Settings};
pub use markers::{MAX_CANDIDATES, MAX_MARKERS};
use shoots::{Anchor, Dress};
use std::ops::Range;

use glam::Vec3;

/// The influence distance in internodes (`segment`s).
pub const INFLUENCE_SEGMENTS: f32 = 6.0;

/// The pipe model exponent of new shoots (da Vinci's rule: cross-sections add up).
pub const PIPE_POWER: f32 = 2.0;

/// Most nodes sampled on the existing tree; past it they are spaced further apart than `segment`.
const MAX_TREE_NODES: f32 = 200_000.0;

/// Smallest radius of a new shoot (m), the skeleton's smallest.
const MIN_TIP: f32 = 1e-3;

/// What a stroke grew.
#[derive(Clone, Debug, PartialEq)]
pub struct PaintOutcome {
    /// Indices of the new stems in `skeleton.stems` (before the roots).
    pub stems: Range<usize>,
    /// Every marker the stroke scattered, live or dead (for Show Markers).
    pub markers: Vec<Vec3>,
    /// Growth iterations run.
    pub iterations: u32,
}

/// The growth of one stroke from one tree, extendable as the stroke is drawn (the incremental
/// rule in the module doc).
pub struct PaintGrowth {
    colony: Colony,
    anchors: Vec<Anchor>,
    points: Vec<Vec3>,
    paint: Paint,
    seed: u32,
    index: usize,
    dress: Dress,
    stems: usize,
    tree_vertices: u64,
    max_vertices: u32,
}

/// The iteration cap of the growth after brush point `k`: twice the internodes it takes to
/// cross the point's capsule and the influence distance, plus 8.
pub fn iteration_cap(points: &[Vec3], k: usize, p: &Paint, influence: f32) -> u32 {
    let len = points[k].distance(points[k.saturating_sub(1)]);
    let cross = (len + 2.0 * p.radius + influence) / p.segment;
    (2.0 * cross.ceil() + 8.0).min(4096.0) as u32
}

/// An error naming field `field` of edit `index`.
fn field_error(index: usize, field: &str, message: &str) -> SylvaError {
    SylvaError::InvalidParam {
        param: format!("edits[{index}].{field}"),
        message: format!("edits[{index}].{field} {message}"),
    }
}

/// Refuse what the growth cannot run with (the edit list's validation names the ranges).
fn check(p: &Paint, index: usize) -> Result<(), SylvaError> {
    for (field, v) in [("radius", p.radius), ("density", p.density), ("segment", p.segment), ("kill", p.kill)] {
        if !v.is_finite() || v < 0.0 || (v == 0.0 && field != "density") {
            return Err(field_error(index, field, "must be a positive number"));
        }
    }
    if p.points.iter().any(|q| !q.is_finite()) {
        return Err(field_error(index, "points", "must be finite"));
    }
    Ok(())
}

impl PaintGrowth {
    /// The growth of stroke `paint` (edit `index` of a tree of seed `seed`) from `skeleton`,
    /// before any brush point: the tree's nodes sampled, no marker yet.
    pub fn new(
        skeleton: &Skeleton,
        paint: &Paint,
        seed: u32,
        index: usize,
        max_vertices: u32,
    ) -> Result<PaintGrowth, SylvaError> {
        check(paint, index)?;
        let own = &skeleton.stems[..skeleton.first_root()];
        let total: f32 = own.iter().map(|s| s.length / paint.segment + 2.0).sum();
        let spacing = paint.segment * (total / MAX_TREE_NODES).max(1.0);
        let mut nodes = Vec::new();
        let mut anchors = Vec::new();
        for (i, s) in own.iter().enumerate() {
            let n = (s.length / spacing).ceil().max(1.0) as u32;
            let mut curve = s.points();
            for j in 0..=n {
                let t = j as f32 / n as f32;
                if s.radius_at(t) < MIN_TIP {
                    continue; // a tapered tip too thin to carry a shoot thinner than itself
                }
                nodes.push(curve.at(t));
                anchors.push(Anchor { stem: i as u32, t });
            }
        }
        let tree_vertices: u64 = skeleton.stems.iter().map(|s| min_vertices(s.points.len() as u32 - 1)).sum();
        let settings = Settings {
            influence: (INFLUENCE_SEGMENTS * paint.segment).max(paint.kill + paint.segment),
            kill: paint.kill,
            segment: paint.segment,
            max_new: (u64::from(max_vertices).saturating_sub(tree_vertices) / 4) as usize,
        };
        let tip = own.iter().map(|s| s.radius_at(1.0)).fold(f32::INFINITY, f32::min).max(MIN_TIP);
        let deepest = own.iter().map(|s| s.level).max().unwrap_or(0);
        Ok(PaintGrowth {
            colony: Colony::new(&nodes, settings),
            anchors,
            points: Vec::new(),
            paint: Paint { points: Vec::new(), ..paint.clone() },
            seed,
            index,
            dress: Dress { tip, delta: PIPE_POWER, deepest, first: own.len() as u32, year: skeleton.age },
            stems: skeleton.stems.len(),
            tree_vertices,
            max_vertices,
        })
    }

    /// Grow toward the stroke `points` (the whole stroke so far: the points given before, then
    /// the new ones), brush point by brush point. Fails when `points` does not start with the
    /// points given before, on the marker cap and on the vertex budget.
    pub fn extend(&mut self, points: &[Vec3]) -> Result<(), SylvaError> {
        let (done, index) = (self.points.len(), self.index);
        if points.len() < done || points[..done] != self.points[..] {
            return Err(field_error(index, "points", "must continue the stroke grown so far"));
        }
        if points.iter().any(|q| !q.is_finite()) {
            return Err(field_error(index, "points", "must be finite"));
        }
        let p = &self.paint;
        let count = markers::marker_count(points, 0, p.radius, p.density);
        let drawn = markers::candidate_count(points, 0, p.radius, p.density);
        if count > MAX_MARKERS || drawn > MAX_CANDIDATES {
            let why = if count > MAX_MARKERS {
                format!("would scatter {count:.0} markers, more than {MAX_MARKERS}")
            } else {
                format!("would draw {drawn:.0} candidate markers, more than {MAX_CANDIDATES} (its points are close for its radius)")
            };
            return Err(SylvaError::Budget {
                param: format!("edits[{index}].density"),
                message: format!(
                    "edits[{index}]: this stroke {why}: lower edits[{index}].density or its radius, or paint a shorter stroke"
                ),
            });
        }
        let influence = (INFLUENCE_SEGMENTS * p.segment).max(p.kill + p.segment);
        for k in done..points.len() {
            let m = markers::region(points, k, p.radius, p.density, self.seed, index);
            self.colony.add_markers(&m);
            self.colony.grow(iteration_cap(points, k, p, influence))?;
        }
        self.points = points.to_vec();
        Ok(())
    }

    /// Every marker scattered so far, live or dead.
    pub fn markers(&self) -> &[Vec3] {
        &self.colony.markers
    }

    /// Add the new stems to `skeleton`, the tree this growth was made from: before its roots
    /// (whose parent indices move along). Fails on the vertex budget.
    pub fn apply(&self, skeleton: &mut Skeleton) -> Result<PaintOutcome, SylvaError> {
        let first = self.dress.first as usize;
        if skeleton.stems.len() != self.stems || skeleton.first_root() != first {
            return Err(SylvaError::Input {
                message: format!("edits[{}]: the paint growth belongs to another skeleton", self.index),
            });
        }
        let c = &self.colony;
        let new: Vec<Stem> = shoots::shoots(&skeleton.stems, &c.nodes, c.existing, &self.anchors, self.dress);
        let need = self.tree_vertices + new.iter().map(|s| min_vertices(s.points.len() as u32 - 1)).sum::<u64>();
        if need > u64::from(self.max_vertices) {
            return Err(budget_error(skeleton.mode, self.max_vertices, "at least ", need));
        }
        let count = new.len();
        for root in skeleton.stems[first..].iter_mut().filter(|s| s.kind == StemKind::Root) {
            root.parent = root.parent.map(|p| if p as usize >= first { p + count as u32 } else { p });
        }
        skeleton.stems.splice(first..first, new);
        Ok(PaintOutcome { stems: first..first + count, markers: c.markers.clone(), iterations: c.iterations })
    }
}

/// Grow stroke `paint`, edit `index` of a tree of seed `seed`, on `skeleton` (see the module
/// doc): the new stems are added to it.
pub fn paint(
    skeleton: &mut Skeleton,
    paint: &Paint,
    seed: u32,
    index: usize,
    max_vertices: u32,
) -> Result<PaintOutcome, SylvaError> {
    let mut growth = PaintGrowth::new(skeleton, paint, seed, index, max_vertices)?;
    growth.extend(&paint.points)?;
    growth.apply(skeleton)
}
