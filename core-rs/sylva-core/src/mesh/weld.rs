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
//! 2. **Footprint loop** ([`join`], after the parent's and the child's rings are swept). For every
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
//!    turn on ([`MeshBuilder::unwrap_u`]).
//!
//! Every new triangle is checked before anything is committed: non-degenerate and wound with its
//! vertex normals. If no footprint point is
//! found, the loops' angles are not monotone around the axis, a claimed quad is already taken, or
//! a check fails, the junction's vertices are dropped and the child is
//! swept again as a separate tube from its parent's axis with a closed base: a **fallback**, counted in [`super::tube::WeldStats`].
//! Deeper levels (3) are always such closed separate tubes.

use super::tube::{Frame, StemMesh, StemWind};
use super::{MeshBuilder, WIND_STRIDE};
use crate::math::{atan2, unit_or, PI, TAU};
use crate::params::TreeParams;
use crate::skeleton::{Skeleton, Stem};
use glam::{Vec2, Vec3};

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
    let w = s.sample(t_start).0 - c;
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
            if (stems[i].level == stems[parent].level) != clones {
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

/// Everything [`join`] reads.
pub(crate) struct Join<'a> {
    /// The planned junction.
    pub junction: &'a Junction,
    /// The parent's swept tube.
    pub parent: &'a StemMesh,
    /// The parent stem.
    pub parent_stem: &'a Stem,
    /// The child's swept tube (ring 0 is its junction ring).
    pub child: &'a StemMesh,
    /// The child stem.
    pub child_stem: &'a Stem,
    /// Ring parameters of all stems.
    pub ts: &'a [f32],
    /// Ring frames of all stems.
    pub frames: &'a [Frame],
    /// The child's wind constants.
    pub wind: &'a StemWind,
    /// Collar loops between hole and junction ring.
    pub loops: usize,
}

/// Reused buffers of [`join`].
#[derive(Default)]
pub(crate) struct Scratch {
    hole: Vec<u32>,
    angle: Vec<f32>,
    ring: Vec<f32>,
    pos: Vec<Vec3>,
    along: Vec<Vec3>,
    chord: Vec<f32>,
    pub(crate) tris: Vec<u32>,
    /// The footprint loop: position, normal and wind per column of the junction ring.
    foot: Vec<(Vec3, Vec3, [f32; WIND_STRIDE], [f32; 2])>,
    /// The parent quad (row, column) under each footprint point, and where in it.
    cells: Vec<(usize, i32, Vec2)>,
    /// The collar's own normal at each footprint point.
    collar_n: Vec<Vec3>,
    /// The hole's vertices in the parent's surface coordinates.
    flat: Vec<Vec2>,
    /// The footprint loop in the parent's surface coordinates.
    foot_flat: Vec<Vec2>,
}

/// Steps 2 to 4: open the parent, add the collar loops and zip them in. On success the hole's
/// quads are marked in `claimed`, the new vertices stay in `out` and the new triangles go to
/// `bridges`; on failure nothing is changed.
pub(crate) fn join(
    j: &Join,
    claimed: &mut [bool],
    out: &mut MeshBuilder,
    bridges: &mut Vec<u32>,
    sc: &mut Scratch,
) -> bool {
    let (pm, jn) = (j.parent, j.junction);
    let pts = &j.ts[pm.ring0..pm.ring0 + pm.rings as usize];
    // The rows between the parent's nearest rings below and above the footprint (`plan_rings`
    // put them within REACH footprint lengths of it).
    let reach = REACH * (jn.t_hi - jn.t_lo) + 1e-5;
    let above = pts.partition_point(|&x| x <= jn.t_lo);
    let rb = pts.partition_point(|&x| x < jn.t_hi);
    if above == 0 || rb >= pts.len() {
        return false; // the footprint is not on the parent's tube
    }
    let ra = above - 1;
    if jn.t_lo - pts[ra] > reach || pts[rb] - jn.t_hi > reach {
        return false;
    }
    // Columns around the child's azimuth, in the parent's transported frame at mid-footprint.
    let f = j.frames[pm.ring0 + (ra + rb) / 2];
    let t_mid = pts[(ra + rb) / 2];
    let jf = j.frames[j.child.ring0];
    let mut w = jf.centre - f.centre;
    w -= f.tangent * w.dot(f.tangent);
    let phi = atan2(w.dot(f.tangent.cross(f.normal)), w.dot(f.normal));
    let r_mid = j.parent_stem.radius_at(pts[(ra + rb) / 2]).max(1e-6);
    let rc = j.child_stem.radius_at(jn.t_start).max(1e-6);
    let beta = asin((jn.foot / r_mid).min(0.9)).max(atan2(jn.foot + 0.25 * rc, w.length()));
    let sides = pm.sides as i32;
    let dcol = TAU / sides as f32;
    let (ja, jb) = {
        let ja = ((phi - beta) / dcol).floor() as i32;
        (ja, (((phi + beta) / dcol).ceil() as i32).max(ja + 1))
    };
    // The footprint loop: for every column of the junction ring, the point where the line
    // along the child's axis through that column, widened to the collar's radius, leaves the
    // parent's surface (less widened where that line misses the parent: a child about as thick
    // as its parent). Normal and wind are interpolated from the parent there. The estimate
    // above is searched with a margin of two rows and two columns around it.
    let stride = pm.sides + 1;
    let (wa, wb) = (ra.saturating_sub(2), (rb + 2).min(pts.len() - 1));
    let (ca, cb) = if jb - ja + 4 < sides { (ja - 2, jb + 2) } else { (ja, jb) };
    let nr = j.child.sides as usize;
    let widen = jn.foot / rc;
    let (mut ra, mut rb, mut ja, mut jb) = (usize::MAX, 0, i32::MAX, i32::MIN);
    let r_len = j.parent_stem.length.max(1e-6);
    // The first hit (largest s) of the line q + s d with the quads in rows × cols.
    let search = |q: Vec3, rows: std::ops::Range<usize>, cols: std::ops::Range<i32>| {
        let mut best: Option<(f32, [u32; 3], Vec3, usize, i32, Vec2)> = None;
        for r in rows {
            for c in cols.clone() {
                // The quad as `emit` writes it (the seam's duplicate column after the last).
                let a = pm.first + r as u32 * stride + c.rem_euclid(sides) as u32;
                let (b, c2, d) = (a + 1, a + 1 + stride, a + stride);
                for (half, t) in [[a, b, c2], [a, c2, d]].into_iter().enumerate() {
                    if let Some((s, w)) = line_hit(q, jf.tangent, t.map(|v| out.vertex_at(v).0)) {
                        if best.is_none_or(|(s0, ..)| s > s0) {
                            // Where in the quad: across its columns, along its rows (0..1).
                            let uv = if half == 0 { Vec2::new(w.y + w.z, w.z) } else { Vec2::new(w.y, w.y + w.z) };
                            best = Some((s, t, w, r, c, uv));
                        }
                    }
                }
            }
        }
        best
    };
    // Where the line leaves the parent's local cylinder: the quad to look at first.
    let guess = |q: Vec3| {
        let (t_ax, d) = (f.tangent, jf.tangent);
        let o = q - f.centre;
        let (o, d) = (o - t_ax * o.dot(t_ax), d - t_ax * d.dot(t_ax));
        let (a, b, c) = (d.dot(d), 2.0 * o.dot(d), o.dot(o) - r_mid * r_mid);
        let disc = b * b - 4.0 * a * c;
        if a < 1e-12 || disc < 0.0 {
            return None;
        }
        let x = q + jf.tangent * ((-b + disc.sqrt()) / (2.0 * a)) - f.centre;
        let t = t_mid + x.dot(t_ax) / r_len;
        let r = pts.partition_point(|&p| p <= t).saturating_sub(1);
        let c = (atan2(x.dot(t_ax.cross(f.normal)), x.dot(f.normal)) / dcol).floor() as i32;
        Some((r, c))
    };
    // From that quad, step across the grid toward the crossing (a few quads at most).
    let walk = |q: Vec3, mut r: usize, mut c: i32| {
        for _ in 0..6 {
            if r < wa || r >= wb || c < ca || c >= cb {
                return None;
            }
            let a = pm.first + r as u32 * stride + c.rem_euclid(sides) as u32;
            let (b, c2, d) = (a + 1, a + 1 + stride, a + stride);
            let (pa, pb, pc, pd) = (out.vertex_at(a).0, out.vertex_at(b).0, out.vertex_at(c2).0, out.vertex_at(d).0);
            let (s, u, v) = line_plane(q, jf.tangent, [pa, pb, pc])?;
            if u >= 0.0 && v >= 0.0 && u + v <= 1.0 {
                return Some((s, [a, b, c2], Vec3::new(1.0 - u - v, u, v), r, c, Vec2::new(u + v, v)));
            }
            if let Some((s, u2, v2)) = line_plane(q, jf.tangent, [pa, pc, pd]) {
                if u2 >= 0.0 && v2 >= 0.0 && u2 + v2 <= 1.0 {
                    return Some((s, [a, c2, d], Vec3::new(1.0 - u2 - v2, u2, v2), r, c, Vec2::new(u2, u2 + v2)));
                }
            }
            // Across the columns x = u + v, along the rows y = v, in the first half's plane.
            let (x, y) = (u + v, v);
            let dr = if y < 0.0 { -1 } else { i32::from(y > 1.0) };
            let dc = if x < 0.0 { -1 } else { i32::from(x > 1.0) };
            if (dr, dc) == (0, 0) || (dr < 0 && r == 0) {
                return None;
            }
            (r, c) = ((r as i64 + i64::from(dr)) as usize, c + dc);
        }
        None
    };
    let claim = |r: usize, c: i32| pm.claim + r * pm.sides as usize + c.rem_euclid(sides) as usize;
    let free = |claimed: &[bool], rows: std::ops::Range<usize>, cols: std::ops::Range<i32>| {
        rows.clone().all(|r| cols.clone().all(|c| !claimed[claim(r, c)]))
    };
    // Where the flared footprint's quads are already another junction's, the footprint of the
    // branch itself (no flare) may still fit.
    for first in [widen, 1.0] {
        (ra, rb, ja, jb) = (usize::MAX, 0, i32::MAX, i32::MIN);
        sc.foot.clear();
        sc.cells.clear();
        for m in 0..nr {
            let p = out.vertex_at(j.child.first + m as u32).0;
            let mut best = None;
            for w in [first, 1.0, 0.75, 0.5] {
                let q = jf.centre + (p - jf.centre) * w;
                if let Some((r, c)) = guess(q) {
                    best = walk(q, r, c);
                }
                if best.is_none() {
                    best = search(q, wa..wb, ca..cb);
                }
                if best.is_some() {
                    break;
                }
            }
            let Some((_, t, bary, r, c, uv)) = best else { return false };
            sc.cells.push((r, c, uv));
            (ra, rb, ja, jb) = (ra.min(r), rb.max(r + 1), ja.min(c), jb.max(c + 1));
            // A little inside the triangle: never on a parent vertex or edge.
            let bary = bary * 0.98 + Vec3::splat(0.02 / 3.0);
            let mix = |x: Vec3, y: Vec3, z: Vec3| x * bary.x + y * bary.y + z * bary.z;
            let ((pa, na), (pb, nb), (pc, nc)) = (out.vertex_at(t[0]), out.vertex_at(t[1]), out.vertex_at(t[2]));
            let n = unit_or(mix(na, nb, nc), || jf.tangent);
            // The parent's pivot, level and phase as they are; stiffness, distance, radius and uv
            // interpolated: the footprint loop is part of the parent's surface.
            let (wa, wb, wc) = (out.wind_at(t[0]), out.wind_at(t[1]), out.wind_at(t[2]));
            let wind: [f32; WIND_STRIDE] =
                std::array::from_fn(|k| if k < 5 { wa[k] } else { wa[k] * bary.x + wb[k] * bary.y + wc[k] * bary.z });
            let (ua, ub, uc) = (out.uv_at(t[0]), out.uv_at(t[1]), out.uv_at(t[2]));
            let uv = [0, 1].map(|k| ua[k] * bary.x + ub[k] * bary.y + uc[k] * bary.z);
            sc.foot.push((mix(pa, pb, pc), n, wind, uv));
        }

        if free(claimed, ra..rb, ja..jb) {
            break;
        }
        if first <= 1.0 {
            return false;
        }
    }
    // Collar curves, one per column: from the footprint loop (loop 0) to the junction ring.
    let loops = j.loops + 1;
    sc.pos.clear();
    sc.pos.resize(loops * nr, Vec3::ZERO);
    sc.along.clear();
    sc.along.resize(loops * nr, Vec3::ZERO);
    sc.chord.clear();
    for m in 0..nr {
        let (p0, n0, ..) = sc.foot[m];
        let p3 = out.vertex_at(j.child.first + m as u32).0;
        let chord = p3 - p0;
        let len = chord.length();
        let t0 = unit_or(chord - n0 * chord.dot(n0), || jf.tangent);
        let (b1, b2) = (p0 + t0 * (0.4 * len), p3 - jf.tangent * (0.4 * len));
        for li in 0..loops {
            let u = li as f32 / (loops + 1) as f32;
            let v = 1.0 - u;
            sc.pos[li * nr + m] = p0 * (v * v * v) + b1 * (3.0 * u * v * v) + b2 * (3.0 * u * u * v) + p3 * (u * u * u);
            sc.along[li * nr + m] = (b1 - p0) * (v * v) + (b2 - b1) * (2.0 * u * v) + (p3 - b2) * (u * u);
        }
        sc.chord.push(len);
    }
    // Write the loops (seam duplicated: column nr repeats column 0 with u = 1), then the
    // footprint loop again with the child's bark coordinates (see `uv_seam`).
    let cs = j.child_stem;
    let record = j.wind.record(cs, jn.t_start, rc);
    let stride_c = nr + 1;
    let first_new = out.next_index();
    let uv_seam = first_new + (loops * stride_c) as u32;
    sc.collar_n.clear();
    {
        let block = out.alloc_vertices((loops + 1) * stride_c);
        for li in 0..=loops {
            // Loop `loops` is the footprint loop's copy: same place, normal and sway as the
            // footprint loop (no crack under wind), but `u`, `v` and distance continue the
            // collar's, so the child's bark runs on down to the footprint instead of being
            // smeared across the first collar row (the parent's `u` range is a small part of
            // the child's 0..1).
            let (li, copy) = if li == loops { (0, true) } else { (li, false) };
            let row = if copy { loops } else { li };
            let back = 1.0 - li as f32 / (loops + 1) as f32;
            for c in 0..stride_c {
                let m = c % nr;
                let k = li * nr + m;
                let around = sc.pos[li * nr + (m + 1) % nr] - sc.pos[li * nr + (m + nr - 1) % nr];
                let radial = sc.pos[k] - jf.centre;
                let collar = unit_or(around.cross(sc.along[k]), || unit_or(radial, || jf.normal));
                if li == 0 && !copy && c < nr {
                    sc.collar_n.push(collar);
                }
                let slot = row * stride_c + c;
                block.positions[slot * 3..slot * 3 + 3].copy_from_slice(&sc.pos[k].to_array());
                block.normals[slot * 3..slot * 3 + 3].copy_from_slice(&collar.to_array());
                let dist = back * sc.chord[m];
                let uv = if li == 0 && !copy {
                    sc.foot[m].3
                } else {
                    [c as f32 / nr as f32, j.child.v0 - dist / (TAU * rc)]
                };
                block.uvs[slot * 2..slot * 2 + 2].copy_from_slice(&uv);
                let wr = if li == 0 {
                    let mut wr = sc.foot[m].2;
                    if copy {
                        wr[6] = record[6] - dist;
                    }
                    wr
                } else {
                    let mut wr = record;
                    wr[6] -= dist;
                    wr
                };
                block.wind[slot * WIND_STRIDE..(slot + 1) * WIND_STRIDE].copy_from_slice(&wr);
            }
        }
    }
    // Quads between the footprint loop, the collar loops and the junction ring.
    sc.tris.clear();
    for li in 0..loops {
        let lo = first_new + (li * stride_c) as u32;
        let hi = if li + 1 < loops { lo + stride_c as u32 } else { j.child.first };
        let lo = if li == 0 { uv_seam } else { lo };
        for m in 0..nr as u32 {
            let (a, b, c, d) = (lo + m, lo + m + 1, hi + m + 1, hi + m);
            sc.tris.extend_from_slice(&[a, b, c, a, c, d]);
        }
    }
    let collar_tris = sc.tris.len();
    let good = well_wound;
    // The footprint loop is the crease between the parent's surface (the zip) and the collar:
    // its normal blends theirs, halfway if that suits both, else leaning to one side. The hole
    // is tried as found, then one quad wider all round (more room for the zip).
    const EDGE: f32 = 0.2;
    let base = (ra, rb, ja, jb);
    for w in [0.5, 0.25, 0.75, 0.0] {
        for m in 0..stride_c {
            let n = unit_or(sc.foot[m % nr].1 * (1.0 - w) + sc.collar_n[m % nr] * w, || sc.collar_n[m % nr]);
            out.set_normal(first_new + m as u32, n);
            out.set_normal(uv_seam + m as u32, n);
        }
        if !good(out, &sc.tris[..collar_tris]) {
            continue;
        }
        for grow in [false, true] {
            let (mut ra, mut rb, mut ja, mut jb) = base;
            let cells = &sc.cells;
            let near_lo = grow || cells.iter().any(|x| x.0 == ra && x.2.y < EDGE);
            let near_hi = grow || cells.iter().any(|x| x.0 + 1 == rb && x.2.y > 1.0 - EDGE);
            let near_left = grow || cells.iter().any(|x| x.1 == ja && x.2.x < EDGE);
            let near_right = grow || cells.iter().any(|x| x.1 + 1 == jb && x.2.x > 1.0 - EDGE);
            if ra > 0 && near_lo && free(claimed, ra - 1..ra, ja..jb) {
                ra -= 1;
            }
            if rb + 1 < pts.len() && near_hi && free(claimed, rb..rb + 1, ja..jb) {
                rb += 1;
            }
            if jb - ja + 1 < sides && near_left && free(claimed, ra..rb, ja - 1..ja) {
                ja -= 1;
            }
            if jb - ja + 1 < sides && near_right && free(claimed, ra..rb, jb..jb + 1) {
                jb += 1;
            }
            sc.tris.truncate(collar_tris);
            if zip_hole(sc, j, (ra, rb, ja, jb), first_new)
                && good(out, &sc.tris[collar_tris..])
                && out.unwrap_u(&mut sc.tris[collar_tris..], stride_c, |i, k| j.parent.seam_twin(i, k))
            {
                for r in ra..rb {
                    for c in ja..jb {
                        claimed[claim(r, c)] = true;
                    }
                }
                bridges.extend_from_slice(&sc.tris);
                return true;
            }
        }
    }
    out.truncate_vertices(first_new);
    false
}

/// True if every triangle of `tris` is non-degenerate and wound with its vertex normals (its
/// face normal on the side of their sum).
pub(crate) fn well_wound(out: &MeshBuilder, tris: &[u32]) -> bool {
    tris.chunks_exact(3).all(|t| {
        let ((a, na), (b, nb), (c, nc)) = (out.vertex_at(t[0]), out.vertex_at(t[1]), out.vertex_at(t[2]));
        let cross = (b - a).cross(c - a);
        cross.length_squared() > 0.0 && cross.dot(na + nb + nc) > 0.0
    })
}

/// Step 5: the hole over parent rows `ra..rb` and columns `ja..jb`, zipped to the footprint loop
/// (written at `first_new`); its triangles are appended to `sc.tris`. The zip works in the
/// parent's own surface coordinates (around, along; metres), where the hole is a rectangle and
/// the footprint loop a closed curve inside it. False if the footprint loop does not turn
/// monotonically around its centre there, or the zip would fold.
fn zip_hole(sc: &mut Scratch, j: &Join, (ra, rb, ja, jb): (usize, usize, i32, i32), first_new: u32) -> bool {
    let pm = j.parent;
    let nr = j.child.sides as usize;
    let sides = pm.sides as i32;
    let pts = &j.ts[pm.ring0..pm.ring0 + pm.rings as usize];
    let len = j.parent_stem.length;
    let col = TAU * j.parent_stem.radius_at(pts[(ra + rb) / 2]).max(1e-6) / sides as f32;
    let at = |r: usize, c: f32, v: f32| {
        let t = if v > 0.0 { pts[r] + v * (pts[r + 1] - pts[r]) } else { pts[r] };
        Vec2::new(c * col, t * len)
    };
    // The hole's boundary, counter-clockwise seen from outside.
    let stride = pm.sides + 1;
    let vid = |r: usize, c: i32| pm.first + r as u32 * stride + c.rem_euclid(sides) as u32;
    sc.hole.clear();
    sc.flat.clear();
    for c in ja..jb {
        sc.hole.push(vid(ra, c));
        sc.flat.push(at(ra, c as f32, 0.0));
    }
    for r in ra..rb {
        sc.hole.push(vid(r, jb));
        sc.flat.push(at(r, jb as f32, 0.0));
    }
    for c in ((ja + 1)..=jb).rev() {
        sc.hole.push(vid(rb, c));
        sc.flat.push(at(rb, c as f32, 0.0));
    }
    for r in ((ra + 1)..=rb).rev() {
        sc.hole.push(vid(r, ja));
        sc.flat.push(at(r, ja as f32, 0.0));
    }
    let l = sc.hole.len();
    // The footprint loop in the same coordinates, and its centre.
    sc.foot_flat.clear();
    sc.foot_flat.extend(sc.cells.iter().map(|&(r, c, uv)| at(r, c as f32 + uv.x, uv.y)));
    let centre = sc.foot_flat.iter().copied().sum::<Vec2>() / nr as f32;
    let angle_of = |p: Vec2| turn_of(p - centre);
    // Angles from the hole's vertex of smallest angle; the rectangle turns monotonically around
    // any point inside it.
    sc.angle.clear();
    sc.angle.extend(sc.flat.iter().map(|&p| angle_of(p)));
    let k0 = (0..l).fold(0, |m, k| if sc.angle[k] < sc.angle[m] { k } else { m });
    sc.hole.rotate_left(k0);
    sc.angle.rotate_left(k0);
    sc.flat.rotate_left(k0);
    let a0 = sc.angle[0];
    for a in &mut sc.angle {
        *a -= a0;
    }
    if !sc.angle.windows(2).all(|w| w[0] < w[1]) {
        return false;
    }
    // The footprint loop's columns in the same terms: start at the column just before the
    // hole's first vertex (an angle below 0), then increasing to one full turn later.
    sc.ring.clear();
    sc.ring.extend(sc.foot_flat.iter().map(|&p| {
        let a = angle_of(p) - a0;
        if a < 0.0 {
            a + TURN
        } else {
            a
        }
    }));
    let kstar = (0..nr).fold(0, |m, k| if sc.ring[k] > sc.ring[m] { k } else { m });
    let ring_ang = |k: usize| {
        let a = sc.ring[(kstar + k) % nr];
        if k == 0 {
            a - TURN
        } else {
            a
        }
    };
    if !(1..nr).all(|k| ring_ang(k - 1) < ring_ang(k)) {
        return false;
    }
    let column = |k: usize| {
        let c = kstar + k;
        if c <= nr {
            c
        } else {
            c - nr
        }
    };
    let ang_h = |i: usize| if i < l { sc.angle[i] } else { TURN };
    let ang_r = |k: usize| if k < nr { ring_ang(k) } else { ring_ang(0) + TURN };
    // Each step advances the loop whose next vertex comes first by angle, unless that triangle
    // would turn the wrong way and the other would not.
    let hole_at = |i: usize| sc.flat[i % l];
    let foot_at = |k: usize| sc.foot_flat[column(k) % nr];
    let turns = |a: Vec2, b: Vec2, c: Vec2| (b - a).perp_dot(c - a) > 0.0;
    let (mut i, mut k) = (0, 0);
    while i < l || k < nr {
        let hole_ok = i < l && turns(hole_at(i), hole_at(i + 1), foot_at(k));
        let foot_ok = k < nr && turns(hole_at(i), foot_at(k + 1), foot_at(k));
        let advance_hole = match (hole_ok, foot_ok) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => k == nr || (i < l && ang_h(i + 1) < ang_r(k + 1)),
            (false, false) => return false,
        };
        if advance_hole {
            sc.tris.extend_from_slice(&[sc.hole[i], sc.hole[(i + 1) % l], first_new + column(k) as u32]);
            i += 1;
        } else {
            sc.tris.extend_from_slice(&[
                sc.hole[i % l],
                first_new + column(k + 1) as u32,
                first_new + column(k) as u32,
            ]);
            k += 1;
        }
    }
    true
}

/// One turn in [`turn_of`]'s units.
const TURN: f32 = 4.0;

/// A pseudo-angle of `v` in [0, 4): increasing with its angle from +x (counter-clockwise), as
/// good as the angle for ordering and much cheaper than `atan2`.
fn turn_of(v: Vec2) -> f32 {
    let s = v.x.abs() + v.y.abs();
    if s == 0.0 {
        return 0.0;
    }
    let r = v.y / s;
    if v.x < 0.0 {
        2.0 - r
    } else if v.y < 0.0 {
        TURN + r
    } else {
        r
    }
}

/// Where the line `q + s d` crosses the plane of triangle `t` leaving it on its outer side: `s`
/// and the (unclamped) coordinates `u`, `v` along `t[1] - t[0]` and `t[2] - t[0]`.
fn line_plane(q: Vec3, d: Vec3, t: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let h = d.cross(e2);
    let det = e1.dot(h);
    // det = -d · (e1 × e2): leaving through the outer side (along the normal) makes it negative.
    if det >= -1e-12 * e1.length_squared().max(e2.length_squared()) {
        return None;
    }
    let inv = 1.0 / det;
    let o = q - t[0];
    let qv = o.cross(e1);
    Some((e2.dot(qv) * inv, o.dot(h) * inv, d.dot(qv) * inv))
}

/// Where the line `q + s d` crosses triangle `t` leaving it on its outer side (wound
/// counter-clockwise seen from outside): `s` and the barycentric weights of the crossing.
fn line_hit(q: Vec3, d: Vec3, t: [Vec3; 3]) -> Option<(f32, Vec3)> {
    let (s, u, v) = line_plane(q, d, t)?;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then(|| (s, Vec3::new(1.0 - u - v, u, v)))
}
