//! Normals and tangents for export (glTF `NORMAL` and `TANGENT`, KHR_mesh_quantization bytes):
//! Lengyel's per-triangle tangents, and the faster frames the GLB writes, which take a tube-ring
//! vertex's tangent from its ring neighbours ([`crate::mesh::TreeMesh::rings`]) and use
//! Lengyel's sums only for the vertices on no ring.

use super::quant::{self, LANES};
use crate::mesh::TreeMesh;
use glam::Vec3;

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

/// The tangents the GLB writer gives a mesh's vertices ([`frames_snorm8_append`]), 4 floats
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
    frame_blocks(mesh, |f, k| {
        for i in 0..k {
            out.extend_from_slice(&[f.t[0][i], f.t[1][i], f.t[2][i], f.w[i]]);
        }
    });
    out
}

/// Unit normals (3 floats each) appended to `out` as glTF normalised `i8`, 4 bytes per vertex
/// (`xyz`, one byte of padding), each unit within the glTF validator's tolerance (see [`super::glb`]).
pub fn normals_snorm8_append(normals: &[f32], out: &mut Vec<u8>) {
    let mut block = [0u8; 4 * LANES];
    for c in normals.chunks(3 * LANES) {
        for (d, v) in block.chunks_exact_mut(4).zip(c.chunks_exact(3)) {
            d.copy_from_slice(&quant::snorm8_unit_word([v[0], v[1], v[2]]).to_le_bytes());
        }
        out.extend_from_slice(&block[..c.len() / 3 * 4]);
    }
}

/// A mesh's normals and its tangents ([`mesh_tangents`]) appended to `out` as glTF normalised
/// `i8`, 8 bytes per vertex: the normal (`xyz`, one byte of padding), then the tangent (`xyz`,
/// `w` = ±127); each vector unit within the glTF validator's tolerance (see [`super::glb`]). One pass
/// over the vertices in order, a block of [`LANES`] at a time ([`quant::snorm8_unit_words`]);
/// in wasm without SIMD, where the blocks only add loads and stores, one vertex at a time
/// ([`frames_snorm8_scalar`], the same arithmetic and bytes).
pub fn frames_snorm8_append(mesh: &TreeMesh, out: &mut Vec<u8>) {
    if cfg!(all(target_arch = "wasm32", not(target_feature = "simd128"))) {
        return frames_snorm8_scalar(mesh, out);
    }
    let mut normals = [0u32; LANES];
    let mut tangents = [0u32; LANES];
    let mut block = [0u64; LANES];
    frame_blocks(mesh, |f, k| {
        quant::snorm8_unit_words(&f.n, &mut normals);
        quant::snorm8_unit_words(&f.t, &mut tangents);
        for i in 0..LANES {
            let w: u32 = if f.w[i] < 0.0 { 0x81 } else { 0x7f };
            block[i] = (u64::from(normals[i]) | u64::from(tangents[i] | w << 24) << 32).to_le();
        }
        out.extend_from_slice(&bytemuck::cast_slice(&block)[..8 * k]);
    });
}

/// What both frame writers read: the vertex count, positions and normals, the mesh's rings (none
/// if they do not describe these vertices) and Lengyel's sums for the vertices on no ring.
struct FrameInputs<'a> {
    n: usize,
    pos: &'a [[f32; 3]],
    nrm: &'a [[f32; 3]],
    rings: &'a [[u32; 2]],
    others: Vec<[f32; 4]>,
}

impl<'a> FrameInputs<'a> {
    fn of(mesh: &'a TreeMesh) -> Self {
        let n = mesh.vertex_count().min(mesh.normals.len() / 3);
        let rings = if rings_valid(&mesh.rings, n) { &mesh.rings[..] } else { &[] };
        FrameInputs {
            n,
            pos: bytemuck::cast_slice(&mesh.positions[..3 * n]),
            nrm: bytemuck::cast_slice(&mesh.normals[..3 * n]),
            rings,
            others: other_sums(mesh, n, rings),
        }
    }
}

/// [`frames_snorm8_append`] one vertex at a time: each tangent direction (ring neighbours'
/// difference, or Lengyel's sums) through [`tangent_of`] and [`frame_word`], the arithmetic of
/// [`FrameBlock::finish`] and [`quant::snorm8_unit_words`] lane by lane.
fn frames_snorm8_scalar(mesh: &TreeMesh, out: &mut Vec<u8>) {
    let FrameInputs { n, pos, nrm, rings, others } = FrameInputs::of(mesh);
    let mut sums = others.iter();
    let mut block = [0u64; LANES];
    let mut k = 0;
    // The next ring not yet passed (`n..n` after the last).
    let mut ring = rings.iter().map(|r| r[0] as usize..(r[0] + r[1]) as usize);
    let mut r = ring.next().unwrap_or(n..n);
    for (v, nn) in nrm.iter().enumerate() {
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
        block[k] = frame_word(*nn, u.to_array(), w).to_le();
        k += 1;
        if k == LANES {
            out.extend_from_slice(bytemuck::cast_slice(&block));
            k = 0;
        }
    }
    out.extend_from_slice(&bytemuck::cast_slice(&block)[..8 * k]);
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

/// Calls `emit(block, k)` for the vertices of `mesh` in order, [`LANES`] at a time (`k` of them
/// in the block, fewer in the last), with the normals and the tangents of [`mesh_tangents`]: the
/// ring vertices' from their ring neighbours, the others' from Lengyel's sums over the
/// triangles touching them ([`other_sums`]).
#[inline(always)]
fn frame_blocks(mesh: &TreeMesh, mut emit: impl FnMut(&FrameBlock, usize)) {
    let FrameInputs { n, pos, nrm, rings, others } = FrameInputs::of(mesh);
    let mut sums = others.iter();
    let mut f = FrameBlock { n: [[0.0; LANES]; 3], t: [[0.0; LANES]; 3], w: [1.0; LANES] };
    // The next ring not yet passed (`n..n` after the last).
    let mut ring = rings.iter().map(|r| r[0] as usize..(r[0] + r[1]) as usize);
    let mut r = ring.next().unwrap_or(n..n);
    for first in (0..n).step_by(LANES) {
        let end = first + LANES.min(n - first);
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

/// Lengyel's sums ([`tangent_sums`]) of the vertices of `mesh` (the first `n`) that lie on none
/// of `rings` (valid, see [`rings_valid`]), in vertex order: one pass over the triangles, each
/// tested against a bit set of those vertices, adding only to them (a vertex's slot is its rank
/// in the bit set: the count before its byte, plus the bits below it in its byte).
fn other_sums(mesh: &TreeMesh, n: usize, rings: &[[u32; 2]]) -> Vec<[f32; 4]> {
    let on_rings: usize = rings.iter().map(|r| r[1] as usize).sum();
    let mut acc = vec![[0.0f32; 4]; n - on_rings];
    if rings.is_empty() {
        tangent_sums(&mesh.positions, &mesh.uvs, &mesh.indices, &mut acc);
        return acc;
    }
    if acc.is_empty() {
        return acc;
    }
    // Bit v: vertex v is on no ring (bits past n stay set: no index reaches them).
    let mut bits = vec![0xffu8; n.div_ceil(8) + 1];
    for r in rings {
        let (lo, hi) = (r[0] as usize, (r[0] + r[1]) as usize);
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
    let mut rank = Vec::with_capacity(bits.len());
    let mut before = 0u32;
    for &b in &bits {
        rank.push(before);
        before += b.count_ones();
    }
    let pos: &[[f32; 3]] = bytemuck::cast_slice(&mesh.positions[..3 * n]);
    let uv: &[[f32; 2]] = bytemuck::cast_slice(&mesh.uvs[..2 * n]);
    let other = |v: usize| bits[v >> 3] >> (v & 7) & 1;
    for tri in mesh.indices.chunks_exact(3) {
        let (a, b, c) = (tri[0] as usize, tri[1] as usize, tri[2] as usize);
        if other(a) | other(b) | other(c) == 0 {
            continue;
        }
        let Some(d) = lengyel(pos, uv, a, b, c) else { continue };
        for v in [a, b, c] {
            if other(v) != 0 {
                let below = bits[v >> 3] & ((1u8 << (v & 7)) - 1);
                let slot = &mut acc[(rank[v >> 3] + below.count_ones()) as usize];
                *slot = [slot[0] + d[0], slot[1] + d[1], slot[2] + d[2], slot[3] + d[3]];
            }
        }
    }
    acc
}

/// A vertex's normal and tangent (unit vectors, `w` = ±1) as the 8 little-endian bytes of
/// [`frames_snorm8_append`].
#[inline(always)]
fn frame_word(n: [f32; 3], t: [f32; 3], w: f32) -> u64 {
    let w: u32 = if w < 0.0 { 0x81 } else { 0x7f };
    u64::from(quant::snorm8_unit_word(n)) | u64::from(quant::snorm8_unit_word(t) | w << 24) << 32
}

/// Normals (3 floats each) and given tangents (4 floats each, `w` = ±1) appended to `out` as
/// [`frames_snorm8_append`] writes them.
pub fn frames_of_snorm8_append(normals: &[f32], tangents: &[f32], out: &mut Vec<u8>) {
    let mut block = [0u8; 8 * LANES];
    for (c, t) in normals.chunks(3 * LANES).zip(tangents.chunks(4 * LANES)) {
        for ((d, n), t) in block.chunks_exact_mut(8).zip(c.chunks_exact(3)).zip(t.chunks_exact(4)) {
            d.copy_from_slice(&frame_word([n[0], n[1], n[2]], [t[0], t[1], t[2]], t[3]).to_le_bytes());
        }
        out.extend_from_slice(&block[..c.len() / 3 * 8]);
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
    fn frames_one_vertex_at_a_time_are_the_blocks_bytes() {
        // The scalar path (wasm without SIMD) and the block path write the same bytes.
        for name in ["default", "weeping_willow"] {
            let g = crate::generate(&crate::presets::find(name).unwrap().params().unwrap()).unwrap();
            let (mut a, mut b) = (Vec::new(), Vec::new());
            frames_snorm8_scalar(&g.mesh, &mut a);
            let (mut normals, mut tangents) = ([0u32; LANES], [0u32; LANES]);
            frame_blocks(&g.mesh, |f, k| {
                quant::snorm8_unit_words(&f.n, &mut normals);
                quant::snorm8_unit_words(&f.t, &mut tangents);
                for i in 0..k {
                    let w: u32 = if f.w[i] < 0.0 { 0x81 } else { 0x7f };
                    b.extend_from_slice(
                        &(u64::from(normals[i]) | u64::from(tangents[i] | w << 24) << 32).to_le_bytes(),
                    );
                }
            });
            assert_eq!(a.len(), 8 * g.mesh.vertex_count());
            assert!(a == b, "{name}");
        }
    }
}
