//! Crown shapes: Weber & Penn's ShapeRatio (1995, §4.3), the envelope that scales level-1 branch
//! lengths by their height on the trunk. Convention (ANCHORS §2): `r = 1` at the crown base
//! (lowest branch), `r = 0` at the top, so every silhouette looks like its name. The envelope
//! preview in the app draws [`envelope_profile`], which calls this very function.

use crate::math::{sin, PI};
use crate::param_enum::param_enum;

param_enum! {
    /// The eight crown envelopes of the Crown Shape guide, in Weber & Penn's numbering.
    CrownShape {
        /// Christmas tree: longest branches at the crown base (fir, spruce).
        Conical = 0, "Conical";
        /// Ball: longest in the middle (oak, maple).
        Spherical = 1, "Spherical";
        /// Dome: longest at the base, rounding to the top (umbrella trees).
        Hemispherical = 2, "Hemispherical";
        /// All branches the same length (the default).
        Cylindrical = 3, "Cylindrical";
        /// A gentle taper from base to top.
        TaperedCylindrical = 4, "Tapered Cylindrical";
        /// Widest at 70% of the crown from the top, pointed tip (cedar, cypress).
        Flame = 5, "Flame";
        /// Widest at the top: fan or mushroom.
        InverseConical = 6, "Inverse Conical";
        /// A softer flame.
        TendFlame = 7, "Tend Flame";
    }
}

impl CrownShape {
    /// Weber & Penn's ShapeRatio(shape, r) for `r` in [0, 1] (1 = crown base, 0 = top).
    pub fn ratio(self, r: f32) -> f32 {
        let r = r.clamp(0.0, 1.0);
        match self {
            CrownShape::Conical => 0.2 + 0.8 * r,
            CrownShape::Spherical => 0.2 + 0.8 * sin(PI * r),
            CrownShape::Hemispherical => 0.2 + 0.8 * sin(0.5 * PI * r),
            CrownShape::Cylindrical => 1.0,
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
    if !(0.0..=1.0).contains(&r) {
        return 0.0;
    }
    let peak = peak.clamp(1e-6, 1.0 - 1e-6);
    if r < 1.0 - peak {
        crate::math::pow(r / (1.0 - peak), power_high)
    } else {
        crate::math::pow((1.0 - r) / peak, power_low)
    }
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

/// The crown envelope of a generated tree for the viewer's Show Preview: pairs
/// `[height, radius]` (m, bottom to top) of a solid of revolution around the vertical axis that
/// holds every level-1 branch. At each attachment height on the trunk (and its split clones)
/// the longest possible level-1 branch is `L_trunk * (l1_length + l1_length_v) *
/// ShapeRatio(shape, r)`, the very function the generator uses; the branch reaches at most a
/// sphere of that radius around its attachment point, and the profile is the outline of the
/// union of those spheres.
pub fn preview_profile(
    skeleton: &crate::skeleton::Skeleton,
    p: &crate::params::TreeParams,
    samples: usize,
) -> Vec<[f32; 2]> {
    let l1 = &p.level[1];
    let max_len = l1.length + l1.length_v;
    // (centre, reach) of the attachment spheres.
    let mut spheres: Vec<(glam::Vec3, f32)> = Vec::new();
    for stem in skeleton.stems.iter().filter(|s| s.level == 0) {
        let chain = stem.chain_length;
        let span = chain - skeleton.crown_base;
        for i in 0..=48 {
            let z = i as f32 / 48.0;
            let along = stem.chain_start * chain + z * stem.length;
            if along < skeleton.crown_base || span <= 0.0 {
                continue;
            }
            let r = (chain - along) / span;
            let (c, _) = stem.sample(z);
            // Inflated by the sampling step, so attachment points between samples are covered.
            spheres.push((c, chain * max_len * p.shape.ratio(r) + stem.length / 48.0));
        }
    }
    if spheres.is_empty() || p.levels < 2 {
        return Vec::new();
    }
    let lo = spheres.iter().map(|(c, l)| c.y - l).fold(f32::INFINITY, f32::min).max(0.0);
    let hi = spheres.iter().map(|(c, l)| c.y + l).fold(f32::NEG_INFINITY, f32::max);
    let n = samples.max(3);
    (0..n)
        .map(|i| {
            let y = lo + (hi - lo) * i as f32 / (n - 1) as f32;
            let r = spheres
                .iter()
                .filter_map(|(c, l)| {
                    let dy = y - c.y;
                    (dy.abs() <= *l).then(|| (c.x * c.x + c.z * c.z).sqrt() + (l * l - dy * dy).sqrt())
                })
                .fold(0.0f32, f32::max);
            [y, r]
        })
        .collect()
}

/// Radius of a profile from [`preview_profile`] at height `y` (linear between samples; 0 outside).
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
    fn names_round_trip() {
        for (i, l) in CrownShape::LABELS.iter().enumerate() {
            assert_eq!(CrownShape::from_name(l), Some(CrownShape::from_index(i)));
        }
        assert_eq!(CrownShape::from_name("inverse-conical"), Some(CrownShape::InverseConical));
        assert_eq!(CrownShape::from_name("nope"), None);
    }
}
