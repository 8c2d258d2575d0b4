//! Welded junctions (issue #5, item 3): a child stem's tube is connected into its parent's
//! surface instead of being buried in it, so trunk + level 1 + level 2 form one closed,
//! edge-manifold surface.
//!
//! The idea follows the maple page's twigs and ramiforms (reference 003): a junction is a short
//! **Bezier cylinder** (a circle swept along a Bezier spline) from a loop on the parent's surface
//! to the child's first ring. Here it goes in five steps:
//!
//! 1. **Plan** ([`plan`], before any vertex exists). From the skeleton alone: the angle θ between
//!    the child's first direction and the parent's axis, the distance `s_out = (R + r |cos θ|) /
//!    sin θ` along the child at which its tube (radius `r`) has left the parent's (radius `R`,
//!    times the lobe/fluting bound on the trunk), and the child's **junction ring** at
//!    `s_out + collar r / 2`: the child's tube starts there. The **footprint** on the parent is the ellipse of the child's collar (radius
//!    `r' = r (1 + collar (1 - r / R) / 2)`: no flare on an even fork) around the point where the
//!    child's axis pierces the parent, `±r' / sin θ` along the parent and `±asin(r' / R)` around
//!    it, widened to cover the junction ring as seen from the parent (a curved child leans).
//!    The parent gets no full rings across the footprint: only a ring at a footprint's end where
//!    its own nearest ring is more than [`REACH`] footprint lengths away, and one between two
//!    footprints side by side around it that no ring separates (`tube::plan_rings`). Footprints
//!    that would overlap one already accepted on the same parent, leave the parent's tube (below
//!    its own junction ring, across the trunk's bottom cap or near the tip), leave at less than
//!    10° or need a junction ring beyond half the child are not welded. Split clones are planned
//!    first: a smooth Y matters more than a side twig. A split clone within 30° of its original
//!    forks it instead ([`super::fork`]: the original's tube splits in two), when the two
//!    tubes separate within the first half of the clone.
//! 2. **Footprint loop** ([`join`](fn@join), after the parent's and the child's rings are swept). For every
//!    column of the child's junction ring, the line along the child's axis through that column,
//!    widened to the collar's radius `r'`, is followed back to where it leaves the parent's
//!    faceted surface (a guess from the parent's local cylinder, then the quads around it): that
//!    point, with the parent's interpolated normal and wind, is the footprint loop's vertex. Seen
//!    along the child's axis the loop is the widened junction ring itself, a circle.
//! 3. **Hole.** The parent quads under the footprint loop are *claimed* (not emitted); if another
//!    junction holds one of them, the unflared footprint (the branch's own radius) is tried
//!    before giving up. Their boundary is one closed loop of parent vertices, walked
//!    counter-clockwise seen from outside (bottom ring, right column, top ring, left column); the
//!    hole grows by a row or column where the loop comes within a fifth of a quad of its edge,
//!    and by one all round if the first zip fails. The vertices inside the hole stay in the
//!    buffers, unused by any triangle.
//! 4. **Collar** (the blend). Each footprint vertex is joined to its ring vertex by a cubic Bezier
//!    that leaves the parent *tangentially* (first control point along the parent's tangent
//!    plane) and arrives *along the child's axis* (last control point back along it), both handles
//!    0.4 of the chord. `collar_loops(quality)` loops of the child's column count sit on these
//!    curves at even parameters: a collar that flares from the footprint into the branch, C1 with
//!    both surfaces up to the loop spacing. For a split clone the hole spans the side of the
//!    original facing it, so the collar becomes the crotch of a Y (the ramiform's top patch).
//! 5. **Zip**. In the parent's own surface coordinates (around × along, in metres) the hole is a
//!    rectangle and the footprint loop a closed curve inside it. Both are ordered by angle around
//!    the footprint's centre, starting from the hole's vertex of smallest angle. The hole (any
//!    number of vertices) is zipped to the footprint loop: both run counter-clockwise, each step
//!    advances the loop whose next vertex comes first, unless that triangle would turn the wrong
//!    way and the other would not; one triangle per step, so every edge of both loops is used
//!    exactly once (a whole turn of one loop at a single vertex of the other is refused). These
//!    triangles lie on the parent's facets. Quads join the footprint loop, the collar loops and
//!    the junction ring. The footprint loop is the crease between the two: its normal blends the
//!    parent's and the collar's, halfway where that suits every triangle, else leaning to one side.
//! 6. **Bark coordinates.** The footprint loop is written twice at the same places: with the
//!    parent's `u`, `v` for the zip (the parent's bark runs on up to the footprint) and with the
//!    child's for the collar (the child's runs on down to it), so neither texture is squeezed
//!    across a row; the two copies share normals and sway, so the surface stays closed. Zip
//!    triangles that straddle the parent's texture seam get copies of their vertices a whole
//!    turn on ([`MeshBuilder::unwrap_u`](super::MeshBuilder::unwrap_u)).
//!
//! Every new triangle is checked before anything is committed: non-degenerate and wound with its
//! vertex normals. If no footprint point is
//! found, the loops' angles are not monotone around the axis, a claimed quad is already taken, or
//! a check fails, the junction's vertices are dropped and the child is
//! swept again as a separate tube from its parent's axis with a closed base: a **fallback**, counted in [`super::tube::WeldStats`].
//! Deeper levels (3) are always such closed separate tubes.

mod footprint;
mod join;
mod zip;

pub(crate) use join::{join, well_wound, Join, Scratch};

use crate::math::{atan2, unit_or, PI, TAU};
use crate::params::TreeParams;
use crate::skeleton::{Skeleton, Stem, StemKind};

/// Smallest sine of the angle between a child and its parent that is welded (about 20°): below
/// it the child leaves the parent's surface too far along its own length.
const MIN_SIN: f32 = 0.17;
/// The junction ring must sit in the first half of the child.
pub(crate) const MAX_START: f32 = 0.5;
/// How far (in footprint lengths) the parent's nearest ring below and above a footprint may be:
/// the hole spans the rows between them. Farther rings get a ring added at the footprint's end.
pub(crate) const REACH: f32 = 1.0;

/// Where a welded child starts and where it opens its parent (fractions of each stem).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Junction {
    /// The parent stem.
    pub parent: u32,
    /// Fraction of the child where its junction ring (its first ring) sits.
    pub t_start: f32,
    /// Fractions of the parent where the footprint starts and ends.
    pub t_lo: f32,
    /// See `t_lo`.
    pub t_hi: f32,
    /// Radius of the footprint (the collar's base) (m).
    pub foot: f32,
    /// Estimated azimuth of the footprint around the parent (radians; only compared between
    /// footprints close along the same parent).
    pub phi: f32,
    /// Half-width of the footprint around the parent (radians).
    pub beta: f32,
    /// A shallow split clone forked from its original ([`super::fork`]): `t_lo` is the split
    /// ring on the original, `t_hi` the original's next ring, and no other ring lies between.
    pub fork: bool,
}

impl Junction {
    /// True if two footprints on the same parent are closer around it than their half-widths
    /// plus `pad` (radians).
    pub(crate) fn side_by_side(&self, other: &Junction, pad: f32) -> bool {
        let mut d = (self.phi - other.phi).abs() % TAU;
        if d > PI {
            d = TAU - d;
        }
        d < self.beta + other.beta + pad
    }
}

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

/// How far the trunk's surface reaches beyond its nominal radius (lobes, fluting, ripple).
pub(crate) fn surface_bound(p: &TreeParams) -> f32 {
    let lobes = 1.0 + if p.lobes > 0 { p.lobe_depth } else { 0.0 };
    let refine =
        if p.refine_curves > 0 { (p.refine_offset + p.refine_radius) * (1.0 + p.refine_variation) } else { 0.0 };
    lobes * refine.max(1.0) * (1.0 + p.base_ripple)
}

/// `asin(x)` for x in [0, 1) through the portable `atan2`.
fn asin(x: f32) -> f32 {
    atan2(x, (1.0 - x * x).max(0.0).sqrt())
}

/// Step 1 for one stem: its junction, the estimated azimuth of its footprint around the parent
/// and the footprint's half-width in angle.
fn geometry(stems: &[Stem], i: usize, p: &TreeParams) -> Option<Junction> {
    let s = &stems[i];
    let pi = s.parent?;
    let par = &stems[pi as usize];
    let lp = par.length.max(1e-6);
    let tc = (s.offset / lp).clamp(0.0, 1.0);
    let (pc, tan) = par.sample(tc);
    let (_, d0) = s.sample(0.0);
    let cos = d0.dot(tan).clamp(-1.0, 1.0);
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    if sin < MIN_SIN {
        return None;
    }
    let rc = s.radius_at(0.0);
    let r_axis = par.radius_at(tc).max(1e-6);
    // The collar flares less on a child nearly as thick as its parent (none on an even fork).
    let foot = rc * (1.0 + 0.5 * p.weld_collar * (1.0 - rc / r_axis).max(0.0));
    let off_axis = s.base() - pc;
    let t_base = tc + off_axis.dot(tan) / lp;
    let t_mid = t_base + r_axis * cos / sin / lp;
    let half = foot / sin / lp;
    let (mut t_lo, mut t_hi) = (t_mid - half, t_mid + half);
    if t_lo <= 1e-3 || t_hi >= 0.95 {
        return None;
    }
    let bound = if par.lobed { surface_bound(p) } else { 1.0 };
    let r_max = r_axis.max(par.radius_at(t_lo)).max(par.radius_at(t_hi)) * bound * 1.05 + off_axis.length();
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
    let ring_half = (rc * (1.0 - ct * ct).max(0.0).sqrt() + (foot - rc) + 0.25 * rc) / lp;
    t_lo = t_lo.min(ring_mid - ring_half);
    t_hi = t_hi.max(ring_mid + ring_half);
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
pub(crate) fn plan(skeleton: &Skeleton, p: &TreeParams, sides: &[u32]) -> Vec<Option<Junction>> {
    let stems = &skeleton.stems;
    let n = stems.len();
    // A shallow split clone forks its original; the others open a footprint in their parent.
    let geo: Vec<Option<Junction>> = (0..n)
        .map(|i| {
            if is_candidate(stems, i) {
                super::fork::geometry(stems, i, p, sides).or_else(|| geometry(stems, i, p))
            } else {
                None
            }
        })
        .collect();
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
