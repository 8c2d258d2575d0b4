//! Stage 3, triangulation (Leaf Generation guide §3): the blade filled with triangles.
//!
//! The method of Mtree's *Leaf Generation Guide* (§3) comes first: **concentric rings** shrinking
//! toward a centre, joined by triangle strips, with a fan to the centre ([`rings`]). It is valid
//! exactly when the outline is star-shaped about the centre, so the centre is the candidate deepest
//! inside the outline's kernel, and every ring triangle is checked. Where no such centre exists (a
//! waisted spline outline with deep teeth) or a triangle would fold, a robust method takes over
//! ([`cdt`]): ear clipping of the outline, Lawson flips to a constrained Delaunay triangulation,
//! and interior points inserted with Delaunay legalisation.
//!
//! Either way the outline points are the first vertices and the outline edges are exactly the
//! boundary edges; [`validate`] checks that the result is an embedding of the blade.

pub mod cdt;
pub mod rings;
mod triangulation;

pub use triangulation::{Method, Triangulation};

use crate::leaf::geom::{orient, polygon_area, DVec2};
use crate::leaf::margin::Outline;
use glam::Vec2;

/// Stage 3: rings about the deepest kernel point when the outline is star-shaped, else the
/// robust method. `rings` (1..16) sets the interior detail of both.
pub fn build(outline: &Outline, rings: u32) -> Triangulation {
    let poly = &outline.points;
    let mut candidates = vec![outline.center, centroid(poly)];
    candidates.extend((1..16).map(|k| Vec2::new(0.0, k as f32 / 16.0)));
    if let Some(c) = rings::kernel_center(poly, &candidates) {
        if let Some(t) = rings::build(poly, c, rings) {
            return t;
        }
    }
    cdt::build(poly, rings)
}

/// Area centroid of a polygon (its first point when the area is zero).
pub fn centroid(poly: &[Vec2]) -> Vec2 {
    let n = poly.len();
    let (mut cx, mut cy, mut a2) = (0.0f64, 0.0f64, 0.0f64);
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        let cross = f64::from(p.x) * f64::from(q.y) - f64::from(q.x) * f64::from(p.y);
        a2 += cross;
        cx += (f64::from(p.x) + f64::from(q.x)) * cross;
        cy += (f64::from(p.y) + f64::from(q.y)) * cross;
    }
    if a2.abs() < 1e-300 {
        return poly[0];
    }
    Vec2::new((cx / (3.0 * a2)) as f32, (cy / (3.0 * a2)) as f32)
}

/// Angle at `b` between `a` and `c` (0..π).
fn angle(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    let (u, v) = (DVec2::from_vec2(a - b), DVec2::from_vec2(c - b));
    let d = u.length() * v.length();
    if d == 0.0 {
        return 0.0;
    }
    libm::acos((u.dot(v) / d).clamp(-1.0, 1.0))
}

/// Checks that `t` triangulates the closed polygon `outline` without folds or overlaps:
/// the outline is its first vertices; every triangle is counter-clockwise with positive area;
/// every edge is used once in each direction, except the outline edges, used exactly once in
/// outline order; the angles around each interior vertex sum to 2π and those at each outline
/// vertex to the outline's interior angle (so every point of the blade is covered once); the
/// areas sum to the outline's area within 0.5%.
pub fn validate(outline: &[Vec2], t: &Triangulation) -> Result<(), String> {
    let n = outline.len();
    let nv = t.vertices.len();
    if t.boundary != n || nv < n || t.vertices[..n] != *outline {
        return Err("the outline is not the first vertices".into());
    }
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(t.triangles.len() * 3);
    let mut angle_sum = vec![0.0f64; nv];
    let mut area = 0.0;
    for (k, tri) in t.triangles.iter().enumerate() {
        if tri.iter().any(|&i| i as usize >= nv) {
            return Err(format!("triangle {k} indexes past the vertices"));
        }
        let [a, b, c] = tri.map(|i| t.vertices[i as usize]);
        let o = orient(a, b, c);
        if o <= 0.0 {
            return Err(format!("triangle {k} {tri:?} is inverted or degenerate (2*area {o:e})"));
        }
        area += 0.5 * o;
        for e in 0..3 {
            edges.push((tri[e], tri[(e + 1) % 3]));
            let (p, q, r) = (tri[(e + 2) % 3], tri[e], tri[(e + 1) % 3]);
            angle_sum[q as usize] += angle(t.vertices[p as usize], t.vertices[q as usize], t.vertices[r as usize]);
        }
    }
    edges.sort_unstable();
    if let Some(w) = edges.windows(2).find(|w| w[0] == w[1]) {
        return Err(format!("edge {:?} is used twice in the same direction (overlap)", w[0]));
    }
    let mut boundary = 0usize;
    for &(a, b) in &edges {
        if edges.binary_search(&(b, a)).is_err() {
            let is_outline = (a as usize) < n && b as usize == (a as usize + 1) % n;
            if !is_outline {
                return Err(format!("edge ({a}, {b}) is open but not an outline edge"));
            }
            boundary += 1;
        }
    }
    if boundary != n {
        return Err(format!("{boundary} boundary edges for an outline of {n} points"));
    }
    const TAU: f64 = std::f64::consts::TAU;
    for (i, &sum) in angle_sum.iter().enumerate() {
        let want = if i < n {
            let (a, b, c) = (outline[(i + n - 1) % n], outline[i], outline[(i + 1) % n]);
            let inner = angle(c, b, a);
            if orient(a, b, c) >= 0.0 {
                inner
            } else {
                TAU - inner
            }
        } else {
            TAU
        };
        if sum == 0.0 {
            return Err(format!("vertex {i} is not used"));
        }
        if (sum - want).abs() > 1e-3 {
            return Err(format!("angles around vertex {i} sum to {sum}, expected {want} (fold)"));
        }
    }
    let want = polygon_area(outline);
    if (area - want).abs() > 0.005 * want.abs() {
        return Err(format!("triangle areas sum to {area}, the outline's area is {want}"));
    }
    Ok(())
}
