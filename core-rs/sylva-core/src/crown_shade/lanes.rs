//! [`CrownLight::sky_at_lanes`]: the light field read at four points at once, in the lanes of
//! wasm `simd128` vectors, for the bark's occlusion (every bark vertex reads it,
//! [`crate::mesh::shade`]) and the leaves' tints ([`super::darken_with`], four leaves at a time).
//! The same IEEE operations in the same order as [`CrownLight::sky_at`], lane by lane (no fused
//! multiply-add, nothing reordered), so the same bits; `scripts/wasm-parity.mjs` compares every
//! case's hash, which holds the occlusion and the tints, with the native one.

use super::CrownLight;
use core::arch::wasm32::*;

impl CrownLight {
    /// [`CrownLight::sky_at`] at the four points (`x`, `y`, `z`), one per lane.
    #[target_feature(enable = "simd128")]
    #[inline]
    pub fn sky_at_lanes(&self, x: v128, y: v128, z: v128) -> v128 {
        let [nx, ny, nz] = self.n;
        let cell = f32x4_splat(self.cell);
        // (p - min) / cell - 0.5 along each axis.
        let f = |v: v128, min: f32| f32x4_sub(f32x4_div(f32x4_sub(v, f32x4_splat(min)), cell), f32x4_splat(0.5));
        let (fx, fy, fz) = (f(x, self.min.x), f(y, self.min.y), f(z, self.min.z));
        // Above the grid: the open sky.
        let above = f32x4_gt(fy, f32x4_splat((ny - 1) as f32));
        // `f32::clamp(0, n - 1)` (below the low end the low end, then above the high end the
        // high end, NaN kept) as a pseudo-maximum and a pseudo-minimum; the lower cell centre
        // through `i32` and the fraction past it.
        let axis = |v: v128, n: usize| {
            let v = f32x4_pmin(f32x4_pmax(v, f32x4_splat(0.0)), f32x4_splat((n - 1) as f32));
            let i = i32x4_trunc_sat_f32x4(v);
            (i, f32x4_sub(v, f32x4_convert_i32x4(i)))
        };
        let ((x0, tx), (y0, ty), (z0, tz)) = (axis(fx, nx), axis(fy, ny), axis(fz, nz));
        // The cell's record, (z0 ny + y0) nx + x0 (at most 21³ cells).
        let at = i32x4_add(i32x4_mul(i32x4_add(i32x4_mul(z0, i32x4_splat(ny as i32)), y0), i32x4_splat(nx as i32)), x0);
        let rec = [
            &self.corners[i32x4_extract_lane::<0>(at) as usize],
            &self.corners[i32x4_extract_lane::<1>(at) as usize],
            &self.corners[i32x4_extract_lane::<2>(at) as usize],
            &self.corners[i32x4_extract_lane::<3>(at) as usize],
        ];
        // Each record's two halves as vectors, turned into one vector per corner (lane k the
        // corner of record k): a 4 × 4 transpose of each half.
        let half = |h: usize| transpose(rec.map(|r| &r[4 * h..4 * h + 4]));
        let ([c0, c1, c2, c3], [c4, c5, c6, c7]) = (half(0), half(1));
        let lerp = |a: v128, b: v128, t: v128| f32x4_add(a, f32x4_mul(f32x4_sub(b, a), t));
        let (x00, x10) = (lerp(c0, c1, tx), lerp(c2, c3, tx));
        let (x01, x11) = (lerp(c4, c5, tx), lerp(c6, c7, tx));
        let sky = lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
        v128_bitselect(f32x4_splat(1.0), sky, above)
    }
}

/// [`super::darken_with`] in wasm: each leaf's light read four leaves at a time.
#[target_feature(enable = "simd128")]
pub(super) fn darken(field: &CrownLight, matrices: &[f32], colors: &mut [f32]) {
    let n = colors.len() / 3 / 4 * 4;
    for (m, c) in matrices.chunks_exact(64).zip(colors[..3 * n].chunks_exact_mut(12)) {
        // The leaf's base plus half its length axis (`y`): where its light is read. Each
        // matrix's column as a vector, the four leaves' columns transposed into lanes.
        let columns = |at: usize| transpose(std::array::from_fn(|k| &m[16 * k + at..16 * k + at + 4]));
        let (base, y) = (columns(12), columns(4));
        let axis = |a: usize| f32x4_add(base[a], f32x4_mul(f32x4_splat(0.5), y[a]));
        let sky = field.sky_at_lanes(axis(0), axis(1), axis(2));
        let l = f32x4_add(f32x4_splat(super::MIN_LIGHT), f32x4_mul(f32x4_splat(1.0 - super::MIN_LIGHT), sky));
        let l = [
            f32x4_extract_lane::<0>(l),
            f32x4_extract_lane::<1>(l),
            f32x4_extract_lane::<2>(l),
            f32x4_extract_lane::<3>(l),
        ];
        for (c, l) in c.chunks_exact_mut(3).zip(l) {
            c.iter_mut().for_each(|v| *v *= l);
        }
    }
    super::darken_one_by_one(field, &matrices[16 * n..], &mut colors[3 * n..]);
}

/// Four runs of four floats as four vectors, one per position in the runs (lane `k` from run
/// `k`): a 4 × 4 transpose, four loads and eight shuffles.
#[target_feature(enable = "simd128")]
#[inline]
fn transpose(runs: [&[f32]; 4]) -> [v128; 4] {
    let v = |k: usize| {
        let r: &[f32; 4] = runs[k].try_into().expect("runs of four");
        f32x4(r[0], r[1], r[2], r[3])
    };
    let (a, b, c, d) = (v(0), v(1), v(2), v(3));
    let (ab_lo, ab_hi) = (i32x4_shuffle::<0, 4, 1, 5>(a, b), i32x4_shuffle::<2, 6, 3, 7>(a, b));
    let (cd_lo, cd_hi) = (i32x4_shuffle::<0, 4, 1, 5>(c, d), i32x4_shuffle::<2, 6, 3, 7>(c, d));
    [
        i32x4_shuffle::<0, 1, 4, 5>(ab_lo, cd_lo),
        i32x4_shuffle::<2, 3, 6, 7>(ab_lo, cd_lo),
        i32x4_shuffle::<0, 1, 4, 5>(ab_hi, cd_hi),
        i32x4_shuffle::<2, 3, 6, 7>(ab_hi, cd_hi),
    ]
}
