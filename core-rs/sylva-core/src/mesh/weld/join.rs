//! Steps 2 to 4 of a welded junction (see [`super`]), after the parent's and the child's rings
//! are swept: the **footprint loop** (for every column of the child's junction ring, where the
//! line along the child's axis, widened to the collar's radius, leaves the parent's faceted
//! surface: a guess from the parent's local cylinder, then the quads around it), the **hole**
//! (the parent quads under it are claimed, grown by a row or column where the loop comes close to
//! its edge), and the **collar** loops on cubic Beziers from the footprint loop to the junction
//! ring, leaving the parent tangentially and arriving along the child's axis (after the maple
//! page's Bezier cylinders, reference 003). The zip itself (step 5) is [`super::zip`]; every new
//! triangle is checked ([`well_wound`]) before anything is committed.

use super::zip::zip_hole;
use super::{asin, Junction, REACH};
use crate::math::{atan2, unit_or, HwSqrt, TAU};
use crate::mesh::tube::{Frame, StemMesh, StemWind};
use crate::mesh::{MeshBuilder, WIND_STRIDE};
use crate::skeleton::Stem;
use glam::{Vec2, Vec3};

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
    pub(super) hole: Vec<u32>,
    pub(super) angle: Vec<f32>,
    pub(super) ring: Vec<f32>,
    pos: Vec<Vec3>,
    along: Vec<Vec3>,
    chord: Vec<f32>,
    pub(crate) tris: Vec<u32>,
    /// The footprint loop: position, normal and wind per column of the junction ring.
    foot: Vec<(Vec3, Vec3, [f32; WIND_STRIDE], [f32; 2])>,
    /// The parent quad (row, column) under each footprint point, and where in it.
    pub(super) cells: Vec<(usize, i32, Vec2)>,
    /// The collar's own normal at each footprint point.
    collar_n: Vec<Vec3>,
    /// The hole's vertices in the parent's surface coordinates.
    pub(super) flat: Vec<Vec2>,
    /// The footprint loop in the parent's surface coordinates.
    pub(super) foot_flat: Vec<Vec2>,
    /// The search window's triangles the child's axis leaves through ([`Facing`]), with their
    /// vertices, row, column and half, in the order the search visits them.
    window: Vec<(Facing, [u32; 3], usize, i32, usize)>,
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
    let beta = asin((jn.foot / r_mid).min(0.9)).max(atan2(jn.foot + 0.25 * rc, w.length_hw()));
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
    // The search window's triangles, filled at the first search (most junctions need none).
    sc.window.clear();
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
                    if sc.window.is_empty() {
                        fill_window(&mut sc.window, out, pm.first, stride, sides, wa..wb, ca..cb, jf.tangent);
                    }
                    best = search(&sc.window, q, jf.tangent);
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
        let len = chord.length_hw();
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

/// Where the line `q + s d` crosses the plane of triangle `t` leaving it on its outer side: `s`
/// and the (unclamped) coordinates `u`, `v` along `t[1] - t[0]` and `t[2] - t[0]`.
fn line_plane(q: Vec3, d: Vec3, t: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    Facing::new(d, t).map(|f| f.at(q, d))
}

/// The part of [`line_plane`] that depends on the triangle and the line's direction only, for
/// many lines of one direction (the columns of a junction all follow the child's axis).
#[derive(Clone, Copy)]
struct Facing {
    p0: Vec3,
    e1: Vec3,
    e2: Vec3,
    h: Vec3,
    inv: f32,
}

impl Facing {
    /// `None` when lines along `d` do not leave triangle `t` through its outer side.
    #[inline]
    fn new(d: Vec3, t: [Vec3; 3]) -> Option<Facing> {
        let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
        let h = d.cross(e2);
        let det = e1.dot(h);
        // det = -d · (e1 × e2): leaving through the outer side (along the normal) makes it negative.
        if det >= -1e-12 * crate::math::max(e1.length_squared(), e2.length_squared()) {
            return None;
        }
        Some(Facing { p0: t[0], e1, e2, h, inv: 1.0 / det })
    }

    /// [`line_plane`] of the line `q + s d` (`d` the direction given to [`Facing::new`]).
    #[inline]
    fn at(&self, q: Vec3, d: Vec3) -> (f32, f32, f32) {
        let o = q - self.p0;
        let qv = o.cross(self.e1);
        (self.e2.dot(qv) * self.inv, o.dot(self.h) * self.inv, d.dot(qv) * self.inv)
    }
}

/// The triangles of the parent's quads in `rows` × `cols` (as `emit` writes them: the seam's
/// duplicate column after the last) that lines along `d` leave through their outer side, into
/// `window` in search order.
fn fill_window(
    window: &mut Vec<(Facing, [u32; 3], usize, i32, usize)>,
    out: &MeshBuilder,
    first: u32,
    stride: u32,
    sides: i32,
    rows: std::ops::Range<usize>,
    cols: std::ops::Range<i32>,
    d: Vec3,
) {
    for r in rows {
        for c in cols.clone() {
            let a = first + r as u32 * stride + c.rem_euclid(sides) as u32;
            let (b, c2, e) = (a + 1, a + 1 + stride, a + stride);
            for (half, t) in [[a, b, c2], [a, c2, e]].into_iter().enumerate() {
                if let Some(f) = Facing::new(d, t.map(|v| out.vertex_at(v).0)) {
                    window.push((f, t, r, c, half));
                }
            }
        }
    }
}

/// The first hit (largest `s`) of the line `q + s d` with the triangles of a [`fill_window`]:
/// `s`, the triangle, its barycentric weights, row and column, and where in the quad (across
/// its columns, along its rows, 0..1).
fn search(
    window: &[(Facing, [u32; 3], usize, i32, usize)],
    q: Vec3,
    d: Vec3,
) -> Option<(f32, [u32; 3], Vec3, usize, i32, Vec2)> {
    let mut best: Option<(f32, [u32; 3], Vec3, usize, i32, Vec2)> = None;
    for &(f, t, r, c, half) in window {
        let (s, u, v) = f.at(q, d);
        if u >= 0.0 && v >= 0.0 && u + v <= 1.0 && best.is_none_or(|(s0, ..)| s > s0) {
            let w = Vec3::new(1.0 - u - v, u, v);
            let uv = if half == 0 { Vec2::new(w.y + w.z, w.z) } else { Vec2::new(w.y, w.y + w.z) };
            best = Some((s, t, w, r, c, uv));
        }
    }
    best
}
