//! The veins made visible in 3D: the vein field baked into two RGBA8 textures over the UV box.
//!
//! **Layout** (both buffers): `width × height` texels, both powers of two; row-major, 4 bytes
//! per texel; **row 0 is `v = 0`** (the bottom of the blade's box), so the buffers upload to
//! WebGL as they are (`flipY = false`); texel `(i, j)` covers
//! `u ∈ [i, i+1)/width`, `v ∈ [j, j+1)/height`.
//!
//! * `color`: RGB = blade green blended toward a pale vein colour by the vein coverage, slightly
//!   lighter on the ridges; A = 255 inside the outline (texel centre), 0 outside (for cards).
//! * `normal`: tangent-space normal of the displaced surface (`x` along `u`, `y` along `v`,
//!   `z` out of the front face), each component encoded as `(n + 1) / 2 · 255`; A = ridge height
//!   0..255 (the midrib crest is 255).
//!
//! The height is `2^leaf_texture_level` texels; the width is the power of two nearest
//! `height × box width / box height` (at least 4).

use crate::leaf::field::VeinField;
use crate::leaf::raster::fill_rows;
use crate::leaf::uv::UvFrame;
use glam::{Vec2, Vec3};

/// The baked textures.
#[derive(Clone, Debug, PartialEq)]
pub struct LeafTexture {
    /// Texels per row (a power of two).
    pub width: u32,
    /// Rows (a power of two).
    pub height: u32,
    /// RGBA8 colour, see the module docs.
    pub color: Vec<u8>,
    /// RGBA8 tangent-space normal + ridge height, see the module docs.
    pub normal: Vec<u8>,
}

/// The blade's green (sRGB, 0..1), the colour the leaf's tint multiplies (and what the
/// seasons' palettes are given against, [`crate::season`]).
pub const BLADE: [f32; 3] = [0.30, 0.52, 0.18];

/// Texture size for a UV box: `(width, height)`, both powers of two.
pub fn size(level: u32, frame: &UvFrame) -> (usize, usize) {
    let h = 1usize << level;
    let target = h as f32 * frame.size.x / frame.size.y;
    let mut best = (f32::INFINITY, 4usize);
    for k in 2..=12 {
        let w = (1usize << k) as f32;
        let err = (w / target).max(target / w);
        if err < best.0 {
            best = (err, 1 << k);
        }
    }
    (best.1, h)
}

/// 0..1 to 0..255, rounded (the float-to-int cast saturates, so out-of-range values clamp).
#[inline]
pub(crate) fn byte(x: f32) -> u8 {
    (x * 255.0 + 0.5) as u8
}

/// Bakes the field; `displacement` is the ridge height in leaf units (for the normals).
#[inline(never)]
pub fn bake(field: &VeinField, outline: &[Vec2], displacement: f32) -> LeafTexture {
    let (w, h) = (field.w, field.h);
    let texel = field.texel();
    let inside = fill_rows(outline, field.frame.lo, texel, w, h);
    let blade = Vec3::from(BLADE);
    let vein = Vec3::new(0.72, 0.80, 0.45);
    let blade_rgb = [byte(blade.x), byte(blade.y), byte(blade.z)];
    let mut color = vec![0u8; w * h * 4];
    let mut normal = vec![0u8; w * h * 4];
    let hg = &field.height;
    let (sx, sy) = (displacement / (2.0 * texel.x), displacement / (2.0 * texel.y));
    for y in 0..h {
        let (yd, yu) = (y.saturating_sub(1) * w, (y + 1).min(h - 1) * w);
        let row = y * w;
        let crow = &mut color[4 * row..4 * (row + w)];
        let nrow = &mut normal[4 * row..4 * (row + w)];
        for (x, (c4, n4)) in crow.chunks_exact_mut(4).zip(nrow.chunks_exact_mut(4)).enumerate() {
            let c4: &mut [u8; 4] = c4.try_into().expect("4 bytes");
            let n4: &mut [u8; 4] = n4.try_into().expect("4 bytes");
            let i = row + x;
            let alpha = if inside[i] { 255 } else { 0 };
            let (c, ht) = (field.cover[i], hg[i]);
            let (xl, xr) = (row + x.saturating_sub(1), row + (x + 1).min(w - 1));
            let (dx, dy) = (hg[xr] - hg[xl], hg[yu + x] - hg[yd + x]);
            if c == 0.0 && ht == 0.0 {
                *c4 = [blade_rgb[0], blade_rgb[1], blade_rgb[2], alpha];
            } else {
                let rgb = blade + (vein - blade) * c + Vec3::splat(0.06 * ht);
                *c4 = [byte(rgb.x), byte(rgb.y), byte(rgb.z), alpha];
            }
            if dx == 0.0 && dy == 0.0 {
                *n4 = [128, 128, 255, byte(ht)];
            } else {
                // normalize((-gx, -gy, 1)) with the IEEE square root (a single wasm instruction).
                let (gx, gy) = (-sx * dx, -sy * dy);
                let inv = 1.0 / (gx * gx + gy * gy + 1.0).sqrt();
                *n4 = [byte(0.5 * gx * inv + 0.5), byte(0.5 * gy * inv + 0.5), byte(0.5 * inv + 0.5), byte(ht)];
            }
        }
    }
    LeafTexture { width: w as u32, height: h as u32, color, normal }
}
