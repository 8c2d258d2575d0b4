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
//! * **Side patches.** The original's own quads from `S`'s outer half to `Jo`'s outer half stay;
//!   the quads of `S`'s inner half are claimed, and `S`'s inner half is joined instead to the
//!   clone's `Jc` columns `a..a+n/2` (the clone's outer half, facing the same way).
//! * **Top patch (the crotch).** `Jo`'s inner half (facing the clone) and `Jc`'s inner half
//!   (facing the original) both come down to a **crotch seam** from `S`'s front column to its
//!   back column: where two tubes diverging at ±α meet, their surfaces cross on an ellipse in the
//!   plane between them, at the split point at the front and back and `R / sin α` up in the
//!   middle. Seam vertex `k` (θ = π k / (n/2)) sits `cos θ` of `S`'s radius toward the front and
//!   `sin θ` of the way up to the midpoint of the facing columns `Jo[a + k]`, `Jc[a − k]`
//!   (times 0.9, or 0.7, 0.97 if a triangle turns the wrong way), with the normal of the two
//!   columns' normals plus the branches' mean direction, and the original's wind record. The
//!   seam's vertices are written twice, with the original's `u` and with the clone's, so each
//!   side's bark stays continuous.
//!
//! The result is edge-manifold by construction: every edge of the opened half row, of `Jo`'s
//! inner half and of `Jc` is used once more, and the seam's ends are `S`'s own front and back
//! vertices, whose column edges the original's outer quads and the side patch already use.
//! Every new triangle must be non-degenerate and wound with its vertex normals
//! ([`super::weld::well_wound`]); else nothing is committed and the clone falls back to a
//! separate tube. The original has no rings between `S` and `Jo` ([`keep_gaps`]), and no other
//! child's footprint may use those rows (the fork's footprint spans the whole way round).

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
    let c = &stems[i];
    let pi = c.parent?;
    let o = &stems[pi as usize];
    if o.level != c.level || sides[pi as usize] % 2 != 0 || sides[pi as usize] < 4 {
        return None;
    }
    let (lo, lc) = (o.length.max(1e-6), c.length.max(1e-6));
    let t_split = c.offset / lo;
    if !(1e-3..0.9).contains(&t_split) {
        return None;
    }
    let (_, tan) = o.sample(t_split);
    let (_, d0) = c.sample(0.0);
    let cos = d0.dot(tan).clamp(-1.0, 1.0);
    if 1.0 - cos * cos >= MAX_SIN * MAX_SIN {
        return None;
    }
    let bound = if o.lobed { surface_bound(p) } else { 1.0 };
    let r0 = o.radius_at(t_split).max(1e-6);
    let step = 0.25 * r0;
    let min_s = r0 + c.radius_at(0.0);
    for k in 1..=400 {
        let s = k as f32 * step;
        let (t_o, t_c) = (t_split + s / lo, s / lc);
        if t_c > MAX_START || t_o > 0.9 {
            return None;
        }
        let gap = (o.sample(t_o).0 - c.sample(t_c).0).length();
        if s >= min_s && gap >= CLEARANCE * (o.radius_at(t_o) * bound + c.radius_at(t_c)) {
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

/// Builds the fork of [`Join::child`] on [`Join::parent`] (see the module notes). On success the
/// inner half of row `S` is marked in `claimed`, the crotch loop stays in `out` and the new
/// triangles go to `bridges`; on failure nothing is changed.
pub(crate) fn join(
    j: &Join,
    claimed: &mut [bool],
    out: &mut MeshBuilder,
    bridges: &mut Vec<u32>,
    tris: &mut Vec<u32>,
) -> bool {
    let (pm, cm) = (j.parent, j.child);
    if pm.sides != cm.sides || pm.sides % 2 != 0 {
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
    if (0..h).any(|k| claimed[claim(a + k)]) {
        return false;
    }
    // The two vertices of the quad at column `c` of a ring (the second may be the seam copy).
    let quad = |first: u32, c: usize| (first + (c % n) as u32, first + (c % n) as u32 + 1);
    // The facing columns: Jo's column a + k and Jc's column a - k.
    let p_at = |k: usize| if k < h { quad(o_first, a + k).0 } else { quad(o_first, a + h - 1).1 };
    let q_at = |k: usize| if k < h { quad(c_first, a + n - k - 1).1 } else { quad(c_first, a + n - h).0 };
    let up = unit_or(fo.tangent + fc.tangent, || fs.tangent);
    // The crotch seam runs from S's front column up between the facing halves and down to S's
    // back column, as the two tubes' intersection does (an ellipse in the plane between them):
    // at angle θ_k = π k / (n/2), `cos θ_k` of S's radius toward the front and `sin θ_k` of the
    // way up to the facing columns' midpoint (times `RISES`, tried in order).
    let (sf, sb) = (s_first + (a % n) as u32, s_first + ((a + h) % n) as u32);
    let front = out.vertex_at(sf).0 - fs.centre;
    let first_new = out.next_index();
    // The seam's vertices twice: with the original's `u` (its side of the crotch) and with the
    // clone's (the other side), so the bark's `u` never jumps inside a triangle.
    let m_at = |k: usize, side: u32| match k {
        0 => sf,
        k if k == h => sb,
        k => first_new + side * (h as u32 - 1) + k as u32 - 1,
    };
    let v_s = out.uv_at(sf)[1];
    for rise in RISES {
        out.truncate_vertices(first_new);
        {
            let mut rows = Vec::with_capacity(2 * (h - 1));
            for side in 0..2 {
                for k in 1..h {
                    let ((pp, pn), (qp, qn)) = (out.vertex_at(p_at(k)), out.vertex_at(q_at(k)));
                    // Both copies sway with the original (a crack would open between two records).
                    let wr = out.wind_at(p_at(k));
                    let theta = PI * k as f32 / h as f32;
                    let up_by = rise * sin(theta);
                    let bottom = fs.centre + front * cos(theta);
                    let m = bottom + ((pp + qp) * 0.5 - bottom) * up_by;
                    let nm = unit_or(pn + qn + up, || up);
                    let [u, v] = out.uv_at(if side == 0 { p_at(k) } else { q_at(k) });
                    rows.push((m, nm, [u, v_s + (v - v_s) * up_by], wr));
                }
            }
            let block = out.alloc_vertices(rows.len());
            for (k, (m, nm, uv, wr)) in rows.iter().enumerate() {
                block.positions[3 * k..3 * k + 3].copy_from_slice(&m.to_array());
                block.normals[3 * k..3 * k + 3].copy_from_slice(&nm.to_array());
                block.uvs[2 * k..2 * k + 2].copy_from_slice(uv);
                if !block.wind.is_empty() {
                    block.wind[WIND_STRIDE * k..WIND_STRIDE * (k + 1)].copy_from_slice(wr);
                }
            }
        }
        tris.clear();
        for k in 0..h {
            // Side patch: S's inner half up to Jc's outer half, as the original's own quads.
            let (s0, s1) = quad(s_first, a + k);
            let (c0, c1) = quad(c_first, a + k);
            tris.extend_from_slice(&[s0, s1, c1, s0, c1, c0]);
            // Top patch, original's side: the crotch seam (below) up to Jo's inner half.
            let (p0, p1) = quad(o_first, a + k);
            tris.extend_from_slice(&[m_at(k, 0), m_at(k + 1, 0), p1, m_at(k, 0), p1, p0]);
            // Top patch, clone's side: the clone's columns run the other way.
            let (q1, q0) = quad(c_first, a + n - k - 1);
            tris.extend_from_slice(&[m_at(k + 1, 1), m_at(k, 1), q0, m_at(k + 1, 1), q0, q1]);
        }
        if well_wound(out, tris) {
            for k in 0..h {
                claimed[claim(a + k)] = true;
            }
            bridges.extend_from_slice(tris);
            return true;
        }
    }
    out.truncate_vertices(first_new);
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fork(t_lo: f32, t_hi: f32) -> Junction {
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
