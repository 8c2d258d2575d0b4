//! The end of a stem cut by a hand edit ([`crate::edits::cut`]): instead of a pointed tip the bark
//! tube ends [`BEVEL`] radii short of the cut plane, a thin bark rim chamfers in at 45° to a
//! bevel ring in the cut plane, and inside it a flat face in the [`Material::CutFace`] group
//! shows the end grain. The face's vertices copy the bevel ring's positions exactly (the surface
//! stays closed when welded by position, as [`super::topology`] counts it) and carry disc
//! coordinates: `uv = 0.5 + 0.49 (x, y) / r` in the cut plane's frame, so an end-grain texture
//! drawn as a disc (pith at its centre, growth rings concentric around it, radial checks) maps
//! onto the face with the pith on the stem's axis.

use super::stem::{Frame, StemMesh};
use super::{Material, MeshBuilder, VertexBlock, WIND_STRIDE};
use crate::skeleton::Stem;
use glam::Vec3;

/// Depth and width of the bark rim's chamfer, in radii of the stem at the cut.
pub const BEVEL: f32 = 0.08;
/// Vertices the cut end adds beyond a pointed tip's apex: the bevel ring and the face ring.
pub(crate) fn extra_vertices(sides: u32) -> u64 {
    2 * (u64::from(sides) + 1)
}

/// The chamfer's depth at the end of `stem` (m).
pub(crate) fn bevel(stem: &Stem) -> f32 {
    BEVEL * stem.radius_at(1.0).max(0.05 * stem.radius)
}

/// Writes the cut end of a swept stem into `block`: the face centre at `centre_slot` (the slot
/// a pointed tip's apex takes), the bevel ring and the face ring from `slot` on, both from the
/// last ring (`last` its first slot, `ring` its vertex count, `frame` its frame, `radius` its
/// nominal radius, `v` its bark `v`). `tip` and `tangent` are the stem's end point and direction.
#[allow(clippy::too_many_arguments, reason = "one ring's geometry, and where to write it")]
pub(crate) fn write(
    block: &mut VertexBlock,
    slot: usize,
    centre_slot: usize,
    (last, ring): (usize, usize),
    frame: &Frame,
    radius: f32,
    v: f32,
    (tip, tangent): (Vec3, Vec3),
    record: &[f32; WIND_STRIDE],
) {
    let b = BEVEL * radius;
    let shift = tip - frame.centre;
    let binormal = frame.tangent.cross(frame.normal);
    let v_rim = v + b * std::f32::consts::SQRT_2 / (std::f32::consts::TAU * radius.max(1e-6));
    for j in 0..ring {
        let k = (last + j) * 3;
        let l = Vec3::new(block.positions[k], block.positions[k + 1], block.positions[k + 2]);
        let radial = l - frame.centre;
        let p = l + shift - radial * (b / radius.max(1e-6));
        let n = (radial.normalize_or(frame.normal) + tangent).normalize_or(tangent);
        let u = block.uvs[(last + j) * 2];
        block.write(slot + j, p, n, [u, v_rim]);
        let d = p - tip;
        let disc = [0.5 + 0.49 * d.dot(frame.normal) / radius, 0.5 + 0.49 * d.dot(binormal) / radius];
        block.write(slot + ring + j, p, tangent, disc.map(|x| x.clamp(0.0, 1.0)));
    }
    block.write(centre_slot, tip, tangent, [0.5, 0.5]);
    for s in [centre_slot].into_iter().chain(slot..slot + 2 * ring) {
        if !block.wind.is_empty() {
            block.wind[s * WIND_STRIDE..(s + 1) * WIND_STRIDE].copy_from_slice(record);
        }
    }
}

/// The chamfer's quads from the last ring to the bevel ring (bark), written where a pointed
/// tip's fan would go: `2 * sides` triangles.
pub(crate) fn rim_indices(m: &StemMesh, bevel: u32, out: &mut [u32]) {
    let (s, st) = (m.sides, m.sides + 1);
    let row = m.first + (m.rings - 1) * st;
    for (j, q) in (0..s).zip(out.chunks_exact_mut(6)) {
        let (a, b) = (row + j, row + j + 1);
        let (c, d) = (bevel + j + 1, bevel + j);
        q.copy_from_slice(&[a, b, c, a, c, d]);
    }
}

/// The faces of every cut end, as a [`Material::CutFace`] group after the bark's triangles.
pub(crate) fn emit_faces(meshes: &[Option<StemMesh>], out: &mut MeshBuilder) {
    let cut: Vec<&StemMesh> = meshes.iter().flatten().filter(|m| m.cut.is_some()).collect();
    if cut.is_empty() {
        return;
    }
    out.begin_group(Material::CutFace);
    for m in cut {
        let face = m.cut.expect("filtered") + m.sides + 1;
        let idx = out.alloc_indices(m.sides as usize * 3);
        for (j, f) in (0..m.sides).zip(idx.chunks_exact_mut(3)) {
            f.copy_from_slice(&[face + j, face + j + 1, m.apex]);
        }
    }
}
