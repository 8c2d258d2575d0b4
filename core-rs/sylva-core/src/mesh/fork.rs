//! Smooth Y forks (issue #5, item 3): a split clone that leaves its original at a shallow angle
//! becomes one branch of a **ramiform**, after the maple page (reference 003): "two twigs are
//! connected smoothly … four Bezier semi-cylinders: two side patches similar to twigs, two more
//! patches to make a smooth top part" (a C0 simplification of Bloomenthal's node). Below about
//! 30° a clone runs inside its original for many radii (at 10° two equal tubes overlap for about
//! eleven radii), so a footprint on the original's side ([`super::weld`]) cannot be found; the
//! fork instead splits the original's tube in two.
//!
//! With `S` the original's ring at the split point, `Jo` the original's next ring (where the two
//! tubes have separated: [`geometry`]) and `Jc` the clone's first ring (its junction ring):
//!
//! * **Frames.** Both tubes have the same number of sides `n` (even), and the clone's sweep
//!   starts from `S`'s frame normal, so column `k` of every ring points the same way and the
//!   clone's `v` continues the original's at `S`: bark UVs run on unbroken into both branches.
//! * **Halves.** `S` is cut into two halves by the plane through the original's axis across the
//!   clone's direction: columns `a..a+n/2` face the clone (inner), the rest face away (outer).
//! * **Side patches** (the ramiform's twig-like patches). Row `S` of the original is claimed
//!   (not emitted). `S`'s outer half is joined to `Jo`'s outer half, and `S`'s inner half to the
//!   clone's `Jc` columns `a..a+n/2` (the clone's outer half, facing the same way), each by
//!   [`super::fork_rows::rows`] rows of quads: per column a cubic Bezier from `S` (leaving along the original's
//!   axis, so the trunk below flows on without a kink; toward the front and back of the
//!   clone's patch leaning with the clone) to the ring (arriving along its branch's axis),
//!   handles 0.4 of the chord, loops at even parameters, normals across the loops.
//! * **Top patch (the crotch).** `Jo`'s inner half (facing the clone) and `Jc`'s inner half
//!   (facing the original) both come down to a **crotch seam** from `S`'s front column to its
//!   back column: where two tubes diverging at ±α meet, their surfaces cross on an ellipse in the
//!   plane between them, at the split point at the front and back and `R / sin α` up in the
//!   middle. Seam vertex `k` (θ = π k / (n/2)) sits `cos θ` of `S`'s radius toward the front and
//!   `sin θ` of the way up to the midpoint of the facing columns `Jo[a + k]`, `Jc[a − k]`
//!   (times 0.9, or 0.7, 0.97 if a triangle turns the wrong way), with the normal of the two
//!   columns' normals plus the branches' mean direction, and the original's wind record. The
//!   seam's vertices are written twice, with the original's `u` and with the clone's, so each
//!   side's bark stays continuous. One row of quads joins the seam to each ring; the row's end
//!   quads meet the side patches' end columns and are zipped strips ([`zip`]).
//!
//! Triangles that straddle the original's texture seam get copies of their vertices a whole
//! turn on ([`MeshBuilder::unwrap_u`]).
//!
//! The result is edge-manifold by construction: every edge of row `S`, of `Jo` and of `Jc` is
//! used once more, the seam's edges by both crotch rows, and the seam's ends are `S`'s own front
//! and back vertices. Every new triangle must be non-degenerate and wound with its vertex normals
//! ([`super::weld::well_wound`]; a skewed side-patch quad may take its other diagonal); else
//! nothing is committed and the clone falls back to a separate tube. The original has no rings
//! between `S` and `Jo` ([`keep_gaps`]), and no other child's footprint may use those rows (the
//! fork's footprint spans the whole way round).

use super::tube::Frame;
use super::weld::{surface_bound, well_wound, Join, Junction, MAX_START};
use super::{MeshBuilder, WIND_STRIDE};
use crate::math::{atan2, cos, sin, unit_or, PI, TAU};
use crate::params::TreeParams;
use crate::skeleton::Stem;
use glam::Vec3;

/// Largest sine of the clone's angle to its original that makes a fork (30°); steeper clones
/// are welded into the original's side ([`super::weld`]).
const MAX_SIN: f32 = 0.5;
/// The junction rings must be apart by this factor times the sum of the two radii.
const CLEARANCE: f32 = 1.1;
/// Steps of the search for the rings where the tubes have separated, and how many of them the
/// search skips at a time before looking at each.
const STEPS: usize = 400;
const COARSE: usize = 4;
/// How far up from the split toward the facing columns' midpoint the crotch seam rises in the
/// middle, tried in order until every triangle is well wound.
const RISES: [f32; 3] = [0.9, 0.7, 0.97];

/// The fork junction of split clone `i` (same level as its parent, the original), or None when
/// it is no shallow fork or its tubes do not separate soon enough: `t_lo` is the split point on
/// the original (ring `S`), `t_hi` the original's ring `Jo`, `t_start` the clone's ring `Jc`;
/// both rings sit the same distance from the split along their stems, the first distance (in
/// quarter radii) at which their centres are [`CLEARANCE`] times their radii apart. `sides` are
/// the stems' numbers of sides: the original's must be even.
pub(crate) fn geometry(stems: &[Stem], i: usize, p: &TreeParams, sides: &[u32]) -> Option<Junction> {
    geometry_from(stems, i, p, sides, None)
}

/// [`geometry`] with the split moved up the original to `from` (its `t`; None: the clone's own
/// base). A second clone that leaves at the same point as a fork forks one step up, at that
/// fork's ring `Jo` (a fork's rows are its own): the clone then seems to leave a little higher,
/// where it has already drawn a little away, rather than becoming a separate tube.
pub(crate) fn geometry_from(
    stems: &[Stem],
    i: usize,
    p: &TreeParams,
    sides: &[u32],
    from: Option<f32>,
) -> Option<Junction> {
    let c = &stems[i];
    let pi = c.parent?;
    let o = &stems[pi as usize];
    if o.level != c.level || sides[pi as usize] % 2 != 0 || sides[pi as usize] < 4 {
        return None;
    }
    let (lo, lc) = (o.length.max(1e-6), c.length.max(1e-6));
    let t_base = c.offset / lo;
    let t_split = from.unwrap_or(t_base);
    if !(1e-3..0.9).contains(&t_split) || t_split < t_base {
        return None;
    }
    let (_, tan) = o.sample(t_base);
    let (_, d0) = c.sample(0.0);
    let cos = d0.dot(tan).clamp(-1.0, 1.0);
    if 1.0 - cos * cos >= MAX_SIN * MAX_SIN {
        return None;
    }
    let bound = if o.lobed { surface_bound(p) } else { 1.0 };
    let r0 = o.radius_at(t_split).max(1e-6);
    let step = 0.25 * r0;
    // The clone's distance from its base where the original is `s` above the split.
    let ahead = (t_split - t_base) * lo;
    // A clone that has drawn away already would separate at once, in a steep short crotch:
    // one forking one step up gets a quarter more length (more makes its side patch fold).
    let min_s = (r0 + c.radius_at(0.0)) * if ahead > 0.0 { 1.25 } else { 1.0 };
    // Step k: how far up the original from the split, and where both stems are then.
    let at_step = |k: usize| {
        let s = k as f32 * step;
        (s, t_split + s / lo, (ahead + s) / lc)
    };
    let (mut on_o, mut on_c) = (o.points(), c.points());
    // Some(true) where the tubes have separated, None past the search's end.
    let mut separated = |k: usize| {
        let (s, t_o, t_c) = at_step(k);
        if t_c > MAX_START || t_o > 0.9 {
            return None;
        }
        let gap = (on_o.at(t_o) - on_c.at(t_c)).length();
        Some(s >= min_s && gap >= CLEARANCE * (o.radius_at(t_o) * bound + c.radius_at(t_c)))
    };
    // Every COARSE-th step first (a radius apart); the steps before one that separates (or ends
    // the search) are then tried in order for the first that does. A separation that does not
    // last to the next coarse step (the tubes touch again within a radius) is not taken; on
    // every preset the forks are the ones a step-by-step search finds (same golden hashes).
    let mut k = 0;
    while k < STEPS {
        let hi = (k + COARSE).min(STEPS);
        if separated(hi) == Some(false) {
            k = hi;
            continue;
        }
        for j in k + 1..=hi {
            match separated(j) {
                None => return None,
                Some(false) => {}
                Some(true) => {
                    let (_, t_o, t_c) = at_step(j);
                    return Some(Junction {
                        parent: pi,
                        t_start: t_c,
                        t_lo: t_split,
                        t_hi: t_o,
                        foot: c.radius_at(0.0),
                        phi: 0.0,
                        // The whole way round: no other footprint may share the fork's rows.
                        beta: PI,
                        fork: true,
                    });
                }
            }
        }
        k = hi;
    }
    None
}

/// Keeps the rows of the forks among `feet` open: removes the rings of `ts[first..]` (sorted)
/// strictly inside each fork's `t_lo..t_hi` and makes sure both ends are rings, exactly.
pub(crate) fn keep_gaps(feet: &[Junction], ts: &mut Vec<f32>, first: usize) {
    for f in feet.iter().filter(|f| f.fork) {
        let rings = &ts[first..];
        let a = rings.partition_point(|&x| x < f.t_lo - 1e-4) + first;
        let b = rings.partition_point(|&x| x <= f.t_hi + 1e-4) + first;
        ts.splice(a..b, [f.t_lo, f.t_hi]);
    }
}

/// Where the clone's sweep starts: the frame normal of ring `S` (so the columns line up with
/// the original's) and the `v` of `S` (so the bark runs on), given the original's swept tube.
pub(crate) fn clone_start(
    j: &Junction,
    parent: &super::tube::StemMesh,
    ts: &[f32],
    frames: &[Frame],
    out: &MeshBuilder,
) -> Option<(Vec3, f32)> {
    let rs = split_ring(j, parent, ts)?;
    let v = out.uv_at(parent.first + rs as u32 * (parent.sides + 1))[1];
    Some((frames[parent.ring0 + rs].normal, v))
}

/// Index (within the original's tube) of ring `S`, followed by ring `Jo`.
fn split_ring(j: &Junction, pm: &super::tube::StemMesh, ts: &[f32]) -> Option<usize> {
    let pts = &ts[pm.ring0..pm.ring0 + pm.rings as usize];
    let rs = pts.partition_point(|&x| x < j.t_lo);
    (rs + 1 < pts.len() && pts[rs] == j.t_lo && pts[rs + 1] == j.t_hi).then_some(rs)
}

/// Vertices [`join`] adds at most for a fork of `sides` sides with `rows` side-patch rows
/// ([`super::fork_rows`]): two
/// side patches of `rows - 1` loops of `sides / 2 + 2` vertices (one a seam copy) and the
/// crotch seam's inner vertices, twice.
pub(crate) fn vertices(sides: u32, rows: usize) -> usize {
    let h = sides as usize / 2;
    2 * (rows - 1) * (h + 2) + 2 * (h - 1) + seam_copies(sides)
}

/// Copies [`join`] may add where its triangles cross the original's bark seam
/// ([`MeshBuilder::unwrap_u`]).
fn seam_copies(sides: u32) -> usize {
    2 * (sides as usize + 1)
}

/// Indices [`join`] adds at most: the side patches' quads and the crotch's row of quads (whose
/// end quads become fans of `rows + 1` triangles).
pub(crate) fn indices(sides: u32, rows: usize) -> usize {
    let h = sides as usize / 2;
    3 * (2 * 2 * h * rows + 2 * 2 * h + 4 * rows)
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

/// Builds the fork of [`Join::child`] on [`Join::parent`] (see the module notes) with `rows`
/// side-patch rows ([`rows`]). On success row `S` of the original is marked in `claimed`, the
/// new vertices stay in `out` and the new triangles go to `bridges`; on failure nothing is
/// changed.
pub(crate) fn join(
    j: &Join,
    rows: usize,
    claimed: &mut [bool],
    out: &mut MeshBuilder,
    bridges: &mut Vec<u32>,
    tris: &mut Vec<u32>,
) -> bool {
    let (pm, cm) = (j.parent, j.child);
    if pm.sides != cm.sides || pm.sides % 2 != 0 || rows < 2 {
        return false;
    }
    let Some(rs) = split_ring(j.junction, pm, j.ts) else { return false };
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
    let claim = |c: usize| pm.claim + rs * n + c % n;
    if (0..n).any(|c| claimed[claim(c)]) {
        return false;
    }
    // The two vertices of the quad at column `c` of a ring (the second may be the seam copy).
    let quad = |first: u32, c: usize| (first + (c % n) as u32, first + (c % n) as u32 + 1);
    // The facing columns: Jo's column a + k and Jc's column a - k.
    let p_at = |k: usize| o_first + ((a + k) % n) as u32;
    let q_at = |k: usize| c_first + ((a + n - k) % n) as u32;
    let up = unit_or(fo.tangent + fc.tangent, || fs.tangent);
    let (sf, sb) = (s_first + (a % n) as u32, s_first + ((a + h) % n) as u32);
    let front = out.vertex_at(sf).0 - fs.centre;
    let v_s = out.uv_at(sf)[1];
    let first_new = out.next_index();
    // The seam's inner vertices, once per branch (each with its branch's `u`); its ends are S's
    // front and back vertices.
    let m_at = |k: usize, branch: u32| match k {
        0 => sf,
        k if k == h => sb,
        k => first_new + branch * (h as u32 - 1) + k as u32 - 1,
    };
    let loops = rows - 1;
    // Side patches: the original's outer half (columns a + h ..= a + n) up to Jo, the clone's
    // outer half (columns a ..= a + h) up to Jc.
    let mut next = first_new + 2 * (h as u32 - 1);
    let mut patch = |start: usize| {
        let start = start % n;
        let p = Patch { start, wraps: start + h > n, first: next };
        next += (loops * p.width(h)) as u32;
        p
    };
    let sides = [(patch(a + h), o_first, fo), (patch(a), c_first, fc)];
    for rise in RISES {
        out.truncate_vertices(first_new);
        let mut verts: Vec<(Vec3, Vec3, [f32; 2], [f32; WIND_STRIDE])> = Vec::new();
        // The crotch seam (see the module notes).
        for branch in 0..2 {
            for k in 1..h {
                let ((pp, pn), (qp, qn)) = (out.vertex_at(p_at(k)), out.vertex_at(q_at(k)));
                let theta = PI * k as f32 / h as f32;
                let up_by = rise * sin(theta);
                let base = fs.centre + front * cos(theta);
                let m = base + ((pp + qp) * 0.5 - base) * up_by;
                let nm = unit_or(pn + qn + up, || up);
                // Both copies sway with the original (a crack would open between two records);
                // distance and radius rise from S's with the seam, as `v` does.
                let (w0, mut wr) = (out.wind_at(sf), out.wind_at(p_at(k)));
                wr[6] = w0[6] + (wr[6] - w0[6]) * up_by;
                wr[7] = w0[7] + (wr[7] - w0[7]) * up_by;
                let [u, v] = out.uv_at(if branch == 0 { p_at(k) } else { q_at(k) });
                verts.push((m, nm, [u, v_s + (v - v_s) * up_by], wr));
            }
        }
        // Side patches: per column a cubic Bezier from S (leaving along the original's axis) to
        // the branch's ring (arriving along the branch's axis); the loops at even parameters.
        for (p, ring, f) in &sides {
            let mut cols: Vec<(Vec3, Vec3, Vec3, Vec3)> = Vec::with_capacity(h + 1);
            for e in 0..=h {
                let (p0, p3) =
                    (out.vertex_at(p.ring(s_first, e, false, n)).0, out.vertex_at(p.ring(*ring, e, false, n)).0);
                let len = (p3 - p0).length();
                // Leaving S along the original's axis, except toward the front and back of the
                // clone's patch, which lean with the clone: there they must stay on the clone's
                // side of the crotch seam, which leans half as much.
                let t0 = if *ring == c_first {
                    let side = sin(PI * e as f32 / h as f32);
                    unit_or(fs.tangent * side + f.tangent * (1.0 - side), || fs.tangent)
                } else {
                    fs.tangent
                };
                cols.push((p0, p0 + t0 * (0.4 * len), p3 - f.tangent * (0.4 * len), p3));
            }
            let bez = |e: usize, u: f32| {
                let (p0, b1, b2, p3) = cols[e];
                let v = 1.0 - u;
                let pos = p0 * (v * v * v) + b1 * (3.0 * u * v * v) + b2 * (3.0 * u * u * v) + p3 * (u * u * u);
                let along = (b1 - p0) * (v * v) + (b2 - b1) * (2.0 * u * v) + (p3 - b2) * (u * u);
                (pos, along)
            };
            for li in 0..loops {
                let u = (li + 1) as f32 / rows as f32;
                for slot in 0..p.width(h) {
                    // Column of the slot, and whether it is the seam copy's right-end twin.
                    let (e, right) = match (p.wraps, p.start + slot) {
                        (true, cu) if cu > n => (slot - 1, false),
                        (true, cu) if cu == n => (slot, true),
                        _ => (slot, false),
                    };
                    let (pos, along) = bez(e, u);
                    let around = bez((e + 1).min(h), u).0 - bez(e.saturating_sub(1), u).0;
                    let nm = unit_or(around.cross(along), || unit_or(pos - f.centre, || up));
                    let (bottom, top) = (p.ring(s_first, e, right, n), p.ring(*ring, e, right, n));
                    let (w0, mut wr) = (out.wind_at(bottom), out.wind_at(top));
                    wr[6] = w0[6] * (1.0 - u) + wr[6] * u;
                    wr[7] = w0[7] * (1.0 - u) + wr[7] * u;
                    let v = out.uv_at(bottom)[1] * (1.0 - u) + out.uv_at(top)[1] * u;
                    verts.push((pos, nm, [p.u(e, right, n), v], wr));
                }
            }
        }
        debug_assert_eq!(first_new as usize + verts.len(), next as usize);
        {
            let block = out.alloc_vertices(verts.len());
            for (k, (m, nm, uv, wr)) in verts.iter().enumerate() {
                block.positions[3 * k..3 * k + 3].copy_from_slice(&m.to_array());
                block.normals[3 * k..3 * k + 3].copy_from_slice(&nm.to_array());
                block.uvs[2 * k..2 * k + 2].copy_from_slice(uv);
                if !block.wind.is_empty() {
                    block.wind[WIND_STRIDE * k..WIND_STRIDE * (k + 1)].copy_from_slice(wr);
                }
            }
        }
        tris.clear();
        // Side patches, as the original's own quads.
        for (p, ring, _) in &sides {
            for row in 0..rows {
                let lo = |e: usize, r: bool| if row == 0 { p.ring(s_first, e, r, n) } else { p.at(row - 1, e, r, n) };
                let hi = |e: usize, r: bool| if row + 1 == rows { p.ring(*ring, e, r, n) } else { p.at(row, e, r, n) };
                for e in 0..h {
                    quad_tris(out, tris, [lo(e, false), lo(e + 1, true), hi(e + 1, true), hi(e, false)]);
                }
            }
        }
        // The patches' end columns (from S up to a ring), bottom to top.
        let column = |p: &Patch, ring: u32, e: usize, right: bool| {
            let mut c = vec![p.ring(s_first, e, right, n)];
            c.extend((0..loops).map(|li| p.at(li, e, right, n)));
            c.push(p.ring(ring, e, right, n));
            c
        };
        let (po, pc) = (&sides[0].0, &sides[1].0);
        // Height parameter of a seam vertex (0 at S, 1 at the rings), as placed above.
        let lift = |k: usize| rise * sin(PI * k as f32 / h as f32);
        let chain = |c: Vec<u32>| -> Vec<(u32, f32)> {
            let last = (c.len() - 1) as f32;
            c.into_iter().enumerate().map(|(i, v)| (v, i as f32 / last)).collect()
        };
        // The crotch, original's side: the seam up to Jo's inner half. Its end quads border the
        // original's patch's end columns (S's front and back up to Jo): zipped strips.
        for k in 0..h {
            let (p0, p1) = quad(o_first, a + k);
            let (m0, m1) = (m_at(k, 0), m_at(k + 1, 0));
            if k == 0 {
                zip(out, tris, &chain(column(po, o_first, h, true)), &[(m1, lift(1)), (p1, 1.0)]);
            } else if k + 1 == h {
                zip(out, tris, &[(m0, lift(k)), (p0, 1.0)], &chain(column(po, o_first, 0, false)));
            } else {
                tris.extend_from_slice(&[m0, m1, p1, m0, p1, p0]);
            }
        }
        // The crotch, clone's side: the clone's columns run the other way.
        for k in 0..h {
            let (q1, q0) = quad(c_first, a + n - k - 1);
            let (m0, m1) = (m_at(k, 1), m_at(k + 1, 1));
            if k == 0 {
                zip(out, tris, &[(m1, lift(1)), (q1, 1.0)], &chain(column(pc, c_first, 0, false)));
            } else if k + 1 == h {
                zip(out, tris, &chain(column(pc, c_first, h, true)), &[(m0, lift(k)), (q0, 1.0)]);
            } else {
                tris.extend_from_slice(&[m1, m0, q0, m1, q0, q1]);
            }
        }
        if well_wound(out, tris)
            && out.unwrap_u(tris, seam_copies(pm.sides), |i, k| pm.seam_twin(i, k).or_else(|| cm.seam_twin(i, k)))
        {
            for c in 0..n {
                claimed[claim(c)] = true;
            }
            bridges.extend_from_slice(tris);
            return true;
        }
    }
    out.truncate_vertices(first_new);
    false
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A fork junction on stem 0 from `t_lo` to `t_hi` (shared with `fork_rows`' tests).
    pub(crate) fn fork(t_lo: f32, t_hi: f32) -> Junction {
        Junction { parent: 0, t_start: 0.2, t_lo, t_hi, foot: 0.1, phi: 0.0, beta: PI, fork: true }
    }

    #[test]
    fn a_forks_rows_stay_open_between_its_two_rings() {
        let mut ts = vec![9.0, 0.0, 0.1, 0.2, 0.25, 0.3, 0.5, 0.9];
        keep_gaps(&[fork(0.15, 0.32), Junction { fork: false, ..fork(0.6, 0.7) }], &mut ts, 1);
        assert_eq!(ts, vec![9.0, 0.0, 0.1, 0.15, 0.32, 0.5, 0.9]);
        // A ring within 1e-4 of an end is replaced by the exact end.
        let mut ts = vec![0.0, 0.15005, 0.2, 0.31995, 0.5];
        keep_gaps(&[fork(0.15, 0.32)], &mut ts, 0);
        assert_eq!(ts, vec![0.0, 0.15, 0.32, 0.5]);
    }
}
