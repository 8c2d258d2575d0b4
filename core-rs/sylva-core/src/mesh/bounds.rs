//! [`Bounds`]: the box of a mesh's positions, and the per-lane ranges of records of floats
//! behind it (also the GLB export's accessor bounds). Plain comparisons throughout (NaN never
//! wins; on a tie the value already held). In wasm the records are compared four floats at a time
//! in `simd128` lanes, whose pseudo-minimum and pseudo-maximum are exactly these comparisons.

use serde::Serialize;

/// Axis-aligned bounds of all positions (m).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bounds {
    /// Smallest x, y, z.
    pub min: [f32; 3],
    /// Largest x, y, z.
    pub max: [f32; 3],
}

impl Bounds {
    /// The box of points (3 floats each), a zero box when there are none. Plain comparisons
    /// (NaN never wins): `f32::min` and `f32::max` are calls to `fminf` and `fmaxf` in wasm,
    /// which cost the bounds of a big tree milliseconds there.
    pub fn of(positions: &[f32]) -> Bounds {
        if positions.len() < 3 {
            return Bounds { min: [0.0; 3], max: [0.0; 3] };
        }
        // Four points per record: 12 lanes run as vector code where there is vector code.
        let whole = positions.len() / 12 * 12;
        let (lo4, hi4) = ranges::<12>(&positions[..whole]);
        let mut r = ranges::<3>(&positions[whole..]);
        for j in 0..4 {
            let part = |x: &[f32; 12]| std::array::from_fn(|k| x[3 * j + k]);
            r = merge_ranges(r, (part(&lo4), part(&hi4)));
        }
        Bounds { min: r.0, max: r.1 }
    }
}

/// Per-lane smallest and largest values of records of `N` floats (infinities for none), with
/// plain comparisons (NaN never wins).
pub(crate) fn ranges<const N: usize>(v: &[f32]) -> ([f32; N], [f32; N]) {
    #[cfg(target_arch = "wasm32")]
    if N % 4 == 0 && N <= 16 {
        return lanes::ranges(v);
    }
    let mut lo = [f32::INFINITY; N];
    let mut hi = [f32::NEG_INFINITY; N];
    for r in v.chunks_exact(N) {
        for k in 0..N {
            lo[k] = if r[k] < lo[k] { r[k] } else { lo[k] };
            hi[k] = if r[k] > hi[k] { r[k] } else { hi[k] };
        }
    }
    (lo, hi)
}

/// The smallest and largest of two [`ranges`], lane by lane (NaN never wins; on a tie the
/// first's value).
pub(crate) fn merge_ranges<const N: usize>(a: ([f32; N], [f32; N]), b: ([f32; N], [f32; N])) -> ([f32; N], [f32; N]) {
    (
        std::array::from_fn(|k| if b.0[k] < a.0[k] { b.0[k] } else { a.0[k] }),
        std::array::from_fn(|k| if b.1[k] > a.1[k] { b.1[k] } else { a.1[k] }),
    )
}

#[cfg(target_arch = "wasm32")]
mod lanes {
    use core::arch::wasm32::*;

    /// [`super::ranges`] of records of `N` floats (a multiple of 4, at most 16), four lanes at
    /// a time: `f32x4_pmin(lo, x)` is `x < lo ? x : lo` and `f32x4_pmax(hi, x)` is
    /// `hi < x ? x : hi`, the plain comparisons lane by lane.
    #[target_feature(enable = "simd128")]
    pub(super) fn ranges<const N: usize>(v: &[f32]) -> ([f32; N], [f32; N]) {
        let mut lo = [f32x4_splat(f32::INFINITY); 4];
        let mut hi = [f32x4_splat(f32::NEG_INFINITY); 4];
        for r in v.chunks_exact(N) {
            for q in 0..N / 4 {
                let x = f32x4(r[4 * q], r[4 * q + 1], r[4 * q + 2], r[4 * q + 3]);
                lo[q] = f32x4_pmin(lo[q], x);
                hi[q] = f32x4_pmax(hi[q], x);
            }
        }
        let lane = |v: &[v128; 4], k: usize| {
            let q = v[k / 4];
            match k % 4 {
                0 => f32x4_extract_lane::<0>(q),
                1 => f32x4_extract_lane::<1>(q),
                2 => f32x4_extract_lane::<2>(q),
                _ => f32x4_extract_lane::<3>(q),
            }
        };
        (std::array::from_fn(|k| lane(&lo, k)), std::array::from_fn(|k| lane(&hi, k)))
    }
}
