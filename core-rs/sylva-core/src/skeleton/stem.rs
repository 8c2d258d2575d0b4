//! One stem of the skeleton: its centre polyline, radius profile (Weber & Penn taper and trunk
//! flare, or per-point radii from the pipe model) and the smooth centre curve the mesher follows.

use crate::math::{pow, unit_or};
use glam::Vec3;

/// A stem's centre polyline (inline storage for up to four points).
pub type Points = smallvec::SmallVec<[Vec3; 4]>;

/// What a stem is in the tree. The skeleton records it, so later stages read it instead of
/// re-deriving it from the parameters or the stem order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum StemKind {
    /// A trunk: the first stem of a Weber & Penn tree, or a grown tree's stem from a start point.
    Trunk,
    /// A child of another stem (a branch of any level, a grown tree's side shoot).
    Branch,
    /// A clone made by a segment or base split: it continues the stem it split from (its parent),
    /// at the same level.
    SplitClone,
    /// A surface root leaving the trunk base; roots come after every other stem.
    Root,
}

/// One stem: the trunk, a branch or a twig.
#[derive(Clone, Debug)]
pub struct Stem {
    /// What the stem is: trunk, branch, split clone or root.
    pub kind: StemKind,
    /// 0 = trunk, 1 = branches on the trunk, ...
    pub level: u8,
    /// Index of the parent stem in [`Skeleton::stems`](super::Skeleton::stems).
    pub parent: Option<u32>,
    /// Distance along the parent where this stem starts (m).
    pub offset: f32,
    /// Centre polyline from base to tip: `curve_res + 1` points, equally spaced along the stem.
    /// Stored inline up to four points: most stems are short twigs, and this saves an
    /// allocation for each of them.
    pub points: Points,
    /// A unit vector perpendicular to the first segment: the reference for ring orientation.
    pub base_normal: Vec3,
    /// Length of this record (m).
    pub length: f32,
    /// Radius at the base of this record before flare (m).
    pub radius: f32,
    /// Weber & Penn `nTaper` of this stem's level.
    pub taper: f32,
    /// Trunk flare (0 for branches).
    pub flare: f32,
    /// Down angle from the parent (degrees; 0 for the trunk).
    pub down_angle: f32,
    /// Length of the whole Weber & Penn stem this record belongs to (differs for split clones).
    pub chain_length: f32,
    /// Base radius of the whole stem.
    pub chain_radius: f32,
    /// Fraction of the whole stem where this record starts (0, or the split point of a clone).
    pub chain_start: f32,
    /// True for the trunk record (kind [`StemKind::Trunk`] of a Weber & Penn tree), which carries
    /// the Lobes.
    pub lobed: bool,
    /// Radius at each of [`Stem::points`] when the profile is given point by point (grown
    /// trees, pipe model) instead of by Weber & Penn's taper.
    pub radii: Option<Vec<f32>>,
    /// The stem was cut at its tip by a hand edit ([`crate::edits`]): the mesh stage closes it
    /// with a cut face (a bark rim around end grain) instead of a pointed tip.
    pub cut_end: bool,
    /// How far woundwood has closed over the cut end, as a fraction of its radius (0: a fresh
    /// cut; 1: closed). A dated cut's years since it was made set it ([`crate::edits::cut`]).
    pub callus: f32,
    /// The year the wood at this record's base grew (0 for the trunk; see [`crate::age`]).
    pub born: f32,
    /// The year the wood at this record's tip grew (the Mature Age for a mature stem, the Age
    /// for one still growing); leaves on wood between are dated by linear interpolation.
    pub tip_year: f32,
}

impl Stem {
    /// Radius at fraction `z` (0 = base, 1 = tip) of the stem: W&P taper, plus flare on the trunk.
    pub fn radius_at(&self, z: f32) -> f32 {
        if let Some(r) = &self.radii {
            let f = z.clamp(0.0, 1.0) * (r.len() - 1) as f32;
            let i = (f as usize).min(r.len() - 2);
            return r[i] + (r[i + 1] - r[i]) * (f - i as f32);
        }
        let zc = self.chain_start + z * (1.0 - self.chain_start);
        taper_radius(self.chain_radius, self.taper, self.chain_length, zc) * flare_factor(self.flare, zc)
    }

    /// Base point of the stem.
    pub fn base(&self) -> Vec3 {
        self.points[0]
    }

    /// Tip point of the stem.
    pub fn tip(&self) -> Vec3 {
        *self.points.last().expect("a stem has points")
    }

    /// Point and unit direction at distance `d` along the stem (clamped to the stem).
    pub fn point_at(&self, d: f32) -> (Vec3, Vec3) {
        self.sample((d / self.length).clamp(0.0, 1.0))
    }

    /// Point and unit tangent at fraction `t` (0 = base, 1 = tip) of the smooth centre curve: a
    /// Catmull-Rom spline through [`Stem::points`] (ends extrapolated). The mesh and the child
    /// attachment points both use this, so children start exactly on their parent's axis.
    pub fn sample(&self, t: f32) -> (Vec3, Vec3) {
        let (i, u) = self.locate(t);
        self.segment(i).eval(u)
    }

    /// The point of [`Stem::sample`] alone (no tangent: cheaper where only places matter).
    pub fn point(&self, t: f32) -> Vec3 {
        let (i, u) = self.locate(t);
        self.segment(i).position(u)
    }

    /// A reader of [`Stem::point`] for many nearby `t`: it keeps the last segment's cubic.
    pub fn points(&self) -> StemPoints<'_> {
        StemPoints { stem: self, index: 0, segment: self.segment(0) }
    }

    /// Whether [`Stem::radius_at`] never grows from base to tip: Weber & Penn's taper below 2
    /// (a cone, or one rounded tip) with a flare that widens the base, no radii point by point.
    pub fn radius_never_grows(&self) -> bool {
        self.radii.is_none() && (0.0..2.0).contains(&self.taper) && self.flare >= 0.0 && self.chain_start <= 1.0
    }

    /// Number of cubic segments of the centre curve.
    pub fn segments(&self) -> usize {
        self.points.len() - 1
    }

    /// Segment index and local parameter of fraction `t`.
    pub fn locate(&self, t: f32) -> (usize, f32) {
        let segs = self.points.len() - 1;
        let f = t.clamp(0.0, 1.0) * segs as f32;
        let i = (f as usize).min(segs - 1);
        (i, f - i as f32)
    }

    /// The cubic of segment `i` of the centre curve (for evaluating many points on one segment).
    pub fn segment(&self, i: usize) -> Segment {
        let pts = &self.points;
        let segs = pts.len() - 1;
        let p1 = pts[i];
        let p2 = pts[i + 1];
        let p0 = if i > 0 { pts[i - 1] } else { 2.0 * p1 - p2 };
        let p3 = if i + 2 <= segs { pts[i + 2] } else { 2.0 * p2 - p1 };
        Segment { p1, p2, d: p2 - p0, a: 2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3, b: -p0 + 3.0 * p1 - 3.0 * p2 + p3 }
    }

    /// `d radius / d arc length` at fraction `t`: exact for the linear tapers (the common case),
    /// a central difference where flare or rounded tips make the profile curved.
    pub fn radius_slope(&self, t: f32) -> f32 {
        if self.flare == 0.0 && self.taper <= 1.0 && self.radii.is_none() {
            return -self.chain_radius * self.taper / self.chain_length;
        }
        let eps = 1e-3f32;
        let (ta, tb) = ((t - eps).max(0.0), (t + eps).min(1.0));
        (self.radius_at(tb) - self.radius_at(ta)) / ((tb - ta) * self.length)
    }
}

/// [`Stem::point`] and [`Stem::sample`] with the last segment's cubic kept ([`Stem::points`]):
/// the same values, without rebuilding the cubic while `t` stays on one segment.
pub struct StemPoints<'a> {
    stem: &'a Stem,
    /// The segment `segment` is the cubic of.
    index: usize,
    segment: Segment,
}

impl StemPoints<'_> {
    /// The centre curve's point at fraction `t`.
    pub fn at(&mut self, t: f32) -> Vec3 {
        let u = self.locate(t);
        self.segment.position(u)
    }

    /// [`Stem::sample`] at fraction `t`: the centre curve's point and unit tangent.
    pub fn sample(&mut self, t: f32) -> (Vec3, Vec3) {
        let u = self.locate(t);
        self.segment.eval(u)
    }

    /// Makes `segment` the one fraction `t` lies on; returns the local parameter there.
    #[inline]
    fn locate(&mut self, t: f32) -> f32 {
        let (i, u) = self.stem.locate(t);
        if self.index != i {
            (self.index, self.segment) = (i, self.stem.segment(i));
        }
        u
    }
}

/// One segment of a stem's Catmull-Rom centre curve, in polynomial form.
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    p1: Vec3,
    p2: Vec3,
    d: Vec3,
    a: Vec3,
    b: Vec3,
}

impl Segment {
    /// Point and unit tangent at local parameter `u` in [0, 1].
    #[inline]
    pub fn eval(&self, u: f32) -> (Vec3, Vec3) {
        let pos = self.position(u);
        let tan = 0.5 * (self.d + self.a * (2.0 * u) + self.b * (3.0 * u * u));
        (pos, unit_or(tan, || (self.p2 - self.p1).normalize_or(Vec3::Y)))
    }

    /// The point at local parameter `u` (the position [`Segment::eval`] returns, without the
    /// tangent and its square root).
    #[inline]
    pub fn position(&self, u: f32) -> Vec3 {
        0.5 * (2.0 * self.p1 + self.d * u + self.a * (u * u) + self.b * (u * u * u))
    }

    /// The Bernstein control points of `d position / du` (a quadratic): the derivative at
    /// every `u` in [0, 1] lies in their convex hull, so a chord of the segment from `u0` to
    /// `u1` is `(u1 - u0)` times a point of that hull.
    pub fn hodograph(&self) -> [Vec3; 3] {
        let (c0, c1, c2) = (0.5 * self.d, self.a, 1.5 * self.b);
        [c0, c0 + 0.5 * c1, c0 + c1 + c2]
    }

    /// The size of the terms [`Segment::position`] adds (its rounding error is a few units in
    /// the last place of this).
    pub fn magnitude(&self) -> f32 {
        2.0 * self.p1.length() + self.d.length() + self.a.length() + self.b.length()
    }
}

/// Weber & Penn's taper: the radius at fraction `z` of a stem of base radius `r0`, length `len`.
/// `taper` in 0..1 narrows linearly to `1 - taper`; 1..2 rounds the tip into a hemisphere; 2..3
/// makes periodic spheres along the stem.
pub fn taper_radius(r0: f32, taper: f32, len: f32, z: f32) -> f32 {
    let unit_taper = if taper < 1.0 {
        taper
    } else if taper < 2.0 {
        2.0 - taper
    } else {
        0.0
    };
    let taper_z = r0 * (1.0 - unit_taper * z);
    if taper < 1.0 {
        return taper_z;
    }
    let z2 = (1.0 - z) * len;
    let depth = if taper < 2.0 || z2 < taper_z { 1.0 } else { taper - 2.0 };
    let z3 = if taper < 2.0 { z2 } else { (z2 - 2.0 * taper_z * ((z2 / (2.0 * taper_z) + 0.5).floor())).abs() };
    if taper < 2.0 && z3 >= taper_z {
        taper_z
    } else {
        let s = (taper_z * taper_z - (z3 - taper_z) * (z3 - taper_z)).max(0.0).sqrt();
        (1.0 - depth) * taper_z + depth * s
    }
}

/// Weber & Penn trunk flare: `1 + flare (100^y - 1) / 100` with `y = max(0, 1 - 8 z)`.
pub fn flare_factor(flare: f32, z: f32) -> f32 {
    if flare == 0.0 {
        return 1.0;
    }
    let y = (1.0 - 8.0 * z).max(0.0);
    1.0 + flare * (pow(100.0, y) - 1.0) / 100.0
}
