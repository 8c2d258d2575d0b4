//! The blade as a raster for fast inside tests (vein growth) and the texture's alpha: cells
//! classified by scanlines through their centres, cells an edge passes near marked "boundary"
//! and answered exactly with a crossing test over the few edges spanning that row.

use crate::leaf::geom::bounds;
use glam::Vec2;

const OUT: u8 = 0;
const IN: u8 = 1;
const EDGE: u8 = 2;

/// Inside flags of the cell centres of a `w × h` grid with square cells of side `cell` whose
/// lower-left corner is `lo` (row-major, row 0 at the lowest `y`).
pub fn fill_rows(poly: &[Vec2], lo: Vec2, cell: Vec2, w: usize, h: usize) -> Vec<bool> {
    let n = poly.len();
    let mut out = vec![false; w * h];
    // Edges bucketed by the rows whose centre line they cross.
    let mut rows: Vec<Vec<u32>> = vec![Vec::new(); h];
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let (y0, y1) = (a.y.min(b.y), a.y.max(b.y));
        let r0 = ((y0 - lo.y) / cell.y - 0.5).ceil().max(0.0) as usize;
        let r1 = ((y1 - lo.y) / cell.y - 0.5).floor();
        if r1 < 0.0 {
            continue;
        }
        for row in rows.iter_mut().take((r1 as usize).min(h - 1) + 1).skip(r0) {
            row.push(i as u32);
        }
    }
    let mut xs: Vec<f32> = Vec::new();
    for (j, edges) in rows.iter().enumerate() {
        let y = lo.y + (j as f32 + 0.5) * cell.y;
        xs.clear();
        for &e in edges {
            let (a, b) = (poly[e as usize], poly[(e as usize + 1) % n]);
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
        xs.sort_by(f32::total_cmp);
        for span in xs.chunks_exact(2) {
            let i0 = ((span[0] - lo.x) / cell.x - 0.5).ceil().max(0.0) as usize;
            let i1 = ((span[1] - lo.x) / cell.x - 0.5).floor();
            if i1 < 0.0 {
                continue;
            }
            for v in out[j * w..(j + 1) * w].iter_mut().take((i1 as usize).min(w - 1) + 1).skip(i0) {
                *v = true;
            }
        }
    }
    out
}

/// A rasterised blade answering exact inside tests.
#[derive(Clone, Debug)]
pub struct Mask {
    poly: Vec<Vec2>,
    lo: Vec2,
    cell: f32,
    w: usize,
    h: usize,
    cells: Vec<u8>,
    /// Per row: edges whose `y` range overlaps the row.
    row_edges: Vec<Vec<u32>>,
}

impl Mask {
    /// The mask of a counter-clockwise polygon on a grid of about `res` cells along its longer side.
    pub fn new(poly: &[Vec2], res: usize) -> Mask {
        let (lo, hi) = bounds(poly);
        let size = (hi - lo).max_element().max(1e-6);
        let cell = size / res as f32;
        let lo = lo - Vec2::splat(cell);
        let w = ((hi.x - lo.x) / cell) as usize + 2;
        let h = ((hi.y - lo.y) / cell) as usize + 2;
        let inside = fill_rows(poly, lo, Vec2::splat(cell), w, h);
        let mut cells: Vec<u8> = inside.iter().map(|&b| if b { IN } else { OUT }).collect();
        let n = poly.len();
        let mut row_edges = vec![Vec::new(); h];
        for i in 0..n {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            let r0 = (((a.y.min(b.y) - lo.y) / cell) as usize).min(h - 1);
            let r1 = (((a.y.max(b.y) - lo.y) / cell) as usize).min(h - 1);
            for row in &mut row_edges[r0..=r1] {
                row.push(i as u32);
            }
            let steps = ((b - a).length() / (0.5 * cell)) as usize + 1;
            for k in 0..=steps {
                let q = a + (b - a) * (k as f32 / steps as f32);
                let (cx, cy) = (((q.x - lo.x) / cell) as isize, ((q.y - lo.y) / cell) as isize);
                for y in (cy - 1).max(0)..=(cy + 1).min(h as isize - 1) {
                    for x in (cx - 1).max(0)..=(cx + 1).min(w as isize - 1) {
                        cells[y as usize * w + x as usize] = EDGE;
                    }
                }
            }
        }
        Mask { poly: poly.to_vec(), lo, cell, w, h, cells, row_edges }
    }

    /// Whether `p` lies inside the blade.
    pub fn contains(&self, p: Vec2) -> bool {
        let (fx, fy) = ((p.x - self.lo.x) / self.cell, (p.y - self.lo.y) / self.cell);
        if !(fx >= 0.0 && fy >= 0.0) {
            return false;
        }
        let (x, y) = (fx as usize, fy as usize);
        if x >= self.w || y >= self.h {
            return false;
        }
        match self.cells[y * self.w + x] {
            IN => true,
            OUT => false,
            _ => {
                let n = self.poly.len();
                let mut inside = false;
                for &e in &self.row_edges[y] {
                    let (a, b) = (self.poly[e as usize], self.poly[(e as usize + 1) % n]);
                    if (a.y > p.y) != (b.y > p.y) {
                        let xc = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                        if p.x < xc {
                            inside = !inside;
                        }
                    }
                }
                inside
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::leaf::geom::point_in_polygon;
    use crate::rng::Rng;

    #[test]
    fn mask_agrees_with_the_exact_test() {
        let poly: Vec<Vec2> = (0..40)
            .map(|i| {
                let a = i as f32 * std::f32::consts::TAU / 40.0;
                let r = if i % 2 == 0 { 1.0 } else { 0.45 };
                Vec2::new(r * crate::math::cos(a), r * crate::math::sin(a))
            })
            .collect();
        let mask = Mask::new(&poly, 64);
        let mut rng = Rng::new(3, "mask");
        for _ in 0..20_000 {
            let p = Vec2::new(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
            assert_eq!(mask.contains(p), point_in_polygon(p, &poly), "{p}");
        }
    }
}
