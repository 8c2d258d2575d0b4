//! # Welded junctions
//!
//! A level-1 or level-2 branch is joined into its parent's surface instead of being buried in it,
//! so trunk + level 1 + level 2 form one closed, edge-manifold surface. The junction is a short
//! **Bezier cylinder** from a loop on the parent to the branch's first ring, after the twigs
//! and ramiforms of *Modeling the Mighty Maple for Web* (ibiblio.org/e-notes).
//!
//! ## Steps
//!
//! 1. **Plan** ([`plan`], from the skeleton alone): the angle θ to the parent's axis, where the
//!    branch's tube leaves the parent (`s_out = (R + r |cos θ|) / sin θ`), its *junction ring*
//!    at `s_out + collar r / 2`, and the ellipse-shaped *footprint* (radius
//!    `r' = r (1 + collar (1 - r / R) / 2)`). Overlapping, too shallow (< 10°) or out-of-tube
//!    footprints are not welded; split clones are planned first, and one within 30° of its
//!    original forks it instead ([`super::fork`]).
//! 2. **Footprint loop** ([`join`](fn@join)): for each column of the junction ring, where the
//!    line along the branch, widened to `r'`, leaves the parent's faceted surface.
//! 3. **Hole**: the parent's quads under the loop are claimed (not emitted); their boundary is
//!    one counter-clockwise loop, grown by a row or column where the footprint comes too close.
//! 4. **Collar**: footprint and ring vertices are joined by cubic Beziers leaving the parent
//!    tangentially and arriving along the branch's axis (handles 0.4 of the chord); for a split
//!    clone the collar becomes the crotch of a Y.
//! 5. **Zip** ([`zip`]): the hole's rim and the footprint loop, both ordered by angle, are zipped
//!    one triangle per step on the parent's own facets.
//! 6. **Bark coordinates**: the footprint loop is written twice (the parent's `u`, `v` for the
//!    zip, the branch's for the collar; same normals and sway), and triangles across a texture
//!    seam get vertex copies a turn on ([`MeshBuilder::unwrap_u`](super::MeshBuilder::unwrap_u)).
//!
//! ## Safety
//!
//! Every new triangle is checked before anything is committed (not degenerate, wound with its
//! vertex normals). When a footprint point is missing, the loops are not monotone, a quad is
//! taken or a check fails, the junction's vertices are dropped and the branch is swept as a
//! separate closed tube: a **fallback**, counted in [`super::tube::WeldStats`]. Level-3 stems are
//! always separate closed tubes.

mod crossing;
mod footprint;
mod join;
mod zip;

use super::junction::surface_bound;
pub(crate) use super::junction::{Join, Junction, MAX_START};
pub(crate) use footprint::Scratch;
pub(crate) use join::join;

use crate::math::{atan2, max, unit_or, TAU};
use crate::params::MeshParams;
use crate::skeleton::{Skeleton, Stem, StemKind};

/// Smallest sine of the angle between a child and its parent that is welded (about 20°): below
/// it the child leaves the parent's surface too far along its own length.
const MIN_SIN: f32 = 0.17;
/// How far (in footprint lengths) the parent's nearest ring below and above a footprint may be:
/// the hole spans the rows between them. Farther rings get a ring added at the footprint's end.
pub(crate) const REACH: f32 = 1.0;

/// Fewest stems whose junction geometry [`plan`] computes on every thread.
const PARALLEL_PLAN: usize = 2048;

/// True for the stems the junctions weld: levels 1 and 2 on their parents and split clones up to
/// level 2 (a clone has its original's level).
pub(crate) fn is_candidate(stems: &[Stem], i: usize) -> bool {
    let s = &stems[i];
    s.level <= 2 && s.parent.is_some_and(|p| stems[p as usize].level <= s.level)
}

/// Number of collar loops between the footprint loop and the child's junction ring.
pub(crate) fn collar_loops(quality: f32) -> usize {
    (quality.round() as usize).clamp(1, 3)
}

/// `i % n` for `i < 2 n`: a ring's index one turn on brought back, without the division a
/// remainder costs (wasm's `rem_u` is one, in the junctions' loops over every column).
#[inline]
fn wrap(i: usize, n: usize) -> usize {
    debug_assert!(i < 2 * n);
    if i >= n {
        i - n
    } else {
        i
    }
}

/// `asin(x)` for x in [0, 1) through the portable `atan2`.
fn asin(x: f32) -> f32 {
    atan2(x, (1.0 - x * x).max(0.0).sqrt())
}

/// Step 1 for one stem: its junction, the estimated azimuth of its footprint around the parent
/// and the footprint's half-width in angle.
fn geometry(stems: &[Stem], i: usize, p: &MeshParams) -> Option<Junction> {
    let s = &stems[i];
    let pi = s.parent?;
    let par = &stems[pi as usize];
    let lp = par.length.max(1e-6);
    let tc = (s.offset / lp).clamp(0.0, 1.0);
    let (pc, tan) = par.sample(tc);
    let (_, d0) = s.sample(0.0);
    let cos = d0.dot(tan).clamp(-1.0, 1.0);
    let sin = max(1.0 - cos * cos, 0.0).sqrt();
    if sin < MIN_SIN {
        return None;
    }
    let rc = s.radius_at(0.0);
    let r_axis = max(par.radius_at(tc), 1e-6);
    // The collar flares less on a child nearly as thick as its parent (none on an even fork).
    let foot = rc * (1.0 + 0.5 * p.weld_collar * max(1.0 - rc / r_axis, 0.0));
    let off_axis = s.base() - pc;
    let t_base = tc + off_axis.dot(tan) / lp;
    let t_mid = t_base + r_axis * cos / sin / lp;
    let half = foot / sin / lp;
    let (mut t_lo, mut t_hi) = (t_mid - half, t_mid + half);
    if t_lo <= 1e-3 || t_hi >= 0.95 {
        return None;
    }
    let bound = if par.lobed { surface_bound(p) } else { 1.0 };
    let r_max = max(max(r_axis, par.radius_at(t_lo)), par.radius_at(t_hi)) * bound * 1.05 + off_axis.length();
    let s_out = (r_max + rc * cos.abs()) / sin;
    let t_start = (s_out + 0.5 * p.weld_collar * rc) / s.length.max(1e-6);
    if t_start > MAX_START {
        return None;
    }
    // The hole must also cover the junction ring seen from the parent (a curved child leans
    // away from its first direction), with the collar's margin beyond it.
    let (jc, jt) = s.sample(t_start);
    let ring_mid = tc + (jc - pc).dot(tan) / lp;
    let ct = jt.dot(tan);
    let ring_half = (rc * max(1.0 - ct * ct, 0.0).sqrt() + (foot - rc) + 0.25 * rc) / lp;
    t_lo = t_lo.min(ring_mid - ring_half);
    t_hi = max(t_hi, ring_mid + ring_half);
    if t_lo <= 1e-3 || t_hi >= 0.95 {
        return None;
    }
    let beta = asin((foot / r_axis).min(0.9));
    // Azimuth in a frame at the footprint without transport: only compared between footprints
    // close along the same parent, where the transported frame barely turns.
    let (c, t) = par.sample(t_mid);
    let n = unit_or(par.base_normal - t * par.base_normal.dot(t), || t.any_orthonormal_vector());
    let w = s.point(t_start) - c;
    let phi = atan2(w.dot(t.cross(n)), w.dot(n));
    Some(Junction { parent: pi, t_start, t_lo, t_hi, foot, phi, beta, fork: false })
}

/// Step 1: the junction of every stem that can be welded (None for the others).
pub(crate) fn plan(skeleton: &Skeleton, p: &MeshParams, sides: &[u32]) -> Vec<Option<Junction>> {
    let stems = &skeleton.stems;
    let n = stems.len();
    // A shallow split clone forks its original; the others open a footprint in their parent.
    // Each stem's geometry reads the skeleton alone: computed in ranges on every thread (a
    // willow's thousands of clones each search up to 100 steps for where they separate).
    let of = |i: usize| {
        if is_candidate(stems, i) {
            super::fork::geometry(stems, i, p, sides).or_else(|| geometry(stems, i, p))
        } else {
            None
        }
    };
    let threads = if n >= PARALLEL_PLAN { crate::par::threads() } else { 1 };
    let parts = crate::par::ranges(n, threads * 8);
    let geo: Vec<Option<Junction>> = crate::par::map(parts, threads, |r| r.map(of).collect::<Vec<_>>()).concat();
    let mut out = vec![None; n];
    // Accepted footprints per parent as linked lists: (junction, next).
    let mut head = vec![u32::MAX; n];
    let mut feet: Vec<(Junction, u32)> = Vec::new();
    for clones in [true, false] {
        for i in 0..n {
            let Some(j) = geo[i] else { continue };
            let parent = j.parent as usize;
            if (stems[i].kind == StemKind::SplitClone) != clones {
                continue;
            }
            // The parent's tube starts at its own junction ring if it gets one.
            let parent_start = geo[parent].map_or(0.0, |g| g.t_start);
            if j.t_lo <= parent_start + 1e-3 {
                continue;
            }
            let pad = TAU / sides[parent] as f32;
            // The first accepted footprint on the parent that `j` overlaps.
            let blocker = |j: &Junction| {
                let mut k = head[parent];
                while k != u32::MAX {
                    let (f, next) = &feet[k as usize];
                    if j.t_lo < f.t_hi && f.t_lo < j.t_hi && j.side_by_side(f, pad) {
                        return Some(*f);
                    }
                    k = *next;
                }
                None
            };
            // A fork blocked by another fork (two clones leaving at one point) forks one step
            // up, at the other fork's upper ring; once more for a third clone.
            let mut j = Some(j);
            for _ in 0..3 {
                let Some(f) = j.and_then(|j| blocker(&j)) else { break };
                j = j
                    .filter(|j| j.fork && f.fork)
                    .and_then(|_| super::fork::geometry_from(stems, i, p, sides, Some(f.t_hi)));
            }
            if let Some(j) = j.filter(|j| blocker(j).is_none()) {
                feet.push((j, head[parent]));
                head[parent] = (feet.len() - 1) as u32;
                out[i] = Some(j);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn wrap_is_the_remainder_below_two_turns() {
        for n in 1..70 {
            for i in 0..2 * n {
                assert_eq!(super::wrap(i, n), i % n);
            }
        }
    }
}
