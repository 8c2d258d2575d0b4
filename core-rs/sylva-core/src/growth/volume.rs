//! Growth volumes (the SCA add-on's groups): the **crown** holds the markers (an ellipsoid, or
//! one of the eight crown envelopes as a solid of revolution, same ShapeRatio as the parametric
//! model, or a crown outline drawn by hand, revolved); the **shadow** group holds no markers; the **exclusion** group stops branches at its
//! surface. An optional wall box is both: nothing grows into it, and markers it hides from the
//! sky are removed, so the tree grows away from it.

use crate::edits::crown::DrawnCrown;
use crate::params::{CrownShape, Primitive};
use crate::rng::Rng;
use glam::Vec3;

/// Lowest height a growing branch may reach (m): branches do not grow into the soil.
pub const GROUND_CLEARANCE: f32 = 0.1;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Smallest corner.
    pub min: Vec3,
    /// Largest corner.
    pub max: Vec3,
}

impl Aabb {
    /// Whether `p` is inside (or on) the box.
    pub fn contains(&self, p: Vec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// Whether the ray `o + t d`, `t > 0`, hits the box (slab test).
    pub fn hit_by_ray(&self, o: Vec3, d: Vec3) -> bool {
        let inv = d.recip();
        let t1 = (self.min - o) * inv;
        let t2 = (self.max - o) * inv;
        let near = t1.min(t2).max_element();
        let far = t1.max(t2).min_element();
        far >= near.max(0.0)
    }

    /// Whether the segment from `a` to `b` touches the box.
    pub fn hit_by_segment(&self, a: Vec3, b: Vec3) -> bool {
        let d = b - a;
        let inv = d.recip();
        let t1 = (self.min - a) * inv;
        let t2 = (self.max - a) * inv;
        let near = t1.min(t2).max_element();
        let far = t1.max(t2).min_element();
        far >= near.max(0.0) && near <= 1.0
    }
}

/// The shape of the crown volume.
#[derive(Clone, Debug, PartialEq)]
pub enum CrownVolume {
    /// An ellipsoid of horizontal radius `radius` and height `height`, bottom at `base`.
    Ellipsoid {
        /// Bottom of the crown above the ground (m).
        base: f32,
        /// Height of the crown (m).
        height: f32,
        /// Horizontal radius (m).
        radius: f32,
    },
    /// A crown envelope as a solid of revolution: radius `radius * ShapeRatio(shape, r)` with
    /// `r = 1` at the crown base and 0 at the top.
    Envelope {
        /// Bottom of the crown above the ground (m).
        base: f32,
        /// Height of the crown (m).
        height: f32,
        /// Largest horizontal radius (m).
        radius: f32,
        /// Which envelope.
        shape: CrownShape,
    },
    /// A crown outline drawn by hand, revolved about the trunk axis (`crate::edits::crown`).
    Drawn(DrawnCrown),
}

impl CrownVolume {
    /// Horizontal radius of the volume at height `y` (0 outside its height range).
    pub fn radius_at(&self, y: f32) -> f32 {
        match *self {
            CrownVolume::Ellipsoid { base, height, radius } => {
                let h = (y - base) / height * 2.0 - 1.0;
                if h.abs() > 1.0 {
                    0.0
                } else {
                    radius * (1.0 - h * h).sqrt()
                }
            }
            CrownVolume::Envelope { base, height, radius, shape } => {
                let f = (y - base) / height;
                if !(0.0..=1.0).contains(&f) {
                    0.0
                } else {
                    radius * shape.ratio(1.0 - f)
                }
            }
            CrownVolume::Drawn(ref d) => d.width_at(y),
        }
    }

    /// Bounding box.
    pub fn bounds(&self) -> Aabb {
        let (base, height, radius) = match *self {
            CrownVolume::Ellipsoid { base, height, radius } | CrownVolume::Envelope { base, height, radius, .. } => {
                (base, height, radius)
            }
            CrownVolume::Drawn(ref d) => {
                let (min, max) = d.bounds();
                return Aabb { min, max };
            }
        };
        Aabb { min: Vec3::new(-radius, base, -radius), max: Vec3::new(radius, base + height, radius) }
    }

    /// Whether `p` is inside.
    pub fn contains(&self, p: Vec3) -> bool {
        if let CrownVolume::Drawn(d) = self {
            return d.contains(p);
        }
        let r = self.radius_at(p.y);
        p.x * p.x + p.z * p.z <= r * r
    }
}

impl Primitive {
    /// Whether `p` is inside (or on) the primitive.
    pub fn contains(&self, p: Vec3) -> bool {
        match *self {
            Primitive::Sphere { centre, radius } => p.distance_squared(centre) <= radius * radius,
            Primitive::Box { centre, size } => (p - centre).abs().cmple(0.5 * size).all(),
            Primitive::Cylinder { centre, radius, height } => {
                let d = p - centre;
                d.y.abs() <= 0.5 * height && d.x * d.x + d.z * d.z <= radius * radius
            }
        }
    }

    /// Bounding box.
    pub fn bounds(&self) -> Aabb {
        let (c, h) = match *self {
            Primitive::Sphere { centre, radius } => (centre, Vec3::splat(radius)),
            Primitive::Box { centre, size } => (centre, 0.5 * size),
            Primitive::Cylinder { centre, radius, height } => (centre, Vec3::new(radius, 0.5 * height, radius)),
        };
        Aabb { min: c - h, max: c + h }
    }

    /// Normalised depth of `p` from the centre (0 at the centre, 1 on the surface; for the
    /// surface bias of markers in a primitive crown).
    pub fn depth(&self, p: Vec3) -> f32 {
        match *self {
            Primitive::Sphere { centre, radius } => p.distance(centre) / radius,
            Primitive::Box { centre, size } => ((p - centre).abs() / (0.5 * size)).max_element(),
            Primitive::Cylinder { centre, radius, height } => {
                let d = p - centre;
                ((d.x * d.x + d.z * d.z).sqrt() / radius).max(d.y.abs() / (0.5 * height))
            }
        }
    }

    /// Whether the segment from `a` to `b` touches the primitive: exact for spheres and boxes,
    /// for cylinders the closest approach to the axis within the slab, sampled every tenth.
    pub fn hit_by_segment(&self, a: Vec3, b: Vec3) -> bool {
        match *self {
            Primitive::Sphere { centre, radius } => {
                let d = b - a;
                let len2 = d.length_squared();
                let t = if len2 > 0.0 { ((centre - a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
                (a + d * t).distance_squared(centre) <= radius * radius
            }
            Primitive::Box { .. } => self.bounds().hit_by_segment(a, b) || self.contains(a),
            Primitive::Cylinder { .. } => (0..=10).any(|k| self.contains(a.lerp(b, k as f32 / 10.0))),
        }
    }
}

/// Everything that shapes where markers are and where branches may go.
#[derive(Clone, Debug)]
pub struct Environment {
    /// Where the markers are.
    pub crown: CrownVolume,
    /// Offsets of extra copies of the crown (hedgerows: one crown per start point).
    pub crown_offsets: Vec<Vec3>,
    /// Boxes that hold no markers (the shadow group).
    pub shadow: Vec<Aabb>,
    /// Boxes that branches stop at (the exclusion group).
    pub exclusion: Vec<Aabb>,
    /// Boxes that block light from the sky: markers that see too little sky past them are removed.
    pub occluders: Vec<Aabb>,
    /// User crown group: when not empty, the crown is the union of these (and `crown` is unused).
    pub crown_union: Vec<Primitive>,
    /// User shadow group: no markers inside.
    pub shadow_prims: Vec<Primitive>,
    /// User exclusion group: no markers inside, and branches stop at their surface.
    pub exclusion_prims: Vec<Primitive>,
}

/// Sky directions used for the occluder test: straight up and eight at 45° elevation.
fn sky_directions() -> [Vec3; 9] {
    let d = std::f32::consts::FRAC_1_SQRT_2;
    let mut out = [Vec3::Y; 9];
    for (k, slot) in out.iter_mut().enumerate().skip(1) {
        let a = crate::math::TAU * (k - 1) as f32 / 8.0;
        *slot = Vec3::new(d * crate::math::cos(a), d, d * crate::math::sin(a));
    }
    out
}

impl Environment {
    /// Whether a marker may exist at `p`: inside a crown copy, outside every shadow box and
    /// exclusion box, and seeing at least 7 of the 9 sky directions past the occluders.
    pub fn marker_allowed(&self, p: Vec3) -> bool {
        let in_crown = self.crown_offsets.iter().any(|o| self.crown_contains(p - *o));
        if !in_crown || self.shadow.iter().chain(&self.exclusion).any(|b| b.contains(p)) {
            return false;
        }
        if self.shadow_prims.iter().chain(&self.exclusion_prims).any(|v| v.contains(p)) {
            return false;
        }
        if self.occluders.is_empty() {
            return true;
        }
        let blocked = sky_directions().iter().filter(|d| self.occluders.iter().any(|b| b.hit_by_ray(p, **d))).count();
        blocked <= 2
    }

    /// Whether a branch may grow from `a` to `b`: it stops at exclusion boxes and never grows
    /// closer to the ground than [`GROUND_CLEARANCE`] unless it rises (the trunk starts on the
    /// ground, and with an Internode under the clearance its first steps end below it).
    pub fn segment_allowed(&self, a: Vec3, b: Vec3) -> bool {
        (b.y >= GROUND_CLEARANCE || b.y > a.y)
            && !self.exclusion.iter().any(|x| x.hit_by_segment(a, b))
            && !self.exclusion_prims.iter().any(|x| x.hit_by_segment(a, b))
    }

    /// Whether `p` (relative to a crown copy's offset) is in the crown: the user crown group's
    /// union when there is one, else the parametric crown.
    pub fn crown_contains(&self, p: Vec3) -> bool {
        if self.crown_union.is_empty() {
            self.crown.contains(p)
        } else {
            self.crown_union.iter().any(|v| v.contains(p))
        }
    }

    /// Bounding box of one crown copy (before its offset).
    pub fn crown_bounds(&self) -> Aabb {
        if self.crown_union.is_empty() {
            return self.crown.bounds();
        }
        let mut out = Aabb { min: Vec3::splat(f32::INFINITY), max: Vec3::splat(f32::NEG_INFINITY) };
        for v in &self.crown_union {
            let b = v.bounds();
            out.min = out.min.min(b.min);
            out.max = out.max.max(b.max);
        }
        out
    }

    /// Bounding box of all crown copies.
    pub fn bounds(&self) -> Aabb {
        let b = self.crown_bounds();
        let mut out = Aabb { min: Vec3::splat(f32::INFINITY), max: Vec3::splat(f32::NEG_INFINITY) };
        for o in &self.crown_offsets {
            out.min = out.min.min(b.min + *o);
            out.max = out.max.max(b.max + *o);
        }
        out
    }

    /// Sample up to `count` markers by rejection: uniform in the crown, then kept with a weight
    /// for `surface_bias` (-1: toward the axis, 1: toward the surface) and `top_bias` (-1: toward
    /// the bottom, 1: toward the top). Gives up after `50 * count` candidates (a crown hidden by
    /// shadow boxes yields fewer markers, never a hang).
    pub fn sample_markers(&self, count: usize, surface_bias: f32, top_bias: f32, rng: &mut Rng) -> Vec<Vec3> {
        let b = self.crown_bounds();
        let (base, height) = (b.min.y, b.max.y - b.min.y);
        let mut out = Vec::with_capacity(count);
        let mut tries = 0usize;
        while out.len() < count && tries < 50 * count.max(1) {
            tries += 1;
            let o = self.crown_offsets[rng.next_u32() as usize % self.crown_offsets.len()];
            let local =
                Vec3::new(rng.uniform(b.min.x, b.max.x), rng.uniform(b.min.y, b.max.y), rng.uniform(b.min.z, b.max.z));
            let keep = rng.next_f32();
            let rho = if self.crown_union.is_empty() {
                if !self.crown.contains(local) {
                    continue;
                }
                let rmax = self.crown.radius_at(local.y).max(1e-6);
                ((local.x * local.x + local.z * local.z).sqrt() / rmax).min(1.0)
            } else {
                match self.crown_union.iter().find(|v| v.contains(local)) {
                    Some(v) => v.depth(local).min(1.0),
                    None => continue,
                }
            };
            let h = ((local.y - base) / height).clamp(0.0, 1.0);
            let weight = bias(rho, surface_bias) * bias(h, top_bias);
            let p = local + o;
            if keep < weight && self.marker_allowed(p) {
                out.push(p);
            }
        }
        out
    }
}

/// Acceptance weight in [0, 1] for a position `x` in [0, 1]: `x^(4b)` toward 1 for positive `b`,
/// `(1 - x)^(-4b)` toward 0 for negative `b`, 1 for `b = 0`.
fn bias(x: f32, b: f32) -> f32 {
    if b > 0.0 {
        crate::math::pow(x, 4.0 * b)
    } else if b < 0.0 {
        crate::math::pow(1.0 - x, -4.0 * b)
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env() -> Environment {
        Environment {
            crown: CrownVolume::Ellipsoid { base: 2.0, height: 6.0, radius: 3.0 },
            crown_offsets: vec![Vec3::ZERO],
            shadow: vec![Aabb { min: Vec3::new(0.0, 0.0, -5.0), max: Vec3::new(5.0, 20.0, 5.0) }],
            exclusion: vec![],
            occluders: vec![],
            crown_union: vec![],
            shadow_prims: vec![],
            exclusion_prims: vec![],
        }
    }

    #[test]
    fn markers_lie_in_crown_minus_shadow() {
        let e = env();
        let m = e.sample_markers(3000, 0.0, 0.0, &mut Rng::new(1, "t"));
        assert!(m.len() > 1000);
        for p in &m {
            assert!(e.crown.contains(*p) && p.x < 0.0, "{p}");
        }
    }

    #[test]
    fn biases_move_the_markers() {
        let e = Environment { shadow: vec![], ..env() };
        let mean_rho = |sb: f32| {
            let m = e.sample_markers(2000, sb, 0.0, &mut Rng::new(2, "t"));
            m.iter().map(|p| (p.x * p.x + p.z * p.z).sqrt() / e.crown.radius_at(p.y)).sum::<f32>() / m.len() as f32
        };
        assert!(mean_rho(1.0) > mean_rho(0.0) + 0.1 && mean_rho(-1.0) < mean_rho(0.0) - 0.1);
        let mean_y = |tb: f32| {
            let m = e.sample_markers(2000, 0.0, tb, &mut Rng::new(3, "t"));
            m.iter().map(|p| p.y).sum::<f32>() / m.len() as f32
        };
        assert!(mean_y(1.0) > mean_y(0.0) + 0.5);
    }

    #[test]
    fn ray_and_segment_tests() {
        let b = Aabb { min: Vec3::new(-1.0, 0.0, -1.0), max: Vec3::new(1.0, 2.0, 1.0) };
        assert!(b.hit_by_ray(Vec3::new(0.0, -1.0, 0.0), Vec3::Y));
        assert!(!b.hit_by_ray(Vec3::new(0.0, 3.0, 0.0), Vec3::Y));
        assert!(b.hit_by_segment(Vec3::new(-2.0, 1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)));
        assert!(!b.hit_by_segment(Vec3::new(-3.0, 1.0, 0.0), Vec3::new(-2.0, 1.0, 0.0)));
    }

    #[test]
    fn primitives_contain_and_block_segments() {
        let s = Primitive::Sphere { centre: Vec3::new(0.0, 5.0, 0.0), radius: 2.0 };
        assert!(s.contains(Vec3::new(1.9, 5.0, 0.0)) && !s.contains(Vec3::new(1.5, 6.5, 0.0)));
        assert!(s.hit_by_segment(Vec3::new(-5.0, 5.0, 0.0), Vec3::new(5.0, 5.0, 0.0)));
        assert!(!s.hit_by_segment(Vec3::new(-5.0, 7.5, 0.0), Vec3::new(5.0, 7.5, 0.0)));
        let b = Primitive::Box { centre: Vec3::new(1.0, 1.0, 1.0), size: Vec3::new(2.0, 4.0, 6.0) };
        assert!(b.contains(Vec3::new(1.9, 2.9, 3.9)) && !b.contains(Vec3::new(2.1, 1.0, 1.0)));
        assert!(b.hit_by_segment(Vec3::new(-3.0, 1.0, 1.0), Vec3::new(5.0, 1.0, 1.0)));
        assert!(b.hit_by_segment(Vec3::new(1.0, 1.0, 1.0), Vec3::new(1.1, 1.0, 1.0)), "inside");
        let c = Primitive::Cylinder { centre: Vec3::new(0.0, 2.0, 0.0), radius: 1.0, height: 2.0 };
        assert!(c.contains(Vec3::new(0.7, 2.9, 0.7)) && !c.contains(Vec3::new(0.0, 3.1, 0.0)));
        assert!(!c.contains(Vec3::new(0.8, 2.0, 0.8)));
        assert!(c.hit_by_segment(Vec3::new(-2.0, 2.0, 0.0), Vec3::new(2.0, 2.0, 0.0)));
        assert!(!c.hit_by_segment(Vec3::new(-2.0, 4.0, 0.0), Vec3::new(2.0, 4.0, 0.0)));
        assert_eq!(c.bounds(), Aabb { min: Vec3::new(-1.0, 1.0, -1.0), max: Vec3::new(1.0, 3.0, 1.0) });
    }

    #[test]
    fn markers_lie_in_the_crown_union_minus_shadow_primitives() {
        let a = Primitive::Sphere { centre: Vec3::new(-2.0, 5.0, 0.0), radius: 1.5 };
        let b = Primitive::Box { centre: Vec3::new(2.0, 5.0, 0.0), size: Vec3::splat(2.0) };
        let shadow = Primitive::Cylinder { centre: Vec3::new(-2.0, 5.0, 0.0), radius: 0.7, height: 10.0 };
        let e = Environment { shadow: vec![], crown_union: vec![a, b], shadow_prims: vec![shadow], ..env() };
        let m = e.sample_markers(2000, 0.0, 0.0, &mut Rng::new(4, "t"));
        assert!(m.len() > 1000);
        assert!(m.iter().any(|p| a.contains(*p)) && m.iter().any(|p| b.contains(*p)));
        for p in &m {
            assert!((a.contains(*p) || b.contains(*p)) && !shadow.contains(*p), "{p}");
        }
    }
}
