//! The end of a stem cut by a hand edit ([`crate::edits::cut`]): instead of a pointed tip the bark
//! tube ends [`BEVEL`] radii short of the cut plane, a thin bark rim chamfers in at 45° to a
//! bevel ring in the cut plane, and inside it a flat face in the [`Material::CutFace`] group
//! shows the end grain. The face's vertices copy the bevel ring's positions exactly (the surface
//! stays closed when welded by position, as [`super::topology`] counts it) and carry disc
//! coordinates: `uv = 0.5 + 0.49 (x, y) / r` in the cut plane's frame, so an end-grain texture
//! drawn as a disc (pith at its centre, growth rings concentric around it, radial checks) maps
//! onto the face with the pith on the stem's axis.
//!
//! **Callus.** An old cut ([`Stem::callus`] > 0, a dated cut some years after it was made) is
//! closing: woundwood grows from the cambium at the rim and rolls in over the face (Neely 1988,
//! *Closure of branch pruning wounds*; Shigo 1984, *Compartmentalization: a conceptual framework
//! for understanding how trees grow and defend themselves*). The rim then rises from the last
//! ring to a rounded roll's crest ([`ROLL_HEIGHT`] of its width above the cut plane) and curls
//! down to an inner ring at the wound's open radius, all bark; the end-grain face is the disc
//! inside it, with the same disc coordinates (the pith stays at the centre, the outer rings are
//! under the roll). A closed wound keeps a seam of [`OPEN_MIN`] of the radius. One more ring
//! (the inner one) and its quads are the whole cost.
pub(crate) use super::stem::CutEnd;
use super::stem::{Frame, StemMesh};
use super::{Material, MeshBuilder, Tail, VertexBlock, WIND_STRIDE};
use crate::skeleton::Stem;
use glam::Vec3;
use std::f32::consts::TAU;

/// Depth and width of the bark rim's chamfer, in radii of the stem at the cut.
pub const BEVEL: f32 = 0.08;
/// Height of the callus roll's crest above the cut plane, in widths of the woundwood.
pub const ROLL_HEIGHT: f32 = 0.3;
/// Where the roll's crest lies across the woundwood, as a fraction of its width from the rim.
const CREST: f32 = 0.4;
/// The open radius of a closed wound (its seam), in radii of the stem at the cut.
pub const OPEN_MIN: f32 = 0.04;

/// Rings the cut end adds beyond a pointed tip's apex: the bevel ring and the face ring, and a
/// callus's inner ring.
pub(crate) fn rings(stem: &Stem) -> usize {
    if stem.callus > 0.0 {
        3
    } else {
        2
    }
}

/// Vertices the cut end of `stem` adds beyond a pointed tip's apex.
pub(crate) fn extra_vertices(stem: &Stem, sides: u32) -> u64 {
    rings(stem) as u64 * (u64::from(sides) + 1)
}

/// Indices the cut end of `stem` adds beyond a pointed tip's fan: the rim's quads (and a
/// callus's second row of them) and the face's fan.
pub(crate) fn extra_indices(stem: &Stem, sides: u32) -> u64 {
    u64::from(sides) * if stem.callus > 0.0 { 15 } else { 9 }
}

/// Triangles the rim of a cut end takes where a pointed tip's fan would go, per side.
pub(crate) fn rim_triangles(end: CutEnd) -> usize {
    if end.callus {
        4
    } else {
        2
    }
}

/// The chamfer's depth at the end of `stem` (m).
pub(crate) fn bevel(stem: &Stem) -> f32 {
    BEVEL * stem.radius_at(1.0).max(0.05 * stem.radius)
}

/// Writes the cut end of a swept stem into `block`: the face centre at `centre_slot` (the slot
/// a pointed tip's apex takes), the bevel ring and the face ring from `slot` on, both from the
/// last ring (`last` its first slot, `ring` its vertex count, `frame` its frame, `radius` its
/// nominal radius, `v` its bark `v`). `tip` and `tangent` are the stem's end point and direction.
/// With `callus` > 0 the rim is a callus roll instead ([`write_callus`]).
#[allow(clippy::too_many_arguments, reason = "one ring's geometry, and where to write it")]
pub(crate) fn write(
    block: &mut VertexBlock,
    slot: usize,
    centre_slot: usize,
    (last, ring): (usize, usize),
    frame: &Frame,
    (radius, callus): (f32, f32),
    v: f32,
    (tip, tangent): (Vec3, Vec3),
    record: &[f32; WIND_STRIDE],
) {
    if callus > 0.0 {
        write_callus(block, slot, (last, ring), frame, (radius, callus), v, (tip, tangent));
    } else {
        write_bevel(block, slot, (last, ring), frame, radius, v, (tip, tangent));
    }
    block.write(centre_slot, tip, tangent, [0.5, 0.5]);
    let rings = if callus > 0.0 { 3 } else { 2 };
    for s in [centre_slot].into_iter().chain(slot..slot + rings * ring) {
        if !block.wind.is_empty() {
            block.wind[s * WIND_STRIDE..(s + 1) * WIND_STRIDE].copy_from_slice(record);
        }
    }
}

/// A fresh cut's rim: the bevel ring and the face ring (see [`write`](fn@write)).
fn write_bevel(
    block: &mut VertexBlock,
    slot: usize,
    (last, ring): (usize, usize),
    frame: &Frame,
    radius: f32,
    v: f32,
    (tip, tangent): (Vec3, Vec3),
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
}

/// An old cut's callus roll: the crest ring at `slot`, the face ring after it and the inner ring
/// after that (see the module doc). `callus` is the closed fraction of the radius.
fn write_callus(
    block: &mut VertexBlock,
    slot: usize,
    (last, ring): (usize, usize),
    frame: &Frame,
    (radius, callus): (f32, f32),
    v: f32,
    (tip, tangent): (Vec3, Vec3),
) {
    let r = radius.max(1e-6);
    let b = BEVEL * radius;
    let width = callus.min(1.0) * radius;
    let open = radius * (1.0 - callus).max(OPEN_MIN);
    let (crest_r, crest_h) = (radius - CREST * width, ROLL_HEIGHT * width);
    let binormal = frame.tangent.cross(frame.normal);
    // Bark `v` along the roll's profile (the same on every side: continuous across the ring).
    // (Not `hypot`: std's is the platform's libm, which differs natively and in wasm.)
    let v_crest = v + glam::Vec2::new(CREST * width, b + crest_h).length() / (TAU * r);
    let v_inner = v_crest + glam::Vec2::new(crest_r - open, crest_h).length() / (TAU * r);
    let shift = tip - frame.centre;
    for j in 0..ring {
        let k = (last + j) * 3;
        let l = Vec3::new(block.positions[k], block.positions[k + 1], block.positions[k + 2]);
        // The ring's own radial (lobes kept), scaled to a radius in the cut plane.
        let radial = l - frame.centre;
        let out = radial.normalize_or(frame.normal);
        let at = |rho: f32, h: f32| l + shift + radial * (rho / r - 1.0) + tangent * h;
        let u = block.uvs[(last + j) * 2];
        let crest = at(crest_r, crest_h);
        block.write(slot + j, crest, (out * 0.35 + tangent).normalize_or(tangent), [u, v_crest]);
        let inner = at(open, 0.0);
        block.write(slot + 2 * ring + j, inner, (tangent - out * 0.6).normalize_or(tangent), [u, v_inner]);
        let d = inner - tip;
        let disc = [0.5 + 0.49 * d.dot(frame.normal) / r, 0.5 + 0.49 * d.dot(binormal) / r];
        block.write(slot + ring + j, inner, tangent, disc.map(|x| x.clamp(0.0, 1.0)));
    }
}

/// The chamfer's quads from the last ring to the bevel ring (bark), and a callus's from its
/// crest ring to its inner ring, written where a pointed tip's fan would go:
/// [`rim_triangles`]` * sides` triangles.
pub(crate) fn rim_indices(m: &StemMesh, end: CutEnd, out: &mut Tail<u32>) {
    let (s, st) = (m.sides, m.sides + 1);
    let row = m.first + (m.rings - 1) * st;
    let bevel = end.first;
    for j in 0..s {
        let (a, b) = (row + j, row + j + 1);
        let (c, d) = (bevel + j + 1, bevel + j);
        out.push([a, b, c, a, c, d]);
    }
    if !end.callus {
        return;
    }
    let inner = bevel + 2 * st;
    for j in 0..s {
        let (a, b) = (bevel + j, bevel + j + 1);
        let (c, d) = (inner + j + 1, inner + j);
        out.push([a, b, c, a, c, d]);
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
        let face = m.cut.expect("filtered").first + m.sides + 1;
        let idx = out.alloc_indices(m.sides as usize * 3);
        for (j, f) in (0..m.sides).zip(idx.chunks_exact_mut(3)) {
            f.copy_from_slice(&[face + j, face + j + 1, m.apex]);
        }
    }
}
