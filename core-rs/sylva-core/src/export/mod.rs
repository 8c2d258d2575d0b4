//! # Export
//!
//! Files a generated tree can be saved as, built from [`Generated`] alone (no state, no I/O:
//! the functions return bytes and strings; the CLI and the wasm binding write or hand them on):
//!
//! * [`glb`]: glTF 2.0 binary (Khronos glTF 2.0 specification, §4.4 "GLB File Format"): bark
//!   and leaf meshes, PBR metallic-roughness materials, the baked bark and leaf textures as
//!   embedded PNGs, vertex colours, tangents for the normal maps, wind data as custom vertex
//!   attributes, leaves instanced with `EXT_mesh_gpu_instancing` or baked into one mesh.
//! * [`obj`]: Wavefront OBJ + MTL (bark and baked leaves), the textures as PNG files.
//! * [`png`]: the small deterministic PNG encoder both use (PNG spec, 3rd ed., RGBA8).
//!
//! What goes in a file is chosen by [`ExportOptions`]; [`ExportOptions::default`] is the one
//! place the defaults live. Every output is deterministic: the same tree and options give the
//! same bytes on every target (no hash-map iteration, floats printed in Rust's shortest
//! round-trip form, a pinned deflate).
//!
//! The parts shared by both formats sit here: per-vertex bark colours ([`bark_colors`]),
//! MikkTSpace-style tangents (Lengyel's method, [`tangents`]; for the bark the same direction read
//! off the mesh's tube rings wherever it can be, [`mesh_tangents`]), the leaves baked into one
//! mesh ([`bake_leaves`]), instance matrices split into translation, rotation and scale
//! ([`decompose`]), and the PNG textures, encoded once and cached ([`bark_pngs`], [`leaf_pngs`]).

mod bake;
mod frames;
pub mod glb;
pub mod growth;
mod lods;
pub mod obj;
mod options;
pub mod organs;
pub mod png;
mod quant;
mod textures;
mod tint;
pub mod zip;

pub use bake::{
    bake_instances, bake_leaves, bake_leaves_scaled, decompose, decompose_rotation, decompose_scale, scale_texels,
    tint_scale, BakedLeaves,
};
pub use lods::{lod_level_glb, lods_glb, LOD_SCREEN_SIZES};
pub use options::{ExportOptions, LeafMode};
pub use tint::{bark_colors, bark_colors_into, TINT_STEPS};

pub use frames::{frames_of_snorm8_write, frames_snorm8_write, mesh_tangents, normals_snorm8_write, tangents};
pub use textures::{bark_pngs, end_grain_pngs, leaf_pngs, leaf_pngs_scaled, TexturePngs};

use crate::Generated;

/// The glTF GLB bytes of a tree ([`glb::write`]).
///
/// ```
/// use sylva_core::export::{to_glb, ExportOptions};
/// use sylva_core::{generate, TreeParams};
///
/// let mut params = TreeParams::default();
/// params.set("levels", 1.0)?;
/// let glb = to_glb(&generate(&params)?, &ExportOptions::default());
/// assert_eq!(&glb[..4], b"glTF"); // a binary glTF 2.0 container
/// assert_eq!(u32::from_le_bytes(glb[8..12].try_into().unwrap()) as usize, glb.len());
/// # Ok::<(), sylva_core::SylvaError>(())
/// ```
pub fn to_glb(g: &Generated, opts: &ExportOptions) -> Vec<u8> {
    glb::write(g, opts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::TreeMesh;
    use glam::{Mat3, Quat, Vec3};

    #[test]
    fn options_from_json() {
        assert_eq!(ExportOptions::from_json("").unwrap(), ExportOptions::default());
        let o = ExportOptions::from_json(r#"{"leaves":"Baked","wind":false,"bark_texture_size":64}"#).unwrap();
        assert_eq!(o.leaves, LeafMode::Baked);
        assert!(!o.wind && o.textures);
        assert_eq!(o.bark_texture_size, 64);
        assert!(!o.strict && ExportOptions::from_json(r#"{"strict":true}"#).unwrap().strict);
        for bad in [
            r#"{"leaves":"some"}"#,
            r#"{"wind":1}"#,
            r#"{"strict":"yes"}"#,
            r#"{"size":1}"#,
            "[1]",
            r#"{"bark_texture_size":100}"#,
        ] {
            assert!(ExportOptions::from_json(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn decompose_recovers_the_matrix() {
        // Rotation of 0.7 rad about a tilted axis, scales (0.3, 0.5, 0.5), translation.
        let q = crate::math::quat_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 0.7);
        let m = glam::Mat4::from_scale_rotation_translation(Vec3::new(0.3, 0.5, 0.5), q, Vec3::new(1.0, 2.0, 3.0));
        let (t, r, s) = decompose(&m.to_cols_array());
        let back = glam::Mat4::from_scale_rotation_translation(Vec3::from(s), Quat::from_array(r), Vec3::from(t));
        for (a, b) in back.to_cols_array().iter().zip(m.to_cols_array()) {
            assert!((a - b).abs() < 1e-5, "{back} vs {m}");
        }
        assert!((Quat::from_array(r).length() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn decompose_matches_glam_bit_for_bit() {
        // The glam formulation the IEEE-square-root one replaces.
        let glam_rotation = |m: &[f32]| {
            let (c0, c1, c2) = (Vec3::from_slice(&m[0..3]), Vec3::from_slice(&m[4..7]), Vec3::from_slice(&m[8..11]));
            let c0 = if c0.cross(c1).dot(c2) < 0.0 { -c0 } else { c0 };
            let x = crate::math::unit_or(c0, || Vec3::X);
            let y = crate::math::unit_or(c1 - x * x.dot(c1), || crate::math::unit_or(x.cross(Vec3::Z), || Vec3::Y));
            Quat::from_mat3(&Mat3::from_cols(x, y, x.cross(y))).normalize().to_array()
        };
        let glam_scale = |m: &[f32]| {
            let (c0, c1, c2) = (Vec3::from_slice(&m[0..3]), Vec3::from_slice(&m[4..7]), Vec3::from_slice(&m[8..11]));
            let sx = c0.length();
            [if c0.cross(c1).dot(c2) < 0.0 { -sx } else { sx }, c1.length(), c2.length()]
        };
        let mut rng = crate::rng::Rng::new(7, "decompose");
        for i in 0..20_000 {
            let mut r = || rng.next_f32() * 2.0 - 1.0;
            let axis = Vec3::new(r(), r(), r()).normalize_or(Vec3::Y);
            let q = crate::math::quat_axis_angle(axis, r() * 3.2);
            let s = Vec3::new(if i % 3 == 0 { -0.3 } else { 0.3 } + r() * 0.1, 0.5 + r() * 0.2, 0.4);
            let m = glam::Mat4::from_scale_rotation_translation(s, q, Vec3::new(r(), r(), r())).to_cols_array();
            assert_eq!(decompose_rotation(&m).map(f32::to_bits), glam_rotation(&m).map(f32::to_bits), "{m:?}");
            assert_eq!(decompose_scale(&m).map(f32::to_bits), glam_scale(&m).map(f32::to_bits), "{m:?}");
        }
    }

    #[test]
    fn bark_colors_are_darker_at_the_foot() {
        let mesh = TreeMesh {
            positions: vec![0.0, 0.0, 0.0, 0.0, 5.0, 0.0, 0.0, 10.0, 0.0],
            normals: [1.0, 0.0, 0.0].repeat(3),
            uvs: vec![0.0; 6],
            indices: vec![0, 1, 2],
            groups: Vec::new(),
            wind: Vec::new(),
            rings: Vec::new(),
            shade: Vec::new(),
        };
        let c = bark_colors(&mesh);
        assert_eq!(c.len(), 12);
        let lum = |i: usize| c[4 * i] as u32 + c[4 * i + 1] as u32 + c[4 * i + 2] as u32;
        assert!(lum(0) < lum(1) && lum(1) < lum(2), "{c:?}");
        assert!(c.chunks_exact(4).all(|p| p[3] == 255));
        // The bark occlusion darkens the tint: a vertex in the dark gets a quarter of it.
        let shaded = bark_colors(&TreeMesh { shade: vec![255, 64, 255], ..mesh });
        assert_eq!((shaded[0], shaded[8]), (c[0], c[8]));
        assert!((i32::from(shaded[4]) - i32::from(c[4]) / 4).abs() <= 1, "{} vs {}", shaded[4], c[4]);
    }
}
