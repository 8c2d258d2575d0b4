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

mod frames;
pub mod glb;
pub mod obj;
pub mod png;
mod quant;
mod textures;

pub use frames::{frames_of_snorm8_write, frames_snorm8_write, mesh_tangents, normals_snorm8_write, tangents};
use quant::LANES;
pub use textures::{bark_pngs, leaf_pngs, TexturePngs};

use crate::error::SylvaError;
use crate::foliage::Foliage;
use crate::mesh::TreeMesh;
use crate::Generated;
use glam::{Mat3, Vec3};

/// How the leaves are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LeafMode {
    /// One leaf mesh drawn once per leaf (GLB: `EXT_mesh_gpu_instancing`, per-leaf TRS and
    /// colour). OBJ has no instancing and writes the leaves baked instead.
    #[default]
    Instanced,
    /// Every leaf transformed into one mesh, with the per-leaf colour as a vertex colour.
    Baked,
    /// No leaves.
    None,
}

impl LeafMode {
    /// The mode for a name: `instanced`, `baked` or `none` (any case).
    pub fn from_name(name: &str) -> Option<LeafMode> {
        match name.to_ascii_lowercase().as_str() {
            "instanced" => Some(LeafMode::Instanced),
            "baked" => Some(LeafMode::Baked),
            "none" => Some(LeafMode::None),
            _ => None,
        }
    }
}

/// What an export contains. The defaults ([`ExportOptions::default`]) give the complete file.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportOptions {
    /// How leaves are written. Default [`LeafMode::Instanced`].
    pub leaves: LeafMode,
    /// Write the wind attributes (`_WIND_PIVOT`, `_WIND_PARAMS`) when the mesh has wind data.
    /// Default `true`.
    pub wind: bool,
    /// Embed (GLB) or reference (OBJ) the baked textures. Default `true`.
    pub textures: bool,
    /// With `textures`: the normal maps. Default `true`.
    pub normal_maps: bool,
    /// With `normal_maps`: per-vertex tangents (GLB `TANGENT`, 4 bytes per vertex). Default
    /// `true`. Without them viewers compute their own (the glTF 2.0 specification asks for
    /// MikkTSpace; the Khronos validator warns that such a tangent space may differ between
    /// implementations); computing them is the most expensive part of a big export.
    pub tangents: bool,
    /// Per-vertex colours (`COLOR_0`): bark tint, baked leaf colours. Default `true`.
    pub vertex_colors: bool,
    /// Edge of the square bark textures in texels, a power of two from 16 to 2048. Default 512.
    pub bark_texture_size: u32,
}

impl Default for ExportOptions {
    fn default() -> Self {
        ExportOptions {
            leaves: LeafMode::Instanced,
            wind: true,
            textures: true,
            normal_maps: true,
            tangents: true,
            vertex_colors: true,
            bark_texture_size: 512,
        }
    }
}

impl ExportOptions {
    /// Options from a JSON object; missing fields keep their defaults, e.g.
    /// `{"leaves": "baked", "wind": false, "bark_texture_size": 256}`. An empty string means
    /// all defaults. Unknown fields and wrong types are errors.
    pub fn from_json(json: &str) -> Result<ExportOptions, SylvaError> {
        let mut o = ExportOptions::default();
        if json.trim().is_empty() {
            return Ok(o);
        }
        let bad = |message: String| SylvaError::Input { message };
        let v: serde_json::Value =
            serde_json::from_str(json).map_err(|e| bad(format!("export options are not JSON: {e}")))?;
        let map = v.as_object().ok_or_else(|| bad("export options must be a JSON object".into()))?;
        for (k, v) in map {
            let flag = || v.as_bool().ok_or_else(|| bad(format!("export option '{k}' must be true or false")));
            match k.as_str() {
                "leaves" => {
                    o.leaves = v.as_str().and_then(LeafMode::from_name).ok_or_else(|| {
                        bad(format!("export option 'leaves' must be \"instanced\", \"baked\" or \"none\", got {v}"))
                    })?
                }
                "wind" => o.wind = flag()?,
                "textures" => o.textures = flag()?,
                "normal_maps" => o.normal_maps = flag()?,
                "tangents" => o.tangents = flag()?,
                "vertex_colors" => o.vertex_colors = flag()?,
                "bark_texture_size" => {
                    o.bark_texture_size =
                        v.as_u64().filter(|&s| (16..=2048).contains(&s) && s.is_power_of_two()).ok_or_else(|| {
                            bad(format!("export option 'bark_texture_size' must be a power of two 16..2048, got {v}"))
                        })? as u32
                }
                other => return Err(bad(format!("unknown export option '{other}'"))),
            }
        }
        Ok(o)
    }
}

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

/// Per-vertex bark tint, RGBA8 (A = 255), multiplied with the bark texture by viewers: old bark
/// at the foot of the tree is darker and a little greener (soil splash, moss), young bark
/// higher up and on thin stems lighter and greyer. With wind data the "age" is the stem's
/// stiffness (local radius relative to the trunk base); without it, the height above the
/// ground relative to the tree's height; the bark occlusion ([`TreeMesh::shade`]) multiplies it.
/// The tint is a function of two numbers in 0..1
/// (youth, nearness to the ground), tabulated at [`TINT_STEPS`] steps each: the export pays
/// one table look-up per vertex.
pub fn bark_colors(mesh: &TreeMesh) -> Vec<u8> {
    let mut out = vec![0u8; mesh.vertex_count() * 4];
    bark_colors_into(mesh, &mut out);
    out
}

/// [`bark_colors`] written into `out` (4 bytes per vertex).
pub fn bark_colors_into(mesh: &TreeMesh, out: &mut [u8]) {
    bark_colors_in(mesh, &mesh.bounds(), out);
}

/// [`bark_colors_into`] with the mesh's bounds already known.
pub(crate) fn bark_colors_in(mesh: &TreeMesh, b: &crate::mesh::Bounds, out: &mut [u8]) {
    let tint = BarkTint::new(mesh, b);
    for (k, c) in out.chunks_mut(4 * LANES).enumerate() {
        tint.write(mesh, k * LANES, c);
    }
}

/// The bark tint of one mesh ([`bark_colors`]): the table and the scales of its two inputs.
pub(crate) struct BarkTint {
    /// `[young][ground]` RGBA words.
    table: Vec<[u8; 4]>,
    min_y: f32,
    y_young: f32,
    y_ground: f32,
    /// Whether "young" comes from the wind data's stiffness.
    stiffness: bool,
}

impl BarkTint {
    pub(crate) fn new(mesh: &TreeMesh, b: &crate::mesh::Bounds) -> BarkTint {
        let height = (b.max[1] - b.min[1]).max(1e-6);
        let foot = 0.08 * height;
        let steps = (TINT_STEPS - 1) as f32;
        let mut table = vec![[0u8; 4]; TINT_STEPS * TINT_STEPS];
        for (k, e) in table.iter_mut().enumerate() {
            let (young, ground) = ((k / TINT_STEPS) as f32 / steps, (k % TINT_STEPS) as f32 / steps);
            let light = 0.82 + 0.18 * young - 0.22 * ground;
            let grey = 0.12 * young; // young bark: less brown
            let r = light * ((1.0 - 0.10 * ground) * (1.0 - grey) + grey);
            let g = light * (1.0 + 0.04 * ground);
            let bl = light * ((1.0 - 0.12 * ground) * (1.0 - grey) + grey * 1.02);
            *e = [unorm8(r), unorm8(g), unorm8(bl), 255];
        }
        let n = mesh.vertex_count();
        BarkTint {
            table,
            min_y: b.min[1],
            y_young: steps / height,
            y_ground: steps / foot.max(1e-6),
            stiffness: n > 0 && mesh.wind.len() == n * crate::mesh::WIND_STRIDE,
        }
    }

    /// The colours of vertices `first..first + out.len() / 4` into `out`.
    #[inline(always)]
    pub(crate) fn write(&self, mesh: &TreeMesh, first: usize, out: &mut [u8]) {
        let k = out.len() / 4;
        let steps = (TINT_STEPS - 1) as f32;
        let step = |x: f32| (x.clamp(0.0, steps) + 0.5) as i32 as usize;
        let ys = mesh.positions[3 * first..3 * (first + k)].chunks_exact(3).map(|p| p[1] - self.min_y);
        if self.stiffness {
            let w = crate::mesh::WIND_STRIDE;
            let stiff = mesh.wind[w * first..w * (first + k)].chunks_exact(w).map(|r| r[5]);
            for ((c, y), s) in out.chunks_exact_mut(4).zip(ys).zip(stiff) {
                c.copy_from_slice(&self.table[step((1.0 - s) * steps) * TINT_STEPS + step(steps - y * self.y_ground)]);
            }
        } else {
            for (c, y) in out.chunks_exact_mut(4).zip(ys) {
                c.copy_from_slice(&self.table[step(y * self.y_young) * TINT_STEPS + step(steps - y * self.y_ground)]);
            }
        }
        // The bark occlusion (crown depth, cavities: `mesh::shade`) darkens the tint.
        if mesh.shade.len() == mesh.vertex_count() {
            for (c, &s) in out.chunks_exact_mut(4).zip(&mesh.shade[first..first + k]) {
                for x in &mut c[..3] {
                    *x = ((u16::from(*x) * u16::from(s) + 127) / 255) as u8;
                }
            }
        }
    }
}

/// Steps per axis of the bark tint table ([`bark_colors`]).
pub const TINT_STEPS: usize = 64;

/// 0..1 to 0..255, rounded, clamped.
#[inline]
fn unorm8(x: f32) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// One leaf instance matrix (column-major 4×4) as glTF TRS: translation, unit rotation
/// quaternion `[x, y, z, w]` and scale. The columns of the upper 3×3 are taken as the scaled
/// axes; a mirroring matrix gets a negative `x` scale. Exact for the foliage's matrices, whose
/// axes are perpendicular.
pub fn decompose(m: &[f32]) -> ([f32; 3], [f32; 4], [f32; 3]) {
    ([m[12], m[13], m[14]], decompose_rotation(m), decompose_scale(m))
}

/// The rotation part of [`decompose`]: the unit quaternion `[x, y, z, w]` of the first two axis
/// columns made orthonormal (Gram-Schmidt; the first negated when the matrix mirrors, as its
/// scale is) and their cross product.
pub fn decompose_rotation(m: &[f32]) -> [f32; 4] {
    let (c0, c1, c2) = (Vec3::new(m[0], m[1], m[2]), Vec3::new(m[4], m[5], m[6]), Vec3::new(m[8], m[9], m[10]));
    let c0 = if c0.cross(c1).dot(c2) < 0.0 { -c0 } else { c0 };
    let x = crate::math::unit_or(c0, || Vec3::X);
    let y = crate::math::unit_or(c1 - x * x.dot(c1), || crate::math::unit_or(x.cross(Vec3::Z), || Vec3::Y));
    let q = quat_from_axes(x, y, x.cross(y));
    // `Quat::normalize`, with the IEEE square root (glam's goes through libm, a function call
    // in wasm; both are correctly rounded, so the results are the same).
    let inv = 1.0 / (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    q.map(|c| c * inv)
}

/// `Quat::from_mat3` of the rotation with these axis columns (glam's operations in glam's
/// order, after DirectXMath's `XMQuaternionRotationMatrix`), with the IEEE square root.
fn quat_from_axes(x: Vec3, y: Vec3, z: Vec3) -> [f32; 4] {
    let (m00, m01, m02) = (x.x, x.y, x.z);
    let (m10, m11, m12) = (y.x, y.y, y.z);
    let (m20, m21, m22) = (z.x, z.y, z.z);
    if m22 <= 0.0 {
        let dif10 = m11 - m00;
        let omm22 = 1.0 - m22;
        if dif10 <= 0.0 {
            let four_xsq = omm22 - dif10;
            let inv = 0.5 / four_xsq.sqrt();
            [four_xsq * inv, (m01 + m10) * inv, (m02 + m20) * inv, (m12 - m21) * inv]
        } else {
            let four_ysq = omm22 + dif10;
            let inv = 0.5 / four_ysq.sqrt();
            [(m01 + m10) * inv, four_ysq * inv, (m12 + m21) * inv, (m20 - m02) * inv]
        }
    } else {
        let sum10 = m11 + m00;
        let opm22 = 1.0 + m22;
        if sum10 <= 0.0 {
            let four_zsq = opm22 - sum10;
            let inv = 0.5 / four_zsq.sqrt();
            [(m02 + m20) * inv, (m12 + m21) * inv, four_zsq * inv, (m01 - m10) * inv]
        } else {
            let four_wsq = opm22 + sum10;
            let inv = 0.5 / four_wsq.sqrt();
            [(m12 - m21) * inv, (m20 - m02) * inv, (m01 - m10) * inv, four_wsq * inv]
        }
    }
}

/// The scale part of [`decompose`]: the lengths of the three axis columns, the first negative
/// when the matrix mirrors.
pub fn decompose_scale(m: &[f32]) -> [f32; 3] {
    let c0 = Vec3::new(m[0], m[1], m[2]);
    let c1 = Vec3::new(m[4], m[5], m[6]);
    let c2 = Vec3::new(m[8], m[9], m[10]);
    let len = |c: Vec3| c.dot(c).sqrt(); // `Vec3::length` with the IEEE square root
    let sx = len(c0);
    [if c0.cross(c1).dot(c2) < 0.0 { -sx } else { sx }, len(c1), len(c2)]
}

/// The leaves as one mesh in tree space: each instance's copy of the leaf mesh transformed by
/// its matrix (normals by the inverse transpose), plus per-vertex RGBA8 colours from the
/// per-leaf tint (clamped to 0..1) and, when asked, tangents.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BakedLeaves {
    /// The geometry (one `leaves` group).
    pub mesh: TreeMesh,
    /// RGBA8 per vertex.
    pub colors: Vec<u8>,
    /// 4 floats per vertex (see [`tangents`]), empty unless asked for.
    pub tangents: Vec<f32>,
}

/// Bakes the instanced foliage into one mesh ([`BakedLeaves`]); `with_tangents` also transforms
/// the leaf mesh's tangents.
pub fn bake_leaves(f: &Foliage, with_tangents: bool) -> BakedLeaves {
    let leaf = &f.mesh;
    let (nv, count) = (leaf.vertex_count(), f.count());
    let leaf_t =
        if with_tangents { tangents(&leaf.positions, &leaf.normals, &leaf.uvs, &leaf.indices) } else { Vec::new() };
    let total = nv * count;
    let mut mesh = TreeMesh {
        positions: Vec::with_capacity(total * 3),
        normals: Vec::with_capacity(total * 3),
        uvs: Vec::with_capacity(total * 2),
        indices: Vec::with_capacity(leaf.indices.len() * count),
        groups: Vec::new(),
        wind: Vec::new(),
        rings: Vec::new(),
        shade: Vec::new(),
    };
    let mut colors = Vec::with_capacity(total * 4);
    let mut tan = Vec::with_capacity(if with_tangents { total * 4 } else { 0 });
    for (k, (m, rgb)) in f.matrices.chunks_exact(16).zip(f.colors.chunks_exact(3)).enumerate() {
        let lin =
            Mat3::from_cols(Vec3::new(m[0], m[1], m[2]), Vec3::new(m[4], m[5], m[6]), Vec3::new(m[8], m[9], m[10]));
        let t = Vec3::new(m[12], m[13], m[14]);
        let det = lin.determinant();
        let normal_m = if det != 0.0 { lin.inverse().transpose() } else { lin };
        for v in 0..nv {
            let p = Vec3::from_slice(&leaf.positions[3 * v..3 * v + 3]);
            mesh.positions.extend_from_slice(&(lin * p + t).to_array());
            let n = Vec3::from_slice(&leaf.normals[3 * v..3 * v + 3]);
            let n = crate::math::unit_or(normal_m * n, || Vec3::Y);
            mesh.normals.extend_from_slice(&n.to_array());
            mesh.uvs.extend_from_slice(&leaf.uvs[2 * v..2 * v + 2]);
            if with_tangents {
                let d = Vec3::from_slice(&leaf_t[4 * v..4 * v + 3]);
                let d = lin * d;
                let d = crate::math::unit_or(d - n * n.dot(d), || crate::math::unit_or(n.cross(Vec3::Y), || Vec3::X));
                let w = if det < 0.0 { -leaf_t[4 * v + 3] } else { leaf_t[4 * v + 3] };
                tan.extend_from_slice(&[d.x, d.y, d.z, w]);
            }
        }
        let first = (k * nv) as u32;
        for tri in leaf.indices.chunks_exact(3) {
            let (a, b, c) = (tri[0] + first, tri[1] + first, tri[2] + first);
            // A mirroring matrix flips the winding; keep the front counter-clockwise.
            if det < 0.0 {
                mesh.indices.extend_from_slice(&[a, c, b]);
            } else {
                mesh.indices.extend_from_slice(&[a, b, c]);
            }
        }
        let c = [unorm8(rgb[0]), unorm8(rgb[1]), unorm8(rgb[2]), 255];
        for _ in 0..nv {
            colors.extend_from_slice(&c);
        }
    }
    if !mesh.indices.is_empty() {
        mesh.groups.push(crate::mesh::MeshGroup {
            material: crate::mesh::Material::Leaves,
            start: 0,
            count: mesh.indices.len() as u32,
        });
    }
    BakedLeaves { mesh, colors, tangents: tan }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;

    #[test]
    fn options_from_json() {
        assert_eq!(ExportOptions::from_json("").unwrap(), ExportOptions::default());
        let o = ExportOptions::from_json(r#"{"leaves":"Baked","wind":false,"bark_texture_size":64}"#).unwrap();
        assert_eq!(o.leaves, LeafMode::Baked);
        assert!(!o.wind && o.textures);
        assert_eq!(o.bark_texture_size, 64);
        for bad in [r#"{"leaves":"some"}"#, r#"{"wind":1}"#, r#"{"size":1}"#, "[1]", r#"{"bark_texture_size":100}"#] {
            assert!(ExportOptions::from_json(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn decompose_recovers_the_matrix() {
        // Rotation of 0.7 rad about a tilted axis, scales (0.3, 0.5, 0.5), translation.
        let q = Quat::from_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 0.7);
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
            let q = Quat::from_axis_angle(axis, r() * 3.2);
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
