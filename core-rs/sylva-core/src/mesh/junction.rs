//! What a welded junction ([`super::weld`]) and a Y fork ([`super::fork`]) share: where a child
//! meets its parent ([`Junction`]), everything a join reads ([`Join`]), how far the trunk's
//! surface reaches ([`surface_bound`]) and the check of every new triangle ([`well_wound`]). A
//! module of its own so that the weld plan can call the fork's geometry without the fork
//! importing back from the weld.

use super::stem::{Frame, StemMesh, StemWind};
use super::MeshBuilder;
use crate::math::{PI, TAU};
use crate::params::MeshParams;
use crate::skeleton::Stem;

/// The junction ring must sit in the first half of the child.
pub(crate) const MAX_START: f32 = 0.5;

/// Where a welded child starts and where it opens its parent (fractions of each stem).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Junction {
    /// The parent stem.
    pub parent: u32,
    /// Fraction of the child where its junction ring (its first ring) sits.
    pub t_start: f32,
    /// Fractions of the parent where the footprint starts and ends.
    pub t_lo: f32,
    /// See `t_lo`.
    pub t_hi: f32,
    /// Radius of the footprint (the collar's base) (m).
    pub foot: f32,
    /// Estimated azimuth of the footprint around the parent (radians; only compared between
    /// footprints close along the same parent).
    pub phi: f32,
    /// Half-width of the footprint around the parent (radians).
    pub beta: f32,
    /// A shallow split clone forked from its original ([`super::fork`]): `t_lo` is the split
    /// ring on the original, `t_hi` the original's next ring, and no other ring lies between.
    pub fork: bool,
}

impl Junction {
    /// True if two footprints on the same parent are closer around it than their half-widths
    /// plus `pad` (radians).
    pub(crate) fn side_by_side(&self, other: &Junction, pad: f32) -> bool {
        let mut d = (self.phi - other.phi).abs() % TAU;
        if d > PI {
            d = TAU - d;
        }
        d < self.beta + other.beta + pad
    }
}

/// How far the trunk's surface reaches beyond its nominal radius (lobes, fluting, ripple).
pub(crate) fn surface_bound(p: &MeshParams) -> f32 {
    let lobes = 1.0 + if p.lobes > 0 { p.lobe_depth } else { 0.0 };
    let refine =
        if p.refine_curves > 0 { (p.refine_offset + p.refine_radius) * (1.0 + p.refine_variation) } else { 0.0 };
    lobes * refine.max(1.0) * (1.0 + p.base_ripple)
}

/// Everything [`join`](fn@super::weld::join) reads.
pub(crate) struct Join<'a> {
    /// The planned junction.
    pub junction: &'a Junction,
    /// The parent's swept tube.
    pub parent: &'a StemMesh,
    /// The parent stem.
    pub parent_stem: &'a Stem,
    /// The child's swept tube (ring 0 is its junction ring).
    pub child: &'a StemMesh,
    /// The child stem.
    pub child_stem: &'a Stem,
    /// Ring parameters of all stems.
    pub ts: &'a [f32],
    /// Ring frames of all stems.
    pub frames: &'a [Frame],
    /// The child's wind constants.
    pub wind: &'a StemWind,
    /// Collar loops between hole and junction ring.
    pub loops: usize,
}

/// True if every triangle of `tris` is non-degenerate and wound with its vertex normals (its
/// face normal on the side of their sum).
pub(crate) fn well_wound(out: &MeshBuilder, tris: &[u32]) -> bool {
    tris.chunks_exact(3).all(|t| {
        let ((a, na), (b, nb), (c, nc)) = (out.vertex_at(t[0]), out.vertex_at(t[1]), out.vertex_at(t[2]));
        let cross = (b - a).cross(c - a);
        cross.length_squared() > 0.0 && cross.dot(na + nb + nc) > 0.0
    })
}
