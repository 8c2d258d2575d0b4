//! Draw the crown: a closed outline drawn from the side, `[radius, height]` pairs in metres, is
//! **revolved about the trunk axis** (the vertical line through the origin, tree space). The
//! revolution (rather than an extrusion in depth) keeps the crown round from every side, as the
//! eight Weber & Penn envelopes and the growth volumes are, so the tree looks like the drawing
//! from whichever side it was drawn. A point is in the drawn crown when its distance from the
//! axis and its height, `(ρ, y)`, lie inside the outline polygon (even-odd rule; the closing edge
//! from the last point back to the first is implied).
//!
//! Two uses:
//! * **Weber & Penn** (Crown Shape *Drawn*): the ShapeRatio of a level-1 branch is the outline's
//!   widest radius at the height of its attachment point, relative to the outline's widest
//!   radius anywhere ([`DrawnCrown::ratio_at_height`]). The height is the attachment point's real
//!   height in metres, so the branches grow where the outline was drawn: the crown starts no lower
//!   and ends no higher than the outline (branches below or above it get ratio 0, and a branch
//!   shorter than its own thickness is not built). Without a crown edit the Drawn shape is
//!   Cylindrical (ratio 1), so the parameter alone never fails.
//! * **Grown trees**: the crown markers fill the solid of revolution ([`DrawnCrown::contains`]),
//!   in place of the parametric crown (ellipsoid or envelope) whatever Crown Volume says; the
//!   user's crown-group primitives, when Crown Volume is Primitives and there are some, still win.
//!
//! Validation of an outline (enough points, finite, in range, not crossing itself) belongs to the
//! edit list's validation, which calls [`self_crossing`]; [`DrawnCrown::new`] only refuses what it
//! cannot use.

use crate::params::Crown;
use glam::{Vec2, Vec3};

/// A crown outline ready for queries: the polygon and its extent.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawnCrown {
    outline: Vec<Vec2>,
    widest: f32,
    lo: f32,
    hi: f32,
}

impl DrawnCrown {
    /// The drawn crown of `crown`, or None when the outline cannot hold anything: fewer than three
    /// points, a coordinate that is not finite, or no point away from the axis.
    pub fn new(crown: &Crown) -> Option<DrawnCrown> {
        let outline = crown.outline.clone();
        if outline.len() < 3 || outline.iter().any(|p| !p.is_finite()) {
            return None;
        }
        let widest = outline.iter().map(|p| p.x).fold(0.0f32, f32::max);
        let lo = outline.iter().map(|p| p.y).fold(f32::INFINITY, f32::min);
        let hi = outline.iter().map(|p| p.y).fold(f32::NEG_INFINITY, f32::max);
        (widest > 0.0 && hi > lo).then_some(DrawnCrown { outline, widest, lo, hi })
    }

    /// The outline's points, `[radius, height]`.
    pub fn outline(&self) -> &[Vec2] {
        &self.outline
    }

    /// The closed outline's edges, the closing edge last.
    fn edges(&self) -> impl Iterator<Item = (Vec2, Vec2)> + '_ {
        let n = self.outline.len();
        (0..n).map(move |i| (self.outline[i], self.outline[(i + 1) % n]))
    }

    /// The outline's widest radius at height `y` (m): the largest radius where the horizontal
    /// line at `y` meets the outline, 0 above or below it.
    pub fn width_at(&self, y: f32) -> f32 {
        let mut w = 0.0f32;
        for (a, b) in self.edges() {
            if y < a.y.min(b.y) || y > a.y.max(b.y) {
                continue;
            }
            let x = if a.y == b.y { a.x.max(b.x) } else { a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y) };
            w = w.max(x);
        }
        w
    }

    /// The Drawn ShapeRatio at height `y` (m): [`DrawnCrown::width_at`] relative to the widest
    /// radius of the whole outline, in [0, 1].
    pub fn ratio_at_height(&self, y: f32) -> f32 {
        (self.width_at(y) / self.widest).clamp(0.0, 1.0)
    }

    /// The widest radius of the outline (m).
    pub fn widest(&self) -> f32 {
        self.widest
    }

    /// Lowest and highest height of the outline (m).
    pub fn heights(&self) -> (f32, f32) {
        (self.lo, self.hi)
    }

    /// Whether `p` (tree space) is inside the solid of revolution.
    pub fn contains(&self, p: Vec3) -> bool {
        let q = Vec2::new((p.x * p.x + p.z * p.z).sqrt(), p.y);
        let mut inside = false;
        for (a, b) in self.edges() {
            if (a.y > q.y) != (b.y > q.y) {
                let x = a.x + (b.x - a.x) * (q.y - a.y) / (b.y - a.y);
                if q.x < x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Bounding box of the solid of revolution: smallest and largest corner.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        (Vec3::new(-self.widest, self.lo, -self.widest), Vec3::new(self.widest, self.hi, self.widest))
    }
}

/// The marker volume of a drawn outline for a grown tree: whether a point lies in the outline's
/// solid of revolution (always false for an outline [`DrawnCrown::new`] refuses).
pub fn drawn_volume(outline: &[Vec2]) -> impl Fn(Vec3) -> bool {
    let drawn = DrawnCrown::new(&Crown { outline: outline.to_vec() });
    move |p| drawn.as_ref().is_some_and(|d| d.contains(p))
}

/// The first pair of edges `(i, j)`, `i < j`, of the closed outline that cross or touch, where
/// edge `i` runs from point `i` to point `i + 1` (the last edge back to point 0); None for a simple
/// polygon. Neighbouring edges share a point and count only when they fold back over each other.
pub fn self_crossing(outline: &[Vec2]) -> Option<(usize, usize)> {
    let n = outline.len();
    if n < 3 {
        return None;
    }
    let edge = |i: usize| (outline[i], outline[(i + 1) % n]);
    for i in 0..n {
        for j in i + 1..n {
            let (a, b) = edge(i);
            let (c, d) = edge(j);
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            let hit = if adjacent {
                // The shared point is b (j = i + 1) or a (the closing edge); the two edges fold
                // back when they are collinear and leave the shared point the same way.
                let (shared, u, v) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                let (du, dv) = (u - shared, v - shared);
                du.perp_dot(dv) == 0.0 && du.dot(dv) > 0.0
            } else {
                segments_meet(a, b, c, d)
            };
            if hit {
                return Some((i, j));
            }
        }
    }
    None
}

/// Whether segments `ab` and `cd` share a point (crossing, touching or overlapping), computed in
/// f64 so nearly parallel edges are judged reliably.
fn segments_meet(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> bool {
    let orient = |p: Vec2, q: Vec2, r: Vec2| {
        let v = (f64::from(q.x) - f64::from(p.x)) * (f64::from(r.y) - f64::from(p.y))
            - (f64::from(q.y) - f64::from(p.y)) * (f64::from(r.x) - f64::from(p.x));
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    };
    let on = |p: Vec2, q: Vec2, r: Vec2| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    if o1 != o2 && o3 != o4 {
        return true;
    }
    (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(p: &[[f32; 2]]) -> Vec<Vec2> {
        p.iter().map(|&[x, y]| Vec2::new(x, y)).collect()
    }

    #[test]
    fn self_crossing_finds_a_bow_tie_and_accepts_convex_outlines() {
        let bow_tie = v(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
        assert_eq!(self_crossing(&bow_tie), Some((0, 2)));
        let convex = v(&[[0.0, 2.0], [2.5, 4.0], [2.0, 8.0], [0.0, 9.0]]);
        assert_eq!(self_crossing(&convex), None);
        let concave = v(&[[0.0, 1.0], [3.0, 2.0], [1.0, 4.0], [3.0, 6.0], [0.0, 7.0]]);
        assert_eq!(self_crossing(&concave), None);
        // A spike that doubles back on itself, and a figure eight touching at a point.
        assert!(self_crossing(&v(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 2.0]])).is_some());
        assert!(self_crossing(&v(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [2.0, 2.0], [1.0, 1.0], [0.0, 2.0]])).is_some());
    }

    #[test]
    fn width_ratio_and_containment_follow_the_outline() {
        let d = DrawnCrown::new(&Crown { outline: v(&[[0.0, 2.0], [2.5, 4.0], [2.0, 8.0], [0.0, 9.0]]) }).unwrap();
        assert_eq!(d.width_at(4.0), 2.5);
        assert!((d.width_at(6.0) - 2.25).abs() < 1e-6);
        assert_eq!(d.width_at(1.0), 0.0);
        assert_eq!(d.ratio_at_height(4.0), 1.0);
        assert!((d.ratio_at_height(8.5) - 1.0 / 2.5).abs() < 1e-6);
        assert!(d.contains(Vec3::new(1.5, 4.0, 1.5)) && !d.contains(Vec3::new(2.0, 4.0, 2.0)));
        assert!(!d.contains(Vec3::new(0.0, 1.0, 0.0)) && d.contains(Vec3::new(0.0, 5.0, 0.1)));
        let inside = drawn_volume(d.outline());
        assert!(inside(Vec3::new(0.0, 5.0, 1.0)) && !inside(Vec3::new(0.0, 9.5, 0.0)));
        assert!(DrawnCrown::new(&Crown { outline: v(&[[0.0, 0.0], [0.0, 1.0], [0.0, 2.0]]) }).is_none());
        assert!(DrawnCrown::new(&Crown { outline: v(&[[1.0, 0.0], [f32::NAN, 1.0], [0.0, 2.0]]) }).is_none());
    }
}
