//! # Smooth Y forks
//!
//! A split clone that leaves its original below about 30° runs inside it for many radii, so it has
//! no footprint ([`super::weld`]); the original's tube splits in two instead. The shape is the
//! **ramiform** of *Modeling the Mighty Maple for Web* (ibiblio.org/e-notes) (two twig-like side
//! patches and a smooth top part), a C0 simplification of Bloomenthal's node.
//!
//! ## Rings and patches
//!
//! `S` is the original's ring at the split, `Jo` its next ring (where the tubes have separated:
//! [`geometry`]), `Jc` the clone's first ring.
//!
//! * **Frames**: both tubes have the same even number of sides and the clone starts from `S`'s
//!   frame and `v`, so column `k` points the same way in every ring and the bark runs on unbroken.
//! * **Halves**: `S` is cut by the plane through the original's axis across the clone's direction
//!   into an inner half (facing the clone) and an outer half.
//! * **Side patches**: `S`'s outer half rises to `Jo`, its inner half to the clone's facing
//!   columns of `Jc`, through [`super::fork_rows::rows`] rows of cubic Bezier columns (leaving
//!   along the original's axis, arriving along the branch's; handles 0.4 of the chord).
//! * **Crotch**: the inner halves of `Jo` and `Jc` come down to a seam on the ellipse where the
//!   two tubes cross (from `S`'s front column to its back, `R / sin α` up in the middle), written
//!   twice with each side's `u`; the steps are in [`mod@join`].
//!
//! ## Safety
//!
//! Edge-manifold by construction (every edge of `S`, `Jo` and `Jc` is used once more, the seam's
//! by both crotch rows). Every new triangle must be non-degenerate and wound with its normals
//! ([`super::junction::well_wound`]), else the clone falls back to a separate tube. The original
//! keeps no rings between `S` and `Jo` ([`keep_gaps`]) and no other footprint may use those rows;
//! triangles across the texture seam get vertex copies a turn on ([`MeshBuilder::unwrap_u`]).

mod clear;
mod join;

pub(crate) use join::{join, Scratch};

use super::junction::{surface_bound, Junction, MAX_START};
use super::stem::{Frame, StemMesh};
use super::MeshBuilder;
use crate::math::PI;
use crate::params::MeshParams;
use crate::skeleton::Stem;
use glam::Vec3;
use std::cell::Cell;

/// Largest sine of the clone's angle to its original that makes a fork (30°); steeper clones
/// are welded into the original's side ([`super::weld`]).
const MAX_SIN: f32 = 0.5;
/// The junction rings must be apart by this factor times the sum of the two radii.
const CLEARANCE: f32 = 1.1;
/// Steps of the search for the rings where the tubes have separated, and how many of them the
/// search skips at a time before looking at each.
const STEPS: usize = 400;
const COARSE: usize = 4;
/// How much further than the clone itself (radians, 12°) the side patch of a clone forking
/// one step up may lean before it shows as a knee; such a clone stays a separate tube.
const MAX_KNEE: f32 = 0.21;
/// How far up from the split toward the facing columns' midpoint the crotch seam rises in the
/// middle, tried in order until every triangle is well wound.
const RISES: [f32; 3] = [0.9, 0.7, 0.97];

/// The fork junction of split clone `i` (same level as its parent, the original), or None when
/// it is no shallow fork or its tubes do not separate soon enough: `t_lo` is the split point on
/// the original (ring `S`), `t_hi` the original's ring `Jo`, `t_start` the clone's ring `Jc`;
/// both rings sit the same distance from the split along their stems, the first distance (in
/// quarter radii) at which their centres are [`CLEARANCE`] times their radii apart. `sides` are
/// the stems' numbers of sides: the original's must be even.
pub(crate) fn geometry(stems: &[Stem], i: usize, p: &MeshParams, sides: &[u32]) -> Option<Junction> {
    geometry_from(stems, i, p, sides, None)
}

/// [`geometry`] with the split moved up the original to `from` (its `t`; None: the clone's own
/// base). A second clone that leaves at the same point as a fork forks one step up, at that
/// fork's ring `Jo` (a fork's rows are its own): the clone then seems to leave a little higher,
/// where it has already drawn a little away, rather than becoming a separate tube; unless it
/// has drawn so far away that its side patch would lean more than [`MAX_KNEE`] past the clone
/// (a knee), when it is a separate tube after all (None).
pub(crate) fn geometry_from(
    stems: &[Stem],
    i: usize,
    p: &MeshParams,
    sides: &[u32],
    from: Option<f32>,
) -> Option<Junction> {
    search(stems, i, p, sides, from, true, &mut 0)
}

/// [`geometry_from`], skipping the steps that certainly do not separate ([`clear`]) or not;
/// counts the steps evaluated into `probes`.
fn search(
    stems: &[Stem],
    i: usize,
    p: &MeshParams,
    sides: &[u32],
    from: Option<f32>,
    skip: bool,
    probes: &mut usize,
) -> Option<Junction> {
    let c = &stems[i];
    let pi = c.parent?;
    let o = &stems[pi as usize];
    if o.level != c.level || sides[pi as usize] % 2 != 0 || sides[pi as usize] < 4 {
        return None;
    }
    let lo = o.length.max(1e-6);
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
    let lc = c.length.max(1e-6);
    let walk =
        clear::Search { o, c, lo, lc, t_split, ahead, step, bound, min_s, max_start: MAX_START, memo: Cell::new(None) };
    let (mut on_o, mut on_c) = (o.points(), c.points());
    // The gap between the centres at step `k` and whether it separates the tubes; None past
    // the search's end.
    let mut probe = |k: usize| {
        *probes += 1;
        let (s, t_o, t_c) = walk.at_step(k);
        if walk.past_end(t_o, t_c) {
            return None;
        }
        let gap = (on_o.at(t_o) - on_c.at(t_c)).length();
        Some((gap, s >= min_s && gap >= walk.clearance(t_o, t_c)))
    };
    // Every COARSE-th step first (a radius apart); the steps before one that separates (or ends
    // the search) are then tried in order for the first that does. A separation that does not
    // last to the next coarse step (the tubes touch again within a radius) is not taken; on
    // every preset the forks are the ones a step-by-step search finds (same golden hashes).
    // Coarse steps that certainly do not separate are skipped ([`clear`]).
    let mut k = 0;
    while k < STEPS {
        let hi = (k + COARSE).min(STEPS);
        if let Some((gap, false)) = probe(hi) {
            k = if skip { walk.clear_until(hi, gap) } else { hi };
            continue;
        }
        for j in k + 1..=hi {
            match probe(j) {
                None => return None,
                Some((_, false)) => {}
                Some((_, true)) => {
                    let (s, t_o, t_c) = walk.at_step(j);
                    // A clone forking one step up has drawn away already: its side patch runs
                    // from the original's ring out to the clone, leaning further than the clone
                    // itself. Past MAX_KNEE more it shows as a knee; it stays a separate tube.
                    if ahead > 0.0 {
                        let (base, _) = o.sample(t_split);
                        let w = on_c.at(t_c) - base;
                        let out = (w - tan * w.dot(tan)).length();
                        let lean = crate::math::atan2(out, s.max(1e-6));
                        if lean - crate::math::acos(cos) > MAX_KNEE {
                            return None;
                        }
                    }
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
    parent: &StemMesh,
    ts: &[f32],
    frames: &[Frame],
    out: &MeshBuilder,
) -> Option<(Vec3, f32)> {
    let rs = split_ring(j, parent, ts)?;
    let v = out.uv_at(parent.first + rs as u32 * (parent.sides + 1))[1];
    Some((frames[parent.ring0 + rs].normal, v))
}

/// Index (within the original's tube) of ring `S`, followed by ring `Jo`.
fn split_ring(j: &Junction, pm: &StemMesh, ts: &[f32]) -> Option<usize> {
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
#[allow(clippy::disallowed_methods, reason = "the tests' own measures, not output bytes")]
pub(crate) mod tests {
    use super::*;

    /// A fork junction on stem 0 from `t_lo` to `t_hi` (shared with `fork_rows`' tests).
    pub(crate) fn fork(t_lo: f32, t_hi: f32) -> Junction {
        Junction { parent: 0, t_start: 0.2, t_lo, t_hi, foot: 0.1, phi: 0.0, beta: PI, fork: true }
    }

    /// How much further than the clone itself the fork of clone `i` leans from its split
    /// ring `S` to the clone's ring `Jc` (radians), and whether it forks above its own base.
    fn knee(stems: &[Stem], i: usize, j: &Junction) -> (f32, bool) {
        let (c, o) = (&stems[i], &stems[j.parent as usize]);
        let t_base = c.offset / o.length;
        let (_, tan) = o.sample(t_base);
        let (base, _) = o.sample(j.t_lo);
        let w = c.sample(j.t_start).0 - base;
        let out = (w - tan * w.dot(tan)).length();
        let s = (j.t_hi - j.t_lo) * o.length;
        let own = c.sample(0.0).1.dot(tan).clamp(-1.0, 1.0).acos();
        (out.atan2(s) - own, j.t_lo > t_base + 1e-4)
    }

    #[test]
    fn a_clone_forking_one_step_up_leans_no_further_than_a_knee_allows() {
        // Issue #17's knee: CA Black Oak's trunk splits three ways at one point; the second
        // clone forked one step up, where it had drawn far away, and its side patch ran out
        // sideways (about 30° past the clone) before turning up along it.
        for levels in [1.0, 4.0] {
            let mut p = crate::presets::find("ca_black_oak").unwrap().params().unwrap();
            p.set("levels", levels).unwrap();
            p.set("l0_curve_v", 0.0).unwrap();
            let sk = crate::skeleton::build(&p.skeleton).unwrap();
            let sides = vec![16; sk.stems.len()];
            let plan = super::super::weld::plan(&sk, &p.mesh, &sides);
            let mut shifted = 0;
            for (i, j) in plan.iter().enumerate() {
                let Some(j) = j.filter(|j| j.fork) else { continue };
                let (excess, up) = knee(&sk.stems, i, &j);
                if up {
                    shifted += 1;
                    assert!(
                        excess <= MAX_KNEE + 1e-4,
                        "levels {levels}: clone {i} leans {}° past itself",
                        excess.to_degrees()
                    );
                }
            }
            // The knee of the issue, unchecked: the clone that forked one step up.
            let mut rejected = 0;
            for (i, j) in plan.iter().enumerate() {
                let Some(f) = j.filter(|j| j.fork) else { continue };
                for k in (0..sk.stems.len()).filter(|&k| k != i && plan[k].is_none()) {
                    let same_split =
                        sk.stems[k].parent == sk.stems[i].parent && sk.stems[k].offset == sk.stems[i].offset;
                    if same_split && geometry_from(&sk.stems, k, &p.mesh, &sides, Some(f.t_hi)).is_none() {
                        rejected += 1;
                    }
                }
            }
            assert!(shifted + rejected > 0, "levels {levels}: the tree has clones sharing a split");
            if levels == 1.0 {
                assert!(rejected > 0, "the trunk's knee is now a separate tube");
            }
        }
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

#[cfg(test)]
mod search_tests {
    use super::*;

    /// The skipping search finds the same fork as the step-by-step one for every split clone of
    /// every preset (three seeds, two ages), from its own base and one step up.
    #[test]
    fn skipping_finds_the_same_forks() {
        let (mut clones, mut forks) = (0, 0);
        let (mut plain_probes, mut probes) = (0, 0);
        for preset in crate::presets::PRESETS {
            for (seed, age) in [(None, None), (Some(7.0), None), (Some(12345.0), Some(0.6))] {
                let mut params = preset.params().expect("preset");
                if let Some(seed) = seed {
                    params.set("seed", seed).expect("seed");
                }
                if let Some(f) = age {
                    let years = params.get("age").expect("age") * f;
                    params.set("age", years.round().max(1.0)).expect("age");
                }
                let Ok(sk) = crate::skeleton::build(&params.skeleton) else { continue };
                let sides = vec![8u32; sk.stems.len()];
                for i in 0..sk.stems.len() {
                    if sk.stems[i].kind != crate::skeleton::StemKind::SplitClone {
                        continue;
                    }
                    clones += 1;
                    let mut both = |from: Option<f32>| {
                        let plain = search(&sk.stems, i, &params.mesh, &sides, from, false, &mut plain_probes);
                        let skipping = search(&sk.stems, i, &params.mesh, &sides, from, true, &mut probes);
                        assert_eq!(skipping, plain, "{} stem {i} from {from:?}", preset.name);
                        plain
                    };
                    if let Some(j) = both(None) {
                        forks += 1;
                        both(Some(j.t_hi));
                    }
                }
            }
        }
        assert!(clones > 10_000 && forks > 1_000, "{clones} clones, {forks} forks");
        // The shortcut is taken: a willow's clones run along their originals for many steps.
        assert!(probes * 4 < plain_probes, "{probes} steps evaluated skipping, {plain_probes} without");
        eprintln!("{clones} clones, {forks} forks; {probes} steps evaluated skipping, {plain_probes} without");
    }
}
