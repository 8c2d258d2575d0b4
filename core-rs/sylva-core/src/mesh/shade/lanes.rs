//! The bark's occlusion four vertices at a time in wasm, in the lanes of `simd128` vectors: the
//! light field read by [`CrownLight::sky_at_lanes`], then the light and its byte, each lane the
//! same IEEE operations in the same order as the one-vertex code in [`super`] (so the same
//! bytes; `scripts/wasm-parity.mjs` compares every preset's occlusion with the native one).
//! Natively the bark's occlusion is shared between the cores instead.

use crate::crown_shade::{CrownLight, MIN_LIGHT};
use core::arch::wasm32::*;

/// [`super::light_bytes`] in wasm.
#[target_feature(enable = "simd128")]
pub(super) fn light_bytes(c: &CrownLight, positions: &[f32], out: &mut [u8]) {
    let n = out.len() / 4 * 4;
    for (p, o) in positions.chunks_exact(12).zip(out[..n].chunks_exact_mut(4)) {
        // `to_byte`: clamped to 0..1 (NaN kept, then 0 through `i32`), times 255 plus a half,
        // through `i32`; 0 to 255 already, so the saturating narrowings to bytes cut nothing.
        let l = f32x4_pmin(f32x4_pmax(light4(c, p), f32x4_splat(0.0)), f32x4_splat(1.0));
        let i = i32x4_trunc_sat_f32x4(f32x4_add(f32x4_mul(l, f32x4_splat(255.0)), f32x4_splat(0.5)));
        let h = i16x8_narrow_i32x4(i, i);
        o.copy_from_slice(&u32x4_extract_lane::<0>(u8x16_narrow_i16x8(h, h)).to_le_bytes());
    }
    super::light_bytes_one_by_one(c, &positions[n * 3..], &mut out[n..]);
}

/// [`super::lights`] in wasm.
#[target_feature(enable = "simd128")]
pub(super) fn lights(c: &CrownLight, positions: &[f32], out: &mut [f32]) {
    let n = out.len() / 4 * 4;
    for (p, o) in positions.chunks_exact(12).zip(out[..n].chunks_exact_mut(4)) {
        let l = light4(c, p);
        o.copy_from_slice(&[
            f32x4_extract_lane::<0>(l),
            f32x4_extract_lane::<1>(l),
            f32x4_extract_lane::<2>(l),
            f32x4_extract_lane::<3>(l),
        ]);
    }
    super::lights_one_by_one(c, &positions[n * 3..], &mut out[n..]);
}

/// [`CrownLight::light`] of the sky at four points (`x, y, z` each: 12 floats).
#[target_feature(enable = "simd128")]
#[inline]
fn light4(c: &CrownLight, p: &[f32]) -> v128 {
    let axis = |a: usize| f32x4(p[a], p[3 + a], p[6 + a], p[9 + a]);
    let sky = c.sky_at_lanes(axis(0), axis(1), axis(2));
    f32x4_add(f32x4_splat(MIN_LIGHT), f32x4_mul(f32x4_splat(1.0 - MIN_LIGHT), sky))
}
