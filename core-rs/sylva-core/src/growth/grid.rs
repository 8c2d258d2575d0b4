//! A uniform grid over a box for fixed-radius neighbour queries (a grid updated
//! incrementally keeps space colonization fast; all-pairs searches are what make other tools
//! slow). Items are indices with positions; each cell holds a singly linked list threaded
//! through `next`, so insertion is O(1) and never reallocates per cell.

use glam::Vec3;

const NONE: u32 = u32::MAX;

/// Grid of cells of edge `cell` covering `[min, min + dims * cell)`; points outside are clamped
/// into the border cells (queries still check true distances).
pub struct Grid {
    min: Vec3,
    inv_cell: f32,
    dims: [usize; 3],
    head: Vec<u32>,
    next: Vec<u32>,
}

impl Grid {
    /// A grid over `[min, max]` with cells of at least `cell` (enlarged so no axis has more than
    /// `max_dim` cells).
    pub fn new(min: Vec3, max: Vec3, cell: f32, max_dim: usize) -> Grid {
        let size = (max - min).max(Vec3::splat(1e-3));
        let cell = cell.max(size.max_element() / max_dim as f32).max(1e-4);
        let dims = [
            ((size.x / cell) as usize + 1).min(max_dim),
            ((size.y / cell) as usize + 1).min(max_dim),
            ((size.z / cell) as usize + 1).min(max_dim),
        ];
        Grid { min, inv_cell: 1.0 / cell, dims, head: vec![NONE; dims[0] * dims[1] * dims[2]], next: Vec::new() }
    }

    fn coord(&self, p: Vec3) -> [usize; 3] {
        let c = (p - self.min) * self.inv_cell;
        let clamp = |v: f32, d: usize| (v.max(0.0) as usize).min(d - 1);
        [clamp(c.x, self.dims[0]), clamp(c.y, self.dims[1]), clamp(c.z, self.dims[2])]
    }

    fn cell_index(&self, c: [usize; 3]) -> usize {
        (c[2] * self.dims[1] + c[1]) * self.dims[0] + c[0]
    }

    /// Insert item `id` (ids must be inserted in order 0, 1, 2, ...) at `p`.
    pub fn insert(&mut self, id: u32, p: Vec3) {
        debug_assert_eq!(id as usize, self.next.len());
        let cell = self.cell_index(self.coord(p));
        self.next.push(self.head[cell]);
        self.head[cell] = id;
    }

    /// Call `f` with every item in the cells that can hold points within `radius` of `p`
    /// (a superset: check distances in `f`). The radius must not exceed about one cell for the
    /// 3x3x3 neighbourhood to suffice; larger radii visit more cells.
    pub fn for_each_near(&self, p: Vec3, radius: f32, mut f: impl FnMut(u32)) {
        let lo = self.coord(p - Vec3::splat(radius));
        let hi = self.coord(p + Vec3::splat(radius));
        for z in lo[2]..=hi[2] {
            for y in lo[1]..=hi[1] {
                for x in lo[0]..=hi[0] {
                    let mut i = self.head[self.cell_index([x, y, z])];
                    while i != NONE {
                        f(i);
                        i = self.next[i as usize];
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_exactly_the_points_a_brute_force_search_finds() {
        let mut rng = crate::rng::Rng::new(3, "grid-test");
        let pts: Vec<Vec3> = (0..2000)
            .map(|_| Vec3::new(rng.uniform(-5.0, 5.0), rng.uniform(0.0, 8.0), rng.uniform(-5.0, 5.0)))
            .collect();
        let mut g = Grid::new(Vec3::new(-5.0, 0.0, -5.0), Vec3::new(5.0, 8.0, 5.0), 0.7, 64);
        for (i, p) in pts.iter().enumerate() {
            g.insert(i as u32, *p);
        }
        for q in pts.iter().step_by(37) {
            let mut near = Vec::new();
            g.for_each_near(*q, 0.7, |i| {
                if pts[i as usize].distance(*q) <= 0.7 {
                    near.push(i)
                }
            });
            near.sort_unstable();
            let brute: Vec<u32> = (0..pts.len() as u32).filter(|&i| pts[i as usize].distance(*q) <= 0.7).collect();
            assert_eq!(near, brute);
        }
    }
}
