//! Small 2D geometry shared by the leaf stages: orientation and area in `f64` over `f32` points
//! (the differences and products are exact, so signs are reliable), point-in-polygon by the
//! crossing rule, and point-segment distance.

use glam::Vec2;

/// Twice the signed area of triangle `a, b, c`: positive when counter-clockwise.
#[inline]
pub fn orient(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    let (ax, ay) = (f64::from(a.x), f64::from(a.y));
    (f64::from(b.x) - ax) * (f64::from(c.y) - ay) - (f64::from(b.y) - ay) * (f64::from(c.x) - ax)
}

/// Signed area of a closed polygon (counter-clockwise positive).
pub fn polygon_area(poly: &[Vec2]) -> f64 {
    let n = poly.len();
    let mut sum = 0.0;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        sum += f64::from(a.x) * f64::from(b.y) - f64::from(b.x) * f64::from(a.y);
    }
    0.5 * sum
}

/// Whether `p` lies inside the closed polygon (crossing rule; points exactly on an edge may go
/// either way).
pub fn point_in_polygon(p: Vec2, poly: &[Vec2]) -> bool {
    let n = poly.len();
    let mut inside = false;
    let mut j = n - 1;
    for i in 0..n {
        let (a, b) = (poly[i], poly[j]);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
        j = i;
    }
    inside
}

/// Distance from `p` to the segment `a, b`.
#[inline]
pub fn dist_to_segment(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 { ((p - a).dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + ab * t)).length()
}

/// Smallest distance from `p` to the closed polygon's edges.
pub fn dist_to_polygon(p: Vec2, poly: &[Vec2]) -> f32 {
    let n = poly.len();
    (0..n).map(|i| dist_to_segment(p, poly[i], poly[(i + 1) % n])).fold(f32::INFINITY, f32::min)
}

/// Axis-aligned bounds `(min, max)` of a point set (zero box when empty).
pub fn bounds(points: &[Vec2]) -> (Vec2, Vec2) {
    if points.is_empty() {
        return (Vec2::ZERO, Vec2::ZERO);
    }
    points
        .iter()
        .fold((Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY)), |(lo, hi), &p| (lo.min(p), hi.max(p)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_area_orientation_and_inside() {
        let sq = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0)];
        assert_eq!(polygon_area(&sq), 1.0);
        assert!(orient(sq[0], sq[1], sq[2]) > 0.0);
        assert!(point_in_polygon(Vec2::new(0.5, 0.5), &sq));
        assert!(!point_in_polygon(Vec2::new(1.5, 0.5), &sq));
        assert!((dist_to_polygon(Vec2::new(0.5, 0.25), &sq) - 0.25).abs() < 1e-6);
    }
}

/// A 2D vector in `f64` for the outline curves (glam is built without its `f64` types).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DVec2 {
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
}

impl DVec2 {
    /// `(0, 0)`.
    pub const ZERO: DVec2 = DVec2 { x: 0.0, y: 0.0 };

    /// A vector from its components.
    #[inline]
    pub const fn new(x: f64, y: f64) -> DVec2 {
        DVec2 { x, y }
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: DVec2) -> f64 {
        self.x * o.x + self.y * o.y
    }
    /// Squared length.
    #[inline]
    pub fn length_squared(self) -> f64 {
        self.dot(self)
    }
    /// Length.
    #[inline]
    pub fn length(self) -> f64 {
        self.length_squared().sqrt()
    }
    /// Rounded to `f32`.
    #[inline]
    pub fn as_vec2(self) -> Vec2 {
        Vec2::new(self.x as f32, self.y as f32)
    }
    /// Widened from `f32`.
    #[inline]
    pub fn from_vec2(v: Vec2) -> DVec2 {
        DVec2::new(f64::from(v.x), f64::from(v.y))
    }
}

impl std::ops::Add for DVec2 {
    type Output = DVec2;
    #[inline]
    fn add(self, o: DVec2) -> DVec2 {
        DVec2::new(self.x + o.x, self.y + o.y)
    }
}

impl std::ops::Sub for DVec2 {
    type Output = DVec2;
    #[inline]
    fn sub(self, o: DVec2) -> DVec2 {
        DVec2::new(self.x - o.x, self.y - o.y)
    }
}

impl std::ops::Mul<f64> for DVec2 {
    type Output = DVec2;
    #[inline]
    fn mul(self, s: f64) -> DVec2 {
        DVec2::new(self.x * s, self.y * s)
    }
}
