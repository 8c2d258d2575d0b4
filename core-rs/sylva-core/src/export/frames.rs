//! Normals and tangents for export (glTF `NORMAL` and `TANGENT`, KHR_mesh_quantization bytes):
//! Lengyel's per-triangle tangents, and the faster frames the GLB writes, which take a tube-ring
//! vertex's tangent from its ring neighbours ([`crate::mesh::TreeMesh::rings`]) and use
//! Lengyel's sums only for the vertices on no ring.

use super::quant::{self, LANES};
use crate::mesh::TreeMesh;
use glam::Vec3;
use std::ops::Range;

/// Per-vertex tangents, 4 floats each (glTF `TANGENT`): `xyz` = the unit direction of
/// increasing `u` in the surface, `w` = ±1 such that `cross(normal, xyz) · w` points along
/// increasing `v` (so a tangent-space normal map whose `x` runs along `u` and `y` along `v`,
/// as the baked bark and leaf maps do, is read the right way up by the glTF formula
/// `bitangent = cross(normal, tangent.xyz) * tangent.w`).
///
/// Lengyel's method: each triangle adds its `dP/du` (weighted by its UV area) to its three
/// vertices and votes for the handedness `sign(du1·dv2 − du2·dv1)`; the sum is made
/// perpendicular to the normal and normalised. Vertices no triangle gives a direction get any
/// unit vector perpendicular to the normal.
pub fn tangents(positions: &[f32], normals: &[f32], uvs: &[f32], indices: &[u32]) -> Vec<f32> {
    let n = positions.len() / 3;
    let mut acc = vec![[0.0f32; 4]; n];
    tangent_sums(positions, uvs, indices, &mut acc);
    let mut out = Vec::with_capacity(4 * n);
    for (o, nn) in acc.iter().zip(normals.chunks_exact(3)) {
        let (u, w) = tangent_of(*o, &[nn[0], nn[1], nn[2]]);
        out.extend_from_slice(&[u.x, u.y, u.z, w]);
    }
    out
}

/// The tangents the GLB writer gives a mesh's vertices ([`frames_snorm8_write`]), 4 floats
/// each as in [`tangents`]. A vertex on one of the mesh's tube rings ([`TreeMesh::rings`])
/// takes the direction of increasing `u` from its ring: the difference of its two neighbours
/// around the ring (across the seam for the first vertex and its twin, which get the same
/// tangent), made perpendicular to the normal and normalised, with `w` = +1 (the rings' `u`
/// runs counter-clockwise about the stem, `v` along it). That is the chord Lengyel's sum
/// averages over the ring's quads, without the pass over the triangles. Every other vertex
/// (caps, tips, weld collars and fork patches, hole cavities, leaves) gets Lengyel's tangent
/// ([`tangents`]) from the triangles that touch such vertices.
pub fn mesh_tangents(mesh: &TreeMesh) -> Vec<f32> {
    let mut out = Vec::with_capacity(4 * mesh.vertex_count());
    frame_blocks(mesh, 0..mesh.vertex_count(), |f, k| {
        for i in 0..k {
            out.extend_from_slice(&[f.t[0][i], f.t[1][i], f.t[2][i], f.w[i]]);
        }
    });
    out
}

/// Unit normals (3 floats each) as glTF normalised `i8` into `out`, 4 bytes per vertex (`xyz`,
/// one byte of padding), each unit within the glTF validator's tolerance (see [`super::glb`]).
pub fn normals_snorm8_write(normals: &[f32], out: &mut [u8]) {
    for (d, v) in out.chunks_exact_mut(4).zip(normals.chunks_exact(3)) {
        d.copy_from_slice(&quant::snorm8_unit_word([v[0], v[1], v[2]]).to_le_bytes());
    }
}

/// The normals and tangents ([`mesh_tangents`]) of a mesh's vertices `vertices` as glTF
/// normalised `i8` into `out` (8 bytes per vertex of the range): the normal (`xyz`, one byte of
/// padding), then the tangent (`xyz`, `w` = ±127); each vector unit within the glTF
/// validator's tolerance (see [`super::glb`]). Any split of the vertices into ranges writes the
/// same bytes (the GLB writer splits them between threads). One pass over the vertices in
/// order, a block of [`LANES`] at a time ([`quant::snorm8_unit_words`]); in wasm without SIMD,
/// where the blocks only add loads and stores, one vertex at a time ([`frames_snorm8_scalar`],
/// the same arithmetic and bytes).
pub fn frames_snorm8_write(mesh: &TreeMesh, vertices: Range<usize>, out: &mut [u8]) {
    if cfg!(all(target_arch = "wasm32", not(target_feature = "simd128"))) {
        return frames_snorm8_scalar(mesh, vertices, out);
    }
    let mut normals = [0u32; LANES];
    let mut tangents = [0u32; LANES];
    let mut blocks = out.chunks_mut(8 * LANES);
    frame_blocks(mesh, vertices, |f, _| {
        quant::snorm8_unit_words(&f.n, &mut normals);
        quant::snorm8_unit_words(&f.t, &mut tangents);
        let Some(block) = blocks.next() else { return };
        for (i, d) in block.chunks_exact_mut(8).enumerate() {
            d.copy_from_slice(&frame_bytes(normals[i], tangents[i], f.w[i]));
        }
    });
}

/// A normal and a tangent word ([`quant::snorm8_unit_word`]) and the handedness as the 8 bytes
/// of a vertex in [`frames_snorm8_write`].
#[inline(always)]
fn frame_bytes(normal: u32, tangent: u32, w: f32) -> [u8; 8] {
    let w: u32 = if w < 0.0 { 0x81 } else { 0x7f };
    (u64::from(normal) | u64::from(tangent | w << 24) << 32).to_le_bytes()
}

/// What both frame writers read for a range of vertices: the vertex count, positions and
/// normals, the mesh's rings (none if they do not describe these vertices) from the first one
/// reaching into the range, and Lengyel's sums for the range's vertices on no ring.
struct FrameInputs<'a> {
    n: usize,
    range: Range<usize>,
    pos: &'a [[f32; 3]],
    nrm: &'a [[f32; 3]],
    rings: &'a [[u32; 2]],
    others: Vec<[f32; 4]>,
}

impl<'a> FrameInputs<'a> {
    fn of(mesh: &'a TreeMesh, vertices: Range<usize>) -> Self {
        let n = mesh.vertex_count().min(mesh.normals.len() / 3);
        let range = vertices.start.min(n)..vertices.end.min(n);
        let rings = if rings_valid(&mesh.rings, n) { &mesh.rings[..] } else { &[] };
        let rings = &rings[rings.partition_point(|r| (r[0] + r[1]) as usize <= range.start)..];
        FrameInputs {
            n,
            pos: bytemuck::cast_slice(&mesh.positions[..3 * n]),
            nrm: bytemuck::cast_slice(&mesh.normals[..3 * n]),
            rings,
            others: other_sums(mesh, n, rings, range.clone()),
            range,
        }
    }
}

/// [`frames_snorm8_write`] one vertex at a time: each tangent direction (ring neighbours'
/// difference, or Lengyel's sums) through [`tangent_of`] and [`frame_word`], the arithmetic of
/// [`FrameBlock::finish`] and [`quant::snorm8_unit_words`] lane by lane.
fn frames_snorm8_scalar(mesh: &TreeMesh, vertices: Range<usize>, out: &mut [u8]) {
    let FrameInputs { n, range, pos, nrm, rings, others } = FrameInputs::of(mesh, vertices);
    let mut sums = others.iter();
    // The next ring not yet passed (`n..n` after the last).
    let mut ring = rings.iter().map(|r| r[0] as usize..(r[0] + r[1]) as usize);
    let mut r = ring.next().unwrap_or(n..n);
    for ((v, nn), d) in range.clone().zip(&nrm[range]).zip(out.chunks_exact_mut(8)) {
        if v == r.end {
            r = ring.next().unwrap_or(n..n);
        }
        let o = if v < r.start {
            sums.next().copied().unwrap_or_default()
        } else {
            // Neighbours around the ring; the first vertex and its seam twin take the two
            // beside the seam.
            let a = pos[if v == r.start { r.end - 2 } else { v - 1 }];
            let b = pos[if v + 1 == r.end { r.start + 1 } else { v + 1 }];
            [b[0] - a[0], b[1] - a[1], b[2] - a[2], 1.0]
        };
        let (u, w) = tangent_of(o, nn);
        d.copy_from_slice(&frame_word(*nn, u.to_array(), w));
    }
}

/// The frames of [`LANES`] consecutive vertices, one array per component (so the loops over
/// them run as vector code where there is vector code).
struct FrameBlock {
    /// Normals `x`, `y`, `z`.
    n: [[f32; LANES]; 3],
    /// Unit tangents `x`, `y`, `z` (on entry to [`FrameBlock::finish`]: the directions to make
    /// perpendicular to the normals and normalise).
    t: [[f32; LANES]; 3],
    /// Handedness, ±1.
    w: [f32; LANES],
}

impl FrameBlock {
    /// Makes the first `k` tangent directions perpendicular to their normals and unit: the
    /// arithmetic of `crate::math::unit_or` in a loop without branches, then a second look at
    /// the rare lanes it cannot normalise ([`any_perpendicular`]).
    #[inline(always)]
    fn finish(&mut self, k: usize) {
        let [nx, ny, nz] = &self.n;
        let [tx, ty, tz] = &mut self.t;
        let mut bad = [false; LANES];
        for i in 0..LANES {
            let (n, d) = ([nx[i], ny[i], nz[i]], [tx[i], ty[i], tz[i]]);
            let dot = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
            let p = [d[0] - n[0] * dot, d[1] - n[1] * dot, d[2] - n[2] * dot];
            let len2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
            bad[i] = !(len2 > 1e-24 && len2 < f32::INFINITY);
            let inv = 1.0 / len2.sqrt();
            (tx[i], ty[i], tz[i]) = (p[0] * inv, p[1] * inv, p[2] * inv);
        }
        for i in (0..k).filter(|&i| bad[i]) {
            let u = any_perpendicular(Vec3::new(nx[i], ny[i], nz[i]));
            (tx[i], ty[i], tz[i]) = (u.x, u.y, u.z);
        }
    }
}

/// Calls `emit(block, k)` for the vertices `vertices` of `mesh` in order, [`LANES`] at a time
/// (`k` of them in the block, fewer in the last), with the normals and the tangents of [`mesh_tangents`]: the
/// ring vertices' from their ring neighbours, the others' from Lengyel's sums over the
/// triangles touching them ([`other_sums`]).
#[inline(always)]
fn frame_blocks(mesh: &TreeMesh, vertices: Range<usize>, mut emit: impl FnMut(&FrameBlock, usize)) {
    let FrameInputs { n, range, pos, nrm, rings, others } = FrameInputs::of(mesh, vertices);
    let mut sums = others.iter();
    let mut f = FrameBlock { n: [[0.0; LANES]; 3], t: [[0.0; LANES]; 3], w: [1.0; LANES] };
    // The next ring not yet passed (`n..n` after the last).
    let mut ring = rings.iter().map(|r| r[0] as usize..(r[0] + r[1]) as usize);
    let mut r = ring.next().unwrap_or(n..n);
    for first in range.clone().step_by(LANES) {
        let end = first + LANES.min(range.end - first);
        for (i, nn) in nrm[first..end].iter().enumerate() {
            (f.n[0][i], f.n[1][i], f.n[2][i]) = (nn[0], nn[1], nn[2]);
        }
        let mut v = first;
        while v < end {
            if v < r.start {
                // Vertices on no ring: Lengyel's sums, in order.
                for (i, o) in (v - first..r.start.min(end) - first).zip(&mut sums) {
                    (f.t[0][i], f.t[1][i], f.t[2][i]) = (o[0], o[1], o[2]);
                    f.w[i] = if o[3] < 0.0 { -1.0 } else { 1.0 };
                }
                v = r.start.min(end);
                continue;
            }
            // Ring vertices: the difference of the neighbours around the ring; the first
            // vertex and its seam twin (the last) both take the two beside the seam.
            let stop = r.end.min(end);
            f.w[v - first..stop - first].fill(1.0);
            let seam = |f: &mut FrameBlock, i: usize| {
                let (a, b) = (pos[r.end - 2], pos[r.start + 1]);
                (f.t[0][i], f.t[1][i], f.t[2][i]) = (b[0] - a[0], b[1] - a[1], b[2] - a[2]);
            };
            if v == r.start {
                seam(&mut f, v - first);
                v += 1;
            }
            let inner = stop.min(r.end - 1);
            for u in v..inner {
                let (a, b, i) = (pos[u - 1], pos[u + 1], u - first);
                (f.t[0][i], f.t[1][i], f.t[2][i]) = (b[0] - a[0], b[1] - a[1], b[2] - a[2]);
            }
            v = v.max(inner);
            if v < stop {
                seam(&mut f, v - first);
                v += 1;
            }
            if v == r.end {
                r = ring.next().unwrap_or(n..n);
            }
        }
        f.finish(end - first);
        emit(&f, end - first);
    }
}

/// Whether `rings` can be read as [`TreeMesh::rings`] of a mesh with `n` vertices: sorted,
/// disjoint, inside the mesh, at least 3 vertices each (else the writer ignores them all).
fn rings_valid(rings: &[[u32; 2]], n: usize) -> bool {
    let mut end = 0u64;
    rings.iter().all(|&[first, count]| {
        let ok = u64::from(first) >= end && count >= 3;
        end = u64::from(first) + u64::from(count);
        ok
    }) && end <= n as u64
}

/// Lengyel's sums ([`tangent_sums`]) of the vertices `range` of `mesh` (of its first `n`) that
/// lie on none of `rings` (valid, see [`rings_valid`]; those before the range may be left out),
/// in vertex order: one pass over all the triangles, each tested against a bit set of those
/// vertices, adding only to them (a vertex's slot is its rank in the bit set: the count before
/// its byte, plus the bits below it in its byte). A vertex's sum does not depend on the range:
/// its triangles add to it in the same order.
fn other_sums(mesh: &TreeMesh, n: usize, rings: &[[u32; 2]], range: Range<usize>) -> Vec<[f32; 4]> {
    let (lo, len) = (range.start, range.len());
    // Bit i: vertex lo + i is on no ring (bits past len are never read).
    let mut bits = vec![0xffu8; len.div_ceil(8)];
    let mut on_rings = 0;
    for r in rings {
        let (a, b) = ((r[0] as usize).max(lo), ((r[0] + r[1]) as usize).min(range.end));
        if a >= range.end {
            break;
        }
        if a < b {
            clear_bits(&mut bits, a - lo, b - lo);
            on_rings += b - a;
        }
    }
    let mut acc = vec![[0.0f32; 4]; len - on_rings];
    if acc.is_empty() {
        return acc;
    }
    let mut rank = Vec::with_capacity(bits.len());
    let mut before = 0u32;
    for &b in &bits {
        rank.push(before);
        before += b.count_ones();
    }
    let pos: &[[f32; 3]] = bytemuck::cast_slice(&mesh.positions[..3 * n]);
    let uv: &[[f32; 2]] = bytemuck::cast_slice(&mesh.uvs[..2 * n]);
    let other = |v: usize| {
        let i = v.wrapping_sub(lo);
        if i < len {
            bits[i >> 3] >> (i & 7) & 1
        } else {
            0
        }
    };
    for tri in mesh.indices.chunks_exact(3) {
        let (a, b, c) = (tri[0] as usize, tri[1] as usize, tri[2] as usize);
        if other(a) | other(b) | other(c) == 0 {
            continue;
        }
        let Some(d) = lengyel(pos, uv, a, b, c) else { continue };
        for v in [a, b, c] {
            if other(v) != 0 {
                let i = v - lo;
                let below = bits[i >> 3] & ((1u8 << (i & 7)) - 1);
                let slot = &mut acc[(rank[i >> 3] + below.count_ones()) as usize];
                *slot = [slot[0] + d[0], slot[1] + d[1], slot[2] + d[2], slot[3] + d[3]];
            }
        }
    }
    acc
}

/// Clears bits `lo..hi` of a bit set (bit `i` is bit `i % 8` of byte `i / 8`).
fn clear_bits(bits: &mut [u8], lo: usize, hi: usize) {
    let (a, b) = (lo.div_ceil(8), hi / 8);
    if a < b {
        bits[a..b].fill(0);
        for v in (lo..a * 8).chain(b * 8..hi) {
            bits[v >> 3] &= !(1 << (v & 7));
        }
    } else {
        for v in lo..hi {
            bits[v >> 3] &= !(1 << (v & 7));
        }
    }
}

/// A vertex's normal and tangent (unit vectors, `w` = ±1) as the 8 bytes of
/// [`frames_snorm8_write`].
#[inline(always)]
fn frame_word(n: [f32; 3], t: [f32; 3], w: f32) -> [u8; 8] {
    frame_bytes(quant::snorm8_unit_word(n), quant::snorm8_unit_word(t), w)
}

/// Normals (3 floats each) and given tangents (4 floats each, `w` = ±1) into `out` as
/// [`frames_snorm8_write`] writes them.
pub fn frames_of_snorm8_write(normals: &[f32], tangents: &[f32], out: &mut [u8]) {
    for ((d, n), t) in out.chunks_exact_mut(8).zip(normals.chunks_exact(3)).zip(tangents.chunks_exact(4)) {
        d.copy_from_slice(&frame_word([n[0], n[1], n[2]], [t[0], t[1], t[2]], t[3]));
    }
}

/// Lengyel's sums: per vertex (`acc`, zero on entry, one entry per vertex) the UV-area weighted
/// `dP/du` of its triangles and the sum of their handedness votes ([`lengyel`]).
fn tangent_sums(positions: &[f32], uvs: &[f32], indices: &[u32], acc: &mut [[f32; 4]]) {
    let n = acc.len();
    let pos: &[[f32; 3]] = bytemuck::cast_slice(&positions[..3 * n]);
    let uv: &[[f32; 2]] = bytemuck::cast_slice(&uvs[..2 * n]);
    for tri in indices.chunks_exact(3) {
        let (a, b, c) = (tri[0] as usize, tri[1] as usize, tri[2] as usize);
        let Some(d) = lengyel(pos, uv, a, b, c) else { continue };
        for v in [a, b, c] {
            let o = &mut acc[v];
            *o = [o[0] + d[0], o[1] + d[1], o[2] + d[2], o[3] + d[3]];
        }
    }
}

/// One triangle's term of Lengyel's sums: its `dP/du` times the sign `s` of its UV area
/// (`du1·dv2 − du2·dv1`, so weighted by the area's magnitude), and `s`; `None` for a triangle
/// without UV area.
#[inline(always)]
fn lengyel(pos: &[[f32; 3]], uv: &[[f32; 2]], a: usize, b: usize, c: usize) -> Option<[f32; 4]> {
    let (pa, pb, pc) = (pos[a], pos[b], pos[c]);
    let (ua, ub, uc) = (uv[a], uv[b], uv[c]);
    let e1 = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
    let e2 = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
    let (du1, dv1) = (ub[0] - ua[0], ub[1] - ua[1]);
    let (du2, dv2) = (uc[0] - ua[0], uc[1] - ua[1]);
    let r = du1 * dv2 - du2 * dv1;
    if r == 0.0 || !r.is_finite() {
        return None;
    }
    let s = if r > 0.0 { 1.0 } else { -1.0 };
    Some([(e1[0] * dv2 - e2[0] * dv1) * s, (e1[1] * dv2 - e2[1] * dv1) * s, (e1[2] * dv2 - e2[2] * dv1) * s, s])
}

/// A vertex's tangent from its sums ([`tangent_sums`]) and normal: the sum made perpendicular to
/// the normal and normalised (any perpendicular unit vector when that fails), and `w` = ±1.
#[inline(always)]
fn tangent_of(o: [f32; 4], nn: &[f32; 3]) -> (Vec3, f32) {
    let nv = Vec3::from_array(*nn);
    let d = Vec3::new(o[0], o[1], o[2]);
    let u = crate::math::unit_or(d - nv * nv.dot(d), || any_perpendicular(nv));
    (u, if o[3] < 0.0 { -1.0 } else { 1.0 })
}

/// A unit vector perpendicular to `n` (for vertices no triangle gives a tangent).
#[cold]
#[inline(never)]
fn any_perpendicular(n: Vec3) -> Vec3 {
    crate::math::unit_or(n.cross(Vec3::Y), || crate::math::unit_or(n.cross(Vec3::X), || Vec3::X))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangents_follow_u_and_v() {
        // A quad in the xy plane facing +z: u along +x, v along +y -> tangent +x, w = +1
        // (cross(+z, +x) = +y = +v).
        let pos = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0];
        let nrm = [0.0, 0.0, 1.0].repeat(4);
        let uv = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
        let t = tangents(&pos, &nrm, &uv, &[0, 1, 2, 0, 2, 3]);
        for v in t.chunks_exact(4) {
            assert_eq!(v, [1.0, 0.0, 0.0, 1.0]);
        }
        // v running down (-y): the bitangent must flip, w = -1.
        let uv = [0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0];
        let t = tangents(&pos, &nrm, &uv, &[0, 1, 2, 0, 2, 3]);
        for v in t.chunks_exact(4) {
            assert_eq!(v, [1.0, 0.0, 0.0, -1.0]);
        }
    }

    #[test]
    fn frames_are_the_same_bytes_one_vertex_at_a_time_and_in_any_split() {
        // The scalar path (wasm without SIMD) and the block path write the same bytes, and so
        // does every split of the vertices into ranges (the GLB writer's threads): ranges that
        // start inside a ring, inside a block and among the vertices on no ring.
        for name in ["default", "weeping_willow"] {
            let g = crate::generate(&crate::presets::find(name).unwrap().params().unwrap()).unwrap();
            let n = g.mesh.vertex_count();
            let mut scalar = vec![0u8; 8 * n];
            frames_snorm8_scalar(&g.mesh, 0..n, &mut scalar);
            let mut whole = vec![0u8; 8 * n];
            frames_snorm8_write(&g.mesh, 0..n, &mut whole);
            assert!(scalar == whole, "{name}: scalar");
            let off_ring =
                (0..n).find(|&v| !g.mesh.rings.iter().any(|r| (r[0] as usize..(r[0] + r[1]) as usize).contains(&v)));
            let cuts = [0, 1, 37, n / 3, off_ring.map_or(n / 2, |v| v + 1), n / 2 + 5, n - 3, n];
            let mut cuts = cuts.to_vec();
            cuts.sort_unstable();
            let mut split = vec![0u8; 8 * n];
            let mut split_scalar = vec![0u8; 8 * n];
            for w in cuts.windows(2) {
                frames_snorm8_write(&g.mesh, w[0]..w[1], &mut split[8 * w[0]..8 * w[1]]);
                frames_snorm8_scalar(&g.mesh, w[0]..w[1], &mut split_scalar[8 * w[0]..8 * w[1]]);
            }
            assert!(split == whole, "{name}: split");
            assert!(split_scalar == whole, "{name}: split, scalar");
        }
    }
}
