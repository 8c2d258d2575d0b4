//! The bark's occlusion four vertices at a time in wasm, in the lanes of `simd128` vectors: the
//! light field read by [`CrownLight::sky_at_lanes`], then the light and its byte, each lane the
//! same IEEE operations in the same order as the one-vertex code in [`super`] (so the same
//! bytes; `scripts/wasm-parity.mjs` compares every preset's occlusion with the native one).
//! Natively the bark's occlusion is shared between the cores instead.

use super::{cavity_light, Hole};
use crate::crown_shade::{CrownLight, MIN_LIGHT};
use core::arch::wasm32::*;
use glam::Vec3;

/// [`super::light_bytes`] in wasm: the light of four vertices at a time, darkened by each of
/// `cavities` (a hole and its stem's radius) as [`cavity_light`] does, then their bytes.
#[target_feature(enable = "simd128")]
pub(super) fn light_bytes(c: &CrownLight, cavities: &[(&Hole, f32)], positions: &[f32], out: &mut [u8]) {
    let n = out.len() / 4 * 4;
    let quads = positions.chunks_exact(12).zip(out[..n].chunks_exact_mut(4));
    // Most trees have no holes: the light alone, in its own tight loop.
    if cavities.is_empty() {
        for (p, o) in quads {
            o.copy_from_slice(&bytes4(light4(c, p)));
        }
    } else {
        for (p, o) in quads {
            let mut light = light4(c, p);
            for &(h, stem_radius) in cavities {
                light = f32x4_mul(light, cavity4(h, stem_radius, p));
            }
            o.copy_from_slice(&bytes4(light));
        }
    }
    super::light_bytes_one_by_one(c, cavities, &positions[n * 3..], &mut out[n..]);
}

/// `to_byte` of four lights: clamped to 0..1 (NaN kept, then 0 through `i32`), times 255 plus a
/// half, through `i32`; 0 to 255 already, so the saturating narrowings to bytes cut nothing.
#[target_feature(enable = "simd128")]
#[inline]
fn bytes4(light: v128) -> [u8; 4] {
    let l = f32x4_pmin(f32x4_pmax(light, f32x4_splat(0.0)), f32x4_splat(1.0));
    let i = i32x4_trunc_sat_f32x4(f32x4_add(f32x4_mul(l, f32x4_splat(255.0)), f32x4_splat(0.5)));
    let h = i16x8_narrow_i32x4(i, i);
    u32x4_extract_lane::<0>(u8x16_narrow_i16x8(h, h)).to_le_bytes()
}

/// [`cavity_light`] at four points (`x, y, z` each: 12 floats): 1 where a point is above the
/// opening's plane or farther from its axis than 1.6 radii (its first two tests, the same
/// operations lane by lane), else the one-point function (the few points inside a cavity).
#[target_feature(enable = "simd128")]
#[inline]
fn cavity4(h: &Hole, stem_radius: f32, p: &[f32]) -> v128 {
    let [x, y, z] = xyz(p);
    let (rx, ry, rz) = (
        f32x4_sub(x, f32x4_splat(h.centre.x)),
        f32x4_sub(y, f32x4_splat(h.centre.y)),
        f32x4_sub(z, f32x4_splat(h.centre.z)),
    );
    let n = h.normal;
    // -(rel · normal), glam's `dot` order.
    let dot = f32x4_add(
        f32x4_add(f32x4_mul(rx, f32x4_splat(n.x)), f32x4_mul(ry, f32x4_splat(n.y))),
        f32x4_mul(rz, f32x4_splat(n.z)),
    );
    let below = f32x4_neg(dot);
    // |rel + normal below|, glam's `length`.
    let (lx, ly, lz) = (
        f32x4_add(rx, f32x4_mul(f32x4_splat(n.x), below)),
        f32x4_add(ry, f32x4_mul(f32x4_splat(n.y), below)),
        f32x4_add(rz, f32x4_mul(f32x4_splat(n.z), below)),
    );
    let lateral = f32x4_sqrt(f32x4_add(f32x4_add(f32x4_mul(lx, lx), f32x4_mul(ly, ly)), f32x4_mul(lz, lz)));
    let outside = v128_or(f32x4_le(below, f32x4_splat(0.0)), f32x4_gt(lateral, f32x4_splat(1.6 * h.radius)));
    let inside = !i32x4_bitmask(outside) & 0xf;
    if inside == 0 {
        return f32x4_splat(1.0);
    }
    let mut c = [1.0f32; 4];
    for k in (0..4).filter(|k| inside & (1 << k) != 0) {
        c[k] = cavity_light(h, stem_radius, Vec3::new(p[3 * k], p[3 * k + 1], p[3 * k + 2]));
    }
    f32x4(c[0], c[1], c[2], c[3])
}

/// [`CrownLight::light`] of the sky at four points (`x, y, z` each: 12 floats).
#[target_feature(enable = "simd128")]
#[inline]
fn light4(c: &CrownLight, p: &[f32]) -> v128 {
    let [x, y, z] = xyz(p);
    let sky = c.sky_at_lanes(x, y, z);
    f32x4_add(f32x4_splat(MIN_LIGHT), f32x4_mul(f32x4_splat(1.0 - MIN_LIGHT), sky))
}

/// Four points (`x, y, z` each: 12 floats) as their `x`, `y` and `z` lanes: three loads and
/// two shuffles per axis.
#[target_feature(enable = "simd128")]
#[inline]
fn xyz(p: &[f32]) -> [v128; 3] {
    let p: &[f32; 12] = p.try_into().expect("four points");
    let v = |k: usize| f32x4(p[k], p[k + 1], p[k + 2], p[k + 3]);
    let (a, b, c) = (v(0), v(4), v(8));
    [
        i32x4_shuffle::<0, 1, 2, 5>(i32x4_shuffle::<0, 3, 6, 0>(a, b), c),
        i32x4_shuffle::<0, 1, 2, 6>(i32x4_shuffle::<1, 4, 7, 0>(a, b), c),
        i32x4_shuffle::<0, 1, 4, 7>(i32x4_shuffle::<2, 5, 0, 0>(a, b), c),
    ]
}
