//! Crown shapes: Weber & Penn's ShapeRatio (1995, §4.3), the envelope that scales level-1 branch
//! lengths by their height on the trunk. Convention (as in the paper): `r = 1` at the crown base
//! (lowest branch), `r = 0` at the top, so every silhouette looks like its name. The envelope
//! preview in the app draws [`envelope_profile`], which calls this very function.

use crate::math::{sin, PI};
use crate::params::CrownShape;

impl CrownShape {
    /// Weber & Penn's ShapeRatio(shape, r) for `r` in [0, 1] (1 = crown base, 0 = top).
    pub fn ratio(self, r: f32) -> f32 {
        let r = r.clamp(0.0, 1.0);
        match self {
            CrownShape::Conical => 0.2 + 0.8 * r,
            CrownShape::Spherical => 0.2 + 0.8 * sin(PI * r),
            CrownShape::Hemispherical => 0.2 + 0.8 * sin(0.5 * PI * r),
            // Drawn: the outline's ratio comes from `crate::edits::crown::DrawnCrown` where a crown
            // edit is given; without one the shape is Cylindrical.
            CrownShape::Cylindrical | CrownShape::Drawn => 1.0,
            CrownShape::TaperedCylindrical => 0.5 + 0.5 * r,
            CrownShape::Flame => {
                if r <= 0.7 {
                    r / 0.7
                } else {
                    (1.0 - r) / 0.3
                }
            }
            CrownShape::InverseConical => 1.0 - 0.8 * r,
            CrownShape::TendFlame => {
                if r <= 0.7 {
                    0.5 + 0.5 * r / 0.7
                } else {
                    0.5 + 0.5 * (1.0 - r) / 0.3
                }
            }
        }
    }
}

/// Weber & Penn's shape 8, the pruning envelope, for `r` in [0, 1] (0 outside): rising as
/// `(r / (1 - peak))^power_high` up to the widest point at `r = 1 - peak`, then falling as
/// `((1 - r) / peak)^power_low` toward the crown base.
pub fn prune_envelope(r: f32, peak: f32, power_low: f32, power_high: f32) -> f32 {
    match prune_base(r, peak, power_low, power_high) {
        Some((base, power)) => crate::math::pow(base, power),
        None => 0.0,
    }
}

/// A lower bound of [`prune_envelope`] without its power (0 where none is known), at most
/// 0.999 of the envelope as `libm` computes it. For a base `x = m 2^e` in (0, 1] (`m` in
/// [1, 2)) and a power `p >= 0`: `x^p = e^(p ln x) >= 1 + p ln x >= 1 + p e ln 2`, and
/// `x^p >= x` when `p <= 1`; the margin covers the power's rounding many times over.
pub fn prune_envelope_floor(r: f32, peak: f32, power_low: f32, power_high: f32) -> f32 {
    let Some((x, p)) = prune_base(r, peak, power_low, power_high) else { return 0.0 };
    if !(f32::MIN_POSITIVE..=1.0).contains(&x) || !(0.0..=1e6).contains(&p) {
        return 0.0;
    }
    let e = ((x.to_bits() >> 23) & 0xff) as i32 - 127;
    let by_log = 1.0 + p * e as f32 * std::f32::consts::LN_2;
    let by_base = if p <= 1.0 { x } else { 0.0 };
    0.999 * crate::math::max(by_log, by_base)
}

/// [`prune_envelope`]'s base and power at `r` (None outside [0, 1]).
fn prune_base(r: f32, peak: f32, power_low: f32, power_high: f32) -> Option<(f32, f32)> {
    if !(0.0..=1.0).contains(&r) {
        return None;
    }
    let peak = peak.clamp(1e-6, 1.0 - 1e-6);
    Some(if r < 1.0 - peak { (r / (1.0 - peak), power_high) } else { ((1.0 - r) / peak, power_low) })
}

/// `samples` pairs `[r, ShapeRatio(r)]` for r evenly spaced from 0 (top) to 1 (crown base).
pub fn envelope_profile(shape: CrownShape, samples: usize) -> Vec<[f32; 2]> {
    let n = samples.max(2);
    (0..n)
        .map(|i| {
            let r = i as f32 / (n - 1) as f32;
            [r, shape.ratio(r)]
        })
        .collect()
}

/// Radius of a profile from [`crate::skeleton::preview_profile`] at height `y` (linear between samples; 0 outside).
pub fn profile_radius(profile: &[[f32; 2]], y: f32) -> f32 {
    profile
        .windows(2)
        .find(|w| y >= w[0][0] && y <= w[1][0])
        .map(|w| {
            let t = if w[1][0] > w[0][0] { (y - w[0][0]) / (w[1][0] - w[0][0]) } else { 0.0 };
            w[0][1] + (w[1][1] - w[0][1]) * t
        })
        .unwrap_or(0.0)
}

/// The envelope profile as a wireframe for the viewer: line-segment endpoint pairs (`x, y, z`
/// per point, two points per segment) forming a ring at every profile height and `meridians`
/// profile curves around the vertical axis.
pub fn preview_lines(profile: &[[f32; 2]], meridians: usize, ring_segments: usize) -> Vec<f32> {
    use crate::math::{cos, sin, TAU};
    let ring: Vec<(f32, f32)> = (0..=ring_segments)
        .map(|k| {
            let a = TAU * k as f32 / ring_segments as f32;
            (cos(a), sin(a))
        })
        .collect();
    let mut out = Vec::with_capacity(profile.len() * (ring_segments + meridians) * 6);
    let mut push = |x: f32, y: f32, z: f32| out.extend_from_slice(&[x, y, z]);
    for &[y, r] in profile.iter().filter(|p| p[1] > 0.0) {
        for w in ring.windows(2) {
            push(r * w[0].0, y, r * w[0].1);
            push(r * w[1].0, y, r * w[1].1);
        }
    }
    for m in 0..meridians {
        let (c, s) = ring[m * ring_segments / meridians.max(1)];
        for w in profile.windows(2) {
            push(w[0][1] * c, w[0][0], w[0][1] * s);
            push(w[1][1] * c, w[1][0], w[1][1] * s);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_prune_floor_is_below_the_envelope_and_close_for_small_powers() {
        let mut close = 0;
        for peak in [0.0, 0.05, 0.3, 0.6, 0.95, 1.0] {
            for power in [0.0, 0.001, 0.01, 0.3, 0.5, 0.999, 1.0, 1.5, 4.0, 10.0] {
                for i in 0..=20_000 {
                    let r = i as f32 / 20_000.0;
                    let (floor, env) =
                        (prune_envelope_floor(r, peak, power, power), prune_envelope(r, peak, power, power));
                    assert!(
                        floor <= 0.999 * env + 1e-7 && floor >= 0.0,
                        "r {r} peak {peak} power {power}: {floor} {env}"
                    );
                    close += usize::from(power <= 0.01 && env > 0.0 && floor > 0.99 * env);
                }
            }
            assert_eq!(prune_envelope_floor(1.5, peak, 0.5, 0.5), 0.0);
            assert_eq!(prune_envelope_floor(-0.5, peak, 0.5, 0.5), 0.0);
        }
        // Where a willow's envelope is nearly flat (a power of a thousandth), the floor is
        // within a per cent of it almost everywhere: the power is then rarely needed.
        assert!(close > 6 * 2 * 19_000, "{close}");
    }

    #[test]
    fn names_round_trip() {
        for (i, l) in CrownShape::LABELS.iter().enumerate() {
            assert_eq!(CrownShape::from_name(l), Some(CrownShape::from_index(i)));
        }
        assert_eq!(CrownShape::from_name("inverse-conical"), Some(CrownShape::InverseConical));
        assert_eq!(CrownShape::from_name("nope"), None);
    }
}
