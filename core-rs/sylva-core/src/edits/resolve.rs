//! Finding the stem an edit names by a point: the stem whose surface is nearest to the point
//! (the distance to its centre curve minus its radius there), within a tolerance of
//! [`TOLERANCE`] m or [`TOLERANCE_RADII`] times the local radius, whichever is larger. Roots are
//! never picked. The centre curve is the one the bark follows ([`crate::skeleton::Stem::sample`]),
//! sampled [`SAMPLES`] times per segment.

use crate::skeleton::{Skeleton, StemKind};
use glam::Vec3;

/// Smallest tolerance between a point and a stem's surface (m).
pub const TOLERANCE: f32 = 0.05;
/// Tolerance in local radii (for thick stems).
pub const TOLERANCE_RADII: f32 = 1.5;
/// Samples of the centre curve per polyline segment.
pub const SAMPLES: usize = 8;

/// Where a point lies on the stem it names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Index of the stem.
    pub stem: usize,
    /// Fraction of the stem (0 = base, 1 = tip) nearest to the point.
    pub t: f32,
    /// Arc length along the stem there (m).
    pub along: f32,
    /// Distance from the point to the stem's surface (m; negative inside).
    pub gap: f32,
}

/// The stem nearest to `at`, or why none is within the tolerance.
pub fn nearest(skeleton: &Skeleton, at: Vec3) -> Result<Hit, String> {
    let mut best: Option<Hit> = None;
    for (i, s) in skeleton.stems.iter().enumerate() {
        if s.kind == StemKind::Root {
            continue;
        }
        // A bounding ball of the stem's points, padded by its largest radius and the curve's
        // overshoot between points: skip stems that cannot beat the best so far.
        let (lo, hi) =
            s.points.iter().fold((Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)), |(lo, hi), &q| (lo.min(q), hi.max(q)));
        let centre = 0.5 * (lo + hi);
        let reach = 0.5 * (hi - lo).length() * 1.1 + s.radius_at(0.0).max(s.radius) + 1e-3;
        if best.is_some_and(|b| at.distance(centre) - reach > b.gap) {
            continue;
        }
        if let Some(hit) = on_stem(skeleton, i, at).filter(|h| best.is_none_or(|b| h.gap < b.gap)) {
            best = Some(hit);
        }
    }
    let hit = best.ok_or_else(|| "the tree has no stems".to_string())?;
    let stem = &skeleton.stems[hit.stem];
    let tolerance = TOLERANCE.max(TOLERANCE_RADII * stem.radius_at(hit.t));
    if hit.gap > tolerance {
        return Err(format!(
            "no stem within {tolerance:.2} m of [{:.2}, {:.2}, {:.2}] (the nearest bark is {:.2} m away)",
            at.x, at.y, at.z, hit.gap
        ));
    }
    Ok(hit)
}

/// The point of stem `i`'s centre curve nearest to `at`, as a [`Hit`].
fn on_stem(skeleton: &Skeleton, i: usize, at: Vec3) -> Option<Hit> {
    let s = &skeleton.stems[i];
    let n = (s.points.len() - 1) * SAMPLES;
    let mut cursor = s.points();
    let mut prev = cursor.at(0.0);
    let mut best: Option<(f32, f32)> = None; // (gap, t)
    for k in 1..=n {
        let (t0, t1) = ((k - 1) as f32 / n as f32, k as f32 / n as f32);
        let next = cursor.at(t1);
        let d = next - prev;
        let u = if d.length_squared() > 0.0 { ((at - prev).dot(d) / d.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
        let t = t0 + (t1 - t0) * u;
        let gap = at.distance(prev + d * u) - s.radius_at(t);
        if best.is_none_or(|(g, _)| gap < g) {
            best = Some((gap, t));
        }
        prev = next;
    }
    best.map(|(gap, t)| Hit { stem: i, t, along: t * s.length, gap })
}
