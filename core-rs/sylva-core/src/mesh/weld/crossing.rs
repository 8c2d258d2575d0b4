//! The crossings of the footprint's lines (step 2 of a welded junction, [`super::footprint`]):
//! where a line along the child's axis leaves a triangle of the parent through its outer side,
//! for one triangle ([`line_plane`]), for many lines of one direction ([`Facing`]) and for a
//! whole window of the parent's quads ([`search`]).

use glam::{Vec2, Vec3};

/// The parent quad under one footprint point, and where in it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Cell {
    /// Row of the quad.
    pub row: usize,
    /// Column of the quad (may run past the seam).
    pub col: i32,
    /// Where in the quad: `x` across its columns, `y` along its rows, 0..1.
    pub at: Vec2,
}

/// Where a line along the child's axis leaves one of the parent's triangles.
#[derive(Clone, Copy, Debug)]
pub(super) struct Hit {
    /// Parameter along the line.
    pub s: f32,
    /// The triangle's vertices.
    pub tri: [u32; 3],
    /// Barycentric weights of the crossing in `tri`.
    pub bary: Vec3,
    /// The quad's cell and where in it the crossing lies.
    pub cell: Cell,
}

impl Hit {
    /// The crossing at (`u`, `v`) along the edges of half `half` (0: `a, b, c`; 1: `a, c, d`)
    /// of quad (`row`, `col`).
    pub fn new(s: f32, tri: [u32; 3], u: f32, v: f32, row: usize, col: i32, half: usize) -> Hit {
        let at = if half == 0 { Vec2::new(u + v, v) } else { Vec2::new(u, u + v) };
        Hit { s, tri, bary: Vec3::new(1.0 - u - v, u, v), cell: Cell { row, col, at } }
    }
}

/// One triangle of the search window that lines along the child's axis leave through its outer
/// side ([`Facing`]), with its vertices, quad and half, in the order the search visits them.
#[derive(Clone, Copy)]
pub(super) struct WindowTri {
    pub facing: Facing,
    pub tri: [u32; 3],
    pub row: usize,
    pub col: i32,
    pub half: usize,
}

/// Where the line `q + s d` crosses the plane of triangle `t` leaving it on its outer side: `s`
/// and the (unclamped) coordinates `u`, `v` along `t[1] - t[0]` and `t[2] - t[0]`.
pub(super) fn line_plane(q: Vec3, d: Vec3, t: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    Facing::new(d, t).map(|f| f.at(q, d))
}

/// The part of [`line_plane`] that depends on the triangle and the line's direction only, for
/// many lines of one direction (the columns of a junction all follow the child's axis).
#[derive(Clone, Copy)]
pub(super) struct Facing {
    p0: Vec3,
    e1: Vec3,
    e2: Vec3,
    h: Vec3,
    inv: f32,
}

impl Facing {
    /// `None` when lines along `d` do not leave triangle `t` through its outer side.
    #[inline]
    pub fn new(d: Vec3, t: [Vec3; 3]) -> Option<Facing> {
        let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
        let h = d.cross(e2);
        let det = e1.dot(h);
        // det = -d · (e1 × e2): leaving through the outer side (along the normal) makes it negative.
        if det >= -1e-12 * crate::math::max(e1.length_squared(), e2.length_squared()) {
            return None;
        }
        Some(Facing { p0: t[0], e1, e2, h, inv: 1.0 / det })
    }

    /// [`line_plane`] of the line `q + s d` (`d` the direction given to [`Facing::new`]).
    #[inline]
    pub fn at(&self, q: Vec3, d: Vec3) -> (f32, f32, f32) {
        let o = q - self.p0;
        let qv = o.cross(self.e1);
        (self.e2.dot(qv) * self.inv, o.dot(self.h) * self.inv, d.dot(qv) * self.inv)
    }
}

/// The first hit (largest `s`) of the line `q + s d` with the triangles of a window.
pub(super) fn search(window: &[WindowTri], q: Vec3, d: Vec3) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for w in window {
        // Facing::at, its `u` first: most of the window's triangles are left on it alone.
        let f = &w.facing;
        let o = q - f.p0;
        let u = o.dot(f.h) * f.inv;
        if !(0.0..=1.0).contains(&u) {
            continue;
        }
        let qv = o.cross(f.e1);
        let v = d.dot(qv) * f.inv;
        if v >= 0.0 && u + v <= 1.0 {
            let s = f.e2.dot(qv) * f.inv;
            if best.is_none_or(|b| s > b.s) {
                best = Some(Hit::new(s, w.tri, u, v, w.row, w.col, w.half));
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    /// [`search`] as the plain formula: every triangle's crossing from [`Facing::at`].
    fn search_by_the_formula(window: &[WindowTri], q: Vec3, d: Vec3) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        for w in window {
            let (s, u, v) = w.facing.at(q, d);
            if u >= 0.0 && v >= 0.0 && u + v <= 1.0 && best.is_none_or(|b| s > b.s) {
                best = Some(Hit::new(s, w.tri, u, v, w.row, w.col, w.half));
            }
        }
        best
    }

    #[test]
    fn the_search_finds_the_hit_of_its_plain_formula() {
        let mut rng = Rng::new(7, "footprint_test");
        let mut point =
            |scale: f32| Vec3::new(rng.next_f32() - 0.5, rng.next_f32() - 0.5, rng.next_f32() - 0.5) * scale;
        let (mut hits, mut misses) = (0, 0);
        for _ in 0..400 {
            let d = point(2.0).normalize_or(Vec3::Y);
            let mut window = Vec::new();
            for k in 0..40 {
                let a = point(1.0);
                let t = [a, a + point(1.2), a + point(1.2)];
                // Some triangles share a corner, as a window's quads do.
                let t = if k % 3 == 0 { [t[0], t[2], t[1]] } else { t };
                if let Some(facing) = Facing::new(d, t) {
                    window.push(WindowTri {
                        facing,
                        tri: [k, k + 1, k + 2],
                        row: k as usize,
                        col: 0,
                        half: k as usize % 2,
                    });
                }
            }
            for _ in 0..50 {
                let q = point(1.5);
                let (a, b) = (search(&window, q, d), search_by_the_formula(&window, q, d));
                match (a, b) {
                    (None, None) => misses += 1,
                    (Some(a), Some(b)) => {
                        hits += 1;
                        assert_eq!(
                            (a.s.to_bits(), a.tri, a.bary.to_array().map(f32::to_bits)),
                            (b.s.to_bits(), b.tri, b.bary.to_array().map(f32::to_bits))
                        );
                    }
                    _ => panic!("one found a hit, the other none"),
                }
            }
        }
        assert!(hits > 1000 && misses > 1000, "{hits} hits, {misses} misses");
    }
}
