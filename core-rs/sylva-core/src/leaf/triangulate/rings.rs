//! Concentric rings (Leaf Generation guide §3): ring `k` of `R` is the outline scaled by
//! `1 - k/R` about a centre `c`; neighbouring rings are joined by strips of two triangles per
//! outline edge (split along the shorter diagonal) and the innermost ring by a fan to `c`.
//! Each strip quad lies inside the wedge `c, p_i, p_i+1`, so the result is valid whenever every
//! wedge is counter-clockwise, i.e. `c` lies in the outline's kernel (rings alone only
//! triangulate star-shaped outlines). [`kernel_center`] picks such a centre or reports there is none.

use super::triangulation::{Method, Triangulation};
use crate::leaf::geom::orient;
use glam::Vec2;

/// The candidate deepest inside the kernel of the counter-clockwise polygon (largest smallest
/// distance to the lines of its edges), or `None` when no candidate sees every edge from the
/// inside.
pub fn kernel_center(poly: &[Vec2], candidates: &[Vec2]) -> Option<Vec2> {
    let n = poly.len();
    let mut best: Option<(f64, Vec2)> = None;
    for &c in candidates {
        let mut depth = f64::INFINITY;
        for i in 0..n {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            let len = f64::from((b - a).length());
            if len == 0.0 {
                continue;
            }
            depth = depth.min(orient(a, b, c) / len);
            if depth <= 0.0 {
                break;
            }
        }
        if depth > 1e-6 && best.is_none_or(|(d, _)| depth > d) {
            best = Some((depth, c));
        }
    }
    best.map(|(_, c)| c)
}

/// Rings about `c`, or `None` if any triangle would be inverted or degenerate.
pub fn build(poly: &[Vec2], c: Vec2, rings: u32) -> Option<Triangulation> {
    let n = poly.len();
    let r = rings.max(1) as usize;
    let mut vertices = Vec::with_capacity(n * r + 1);
    vertices.extend_from_slice(poly);
    for k in 1..r {
        let s = 1.0 - k as f32 / r as f32;
        vertices.extend(poly.iter().map(|&p| c + (p - c) * s));
    }
    let center = vertices.len() as u32;
    vertices.push(c);
    let mut triangles = Vec::with_capacity(n * (2 * r - 1));
    let id = |ring: usize, i: usize| (ring * n + i % n) as u32;
    for k in 0..r - 1 {
        for i in 0..n {
            let (o0, o1, q0, q1) = (id(k, i), id(k, i + 1), id(k + 1, i), id(k + 1, i + 1));
            let d1 = (vertices[o0 as usize] - vertices[q1 as usize]).length_squared();
            let d2 = (vertices[o1 as usize] - vertices[q0 as usize]).length_squared();
            if d1 <= d2 {
                triangles.push([o0, o1, q1]);
                triangles.push([o0, q1, q0]);
            } else {
                triangles.push([o0, o1, q0]);
                triangles.push([o1, q1, q0]);
            }
        }
    }
    for i in 0..n {
        triangles.push([id(r - 1, i), id(r - 1, i + 1), center]);
    }
    let ok = triangles
        .iter()
        .all(|t| orient(vertices[t[0] as usize], vertices[t[1] as usize], vertices[t[2] as usize]) > 0.0);
    ok.then_some(Triangulation { vertices, triangles, method: Method::Rings, boundary: n })
}
