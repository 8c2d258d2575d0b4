//! The leaves' geometry, a batch of leaves at a time: each leaf's frame (where it sits, its
//! direction and side), its twig's directions, the lowering and the turn toward the sky, and its
//! matrix (see [`super`] for the rules).
//!
//! Every step normalises a vector (a square root and a division), and in a leaf each step waits
//! for the one before. One leaf at a time, the processor waits on that chain; here each step runs
//! over the whole batch before the next, so the batch's square roots and divisions overlap. Each
//! leaf's arithmetic is the same operations in the same order as one at a time, so the bytes are
//! the same.

use crate::math;
use glam::Vec3;

/// Leaves per batch.
pub(super) const LANES: usize = 8;

/// Where one leaf sits: the stem's centre curve point and unit tangent there, the stem's base
/// normal (where the golden-angle turns start), and the sine and cosine of the leaf's turn.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Site {
    pub pos: Vec3,
    pub tangent: Vec3,
    pub base_normal: Vec3,
    pub turn: [f32; 2],
}

/// The frames of `sites` (at most [`LANES`]): position, direction (midrib) and side, with
/// `angle` the cosine and sine of the Foliage Angle.
pub(super) fn leaf_frames(sites: &[Site], angle: (f32, f32)) -> [(Vec3, Vec3, Vec3); LANES] {
    let mut side0 = [Vec3::ZERO; LANES];
    for (s, out) in sites.iter().zip(&mut side0) {
        let (t, b) = (s.tangent, s.base_normal);
        *out = math::unit_or(b - t * t.dot(b), || math::unit_or(t.cross(Vec3::Y), || t.cross(Vec3::X).normalize()));
    }
    let mut frames = [(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO); LANES];
    for ((s, &side0), out) in sites.iter().zip(&side0).zip(&mut frames) {
        let side = rotate_sc(side0, s.tangent, s.turn);
        let dir = math::unit_or(s.tangent * angle.0 + side * angle.1, || s.tangent);
        *out = (s.pos, dir, side);
    }
    frames
}

/// The directions of each frame's leaves, `per_site` a frame in order into `dirs`: the frame's
/// direction, and with three (Twigs of Three) the same turned by ±0.6 rad about `dir × side`.
pub(super) fn twig_dirs(frames: &[(Vec3, Vec3, Vec3)], per_site: usize, dirs: &mut [Vec3; 3 * LANES]) {
    if per_site == 1 {
        for (f, d) in frames.iter().zip(dirs.iter_mut()) {
            *d = f.1;
        }
        return;
    }
    let sc = [math::sin(0.6), math::cos(0.6)];
    let sc_neg = [math::sin(-0.6), math::cos(-0.6)];
    for (f, d) in frames.iter().zip(dirs.chunks_exact_mut(3)) {
        let (dir, side) = (f.1, f.2);
        // glam's `normalize_or_zero` with the hardware square root: the same value.
        let axis = dir.cross(side).normalize_or(Vec3::ZERO);
        d.copy_from_slice(&[dir, rotate_sc(dir, axis, sc), rotate_sc(dir, axis, sc_neg)]);
    }
}

/// Each direction of `dirs` lowered ([`lower`]), and its front ([`face_up`]), in place:
/// `dirs[k]` becomes the lowered direction, `fronts[k]` its front.
pub(super) fn lower_and_face_up(dirs: &mut [Vec3], fronts: &mut [Vec3]) {
    for d in dirs.iter_mut() {
        *d = lower(*d);
    }
    for (d, f) in dirs.iter().zip(fronts.iter_mut()) {
        *f = face_up(*d);
    }
}

/// The rule of *Modeling the Mighty Maple for Web*: lower the direction's vertical component,
/// `t_y ← t_y (1 − t_y²)`, and renormalise.
pub fn lower(t: Vec3) -> Vec3 {
    let t = Vec3::new(t.x, t.y * (1.0 - t.y * t.y), t.z);
    math::unit_or(t, || Vec3::X)
}

/// The leaf's front after turning about its direction `t` (unit) toward the sky: world up made
/// perpendicular to `t`; for a horizontal-free (vertical) `t`, any perpendicular.
pub fn face_up(t: Vec3) -> Vec3 {
    math::unit_or(Vec3::Y - t * t.y, || math::unit_or(t.cross(Vec3::X), || Vec3::Z))
}

/// `v` rotated about the unit `axis` by the angle whose sine and cosine are `sc` (Rodrigues).
fn rotate_sc(v: Vec3, axis: Vec3, [s, c]: [f32; 2]) -> Vec3 {
    v * c + axis.cross(v) * s + axis * axis.dot(v) * (1.0 - c)
}

/// One leaf's matrix: leaf `x` → side · width, `y` → direction · length, `z` → front · length.
pub(super) fn push_matrix(out: &mut Vec<f32>, pos: Vec3, dir: Vec3, front: Vec3, len: f32, width: f32) {
    let x = dir.cross(front) * width;
    let y = dir * len;
    let z = front * len;
    out.extend_from_slice(&[x.x, x.y, x.z, 0.0, y.x, y.y, y.z, 0.0, z.x, z.y, z.z, 0.0, pos.x, pos.y, pos.z, 1.0]);
}
