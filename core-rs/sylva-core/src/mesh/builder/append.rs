//! Appending to a [`MeshBuilder`] front to back: each element written once into the buffers'
//! reserved memory ([`Tail`], [`VertexSink`]), with no zero-fill first, for the stages that
//! write their vertices or indices in order (a stem's rings, a collar, a fork, the index pass).

use super::MeshBuilder;
use crate::mesh::WIND_STRIDE;
use std::mem::MaybeUninit;

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

impl MeshBuilder {
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::TreeMesh;

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
