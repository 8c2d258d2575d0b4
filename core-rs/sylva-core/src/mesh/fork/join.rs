//! # Building one fork
//!
//! The join of [`super`] (the ramiform of *Modeling the Mighty Maple for Web*
//! (ibiblio.org/e-notes); see the module notes there), in named steps:
//!
//! 1. [`Fork::new`]: the layout. Rings `S`, `Jo`, `Jc` and their frames, the inner half of `S`
//!    (the `n/2` columns facing the clone), where the new vertices go.
//! 2. [`Fork::seam`]: the crotch seam's vertices, once per branch, raised by `rise`.
//! 3. [`Fork::side_patches`]: the side patches' loops, on cubic Bezier columns from `S` to each
//!    branch's ring.
//! 4. [`Fork::patch_quads`] and [`Fork::crotch`]: the triangles, the crotch rows' end quads
//!    zipped against the side patches' end columns.
//!
//! [`join`] tries the seam's rises ([`RISES`]) in order until every triangle is well wound; the
//! side patches, which do not depend on the rise, are built and checked once.

use super::{seam_copies, split_ring, RISES};
use crate::math::{atan2, cos, sin, unit_or, PI, TAU};
use crate::mesh::junction::{well_wound, Join};
use crate::mesh::stem::Frame;
use crate::mesh::{MeshBuilder, WIND_DISTANCE, WIND_RADIUS, WIND_STRIDE};
use glam::Vec3;

/// Reused buffers of [`join`]: one fork's vertices and triangles, and its side patches' columns.
#[derive(Default)]
pub(crate) struct Scratch {
    /// The candidate triangles (the patches', then the crotch's).
    tris: Vec<u32>,
    seam: Vec<NewVertex>,
    patches: Vec<NewVertex>,
    patch_tris: Vec<u32>,
    /// A side patch's Bezier columns, and their points on one loop.
    cols: Vec<[Vec3; 4]>,
    at: Vec<(Vec3, Vec3)>,
    /// An end column of a side patch ([`Fork::column`]).
    column: Vec<(u32, f32)>,
}

/// One side patch: the half ring of `S` from column `start` (`h + 1` columns, around the stem)
/// up to the same columns of a branch's ring, with `loops` loops between.
struct Patch {
    start: usize,
    /// Whether the columns pass the seam (column `n`) inside: that column is stored twice.
    wraps: bool,
    /// First vertex of the loops (loop by loop, [`Patch::width`] vertices each).
    first: u32,
}

impl Patch {
    fn width(&self, h: usize) -> usize {
        h + 1 + usize::from(self.wraps)
    }

    /// Slot in a loop of column `e` (0..=h) as the left (`right` false) or right end of a quad.
    fn slot(&self, e: usize, right: bool, n: usize) -> usize {
        let cu = self.start + e;
        if self.wraps && (cu > n || (cu == n && !right)) {
            e + 1
        } else {
            e
        }
    }

    /// `u` of a slot's vertices (the seam copy has 1).
    fn u(&self, e: usize, right: bool, n: usize) -> f32 {
        let cu = self.start + e;
        if cu == n && (right || !self.wraps) {
            1.0
        } else {
            (cu % n) as f32 / n as f32
        }
    }

    /// Vertex of a ring starting at `ring` under column `e` as a left or right end.
    fn ring(&self, ring: u32, e: usize, right: bool, n: usize) -> u32 {
        let cu = self.start + e;
        if cu % n == 0 && cu > 0 && right {
            ring + n as u32
        } else {
            ring + (cu % n) as u32
        }
    }

    /// Loop `li`'s vertex of column `e`.
    fn at(&self, li: usize, e: usize, right: bool, n: usize) -> u32 {
        let h = n / 2;
        self.first + (li * self.width(h) + self.slot(e, right, n)) as u32
    }
}

/// A side patch with the ring it climbs to (`Jo` or `Jc`) and that ring's frame.
struct Side {
    patch: Patch,
    ring: u32,
    frame: Frame,
}

/// A vertex the fork adds.
struct NewVertex {
    pos: Vec3,
    normal: Vec3,
    uv: [f32; 2],
    wind: [f32; WIND_STRIDE],
}

/// The layout of one fork, fixed before any vertex is written.
struct Fork {
    /// Sides of both tubes (even), and half of them.
    n: usize,
    h: usize,
    /// Quad rows of each side patch (its loops are `rows - 1`).
    rows: usize,
    /// First vertices of rings `S` (the original's split ring), `Jo` (the original's next ring)
    /// and `Jc` (the clone's first ring).
    s_first: u32,
    o_first: u32,
    c_first: u32,
    /// The frame of `S`.
    fs: Frame,
    /// Column of `S` facing the clone's side: the inner half is `a..a + n/2`.
    a: usize,
    /// The branches' mean direction.
    up: Vec3,
    /// `S`'s front and back vertices (columns `a` and `a + n/2`): the crotch seam's ends.
    sf: u32,
    sb: u32,
    /// From `S`'s centre to its front vertex.
    front: Vec3,
    /// `v` of `S`.
    v_s: f32,
    /// First vertex the fork adds: the seam's inner vertices twice, then the side patches' loops.
    first_new: u32,
    /// One past the last vertex the fork adds.
    end: u32,
    /// The original's side patch (its outer half up to `Jo`), then the clone's (its outer half,
    /// columns `a..=a + n/2`, up to `Jc`).
    sides: [Side; 2],
    /// Offset of row `S`'s quads in the claimed-quad bitmap.
    claim: usize,
}

/// Builds the fork of [`Join::child`] on [`Join::parent`] (see the module notes of [`super`])
/// with `rows` side-patch rows ([`crate::mesh::fork_rows`]). On success row `S` of the original
/// is marked in `claimed`, the new vertices stay in `out` and the new triangles go to `bridges`;
/// on failure nothing is changed.
pub(crate) fn join(
    j: &Join,
    rows: usize,
    claimed: &mut [bool],
    out: &mut MeshBuilder,
    bridges: &mut Vec<u32>,
    sc: &mut Scratch,
) -> bool {
    let Some(fork) = Fork::new(j, rows, claimed, out) else { return false };
    let (pm, cm) = (j.parent, j.child);
    let Scratch { tris, seam, patches, patch_tris, cols, at, column } = sc;
    // The side patches and their quads do not depend on the seam's rise: built and checked
    // once (when they fold, no rise helps), then written again after each rise's seam.
    seam.clear();
    patches.clear();
    fork.seam(out, RISES[0], seam);
    fork.side_patches(out, patches, cols, at);
    debug_assert_eq!(fork.first_new as usize + seam.len() + patches.len(), fork.end as usize);
    write(out, seam);
    write(out, patches);
    patch_tris.clear();
    fork.patch_quads(out, patch_tris);
    if !well_wound(out, patch_tris) {
        out.truncate_vertices(fork.first_new);
        return false;
    }
    for (k, rise) in RISES.into_iter().enumerate() {
        if k > 0 {
            out.truncate_vertices(fork.first_new);
            seam.clear();
            fork.seam(out, rise, seam);
            write(out, seam);
            write(out, patches);
        }
        tris.clear();
        tris.extend_from_slice(patch_tris);
        fork.crotch(out, tris, rise, column);
        if well_wound(out, &tris[patch_tris.len()..])
            && out.unwrap_u(tris, seam_copies(pm.sides), |i, k| pm.seam_twin(i, k).or_else(|| cm.seam_twin(i, k)))
        {
            for c in 0..fork.n {
                claimed[fork.claim(c)] = true;
            }
            bridges.extend_from_slice(tris);
            return true;
        }
    }
    out.truncate_vertices(fork.first_new);
    false
}

/// Appends the fork's new vertices to `out`.
fn write(out: &mut MeshBuilder, verts: &[NewVertex]) {
    out.append_vertices(verts.len(), |sink| {
        for v in verts {
            sink.push(v.pos, v.normal, v.uv);
            sink.push_wind(&v.wind, 1);
        }
    });
}

impl Fork {
    /// The layout of the fork of `j` with `rows` side-patch rows, or None when the two tubes
    /// differ in sides (or have an odd number), `rows` is under 2, the split point is not a ring
    /// of the original or one of row `S`'s quads is already claimed.
    fn new(j: &Join, rows: usize, claimed: &[bool], out: &MeshBuilder) -> Option<Fork> {
        let (pm, cm) = (j.parent, j.child);
        if pm.sides != cm.sides || pm.sides % 2 != 0 || rows < 2 {
            return None;
        }
        let rs = split_ring(j.junction, pm, j.ts)?;
        let n = pm.sides as usize;
        let h = n / 2;
        let st = pm.sides + 1;
        let s_first = pm.first + rs as u32 * st;
        let (o_first, c_first) = (s_first + st, cm.first);
        let fs = j.frames[pm.ring0 + rs];
        let (fo, fc) = (j.frames[pm.ring0 + rs + 1], j.frames[cm.ring0]);
        // The inner half of S: the n/2 columns centred on the clone's direction.
        let mut w = fc.centre - fs.centre;
        w -= fs.tangent * w.dot(fs.tangent);
        let phi = atan2(w.dot(fs.tangent.cross(fs.normal)), w.dot(fs.normal));
        let a = (((phi - 0.5 * PI) / (TAU / n as f32)).round() as i64).rem_euclid(n as i64) as usize;
        let claim = pm.claim + rs * n;
        if (0..n).any(|c| claimed[claim + c % n]) {
            return None;
        }
        let up = unit_or(fo.tangent + fc.tangent, || fs.tangent);
        let (sf, sb) = (s_first + (a % n) as u32, s_first + ((a + h) % n) as u32);
        let front = out.vertex_at(sf).0 - fs.centre;
        let v_s = out.uv_at(sf)[1];
        let first_new = out.next_index();
        // Side patches: the original's outer half (columns a + h ..= a + n) up to Jo, the
        // clone's outer half (columns a ..= a + h) up to Jc.
        let mut next = first_new + 2 * (h as u32 - 1);
        let mut patch = |start: usize| {
            let start = start % n;
            let p = Patch { start, wraps: start + h > n, first: next };
            next += ((rows - 1) * p.width(h)) as u32;
            p
        };
        let sides = [
            Side { patch: patch(a + h), ring: o_first, frame: fo },
            Side { patch: patch(a), ring: c_first, frame: fc },
        ];
        Some(Fork {
            n,
            h,
            rows,
            s_first,
            o_first,
            c_first,
            fs,
            a,
            up,
            sf,
            sb,
            front,
            v_s,
            first_new,
            end: next,
            sides,
            claim,
        })
    }

    /// Slot of row `S`'s quad at column `c` in the claimed-quad bitmap.
    fn claim(&self, c: usize) -> usize {
        self.claim + c % self.n
    }

    /// The two vertices of the quad at column `c` of a ring (the second may be the seam copy).
    fn quad(&self, first: u32, c: usize) -> (u32, u32) {
        (first + (c % self.n) as u32, first + (c % self.n) as u32 + 1)
    }

    /// The facing columns: `Jo`'s column `a + k` ...
    fn p_at(&self, k: usize) -> u32 {
        self.o_first + ((self.a + k) % self.n) as u32
    }

    /// ... and `Jc`'s column `a - k`.
    fn q_at(&self, k: usize) -> u32 {
        self.c_first + ((self.a + self.n - k) % self.n) as u32
    }

    /// Seam vertex `k` (0..=h) of `branch` (0 the original's copy, 1 the clone's): its ends are
    /// `S`'s front and back vertices.
    fn m_at(&self, k: usize, branch: u32) -> u32 {
        match k {
            0 => self.sf,
            k if k == self.h => self.sb,
            k => self.first_new + branch * (self.h as u32 - 1) + k as u32 - 1,
        }
    }

    /// The crotch seam's inner vertices, once per branch (each with its branch's `u`): vertex
    /// `k` sits `cos θ` of `S`'s radius toward the front and `rise · sin θ` of the way up to the
    /// midpoint of the facing columns (θ = π k / h). Both copies sway with the original (a crack
    /// would open between two records); distance and radius rise from `S`'s with the seam, as
    /// `v` does.
    fn seam(&self, out: &MeshBuilder, rise: f32, verts: &mut Vec<NewVertex>) {
        let (h, fs) = (self.h, self.fs);
        for branch in 0..2 {
            for k in 1..h {
                let ((pp, pn), (qp, qn)) = (out.vertex_at(self.p_at(k)), out.vertex_at(self.q_at(k)));
                let theta = PI * k as f32 / h as f32;
                let up_by = rise * sin(theta);
                let base = fs.centre + self.front * cos(theta);
                let pos = base + ((pp + qp) * 0.5 - base) * up_by;
                let normal = unit_or(pn + qn + self.up, || self.up);
                let (w0, mut wind) = (out.wind_at(self.sf), out.wind_at(self.p_at(k)));
                for i in [WIND_DISTANCE, WIND_RADIUS] {
                    wind[i] = w0[i] + (wind[i] - w0[i]) * up_by;
                }
                let [u, v] = out.uv_at(if branch == 0 { self.p_at(k) } else { self.q_at(k) });
                verts.push(NewVertex { pos, normal, uv: [u, self.v_s + (v - self.v_s) * up_by], wind });
            }
        }
    }

    /// The side patches' loops: per column a cubic Bezier from `S` (leaving along the original's
    /// axis) to the branch's ring (arriving along the branch's axis), handles 0.4 of the chord;
    /// the loops at even parameters, normals across the loops.
    fn side_patches(
        &self,
        out: &MeshBuilder,
        verts: &mut Vec<NewVertex>,
        cols: &mut Vec<[Vec3; 4]>,
        at: &mut Vec<(Vec3, Vec3)>,
    ) {
        let (n, h, fs) = (self.n, self.h, self.fs);
        for side in &self.sides {
            let (p, f) = (&side.patch, side.frame);
            cols.clear();
            cols.extend((0..=h).map(|e| {
                let (p0, p3) = (
                    out.vertex_at(p.ring(self.s_first, e, false, n)).0,
                    out.vertex_at(p.ring(side.ring, e, false, n)).0,
                );
                let len = (p3 - p0).length();
                // Leaving S along the original's axis, except toward the front and back of
                // the clone's patch, which lean with the clone: there they must stay on the
                // clone's side of the crotch seam, which leans half as much.
                let t0 = if side.ring == self.c_first {
                    let s = sin(PI * e as f32 / h as f32);
                    unit_or(fs.tangent * s + f.tangent * (1.0 - s), || fs.tangent)
                } else {
                    fs.tangent
                };
                [p0, p0 + t0 * (0.4 * len), p3 - f.tangent * (0.4 * len), p3]
            }));
            for li in 0..self.rows - 1 {
                let u = (li + 1) as f32 / self.rows as f32;
                // Each column's point and direction on this loop, once.
                at.clear();
                at.extend(cols.iter().map(|c| bezier(c, u)));
                for slot in 0..p.width(h) {
                    // Column of the slot, and whether it is the seam copy's right-end twin.
                    let (e, right) = match (p.wraps, p.start + slot) {
                        (true, cu) if cu > n => (slot - 1, false),
                        (true, cu) if cu == n => (slot, true),
                        _ => (slot, false),
                    };
                    let (pos, along) = at[e];
                    let around = at[(e + 1).min(h)].0 - at[e.saturating_sub(1)].0;
                    let normal = unit_or(around.cross(along), || unit_or(pos - f.centre, || self.up));
                    let (bottom, top) = (p.ring(self.s_first, e, right, n), p.ring(side.ring, e, right, n));
                    let (w0, mut wind) = (out.wind_at(bottom), out.wind_at(top));
                    for i in [WIND_DISTANCE, WIND_RADIUS] {
                        wind[i] = w0[i] * (1.0 - u) + wind[i] * u;
                    }
                    let v = out.uv_at(bottom)[1] * (1.0 - u) + out.uv_at(top)[1] * u;
                    verts.push(NewVertex { pos, normal, uv: [p.u(e, right, n), v], wind });
                }
            }
        }
    }

    /// The side patches' quads, as the original's own quads.
    fn patch_quads(&self, out: &MeshBuilder, tris: &mut Vec<u32>) {
        let (n, rows) = (self.n, self.rows);
        for side in &self.sides {
            let p = &side.patch;
            for row in 0..rows {
                let lo =
                    |e: usize, r: bool| if row == 0 { p.ring(self.s_first, e, r, n) } else { p.at(row - 1, e, r, n) };
                let hi =
                    |e: usize, r: bool| if row + 1 == rows { p.ring(side.ring, e, r, n) } else { p.at(row, e, r, n) };
                for e in 0..self.h {
                    quad_tris(out, tris, [lo(e, false), lo(e + 1, true), hi(e + 1, true), hi(e, false)]);
                }
            }
        }
    }

    /// A side patch's end column `e` (from `S` up to its ring), bottom to top, with height
    /// parameters, into `c`.
    fn column<'c>(&self, side: &Side, e: usize, right: bool, c: &'c mut Vec<(u32, f32)>) -> &'c [(u32, f32)] {
        let (p, n) = (&side.patch, self.n);
        // rows + 1 vertices: S's, one per loop, the ring's.
        let last = self.rows as f32;
        c.clear();
        c.push((p.ring(self.s_first, e, right, n), 0.0));
        c.extend((0..self.rows - 1).map(|li| (p.at(li, e, right, n), (li + 1) as f32 / last)));
        c.push((p.ring(side.ring, e, right, n), self.rows as f32 / last));
        c
    }

    /// The crotch: one row of quads from the seam up to each ring's inner half. Its end quads
    /// border the side patches' end columns (`S`'s front and back up to the ring): zipped strips.
    fn crotch(&self, out: &MeshBuilder, tris: &mut Vec<u32>, rise: f32, col: &mut Vec<(u32, f32)>) {
        let (n, h, a) = (self.n, self.h, self.a);
        let [po, pc] = &self.sides;
        // Height parameter of a seam vertex (0 at S, 1 at the rings), as placed by `seam`.
        let lift = |k: usize| rise * sin(PI * k as f32 / h as f32);
        // The original's side: the seam up to Jo's inner half.
        for k in 0..h {
            let (p0, p1) = self.quad(self.o_first, a + k);
            let (m0, m1) = (self.m_at(k, 0), self.m_at(k + 1, 0));
            if k == 0 {
                zip(out, tris, self.column(po, h, true, col), &[(m1, lift(1)), (p1, 1.0)]);
            } else if k + 1 == h {
                zip(out, tris, &[(m0, lift(k)), (p0, 1.0)], self.column(po, 0, false, col));
            } else {
                tris.extend_from_slice(&[m0, m1, p1, m0, p1, p0]);
            }
        }
        // The clone's side: the clone's columns run the other way.
        for k in 0..h {
            let (q1, q0) = self.quad(self.c_first, a + n - k - 1);
            let (m0, m1) = (self.m_at(k, 1), self.m_at(k + 1, 1));
            if k == 0 {
                zip(out, tris, &[(m1, lift(1)), (q1, 1.0)], self.column(pc, 0, false, col));
            } else if k + 1 == h {
                zip(out, tris, self.column(pc, h, true, col), &[(m0, lift(k)), (q0, 1.0)]);
            } else {
                tris.extend_from_slice(&[m1, m0, q0, m1, q0, q1]);
            }
        }
    }
}

/// Point and derivative direction (unscaled) of the cubic Bezier `c` at `u`.
fn bezier(c: &[Vec3; 4], u: f32) -> (Vec3, Vec3) {
    let [p0, b1, b2, p3] = *c;
    let v = 1.0 - u;
    let pos = p0 * (v * v * v) + b1 * (3.0 * u * v * v) + b2 * (3.0 * u * u * v) + p3 * (u * u * u);
    let along = (b1 - p0) * (v * v) + (b2 - b1) * (2.0 * u * v) + (p3 - b2) * (u * u);
    (pos, along)
}

/// Triangulates the strip between two chains of vertices with height parameters (0 bottom, 1
/// top), both listed bottom to top: the strip's boundary runs from `a[0]` to `b[0]`, up `b`,
/// from `b`'s top to `a`'s top, and down `a`. Each step advances the chain whose next vertex is
/// lower, unless only the other step keeps its triangle wound with its normals.
fn zip(out: &MeshBuilder, tris: &mut Vec<u32>, a: &[(u32, f32)], b: &[(u32, f32)]) {
    let (mut i, mut j) = (0, 0);
    while i + 1 < a.len() || j + 1 < b.len() {
        let step_a = [a[i].0, b[j].0, a[(i + 1).min(a.len() - 1)].0];
        let step_b = [a[i].0, b[j].0, b[(j + 1).min(b.len() - 1)].0];
        let (can_a, can_b) = (i + 1 < a.len(), j + 1 < b.len());
        let mut take_a = can_a && (!can_b || a[i + 1].1 <= b[j + 1].1);
        if take_a && can_b && !well_wound(out, &step_a) && well_wound(out, &step_b) {
            take_a = false;
        } else if !take_a && can_a && !well_wound(out, &step_b) && well_wound(out, &step_a) {
            take_a = true;
        }
        if take_a {
            tris.extend_from_slice(&step_a);
            i += 1;
        } else {
            tris.extend_from_slice(&step_b);
            j += 1;
        }
    }
}

/// A quad `[p, q, r, s]` (counter-clockwise) as two triangles, split along the diagonal that
/// keeps both wound with their normals where only one does.
fn quad_tris(out: &MeshBuilder, tris: &mut Vec<u32>, [p, q, r, s]: [u32; 4]) {
    let split = [p, q, r, p, r, s];
    if well_wound(out, &split) {
        tris.extend_from_slice(&split);
    } else {
        tris.extend_from_slice(&[p, q, s, q, r, s]);
    }
}
