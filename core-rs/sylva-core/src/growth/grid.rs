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

    /// Call `f` with every item in `p`'s own cell (the border cell it is clamped into when outside).
    pub fn for_each_in_cell(&self, p: Vec3, mut f: impl FnMut(u32)) {
        let mut i = self.head[self.cell_index(self.coord(p))];
        while i != NONE {
            f(i);
            i = self.next[i as usize];
        }
    }

    /// [`Grid::for_each_near`] (`p`, `radius`): the same cells in the same order, without the
    /// cells that hold no point within `within` of `p`. Those are the corners of the block of
    /// cells around the sphere. With cells of half the radius they are about a third of the
    /// block. A caller that only reads items within `within` gets the same calls, in the same
    /// order, as from [`Grid::for_each_near`].
    ///
    /// The test is conservative. A cell's distance from `p` is measured in cell units, less a
    /// margin far above the rounding of the cell coordinates. A border cell reaches out without
    /// end on its outer side, because points outside the grid are clamped into it.
    pub fn for_each_near_within(&self, p: Vec3, radius: f32, within: f32, mut f: impl FnMut(u32)) {
        let lo = self.coord(p - Vec3::splat(radius));
        let hi = self.coord(p + Vec3::splat(radius));
        let t = (p - self.min) * self.inv_cell;
        let last = [self.dims[0] - 1, self.dims[1] - 1, self.dims[2] - 1];
        let reach = within * self.inv_cell;
        let limit = reach * reach * (1.0 + 1e-4);
        for z in lo[2]..=hi[2] {
            let gz = gap2(z, t.z, last[2]);
            if gz > limit {
                continue;
            }
            for y in lo[1]..=hi[1] {
                let room = limit - gz - gap2(y, t.y, last[1]);
                if room < 0.0 {
                    continue;
                }
                // The row's cells within reach: those meeting `t.x ± d` (a border cell reaches
                // on without end, so the clamped ends keep it).
                let d = room.sqrt() + MARGIN;
                let x0 = (((t.x - d - 1.0).ceil().max(0.0) as usize).min(last[0])).max(lo[0]);
                let x1 = ((t.x + d).floor().max(0.0) as usize).min(last[0]).min(hi[0]);
                if x0 > x1 {
                    continue;
                }
                let row = self.cell_index([0, y, z]);
                for cell in &self.head[row + x0..=row + x1] {
                    let mut i = *cell;
                    while i != NONE {
                        f(i);
                        i = self.next[i as usize];
                    }
                }
            }
        }
    }
}

/// A margin (cell units) far above the rounding of the cell coordinates.
const MARGIN: f32 = 1e-3;

/// The squared gap (cell units, less [`MARGIN`]) between coordinate `t` and cell `c` of an axis
/// whose last cell is `last`; a border cell reaches on without end on its outer side.
#[inline]
fn gap2(c: usize, t: f32, last: usize) -> f32 {
    let below = if c == 0 { 0.0 } else { c as f32 - t };
    let above = if c == last { 0.0 } else { t - (c + 1) as f32 };
    let g = (below.max(above) - MARGIN).max(0.0);
    g * g
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

    /// The items within `within` that each visit calls, in their order.
    fn visits(g: &Grid, pts: &[Vec3], q: Vec3, radius: f32, within: f32) -> (Vec<u32>, Vec<u32>, usize, usize) {
        let (mut all, mut pruned) = (Vec::new(), Vec::new());
        let (mut n_all, mut n_pruned) = (0, 0);
        let close = |i: u32| pts[i as usize].distance_squared(q) <= within * within;
        g.for_each_near(q, radius, |i| {
            n_all += 1;
            if close(i) {
                all.push(i);
            }
        });
        g.for_each_near_within(q, radius, within, |i| {
            n_pruned += 1;
            if close(i) {
                pruned.push(i);
            }
        });
        (all, pruned, n_all, n_pruned)
    }

    #[test]
    fn the_pruned_visit_calls_every_item_within_reach_in_the_plain_order() {
        let mut rng = crate::rng::Rng::new(5, "grid-within-test");
        // Points beyond the grid's box too: they are clamped into its border cells.
        let pts: Vec<Vec3> = (0..4000)
            .map(|_| Vec3::new(rng.uniform(-7.0, 7.0), rng.uniform(-2.0, 10.0), rng.uniform(-7.0, 7.0)))
            .collect();
        let (mut plain, mut pruned) = (0, 0);
        for cell in [0.35, 0.5, 0.9] {
            let mut g = Grid::new(Vec3::new(-5.0, 0.0, -5.0), Vec3::new(5.0, 8.0, 5.0), cell, 160);
            for (i, p) in pts.iter().enumerate() {
                g.insert(i as u32, *p);
            }
            for (k, q) in pts.iter().step_by(13).enumerate() {
                let radius = 2.0 * cell;
                // The reach at, below and above the query radius (a kill distance past it).
                let within = radius * [1.0, 0.6, 1.3][k % 3];
                let (a, b, n_all, n_pruned) = visits(&g, &pts, *q, radius, within);
                assert_eq!(a, b, "cell {cell}, point {k}");
                plain += n_all;
                pruned += n_pruned;
            }
            // A point exactly on cell corners, and one far outside the box.
            for q in [Vec3::new(0.0, 4.0, 0.0), Vec3::new(-30.0, 40.0, 9.0)] {
                let (a, b, _, _) = visits(&g, &pts, q, 2.0 * cell, 2.0 * cell);
                assert_eq!(a, b);
            }
        }
        // The corners of the block go: at least a fifth of the visits.
        assert!(pruned * 5 < plain * 4, "{pruned} of {plain}");
    }

    /// The nearest search of space colonization's new markers: the first nearest item in the
    /// plain visit's order (strictly nearer replaces), and whether one lies within `kill`.
    fn nearest(g: &Grid, pts: &[Vec3], q: Vec3, radius: f32, within: f32, kill: f32) -> (u32, bool, usize) {
        let (mut best, mut best_d2, mut dead, mut visits) = (u32::MAX, f32::INFINITY, false, 0);
        g.for_each_near_within(q, radius, within, |i| {
            visits += 1;
            let d2 = pts[i as usize].distance_squared(q);
            dead |= d2 <= kill * kill;
            if d2 < radius * radius && d2 < best_d2 {
                (best, best_d2) = (i, d2);
            }
        });
        (best, dead, visits)
    }

    #[test]
    fn a_search_bounded_by_the_own_cell_finds_the_same_nearest_item() {
        let mut rng = crate::rng::Rng::new(9, "grid-nearest-test");
        // Clustered points (a crown's nodes), some on one spot (exact ties), some outside the box.
        let mut pts: Vec<Vec3> = (0..3000)
            .map(|_| Vec3::new(rng.uniform(-2.0, 2.0), rng.uniform(2.0, 6.0), rng.uniform(-2.0, 2.0)))
            .collect();
        pts.extend(
            (0..300).map(|_| Vec3::new(rng.uniform(-9.0, 9.0), rng.uniform(-3.0, 11.0), rng.uniform(-9.0, 9.0))),
        );
        pts.extend([Vec3::new(0.5, 3.0, 0.5); 4]);
        let mut g = Grid::new(Vec3::new(-5.0, 0.0, -5.0), Vec3::new(5.0, 8.0, 5.0), 0.75, 160);
        for (i, p) in pts.iter().enumerate() {
            g.insert(i as u32, *p);
        }
        let (mut plain, mut bounded) = (0, 0);
        for k in 0..600 {
            let q = if k % 50 == 0 {
                Vec3::new(0.5, 3.0 + 0.1 * (k / 50) as f32, 0.5)
            } else {
                Vec3::new(rng.uniform(-6.0, 6.0), rng.uniform(-1.0, 9.0), rng.uniform(-6.0, 6.0))
            };
            let (radius, kill) = (1.5f32, if k % 2 == 0 { 0.4 } else { 2.0 });
            let within = radius.max(kill);
            let a = nearest(&g, &pts, q, radius, within, kill);
            let mut bound = f32::INFINITY;
            g.for_each_in_cell(q, |i| bound = bound.min(pts[i as usize].distance_squared(q)));
            let b = nearest(&g, &pts, q, radius, within.min(bound.sqrt()), kill);
            assert_eq!((a.0, a.1), (b.0, b.1), "query {k} at {q}");
            plain += a.2;
            bounded += b.2;
        }
        // In the cluster the nearest item is close: far fewer visits.
        assert!(bounded * 2 < plain, "{bounded} of {plain}");
    }
}
