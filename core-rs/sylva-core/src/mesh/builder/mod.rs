//! [`MeshBuilder`]: how the stages append vertices, triangles and material groups to a
//! [`TreeMesh`] (lyon's `GeometryBuilder` idea): zeroed blocks filled slot by slot here,
//! in-order appends without the zero-fill in [`append`], the bark seam's unwrapping of `u` in
//! [`seam`], a builder continued beside another on a second thread in [`beside`].

use super::{Material, MeshGroup, TreeMesh, WIND_STRIDE};
use crate::par::prefault::{self, Prefault};
use beside::{Prefix, BESIDE};

mod append;
mod beside;
mod seam;

pub use append::{Tail, VertexSink};
pub use seam::seam_shifts;

/// Appends geometry to a [`TreeMesh`] and keeps the material groups. A builder made with
/// [`MeshBuilder::with_wind`] keeps [`TreeMesh::wind`] in step with the vertices: every way of
/// adding vertices adds their wind records too (zeros unless given).
pub struct MeshBuilder {
    /// Another thread faulting in the buffers' reserved memory ([`MeshBuilder::prefault`]);
    /// declared first, so that it stops before the buffers are dropped.
    prefault: Option<Prefault>,
    mesh: TreeMesh,
    wind: bool,
    /// [`MeshBuilder::unwrap_u`]'s copies, kept for its next call (no allocation per call).
    seam_copies: Vec<(u32, i32, u32)>,
    /// The number of this builder's first vertex: 0, or for a builder made by
    /// [`MeshBuilder::beside`] the next number of the builder it continues, whose vertices
    /// before it it reads through `prefix`.
    base: u32,
    /// The vertices numbered below `base`, read in another builder's buffers (all null when
    /// `base` is 0).
    prefix: Prefix,
    /// Whether another builder reads this one's vertices ([`MeshBuilder::beside`]): its
    /// buffers must not move until that builder is absorbed.
    pinned: bool,
    /// `pinned` or a `prefault` running: whether growing the vertex buffers needs a look first
    /// (one test on the path every append takes).
    watched: bool,
}

/// The buffers [`MeshBuilder::prefault`] hands to another thread, as regions of a [`Prefault`].
const POSITIONS: usize = 0;
const NORMALS: usize = 1;
const UVS: usize = 2;
const WIND: usize = 3;
const INDICES: usize = 4;

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
            seam_copies: Vec::new(),
            base: 0,
            prefix: Prefix::NONE,
            pinned: false,
            watched: false,
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
        self.watch();
        prefault::offer(toucher);
    }

    /// Stops the thread faulting in the buffers ([`MeshBuilder::prefault`]), so that it is free
    /// for other work; the buffers' later pages are faulted in by their writers.
    pub fn end_prefault(&mut self) {
        self.prefault = None;
        self.watch();
    }

    /// Sets `watched` from what it stands for.
    fn watch(&mut self) {
        self.watched = self.pinned || self.prefault.is_some();
    }

    /// Before the vertex buffers grow to `n` vertices: the pages they reach claimed from the
    /// prefaulting thread, or that thread stopped if the buffers must move.
    #[inline]
    fn grow_vertices(&mut self, n: usize) {
        if !self.watched {
            return;
        }
        if self.pinned {
            self.check_room(n);
        }
        let Some(pf) = &mut self.prefault else { return };
        let m = &self.mesh;
        let fits = n * 3 <= m.positions.capacity().min(m.normals.capacity()) && n * 2 <= m.uvs.capacity();
        if !fits || (self.wind && n * WIND_STRIDE > m.wind.capacity()) {
            self.prefault = None;
            self.watch();
            return;
        }
        pf.claim(POSITIONS, m.positions.as_ptr() as usize + n * 12);
        pf.claim(NORMALS, m.normals.as_ptr() as usize + n * 12);
        pf.claim(UVS, m.uvs.as_ptr() as usize + n * 8);
        if self.wind {
            pf.claim(WIND, m.wind.as_ptr() as usize + n * WIND_STRIDE * 4);
        }
    }

    /// Panics if the buffers of a pinned builder ([`MeshBuilder::beside`]) would have to move
    /// to hold `n` vertices.
    #[cold]
    fn check_room(&self, n: usize) {
        let m = &self.mesh;
        let fits = n * 3 <= m.positions.capacity().min(m.normals.capacity()) && n * 2 <= m.uvs.capacity();
        assert!(fits && (!self.wind || n * WIND_STRIDE <= m.wind.capacity()), "a pinned builder outgrew its room");
    }

    /// [`MeshBuilder::grow_vertices`] for the indices, to `n` of them.
    #[inline]
    fn grow_indices(&mut self, n: usize) {
        let Some(pf) = &mut self.prefault else { return };
        if n > self.mesh.indices.capacity() {
            self.prefault = None;
            self.watch();
            return;
        }
        pf.claim(INDICES, self.mesh.indices.as_ptr() as usize + n * 4);
    }

    /// The number of this builder's first vertex (0 unless made by [`MeshBuilder::beside`]).
    #[inline(always)]
    pub(crate) fn base(&self) -> u32 {
        if BESIDE {
            self.base
        } else {
            0
        }
    }

    /// Index the next vertex will get.
    pub fn next_index(&self) -> u32 {
        self.base() + (self.mesh.positions.len() / 3) as u32
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
        let base = self.base();
        let end = end - base as usize;
        let m = &mut self.mesh;
        let k = (first - base) as usize;
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
        let n = (first - self.base()) as usize;
        self.mesh.positions.truncate(n * 3);
        self.mesh.normals.truncate(n * 3);
        self.mesh.uvs.truncate(n * 2);
        if self.wind {
            self.mesh.wind.truncate(n * WIND_STRIDE);
        }
    }

    /// Triangles written so far (indices / 3).
    pub fn triangle_count(&self) -> u32 {
        (self.mesh.indices.len() / 3) as u32
    }

    /// Vertex `i`'s position and normal.
    #[inline]
    pub fn vertex_at(&self, i: u32) -> (glam::Vec3, glam::Vec3) {
        if i < self.base() {
            return self.prefix_vertex(i);
        }
        let k = (i - self.base()) as usize * 3;
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

    /// Append triangles given as a flat index list (counter-clockwise seen from outside).
    pub fn extend_indices(&mut self, indices: &[u32]) {
        self.grow_indices(self.mesh.indices.len() + indices.len());
        self.mesh.indices.extend_from_slice(indices);
    }

    /// Replace vertex `i`'s normal.
    #[inline]
    pub fn set_normal(&mut self, i: u32, n: glam::Vec3) {
        let k = (i - self.base()) as usize * 3;
        self.mesh.normals[k..k + 3].copy_from_slice(&n.to_array());
    }

    /// Vertex `i`'s wind record (zeros when this builder has no wind attributes).
    #[inline]
    pub fn wind_at(&self, i: u32) -> [f32; WIND_STRIDE] {
        if i < self.base() {
            return self.prefix_wind(i);
        }
        let k = (i - self.base()) as usize * WIND_STRIDE;
        self.mesh.wind.get(k..k + WIND_STRIDE).map_or([0.0; WIND_STRIDE], |w| w.try_into().expect("stride"))
    }

    /// Vertex `i`'s uv.
    #[inline]
    pub fn uv_at(&self, i: u32) -> [f32; 2] {
        if i < self.base() {
            return self.prefix_uv(i);
        }
        let k = (i - self.base()) as usize * 2;
        [self.mesh.uvs[k], self.mesh.uvs[k + 1]]
    }

    /// Component `k` of the flat positions buffer written so far.
    #[inline]
    pub fn position(&self, k: usize) -> f32 {
        match k.checked_sub(3 * self.base() as usize) {
            Some(own) => self.mesh.positions[own],
            None => self.prefix_position(k),
        }
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
        self.watch();
        self.close_group();
        self.mesh.groups.retain(|g| g.count > 0);
        self.mesh
    }
}
