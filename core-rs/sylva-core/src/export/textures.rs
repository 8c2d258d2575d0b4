//! # PNG textures for the exports
//!
//! The bark maps of a bark type ([`crate::mesh::bark::bake`], the same the viewer shows), its end
//! grain for cut faces ([`crate::mesh::bark::end_grain`]) and the leaf's baked maps, encoded as PNG ([`super::png`]) once and cached by their key: the textures
//! are pure functions of it, so the cache never changes a result, it only saves the encoding
//! time of repeated exports.

use super::png;
use crate::foliage::Foliage;
use crate::params::BarkType;
use std::sync::{Arc, Mutex};

/// Encoded PNG textures: colour and normal map.
#[derive(Clone, Debug, PartialEq)]
pub struct TexturePngs {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// The colour map as a PNG file (RGBA8).
    pub color: Vec<u8>,
    /// The tangent-space normal map as a PNG file (RGBA8, A = height).
    pub normal: Vec<u8>,
    /// Bark only: glTF's packed occlusion (R) + roughness (G) + metalness (B) map as a PNG file.
    pub orm: Option<Vec<u8>>,
}

type PngCache = Mutex<Option<(u64, Arc<TexturePngs>)>>;
static BARK_PNGS: PngCache = Mutex::new(None);
static LEAF_PNGS: PngCache = Mutex::new(None);
static GRAIN_PNGS: PngCache = Mutex::new(None);
static SCALED_LEAF_PNGS: PngCache = Mutex::new(None);

/// `make()` once per `key` (the last key is kept; the textures are pure functions of the key,
/// so the cache never changes a result, it only saves the encoding time of repeated exports).
fn cached(cache: &PngCache, key: u64, make: impl FnOnce() -> TexturePngs) -> Arc<TexturePngs> {
    if let Ok(slot) = cache.lock() {
        if let Some((k, v)) = slot.as_ref() {
            if *k == key {
                return Arc::clone(v);
            }
        }
    }
    let v = Arc::new(make());
    if let Ok(mut slot) = cache.lock() {
        *slot = Some((key, Arc::clone(&v)));
    }
    v
}

/// The baked bark textures of `kind` ([`crate::mesh::bark::bake`], as the viewer uses) as PNGs,
/// `size` texels square.
pub fn bark_pngs(kind: BarkType, size: u32) -> Arc<TexturePngs> {
    cached(&BARK_PNGS, u64::from(size) | (kind as u64) << 32, || {
        let m = crate::mesh::bark::bake(kind, size as usize);
        let s = m.color.size as u32;
        TexturePngs {
            width: s,
            height: s,
            color: png::encode_rgba(s, s, &m.color.rgba),
            normal: png::encode_rgba(s, s, &m.normal.rgba),
            orm: Some(png::encode_rgba(s, s, &m.orm.rgba)),
        }
    })
}

/// The end grain of `kind` for cut faces ([`crate::mesh::bark::end_grain::bake`], as the viewer
/// uses) as PNGs, `size` texels square: colour (alpha = the disc mask) and normal, no ORM map.
pub fn end_grain_pngs(kind: BarkType, size: u32) -> Arc<TexturePngs> {
    cached(&GRAIN_PNGS, u64::from(size) | (kind as u64) << 32, || {
        let m = crate::mesh::bark::end_grain::bake(kind, size as usize);
        let s = m.color.size as u32;
        TexturePngs {
            width: s,
            height: s,
            color: png::encode_rgba(s, s, &m.color.rgba),
            normal: png::encode_rgba(s, s, &m.normal.rgba),
            orm: None,
        }
    })
}

/// The baked leaf textures of `f` as PNGs (`None` when the tree is bare). Cached by leaf hash.
pub fn leaf_pngs(f: &Foliage) -> Option<Arc<TexturePngs>> {
    leaf_pngs_scaled(f, [1.0; 3])
}

/// [`leaf_pngs`] with the colour map's R, G and B multiplied by `scale` ([`super::bake::tint_scale`]:
/// the texture of leaves whose colours are divided by it); [`leaf_pngs`]' own when it is 1.
pub fn leaf_pngs_scaled(f: &Foliage, scale: [f32; 3]) -> Option<Arc<TexturePngs>> {
    let leaf = f.leaf.as_deref()?;
    let t = &leaf.texture;
    let plain = scale == [1.0; 3];
    let (cache, key) = if plain {
        (&LEAF_PNGS, leaf.hash)
    } else {
        (&SCALED_LEAF_PNGS, scale.iter().fold(leaf.hash, |h, s| h.rotate_left(21) ^ u64::from(s.to_bits())))
    };
    Some(cached(cache, key, || {
        let color = if plain {
            png::encode_rgba(t.width, t.height, &t.color)
        } else {
            png::encode_rgba(t.width, t.height, &super::bake::scale_texels(&t.color, scale))
        };
        TexturePngs {
            width: t.width,
            height: t.height,
            color,
            normal: png::encode_rgba(t.width, t.height, &t.normal),
            orm: None,
        }
    }))
}
