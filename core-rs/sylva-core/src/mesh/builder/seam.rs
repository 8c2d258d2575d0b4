//! The bark seam: bark `u` made continuous in triangles built across a stem's texture seam.

use super::MeshBuilder;
use crate::math;

impl MeshBuilder {
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
        let mut copies = std::mem::take(&mut self.seam_copies);
        copies.clear();
        let whole = self.unwrap_with(tris, max, twin, &mut copies);
        self.seam_copies = copies;
        if !whole {
            self.truncate_vertices(first);
        }
        whole
    }

    /// [`MeshBuilder::unwrap_u`] with its list of copies (empty on entry); false when it would
    /// take more than `max` copies.
    fn unwrap_with(
        &mut self,
        tris: &mut [u32],
        max: usize,
        twin: impl Fn(u32, i32) -> Option<u32>,
        copies: &mut Vec<(u32, i32, u32)>,
    ) -> bool {
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
                    return false;
                }
            }
        }
        true
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
    use crate::mesh::WIND_STRIDE;

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

    #[test]
    fn each_unwrap_makes_its_own_copies() {
        // The list of copies is kept between calls: a later call must not reuse an earlier
        // call's copy (made for other triangles, and dropped when that call failed).
        let mut b = MeshBuilder::with_wind(8, 8);
        for u in [0.9, 0.0, 0.05, 0.95] {
            b.vertex_with_wind([u, 0.0, 0.0], [0.0, 0.0, 1.0], [u, 0.5], &[u; WIND_STRIDE]);
        }
        let mut tris = [0, 1, 3];
        assert!(b.unwrap_u(&mut tris, 8, |_, _| None));
        assert_eq!((tris, b.next_index()), ([0, 4, 3], 5));
        let mut tris = [0, 1, 3];
        assert!(b.unwrap_u(&mut tris, 8, |_, _| None));
        assert_eq!((tris, b.next_index()), ([0, 5, 3], 6), "a copy of its own");
        assert_eq!(b.uv_at(5), b.uv_at(4));
        // A failed call drops its copies; the next call copies again at the same place.
        let mut tris = [0, 1, 3, 3, 1, 2];
        assert!(!b.unwrap_u(&mut tris, 1, |_, _| None));
        assert_eq!(b.next_index(), 6);
        let mut tris = [3, 1, 2];
        assert!(b.unwrap_u(&mut tris, 1, |_, _| None));
        assert_eq!((tris, b.next_index()), ([6, 1, 2], 7));
        assert_eq!(b.uv_at(6), [0.95 - 1.0, 0.5]);
    }
}
