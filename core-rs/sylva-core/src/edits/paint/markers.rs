//! The markers of a paint stroke: scattered uniformly, `density` per cubic metre, in the tube of
//! the brush radius around the stroke polyline.
//!
//! The tube is cut into **regions**, one per brush point: region 0 is the ball around the first
//! point; region `k >= 1` is the capsule from point `k - 1` to point `k` minus the previous
//! region's shape (the capsule before it, or the first ball), so consecutive capsules are not
//! filled twice. Region `k` draws from its own generator, seeded by the tree's seed, the edit's
//! index and `k`: it depends on points `k - 2 ..= k` only, so drawing more of a stroke never
//! changes the markers of the part already drawn.

use crate::rng::Rng;
use glam::Vec3;

/// The most markers one stroke may scatter (its tube's volume times its density, [`marker_count`]).
pub const MAX_MARKERS: f64 = 20_000.0;

/// The most candidates one stroke may draw ([`candidate_count`]): a sampling budget. Brush
/// points closer together than the radius draw each region's whole capsule and keep only its
/// new part, so a stroke draws several candidates per marker it keeps.
pub const MAX_CANDIDATES: f64 = 2_000_000.0;

/// The capsule of region `k`: its two end points.
fn capsule(points: &[Vec3], k: usize) -> (Vec3, Vec3) {
    (points[k.saturating_sub(1)], points[k])
}

/// Volume of a capsule of radius `r` around a segment of length `len` (m³).
fn capsule_volume(len: f32, r: f32) -> f64 {
    let (len, r) = (f64::from(len), f64::from(r));
    std::f64::consts::PI * r * r * (len + 4.0 / 3.0 * r)
}

/// How many candidates region `k` draws: `density` times its capsule's volume, rounded.
fn candidates(points: &[Vec3], k: usize, radius: f32, density: f32) -> usize {
    let (a, b) = capsule(points, k);
    (f64::from(density) * capsule_volume(a.distance(b), radius)).round() as usize
}

/// The markers the regions `from..points.len()` of a stroke keep, expected: the density times
/// the volume each adds to the tube (the first point's ball, then the cylinder of each segment;
/// exact for a straight stroke, an overestimate where it turns).
pub fn marker_count(points: &[Vec3], from: usize, radius: f32, density: f32) -> f64 {
    let (r, d) = (f64::from(radius), f64::from(density));
    (from..points.len())
        .map(|k| {
            let (a, b) = capsule(points, k);
            let added = if k == 0 { 4.0 / 3.0 * r } else { f64::from(a.distance(b)) };
            d * std::f64::consts::PI * r * r * added
        })
        .sum()
}

/// The candidates the regions `from..points.len()` of a stroke would draw (for the sampling budget).
pub fn candidate_count(points: &[Vec3], from: usize, radius: f32, density: f32) -> f64 {
    (from..points.len()).map(|k| candidates(points, k, radius, density) as f64).sum()
}

/// Squared distance from `p` to the segment `ab`.
fn dist2_to_segment(p: Vec3, a: Vec3, b: Vec3) -> f32 {
    let d = b - a;
    let len2 = d.length_squared();
    let t = if len2 > 0.0 { ((p - a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (a + d * t).distance_squared(p)
}

/// A point uniform in the ball of radius `r` around the origin (rejection from the cube).
fn in_ball(rng: &mut Rng, r: f32) -> Vec3 {
    loop {
        let q = Vec3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        if q.length_squared() <= 1.0 {
            return q * r;
        }
    }
}

/// The markers of region `k` of the stroke `points` (see the module doc), for the edit at
/// `index` of a tree of seed `seed`.
pub fn region(points: &[Vec3], k: usize, radius: f32, density: f32, seed: u32, index: usize) -> Vec<Vec3> {
    let mut rng = Rng::new(u64::from(seed), &format!("paint/{index}/{k}"));
    let (a, b) = capsule(points, k);
    let prev = (k >= 1).then(|| capsule(points, k - 1));
    let n = candidates(points, k, radius, density);
    let axis = b - a;
    let len = axis.length();
    let dir = if len > 0.0 { axis / len } else { Vec3::Y };
    let (u, v) = dir.any_orthonormal_pair();
    let cylinder = std::f32::consts::PI * radius * radius * len;
    let ball = 4.0 / 3.0 * std::f32::consts::PI * radius * radius * radius;
    let r2 = radius * radius;
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        // Uniform in the capsule: the cylinder or the two half balls, by their volumes.
        let p = if rng.next_f32() * (cylinder + ball) < cylinder {
            let t = rng.next_f32();
            let rho = radius * rng.next_f32().sqrt();
            let angle = crate::math::TAU * rng.next_f32();
            a + axis * t + (u * crate::math::cos(angle) + v * crate::math::sin(angle)) * rho
        } else {
            let q = in_ball(&mut rng, radius);
            if q.dot(dir) < 0.0 {
                a + q
            } else {
                b + q
            }
        };
        if prev.is_none_or(|(c, d)| dist2_to_segment(p, c, d) > r2) {
            out.push(p);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markers_fill_the_tube_once_with_the_density() {
        let pts = [Vec3::new(0.0, 5.0, 0.0), Vec3::new(1.0, 5.0, 0.0), Vec3::new(2.0, 5.5, 0.0)];
        let (r, density) = (0.4, 2000.0);
        let all: Vec<Vec3> = (0..3).flat_map(|k| region(&pts, k, r, density, 1, 0)).collect();
        for p in &all {
            let d = dist2_to_segment(*p, pts[0], pts[1]).min(dist2_to_segment(*p, pts[1], pts[2]));
            assert!(d <= r * r * 1.0001, "{p} outside the tube");
        }
        // The union of the two capsules, by Monte Carlo over its box, times the density.
        let mut rng = Rng::new(9, "t");
        let (lo, hi) = (Vec3::new(-0.4, 4.6, -0.4), Vec3::new(2.4, 5.9, 0.4));
        let inside = (0..200_000)
            .filter(|_| {
                let p = Vec3::new(rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z));
                dist2_to_segment(p, pts[0], pts[1]).min(dist2_to_segment(p, pts[1], pts[2])) <= r * r
            })
            .count();
        let volume = (hi - lo).x * (hi - lo).y * (hi - lo).z * inside as f32 / 200_000.0;
        let want = volume * density;
        assert!((all.len() as f32 - want).abs() < 0.05 * want, "{} markers, want {want}", all.len());
        // The expected count the marker cap reads is the tube's volume times the density.
        let expected = marker_count(&pts, 0, r, density);
        assert!((expected as f32 - want).abs() < 0.05 * want, "expected {expected}, want {want}");
        // A region depends only on the points up to it.
        assert_eq!(region(&pts[..2], 1, r, density, 1, 0), region(&pts, 1, r, density, 1, 0));
    }
}
