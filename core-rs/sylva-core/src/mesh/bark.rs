//! Procedural bark texture, baked in the core (no downloaded images): a tileable height field of
//! vertical fissures between bark plates, gives an RGBA colour map and a tangent-space normal
//! map. Bark UVs run `u` around the stem (0..1) and `v` along it at one unit per circumference,
//! so one tile covers a square of bark and the fissures follow the stem.

use crate::math::{sin, TAU};

/// A baked texture: `size * size` texels, 4 bytes each (RGBA), rows bottom to top (v up).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Edge length in texels (a power of two).
    pub size: usize,
    /// `size * size * 4` bytes.
    pub rgba: Vec<u8>,
}

/// Integer hash of a lattice point (periodic with period `p` in both axes) to [0, 1).
fn lattice(x: i32, y: i32, p: i32, seed: u32) -> f32 {
    let (x, y) = (x.rem_euclid(p) as u32, y.rem_euclid(p) as u32);
    let mut h = x.wrapping_mul(0x8da6_b343) ^ y.wrapping_mul(0xd816_3841) ^ seed.wrapping_mul(0xcb1a_b31f);
    h ^= h >> 13;
    h = h.wrapping_mul(0x5bd1_e995);
    h ^= h >> 15;
    (h >> 8) as f32 / 16_777_216.0
}

/// Smooth value noise at (x, y) in lattice units, periodic with period `p`.
fn noise(x: f32, y: f32, p: i32, seed: u32) -> f32 {
    let (xi, yi) = (x.floor() as i32, y.floor() as i32);
    let (fx, fy) = (x - xi as f32, y - yi as f32);
    let s = |t: f32| t * t * (3.0 - 2.0 * t);
    let (sx, sy) = (s(fx), s(fy));
    let a = lattice(xi, yi, p, seed) + (lattice(xi + 1, yi, p, seed) - lattice(xi, yi, p, seed)) * sx;
    let b = lattice(xi, yi + 1, p, seed) + (lattice(xi + 1, yi + 1, p, seed) - lattice(xi, yi + 1, p, seed)) * sx;
    a + (b - a) * sy
}

/// Bark height at texture coordinates (u, v) in [0, 1): plates separated by wavy vertical
/// fissures (`ridges` across the tile), with fine grain on the plates.
fn height(u: f32, v: f32, ridges: f32, seed: u32) -> f32 {
    let warp = noise(u * 4.0, v * 4.0, 4, seed) * 0.9 + noise(u * 8.0, v * 8.0, 8, seed + 1) * 0.3;
    let phase = u * ridges + warp;
    let f = phase - phase.floor();
    let plate = crate::math::pow(1.0 - (2.0 * f - 1.0).abs(), 0.35); // 0 in the fissure, 1 on the plate
    let breaks = noise(u * ridges, v * 6.0, (ridges as i32).max(1), seed + 2);
    let grain = 0.5 + 0.5 * sin(TAU * (v * 32.0 + noise(u * 16.0, v * 16.0, 16, seed + 3)));
    (0.75 * plate * (0.6 + 0.4 * breaks) + 0.1 * grain).clamp(0.0, 1.0)
}

/// Bake the bark colour (RGBA) and tangent-space normal (RGB = xyz * 0.5 + 0.5, A = height)
/// maps, `size` texels square (a power of two, at least 16).
pub fn bake(size: usize, seed: u32) -> (Texture, Texture) {
    let size = size.next_power_of_two().max(16);
    let ridges = 7.0;
    let h: Vec<f32> = (0..size * size)
        .map(|i| height((i % size) as f32 / size as f32, (i / size) as f32 / size as f32, ridges, seed))
        .collect();
    let at = |x: usize, y: usize| h[(y % size) * size + (x % size)];
    let mut color = Vec::with_capacity(size * size * 4);
    let mut normal = Vec::with_capacity(size * size * 4);
    let strength = 2.5;
    for y in 0..size {
        for x in 0..size {
            let v = at(x, y);
            let tone = noise(x as f32 / size as f32 * 8.0, y as f32 / size as f32 * 8.0, 8, seed + 7);
            // Dark fissures, warm grey-brown plates with some mottling.
            let light = 0.35 + 0.65 * v;
            let rgb = [(92.0 + 40.0 * tone) * light, (68.0 + 28.0 * tone) * light, (50.0 + 18.0 * tone) * light];
            color.extend(rgb.iter().map(|c| c.clamp(0.0, 255.0) as u8));
            color.push(255);
            let dx = (at(x + 1, y) - at(x + size - 1, y)) * strength;
            let dy = (at(x, y + 1) - at(x, y + size - 1)) * strength;
            let len = (dx * dx + dy * dy + 1.0).sqrt();
            let n = [-dx / len, -dy / len, 1.0 / len];
            normal.extend(n.iter().map(|c| ((c * 0.5 + 0.5) * 255.0).round() as u8));
            normal.push((v * 255.0) as u8);
        }
    }
    (Texture { size, rgba: color }, Texture { size, rgba: normal })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn textures_tile_and_have_fissures() {
        let (c, n) = bake(64, 1);
        assert_eq!(c.rgba.len(), 64 * 64 * 4);
        assert_eq!(n.rgba.len(), c.rgba.len());
        // Tileable: the height field wraps (noise is periodic), so opposite edges are close.
        let h = |x: usize, y: usize| n.rgba[(y * 64 + x) * 4 + 3] as i32;
        let seam: i32 = (0..64).map(|y| (h(0, y) - h(63, y)).abs()).max().unwrap();
        let inner: i32 = (0..64).map(|y| (h(31, y) - h(32, y)).abs()).max().unwrap();
        assert!(seam <= inner.max(8) * 3, "seam jump {seam} vs inner {inner}");
        // Fissures: a range of heights from deep to high plates.
        let (lo, hi) = (0..64 * 64).map(|i| n.rgba[i * 4 + 3]).fold((255u8, 0u8), |(a, b), v| (a.min(v), b.max(v)));
        assert!(lo < 40 && hi > 150, "heights {lo}..{hi}");
        // Normals are unit length (within 8-bit encoding).
        for px in n.rgba.chunks_exact(4) {
            let v: Vec<f32> = px[..3].iter().map(|&b| b as f32 / 255.0 * 2.0 - 1.0).collect();
            let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            assert!((len - 1.0).abs() < 0.02, "{len}");
        }
        assert_eq!(bake(64, 1), (c, n), "deterministic");
    }
}
