//! Complex trunk cross-sections (the trunk generator of the tree-generator thesis posted on
//! 3dideas.wordpress.com (2008), §4.2 "Recommendations for Trunk Generation"): around the main
//! circle of each trunk ring sit `count` shape-refinement circles (radius default ⅓ of the main
//! circle), centred on refinement curves offset from the guide curve (default offset = the circle's
//! radius) and spread evenly around it; the cross-section is the outer boundary of the union of all
//! these circles, resampled at a fixed number of points. Resampling casts one ray from the centre
//! per column and keeps the farthest point of the union on it, so the outline is exactly what a ray
//! test against the union sees.

use crate::math::{cos, sin, TAU};

/// One circle of a cross-section, in the ring's plane (coordinates along the ring's normal and
/// binormal, m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// Centre.
    pub c: [f32; 2],
    /// Radius.
    pub r: f32,
}

/// Farthest distance from the origin along the unit direction `d` at which the ray is still
/// inside `circle` (None when the ray misses it).
pub fn ray_exit(circle: Circle, d: [f32; 2]) -> Option<f32> {
    // |t d - c|^2 = r^2  ->  t^2 - 2 t (d.c) + |c|^2 - r^2 = 0
    let b = d[0] * circle.c[0] + d[1] * circle.c[1];
    let cc = circle.c[0] * circle.c[0] + circle.c[1] * circle.c[1] - circle.r * circle.r;
    let disc = b * b - cc;
    if disc < 0.0 {
        return None;
    }
    let t = b + disc.sqrt();
    (t > 0.0).then_some(t)
}

/// The circles of one trunk ring: the main circle of radius `radius` at the origin and `count`
/// refinement circles of radius `radius * refine_radius * (1 + jitter)` centred at distance
/// `radius * refine_offset * (1 + jitter)`, evenly spread starting at angle `phase`. `jitter`
/// gives each refinement circle's relative variation (its length is `count`).
pub fn ring_circles(
    radius: f32,
    refine_offset: f32,
    refine_radius: f32,
    phase: f32,
    jitter: &[[f32; 2]],
) -> Vec<Circle> {
    let count = jitter.len();
    let mut out = Vec::with_capacity(count + 1);
    out.push(Circle { c: [0.0, 0.0], r: radius });
    for (k, j) in jitter.iter().enumerate() {
        let a = phase + TAU * k as f32 / count as f32;
        let off = radius * refine_offset * (1.0 + j[0]);
        out.push(Circle { c: [off * cos(a), off * sin(a)], r: (radius * refine_radius * (1.0 + j[1])).max(0.0) });
    }
    out
}

/// The outline of the union of `circles` as radii along the directions `dirs` (unit vectors):
/// the farthest point of the union on each ray from the origin. The origin must lie inside the
/// first circle (the main one), so every ray has an answer.
pub fn union_outline(circles: &[Circle], dirs: &[(f32, f32)], out: &mut Vec<f32>) {
    out.clear();
    for &(c, s) in dirs {
        let r = circles.iter().filter_map(|k| ray_exit(*k, [c, s])).fold(0.0f32, f32::max);
        out.push(r);
    }
}

#[cfg(test)]
#[allow(clippy::disallowed_methods, reason = "the tests' own measures, not output bytes")]
mod tests {
    use super::*;

    #[test]
    fn outline_is_the_union_boundary_by_ray_test() {
        let circles =
            ring_circles(1.0, 1.0, 1.0 / 3.0, 0.3, &[[0.0, 0.0], [0.2, -0.1], [-0.1, 0.3], [0.05, 0.0], [0.0, 0.0]]);
        let dirs: Vec<(f32, f32)> =
            (0..256).map(|j| (cos(TAU * j as f32 / 256.0), sin(TAU * j as f32 / 256.0))).collect();
        let mut out = Vec::new();
        union_outline(&circles, &dirs, &mut out);
        for (&(c, s), &r) in dirs.iter().zip(&out) {
            let p = [r * c, r * s];
            // On the boundary of some circle...
            let on = circles.iter().any(|k| ((p[0] - k.c[0]).hypot(p[1] - k.c[1]) - k.r).abs() < 1e-4);
            assert!(on, "outline point {p:?} is on no circle");
            // ...and nothing of the union lies farther out along the ray.
            let beyond = [(r + 1e-3) * c, (r + 1e-3) * s];
            assert!(
                circles.iter().all(|k| (beyond[0] - k.c[0]).hypot(beyond[1] - k.c[1]) > k.r),
                "union extends past {p:?}"
            );
            assert!(r >= 1.0 - 1e-5, "the main circle is part of the union");
        }
        // The refinement circles bulge the outline: its largest radius is offset + radius.
        let max = out.iter().cloned().fold(0.0f32, f32::max);
        assert!(max > 1.3 && max <= 1.0 + 0.2 + (1.0 / 3.0) * 1.3 + 1e-4, "max radius {max}");
    }

    #[test]
    fn no_refinement_circles_is_a_circle() {
        let circles = ring_circles(2.0, 1.0, 0.33, 0.0, &[]);
        let mut out = Vec::new();
        union_outline(&circles, &[(1.0, 0.0), (0.0, 1.0), (-0.6, 0.8)], &mut out);
        assert!(out.iter().all(|r| (r - 2.0).abs() < 1e-6));
    }
}
