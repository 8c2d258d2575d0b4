//! Skeleton stage: parameters -> stems (centre polylines with a radius profile), after Weber &
//! Penn, "Creation and Rendering of Realistic Trees" (SIGGRAPH 1995) with the formulas of
//! ANCHORS §3: stem lengths (level 1 scaled by the crown ShapeRatio), radii with RatioPower and
//! child <= parent at the attachment point, taper modes, trunk flare, curvature (Curve,
//! CurveBack, CurveV), DownAngle/Rotate with their negative variants, branch counts with error
//! diffusion, AttractionUp and Angle Spread.
//!
//! Every stem draws from its own generator split off its parent's, so editing a deeper level
//! never changes the stems above it.

use crate::crown::CrownShape;
use crate::error::SylvaError;
use crate::math::{acos, pow, rad, unit_or, PI, TAU};
use crate::params::TreeParams;
use crate::rng::Rng;
use glam::{Quat, Vec3};

/// A stem's centre polyline (inline storage for up to four points).
pub type Points = smallvec::SmallVec<[Vec3; 4]>;

/// One stem: the trunk, a branch or a twig.
#[derive(Clone, Debug)]
pub struct Stem {
    /// 0 = trunk, 1 = branches on the trunk, ...
    pub level: u8,
    /// Index of the parent stem in [`Skeleton::stems`].
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
    /// True for the trunk record, which carries the Lobes.
    pub lobed: bool,
    /// Radius at each of [`Stem::points`] when the profile is given point by point (grown
    /// trees, pipe model) instead of by Weber & Penn's taper.
    pub radii: Option<Vec<f32>>,
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
        let pos = 0.5 * (2.0 * self.p1 + self.d * u + self.a * (u * u) + self.b * (u * u * u));
        let tan = 0.5 * (self.d + self.a * (2.0 * u) + self.b * (3.0 * u * u));
        (pos, unit_or(tan, || (self.p2 - self.p1).normalize_or(Vec3::Y)))
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

/// The stems of one tree, parents before children.
#[derive(Clone, Debug, Default)]
pub struct Skeleton {
    /// All stems; `stems[0]` is the trunk.
    pub stems: Vec<Stem>,
    /// `Scale + var(ScaleV)` drawn for this tree (m).
    pub scale: f32,
    /// Height above the ground where the crown starts (m).
    pub crown_base: f32,
}

/// Smallest stem length that is still built (m); shorter children are dropped.
const MIN_LENGTH: f32 = 1e-3;
/// Smallest radius a stem gets (m): 1 mm keeps every ring wider than f32 rounding at tree
/// heights, so no triangle collapses.
const MIN_RADIUS: f32 = 1e-3;

/// Lower bound of the vertices a stem will need in the mesh stage; used to stop runaway trees
/// before they allocate (the mesh stage checks the exact count against the same budget).
pub fn min_vertices(curve_res: u32) -> u64 {
    (u64::from(curve_res) + 1) * 4 + 1
}

/// The budget error, shared by the skeleton and mesh stages.
pub fn budget_error(what: &str, need: u64, max: u32) -> SylvaError {
    SylvaError::Budget {
        param: "max_vertices".into(),
        message: format!(
            "this tree would need {what}{need} vertices, more than the max_vertices budget of {max}: \
             lower Levels or Branches, or raise Max Vertices"
        ),
    }
}

struct Builder<'a> {
    p: &'a TreeParams,
    stems: Vec<Stem>,
    /// Error-diffusion remainders of fractional branch counts, per level.
    carry: [f32; 4],
    /// Error-diffusion remainders of fractional segment splits, per level.
    split_carry: [f32; 4],
    vertex_floor: u64,
    scale: f32,
    crown_base: f32,
}

/// Where and how a stem (or a clone made by a split) starts.
struct StemStart {
    level: usize,
    parent: Option<u32>,
    /// Distance along the parent record where this record starts.
    offset: f32,
    base: Vec3,
    /// Local +Y along the stem, local +X the axis positive Curve bends around.
    frame: Quat,
    /// Full Weber & Penn length of the stem (for a clone: of the stem it split from).
    length: f32,
    /// Base radius of the whole stem.
    radius: f32,
    down_angle: f32,
    /// First segment this record covers (0, or the split boundary for a clone).
    first_seg: usize,
    /// Per-segment turn back toward the original direction after splits (degrees).
    correction: f32,
    rng: Rng,
}

/// Build the skeleton. Fails only on the vertex budget (parameters are validated before).
pub fn build(p: &TreeParams) -> Result<Skeleton, SylvaError> {
    let mut rng = Rng::new(u64::from(p.seed), "skeleton");
    let scale = (p.scale + rng.var(p.scale_v)).max(0.1);
    let l0 = &p.level[0];
    let length = ((l0.length + rng.var(l0.length_v)) * scale).max(MIN_LENGTH);
    let radius = (length * p.ratio * (p.scale0 + rng.var(p.scale0_v))).max(MIN_RADIUS);
    let mut b = Builder {
        p,
        stems: Vec::new(),
        carry: [0.0; 4],
        split_carry: [0.0; 4],
        vertex_floor: 0,
        scale,
        crown_base: p.base_size * length,
    };
    b.grow(StemStart {
        level: 0,
        parent: None,
        offset: 0.0,
        base: Vec3::ZERO,
        frame: Quat::IDENTITY,
        length,
        radius,
        down_angle: 0.0,
        first_seg: 0,
        correction: 0.0,
        rng,
    })?;
    add_roots(p, &mut b.stems);
    Ok(Skeleton { stems: b.stems, scale, crown_base: b.crown_base })
}

/// The thesis' guide curve (§4.2.1): the trunk's points keep their heights but move by random
/// x/z offsets within `Guide Limit` (the first point stays at the origin, the second moves at most
/// half as far), from their own random stream.
fn guide_curve(p: &TreeParams, points: &mut Points) {
    let mut rng = Rng::new(u64::from(p.seed), "trunk-guide");
    for (i, q) in points.iter_mut().enumerate().skip(1) {
        let limit = if i == 1 { 0.5 * p.guide_xy } else { p.guide_xy };
        q.x += rng.var(limit);
        q.z += rng.var(limit);
    }
}

/// Surface roots: `Roots` stems leaving the trunk base, spread evenly around it (with `Root
/// Spread` of random variation), running outward just under the ground and diving to `Root
/// Depth` (in root radii) below it, tapering to a point. They start inside the flared base, so
/// they emerge from it; their own random stream keeps every other stem unchanged.
fn add_roots(p: &TreeParams, stems: &mut Vec<Stem>) {
    if p.root_count == 0 || stems.is_empty() {
        return;
    }
    let mut rng = Rng::new(u64::from(p.seed), "roots");
    let trunk = stems[0].clone();
    let r0 = trunk.radius * p.root_radius;
    let length = trunk.length * p.root_length;
    let segs = 8usize;
    for k in 0..p.root_count {
        let angle = TAU * (k as f32 + rng.var(0.5 * p.root_spread)) / p.root_count as f32;
        let (dx, dz) = (crate::math::cos(angle), crate::math::sin(angle));
        let len = length * (1.0 + rng.var(0.3 * p.root_spread));
        let start_y = 0.35 * r0;
        let end_y = -p.root_depth * r0;
        let mut points = Points::new();
        for i in 0..=segs {
            let t = i as f32 / segs as f32;
            // Out along the ground, sinking smoothly (smoothstep) from just above it to the depth.
            let s = t * t * (3.0 - 2.0 * t);
            let wobble = rng.var(0.05) * len * t;
            let horizontal = 0.25 * trunk.radius + len * t;
            points.push(Vec3::new(
                dx * horizontal - dz * wobble,
                start_y + (end_y - start_y) * s,
                dz * horizontal + dx * wobble,
            ));
        }
        points[0] = Vec3::new(0.0, start_y, 0.0);
        stems.push(Stem {
            level: 1,
            parent: Some(0),
            offset: 0.0,
            base_normal: Vec3::Y,
            points,
            length: len,
            radius: r0,
            taper: 1.0,
            flare: 0.0,
            down_angle: 90.0,
            chain_length: len,
            chain_radius: r0,
            chain_start: 0.0,
            lobed: false,
            radii: None,
        });
    }
}

impl Builder<'_> {
    /// Grow one stem record (tracing its segments, splitting off clones), then its children and
    /// its clones. Records are pushed parents first.
    fn grow(&mut self, s: StemStart) -> Result<(), SylvaError> {
        let p = self.p;
        let lp = &p.level[s.level];
        self.vertex_floor += min_vertices(lp.curve_res);
        if self.vertex_floor > u64::from(p.max_vertices) {
            return Err(budget_error("at least ", self.vertex_floor, p.max_vertices));
        }
        let mut rng = s.rng.clone();
        let mut length = s.length;
        if p.prune_ratio > 0.0 && s.level >= 1 && s.first_seg == 0 {
            length = self.pruned_length(&s);
            if length < (2.0 * s.radius).max(MIN_LENGTH) {
                return Ok(()); // pruned to a stub that would sit inside its parent
            }
        }
        let mut carry = self.split_carry[s.level];
        let trunk = s.level == 0 && s.parent.is_none();
        let mut points = Points::with_capacity(p.level[s.level].curve_res as usize + 1);
        let clones = trace(p, &s, length, &mut rng, Some(&mut carry), &mut |q| {
            points.push(q);
            true
        });
        self.split_carry[s.level] = carry;
        if trunk && p.guide_xy > 0.0 {
            guide_curve(p, &mut points);
        }
        let segs = lp.curve_res as usize;
        let z0 = s.first_seg as f32 / segs as f32;
        let index = self.stems.len() as u32;
        let record_len = length * (1.0 - z0);
        self.stems.push(Stem {
            level: s.level as u8,
            parent: s.parent,
            offset: s.offset,
            base_normal: s.frame * Vec3::X,
            points,
            length: record_len.max(MIN_LENGTH),
            radius: taper_radius(s.radius, lp.taper, length, z0).max(MIN_RADIUS),
            taper: lp.taper,
            flare: if s.level == 0 { p.flare } else { 0.0 },
            down_angle: s.down_angle,
            chain_length: length,
            chain_radius: s.radius,
            chain_start: z0,
            lobed: trunk,
            radii: None,
        });
        if s.level + 1 < p.levels as usize {
            self.grow_children(s.level, index, &mut rng)?;
        }
        for mut c in clones {
            c.parent = Some(index);
            c.offset = (c.first_seg - s.first_seg) as f32 * length / segs as f32;
            c.length = length;
            self.grow(c)?;
        }
        Ok(())
    }

    /// Weber & Penn pruning: the longest length at which the stem stays inside the pruning
    /// envelope (bisection), then `L - (L - L_fit) * PruneRatio`. A stem's shape does not depend
    /// on its length (bends are per segment), so one unit-length trace, scaled, answers every
    /// trial length.
    fn pruned_length(&self, s: &StemStart) -> f32 {
        let p = self.p;
        let mut unit = Vec::with_capacity(p.level[s.level].curve_res as usize + 1);
        trace(p, s, 1.0, &mut s.rng.clone(), None, &mut |q| {
            unit.push(q - s.base);
            true
        });
        let fits = |len: f32| unit.iter().all(|&d| inside_prune_envelope(p, self.scale, s.base + d * len));
        if fits(s.length) {
            return s.length;
        }
        let (mut lo, mut hi) = (0.0f32, s.length);
        for _ in 0..10 {
            let mid = 0.5 * (lo + hi);
            if fits(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        s.length - (s.length - lo) * p.prune_ratio
    }

    fn grow_children(&mut self, level: usize, index: u32, rng: &mut Rng) -> Result<(), SylvaError> {
        let p = self.p;
        let child = level + 1;
        let cp = &p.level[child];
        let stem = self.stems[index as usize].clone();
        // Weber & Penn reason about whole stems: a clone's children use its stem's length.
        let stem_len = stem.chain_length;
        let chain_offset = stem.chain_start * stem_len;
        let (parent_len, parent_offset) = match stem.parent {
            Some(i) => {
                let parent = &self.stems[i as usize];
                (parent.chain_length, parent.chain_start * parent.chain_length + stem.offset)
            }
            None => (stem_len, 0.0),
        };
        // How many children (W&P §4.3), fractional counts carried over by error diffusion.
        let wanted = match child {
            1 => cp.branches as f32,
            2 => {
                let max_child = (p.level[1].length + p.level[1].length_v).max(1e-6);
                cp.branches as f32 * (0.2 + 0.8 * (stem_len / parent_len) / max_child)
            }
            _ => cp.branches as f32 * (1.0 - 0.5 * parent_offset / parent_len),
        }
        .max(0.0)
            * (stem.length / stem_len);
        let exact = wanted + self.carry[child];
        let count = exact.floor().max(0.0);
        self.carry[child] = exact - count;
        let count = count as usize;
        if count == 0 {
            return Ok(());
        }
        let start = if level == 0 { (self.crown_base - chain_offset).clamp(0.0, stem.length) } else { 0.0 };
        let mut rot = 0.0f32;
        for i in 0..count {
            let mut crng = rng.split();
            let offset = start + (stem.length - start) * (i as f32 + 0.5) / count as f32;
            let along = chain_offset + offset;
            // Crown position r: 1 at the crown base, 0 at the top (ANCHORS §2).
            let crown_span = stem_len - self.crown_base;
            let crown_r = if crown_span > 0.0 { (stem_len - along) / crown_span } else { 0.0 };
            let length = if child == 1 {
                stem_len * (cp.length + crng.var(cp.length_v)) * p.crown().ratio(crown_r)
            } else {
                (cp.length + crng.var(cp.length_v)) * (stem_len - 0.6 * along)
            };
            let mut down = if cp.down_angle_v >= 0.0 {
                cp.down_angle + crng.var(cp.down_angle_v)
            } else {
                let r = (stem_len - along) / stem_len;
                cp.down_angle + cp.down_angle_v * (1.0 - 2.0 * CrownShape::Conical.ratio(r))
            };
            if child == 1 {
                down += p.angle_spread * (2.0 * CrownShape::Conical.ratio(crown_r) - 1.0);
            }
            rot = if cp.rotate >= 0.0 {
                rot + cp.rotate + crng.var(cp.rotate_v)
            } else {
                let side = if i % 2 == 0 { 1.0 } else { -1.0 };
                side * (180.0 + cp.rotate) + crng.var(cp.rotate_v)
            };
            let radius = (stem.chain_radius * pow(length / stem_len, p.ratio_power))
                .min(stem.radius_at(offset / stem.length))
                .max(MIN_RADIUS);
            if length < (2.0 * radius).max(MIN_LENGTH) {
                continue; // shorter than its own thickness: it would sit inside the parent
            }
            let (pos, dir) = stem.point_at(offset);
            // Parent frame at the attachment point: its +Y along `dir`, +X transported from the base.
            let x = unit_or(stem.base_normal - dir * stem.base_normal.dot(dir), || dir.any_orthonormal_vector());
            let parent_frame = Quat::from_mat3(&glam::Mat3::from_cols(x, dir, x.cross(dir)));
            let frame = (parent_frame * Quat::from_rotation_y(rad(rot)) * Quat::from_rotation_x(rad(down))).normalize();
            self.grow(StemStart {
                level: child,
                parent: Some(index),
                offset,
                base: pos,
                frame,
                length,
                radius,
                down_angle: down,
                first_seg: 0,
                correction: 0.0,
                rng: crng,
            })?;
        }
        Ok(())
    }
}

/// Trace the centre polyline of one record: segments `first_seg..curve_res` of a stem of
/// `length`, bending by Curve/CurveBack/CurveV (or winding as a helix for negative CurveV),
/// turning up or down by AttractionUp, and, when `split_carry` is given, splitting into clones
/// (SegSplits with error diffusion, BaseSplits at the trunk's first joint) that turn back toward
/// the original direction over their remaining segments. Each point, base first, goes to
/// `visit`; tracing stops early when it returns false. Returns the clones.
fn trace(
    p: &TreeParams,
    s: &StemStart,
    length: f32,
    rng: &mut Rng,
    mut split_carry: Option<&mut f32>,
    visit: &mut impl FnMut(Vec3) -> bool,
) -> Vec<StemStart> {
    let lp = &p.level[s.level];
    let segs = lp.curve_res.max(1) as usize;
    let seg_len = length / segs as f32;
    let mut clones = Vec::new();
    if !visit(s.base) {
        return clones;
    }
    let mut frame = s.frame;
    let mut pos = s.base;
    let mut correction = s.correction;
    let helix = lp.curve_v < 0.0;
    for i in s.first_seg..segs {
        if helix {
            // Negative CurveV: the stem winds around its initial direction, tilted by |CurveV|.
            let turn = TAU * i as f32 / segs as f32;
            frame = s.frame * Quat::from_rotation_y(turn) * Quat::from_rotation_x(rad(-lp.curve_v));
        } else if i > s.first_seg {
            let bend = if lp.curve_back == 0.0 {
                lp.curve / segs as f32
            } else if i < segs.div_ceil(2) {
                2.0 * lp.curve / segs as f32
            } else {
                2.0 * lp.curve_back / segs as f32
            };
            let bend = bend + rng.var(lp.curve_v) / segs as f32 + correction;
            frame = (frame * Quat::from_rotation_x(rad(bend))).normalize();
            if s.level >= 2 && p.attraction_up != 0.0 {
                frame = attract_up(frame, p.attraction_up, segs);
            }
            if let Some(carry) = split_carry.as_deref_mut() {
                let n = if s.level == 0 && i == 1 && p.base_splits > 0 {
                    p.base_splits as usize
                } else {
                    let exact = lp.seg_splits + *carry;
                    let n = exact.floor();
                    *carry = exact - n;
                    n as usize
                };
                if n > 0 {
                    let base_split = s.level == 0 && i == 1 && p.base_splits > 0;
                    let dir = frame * Vec3::Y;
                    let declination = acos(dir.y).to_degrees();
                    let angle = (lp.split_angle + rng.var(lp.split_angle_v) - declination).max(0.0);
                    let remaining = (segs - i) as f32;
                    for k in 1..=n {
                        let spread = if base_split {
                            360.0 * k as f32 / (n + 1) as f32
                        } else {
                            let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
                            let u = rng.next_f32();
                            sign * (20.0 + 0.75 * (30.0 + (declination - 90.0).abs()) * u * u)
                        };
                        // W&P spread clones about the tree's vertical axis (not the stem's own axis,
                        // which would leave a clone on top of its original when the angle is 0).
                        let clone_frame =
                            (Quat::from_rotation_y(rad(spread)) * frame * Quat::from_rotation_x(rad(angle)))
                                .normalize();
                        clones.push(StemStart {
                            level: s.level,
                            parent: None,
                            offset: 0.0,
                            base: pos,
                            frame: clone_frame,
                            length,
                            radius: s.radius,
                            down_angle: s.down_angle,
                            first_seg: i,
                            correction: correction - angle / remaining,
                            rng: rng.split(),
                        });
                    }
                    frame = (frame * Quat::from_rotation_x(rad(angle))).normalize();
                    correction -= angle / remaining;
                }
            }
        }
        pos += (frame * Vec3::Y) * seg_len;
        if !visit(pos) {
            break;
        }
    }
    clones
}

/// Weber & Penn's pruning test: inside `PruneWidth * ShapeRatio(Envelope, ratio)` where
/// `ratio = (scale - height) / (scale (1 - BaseSize))`.
fn inside_prune_envelope(p: &TreeParams, scale: f32, q: Vec3) -> bool {
    let denom = (scale * (1.0 - p.base_size)).max(1e-6);
    let ratio = (scale - q.y) / denom;
    let width =
        p.prune_width * crate::crown::prune_envelope(ratio, p.prune_width_peak, p.prune_power_low, p.prune_power_high);
    (q.x * q.x + q.z * q.z).sqrt() / scale < width
}

/// Weber & Penn AttractionUp: turn the stem toward the sky by `attraction * declination / segs`
/// (or toward the ground when negative). At most 90% of the way to vertical per segment, so a
/// stem approaches vertical without ever landing exactly on it (stems never coincide).
fn attract_up(frame: Quat, attraction: f32, segs: usize) -> Quat {
    let dir = frame * Vec3::Y;
    let declination = acos(dir.y);
    let axis = dir.cross(Vec3::Y);
    if axis.length_squared() < 1e-12 {
        return frame;
    }
    let turn = (attraction * declination / segs as f32).clamp(-0.9 * (PI - declination), 0.9 * declination);
    (Quat::from_axis_angle(axis.normalize(), turn) * frame).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn taper_modes() {
        // Cone to a point, cylinder, half taper.
        assert!((taper_radius(1.0, 1.0, 10.0, 0.5) - 0.5).abs() < 1e-6);
        assert_eq!(taper_radius(1.0, 0.0, 10.0, 0.9), 1.0);
        assert!((taper_radius(1.0, 0.5, 10.0, 1.0) - 0.5).abs() < 1e-6);
        // 1 < taper <= 2: full radius until one radius from the tip, then a hemisphere closing to 0.
        assert!((taper_radius(1.0, 2.0, 10.0, 0.5) - 1.0).abs() < 1e-6);
        assert!(taper_radius(1.0, 2.0, 10.0, 1.0).abs() < 1e-3);
    }

    #[test]
    fn flare_only_near_ground() {
        assert!((flare_factor(1.0, 0.0) - 1.99).abs() < 1e-5);
        assert_eq!(flare_factor(1.0, 0.2), 1.0);
        assert_eq!(flare_factor(0.0, 0.0), 1.0);
    }

    #[test]
    fn trunk_first_children_inside_crown() {
        let p = TreeParams::default();
        let s = build(&p).unwrap();
        assert_eq!(s.stems[0].level, 0);
        assert_eq!(s.stems.iter().filter(|st| st.level == 1).count(), 50);
        for st in s.stems.iter().filter(|st| st.level == 1) {
            assert!(st.offset >= s.crown_base - 1e-4, "branch below crown base");
            assert!(st.radius <= s.stems[0].radius_at(st.offset / s.stems[0].length) + 1e-6);
        }
        // Every child starts on its parent's axis.
        for st in &s.stems[1..] {
            let parent = &s.stems[st.parent.unwrap() as usize];
            let (pt, _) = parent.point_at(st.offset);
            assert!(pt.distance(st.base()) < 1e-4);
        }
    }

    #[test]
    fn editing_a_deeper_level_keeps_the_upper_levels() {
        let a = build(&TreeParams::default()).unwrap();
        let mut p = TreeParams::default();
        p.level[2].curve_v = 10.0;
        let b = build(&p).unwrap();
        let level1 = |s: &Skeleton| s.stems.iter().filter(|st| st.level <= 1).map(|st| st.tip()).collect::<Vec<_>>();
        assert_eq!(level1(&a), level1(&b));
    }

    #[test]
    fn runaway_tree_hits_the_budget_early() {
        let mut p = TreeParams::default();
        p.levels = 4;
        p.level[1].branches = 500;
        p.level[2].branches = 500;
        p.level[3].branches = 500;
        p.max_vertices = 100_000;
        let e = build(&p).unwrap_err();
        assert!(matches!(e, SylvaError::Budget { .. }), "{e}");
        assert!(e.message().contains("max_vertices budget of 100000"), "{e}");
    }
}
