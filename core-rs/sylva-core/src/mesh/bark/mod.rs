//! Procedural bark textures by species type (`docs/look.md`, "Bark types"), baked in the core (no downloaded
//! images): for each [`BarkType`] a tileable colour map, tangent-space normal map (alpha =
//! height) and an occlusion-roughness-metal map, so the viewer and the GLB / OBJ exports show the
//! same bark. The patterns themselves are in [`patterns`]; the tileable noise in [`noise`].
//!
//! Bark UVs run `u` around the stem (0..1) and `v` along it at one unit per circumference, so one
//! tile covers a square of bark. How many tiles go around a stem follows its girth the way real
//! bark does ([`BarkStyle::repeats`]): the pattern grows with the square root of the girth, so a
//! thick trunk shows wide plates and deep furrows, a branch finer ones, and stems thinner than
//! [`BarkStyle::young_radius`] fade to smooth young bark of [`BarkStyle::young_rgb`]. The viewer
//! applies that rule per fragment from each vertex's stem radius (the wind data's `radius`).

pub mod end_grain;
pub mod noise;
pub mod patterns;

use crate::math::pow;
use crate::params::BarkType;
use serde::Serialize;

/// A baked texture: `size * size` texels, 4 bytes each (RGBA), rows bottom to top (v up).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Edge length in texels (a power of two).
    pub size: usize,
    /// `size * size * 4` bytes.
    pub rgba: Vec<u8>,
}

/// The three maps of one bark type.
#[derive(Clone, Debug, PartialEq)]
pub struct BarkMaps {
    /// sRGB colour, alpha 255.
    pub color: Texture,
    /// Tangent-space normal (RGB = xyz * 0.5 + 0.5), alpha = height.
    pub normal: Texture,
    /// glTF's packed occlusion (R), roughness (G) and metalness (B = 0), alpha 255.
    pub orm: Texture,
}

/// How a bark type is laid on a stem (see the module docs), sent to the viewer as JSON.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BarkStyle {
    /// Width of one texture tile (m) on a stem of 1 m girth; on a stem of girth `g` (m) a tile
    /// is `tile_at_1m * sqrt(g)` wide.
    pub tile_at_1m: f32,
    /// Below this stem radius (m) the bark turns young: smooth and of [`Self::young_rgb`].
    pub young_radius: f32,
    /// Linear RGB of young bark (thin stems).
    pub young_rgb: [f32; 3],
    /// How strongly the normal map is applied on old bark.
    pub relief: f32,
}

impl BarkStyle {
    /// Tiles around a stem of radius `r` (m): `girth / (tile_at_1m * sqrt(girth))`, at least 1.
    pub fn repeats(&self, r: f32) -> f32 {
        let girth = crate::math::TAU * r.max(0.0);
        (girth.sqrt() / self.tile_at_1m).max(1.0)
    }
}

impl BarkType {
    /// Layout of this type on a stem (tile size, young bark).
    pub fn style(self) -> BarkStyle {
        match self {
            // Oak: ridges ~4 cm apart on a 1 m girth (6 per tile); young shoots olive grey.
            BarkType::Furrowed => {
                BarkStyle { tile_at_1m: 0.24, young_radius: 0.03, young_rgb: [0.24, 0.17, 0.09], relief: 1.6 }
            }
            // Pine / fir: plates ~8 cm wide on a 1 m girth; young twigs orange brown.
            BarkType::Plated => {
                BarkStyle { tile_at_1m: 0.4, young_radius: 0.025, young_rgb: [0.30, 0.17, 0.09], relief: 1.4 }
            }
            // Birch / aspen: lenticels 1-3 cm long; young twigs red-brown to grey green.
            BarkType::SmoothBanded => {
                BarkStyle { tile_at_1m: 0.2, young_radius: 0.02, young_rgb: [0.26, 0.2, 0.14], relief: 0.8 }
            }
            // Willow / cypress: strips ~3 cm apart; young shoots yellow olive.
            BarkType::Fibrous => {
                BarkStyle { tile_at_1m: 0.22, young_radius: 0.02, young_rgb: [0.33, 0.3, 0.14], relief: 1.5 }
            }
        }
    }

    /// Depth of the relief in tile widths (sets the normal map's slopes).
    fn depth(self) -> f32 {
        match self {
            BarkType::Furrowed => 0.035,
            BarkType::Plated => 0.03,
            BarkType::SmoothBanded => 0.008,
            BarkType::Fibrous => 0.025,
        }
    }
}

/// The style of `kind` as JSON (what `bark_style_json` returns in wasm).
pub fn style_json(kind: BarkType) -> String {
    serde_json::to_string(&kind.style()).expect("style serialises")
}

/// Feeds the bark type into a content hash: the textures are a pure function of it, so the hash
/// of a tree names its bark too.
pub fn hash_into(kind: BarkType, h: u64) -> u64 {
    (h ^ (0xb4_0000 | kind as u64)).wrapping_mul(0x0000_0100_0000_01b3)
}

/// Linear 0..1 to an sRGB byte: [`srgb8_by_power`]'s byte, found among the smallest inputs of
/// the bytes ([`srgb_steps`]) instead of through a power (libm's `powf`, in software in wasm,
/// three per texel). The byte never falls as the input grows, so the count of steps at or below
/// the input is that byte (tested around every step and over the whole range; NaN: 0 both ways).
fn srgb8(c: f32) -> u8 {
    srgb_steps().partition_point(|&step| step <= c) as u8
}

/// Linear 0..1 to an sRGB byte, through the power: `c^(1/2.2) 255 + ½`, clamped, through `u8`.
fn srgb8_by_power(c: f32) -> u8 {
    (pow(c.clamp(0.0, 1.0), 1.0 / 2.2) * 255.0 + 0.5) as u8
}

/// For each byte from 1 to 255, the smallest input in 0..=1 that [`srgb8_by_power`] takes to it
/// or above: a bisection over the floats' bits (in that range they order like the floats), once
/// per process.
fn srgb_steps() -> &'static [f32; 255] {
    static STEPS: std::sync::OnceLock<[f32; 255]> = std::sync::OnceLock::new();
    STEPS.get_or_init(|| {
        std::array::from_fn(|k| {
            let byte = k as u8 + 1;
            // 0 gives byte 0, below `byte`; 1 gives 255, at least `byte`.
            let (mut below, mut at) = (0u32, 1.0f32.to_bits());
            while at - below > 1 {
                let mid = below + (at - below) / 2;
                if srgb8_by_power(f32::from_bits(mid)) >= byte {
                    at = mid;
                } else {
                    below = mid;
                }
            }
            f32::from_bits(at)
        })
    })
}

/// `texel(i)` of every texel `i` of a `size` × `size` map, row after row, the rows side by side
/// where there are threads ([`crate::par`]; each texel on its own, so the same values).
fn texels<T: Send>(size: usize, texel: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let rows = crate::par::ranges(size, 4 * crate::par::threads());
    crate::par::map(rows, crate::par::threads(), |rows| {
        (rows.start * size..rows.end * size).map(&texel).collect::<Vec<_>>()
    })
    .into_iter()
    .flatten()
    .collect()
}

fn unorm8(c: f32) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// Bake the maps of `kind`, `size` texels square (a power of two, at least 16).
pub fn bake(kind: BarkType, size: usize) -> BarkMaps {
    let size = size.next_power_of_two().max(16);
    let seed = 1 + kind as u32 * 101;
    let samples = texels(size, |i| {
        patterns::sample(kind, (i % size) as f32 / size as f32, (i / size) as f32 / size as f32, seed)
    });
    let at = |x: usize, y: usize| samples[(y % size) * size + (x % size)].height;
    let strength = kind.depth() * size as f32 * 0.5;
    let n = size * size * 4;
    let (mut color, mut normal, mut orm) = (Vec::with_capacity(n), Vec::with_capacity(n), Vec::with_capacity(n));
    for y in 0..size {
        for x in 0..size {
            let s = &samples[y * size + x];
            color.extend(s.rgb.iter().map(|&c| srgb8(c)));
            color.push(255);
            let dx = (at(x + 1, y) - at(x + size - 1, y)) * strength;
            let dy = (at(x, y + 1) - at(x, y + size - 1)) * strength;
            let len = (dx * dx + dy * dy + 1.0).sqrt();
            normal.extend([-dx / len, -dy / len, 1.0 / len].iter().map(|c| unorm8(c * 0.5 + 0.5)));
            normal.push(unorm8(s.height));
            let ao = 0.35 + 0.65 * noise::smoothstep(0.0, 0.6, s.height);
            orm.extend_from_slice(&[unorm8(ao), unorm8(s.rough), 0, 255]);
        }
    }
    let tex = |rgba| Texture { size, rgba };
    BarkMaps { color: tex(color), normal: tex(normal), orm: tex(orm) }
}

/// FNV-1a (64 bits) of `bytes`: the tests' fingerprint of a map's bytes.
#[cfg(test)]
fn fnv64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

#[cfg(test)]
mod tests;
