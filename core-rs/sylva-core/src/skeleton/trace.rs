//! # Tracing one stem record (Weber & Penn 1995, "Creation and Rendering of Realistic Trees")
//!
//! The centre polyline of a record, segment by segment: bends (Curve, CurveBack, CurveV, or a
//! helix for negative CurveV), AttractionUp, segment and base splits into clones, and the pruning
//! envelope test. Each step is a method of [`Tracer`], which carries the running frame, position
//! and split correction.

use crate::math::{self, acos, rad, PI, TAU};
use crate::params::{LevelParams, SkeletonParams};
use crate::rng::Rng;
use glam::{Quat, Vec3};

/// Where and how a stem (or a clone made by a split) starts.
pub(super) struct StemStart {
    pub(super) level: usize,
    pub(super) parent: Option<u32>,
    /// Distance along the parent record where this record starts.
    pub(super) offset: f32,
    pub(super) base: Vec3,
    /// Local +Y along the stem, local +X the axis positive Curve bends around.
    pub(super) frame: Quat,
    /// Full Weber & Penn length of the stem (for a clone: of the stem it split from).
    pub(super) length: f32,
    /// Base radius of the whole stem.
    pub(super) radius: f32,
    pub(super) down_angle: f32,
    /// First segment this record covers (0, or the split boundary for a clone).
    pub(super) first_seg: usize,
    /// Per-segment turn back toward the original direction after splits (degrees).
    pub(super) correction: f32,
    pub(super) rng: Rng,
}

/// Trace the centre polyline of one record: segments `first_seg..curve_res` of a stem of
/// `length`, bending by Curve/CurveBack/CurveV (or winding as a helix for negative CurveV),
/// turning up or down by AttractionUp, and, when `split_carry` is given, splitting into clones
/// (SegSplits with error diffusion, BaseSplits at the trunk's first joint) that turn back toward
/// the original direction over their remaining segments. Each point, base first, goes to
/// `visit`; tracing stops early when it returns false. The clones go to `clones`.
pub(super) fn trace(
    p: &SkeletonParams,
    s: &StemStart,
    length: f32,
    rng: &mut Rng,
    mut split_carry: Option<&mut f32>,
    clones: &mut Vec<StemStart>,
    visit: &mut impl FnMut(Vec3) -> bool,
) {
    let lp = &p.level[s.level];
    let segs = lp.curve_res.max(1) as usize;
    let mut t = Tracer { p, s, lp, segs, length, frame: s.frame, pos: s.base, correction: s.correction };
    let seg_len = length / segs as f32;
    if !visit(s.base) {
        return;
    }
    for i in s.first_seg..segs {
        if lp.curve_v < 0.0 {
            t.helix(i);
        } else if i > s.first_seg {
            t.bend(i, rng);
            let n = split_carry.as_deref_mut().map_or(0, |carry| t.split_count(i, carry));
            if n > 0 {
                t.split(i, n, rng, clones);
            }
        }
        t.pos += (t.frame * Vec3::Y) * seg_len;
        if !visit(t.pos) {
            break;
        }
    }
}

/// One record being traced: what it reads (the parameters, the record, its level's parameters)
/// and where it is (the frame of the current segment, the position reached, the per-segment turn
/// back toward the original direction after splits, in degrees).
struct Tracer<'a> {
    p: &'a SkeletonParams,
    s: &'a StemStart,
    lp: &'a LevelParams,
    /// Segments of the whole stem (`nCurveRes`).
    segs: usize,
    /// Full length of the stem.
    length: f32,
    frame: Quat,
    pos: Vec3,
    correction: f32,
}

impl Tracer<'_> {
    /// Negative CurveV: segment `i` winds around the record's initial direction, tilted by
    /// |CurveV|.
    fn helix(&mut self, i: usize) {
        let turn = TAU * i as f32 / self.segs as f32;
        self.frame = self.s.frame * math::quat_rotation_y(turn) * math::quat_rotation_x(rad(-self.lp.curve_v));
    }

    /// Bends segment `i` by Curve (or Curve then CurveBack over the two halves) plus a random
    /// CurveV and the split correction, then turns it by AttractionUp from level 2 on.
    fn bend(&mut self, i: usize, rng: &mut Rng) {
        let (lp, segs) = (self.lp, self.segs);
        let bend = if lp.curve_back == 0.0 {
            lp.curve / segs as f32
        } else if i < segs.div_ceil(2) {
            2.0 * lp.curve / segs as f32
        } else {
            2.0 * lp.curve_back / segs as f32
        };
        let bend = bend + rng.var(lp.curve_v) / segs as f32 + self.correction;
        self.frame = (self.frame * math::quat_rotation_x(rad(bend))).normalize();
        if self.s.level >= 2 && self.p.attraction_up != 0.0 {
            self.frame = attract_up(self.frame, self.p.attraction_up, segs);
        }
    }

    /// Whether segment `i` is the trunk's first joint, where BaseSplits clones split off.
    fn base_split(&self, i: usize) -> bool {
        self.s.level == 0 && i == 1 && self.p.base_splits > 0
    }

    /// How many clones split off at segment `i`: BaseSplits at the trunk's first joint, else
    /// SegSplits with its fraction carried to the next segment (error diffusion in `carry`).
    fn split_count(&self, i: usize, carry: &mut f32) -> usize {
        if self.base_split(i) {
            return self.p.base_splits as usize;
        }
        let exact = self.lp.seg_splits + *carry;
        let n = exact.floor();
        *carry = exact - n;
        n as usize
    }

    /// Splits `n` clones off at segment `i` into `clones`: each turns away by the split angle
    /// (SplitAngle less the declination), spread about the tree's vertical axis (evenly around
    /// for base splits, alternating sides otherwise), and turns back over its remaining
    /// segments; the original turns by the same angle.
    fn split(&mut self, i: usize, n: usize, rng: &mut Rng, clones: &mut Vec<StemStart>) {
        let base_split = self.base_split(i);
        let dir = self.frame * Vec3::Y;
        let declination = acos(dir.y).to_degrees();
        let angle = (self.lp.split_angle + rng.var(self.lp.split_angle_v) - declination).max(0.0);
        let remaining = (self.segs - i) as f32;
        for k in 1..=n {
            let spread = if base_split {
                360.0 * k as f32 / (n + 1) as f32
            } else {
                let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
                let u = rng.next_f32();
                sign * (20.0 + 0.75 * (30.0 + (declination - 90.0).abs()) * u * u)
            };
            // W&P spread clones about the tree's vertical axis (not the stem's own axis, which
            // would leave a clone on top of its original when the angle is 0).
            let clone_frame =
                (math::quat_rotation_y(rad(spread)) * self.frame * math::quat_rotation_x(rad(angle))).normalize();
            clones.push(StemStart {
                level: self.s.level,
                parent: None,
                offset: 0.0,
                base: self.pos,
                frame: clone_frame,
                length: self.length,
                radius: self.s.radius,
                down_angle: self.s.down_angle,
                first_seg: i,
                correction: self.correction - angle / remaining,
                rng: rng.split(),
            });
        }
        self.frame = (self.frame * math::quat_rotation_x(rad(angle))).normalize();
        self.correction -= angle / remaining;
    }
}

/// Weber & Penn's pruning test: inside `PruneWidth * ShapeRatio(Envelope, ratio)` where
/// `ratio = (scale - height) / (scale (1 - BaseSize))`.
pub(super) fn inside_prune_envelope(p: &SkeletonParams, scale: f32, q: Vec3) -> bool {
    let denom = (scale * (1.0 - p.base_size)).max(1e-6);
    let ratio = (scale - q.y) / denom;
    let lateral = (q.x * q.x + q.z * q.z).sqrt() / scale;
    // The envelope's power of a base of at most 1 (give or take its rounding) is at most 1, so
    // the width never exceeds PruneWidth by a thousandth: a point beyond that is outside
    // without the power (the same answer; most points a pruned stem's search tries).
    if lateral >= 1.001 * p.prune_width {
        return false;
    }
    let (peak, low, high) = (p.prune_width_peak, p.prune_power_low, p.prune_power_high);
    // Well inside a lower bound of the width (computed without the power, a software `powf`
    // in wasm) is inside: most points of a stem that fits.
    if lateral < 0.999 * p.prune_width * crate::crown::prune_envelope_floor(ratio, peak, low, high) {
        return true;
    }
    lateral < p.prune_width * crate::crown::prune_envelope(ratio, peak, low, high)
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
    (math::quat_axis_angle(axis.normalize(), turn) * frame).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`inside_prune_envelope`] without its shortcut.
    fn inside_by_the_formula(p: &SkeletonParams, scale: f32, q: Vec3) -> bool {
        let ratio = (scale - q.y) / (scale * (1.0 - p.base_size)).max(1e-6);
        let width = p.prune_width
            * crate::crown::prune_envelope(ratio, p.prune_width_peak, p.prune_power_low, p.prune_power_high);
        (q.x * q.x + q.z * q.z).sqrt() / scale < width
    }

    #[test]
    fn the_prune_shortcut_gives_the_formulas_answer() {
        let mut p = crate::TreeParams::default().skeleton;
        let mut rng = crate::rng::Rng::new(3, "prune_test");
        let scale = 12.0;
        for (peak, low, high) in [
            (0.5, 0.5, 0.5),
            (0.0, 0.0, 10.0),
            (1.0, 10.0, 0.0),
            (0.3, 1.0, 2.0),
            (0.999, 0.01, 7.0),
            (0.6, 0.001, 0.5),
            (0.4, 3.0, 0.999),
        ] {
            (p.prune_width_peak, p.prune_power_low, p.prune_power_high) = (peak, low, high);
            for width in [0.01, 0.5, 5.0] {
                p.prune_width = width;
                for _ in 0..20_000 {
                    let y = scale * (1.2 * rng.next_f32() - 0.1);
                    // Around the widest point most of all, where the shortcut's bound is tight.
                    let r = scale
                        * width
                        * (0.98 + 0.04 * rng.next_f32())
                        * if rng.next_f32() < 0.5 { 1.0 } else { rng.next_f32() };
                    let a = std::f32::consts::TAU * rng.next_f32();
                    let q = Vec3::new(r * crate::math::cos(a), y, r * crate::math::sin(a));
                    assert_eq!(inside_prune_envelope(&p, scale, q), inside_by_the_formula(&p, scale, q), "{q}");
                }
            }
        }
    }
}
