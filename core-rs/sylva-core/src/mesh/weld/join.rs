//! Steps 2 to 5 of a welded junction (see [`super`]), after the parent's and the child's rings
//! are swept, as named steps of [`join`]:
//!
//! 1. [`Meeting::new`]: the parent's rows and columns around the footprint;
//! 2. [`footprint::find`]: the footprint loop and the quads under it;
//! 3. [`Collar::curves`]: one cubic Bezier per column from the footprint loop to the junction
//!    ring, leaving the parent tangentially and arriving along the child's axis (after the Bezier
//!    cylinders of *Modeling the Mighty Maple for Web* (ibiblio.org/e-notes));
//! 4. [`Collar::write`] and [`Collar::quads`]: the collar loops' vertices and quads;
//! 5. [`open_and_zip`]: the crease normals, the hole (grown where the loop comes close to its
//!    edge) and the zip ([`super::zip`]); every new triangle is checked ([`well_wound`]) before
//!    anything is committed.

use super::crossing::Cell;
use super::footprint::{self, claim_index, free, FootPoint, Meeting, Rect, Scratch};
use super::wrap;
use super::zip::zip_hole;
use crate::math::{unit_or, TAU};
use crate::mesh::junction::{well_wound, Join};
use crate::mesh::stem::Frame;
use crate::mesh::{MeshBuilder, WIND_DISTANCE};
use glam::Vec3;

/// Steps 2 to 5: open the parent, add the collar loops and zip them in. On success the hole's
/// quads are marked in `claimed`, the new vertices stay in `out` and the new triangles go to
/// `bridges`; on failure nothing is changed.
pub(crate) fn join(
    j: &Join,
    claimed: &mut [bool],
    out: &mut MeshBuilder,
    bridges: &mut Vec<u32>,
    sc: &mut Scratch,
) -> bool {
    let Some(meeting) = Meeting::new(j) else { return false };
    let Some(hole) = footprint::find(j, &meeting, claimed, out, sc) else { return false };
    let collar = Collar::new(j, &meeting, out.next_index());
    collar.curves(j, out, sc);
    collar.write(j, out, sc);
    collar.quads(j, sc);
    if open_and_zip(j, &collar, &meeting, hole, claimed, out, sc) {
        bridges.extend_from_slice(&sc.tris);
        return true;
    }
    out.truncate_vertices(collar.first);
    false
}

/// The collar between the footprint loop and the child's junction ring: `loops` loops of
/// `columns + 1` vertices (the seam duplicated), loop 0 on the footprint loop, then a copy of
/// the footprint loop with the child's bark coordinates.
struct Collar {
    /// The child's junction ring's frame.
    ring: Frame,
    /// The child's radius at its junction ring (m).
    rc: f32,
    /// Loops from the footprint loop (loop 0) toward the junction ring.
    loops: usize,
    /// Columns: the child's sides.
    columns: usize,
    /// First vertex of loop 0.
    first: u32,
    /// First vertex of the footprint loop's copy with the child's bark coordinates.
    uv_seam: u32,
}

impl Collar {
    fn new(j: &Join, m: &Meeting, first: u32) -> Collar {
        let (loops, columns) = (j.loops + 1, j.child.sides as usize);
        Collar { ring: m.ring, rc: m.rc, loops, columns, first, uv_seam: first + (loops * (columns + 1)) as u32 }
    }

    /// Vertices per loop (the seam duplicated: column `columns` repeats column 0 with u = 1).
    fn stride(&self) -> usize {
        self.columns + 1
    }

    /// Collar curves, one per column: cubic Beziers from the footprint loop to the junction ring
    /// (both handles 0.4 of the chord), sampled at the loops into `sc.pos` and `sc.along`.
    fn curves(&self, j: &Join, out: &MeshBuilder, sc: &mut Scratch) {
        let (loops, nr, jf) = (self.loops, self.columns, self.ring);
        sc.pos.clear();
        sc.pos.resize(loops * nr, Vec3::ZERO);
        sc.along.clear();
        sc.along.resize(loops * nr, Vec3::ZERO);
        sc.chord.clear();
        for m in 0..nr {
            let FootPoint { pos: p0, normal: n0, .. } = sc.foot[m];
            let p3 = out.vertex_at(j.child.first + m as u32).0;
            let chord = p3 - p0;
            let len = chord.length();
            let t0 = unit_or(chord - n0 * chord.dot(n0), || jf.tangent);
            let (b1, b2) = (p0 + t0 * (0.4 * len), p3 - jf.tangent * (0.4 * len));
            for li in 0..loops {
                let u = li as f32 / (loops + 1) as f32;
                let v = 1.0 - u;
                sc.pos[li * nr + m] =
                    p0 * (v * v * v) + b1 * (3.0 * u * v * v) + b2 * (3.0 * u * u * v) + p3 * (u * u * u);
                sc.along[li * nr + m] = (b1 - p0) * (v * v) + (b2 - b1) * (2.0 * u * v) + (p3 - b2) * (u * u);
            }
            sc.chord.push(len);
        }
    }

    /// Writes the loops, then the footprint loop again with the child's bark coordinates: same
    /// place, normal and sway as the footprint loop (no crack under wind), but `u`, `v` and
    /// distance continue the collar's, so the child's bark runs on down to the footprint
    /// instead of being smeared across the first collar row (the parent's `u` range is a small
    /// part of the child's 0..1). Fills `sc.collar_n` with the collar's normal at each
    /// footprint point.
    fn write(&self, j: &Join, out: &mut MeshBuilder, sc: &mut Scratch) {
        let (loops, nr, stride) = (self.loops, self.columns, self.stride());
        let record = j.wind.record(j.child_stem, j.junction.t_start, self.rc);
        sc.collar_n.clear();
        out.append_vertices((loops + 1) * stride, |sink| {
            for row in 0..=loops {
                let copy = row == loops;
                let li = if copy { 0 } else { row };
                let back = 1.0 - li as f32 / (loops + 1) as f32;
                for c in 0..stride {
                    let m = wrap(c, nr);
                    let k = li * nr + m;
                    // The copy of the footprint loop has its normals, computed for loop 0.
                    let collar = if copy {
                        sc.collar_n[m]
                    } else {
                        let around = sc.pos[li * nr + wrap(m + 1, nr)] - sc.pos[li * nr + wrap(m + nr - 1, nr)];
                        let radial = sc.pos[k] - self.ring.centre;
                        unit_or(around.cross(sc.along[k]), || unit_or(radial, || self.ring.normal))
                    };
                    if li == 0 && !copy && c < nr {
                        sc.collar_n.push(collar);
                    }
                    let dist = back * sc.chord[m];
                    let uv = if li == 0 && !copy {
                        sc.foot[m].uv
                    } else {
                        [c as f32 / nr as f32, j.child.v0 - dist / (TAU * self.rc)]
                    };
                    sink.push(sc.pos[k], collar, uv);
                    let mut wind = if li == 0 { sc.foot[m].wind } else { record };
                    if li != 0 || copy {
                        wind[WIND_DISTANCE] = record[WIND_DISTANCE] - dist;
                    }
                    sink.push_wind(&wind, 1);
                }
            }
        });
    }

    /// Quads between the footprint loop (its copy with the child's bark), the collar loops and
    /// the junction ring, into `sc.tris`.
    fn quads(&self, j: &Join, sc: &mut Scratch) {
        let (loops, nr, stride) = (self.loops, self.columns, self.stride());
        sc.tris.clear();
        for li in 0..loops {
            let lo = self.first + (li * stride) as u32;
            let hi = if li + 1 < loops { lo + stride as u32 } else { j.child.first };
            let lo = if li == 0 { self.uv_seam } else { lo };
            for m in 0..nr as u32 {
                let (a, b, c, d) = (lo + m, lo + m + 1, hi + m + 1, hi + m);
                sc.tris.extend_from_slice(&[a, b, c, a, c, d]);
            }
        }
    }
}

/// How close (a fraction of a quad) the footprint loop may come to the hole's edge before the
/// hole grows by a row or column there.
const EDGE: f32 = 0.2;

/// Step 5. The footprint loop is the crease between the parent's surface (the zip) and the
/// collar: its normal blends theirs, halfway if that suits both, else leaning to one side. The
/// hole is tried as found (grown where the loop comes close to its edge), then one quad wider
/// all round (more room for the zip). On success the hole's quads are claimed and `sc.tris`
/// holds the collar's and the zip's triangles.
fn open_and_zip(
    j: &Join,
    collar: &Collar,
    m: &Meeting,
    found: Rect,
    claimed: &mut [bool],
    out: &mut MeshBuilder,
    sc: &mut Scratch,
) -> bool {
    let collar_tris = sc.tris.len();
    let nr = collar.columns;
    for w in [0.5, 0.25, 0.75, 0.0] {
        for k in 0..collar.stride() {
            let m = wrap(k, nr);
            let n = unit_or(sc.foot[m].normal * (1.0 - w) + sc.collar_n[m] * w, || sc.collar_n[m]);
            out.set_normal(collar.first + k as u32, n);
            out.set_normal(collar.uv_seam + k as u32, n);
        }
        if !well_wound(out, &sc.tris[..collar_tris]) {
            continue;
        }
        for grow in [false, true] {
            let hole = grown(j, m, found, &sc.cells, grow, claimed);
            sc.tris.truncate(collar_tris);
            if zip_hole(sc, j, hole, collar.first)
                && well_wound(out, &sc.tris[collar_tris..])
                && out.unwrap_u(&mut sc.tris[collar_tris..], collar.stride(), |i, k| j.parent.seam_twin(i, k))
            {
                for r in hole.rows() {
                    for c in hole.cols() {
                        claimed[claim_index(j, r, c)] = true;
                    }
                }
                return true;
            }
        }
    }
    false
}

/// The hole `found` grown by a free row or column on each side where the footprint loop comes
/// within [`EDGE`] of it (on every side when `grow`), never all the way around the parent.
fn grown(j: &Join, m: &Meeting, found: Rect, cells: &[Cell], grow: bool, claimed: &[bool]) -> Rect {
    let Rect { mut row_lo, mut row_hi, mut col_lo, mut col_hi } = found;
    let near_lo = grow || cells.iter().any(|x| x.row == row_lo && x.at.y < EDGE);
    let near_hi = grow || cells.iter().any(|x| x.row + 1 == row_hi && x.at.y > 1.0 - EDGE);
    let near_left = grow || cells.iter().any(|x| x.col == col_lo && x.at.x < EDGE);
    let near_right = grow || cells.iter().any(|x| x.col + 1 == col_hi && x.at.x > 1.0 - EDGE);
    if row_lo > 0 && near_lo && free(j, claimed, row_lo - 1..row_lo, col_lo..col_hi) {
        row_lo -= 1;
    }
    if row_hi + 1 < m.pts.len() && near_hi && free(j, claimed, row_hi..row_hi + 1, col_lo..col_hi) {
        row_hi += 1;
    }
    if col_hi - col_lo + 1 < m.sides && near_left && free(j, claimed, row_lo..row_hi, col_lo - 1..col_lo) {
        col_lo -= 1;
    }
    if col_hi - col_lo + 1 < m.sides && near_right && free(j, claimed, row_lo..row_hi, col_hi..col_hi + 1) {
        col_hi += 1;
    }
    Rect { row_lo, row_hi, col_lo, col_hi }
}
