//! Bending a stem so that its point at fraction `a` moves to a target: segment `k` of the
//! centre polyline turns by `slerp(identity, Q, w)` of one rotation `Q`, with the weight
//! `w = 1 - (1 - s / a)^power` rising smoothly from 0 at the stem's base (`s` the segment's
//! middle) to 1 at `a` and staying 1 beyond. Segments are turned, never stretched, so the stem
//! keeps its length. `Q` is found by iteration (each step turns it by the rotation taking the
//! bent point's direction from the base onto the target's), and `power` by bisection so that the
//! point's distance from the base matches the target's: a bend spread along the stem pulls the
//! point toward the base, one gathered near the base hardly. A target the point cannot reach gets
//! the nearest reachable place in its direction. Children ride along: each one's subtree turns
//! rigidly by the bend's rotation at its attachment point and moves with that point; base
//! normals turn with their stems.

use super::stems::{carry_children, Children};
use crate::error::SylvaError;
use crate::math::{self, pow};
use crate::params::edits::bad;
use crate::skeleton::{Points, Skeleton, Stem};
use glam::{Quat, Vec3};

/// Fewest segments a bent stem's polyline gets (stems with fewer are resampled first, so the
/// bend is smooth).
const MIN_SEGMENTS: usize = 16;
/// Iterations of the search for the rotation.
const ITERATIONS: usize = 24;
/// Exponents of the weight profile `1 - (1 - s / a)^power` tried: from a bend spread along the
/// stem to one gathered near its base.
const MIN_POWER: f32 = 2.0;
const MAX_POWER: f32 = 48.0;
/// Bisection steps on the exponent.
const BISECTIONS: usize = 14;

/// Bend stem `i` so that its point at fraction `a` follows to `to`. Edit `index` names the edit
/// in the error of a bend across the tree.
pub fn bend(skeleton: &mut Skeleton, i: usize, a: f32, to: Vec3, index: usize) -> Result<(), SylvaError> {
    let old = resampled(&skeleton.stems[i]);
    let base = old.base();
    let reach = to.distance(base);
    if reach > old.length {
        let field = format!("edits[{index}].to");
        return Err(bad(
            field.clone(),
            format!(
                "{field} is {reach:.2} m from the base of the branch it bends, which is only {:.2} m long: a bend across the tree",
                old.length
            ),
        ));
    }
    let a = a.clamp(1.0 / MIN_SEGMENTS as f32, 1.0);
    let weight = |s: f32, power: f32| 1.0 - pow((1.0 - s / a).max(0.0), power);
    let (q, power) = solve(&old, a, to, &weight);
    let segs = old.points.len() - 1;
    let mut stem = old.clone();
    stem.points = bent(&old, q, &|s| weight(s, power));
    let first = math::slerp(Quat::IDENTITY, q, weight(0.5 / segs as f32, power));
    stem.base_normal = (first * old.base_normal).normalize_or(old.base_normal);
    skeleton.stems[i] = stem;
    // Children ride along.
    carry_children(skeleton, &Children::of_skeleton(skeleton), i, old.length, &|s| {
        math::slerp(Quat::IDENTITY, q, weight(s, power))
    });
    Ok(())
}

/// The polyline of `old` with segment `k` turned by `slerp(identity, q, weight(middle of k))`.
fn bent(old: &Stem, q: Quat, weight: &dyn Fn(f32) -> f32) -> Points {
    let segs = old.points.len() - 1;
    let mut out = Points::with_capacity(segs + 1);
    let mut p = old.points[0];
    out.push(p);
    for k in 0..segs {
        let w = weight((k as f32 + 0.5) / segs as f32);
        p += math::slerp(Quat::IDENTITY, q, w) * (old.points[k + 1] - old.points[k]);
        out.push(p);
    }
    out
}

/// The rotation that points the bent stem's point at `a` from its base toward `to`, for a weight
/// profile of exponent `power` (iterated: each step turns it by the remaining miss).
fn aim(old: &Stem, a: f32, to: Vec3, weight: &dyn Fn(f32) -> f32) -> (Quat, Vec3) {
    let base = old.base();
    let goal = (to - base).normalize_or_zero();
    let mut q = Quat::IDENTITY;
    let mut stem = old.clone();
    for _ in 0..ITERATIONS {
        stem.points = bent(old, q, weight);
        let now = (stem.point(a) - base).normalize_or_zero();
        if goal == Vec3::ZERO || now == Vec3::ZERO || now.dot(goal) > 1.0 - 1e-10 {
            break;
        }
        q = (Quat::from_rotation_arc(now, goal) * q).normalize();
    }
    stem.points = bent(old, q, weight);
    (q, stem.point(a))
}

/// The rotation and the weight profile's exponent that bring the point at `a` nearest to `to`:
/// a bend spread over the whole stem (exponent 2) shortens the chord from the base the most, one
/// gathered near the base (up to [`MAX_POWER`]) the least, so the exponent is bisected until the
/// point's distance from the base matches the target's.
fn solve(old: &Stem, a: f32, to: Vec3, weight: &dyn Fn(f32, f32) -> f32) -> (Quat, f32) {
    let base = old.base();
    let want = to.distance(base);
    let try_power = |power: f32| {
        let (q, p) = aim(old, a, to, &|s| weight(s, power));
        (q, p.distance(base) - want)
    };
    let (q, short) = try_power(MIN_POWER);
    if short >= 0.0 {
        return (q, MIN_POWER);
    }
    let (q_hi, short_hi) = try_power(MAX_POWER);
    if short_hi <= 0.0 {
        return (q_hi, MAX_POWER);
    }
    let (mut lo, mut hi, mut best) = (MIN_POWER, MAX_POWER, (q_hi, MAX_POWER));
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        let (q, miss) = try_power(mid);
        if miss < 0.0 {
            lo = mid;
        } else {
            (hi, best) = (mid, (q, mid));
        }
    }
    best
}

/// Stem `s` with at least [`MIN_SEGMENTS`] segments (its curve and radii resampled at equal
/// fractions), or as it is.
pub(crate) fn resampled(s: &Stem) -> Stem {
    let segs = s.points.len() - 1;
    if segs >= MIN_SEGMENTS {
        return s.clone();
    }
    let n = MIN_SEGMENTS;
    let mut cursor = s.points();
    let mut out = s.clone();
    out.points = (0..=n).map(|k| cursor.at(k as f32 / n as f32)).collect();
    if s.radii.is_some() {
        out.radii = Some((0..=n).map(|k| s.radius_at(k as f32 / n as f32)).collect());
    }
    out
}
