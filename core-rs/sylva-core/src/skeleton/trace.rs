//! Tracing one stem record after Weber & Penn: bends (Curve, CurveBack, CurveV, helices),
//! AttractionUp, segment and base splits into clones, and the pruning envelope test.

use super::StemStart;
use crate::math::{acos, rad, HwSqrt, PI, TAU};
use crate::params::TreeParams;
use crate::rng::Rng;
use glam::{Quat, Vec3};

/// Trace the centre polyline of one record: segments `first_seg..curve_res` of a stem of
/// `length`, bending by Curve/CurveBack/CurveV (or winding as a helix for negative CurveV),
/// turning up or down by AttractionUp, and, when `split_carry` is given, splitting into clones
/// (SegSplits with error diffusion, BaseSplits at the trunk's first joint) that turn back toward
/// the original direction over their remaining segments. Each point, base first, goes to
/// `visit`; tracing stops early when it returns false. Returns the clones.
pub(super) fn trace(
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
            frame = (frame * Quat::from_rotation_x(rad(bend))).normalize_hw();
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
                                .normalize_hw();
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
                    frame = (frame * Quat::from_rotation_x(rad(angle))).normalize_hw();
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
pub(super) fn inside_prune_envelope(p: &TreeParams, scale: f32, q: Vec3) -> bool {
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
    (Quat::from_axis_angle(axis.normalize_hw(), turn) * frame).normalize_hw()
}
