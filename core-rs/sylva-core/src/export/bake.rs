//! The leaves baked into one mesh ([`bake_leaves`]) and instance matrices split into
//! translation, rotation and scale ([`decompose`]). A module of its own so that the writers
//! ([`super::glb`], [`super::obj`]) use them without importing back from [`super`].

use super::frames::tangents;
use super::tint::unorm8;
use crate::foliage::Foliage;
use crate::mesh::TreeMesh;
use glam::{Mat3, Vec3};

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

/// Per colour channel, the largest leaf tint above 1 (1 where none is). A baked file's colours
/// are the tints divided by it and its leaf texture is multiplied by it
/// ([`bake_leaves_scaled`], [`scale_texels`]), so what a viewer shows, their product, is the
/// tint times the texture even where a tint is over 1 (an autumn leaf's red: glTF's `COLOR_0`
/// and a PNG's texels stop at 1). Summer tints reach a few per cent over 1 (the leaves' yellow
/// variation), autumn reds up to about 5.
pub fn tint_scale(f: &Foliage) -> [f32; 3] {
    let mut s = [1.0f32; 3];
    for rgb in f.colors.chunks_exact(3) {
        for (c, &v) in s.iter_mut().zip(rgb) {
            if v.is_finite() && v > *c {
                *c = v;
            }
        }
    }
    s
}

/// RGBA8 texels with R, G and B multiplied by `scale` (rounded, clamped to 255), alpha kept:
/// the leaf texture of a file whose colours are divided by [`tint_scale`].
pub fn scale_texels(rgba: &[u8], scale: [f32; 3]) -> Vec<u8> {
    let mut out = rgba.to_vec();
    for px in out.chunks_exact_mut(4) {
        for (c, s) in px.iter_mut().zip(scale) {
            *c = (f32::from(*c) * s + 0.5).min(255.0) as u8;
        }
    }
    out
}

/// Bakes the instanced foliage into one mesh ([`BakedLeaves`]); `with_tangents` also transforms
/// the leaf mesh's tangents. The colours are the tints clamped to 0..1; see
/// [`bake_leaves_scaled`] for tints over 1.
pub fn bake_leaves(f: &Foliage, with_tangents: bool) -> BakedLeaves {
    bake_leaves_scaled(f, with_tangents, [1.0; 3])
}

/// [`bake_leaves`] with each tint divided by `scale` ([`tint_scale`]) before it is clamped.
pub fn bake_leaves_scaled(f: &Foliage, with_tangents: bool, scale: [f32; 3]) -> BakedLeaves {
    bake_instances(&f.mesh, &f.matrices, &f.colors, with_tangents, scale)
}

/// [`bake_leaves_scaled`] of any instanced mesh: `leaf` drawn once per 4×4 matrix of `matrices`
/// (column-major, 16 floats each) with the RGB tint of `colors` (3 floats each) divided by
/// `scale`; the organ sets ([`crate::organs::OrganSet`]) are baked by it too. The group keeps
/// the material of the leaves.
pub fn bake_instances(
    leaf: &TreeMesh,
    matrices: &[f32],
    colors_in: &[f32],
    with_tangents: bool,
    scale: [f32; 3],
) -> BakedLeaves {
    let (nv, count) = (leaf.vertex_count(), (colors_in.len() / 3).min(matrices.len() / 16));
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
    for (k, (m, rgb)) in matrices.chunks_exact(16).zip(colors_in.chunks_exact(3)).enumerate() {
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
        let c = [unorm8(rgb[0] / scale[0]), unorm8(rgb[1] / scale[1]), unorm8(rgb[2] / scale[2]), 255];
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
