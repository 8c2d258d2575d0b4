//! A builder continued beside another, on a second thread ([`MeshBuilder::beside`]): it numbers
//! its vertices from the other's next number on and reads the vertices before that from the
//! other's buffers, which stay pinned until it is taken in ([`MeshBuilder::absorb`], through
//! [`MeshBuilder::append_copy`]) or dropped ([`MeshBuilder::forgo`]). The bark's deepest level
//! in two halves (`mesh/tube/halves.rs`) is what uses it.

use super::MeshBuilder;
use crate::mesh::WIND_STRIDE;

/// Whether this build continues builders beside others ([`MeshBuilder::beside`]): the threaded
/// wasm module, whose bark sweeps its deepest level in two halves (`mesh/tube/halves.rs`), and
/// the tests. Elsewhere every vertex read skips the test for a continued builder's earlier
/// vertices, which cost the single-threaded module 2 to 3% of its skeleton + mesh.
pub(super) const BESIDE: bool = cfg!(any(test, all(target_arch = "wasm32", target_feature = "atomics")));

/// Another builder's vertex buffers, read-only: the positions, normals, uvs and wind records of
/// the vertices numbered below the reading builder's `base` (`wind` is null when that builder
/// keeps none).
#[derive(Clone, Copy)]
pub(super) struct Prefix {
    positions: *const f32,
    normals: *const f32,
    uvs: *const f32,
    wind: *const f32,
}

impl Prefix {
    /// No buffers: a builder that continues none.
    pub(super) const NONE: Prefix = Prefix {
        positions: std::ptr::null(),
        normals: std::ptr::null(),
        uvs: std::ptr::null(),
        wind: std::ptr::null(),
    };
}

// SAFETY: a `Prefix` only reads memory that its owner neither writes nor moves while the
// builder holding it exists (`MeshBuilder::beside`, `MeshBuilder::absorb`).
#[allow(unsafe_code, reason = "a read-only view of another builder's vertices, sent to another thread")]
unsafe impl Send for Prefix {}

impl Prefix {
    /// Element `k` of a buffer of the prefix (`k` below its length).
    #[inline]
    fn at(p: *const f32, k: usize) -> f32 {
        // SAFETY: the buffers hold the reader's first `base` vertices, which their owner does
        // not write or move while this view exists (`MeshBuilder::beside`, pinned); callers
        // index below `base` vertices.
        #[allow(unsafe_code, reason = "reads of another builder's pinned vertices")]
        unsafe {
            *p.add(k)
        }
    }
}

impl MeshBuilder {
    /// A builder that continues this one beside it, on another thread: its vertices are
    /// numbered from this one's next number on, and the vertices before that are read from this
    /// builder. This builder may go on adding vertices (numbered the same; never past the room it
    /// was made with, which would move its buffers: that panics) but must not change those
    /// before, until [`MeshBuilder::absorb`] takes the other's vertices in after its own.
    pub(crate) fn beside(&mut self, vertices: usize) -> MeshBuilder {
        #[allow(clippy::assertions_on_constants, reason = "false in builds whose reads skip the prefix")]
        {
            assert!(BESIDE, "a builder beside another in a build without them");
        }
        let mut b = Self::with_capacity(vertices, 0);
        if self.wind {
            b.mesh.wind = Vec::with_capacity(vertices * WIND_STRIDE);
            b.wind = true;
        }
        let m = &self.mesh;
        let wind = if self.wind { m.wind.as_ptr() } else { std::ptr::null() };
        b.prefix = Prefix { positions: m.positions.as_ptr(), normals: m.normals.as_ptr(), uvs: m.uvs.as_ptr(), wind };
        b.base = self.next_index();
        self.pinned = true;
        self.watch();
        b
    }

    /// Drops `other`, made by [`MeshBuilder::beside`] from this builder, without its vertices:
    /// this builder may move its buffers again.
    pub(crate) fn forgo(&mut self, other: MeshBuilder) {
        drop(other);
        self.pinned = false;
        self.watch();
    }

    /// Takes in the vertices of `other`, made by [`MeshBuilder::beside`] from this builder, after
    /// this builder's own ([`MeshBuilder::append_copy`]). Returns the number of the first.
    pub(crate) fn absorb(&mut self, other: MeshBuilder) -> u32 {
        // `other` reads nothing of this builder's while it is copied.
        self.pinned = false;
        self.watch();
        self.append_copy(&other, other.base..other.next_index())
    }

    /// Appends copies of `from`'s vertices `range`, with their wind records (zeros if `from`
    /// keeps none) and the tube rings among them renumbered: a block another builder swept
    /// ahead of time, on another thread. Returns the index of the first copy.
    pub fn append_copy(&mut self, from: &MeshBuilder, range: std::ops::Range<u32>) -> u32 {
        let first = self.next_index();
        let (a, b) = ((range.start - from.base()) as usize, (range.end - from.base()) as usize);
        self.grow_vertices(first as usize + (b - a));
        let (m, f) = (&mut self.mesh, &from.mesh);
        m.positions.extend_from_slice(&f.positions[3 * a..3 * b]);
        m.normals.extend_from_slice(&f.normals[3 * a..3 * b]);
        m.uvs.extend_from_slice(&f.uvs[2 * a..2 * b]);
        if self.wind {
            match f.wind.get(WIND_STRIDE * a..WIND_STRIDE * b) {
                Some(w) if from.wind => m.wind.extend_from_slice(w),
                _ => m.wind.resize(m.wind.len() + WIND_STRIDE * (b - a), 0.0),
            }
        }
        let lo = f.rings.partition_point(|r| r[0] < range.start);
        let moved = f.rings[lo..].iter().take_while(|r| r[0] < range.end);
        m.rings.extend(moved.map(|r| [r[0].wrapping_sub(range.start).wrapping_add(first), r[1]]));
        first
    }

    /// Vertex `i`'s position and normal, `i` below `base` ([`MeshBuilder::beside`]).
    #[cold]
    pub(super) fn prefix_vertex(&self, i: u32) -> (glam::Vec3, glam::Vec3) {
        let k = i as usize * 3;
        let v = |b| glam::Vec3::new(Prefix::at(b, k), Prefix::at(b, k + 1), Prefix::at(b, k + 2));
        (v(self.prefix.positions), v(self.prefix.normals))
    }

    /// Component `k` of the flat positions, below `base` vertices.
    #[cold]
    pub(super) fn prefix_position(&self, k: usize) -> f32 {
        Prefix::at(self.prefix.positions, k)
    }

    /// Vertex `i`'s uv, `i` below `base`.
    #[cold]
    pub(super) fn prefix_uv(&self, i: u32) -> [f32; 2] {
        let k = i as usize * 2;
        [Prefix::at(self.prefix.uvs, k), Prefix::at(self.prefix.uvs, k + 1)]
    }

    /// Vertex `i`'s wind record, `i` below `base`.
    #[cold]
    pub(super) fn prefix_wind(&self, i: u32) -> [f32; WIND_STRIDE] {
        let (w, k) = (self.prefix.wind, i as usize * WIND_STRIDE);
        if w.is_null() {
            [0.0; WIND_STRIDE]
        } else {
            std::array::from_fn(|c| Prefix::at(w, k + c))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// Vertex `k`'s position, normal, uv and wind in these tests.
    fn nth(k: u32) -> ([f32; 3], [f32; 3], [f32; 2], [f32; WIND_STRIDE]) {
        let f = k as f32;
        ([f, 2.0 * f, 3.0 * f], [0.0, 1.0, f], [f / 10.0, f], [f + 0.5; WIND_STRIDE])
    }

    fn push(b: &mut MeshBuilder, k: u32) -> u32 {
        let (p, n, uv, w) = nth(k);
        b.vertex_with_wind(p, n, uv, &w)
    }

    #[test]
    fn a_builder_beside_reads_the_vertices_before_it_and_is_absorbed_renumbered() {
        let mut main = MeshBuilder::with_wind(16, 0);
        (0..4).for_each(|k| assert_eq!(push(&mut main, k), k));
        let mut other = main.beside(8);
        assert_eq!((other.base(), other.next_index()), (4, 4));
        // The other's reads of the vertices before it, and of its own.
        for k in 0..4 {
            let (p, n, uv, w) = nth(k);
            assert_eq!(other.vertex_at(k), (Vec3::from(p), Vec3::from(n)));
            assert_eq!((other.uv_at(k), other.wind_at(k)), (uv, w));
            assert_eq!(other.position(3 * k as usize + 1), p[1]);
        }
        // Both go on from vertex 4: this builder with 2, the other with 3 and a ring.
        assert_eq!((push(&mut main, 10), push(&mut main, 11)), (4, 5));
        (20..23).for_each(|k| assert_eq!(push(&mut other, k), k - 16));
        other.rings(4, 1, 2);
        let block = other.block_from(6, 1);
        assert_eq!((block.first, block.positions[0], block.positions.len()), (6, 22.0, 6));
        assert_eq!(other.vertex_at(5).0, Vec3::from(nth(21).0));
        other.set_normal(4, Vec3::X);
        other.truncate_vertices(7);
        assert_eq!(main.absorb(other), 6);
        let m = main.finish();
        assert_eq!(m.vertex_count(), 9);
        let at = |i: usize| [m.positions[3 * i], m.normals[3 * i], m.uvs[2 * i + 1], m.wind[WIND_STRIDE * i]];
        let want = |k: u32, nx: f32| {
            let (p, n, uv, w) = nth(k);
            [p[0], if nx > 0.0 { nx } else { n[0] }, uv[1], w[0]]
        };
        let order = [0, 1, 2, 3, 10, 11, 20, 21, 22];
        for (i, &k) in order.iter().enumerate() {
            assert_eq!(at(i), want(k, if i == 6 { 1.0 } else { 0.0 }), "vertex {i}");
        }
        assert_eq!(m.rings, vec![[6, 2]], "the other's ring, renumbered");
    }

    #[test]
    fn a_builder_forgoing_the_other_may_grow_again() {
        let mut main = MeshBuilder::with_capacity(2, 0);
        push(&mut main, 0);
        let mut other = main.beside(4);
        push(&mut other, 1);
        main.forgo(other);
        (1..40).for_each(|k| assert_eq!(push(&mut main, k), k));
        assert_eq!(main.next_index(), 40);
    }

    #[test]
    #[should_panic(expected = "a pinned builder outgrew its room")]
    fn a_pinned_builder_never_moves_its_vertices() {
        let mut main = MeshBuilder::with_capacity(2, 0);
        push(&mut main, 0);
        let _other = main.beside(4);
        (1..40).for_each(|k| {
            push(&mut main, k);
        });
    }
}
