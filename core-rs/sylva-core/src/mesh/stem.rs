//! What the sweep of one stem ([`super::tube`]) shares with the junctions, forks, twigs and holes
//! that attach to it: the stem's place in the mesh ([`StemMesh`], [`Base`]), its ring frames
//! ([`Frame`]), its wind constants ([`StemWind`]), its number of sides ([`sides_for`]) and the
//! clean-up of its ring positions ([`drop_close`]). A module of its own so that those stages
//! import these from here rather than from the tube stage that calls them.

use super::WIND_STRIDE;
use crate::skeleton::Stem;
use glam::Vec3;

/// What one stem's sweep wrote, for the junctions of its children and the index pass.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StemMesh {
    /// First vertex of ring 0.
    pub first: u32,
    /// Number of rings.
    pub rings: u32,
    /// Sides per ring (a ring holds `sides + 1` vertices, the seam duplicated).
    pub sides: u32,
    /// Index of ring 0 in the shared ring-parameter and frame buffers.
    pub ring0: usize,
    /// The apex closing the tip.
    pub apex: u32,
    /// How the base is closed.
    pub base: Base,
    /// Offset of this stem's quads in the claimed-quad bitmap (`(rings - 1) * sides` entries).
    pub claim: usize,
    /// `v` of ring 0.
    pub v0: f32,
    /// A cut end ([`super::cut_face`]): the first vertex of its bevel ring (the face ring
    /// follows; `apex` is the face's centre).
    pub cut: Option<CutEnd>,
}

/// Where a stem's cut end ([`super::cut_face`]) starts in the mesh (the first vertex of its bevel ring, or of its
/// callus crest ring; the face ring follows, then a callus's inner ring) and whether it has a
/// callus.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CutEnd {
    /// The first vertex of the bevel (or crest) ring.
    pub first: u32,
    /// Whether the end carries a callus roll (an inner ring and its quads).
    pub callus: bool,
}

impl StemMesh {
    /// The same stem's mesh with its vertices moved to start at `first` (a block swept by
    /// another builder and copied in: [`super::MeshBuilder::append_copy`]).
    pub(crate) fn moved(self, first: u32) -> StemMesh {
        let to = |v: u32| v.wrapping_sub(self.first).wrapping_add(first);
        let base = match self.base {
            Base::Trunk(c) => Base::Trunk(to(c)),
            Base::Cap(c) => Base::Cap(to(c)),
            b => b,
        };
        let cut = self.cut.map(|c| CutEnd { first: to(c.first), ..c });
        StemMesh { first, apex: to(self.apex), base, cut, ..self }
    }

    /// The seam twin of ring vertex `i` a whole turn of `u` on (`turns` = 1: a ring's first
    /// vertex, `u` 0, to its last, `u` 1; -1 the other way), if `i` is one of this stem's.
    pub(crate) fn seam_twin(&self, i: u32, turns: i32) -> Option<u32> {
        let stride = self.sides + 1;
        let k = i.checked_sub(self.first).filter(|&k| k < self.rings * stride)?;
        match (k % stride, turns) {
            (0, 1) => Some(i + self.sides),
            (c, -1) if c == self.sides => Some(i - self.sides),
            _ => None,
        }
    }
}

/// How a stem's base ring is closed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Base {
    /// The trunk: a flat downward cap on its own copy of ring 0 (first vertex of the copy).
    Trunk(u32),
    /// A fan from ring 0 to this centre vertex (a separate tube sitting in its parent).
    Cap(u32),
    /// Welded into the parent's surface ([`super::weld`]).
    Welded,
    /// Not closed yet: a branch's base between its sweep and its weld or cap (never left so
    /// for the index pass).
    Open,
}

/// Centre and orientation of one swept ring: column `j` of the ring lies along
/// `normal cos(2πj/sides) + (tangent × normal) sin(2πj/sides)`.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Frame {
    /// Ring centre.
    pub centre: Vec3,
    /// Unit tangent of the centre curve.
    pub tangent: Vec3,
    /// Unit normal, transported along the stem.
    pub normal: Vec3,
}

/// Number of sides around a stem of base radius `r` (m) at the given quality.
pub fn sides_for(r: f32, quality: f32, lobes: u32) -> u32 {
    let base = (quality * (3.0 + 30.0 * r.max(0.0).sqrt())).round() as u32;
    base.max((4 * lobes).min(96)).clamp(3, 96)
}

/// Per-stem constants of the wind attributes ([`TreeMesh::wind`](crate::mesh::TreeMesh::wind)).
#[derive(Clone, Copy, Debug)]
pub struct StemWind {
    /// The stem's base point (the pivot it sways about).
    pub pivot: Vec3,
    /// Branch level.
    pub level: f32,
    /// Random phase 0..1, one per stem.
    pub phase: f32,
    /// Path length from the root to the stem's base (m).
    pub distance: f32,
    /// Trunk base radius (m), the reference for stiffness.
    pub trunk_radius: f32,
}

impl StemWind {
    /// The wind record of a ring at fraction `t` of `stem` with local radius `radius`.
    /// Stiffness is `sqrt(min(1, radius / trunk_radius))`: 1 at the trunk base (and in the flare),
    /// about 0.3 where a stem is a tenth of the trunk, 0.1 at a hundredth: thin twigs sway most.
    #[inline]
    pub fn record(&self, stem: &Stem, t: f32, radius: f32) -> [f32; WIND_STRIDE] {
        let stiffness = (radius / self.trunk_radius).clamp(0.0, 1.0).sqrt();
        let p = self.pivot;
        [p.x, p.y, p.z, self.level, self.phase, stiffness, self.distance + t * stem.length, radius]
    }
}

/// Drops from the sorted ring positions `ts[first..]` every one within 1e-4 of the one kept before
/// it (rings closer than that would give degenerate quads).
pub(crate) fn drop_close(ts: &mut Vec<f32>, first: usize) {
    let rings = &mut ts[first..];
    let mut n = 0;
    for i in 0..rings.len() {
        if n == 0 || rings[i] - rings[n - 1] > 1e-4 {
            rings[n] = rings[i];
            n += 1;
        }
    }
    ts.truncate(first + n);
}
