//! Welded junctions (issue #5, item 3): a child stem's tube is connected into its parent's
//! surface instead of being buried in it, so trunk + level 1 + level 2 form one closed,
//! edge-manifold surface.
//!
//! The idea follows the maple page's twigs and ramiforms (reference 003): a junction is a short
//! **Bezier cylinder** (a circle swept along a Bezier spline) from a loop on the parent's surface
//! to the child's first ring. Here it goes in four steps:
//!
//! 1. **Plan** ([`plan`], before any vertex exists). From the skeleton alone: the angle θ between
//!    the child's first direction and the parent's axis, the distance `s_out = (R + r |cos θ|) /
//!    sin θ` along the child at which its tube (radius `r`) has left the parent's (radius `R`,
//!    times the lobe/fluting bound on the trunk), and the child's **junction ring** at
//!    `s_out + collar r / 2`: the child's tube starts there. The **footprint** on the parent is the ellipse of the child's collar (radius
//!    `r' = r (1 + collar (1 - r / R) / 2)`: no flare on an even fork) around the point where the
//!    child's axis pierces the parent, `±r' / sin θ` along the parent and `±asin(r' / R)` around
//!    it, widened to cover the junction ring as seen from the parent (a curved child leans).
//!    The parent gets extra rings across the footprint (1 to 6 rows, about square quads), so the
//!    hole fits the child whatever the parent's own ring spacing. Footprints that would overlap
//!    one already accepted on the same parent, leave the parent's tube (below its own junction
//!    ring, across the trunk's bottom cap or near the tip), leave at less than 10° or need a
//!    junction ring beyond half the child are not welded. Split clones are planned first: a smooth Y
//!    matters more than a side twig.
//! 2. **Hole** ([`join`], after the parent's and the child's rings are swept). The footprint is
//!    snapped to the parent's (ring, column) grid: the rows between the rings at the footprint's
//!    ends, the columns around the child's azimuth measured in the parent's own transported
//!    frame. These quads are *claimed* (not emitted); their boundary is one closed loop of parent
//!    vertices, walked counter-clockwise seen from outside (bottom ring, right column, top ring,
//!    left column). The vertices inside the hole stay in the buffers, unused by any triangle.
//! 3. **Collar** (the blend). For every column of the child's junction ring, the point of the hole
//!    loop at the same parameter (see 4) is joined to the ring vertex by a cubic
//!    Bezier that leaves the parent *tangentially* (first control point along the parent's
//!    tangent plane) and arrives *along the child's axis* (last control point back along it), both
//!    handles 0.4 of the chord. `collar_loops(quality)` loops of the child's column count sit on
//!    these curves at even parameters: a collar that flares from the wider hole into the branch,
//!    C1 with both surfaces up to the loop spacing. For a split clone the hole spans the side of
//!    the original facing it, so the collar becomes the crotch of a Y (the ramiform's top patch).
//! 4. **Zip**. Around the junction's axis (from the hole's centroid to the junction ring's
//!    centre), the hole loop is parametrised by arc length from its vertex of smallest angle
//!    (raw angles of a projected hole can fold back at its corners), the ring's columns by their
//!    angle relative to that vertex; the collar curves start at the hole point of their column's
//!    parameter. The hole (any number of vertices) is zipped to the first collar loop: both run
//!    counter-clockwise, each step advances the loop whose next vertex has the smaller parameter,
//!    one triangle per step, so every edge of both loops is used exactly once. Quads join the
//!    collar loops and the junction ring.
//!
//! Every new triangle is checked before anything is committed: non-degenerate and wound with its
//! vertex normals. If the ring's angles are not monotone around the junction's axis, a claimed
//! quad is already taken, or a check fails, the junction's vertices are dropped and the child is
//! swept again as a separate tube from its parent's axis with a closed base: a **fallback**, counted in [`super::tube::WeldStats`].
//! Deeper levels (3) are always such closed separate tubes.

use super::tube::{Frame, StemMesh, StemWind};
use super::{MeshBuilder, WIND_STRIDE};
use crate::math::{atan2, unit_or, PI, TAU};
use crate::params::TreeParams;
use crate::skeleton::{Skeleton, Stem};
use glam::Vec3;

/// Smallest sine of the angle between a child and its parent that is welded (about 20°): below
/// it the child leaves the parent's surface too far along its own length.
const MIN_SIN: f32 = 0.17;
/// The junction ring must sit in the first half of the child.
const MAX_START: f32 = 0.5;
/// Most rows a footprint spans on its parent.
const MAX_ROWS: u32 = 6;

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
    /// Rows of parent quads across the footprint (`rows + 1` rings are added to the parent).
    pub rows: u32,
    /// Radius of the footprint (the collar's base) (m).
    pub foot: f32,
}

/// True for the stems the junctions weld: levels 1 and 2 on their parents and split clones up to
/// level 2 (a clone has its original's level).
pub(crate) fn is_candidate(stems: &[Stem], i: usize) -> bool {
    let s = &stems[i];
    s.level <= 2 && s.parent.is_some_and(|p| stems[p as usize].level <= s.level)
}

/// Number of collar loops between a hole and the child's junction ring.
pub(crate) fn collar_loops(quality: f32) -> usize {
    ((2.0 * quality).round() as usize).clamp(1, 4)
}

/// How far the trunk's surface reaches beyond its nominal radius (lobes, fluting, ripple).
fn surface_bound(p: &TreeParams) -> f32 {
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
fn geometry(stems: &[Stem], i: usize, p: &TreeParams) -> Option<(Junction, f32, f32)> {
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
    let sides = crate::mesh::tube::sides_for(par.radius, p.mesh_quality, if par.lobed { p.lobes } else { 0 });
    let column = TAU * r_axis / sides as f32;
    let rows = (((t_hi - t_lo) * lp / column).round() as u32).clamp(1, MAX_ROWS);
    // Azimuth in a frame at the footprint without transport: only compared between footprints
    // close along the same parent, where the transported frame barely turns.
    let (c, t) = par.sample(t_mid);
    let n = unit_or(par.base_normal - t * par.base_normal.dot(t), || t.any_orthonormal_vector());
    let w = s.sample(t_start).0 - c;
    let phi = atan2(w.dot(t.cross(n)), w.dot(n));
    Some((Junction { parent: pi, t_start, t_lo, t_hi, rows, foot }, phi, beta))
}

/// Step 1: the junction of every stem that can be welded (None for the others).
pub(crate) fn plan(skeleton: &Skeleton, p: &TreeParams, sides: &[u32]) -> Vec<Option<Junction>> {
    let stems = &skeleton.stems;
    let n = stems.len();
    let geo: Vec<Option<(Junction, f32, f32)>> =
        (0..n).map(|i| if is_candidate(stems, i) { geometry(stems, i, p) } else { None }).collect();
    let mut out = vec![None; n];
    // Accepted footprints per parent as linked lists: (t_lo, t_hi, phi, beta, next).
    let mut head = vec![u32::MAX; n];
    let mut feet: Vec<(f32, f32, f32, f32, u32)> = Vec::new();
    for clones in [true, false] {
        for i in 0..n {
            let Some((j, phi, beta)) = geo[i] else { continue };
            let parent = j.parent as usize;
            if (stems[i].level == stems[parent].level) != clones {
                continue;
            }
            // The parent's tube starts at its own junction ring if it gets one.
            let parent_start = geo[parent].map_or(0.0, |g| g.0.t_start);
            if j.t_lo <= parent_start + 1e-3 {
                continue;
            }
            let pad = TAU / sides[parent] as f32;
            let mut k = head[parent];
            let mut free = true;
            while k != u32::MAX {
                let (lo, hi, f_phi, f_beta, next) = feet[k as usize];
                let mut d = (phi - f_phi).abs() % TAU;
                if d > PI {
                    d = TAU - d;
                }
                if j.t_lo < hi && lo < j.t_hi && d < beta + f_beta + pad {
                    free = false;
                    break;
                }
                k = next;
            }
            if free {
                feet.push((j.t_lo, j.t_hi, phi, beta, head[parent]));
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
    tris: Vec<u32>,
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
    let closest = |t: f32| {
        let k = pts.partition_point(|&x| x < t);
        if k == 0 {
            0
        } else if k == pts.len() || t - pts[k - 1] < pts[k] - t {
            k - 1
        } else {
            k
        }
    };
    let (ra, rb) = (closest(jn.t_lo), closest(jn.t_hi));
    let tol = 0.25 * (jn.t_hi - jn.t_lo);
    if rb <= ra || (pts[ra] - jn.t_lo).abs() > tol || (pts[rb] - jn.t_hi).abs() > tol {
        return false; // the footprint's rings are not on the parent's tube
    }
    // Columns around the child's azimuth, in the parent's transported frame at mid-footprint.
    let f = j.frames[pm.ring0 + (ra + rb) / 2];
    let jf = j.frames[j.child.ring0];
    let mut w = jf.centre - f.centre;
    w -= f.tangent * w.dot(f.tangent);
    let phi = atan2(w.dot(f.tangent.cross(f.normal)), w.dot(f.normal));
    let r_mid = j.parent_stem.radius_at(pts[(ra + rb) / 2]).max(1e-6);
    let rc = j.child_stem.radius_at(jn.t_start);
    let beta = asin((jn.foot / r_mid).min(0.9)).max(atan2(rc + (jn.foot - rc) + 0.25 * rc, w.length()));
    let sides = pm.sides as i32;
    let dcol = TAU / sides as f32;
    let ja = ((phi - beta) / dcol).floor() as i32;
    let jb = (((phi + beta) / dcol).ceil() as i32).max(ja + 1);
    if jb - ja >= sides {
        return false;
    }
    let claim = |r: usize, c: i32| pm.claim + r * pm.sides as usize + c.rem_euclid(sides) as usize;
    if (ra..rb).any(|r| (ja..jb).any(|c| claimed[claim(r, c)])) {
        return false;
    }
    // The hole's boundary, counter-clockwise seen from outside.
    let stride = pm.sides + 1;
    let vid = |r: usize, c: i32| pm.first + r as u32 * stride + c.rem_euclid(sides) as u32;
    sc.hole.clear();
    sc.hole.extend((ja..jb).map(|c| vid(ra, c)));
    sc.hole.extend((ra..rb).map(|r| vid(r, jb)));
    sc.hole.extend(((ja + 1)..=jb).rev().map(|c| vid(rb, c)));
    sc.hole.extend(((ra + 1)..=rb).rev().map(|r| vid(r, ja)));
    // Angles around the junction's axis, the line from the hole's centroid to the junction
    // ring's centre, relative to the hole's first vertex after rotating the hole to start at
    // its smallest angle. Both loops must turn monotonically around that axis (star-shaped).
    let l = sc.hole.len();
    let centroid = sc.hole.iter().fold(Vec3::ZERO, |acc, &h| acc + out.vertex_at(h).0) / l as f32;
    let axis = unit_or(jf.centre - centroid, || jf.tangent);
    if axis.dot(jf.tangent) <= 0.2 {
        return false;
    }
    let ax = unit_or(jf.normal - axis * jf.normal.dot(axis), || axis.any_orthonormal_vector());
    let ay = axis.cross(ax);
    let angle_of = |p: Vec3| {
        let v = p - jf.centre;
        let a = atan2(v.dot(ay), v.dot(ax));
        if a < 0.0 {
            a + TAU
        } else {
            a
        }
    };
    sc.angle.clear();
    for &h in &sc.hole {
        sc.angle.push(angle_of(out.vertex_at(h).0));
    }
    let k0 = (0..l).fold(0, |m, k| if sc.angle[k] < sc.angle[m] { k } else { m });
    sc.hole.rotate_left(k0);
    sc.angle.rotate_left(k0);
    // From the hole's first vertex on, angles follow arc length along the hole (monotone by
    // construction; a projected hole bulges at its corners, so its raw angles may fold back).
    let a0 = sc.angle[0];
    let mut total = 0.0f32;
    for i in 0..l {
        sc.angle[i] = total;
        total += out.vertex_at(sc.hole[(i + 1) % l]).0.distance(out.vertex_at(sc.hole[i]).0);
    }
    for a in &mut sc.angle {
        *a *= TAU / total;
    }
    if !(total > 0.0 && sc.angle.windows(2).all(|w| w[0] < w[1])) {
        return false;
    }
    // The junction ring's columns in the same terms: start at the column just before the hole's
    // first vertex (an angle below 0), then increasing to one full turn later.
    let nr = j.child.sides as usize;
    let rel = |p: Vec3| {
        let a = angle_of(p) - a0;
        if a < 0.0 {
            a + TAU
        } else {
            a
        }
    };
    sc.ring.clear();
    sc.ring.extend((0..nr).map(|m| rel(out.vertex_at(j.child.first + m as u32).0)));
    let kstar = (0..nr).fold(0, |m, k| if sc.ring[k] > sc.ring[m] { k } else { m });
    let ring_ang = |k: usize| {
        let a = sc.ring[(kstar + k) % nr];
        if k == 0 {
            a - TAU
        } else {
            a
        }
    };
    if !(1..nr).all(|k| ring_ang(k - 1) < ring_ang(k)) {
        return false;
    }
    // Collar curves, one per column of the junction ring.
    let loops = j.loops;
    sc.pos.clear();
    sc.pos.resize(loops * nr, Vec3::ZERO);
    sc.along.clear();
    sc.along.resize(loops * nr, Vec3::ZERO);
    sc.chord.clear();
    for m in 0..nr {
        let a = sc.ring[m];
        let k = sc.angle.partition_point(|&x| x <= a) - 1;
        let (a1, a2) = (sc.angle[k], if k + 1 < l { sc.angle[k + 1] } else { TAU });
        let s = ((a - a1) / (a2 - a1)).clamp(0.0, 1.0);
        let ((p1, n1), (p2, n2)) = (out.vertex_at(sc.hole[k]), out.vertex_at(sc.hole[(k + 1) % l]));
        let p0 = p1.lerp(p2, s);
        let n0 = unit_or(n1.lerp(n2, s), || n1);
        let p3 = out.vertex_at(j.child.first + m as u32).0;
        let chord = p3 - p0;
        let len = chord.length();
        let t0 = unit_or(chord - n0 * chord.dot(n0), || jf.tangent);
        let (b1, b2) = (p0 + t0 * (0.4 * len), p3 - jf.tangent * (0.4 * len));
        for li in 0..loops {
            let u = (li + 1) as f32 / (loops + 1) as f32;
            let v = 1.0 - u;
            sc.pos[li * nr + m] = p0 * (v * v * v) + b1 * (3.0 * u * v * v) + b2 * (3.0 * u * u * v) + p3 * (u * u * u);
            sc.along[li * nr + m] = (b1 - p0) * (v * v) + (b2 - b1) * (2.0 * u * v) + (p3 - b2) * (u * u);
        }
        sc.chord.push(len);
    }
    // Write the loops (seam duplicated: column nr repeats column 0 with u = 1).
    let cs = j.child_stem;
    let rc = cs.radius_at(jn.t_start).max(0.05 * cs.radius);
    let record = j.wind.record(cs, jn.t_start, rc);
    let stride_c = nr + 1;
    let first_new = out.next_index();
    {
        let block = out.alloc_vertices(loops * stride_c);
        for li in 0..loops {
            let back = 1.0 - (li + 1) as f32 / (loops + 1) as f32;
            for c in 0..stride_c {
                let m = c % nr;
                let k = li * nr + m;
                let around = sc.pos[li * nr + (m + 1) % nr] - sc.pos[li * nr + (m + nr - 1) % nr];
                let radial = sc.pos[k] - jf.centre;
                let nrm = unit_or(around.cross(sc.along[k]), || unit_or(radial, || jf.normal));
                let slot = li * stride_c + c;
                block.positions[slot * 3..slot * 3 + 3].copy_from_slice(&sc.pos[k].to_array());
                block.normals[slot * 3..slot * 3 + 3].copy_from_slice(&nrm.to_array());
                let dist = back * sc.chord[m];
                block.uvs[slot * 2..slot * 2 + 2]
                    .copy_from_slice(&[c as f32 / nr as f32, j.child.v0 - dist / (TAU * rc)]);
                let mut wr = record;
                wr[6] -= dist;
                block.wind[slot * WIND_STRIDE..(slot + 1) * WIND_STRIDE].copy_from_slice(&wr);
            }
        }
    }
    // Triangles: zip the hole to the first loop, then quads up to the junction ring.
    sc.tris.clear();
    let up = if loops > 0 { first_new } else { j.child.first };
    let ring = |k: usize| {
        let c = kstar + k;
        (if c <= nr { c } else { c - nr }) as u32
    };
    let ang_h = |i: usize| if i < l { sc.angle[i] } else { TAU };
    let ang_r = |k: usize| if k < nr { ring_ang(k) } else { ring_ang(0) + TAU };
    let (mut i, mut k) = (0, 0);
    while i < l || k < nr {
        if k == nr || (i < l && ang_h(i + 1) < ang_r(k + 1)) {
            sc.tris.extend_from_slice(&[sc.hole[i], sc.hole[(i + 1) % l], up + ring(k)]);
            i += 1;
        } else {
            sc.tris.extend_from_slice(&[sc.hole[i % l], up + ring(k + 1), up + ring(k)]);
            k += 1;
        }
    }
    for li in 0..loops {
        let lo = first_new + (li * stride_c) as u32;
        let hi = if li + 1 < loops { lo + stride_c as u32 } else { j.child.first };
        for m in 0..nr as u32 {
            let (a, b, c, d) = (lo + m, lo + m + 1, hi + m + 1, hi + m);
            sc.tris.extend_from_slice(&[a, b, c, a, c, d]);
        }
    }
    // Check before committing: every triangle non-degenerate and wound with its normals.
    let ok = sc.tris.chunks_exact(3).all(|t| {
        let ((a, na), (b, nb), (c, nc)) = (out.vertex_at(t[0]), out.vertex_at(t[1]), out.vertex_at(t[2]));
        let cross = (b - a).cross(c - a);
        cross.length() > 0.0 && cross.dot(na + nb + nc) > 0.0
    });
    if !ok {
        out.truncate_vertices(first_new);
        return false;
    }
    for r in ra..rb {
        for c in ja..jb {
            claimed[claim(r, c)] = true;
        }
    }
    bridges.extend_from_slice(&sc.tris);
    true
}
