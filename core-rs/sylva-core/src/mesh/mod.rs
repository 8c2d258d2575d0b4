//! Mesh buffers: the one geometry type that leaves the core. The wasm payload, the OBJ (and
//! later GLB) exporters and the tests all read [`TreeMesh`]; the stages write into it through
//! [`MeshBuilder`] (lyon's `GeometryBuilder` idea), so there is one layout to document and check.

pub mod bark;
pub mod fork;
pub mod fork_rows;
pub mod holes;
pub mod shade;
pub mod topology;
pub mod trunk;
pub mod tube;
pub mod twig;
pub mod weld;

use crate::math;
use serde::Serialize;

/// Which material a range of indices uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Material {
    /// Stems: trunk, branches, twigs.
    Bark,
    /// Leaf blades.
    Leaves,
}

/// A contiguous range of `indices` drawn with one material.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MeshGroup {
    /// Material of the range.
    pub material: Material,
    /// First index (an offset into `indices`, a multiple of 3).
    pub start: u32,
    /// Number of indices (a multiple of 3).
    pub count: u32,
}

/// Axis-aligned bounds of all positions (m).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bounds {
    /// Smallest x, y, z.
    pub min: [f32; 3],
    /// Largest x, y, z.
    pub max: [f32; 3],
}

impl Bounds {
    /// The box of points (3 floats each), a zero box when there are none. Plain comparisons
    /// (NaN never wins): `f32::min` and `f32::max` are calls to `fminf` and `fmaxf` in wasm,
    /// which cost the bounds of a big tree milliseconds there.
    pub fn of(positions: &[f32]) -> Bounds {
        if positions.len() < 3 {
            return Bounds { min: [0.0; 3], max: [0.0; 3] };
        }
        // Four points per record: 12 lanes run as vector code where there is vector code.
        let whole = positions.len() / 12 * 12;
        let (lo4, hi4) = ranges::<12>(&positions[..whole]);
        let mut r = ranges::<3>(&positions[whole..]);
        for j in 0..4 {
            let part = |x: &[f32; 12]| std::array::from_fn(|k| x[3 * j + k]);
            r = merge_ranges(r, (part(&lo4), part(&hi4)));
        }
        Bounds { min: r.0, max: r.1 }
    }
}

/// Per-lane smallest and largest values of records of `N` floats (infinities for none), with
/// plain comparisons (NaN never wins).
pub(crate) fn ranges<const N: usize>(v: &[f32]) -> ([f32; N], [f32; N]) {
    let mut lo = [f32::INFINITY; N];
    let mut hi = [f32::NEG_INFINITY; N];
    for r in v.chunks_exact(N) {
        for k in 0..N {
            lo[k] = if r[k] < lo[k] { r[k] } else { lo[k] };
            hi[k] = if r[k] > hi[k] { r[k] } else { hi[k] };
        }
    }
    (lo, hi)
}

/// The smallest and largest of two [`ranges`], lane by lane (NaN never wins; on a tie the
/// first's value).
pub(crate) fn merge_ranges<const N: usize>(a: ([f32; N], [f32; N]), b: ([f32; N], [f32; N])) -> ([f32; N], [f32; N]) {
    (
        std::array::from_fn(|k| if b.0[k] < a.0[k] { b.0[k] } else { a.0[k] }),
        std::array::from_fn(|k| if b.1[k] > a.1[k] { b.1[k] } else { a.1[k] }),
    )
}

/// A generated tree as flat, typed buffers. Coordinates: metres, **Y up**, the tree's base at
/// the origin. Vertex `i` is made of:
///
/// | buffer      | type | per vertex | layout                                                    |
/// |-------------|------|-----------:|-----------------------------------------------------------|
/// | `positions` | f32  | 3          | `x, y, z` (finite)                                         |
/// | `normals`   | f32  | 3          | `nx, ny, nz`, unit length, pointing out of the surface     |
/// | `uvs`       | f32  | 2          | bark: `u` = around the stem 0..1 (seam duplicated at u = 1), `v` = along the stem, continuous, 1 unit per circumference |
///
/// | `wind`      | f32  | 8 (or none)| `pivot_x, pivot_y, pivot_z, level, phase, stiffness, distance, radius` (see below) |
///
/// `wind` is either empty or holds 8 floats per vertex for wind animation and exporters:
/// `pivot` = base point of the stem the vertex belongs to (m), `level` = branch level (0 trunk,
/// 1, 2, 3 as a float), `phase` = 0..1, one random value per stem (stream `"wind"`), `stiffness` =
/// 0..1 (1 = rigid trunk base, toward 0 on thin twigs; from the local radius relative to the trunk
/// base radius), `distance` = path length from the root to the vertex's ring along the stems (m),
/// `radius` = local stem radius at the ring (m).
///
/// `indices` (u32) hold triangles, three per triangle, counter-clockwise seen from outside;
/// `groups` split them by material. 32-bit indices: trees pass 65,535 vertices easily.
///
/// `rings` lists the tube rings among the vertices (see [`TreeMesh::rings`]): structure the
/// exporters use, derived from the same construction; it is not part of [`TreeMesh::content_hash`]
/// nor of the buffers handed to JavaScript.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TreeMesh {
    /// `x, y, z` per vertex.
    pub positions: Vec<f32>,
    /// Unit normal per vertex.
    pub normals: Vec<f32>,
    /// `u, v` per vertex.
    pub uvs: Vec<f32>,
    /// Triangle list.
    pub indices: Vec<u32>,
    /// Index ranges per material.
    pub groups: Vec<MeshGroup>,
    /// Wind data, 8 floats per vertex (layout above), or empty.
    pub wind: Vec<f32>,
    /// Tube rings, `[first vertex, vertex count]` each, sorted and disjoint: a ring is a run of
    /// `sides + 1` consecutive vertices around a swept stem (tube or twig), `u` = `j / sides`
    /// increasing along the run (counter-clockwise about the stem's direction, so
    /// `cross(normal, direction of increasing u)` points along the stem) and `v` the same for
    /// the whole ring, increasing from ring to ring; the last vertex is the seam twin of the
    /// first (the same position, `u = 1`). Every listed vertex still sits where the sweep put
    /// it (rings a later stage rewrites, as holes do, are dropped). Meshes built otherwise may
    /// leave it empty, and code that edits the positions or uvs of a generated mesh should
    /// clear it: it only lets the GLB writer take a ring vertex's tangent from its ring
    /// neighbours instead of accumulating it over triangles.
    pub rings: Vec<[u32; 2]>,
    /// Bark occlusion, one byte per vertex (0 = no light, 255 = open sky; [`shade`]), or empty.
    /// Viewers multiply the bark colour by it; part of [`TreeMesh::content_hash`].
    pub shade: Vec<u8>,
}

/// Floats per vertex in [`TreeMesh::wind`].
pub const WIND_STRIDE: usize = 8;

impl TreeMesh {
    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len() / 3
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Bounds of all positions (zero box for an empty mesh).
    pub fn bounds(&self) -> Bounds {
        Bounds::of(&self.positions)
    }

    /// Content hash of every buffer (positions, normals, uvs, indices, wind, groups): equal hashes
    /// mean byte-identical meshes. Four interleaved 64-bit FNV-1a-style lanes over pairs of
    /// 32-bit words, then mixed; the value is part of the golden tests, so change it only on purpose.
    pub fn content_hash(&self) -> u64 {
        let mut h = Hasher::new();
        h.words(&self.positions, f32::to_bits);
        h.words(&self.normals, f32::to_bits);
        h.words(&self.uvs, f32::to_bits);
        h.words(&self.indices, |i| i);
        if !self.wind.is_empty() {
            h.words(&self.wind, f32::to_bits);
        }
        if !self.shade.is_empty() {
            h.words(&self.shade, u32::from);
        }
        for g in &self.groups {
            h.words(&[g.material as u32, g.start, g.count], |w| w);
        }
        h.finish()
    }

    /// The mesh as Wavefront OBJ text (positions, uvs, normals, one `g` per group).
    pub fn to_obj(&self) -> String {
        use std::fmt::Write;
        let mut s = String::with_capacity(self.positions.len() * 40);
        s.push_str("# Sylva tree\n");
        for p in self.positions.chunks_exact(3) {
            let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
        }
        for t in self.uvs.chunks_exact(2) {
            let _ = writeln!(s, "vt {} {}", t[0], t[1]);
        }
        for n in self.normals.chunks_exact(3) {
            let _ = writeln!(s, "vn {} {} {}", n[0], n[1], n[2]);
        }
        for g in &self.groups {
            let _ = writeln!(s, "g {}", if g.material == Material::Bark { "bark" } else { "leaves" });
            let range = g.start as usize..(g.start + g.count) as usize;
            for t in self.indices[range].chunks_exact(3) {
                let (a, b, c) = (t[0] + 1, t[1] + 1, t[2] + 1);
                let _ = writeln!(s, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}");
            }
        }
        s
    }
}

struct Hasher {
    lanes: [u64; 4],
    n: u64,
}

const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

impl Hasher {
    fn new() -> Self {
        Hasher {
            lanes: [0xcbf2_9ce4_8422_2325, 0x8422_2325_cbf2_9ce4, 0x9e37_79b9_7f4a_7c15, 0x2545_f491_4f6c_dd1d],
            n: 0,
        }
    }

    /// Hash one buffer: each lane takes two 32-bit words per step as one 64-bit word (eight
    /// words per round over four independent multiply chains, so the CPU overlaps them); the
    /// tail goes one word per lane. Every step is a bijection of the lane state, so any change to
    /// any word changes the result.
    fn words<T: Copy>(&mut self, data: &[T], bits: impl Fn(T) -> u32) {
        let pair = |lo: T, hi: T| u64::from(bits(lo)) | u64::from(bits(hi)) << 32;
        let [mut a, mut b, mut c, mut d] = self.lanes;
        let mut chunks = data.chunks_exact(8);
        for q in &mut chunks {
            a = (a ^ pair(q[0], q[1])).wrapping_mul(FNV_PRIME);
            b = (b ^ pair(q[2], q[3])).wrapping_mul(FNV_PRIME);
            c = (c ^ pair(q[4], q[5])).wrapping_mul(FNV_PRIME);
            d = (d ^ pair(q[6], q[7])).wrapping_mul(FNV_PRIME);
        }
        self.lanes = [a, b, c, d];
        for (k, &w) in chunks.remainder().iter().enumerate() {
            let lane = &mut self.lanes[k & 3];
            *lane = (*lane ^ u64::from(bits(w))).wrapping_mul(FNV_PRIME);
        }
        self.n += data.len() as u64;
    }

    fn finish(&self) -> u64 {
        let mut h = self.n;
        for l in self.lanes {
            h = (h ^ l).wrapping_mul(0xff51_afd7_ed55_8ccd);
            h ^= h >> 33;
        }
        h
    }
}

/// Appends geometry to a [`TreeMesh`] and keeps the material groups. A builder made with
/// [`MeshBuilder::with_wind`] keeps [`TreeMesh::wind`] in step with the vertices: every way of
/// adding vertices adds their wind records too (zeros unless given).
pub struct MeshBuilder {
    mesh: TreeMesh,
    wind: bool,
}

/// A block of freshly appended, zeroed vertices (see [`MeshBuilder::alloc_vertices`]).
pub struct VertexBlock<'a> {
    /// Index of the first vertex of the block.
    pub first: u32,
    /// `3n` position floats.
    pub positions: &'a mut [f32],
    /// `3n` normal floats.
    pub normals: &'a mut [f32],
    /// `2n` uv floats.
    pub uvs: &'a mut [f32],
    /// `8n` wind floats ([`WIND_STRIDE`] per vertex), or empty when the builder has no wind.
    pub wind: &'a mut [f32],
}

impl MeshBuilder {
    /// An empty builder with room for about `vertices` vertices and `indices` indices.
    pub fn with_capacity(vertices: usize, indices: usize) -> Self {
        MeshBuilder {
            mesh: TreeMesh {
                positions: Vec::with_capacity(vertices * 3),
                normals: Vec::with_capacity(vertices * 3),
                uvs: Vec::with_capacity(vertices * 2),
                indices: Vec::with_capacity(indices),
                groups: Vec::new(),
                wind: Vec::new(),
                rings: Vec::new(),
                shade: Vec::new(),
            },
            wind: false,
        }
    }

    /// Like [`MeshBuilder::with_capacity`], with a [`TreeMesh::wind`] record for every vertex.
    pub fn with_wind(vertices: usize, indices: usize) -> Self {
        let mut b = Self::with_capacity(vertices, indices);
        b.mesh.wind = Vec::with_capacity(vertices * WIND_STRIDE);
        b.wind = true;
        b
    }

    /// Index the next vertex will get.
    pub fn next_index(&self) -> u32 {
        (self.mesh.positions.len() / 3) as u32
    }

    /// Append one vertex (with a zero wind record if the builder keeps wind); returns its index.
    #[inline]
    pub fn vertex(&mut self, p: [f32; 3], n: [f32; 3], uv: [f32; 2]) -> u32 {
        self.vertex_with_wind(p, n, uv, &[0.0; WIND_STRIDE])
    }

    /// Append one vertex with its wind record (ignored if the builder keeps no wind).
    #[inline]
    pub fn vertex_with_wind(&mut self, p: [f32; 3], n: [f32; 3], uv: [f32; 2], wind: &[f32; WIND_STRIDE]) -> u32 {
        let i = self.next_index();
        self.mesh.positions.extend_from_slice(&p);
        self.mesh.normals.extend_from_slice(&n);
        self.mesh.uvs.extend_from_slice(&uv);
        if self.wind {
            self.mesh.wind.extend_from_slice(wind);
        }
        i
    }

    /// Append `n` zeroed vertices (and wind records) and return mutable views of them, for
    /// stages that fill whole blocks.
    pub fn alloc_vertices(&mut self, n: usize) -> VertexBlock<'_> {
        let first = self.next_index();
        let m = &mut self.mesh;
        let (p, q, u, w) = (m.positions.len(), m.normals.len(), m.uvs.len(), m.wind.len());
        m.positions.resize(p + 3 * n, 0.0);
        m.normals.resize(q + 3 * n, 0.0);
        m.uvs.resize(u + 2 * n, 0.0);
        if self.wind {
            m.wind.resize(w + WIND_STRIDE * n, 0.0);
        }
        VertexBlock {
            first,
            positions: &mut m.positions[p..],
            normals: &mut m.normals[q..],
            uvs: &mut m.uvs[u..],
            wind: &mut m.wind[w..],
        }
    }

    /// Record `count` tube rings of `stride` vertices each (`sides + 1`, see [`TreeMesh::rings`]),
    /// the first starting at vertex `first`, the others following it back to back.
    pub fn rings(&mut self, first: u32, count: u32, stride: u32) {
        self.mesh.rings.extend((0..count).map(|r| [first + r * stride, stride]));
    }

    /// Drop every vertex from index `first` on (and its wind record, and the rings among them):
    /// undoes a block whose triangles were never written.
    pub fn truncate_vertices(&mut self, first: u32) {
        let keep = self.mesh.rings.partition_point(|r| r[0] + r[1] <= first);
        self.mesh.rings.truncate(keep);
        let n = first as usize;
        self.mesh.positions.truncate(n * 3);
        self.mesh.normals.truncate(n * 3);
        self.mesh.uvs.truncate(n * 2);
        if self.wind {
            self.mesh.wind.truncate(n * WIND_STRIDE);
        }
    }

    /// Vertex `i`'s position and normal.
    #[inline]
    pub fn vertex_at(&self, i: u32) -> (glam::Vec3, glam::Vec3) {
        let k = i as usize * 3;
        let (p, n) = (&self.mesh.positions[k..k + 3], &self.mesh.normals[k..k + 3]);
        (glam::Vec3::new(p[0], p[1], p[2]), glam::Vec3::new(n[0], n[1], n[2]))
    }

    /// Append `n` zeroed indices (a multiple of 3) and return them for filling.
    pub fn alloc_indices(&mut self, n: usize) -> &mut [u32] {
        let start = self.mesh.indices.len();
        self.mesh.indices.resize(start + n, 0);
        &mut self.mesh.indices[start..]
    }

    /// Append triangles given as a flat index list (counter-clockwise seen from outside).
    pub fn extend_indices(&mut self, indices: &[u32]) {
        self.mesh.indices.extend_from_slice(indices);
    }

    /// Replace vertex `i`'s normal.
    #[inline]
    pub fn set_normal(&mut self, i: u32, n: glam::Vec3) {
        let k = i as usize * 3;
        self.mesh.normals[k..k + 3].copy_from_slice(&n.to_array());
    }

    /// Vertex `i`'s wind record (zeros when this builder has no wind attributes).
    #[inline]
    pub fn wind_at(&self, i: u32) -> [f32; WIND_STRIDE] {
        let k = i as usize * WIND_STRIDE;
        self.mesh.wind.get(k..k + WIND_STRIDE).map_or([0.0; WIND_STRIDE], |w| w.try_into().expect("stride"))
    }

    /// Vertex `i`'s uv.
    #[inline]
    pub fn uv_at(&self, i: u32) -> [f32; 2] {
        let k = i as usize * 2;
        [self.mesh.uvs[k], self.mesh.uvs[k + 1]]
    }

    /// Makes bark `u` continuous across a stem's texture seam in the triangles `tris`, which
    /// lie on one stem's bark but were built from vertices on both sides of its seam (`u` near 0
    /// on one side, near 1 on the other; zips around a footprint that straddles the seam): each
    /// triangle's vertices are moved by whole turns (the bark texture repeats) to span the
    /// least `u` ([`seam_shifts`]). A moved vertex is replaced by its seam twin where it has one
    /// (`twin(vertex, turns)`: a ring's first vertex and its last, `u` 0 and 1), else by a copy
    /// at the same place with the moved `u`, one copy per vertex and shift. Copies keep the
    /// normal and wind record, so the surface stays closed (welded by position) and sways as
    /// one. False, with the copies dropped and `tris` half done, if it would take more than
    /// `max` copies (the caller discards `tris`).
    pub fn unwrap_u(&mut self, tris: &mut [u32], max: usize, twin: impl Fn(u32, i32) -> Option<u32>) -> bool {
        let first = self.next_index();
        let mut copies: Vec<(u32, i32, u32)> = Vec::new();
        for t in tris.chunks_exact_mut(3) {
            let shifts = seam_shifts([t[0], t[1], t[2]].map(|i| self.uv_at(i)[0]));
            for (i, &k) in t.iter_mut().zip(&shifts) {
                if k == 0 {
                    continue;
                }
                if let Some(j) = twin(*i, k) {
                    *i = j;
                } else if let Some(&(.., c)) = copies.iter().find(|c| c.0 == *i && c.1 == k) {
                    *i = c;
                } else if copies.len() < max {
                    let ((p, n), [u, v], w) = (self.vertex_at(*i), self.uv_at(*i), self.wind_at(*i));
                    let c = self.vertex_with_wind(p.to_array(), n.to_array(), [u + k as f32, v], &w);
                    copies.push((*i, k, c));
                    *i = c;
                } else {
                    self.truncate_vertices(first);
                    return false;
                }
            }
        }
        true
    }

    /// Component `k` of the flat positions buffer written so far.
    #[inline]
    pub fn position(&self, k: usize) -> f32 {
        self.mesh.positions[k]
    }

    /// Append one triangle (counter-clockwise seen from outside).
    #[inline]
    pub fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.mesh.indices.extend_from_slice(&[a, b, c]);
    }

    /// Start a material group at the current index; later triangles belong to it.
    pub fn begin_group(&mut self, material: Material) {
        self.close_group();
        let start = self.mesh.indices.len() as u32;
        self.mesh.groups.push(MeshGroup { material, start, count: 0 });
    }

    fn close_group(&mut self) {
        let len = self.mesh.indices.len() as u32;
        if let Some(g) = self.mesh.groups.last_mut() {
            g.count = len - g.start;
        }
    }

    /// The finished mesh (empty groups dropped).
    pub fn finish(mut self) -> TreeMesh {
        self.close_group();
        self.mesh.groups.retain(|g| g.count > 0);
        self.mesh
    }
}

/// Whole turns to add to each of a triangle's three bark `u` so that they span the least:
/// all within half a turn of one of them (the one that gives the smallest span; ties keep the
/// fewest moves). All zero when the triangle does not cross a seam.
#[inline]
pub fn seam_shifts(u: [f32; 3]) -> [i32; 3] {
    // Within half a turn, moving any vertex a whole turn only widens the span.
    if span(u) <= 0.5 {
        return [0; 3];
    }
    seam_shifts_across(u)
}

/// Largest minus smallest of three `u` (plain comparisons: `f32::max` is a call in wasm).
#[inline(always)]
fn span(u: [f32; 3]) -> f32 {
    math::max(math::max(u[0], u[1]), u[2]) - math::min(math::min(u[0], u[1]), u[2])
}

/// [`seam_shifts`] for a triangle that spans more than half a turn.
#[cold]
fn seam_shifts_across(u: [f32; 3]) -> [i32; 3] {
    let mut best = ([0; 3], f32::INFINITY, 0);
    for anchor in u {
        let k = u.map(|x| math::round(anchor - x) as i32);
        let span = span([0, 1, 2].map(|i| u[i] + k[i] as f32));
        let moves = k.iter().filter(|&&x| x != 0).count();
        if span < best.1 - 1e-6 || (span < best.1 + 1e-6 && moves < best.2) {
            best = (k, span, moves);
        }
    }
    best.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seam_shifts_move_the_fewest_vertices_to_the_least_span() {
        assert_eq!(seam_shifts([0.1, 0.2, 0.3]), [0, 0, 0]);
        // One vertex moved rather than two.
        assert_eq!(seam_shifts([0.95, 0.0, 0.05]), [-1, 0, 0]);
        assert_eq!(seam_shifts([0.05, 0.95, 1.0]), [1, 0, 0]);
        // Already a whole turn on (a copy's u): kept.
        assert_eq!(seam_shifts([1.05, 0.95, 1.0]), [0, 0, 0]);
        // A wide but continuous triangle is left alone.
        assert_eq!(seam_shifts([1.0, 0.69, 0.478]), [0, 0, 0]);
    }

    #[test]
    fn unwrap_u_copies_each_vertex_once_within_the_cap() {
        let mut b = MeshBuilder::with_wind(8, 8);
        for u in [0.9, 0.0, 0.05, 0.95] {
            b.vertex_with_wind([u, 0.0, 0.0], [0.0, 0.0, 1.0], [u, 0.5], &[u; WIND_STRIDE]);
        }
        let mut tris = [0, 1, 3, 3, 1, 2];
        assert!(b.unwrap_u(&mut tris, 8, |_, _| None));
        assert_eq!(b.next_index(), 6, "two copies");
        assert_eq!(tris, [0, 4, 3, 5, 1, 2]);
        assert_eq!(b.uv_at(4), [1.0, 0.5]);
        assert_eq!(b.vertex_at(4), b.vertex_at(1));
        assert_eq!(b.uv_at(5), [0.95 - 1.0, 0.5]);
        assert_eq!(b.wind_at(5), b.wind_at(3));
        // Over the cap: nothing added.
        let mut tris = [0, 1, 3, 3, 1, 2];
        assert!(!b.unwrap_u(&mut tris, 1, |_, _| None));
        assert_eq!(b.next_index(), 6);
        // A seam twin is used instead of a copy.
        let mut tris = [0, 1, 3];
        assert!(b.unwrap_u(&mut tris, 0, |i, k| (i == 1 && k == 1).then_some(4)));
        assert_eq!((tris, b.next_index()), ([0, 4, 3], 6));
    }
}
