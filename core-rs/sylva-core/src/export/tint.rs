//! The per-vertex bark tint both formats write ([`bark_colors`]): darker and greener at the foot
//! of the tree, lighter and greyer on young bark, multiplied by the bark occlusion. A module of its
//! own so that the GLB writer ([`super::glb`]) uses it without importing back from [`super`].

use super::quant::LANES;
use crate::mesh::TreeMesh;

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
pub(super) fn unorm8(x: f32) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}
