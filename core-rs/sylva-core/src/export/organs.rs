//! The flowers, fruit, catkins and buds ([`crate::organs`]) as the writers need them: which
//! sets a file carries ([`exported`]), each set's material colour in linear light, and a set
//! baked into one mesh with its per-instance tints as vertex colours ([`bake_set`]).
//!
//! A set's look is its plain base colour (sRGB in the core, [`OrganSet::color`]) times each
//! instance's tint (linear light). Baked, the tints become RGBA8 vertex colours; a tint over 1
//! cannot be stored there, so, as the leaves' tints move into their texture
//! ([`super::tint_scale`]), the tints are divided per channel by their largest value over 1 and
//! the base colour is multiplied by it (then clamped to glTF's 0..1).

use super::bake::{bake_instances, BakedLeaves};
use super::options::{ExportOptions, LeafMode};
use crate::organs::OrganSet;
use crate::Generated;

/// The organ sets a file of `g` carries: every set with instances and triangles, unless the
/// leaves are left out ([`LeafMode::None`]: a bark-only file carries no parts either).
pub fn exported<'a>(g: &'a Generated, opts: &ExportOptions) -> Vec<&'a OrganSet> {
    if opts.leaves == LeafMode::None {
        return Vec::new();
    }
    g.foliage.organs.iter().filter(|s| s.count() > 0 && !s.mesh.indices.is_empty()).collect()
}

/// One sRGB component (0..1) in linear light (IEC 61966-2-1).
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        crate::math::pow((c + 0.055) / 1.055, 2.4)
    }
}

/// One linear component (0..1) in sRGB (IEC 61966-2-1).
pub fn linear_to_srgb(c: f32) -> f32 {
    if c <= 0.003_130_8 {
        c * 12.92
    } else {
        1.055 * crate::math::pow(c, 1.0 / 2.4) - 0.055
    }
}

/// The set's base colour in linear light.
pub fn linear_color(set: &OrganSet) -> [f32; 3] {
    set.color.map(srgb_to_linear)
}

/// Per channel, the largest tint of the set over 1 (1 where none is).
pub fn tint_scale(set: &OrganSet) -> [f32; 3] {
    let mut s = [1.0f32; 3];
    for rgb in set.colors.chunks_exact(3) {
        for (c, &v) in s.iter_mut().zip(rgb) {
            if v.is_finite() && v > *c {
                *c = v;
            }
        }
    }
    s
}

/// A set baked into one mesh ([`bake_set`]) and the base colour that goes with its vertex
/// colours.
pub struct BakedSet<'a> {
    /// The set.
    pub set: &'a OrganSet,
    /// Every instance's copy of the set's mesh in tree space, tints as RGBA8 vertex colours.
    pub baked: BakedLeaves,
    /// The material's base colour, linear RGB times the tint scale (clamped to 0..1).
    pub base: [f32; 3],
}

/// `set` baked: each instance's copy of the mesh through its matrix, its tint (divided by the
/// set's [`tint_scale`]) as the vertex colour, the base colour multiplied by that scale.
pub fn bake_set(set: &OrganSet) -> BakedSet<'_> {
    let scale = tint_scale(set);
    let baked = bake_instances(&set.mesh, &set.matrices, &set.colors, false, scale);
    let lin = linear_color(set);
    let base = [0, 1, 2].map(|k| (lin[k] * scale[k]).min(1.0));
    BakedSet { set, baked, base }
}

/// A name for files whose names may not hold spaces (OBJ objects, MTL materials):
/// `"cherry blossom petals"` → `"cherry_blossom_petals"`.
pub fn file_name(set: &OrganSet) -> String {
    set.name.replace(' ', "_")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_endpoints_and_midpoint() {
        assert_eq!(srgb_to_linear(0.0), 0.0);
        assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-6);
        // sRGB 0.5 is about 0.214 in linear light.
        assert!((srgb_to_linear(0.5) - 0.2140).abs() < 1e-3);
        for c in [0.0, 0.02, 0.3, 0.5, 0.9, 1.0] {
            assert!((linear_to_srgb(srgb_to_linear(c)) - c).abs() < 1e-5, "{c}");
        }
    }
}
