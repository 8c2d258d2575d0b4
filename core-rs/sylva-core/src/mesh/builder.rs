//! [`MeshBuilder`]: how the stages append vertices, triangles and material groups to a
//! [`TreeMesh`] (lyon's `GeometryBuilder` idea), and the bark seam's unwrapping of `u`.

use super::{Material, MeshGroup, TreeMesh, WIND_STRIDE};
use crate::math;
use crate::par::prefault::{self, Prefault};
use std::mem::MaybeUninit;

/// Appends geometry to a [`TreeMesh`] and keeps the material groups. A builder made with
/// [`MeshBuilder::with_wind`] keeps [`TreeMesh::wind`] in step with the vertices: every way of
/// adding vertices adds their wind records too (zeros unless given).
pub struct MeshBuilder {
    /// Another thread faulting in the buffers' reserved memory ([`MeshBuilder::prefault`]);
    /// declared first, so that it stops before the buffers are dropped.
    prefault: Option<Prefault>,
    mesh: TreeMesh,
    wind: bool,
}

/// The buffers [`MeshBuilder::prefault`] hands to another thread, as regions of a [`Prefault`].
const POSITIONS: usize = 0;
const NORMALS: usize = 1;
const UVS: usize = 2;
const WIND: usize = 3;
const INDICES: usize = 4;

/// One buffer's reserved memory, written front to back ([`VertexSink`],
/// [`MeshBuilder::append_indices`]).
pub struct Tail<'a, T> {
    spare: &'a mut [MaybeUninit<T>],
    /// Elements written: `spare[..len]`, and only those.
    len: usize,
}

impl<'a, T: Copy> Tail<'a, T> {
    fn new(spare: &'a mut [MaybeUninit<T>]) -> Self {
        Tail { spare, len: 0 }
    }

    /// Appends `v` (panics past the reserved room).
    #[inline]
    pub fn push<const N: usize>(&mut self, v: [T; N]) {
        let end = self.len + N;
        for (slot, x) in self.spare[self.len..end].iter_mut().zip(v) {
            slot.write(x);
        }
        self.len = end;
    }

    /// Whether the whole reserved room is written.
    fn is_full(&self) -> bool {
        self.len == self.spare.len()
    }
}

/// Vertices appended front to back ([`MeshBuilder::append_vertices`]): each vertex's position,
/// normal and uv by [`VertexSink::push`], its wind record by [`VertexSink::push_wind`] (ignored
/// when the builder keeps no wind), in the same order.
pub struct VertexSink<'a> {
    /// Index of the first vertex appended.
    pub first: u32,
    positions: Tail<'a, f32>,
    normals: Tail<'a, f32>,
    uvs: Tail<'a, f32>,
    wind: Option<Tail<'a, f32>>,
}

impl VertexSink<'_> {
    /// Appends a vertex's position, normal and uv.
    #[inline]
    pub fn push(&mut self, p: glam::Vec3, n: glam::Vec3, uv: [f32; 2]) {
        self.positions.push(p.to_array());
        self.normals.push(n.to_array());
        self.uvs.push(uv);
    }

    /// Appends the vertices `items` yields (position, normal, uv): a ring in one loop, its
    /// counts kept in registers. Panics past the reserved room.
    #[inline]
    pub fn extend(&mut self, items: impl ExactSizeIterator<Item = (glam::Vec3, glam::Vec3, [f32; 2])>) {
        let count = items.len();
        let (p, n, u) = (&mut self.positions, &mut self.normals, &mut self.uvs);
        assert!(u.len + 2 * count <= u.spare.len(), "a vertex past the reserved room");
        let slots = p.spare[p.len..p.len + 3 * count]
            .chunks_exact_mut(3)
            .zip(n.spare[n.len..n.len + 3 * count].chunks_exact_mut(3))
            .zip(u.spare[u.len..u.len + 2 * count].chunks_exact_mut(2));
        let mut k = 0;
        for (((ps, ns), us), (pos, nrm, uv)) in slots.zip(items) {
            for (slot, x) in ps.iter_mut().zip(pos.to_array()) {
                slot.write(x);
            }
            for (slot, x) in ns.iter_mut().zip(nrm.to_array()) {
                slot.write(x);
            }
            for (slot, x) in us.iter_mut().zip(uv) {
                slot.write(x);
            }
            k += 1;
        }
        // The `k` slots just written, in every buffer (`count` of them, unless `items` yields
        // fewer than its length says).
        p.len += 3 * k;
        n.len += 3 * k;
        u.len += 2 * k;
    }

    /// Appends `count` copies of a wind record.
    #[inline]
    pub fn push_wind(&mut self, record: &[f32; WIND_STRIDE], count: usize) {
        if let Some(w) = &mut self.wind {
            let end = w.len + WIND_STRIDE * count;
            for slots in w.spare[w.len..end].chunks_exact_mut(WIND_STRIDE) {
                for (slot, &x) in slots.iter_mut().zip(record) {
                    slot.write(x);
                }
            }
            w.len = end;
        }
    }

    /// Vertices appended so far.
    pub fn len(&self) -> usize {
        self.uvs.len / 2
    }

    /// Whether none is.
    pub fn is_empty(&self) -> bool {
        self.uvs.len == 0
    }
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

impl VertexBlock<'_> {
    /// Writes the position, normal and uv of the block's vertex `slot`.
    #[inline]
    pub fn write(&mut self, slot: usize, p: glam::Vec3, n: glam::Vec3, uv: [f32; 2]) {
        self.positions[slot * 3..slot * 3 + 3].copy_from_slice(&p.to_array());
        self.normals[slot * 3..slot * 3 + 3].copy_from_slice(&n.to_array());
        self.uvs[slot * 2..slot * 2 + 2].copy_from_slice(&uv);
    }
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
            prefault: None,
        }
    }

    /// Like [`MeshBuilder::with_capacity`], with a [`TreeMesh::wind`] record for every vertex.
    pub fn with_wind(vertices: usize, indices: usize) -> Self {
        let mut b = Self::with_capacity(vertices, indices);
        b.mesh.wind = Vec::with_capacity(vertices * WIND_STRIDE);
        b.wind = true;
        b
    }

    /// Has another thread fault in the memory reserved for the vertices and for the first
    /// `indices` indices ahead of this builder's writes ([`crate::par::prefault`]), when the
    /// code around offers one (the other thread of the bark's [`crate::par::join`] with the
    /// leaves) and the reservation is worth it. The bytes written are the same either way.
    pub fn prefault(&mut self, indices: usize) {
        if self.prefault.is_some() || !prefault::wanted() {
            return;
        }
        let m = &mut self.mesh;
        fn spare<T>(v: &mut Vec<T>, most: usize) -> (usize, usize) {
            let size = std::mem::size_of::<T>();
            (v.as_mut_ptr() as usize + v.len() * size, (v.capacity() - v.len()).min(most) * size)
        }
        let regions = [
            spare(&mut m.positions, usize::MAX),
            spare(&mut m.normals, usize::MAX),
            spare(&mut m.uvs, usize::MAX),
            spare(&mut m.wind, usize::MAX),
            spare(&mut m.indices, indices),
        ];
        if regions.iter().map(|r| r.1).sum::<usize>() < prefault::MIN_BYTES {
            prefault::withdraw();
            return;
        }
        let (pf, toucher) = Prefault::new(&regions);
        self.prefault = Some(pf);
        prefault::offer(toucher);
    }

    /// Stops the thread faulting in the buffers ([`MeshBuilder::prefault`]), so that it is free
    /// for other work; the buffers' later pages are faulted in by their writers.
    pub fn end_prefault(&mut self) {
        self.prefault = None;
    }

    /// Before the vertex buffers grow to `n` vertices: the pages they reach claimed from the
    /// prefaulting thread, or that thread stopped if the buffers must move.
    #[inline]
    fn grow_vertices(&mut self, n: usize) {
        let Some(pf) = &mut self.prefault else { return };
        let m = &self.mesh;
        let fits = n * 3 <= m.positions.capacity().min(m.normals.capacity()) && n * 2 <= m.uvs.capacity();
        if !fits || (self.wind && n * WIND_STRIDE > m.wind.capacity()) {
            self.prefault = None;
            return;
        }
        pf.claim(POSITIONS, m.positions.as_ptr() as usize + n * 12);
        pf.claim(NORMALS, m.normals.as_ptr() as usize + n * 12);
        pf.claim(UVS, m.uvs.as_ptr() as usize + n * 8);
        if self.wind {
            pf.claim(WIND, m.wind.as_ptr() as usize + n * WIND_STRIDE * 4);
        }
    }

    /// [`MeshBuilder::grow_vertices`] for the indices, to `n` of them.
    #[inline]
    fn grow_indices(&mut self, n: usize) {
        let Some(pf) = &mut self.prefault else { return };
        if n > self.mesh.indices.capacity() {
            self.prefault = None;
            return;
        }
        pf.claim(INDICES, self.mesh.indices.as_ptr() as usize + n * 4);
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
        self.grow_vertices(i as usize + 1);
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
        self.block_from(first, n)
    }

    /// Like [`MeshBuilder::alloc_vertices`], with the block reaching back to vertex `first`: the
    /// vertices from there on as written, then `n` zeroed ones, slots counted from `first` (a
    /// stem's cap and cut end written after its rings, [`MeshBuilder::append_vertices`]).
    pub fn block_from(&mut self, first: u32, n: usize) -> VertexBlock<'_> {
        let end = self.next_index() as usize + n;
        self.grow_vertices(end);
        let m = &mut self.mesh;
        let k = first as usize;
        m.positions.resize(3 * end, 0.0);
        m.normals.resize(3 * end, 0.0);
        m.uvs.resize(2 * end, 0.0);
        if self.wind {
            m.wind.resize(WIND_STRIDE * end, 0.0);
        }
        VertexBlock {
            first,
            positions: &mut m.positions[3 * k..],
            normals: &mut m.normals[3 * k..],
            uvs: &mut m.uvs[2 * k..],
            wind: m.wind.get_mut(WIND_STRIDE * k..).unwrap_or_default(),
        }
    }

    /// Appends up to `n` vertices front to back through `fill` ([`VertexSink`]), each written
    /// once into the buffers' reserved memory: no zero-fill first, the pass over the memory a
    /// block of [`MeshBuilder::alloc_vertices`] costs (5 to 7% of a big tree's bark in wasm).
    /// Returns what `fill` returns. Panics if `fill` pushes more than `n` vertices, or a vertex
    /// without its wind record when the builder keeps wind.
    pub fn append_vertices<R>(&mut self, n: usize, fill: impl FnOnce(&mut VertexSink) -> R) -> R {
        let first = self.next_index();
        self.grow_vertices(first as usize + n);
        let wind = self.wind;
        let m = &mut self.mesh;
        m.positions.reserve(3 * n);
        m.normals.reserve(3 * n);
        m.uvs.reserve(2 * n);
        if wind {
            m.wind.reserve(WIND_STRIDE * n);
        }
        let (out, [p, q, u, w]) = {
            let mut sink = VertexSink {
                first,
                positions: Tail::new(&mut m.positions.spare_capacity_mut()[..3 * n]),
                normals: Tail::new(&mut m.normals.spare_capacity_mut()[..3 * n]),
                uvs: Tail::new(&mut m.uvs.spare_capacity_mut()[..2 * n]),
                wind: wind.then(|| Tail::new(&mut m.wind.spare_capacity_mut()[..WIND_STRIDE * n])),
            };
            let out = fill(&mut sink);
            (out, [sink.positions.len, sink.normals.len, sink.uvs.len, sink.wind.map_or(0, |t| t.len)])
        };
        let k = u / 2;
        assert!(p == 3 * k && q == 3 * k && w == if wind { WIND_STRIDE * k } else { 0 }, "every vertex appended whole");
        // SAFETY: each buffer's first `len` reserved elements were written by its `Tail`, whose
        // `len` only grows past elements it has just written (`Tail::push`); `len` is at most
        // the reserved room the tail was given.
        #[allow(unsafe_code, reason = "the length of a vector past the elements just written into its reserved memory")]
        unsafe {
            m.positions.set_len(m.positions.len() + p);
            m.normals.set_len(m.normals.len() + q);
            m.uvs.set_len(m.uvs.len() + u);
            m.wind.set_len(m.wind.len() + w);
        }
        out
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
        self.grow_indices(start + n);
        self.mesh.indices.resize(start + n, 0);
        &mut self.mesh.indices[start..]
    }

    /// Appends `counts.iter().sum()` indices through `fill`, which gets one [`Tail`] per count,
    /// in order, and must write each whole (on any thread: a tail is its own memory), each
    /// index once into the buffer's reserved memory: no zero-fill first. Panics if a tail is
    /// left short.
    pub fn append_indices(&mut self, counts: &[usize], fill: impl FnOnce(&mut [Tail<u32>])) {
        let n: usize = counts.iter().sum();
        let start = self.mesh.indices.len();
        self.grow_indices(start + n);
        let v = &mut self.mesh.indices;
        v.reserve(n);
        let mut spare = &mut v.spare_capacity_mut()[..n];
        let mut tails: Vec<Tail<u32>> = Vec::with_capacity(counts.len());
        for &c in counts {
            let (head, rest) = std::mem::take(&mut spare).split_at_mut(c);
            tails.push(Tail::new(head));
            spare = rest;
        }
        fill(&mut tails);
        assert!(tails.iter().all(Tail::is_full), "every index written");
        drop(tails);
        // SAFETY: the tails cover the `n` reserved elements after the buffer's end, back to
        // back, and each is full: its elements all written ([`Tail::push`]).
        #[allow(unsafe_code, reason = "the length of a vector past the elements just written into its reserved memory")]
        unsafe {
            v.set_len(start + n);
        }
    }

    /// Append triangles given as a flat index list (counter-clockwise seen from outside).
    pub fn extend_indices(&mut self, indices: &[u32]) {
        self.grow_indices(self.mesh.indices.len() + indices.len());
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
        self.grow_indices(self.mesh.indices.len() + 3);
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
        self.prefault = None;
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

    /// Three vertices appended by `append` to a builder holding one already (`wind` or not).
    fn three_vertices(wind: bool, append: impl FnOnce(&mut MeshBuilder)) -> TreeMesh {
        let mut b = if wind { MeshBuilder::with_wind(1, 0) } else { MeshBuilder::with_capacity(1, 0) };
        b.vertex_with_wind([9.0; 3], [0.0, 1.0, 0.0], [0.25, 0.75], &[7.0; WIND_STRIDE]);
        append(&mut b);
        b.finish()
    }

    fn nth(k: usize) -> (glam::Vec3, glam::Vec3, [f32; 2], [f32; WIND_STRIDE]) {
        let x = k as f32;
        (glam::Vec3::new(x, x + 0.5, -x), glam::Vec3::new(0.0, 0.0, 1.0), [x / 4.0, 1.0 - x], [x + 0.25; WIND_STRIDE])
    }

    #[test]
    fn appended_vertices_are_the_vertices_a_block_holds() {
        for wind in [true, false] {
            let by_block = three_vertices(wind, |b| {
                let mut block = b.alloc_vertices(3);
                for k in 0..3 {
                    let (p, n, uv, w) = nth(k);
                    block.write(k, p, n, uv);
                    if wind {
                        block.wind[k * WIND_STRIDE..(k + 1) * WIND_STRIDE].copy_from_slice(&w);
                    }
                }
            });
            // One vertex pushed, two extended, their records pushed after them; room for five.
            let by_sink = three_vertices(wind, |b| {
                let first = b.append_vertices(5, |sink| {
                    let (p, n, uv, w) = nth(0);
                    sink.push(p, n, uv);
                    sink.push_wind(&w, 1);
                    sink.extend((1..3).map(|k| {
                        let (p, n, uv, _) = nth(k);
                        (p, n, uv)
                    }));
                    for k in 1..3 {
                        sink.push_wind(&nth(k).3, 1);
                    }
                    assert_eq!(sink.len(), 3);
                    sink.first
                });
                assert_eq!(first, 1);
            });
            let buffers = |m: &TreeMesh| (m.positions.clone(), m.normals.clone(), m.uvs.clone(), m.wind.clone());
            assert_eq!(buffers(&by_sink), buffers(&by_block));
            assert_eq!(by_sink.positions.len(), 12);
            assert_eq!(by_sink.wind.len(), if wind { 4 * WIND_STRIDE } else { 0 });
        }
    }

    #[test]
    fn a_block_from_an_earlier_vertex_reads_it_and_zeroes_the_new_ones() {
        let m = three_vertices(true, |b| {
            b.append_vertices(1, |sink| {
                sink.push(glam::Vec3::ONE, glam::Vec3::Z, [0.5, 0.5]);
                sink.push_wind(&[3.0; WIND_STRIDE], 1);
            });
            let block = b.block_from(1, 2);
            assert_eq!((block.first, block.positions.len(), block.wind.len()), (1, 9, 3 * WIND_STRIDE));
            assert_eq!(&block.positions[..3], &[1.0; 3]);
            assert_eq!(&block.uvs[2..], &[0.0; 4]);
            block.positions[3] = 2.0;
        });
        assert_eq!(m.positions[..7], [9.0, 9.0, 9.0, 1.0, 1.0, 1.0, 2.0]);
        assert_eq!(m.wind.len(), 4 * WIND_STRIDE);
    }

    #[test]
    #[should_panic(expected = "range end index")]
    fn appending_past_the_room_asked_for_panics() {
        three_vertices(false, |b| {
            b.append_vertices(1, |sink| {
                sink.push(glam::Vec3::ZERO, glam::Vec3::Z, [0.0; 2]);
                sink.push(glam::Vec3::ZERO, glam::Vec3::Z, [0.0; 2]);
            });
        });
    }

    #[test]
    #[should_panic(expected = "every vertex appended whole")]
    fn a_vertex_without_its_wind_record_panics() {
        three_vertices(true, |b| {
            b.append_vertices(2, |sink| sink.push(glam::Vec3::ZERO, glam::Vec3::Z, [0.0; 2]));
        });
    }

    #[test]
    fn indices_appended_by_parts_follow_the_ones_before() {
        let mut b = MeshBuilder::with_capacity(0, 2);
        b.extend_indices(&[9, 9, 9]);
        b.append_indices(&[6, 0, 3], |tails| {
            assert_eq!(tails.len(), 3);
            // The last part first: each tail is its own memory.
            tails[2].push([7, 8, 9]);
            tails[0].push([1, 2, 3]);
            tails[0].push([4, 5, 6]);
        });
        assert_eq!(b.finish().indices, [9, 9, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9]);
    }

    #[test]
    #[should_panic(expected = "every index written")]
    fn a_part_left_short_panics() {
        let mut b = MeshBuilder::with_capacity(0, 0);
        b.append_indices(&[3, 3], |tails| tails[0].push([1, 2, 3]));
    }

    #[test]
    #[should_panic(expected = "a vertex past the reserved room")]
    fn extending_past_the_room_asked_for_panics() {
        three_vertices(false, |b| {
            b.append_vertices(1, |sink| sink.extend([(glam::Vec3::ZERO, glam::Vec3::Z, [0.0; 2]); 2].into_iter()));
        });
    }
}
