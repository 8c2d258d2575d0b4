//! Stage 6, surface deformation (Leaf Generation guide §5). Every vertex keeps its `x, y` in the
//! leaf plane and gets a height
//!
//! ```text
//! z = midrib · y²/2  +  cross · W (x/W)²/2  +  curl · W (1 - d/d_max)²/2  +  veins · h(x, y)
//! ```
//!
//! with `W` the blade's half-width, `d` the vertex's distance to the outline (so the margin
//! curls most and the centre not at all; on a ring triangulation `d/d_max` is the ring's
//! position `k/R`) and `h` the vein influence field (0..1, the midrib's
//! crest is 1; [`crate::leaf::field`]). Each term is bounded by its coefficient, so
//! `|z| ≤ |midrib| Y²/2 + (|cross| + |curl|) W/2 + veins` with `Y = max |y|` ([`bound`]).

use crate::leaf::field::VeinField;
use crate::leaf::geom::dist_to_segment;
use crate::params::LeafParams;
use glam::{Vec2, Vec3};

/// The largest `|z|` the deformation can produce for these parameters and blade extents.
pub fn bound(p: &LeafParams, max_abs_y: f32, half_width: f32) -> f32 {
    0.5 * p.leaf_midrib_curvature.abs() * max_abs_y * max_abs_y
        + 0.5 * (p.leaf_cross_curvature.abs() + p.leaf_edge_curl.abs()) * half_width
        + p.leaf_vein_displacement
}

/// Half-width and largest `|y|` of an outline.
pub fn extents(outline: &[Vec2]) -> (f32, f32) {
    outline.iter().fold((1e-3f32, 0.0f32), |(w, y), p| (w.max(p.x.abs()), y.max(p.y.abs())))
}

/// Edge-curl weight per vertex, 1 on the outline falling to 0 at the centre: `(1 - d/d_max)²`
/// with `d` the distance to the outline (over at most 64 of its edges), or for a ring
/// triangulation the ring's own position, `(1 - k/R)²` on ring `k` of `R`.
pub fn edge_weights(vertices: &[Vec2], outline: &[Vec2], rings: Option<u32>) -> Vec<f32> {
    let n = outline.len();
    if let Some(r) = rings {
        let r = r.max(1) as usize;
        return (0..vertices.len())
            .map(|i| {
                let k = (i / n).min(r);
                let s = 1.0 - k as f32 / r as f32;
                s * s
            })
            .collect();
    }
    let stride = n.div_ceil(64).max(1);
    let coarse: Vec<Vec2> = outline.iter().step_by(stride).copied().collect();
    let m = coarse.len();
    let dist: Vec<f32> = vertices
        .iter()
        .map(|&q| (0..m).map(|i| dist_to_segment(q, coarse[i], coarse[(i + 1) % m])).fold(f32::INFINITY, f32::min))
        .collect();
    let dmax = dist.iter().copied().fold(1e-6f32, f32::max);
    dist.iter()
        .map(|&d| {
            let e = 1.0 - (d / dmax).min(1.0);
            e * e
        })
        .collect()
}

/// Stage 6: 3D positions of the blade's vertices (`edge` from [`edge_weights`]).
pub fn displace(p: &LeafParams, vertices: &[Vec2], outline: &[Vec2], edge: &[f32], field: &VeinField) -> Vec<Vec3> {
    let (w, _) = extents(outline);
    vertices
        .iter()
        .zip(edge)
        .map(|(&q, &e)| {
            let z = 0.5 * p.leaf_midrib_curvature * q.y * q.y
                + 0.5 * p.leaf_cross_curvature * w * (q.x / w) * (q.x / w)
                + 0.5 * p.leaf_edge_curl * w * e
                + p.leaf_vein_displacement * field.sample(q);
            Vec3::new(q.x, q.y, z)
        })
        .collect()
}

/// Area-weighted vertex normals of a triangle list (unit; `+z` where undefined).
#[inline(never)]
pub fn normals(positions: &[Vec3], triangles: &[[u32; 3]]) -> Vec<Vec3> {
    let mut n = vec![Vec3::ZERO; positions.len()];
    for t in triangles {
        let [a, b, c] = t.map(|i| positions[i as usize]);
        let face = (b - a).cross(c - a);
        for &i in t {
            n[i as usize] += face;
        }
    }
    n.into_iter().map(|v| v.try_normalize().unwrap_or(Vec3::Z)).collect()
}
