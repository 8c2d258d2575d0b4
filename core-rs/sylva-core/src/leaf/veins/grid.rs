//! Uniform grids for the space colonization (a grid, never all-pairs searches): a static
//! grid built once by counting sort for the auxin sources, and a growing grid (a linked list per
//! cell) for the vein nodes.

use glam::Vec2;

const NONE: u32 = u32::MAX;
const MAX_CELLS_PER_AXIS: f32 = 1024.0;

/// Cell layout over a rectangle.
#[derive(Clone, Copy, Debug)]
pub struct GridSpec {
    lo: Vec2,
    inv: f32,
    nx: usize,
    ny: usize,
}

impl GridSpec {
    /// Square cells of side at least `cell` (more when the rectangle would need over 1,024
    /// cells along an axis) covering `lo..hi`.
    pub fn new(lo: Vec2, hi: Vec2, cell: f32) -> GridSpec {
        let size = (hi - lo).max(Vec2::splat(1e-6));
        let cell = cell.max(size.max_element() / MAX_CELLS_PER_AXIS).max(1e-6);
        let nx = (size.x / cell) as usize + 1;
        let ny = (size.y / cell) as usize + 1;
        GridSpec { lo, inv: 1.0 / cell, nx, ny }
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Whether the grid has no cells (never: at least one).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn coord(&self, v: f32, n: usize) -> usize {
        let c = v * self.inv;
        if c <= 0.0 {
            0
        } else {
            (c as usize).min(n - 1)
        }
    }

    /// The cell holding `p` (points outside are clamped to the border cells).
    pub fn cell(&self, p: Vec2) -> usize {
        let q = p - self.lo;
        self.coord(q.y, self.ny) * self.nx + self.coord(q.x, self.nx)
    }

    /// Cell ranges `(x0..=x1, y0..=y1)` overlapping the square of half-side `r` around `p`.
    pub fn span(&self, p: Vec2, r: f32) -> (usize, usize, usize, usize) {
        let (a, b) = (p - Vec2::splat(r) - self.lo, p + Vec2::splat(r) - self.lo);
        (self.coord(a.x, self.nx), self.coord(b.x, self.nx), self.coord(a.y, self.ny), self.coord(b.y, self.ny))
    }

    /// Cells per row.
    pub fn width(&self) -> usize {
        self.nx
    }
}

/// A grid over fixed points stored in cell order: the points of a cell, and of a run of cells
/// along a row, have consecutive ids, so a query walks memory in order.
#[derive(Clone, Debug)]
pub struct StaticGrid {
    spec: GridSpec,
    lo: Vec2,
    cell: f32,
    start: Vec<u32>,
}

impl StaticGrid {
    /// Sorts `points` by cell (stable) in place and bins them; returns the grid and, for each
    /// new position, the point's original index.
    pub fn sorted(spec: GridSpec, points: &mut [Vec2]) -> (StaticGrid, Vec<u32>) {
        let cells: Vec<u32> = points.iter().map(|&p| spec.cell(p) as u32).collect();
        let mut start = vec![0u32; spec.len() + 1];
        for &c in &cells {
            start[c as usize + 1] += 1;
        }
        for i in 0..spec.len() {
            start[i + 1] += start[i];
        }
        // Counting sort (stable): the points of a cell keep their order.
        let mut fill = start.clone();
        let mut order = vec![0u32; points.len()];
        for (i, &c) in cells.iter().enumerate() {
            order[fill[c as usize] as usize] = i as u32;
            fill[c as usize] += 1;
        }
        let original: Vec<Vec2> = points.to_vec();
        for (dst, &i) in points.iter_mut().zip(&order) {
            *dst = original[i as usize];
        }
        (StaticGrid { spec, lo: spec.lo, cell: 1.0 / spec.inv, start }, order)
    }

    /// Calls `f(ids)` with runs of ids covering every point within `r` of `p` (cells clipped
    /// to the disk row by row; a superset of the points within `r`).
    #[inline]
    pub fn for_near(&self, p: Vec2, r: f32, mut f: impl FnMut(std::ops::Range<usize>)) {
        let (_, _, y0, y1) = self.spec.span(p, r);
        let w = self.spec.width();
        for y in y0..=y1 {
            let row_lo = self.lo.y + y as f32 * self.cell;
            let dy = if p.y < row_lo { row_lo - p.y } else { (p.y - row_lo - self.cell).max(0.0) };
            if dy > r {
                continue;
            }
            let half = (r * r - dy * dy).sqrt();
            let (x0, x1, _, _) = self.spec.span(Vec2::new(p.x, row_lo), half);
            let (a, b) = (self.start[y * w + x0] as usize, self.start[y * w + x1 + 1] as usize);
            if a < b {
                f(a..b);
            }
        }
    }
}

/// A grid over a growing point set.
#[derive(Clone, Debug)]
pub struct DynGrid {
    spec: GridSpec,
    head: Vec<u32>,
    next: Vec<u32>,
}

impl DynGrid {
    /// An empty grid.
    pub fn new(spec: GridSpec) -> DynGrid {
        DynGrid { spec, head: vec![NONE; spec.len()], next: Vec::new() }
    }

    /// Adds point `id` at `p`; ids must be added in order 0, 1, 2, ...
    pub fn push(&mut self, id: u32, p: Vec2) {
        debug_assert_eq!(id as usize, self.next.len());
        let c = self.spec.cell(p);
        self.next.push(self.head[c]);
        self.head[c] = id;
    }

    /// Whether `pred(id)` holds for any point in the cells overlapping the square of
    /// half-side `r` around `p`.
    #[inline]
    pub fn any_near(&self, p: Vec2, r: f32, mut pred: impl FnMut(u32) -> bool) -> bool {
        let (x0, x1, y0, y1) = self.spec.span(p, r);
        let w = self.spec.width();
        for y in y0..=y1 {
            for x in x0..=x1 {
                let mut id = self.head[y * w + x];
                while id != NONE {
                    if pred(id) {
                        return true;
                    }
                    id = self.next[id as usize];
                }
            }
        }
        false
    }

    /// The point nearest `p` (`(id, squared distance)`; `(u32::MAX, ∞)` when empty): rings of
    /// cells searched outward until no closer point can remain.
    pub fn nearest(&self, p: Vec2, pos: &[Vec2]) -> (u32, f32) {
        let (mut best, mut bd) = (NONE, f32::INFINITY);
        let q = p - self.spec.lo;
        let (cx, cy) = ((q.x * self.spec.inv).floor() as i64, (q.y * self.spec.inv).floor() as i64);
        let (nx, ny) = (self.spec.nx as i64, self.spec.ny as i64);
        let cell = 1.0 / self.spec.inv;
        for ring in 0..=(nx.max(ny) + cx.abs().max(cy.abs())) {
            // Every point outside the rings searched so far is at least this far away.
            let reach = (ring - 1).max(0) as f32 * cell;
            if best != NONE && reach * reach > bd {
                break;
            }
            // Only the ring's own cells: its top and bottom rows, then its side columns.
            let mut visit = |x: i64, y: i64| {
                if x < 0 || y < 0 || x >= nx || y >= ny {
                    return;
                }
                let mut id = self.head[(y * nx + x) as usize];
                while id != NONE {
                    let d = (pos[id as usize] - p).length_squared();
                    if d < bd || (d == bd && id < best) {
                        (best, bd) = (id, d);
                    }
                    id = self.next[id as usize];
                }
            };
            for y in [cy - ring, cy + ring].into_iter().take(if ring == 0 { 1 } else { 2 }) {
                if (0..ny).contains(&y) {
                    for x in (cx - ring).max(0)..=(cx + ring).min(nx - 1) {
                        visit(x, y);
                    }
                }
            }
            for y in (cy - ring + 1).max(0)..=(cy + ring - 1).min(ny - 1) {
                visit(cx - ring, y);
                if ring > 0 {
                    visit(cx + ring, y);
                }
            }
        }
        (best, bd)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    #[test]
    fn queries_match_brute_force() {
        let mut rng = Rng::new(4, "grid");
        let pts: Vec<Vec2> = (0..500).map(|_| Vec2::new(rng.next_f32(), rng.next_f32() * 2.0)).collect();
        let spec = GridSpec::new(Vec2::ZERO, Vec2::new(1.0, 2.0), 0.05);
        let mut dynamic = DynGrid::new(spec);
        for (i, &p) in pts.iter().enumerate() {
            dynamic.push(i as u32, p);
        }
        let mut sorted = pts.clone();
        let (fixed, order) = StaticGrid::sorted(spec, &mut sorted);
        for _ in 0..200 {
            let q = Vec2::new(rng.uniform(-0.2, 1.2), rng.uniform(-0.2, 2.2));
            let brute =
                (0..pts.len()).min_by(|&a, &b| (pts[a] - q).length_squared().total_cmp(&(pts[b] - q).length_squared()));
            assert_eq!(dynamic.nearest(q, &pts).0, brute.unwrap() as u32);
            let r = 0.13;
            let mut near: Vec<u32> = Vec::new();
            fixed.for_near(q, r, |ids| {
                near.extend(ids.map(|i| order[i]).filter(|&i| (pts[i as usize] - q).length() < r))
            });
            near.sort_unstable();
            let want: Vec<u32> = (0..pts.len() as u32).filter(|&i| (pts[i as usize] - q).length() < r).collect();
            assert_eq!(near, want);
        }
    }

    /// A few points in a fine grid, queried from far away (inside and outside the grid): the
    /// ring search visits only each ring's own cells (it once scanned the whole square of every
    /// ring, which made sparse leaves take minutes) and still finds the brute-force nearest.
    #[test]
    fn nearest_in_a_sparse_fine_grid_matches_brute_force() {
        let mut rng = Rng::new(9, "grid");
        let spec = GridSpec::new(Vec2::ZERO, Vec2::ONE, 0.004);
        let pts: Vec<Vec2> = (0..7).map(|_| Vec2::new(rng.next_f32(), rng.next_f32())).collect();
        let mut grid = DynGrid::new(spec);
        for (i, &p) in pts.iter().enumerate() {
            grid.push(i as u32, p);
        }
        for _ in 0..300 {
            let q = Vec2::new(rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5));
            let brute = (0..pts.len() as u32)
                .min_by(|&a, &b| {
                    (pts[a as usize] - q).length_squared().total_cmp(&(pts[b as usize] - q).length_squared())
                })
                .unwrap();
            assert_eq!(grid.nearest(q, &pts), (brute, (pts[brute as usize] - q).length_squared()));
        }
        assert_eq!(DynGrid::new(spec).nearest(Vec2::splat(0.5), &[]).0, NONE);
    }
}
