//! The robust triangulation for outlines that are not star-shaped: ear clipping of the outline
//! (valid for every simple polygon), Lawson edge flips to the constrained Delaunay
//! triangulation (outline edges are the constraints and are never flipped), then interior
//! points on an offset grid inserted one by one (1-to-3 split, Delaunay legalisation), keeping
//! half a spacing away from the outline. Every flip checks that the new quad diagonal lies
//! inside the quad, so no step can fold the mesh.

use super::triangulation::{Method, Triangulation};
use crate::leaf::geom::{bounds, dist_to_segment, orient, polygon_area};
use glam::Vec2;

const NONE: u32 = u32::MAX;

/// Ear clipping + constrained Delaunay flips + interior points (`rings - 1` interior points per
/// two outline points, as many as the ring method would add, at most 4,000).
pub fn build(poly: &[Vec2], rings: u32) -> Triangulation {
    let tris = ear_clip(poly);
    let mut mesh = Mesh::new(poly.to_vec(), tris);
    mesh.delaunay_all();
    let want = (poly.len() * (rings.max(1) as usize - 1) / 2).min(4000);
    if want > 0 {
        let area = polygon_area(poly).abs() as f32;
        let (lo, hi) = bounds(poly);
        // Never finer than 1/1000 of the box (a needle-thin blade has almost no area).
        let h = (area / want as f32).sqrt().max((hi - lo).max_element() / 1000.0);
        for p in interior_points(poly, h) {
            mesh.insert(p, 1e-4 * h);
        }
    }
    Triangulation { vertices: mesh.verts, triangles: mesh.tris, method: Method::Cdt, boundary: poly.len() }
}

/// Ear clipping of a counter-clockwise simple polygon: `n - 2` counter-clockwise triangles.
pub fn ear_clip(poly: &[Vec2]) -> Vec<[u32; 3]> {
    let n = poly.len();
    let mut out = Vec::with_capacity(n.saturating_sub(2));
    if n < 3 {
        return out;
    }
    let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
    let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
    let convex = |a: usize, b: usize, c: usize| orient(poly[a], poly[b], poly[c]) > 0.0;
    let mut reflex: Vec<bool> = (0..n).map(|i| !convex(prev[i], i, next[i])).collect();
    let mut reflex_list: Vec<usize> = (0..n).filter(|&i| reflex[i]).collect();
    let mut alive = vec![true; n];
    let mut remaining = n;
    let mut i = 0;
    let mut misses = 0;
    while remaining > 3 {
        let (a, c) = (prev[i], next[i]);
        let ear = !reflex[i] && convex(a, i, c) && {
            let (pa, pb, pc) = (poly[a], poly[i], poly[c]);
            reflex_list.iter().all(|&r| {
                !alive[r] || !reflex[r] || r == a || r == c || r == i || {
                    let q = poly[r];
                    q == pa
                        || q == pc
                        || !(orient(pa, pb, q) >= 0.0 && orient(pb, pc, q) >= 0.0 && orient(pc, pa, q) >= 0.0)
                }
            })
        };
        if ear || misses > remaining {
            // When rounding leaves no clean ear, clip the most convex vertex left.
            let b = if ear { i } else { most_convex(poly, &prev, &next, &alive, i) };
            let (a, c) = (prev[b], next[b]);
            out.push([a as u32, b as u32, c as u32]);
            alive[b] = false;
            next[a] = c;
            prev[c] = a;
            remaining -= 1;
            for v in [a, c] {
                reflex[v] = !convex(prev[v], v, next[v]);
            }
            reflex_list.retain(|&r| alive[r] && reflex[r]);
            i = a;
            misses = 0;
        } else {
            i = next[i];
            misses += 1;
        }
    }
    out.push([prev[i] as u32, i as u32, next[i] as u32]);
    out
}

fn most_convex(poly: &[Vec2], prev: &[usize], next: &[usize], alive: &[bool], start: usize) -> usize {
    let mut best = (f64::NEG_INFINITY, start);
    let mut v = start;
    loop {
        if alive[v] {
            let o = orient(poly[prev[v]], poly[v], poly[next[v]]);
            if o > best.0 {
                best = (o, v);
            }
        }
        v = next[v];
        if v == start {
            return best.1;
        }
    }
}

/// Offset-grid points with spacing `h` inside the polygon and at least `h/2` from its edges,
/// in serpentine order (so point location walks are short).
fn interior_points(poly: &[Vec2], h: f32) -> Vec<Vec2> {
    let (lo, hi) = bounds(poly);
    let n = poly.len();
    let grid = EdgeGrid::new(poly, lo, hi, h);
    let mut out = Vec::new();
    let rows = ((hi.y - lo.y) / h) as usize + 1;
    for j in 0..rows {
        let y = lo.y + (j as f32 + 0.5) * h;
        let mut xs: Vec<f32> = Vec::new();
        for i in 0..n {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
        xs.sort_by(f32::total_cmp);
        let mut row = Vec::new();
        let shift = if j % 2 == 1 { 0.5 } else { 0.0 };
        for span in xs.chunks_exact(2) {
            let first = ((span[0] - lo.x) / h - 0.5 - shift).ceil().max(0.0) as usize;
            let mut k = first;
            loop {
                let x = lo.x + (k as f32 + 0.5 + shift) * h;
                if x >= span[1] {
                    break;
                }
                let p = Vec2::new(x, y);
                if grid.clear(p, 0.5 * h) {
                    row.push(p);
                }
                k += 1;
            }
        }
        if j % 2 == 1 {
            row.reverse();
        }
        out.extend(row);
    }
    out
}

/// Outline edges binned into square cells, for "is any edge closer than r" queries.
struct EdgeGrid<'a> {
    poly: &'a [Vec2],
    lo: Vec2,
    cell: f32,
    nx: usize,
    ny: usize,
    cells: Vec<Vec<u32>>,
}

impl<'a> EdgeGrid<'a> {
    fn new(poly: &'a [Vec2], lo: Vec2, hi: Vec2, cell: f32) -> Self {
        let nx = ((hi.x - lo.x) / cell) as usize + 1;
        let ny = ((hi.y - lo.y) / cell) as usize + 1;
        let mut cells = vec![Vec::new(); nx * ny];
        let n = poly.len();
        for i in 0..n {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            let (x0, y0) = (((a.x.min(b.x) - lo.x) / cell) as usize, ((a.y.min(b.y) - lo.y) / cell) as usize);
            let (x1, y1) = (((a.x.max(b.x) - lo.x) / cell) as usize, ((a.y.max(b.y) - lo.y) / cell) as usize);
            for y in y0.min(ny - 1)..=y1.min(ny - 1) {
                for x in x0.min(nx - 1)..=x1.min(nx - 1) {
                    cells[y * nx + x].push(i as u32);
                }
            }
        }
        EdgeGrid { poly, lo, cell, nx, ny, cells }
    }

    /// Whether no edge is within `r` (≤ one cell) of `p`.
    fn clear(&self, p: Vec2, r: f32) -> bool {
        let n = self.poly.len();
        let cx = ((p.x - self.lo.x) / self.cell) as isize;
        let cy = ((p.y - self.lo.y) / self.cell) as isize;
        for y in (cy - 1).max(0)..=(cy + 1).min(self.ny as isize - 1) {
            for x in (cx - 1).max(0)..=(cx + 1).min(self.nx as isize - 1) {
                for &e in &self.cells[y as usize * self.nx + x as usize] {
                    let (a, b) = (self.poly[e as usize], self.poly[(e as usize + 1) % n]);
                    if dist_to_segment(p, a, b) < r {
                        return false;
                    }
                }
            }
        }
        true
    }
}

/// A triangle mesh with adjacency: `adj[t][e]` is the triangle across edge
/// `tris[t][e] → tris[t][e+1]`, or `NONE` on the outline.
struct Mesh {
    verts: Vec<Vec2>,
    tris: Vec<[u32; 3]>,
    adj: Vec<[u32; 3]>,
    last: usize,
}

/// `> 0` when `d` lies inside the circumcircle of the counter-clockwise triangle `a, b, c`.
fn in_circle(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> f64 {
    let (ax, ay) = (f64::from(a.x - d.x), f64::from(a.y - d.y));
    let (bx, by) = (f64::from(b.x - d.x), f64::from(b.y - d.y));
    let (cx, cy) = (f64::from(c.x - d.x), f64::from(c.y - d.y));
    (ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay)
        + (cx * cx + cy * cy) * (ax * by - bx * ay)
}

impl Mesh {
    fn new(verts: Vec<Vec2>, tris: Vec<[u32; 3]>) -> Mesh {
        let mut keyed: Vec<(u32, u32, u32, u8)> = Vec::with_capacity(tris.len() * 3);
        for (t, tri) in tris.iter().enumerate() {
            for e in 0..3 {
                let (a, b) = (tri[e], tri[(e + 1) % 3]);
                keyed.push((a.min(b), a.max(b), t as u32, e as u8));
            }
        }
        keyed.sort_unstable();
        let mut adj = vec![[NONE; 3]; tris.len()];
        for w in keyed.windows(2) {
            if (w[0].0, w[0].1) == (w[1].0, w[1].1) {
                adj[w[0].2 as usize][w[0].3 as usize] = w[1].2;
                adj[w[1].2 as usize][w[1].3 as usize] = w[0].2;
            }
        }
        Mesh { verts, tris, adj, last: 0 }
    }

    fn p(&self, v: u32) -> Vec2 {
        self.verts[v as usize]
    }

    fn replace_nbr(&mut self, t: u32, old: u32, new: u32) {
        if t != NONE {
            for e in 0..3 {
                if self.adj[t as usize][e] == old {
                    self.adj[t as usize][e] = new;
                }
            }
        }
    }

    /// Flips edge `e` of `t` if its opposite vertex lies in the circumcircle and the quad is
    /// convex; returns the two triangles made.
    fn flip(&mut self, t: u32, e: usize) -> Option<(u32, u32)> {
        let t2 = self.adj[t as usize][e];
        if t2 == NONE {
            return None;
        }
        let [a, b, c] =
            [self.tris[t as usize][e], self.tris[t as usize][(e + 1) % 3], self.tris[t as usize][(e + 2) % 3]];
        let e2 = (0..3).find(|&k| self.tris[t2 as usize][k] == b && self.tris[t2 as usize][(k + 1) % 3] == a)?;
        let d = self.tris[t2 as usize][(e2 + 2) % 3];
        let (pa, pb, pc, pd) = (self.p(a), self.p(b), self.p(c), self.p(d));
        if in_circle(pa, pb, pc, pd) <= 0.0 || orient(pa, pd, pc) <= 0.0 || orient(pd, pb, pc) <= 0.0 {
            return None;
        }
        let (t_bc, t_ca) = (self.adj[t as usize][(e + 1) % 3], self.adj[t as usize][(e + 2) % 3]);
        let (t_ad, t_db) = (self.adj[t2 as usize][(e2 + 1) % 3], self.adj[t2 as usize][(e2 + 2) % 3]);
        self.tris[t as usize] = [a, d, c];
        self.adj[t as usize] = [t_ad, t2, t_ca];
        self.tris[t2 as usize] = [d, b, c];
        self.adj[t2 as usize] = [t_db, t_bc, t];
        self.replace_nbr(t_ad, t2, t);
        self.replace_nbr(t_bc, t, t2);
        Some((t, t2))
    }

    /// Lawson flips over every edge until the triangulation is constrained Delaunay.
    fn delaunay_all(&mut self) {
        let mut stack: Vec<(u32, usize)> =
            (0..self.tris.len() as u32).flat_map(|t| (0..3).map(move |e| (t, e))).collect();
        let mut budget = 40 * self.tris.len() + 1000;
        while let Some((t, e)) = stack.pop() {
            if budget == 0 {
                break;
            }
            if let Some((t1, t2)) = self.flip(t, e) {
                budget -= 1;
                stack.extend([(t1, 0), (t1, 2), (t2, 0), (t2, 1)]);
            }
        }
    }

    /// The triangle containing `p` strictly inside (each edge at least `margin` away, measured
    /// as twice-area over edge length), by a walk from the last insertion, else a scan.
    fn locate(&self, p: Vec2, margin: f32) -> Option<u32> {
        let inside = |t: usize| {
            let tri = self.tris[t];
            (0..3).all(|e| {
                let (a, b) = (self.p(tri[e]), self.p(tri[(e + 1) % 3]));
                orient(a, b, p) > f64::from(margin) * f64::from((b - a).length())
            })
        };
        let mut t = self.last.min(self.tris.len() - 1);
        'walk: for _ in 0..self.tris.len().min(4096) {
            let tri = self.tris[t];
            for e in 0..3 {
                if orient(self.p(tri[e]), self.p(tri[(e + 1) % 3]), p) < 0.0 {
                    let nb = self.adj[t][e];
                    if nb == NONE {
                        break 'walk;
                    }
                    t = nb as usize;
                    continue 'walk;
                }
            }
            return inside(t).then_some(t as u32);
        }
        (0..self.tris.len()).find(|&t| inside(t)).map(|t| t as u32)
    }

    /// Inserts `p` (1-to-3 split and legalisation) if it lies strictly inside a triangle.
    fn insert(&mut self, p: Vec2, margin: f32) {
        let Some(t) = self.locate(p, margin) else {
            return;
        };
        let v = self.verts.len() as u32;
        self.verts.push(p);
        let [a, b, c] = self.tris[t as usize];
        let [n_ab, n_bc, n_ca] = self.adj[t as usize];
        let (t1, t2) = (self.tris.len() as u32, self.tris.len() as u32 + 1);
        self.tris[t as usize] = [a, b, v];
        self.adj[t as usize] = [n_ab, t1, t2];
        self.tris.push([b, c, v]);
        self.adj.push([n_bc, t2, t]);
        self.tris.push([c, a, v]);
        self.adj.push([n_ca, t, t1]);
        self.replace_nbr(n_bc, t, t1);
        self.replace_nbr(n_ca, t, t2);
        self.last = t as usize;
        let mut stack = vec![t, t1, t2];
        let mut budget = 10_000;
        while let Some(tt) = stack.pop() {
            // The edge opposite the new vertex is edge 0 of every triangle made here.
            if budget == 0 {
                break;
            }
            budget -= 1;
            if let Some((x, y)) = self.flip(tt, 0) {
                stack.extend([x, y]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::leaf::triangulate::validate;

    /// A comb: a star-shaped test fails for it, so it exercises the robust path.
    fn comb() -> Vec<Vec2> {
        let mut p = vec![Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0)];
        for k in (0..5).rev() {
            let x = k as f32 * 0.2;
            p.push(Vec2::new(x + 0.2, 1.0));
            p.push(Vec2::new(x + 0.1, 1.0));
            p.push(Vec2::new(x + 0.1, 0.2));
        }
        p.pop();
        p.push(Vec2::new(0.0, 1.0));
        p.dedup();
        p
    }

    #[test]
    fn comb_is_triangulated_validly_with_and_without_interior_points() {
        let poly = comb();
        assert!(polygon_area(&poly) > 0.0);
        for rings in [1, 3, 8] {
            let t = build(&poly, rings);
            validate(&poly, &t).unwrap_or_else(|e| panic!("rings {rings}: {e}"));
            if rings > 1 {
                assert!(t.vertices.len() > poly.len(), "interior points were inserted");
            }
        }
    }
}
