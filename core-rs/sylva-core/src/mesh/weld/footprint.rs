//! Step 2 of a welded junction (see [`super`]): the **footprint loop**. For every column of the
//! child's junction ring, the line along the child's axis through that column, widened to the
//! collar's radius, is followed back to where it leaves the parent's faceted surface: a guess
//! from the parent's local cylinder ([`Meeting::guess`]), then a walk across the quads around it
//! ([`Meeting::walk`]), else a search of every quad of a window around the estimate (the
//! crossings themselves in [`super::crossing`]).

use super::crossing::{line_plane, search, Cell, Facing, Hit, WindowTri};
use super::{asin, REACH};
use crate::math::{atan2, unit_or, TAU};
use crate::mesh::junction::Join;
use crate::mesh::stem::Frame;
use crate::mesh::{MeshBuilder, WIND_STIFFNESS, WIND_STRIDE};
use glam::{Vec2, Vec3};
use std::ops::Range;

/// Reused buffers of [`join`](super::join()).
#[derive(Default)]
pub(crate) struct Scratch {
    pub(super) hole: Vec<u32>,
    pub(super) angle: Vec<f32>,
    pub(super) ring: Vec<f32>,
    /// Collar points, loop by loop (`loops × columns`), and the curves' directions there.
    pub(super) pos: Vec<Vec3>,
    pub(super) along: Vec<Vec3>,
    /// Length of each column's collar curve's chord.
    pub(super) chord: Vec<f32>,
    pub(crate) tris: Vec<u32>,
    /// The footprint loop, one point per column of the junction ring.
    pub(super) foot: Vec<FootPoint>,
    /// The parent quad under each footprint point, and where in it.
    pub(super) cells: Vec<Cell>,
    /// The collar's own normal at each footprint point.
    pub(super) collar_n: Vec<Vec3>,
    /// The hole's vertices in the parent's surface coordinates.
    pub(super) flat: Vec<Vec2>,
    /// The footprint loop in the parent's surface coordinates.
    pub(super) foot_flat: Vec<Vec2>,
    /// The search window's triangles ([`Meeting::fill_window`]).
    pub(super) window: Vec<WindowTri>,
}

/// A block of the parent's quads: rows `row_lo..row_hi` along it, columns `col_lo..col_hi`
/// around it (columns may run past the seam: they are taken modulo the sides).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Rect {
    /// First row.
    pub row_lo: usize,
    /// One past the last row.
    pub row_hi: usize,
    /// First column.
    pub col_lo: i32,
    /// One past the last column.
    pub col_hi: i32,
}

impl Rect {
    /// Holds no quad; [`Rect::include`] grows it.
    const EMPTY: Rect = Rect { row_lo: usize::MAX, row_hi: 0, col_lo: i32::MAX, col_hi: i32::MIN };

    /// Grows the block to hold quad (`row`, `col`).
    fn include(&mut self, row: usize, col: i32) {
        self.row_lo = self.row_lo.min(row);
        self.row_hi = self.row_hi.max(row + 1);
        self.col_lo = self.col_lo.min(col);
        self.col_hi = self.col_hi.max(col + 1);
    }

    /// Whether quad (`row`, `col`) is in the block.
    fn contains(&self, row: usize, col: i32) -> bool {
        row >= self.row_lo && row < self.row_hi && col >= self.col_lo && col < self.col_hi
    }

    /// The rows.
    pub fn rows(&self) -> Range<usize> {
        self.row_lo..self.row_hi
    }

    /// The columns.
    pub fn cols(&self) -> Range<i32> {
        self.col_lo..self.col_hi
    }
}

/// One vertex of the footprint loop: a point of the parent's surface with the parent's normal,
/// wind record and bark coordinates interpolated there.
#[derive(Clone, Copy, Debug)]
pub(super) struct FootPoint {
    /// Position (m).
    pub pos: Vec3,
    /// The parent's normal.
    pub normal: Vec3,
    /// The parent's wind record.
    pub wind: [f32; WIND_STRIDE],
    /// The parent's bark `u`, `v`.
    pub uv: [f32; 2],
}

/// Where the child meets the parent: the parent's rows around the footprint, the frames and
/// radii there, and the window of quads the footprint loop is searched in.
pub(super) struct Meeting<'a> {
    /// The parent's ring parameters.
    pub pts: &'a [f32],
    /// The parent's frame at mid-footprint, and its `t` there.
    parent_frame: Frame,
    t_mid: f32,
    /// The child's junction ring's frame.
    pub ring: Frame,
    /// The parent's radius at mid-footprint (m).
    r_mid: f32,
    /// The child's radius at its junction ring (m).
    pub rc: f32,
    /// The parent's length (m).
    r_len: f32,
    /// The quads searched: the rows between the parent's nearest rings below and above the
    /// footprint and the columns it is estimated to cover, with a margin of two rows and two
    /// columns.
    window: Rect,
    /// The parent's first vertex, vertices per ring and sides.
    first: u32,
    stride: u32,
    pub sides: i32,
    /// The angle of one parent column.
    dcol: f32,
}

impl<'a> Meeting<'a> {
    /// The rows between the parent's nearest rings below and above the footprint (`plan_rings`
    /// put them within [`REACH`] footprint lengths of it) and the columns around the child's
    /// azimuth, in the parent's transported frame at mid-footprint. None if the footprint is
    /// not on the parent's tube.
    pub fn new(j: &Join<'a>) -> Option<Meeting<'a>> {
        let (pm, jn) = (j.parent, j.junction);
        let pts = &j.ts[pm.ring0..pm.ring0 + pm.rings as usize];
        let reach = REACH * (jn.t_hi - jn.t_lo) + 1e-5;
        let above = pts.partition_point(|&x| x <= jn.t_lo);
        let rb = pts.partition_point(|&x| x < jn.t_hi);
        if above == 0 || rb >= pts.len() {
            return None;
        }
        let ra = above - 1;
        if jn.t_lo - pts[ra] > reach || pts[rb] - jn.t_hi > reach {
            return None;
        }
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
        let ja = ((phi - beta) / dcol).floor() as i32;
        let jb = (((phi + beta) / dcol).ceil() as i32).max(ja + 1);
        let (ca, cb) = if jb - ja + 4 < sides { (ja - 2, jb + 2) } else { (ja, jb) };
        let window = Rect { row_lo: ra.saturating_sub(2), row_hi: (rb + 2).min(pts.len() - 1), col_lo: ca, col_hi: cb };
        Some(Meeting {
            pts,
            parent_frame: f,
            t_mid,
            ring: jf,
            r_mid,
            rc,
            r_len: j.parent_stem.length.max(1e-6),
            window,
            first: pm.first,
            stride: pm.sides + 1,
            sides,
            dcol,
        })
    }

    /// Where the line from `q` along the child's axis leaves the parent's local cylinder: the
    /// quad (row, column) to look at first.
    fn guess(&self, q: Vec3) -> Option<(usize, i32)> {
        let (f, jf) = (self.parent_frame, self.ring);
        let (t_ax, d) = (f.tangent, jf.tangent);
        let o = q - f.centre;
        let (o, d) = (o - t_ax * o.dot(t_ax), d - t_ax * d.dot(t_ax));
        let (a, b, c) = (d.dot(d), 2.0 * o.dot(d), o.dot(o) - self.r_mid * self.r_mid);
        let disc = b * b - 4.0 * a * c;
        if a < 1e-12 || disc < 0.0 {
            return None;
        }
        let x = q + jf.tangent * ((-b + disc.sqrt()) / (2.0 * a)) - f.centre;
        let t = self.t_mid + x.dot(t_ax) / self.r_len;
        let r = self.pts.partition_point(|&p| p <= t).saturating_sub(1);
        let c = (atan2(x.dot(t_ax.cross(f.normal)), x.dot(f.normal)) / self.dcol).floor() as i32;
        Some((r, c))
    }

    /// The quad's first vertex (`a`; `b` is the next column, `d` the next row).
    fn corner(&self, r: usize, c: i32) -> u32 {
        self.first + r as u32 * self.stride + c.rem_euclid(self.sides) as u32
    }

    /// From quad (`r`, `c`), steps across the grid toward the crossing of the line from `q`
    /// along the child's axis (a few quads at most, within the window).
    fn walk(&self, out: &MeshBuilder, q: Vec3, mut r: usize, mut c: i32) -> Option<Hit> {
        let d = self.ring.tangent;
        for _ in 0..6 {
            if !self.window.contains(r, c) {
                return None;
            }
            let a = self.corner(r, c);
            let (b, c2, e) = (a + 1, a + 1 + self.stride, a + self.stride);
            let (pa, pb, pc, pe) = (out.vertex_at(a).0, out.vertex_at(b).0, out.vertex_at(c2).0, out.vertex_at(e).0);
            let (s, u, v) = line_plane(q, d, [pa, pb, pc])?;
            if u >= 0.0 && v >= 0.0 && u + v <= 1.0 {
                return Some(Hit::new(s, [a, b, c2], u, v, r, c, 0));
            }
            if let Some((s, u2, v2)) = line_plane(q, d, [pa, pc, pe]) {
                if u2 >= 0.0 && v2 >= 0.0 && u2 + v2 <= 1.0 {
                    return Some(Hit::new(s, [a, c2, e], u2, v2, r, c, 1));
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
    }

    /// The triangles of the window's quads (as `emit` writes them: the seam's duplicate column
    /// after the last) that lines along the child's axis leave through their outer side, into
    /// `window` in search order.
    fn fill_window(&self, out: &MeshBuilder, window: &mut Vec<WindowTri>) {
        let d = self.ring.tangent;
        for row in self.window.rows() {
            for col in self.window.cols() {
                let a = self.corner(row, col);
                let (b, c2, e) = (a + 1, a + 1 + self.stride, a + self.stride);
                for (half, tri) in [[a, b, c2], [a, c2, e]].into_iter().enumerate() {
                    if let Some(facing) = Facing::new(d, tri.map(|v| out.vertex_at(v).0)) {
                        window.push(WindowTri { facing, tri, row, col, half });
                    }
                }
            }
        }
    }

    /// The footprint point of the line from `q`: the guess and walk, else the first hit in the
    /// whole window (filled at the first search: most junctions need none).
    fn locate(&self, out: &MeshBuilder, window: &mut Vec<WindowTri>, q: Vec3) -> Option<Hit> {
        let mut best = None;
        if let Some((r, c)) = self.guess(q) {
            best = self.walk(out, q, r, c);
        }
        if best.is_none() {
            if window.is_empty() {
                self.fill_window(out, window);
            }
            best = search(window, q, self.ring.tangent);
        }
        best
    }
}

/// Index of the parent's quad (`r`, `c`) in the claimed-quad bitmap.
pub(super) fn claim_index(j: &Join, r: usize, c: i32) -> usize {
    j.parent.claim + r * j.parent.sides as usize + c.rem_euclid(j.parent.sides as i32) as usize
}

/// Whether no quad of `rows` × `cols` of the parent is claimed yet.
pub(super) fn free(j: &Join, claimed: &[bool], rows: Range<usize>, cols: Range<i32>) -> bool {
    rows.clone().all(|r| cols.clone().all(|c| !claimed[claim_index(j, r, c)]))
}

/// Step 2: the footprint loop into `sc.foot` (and each point's quad into `sc.cells`): for every
/// column of the junction ring, where the line along the child's axis through it, widened to
/// the collar's radius, leaves the parent's surface (less widened where that line misses the
/// parent: a child about as thick as its parent). Returns the quads under the loop; where they
/// are already another junction's, the footprint of the branch itself (no flare) is tried.
/// None when a point is not found or the quads are taken.
pub(super) fn find(j: &Join, m: &Meeting, claimed: &[bool], out: &MeshBuilder, sc: &mut Scratch) -> Option<Rect> {
    let nr = j.child.sides as usize;
    let widen = j.junction.foot / m.rc;
    let jf = m.ring;
    sc.window.clear();
    for first in [widen, 1.0] {
        let mut rect = Rect::EMPTY;
        sc.foot.clear();
        sc.cells.clear();
        for k in 0..nr {
            let p = out.vertex_at(j.child.first + k as u32).0;
            let hit = [first, 1.0, 0.75, 0.5]
                .into_iter()
                .find_map(|w| m.locate(out, &mut sc.window, jf.centre + (p - jf.centre) * w))?;
            sc.cells.push(hit.cell);
            rect.include(hit.cell.row, hit.cell.col);
            sc.foot.push(foot_point(out, &hit, jf.tangent));
        }
        if free(j, claimed, rect.rows(), rect.cols()) {
            return Some(rect);
        }
        if first <= 1.0 {
            return None;
        }
    }
    None
}

/// The footprint point of `hit`, a little inside its triangle (never on a parent vertex or
/// edge): the parent's pivot, level and phase as they are; normal, stiffness, distance, radius
/// and `uv` interpolated, since the footprint loop is part of the parent's surface.
fn foot_point(out: &MeshBuilder, hit: &Hit, axis: Vec3) -> FootPoint {
    let t = hit.tri;
    let bary = hit.bary * 0.98 + Vec3::splat(0.02 / 3.0);
    let mix = |x: Vec3, y: Vec3, z: Vec3| x * bary.x + y * bary.y + z * bary.z;
    let ((pa, na), (pb, nb), (pc, nc)) = (out.vertex_at(t[0]), out.vertex_at(t[1]), out.vertex_at(t[2]));
    let (wa, wb, wc) = (out.wind_at(t[0]), out.wind_at(t[1]), out.wind_at(t[2]));
    let wind =
        std::array::from_fn(
            |k| {
                if k < WIND_STIFFNESS {
                    wa[k]
                } else {
                    wa[k] * bary.x + wb[k] * bary.y + wc[k] * bary.z
                }
            },
        );
    let (ua, ub, uc) = (out.uv_at(t[0]), out.uv_at(t[1]), out.uv_at(t[2]));
    FootPoint {
        pos: mix(pa, pb, pc),
        normal: unit_or(mix(na, nb, nc), || axis),
        wind,
        uv: [0, 1].map(|k| ua[k] * bary.x + ub[k] * bary.y + uc[k] * bary.z),
    }
}
