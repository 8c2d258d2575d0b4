//! Crown shapes: Weber & Penn's ShapeRatio (1995, §4.3), the envelope that scales level-1 branch
//! lengths by their height on the trunk. Convention (ANCHORS §2): `r = 1` at the crown base
//! (lowest branch), `r = 0` at the top, so every silhouette looks like its name. The envelope
//! preview in the app draws [`envelope_profile`], which calls this very function.

use crate::math::{sin, PI};
use serde::Serialize;

/// The eight crown envelopes of the Crown Shape guide, in Weber & Penn's numbering.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum CrownShape {
    /// Christmas tree: longest branches at the crown base (fir, spruce).
    Conical = 0,
    /// Ball: longest in the middle (oak, maple).
    Spherical = 1,
    /// Dome: longest at the base, rounding to the top (umbrella trees).
    Hemispherical = 2,
    /// All branches the same length (the default).
    Cylindrical = 3,
    /// A gentle taper from base to top.
    TaperedCylindrical = 4,
    /// Widest at 70% of the crown from the top, pointed tip (cedar, cypress).
    Flame = 5,
    /// Widest at the top: fan or mushroom.
    InverseConical = 6,
    /// A softer flame.
    TendFlame = 7,
}

impl CrownShape {
    /// All shapes in index order.
    pub const ALL: [CrownShape; 8] = [
        CrownShape::Conical,
        CrownShape::Spherical,
        CrownShape::Hemispherical,
        CrownShape::Cylindrical,
        CrownShape::TaperedCylindrical,
        CrownShape::Flame,
        CrownShape::InverseConical,
        CrownShape::TendFlame,
    ];
    /// Display labels in index order (the registry's enum options).
    pub const LABELS: [&'static str; 8] = [
        "Conical",
        "Spherical",
        "Hemispherical",
        "Cylindrical",
        "Tapered Cylindrical",
        "Flame",
        "Inverse Conical",
        "Tend Flame",
    ];

    /// The shape with this index (clamped into range).
    pub fn from_index(i: usize) -> CrownShape {
        CrownShape::ALL[i.min(7)]
    }

    /// Look a shape up by label, case- and separator-insensitively (`"inverse-conical"` works).
    pub fn from_name(name: &str) -> Option<CrownShape> {
        let norm = |s: &str| s.chars().filter(|c| c.is_ascii_alphanumeric()).collect::<String>().to_ascii_lowercase();
        let want = norm(name);
        CrownShape::LABELS.iter().position(|l| norm(l) == want).map(CrownShape::from_index)
    }

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
