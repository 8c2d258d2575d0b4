//! Step 5 of a welded junction (see [`super`]): the hole in the parent is zipped to the
//! footprint loop. In the parent's own surface coordinates (around × along, in metres) the hole
//! is a rectangle and the footprint loop a closed curve inside it. Both are ordered by angle
//! around the footprint's centre, starting from the hole's vertex of smallest angle; both run
//! counter-clockwise, each step advances the loop whose next vertex comes first, unless that
//! triangle would turn the wrong way and the other would not; one triangle per step, so every
//! edge of both loops is used exactly once. These triangles lie on the parent's facets.

use super::footprint::{Rect, Scratch};
use super::wrap;
use crate::math::TAU;
use crate::mesh::junction::Join;
use glam::Vec2;

/// Step 5: the hole over the parent's quads `hole`, zipped to the footprint loop
/// (written at `first_new`); its triangles are appended to `sc.tris`. The zip works in the
/// parent's own surface coordinates (around, along; metres), where the hole is a rectangle and
/// the footprint loop a closed curve inside it. False if the footprint loop does not turn
/// monotonically around its centre there, or the zip would fold.
pub(super) fn zip_hole(sc: &mut Scratch, j: &Join, hole: Rect, first_new: u32) -> bool {
    let Rect { row_lo: ra, row_hi: rb, col_lo: ja, col_hi: jb } = hole;
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
    sc.foot_flat.extend(sc.cells.iter().map(|cell| at(cell.row, cell.col as f32 + cell.at.x, cell.at.y)));
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
        let a = sc.ring[wrap(kstar + k, nr)];
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
    let hole_at = |i: usize| sc.flat[wrap(i, l)];
    let foot_at = |k: usize| sc.foot_flat[wrap(column(k), nr)];
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
            sc.tris.extend_from_slice(&[sc.hole[i], sc.hole[wrap(i + 1, l)], first_new + column(k) as u32]);
            i += 1;
        } else {
            sc.tris.extend_from_slice(&[
                sc.hole[wrap(i, l)],
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
