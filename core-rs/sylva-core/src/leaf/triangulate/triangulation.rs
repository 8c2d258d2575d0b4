//! What stage 3 ([`super`]) returns: the triangulated blade and the method that produced it. A
//! module of its own so that both methods ([`super::rings`], [`super::cdt`]) build it without
//! importing back from the stage that chooses between them.

use glam::Vec2;
use serde::Serialize;

/// Which method produced a triangulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Concentric rings and a centre fan.
    Rings,
    /// Ear clipping, constrained Delaunay flips and interior points.
    Cdt,
}

/// A triangulated blade in the leaf plane.
#[derive(Clone, Debug)]
pub struct Triangulation {
    /// Vertices: the outline points first (same order), then interior points.
    pub vertices: Vec<Vec2>,
    /// Counter-clockwise triangles (indices into `vertices`).
    pub triangles: Vec<[u32; 3]>,
    /// The method used.
    pub method: Method,
    /// Number of outline vertices at the start of `vertices`.
    pub boundary: usize,
}
