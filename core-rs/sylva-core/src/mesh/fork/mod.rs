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
//!   [`super::fork_rows::rows`] rows of quads: per column a cubic Bezier from `S` (leaving along
//!   the original's axis, so the trunk below flows on without a kink; toward the front and back
//!   of the clone's patch leaning with the clone) to the ring (arriving along its branch's
//!   axis), handles 0.4 of the chord, loops at even parameters, normals across the loops.
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
//!   quads meet the side patches' end columns and are zipped strips (the steps: [`mod@join`]).
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

mod join;

pub(crate) use join::join;

use super::tube::Frame;
use super::weld::{surface_bound, Junction, MAX_START};
use super::MeshBuilder;
use crate::math::PI;
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

/// Vertices [`join()`] adds at most for a fork of `sides` sides with `rows` side-patch rows
/// ([`super::fork_rows`]): two side patches of `rows - 1` loops of `sides / 2 + 2` vertices (one
/// a seam copy) and the crotch seam's inner vertices, twice.
pub(crate) fn vertices(sides: u32, rows: usize) -> usize {
    let h = sides as usize / 2;
    2 * (rows - 1) * (h + 2) + 2 * (h - 1) + seam_copies(sides)
}

/// Copies [`join()`] may add where its triangles cross the original's bark seam
/// ([`MeshBuilder::unwrap_u`]).
fn seam_copies(sides: u32) -> usize {
    2 * (sides as usize + 1)
}

/// Indices [`join()`] adds at most: the side patches' quads and the crotch's row of quads (whose
/// end quads become fans of `rows + 1` triangles).
pub(crate) fn indices(sides: u32, rows: usize) -> usize {
    let h = sides as usize / 2;
    3 * (2 * 2 * h * rows + 2 * 2 * h + 4 * rows)
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
