//! Portable math. Every transcendental function goes through `libm` so native and wasm builds
//! compute bit-identical results (the platform `sinf`/`powf` differ in the last bit between
//! glibc and wasm). `sqrt`, `+`, `*` are IEEE-exact everywhere and need no wrapper.

pub use std::f32::consts::{PI, TAU};

/// Sine (radians).
#[inline]
pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}
/// Cosine (radians).
#[inline]
pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}
/// `x` to the power `y`.
#[inline]
pub fn pow(x: f32, y: f32) -> f32 {
    libm::powf(x, y)
}
/// `e` to the power `x`.
#[inline]
pub fn exp(x: f32) -> f32 {
    libm::expf(x)
}
/// Natural logarithm.
#[inline]
pub fn ln(x: f32) -> f32 {
    libm::logf(x)
}
/// Arc cosine with the argument clamped to [-1, 1].
#[inline]
pub fn acos(x: f32) -> f32 {
    libm::acosf(x.clamp(-1.0, 1.0))
}
/// Two-argument arc tangent.
#[inline]
pub fn atan2(y: f32, x: f32) -> f32 {
    libm::atan2f(y, x)
}
/// The larger of two numbers, by a plain comparison (`a` on a tie). `f32::max` is a call to
/// `fmaxf` in wasm (its rule for NaN has no instruction there), too slow for the hottest loops.
/// The same value as `f32::max` whenever neither is NaN (either zero for `-0.0` and `0.0`).
#[inline(always)]
pub fn max(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}

/// The smaller of two numbers, by a plain comparison: [`max`]'s twin for `f32::min`.
#[inline(always)]
pub fn min(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

/// `x.round()` (halfway cases away from zero) from `trunc`, an instruction in wasm where
/// `f32::round` is a call to `roundf`: the fraction `x - trunc(x)` is exact, so the result is
/// `f32::round`'s for every `x`.
#[inline]
pub fn round(x: f32) -> f32 {
    let t = x.trunc();
    if (x - t).abs() >= 0.5 {
        t + 1f32.copysign(x)
    } else {
        t
    }
}

/// Degrees to radians.
#[inline]
pub fn rad(deg: f32) -> f32 {
    deg * (PI / 180.0)
}

/// `v` normalised, or `fallback()` (evaluated only then) when `v` is too short to normalise.
#[inline]
pub fn unit_or(v: glam::Vec3, fallback: impl FnOnce() -> glam::Vec3) -> glam::Vec3 {
    let len2 = v.length_squared();
    if len2 > 1e-24 && len2.is_finite() {
        v * (1.0 / len2.sqrt())
    } else {
        fallback()
    }
}

/// glam's `Quat::from_rotation_x`, its sine and cosine from libm (glam is built without its
/// `libm` feature, so its own would take them from the platform: glibc natively).
#[inline]
pub fn quat_rotation_x(angle: f32) -> glam::Quat {
    let (s, c) = libm::sincosf(angle * 0.5);
    glam::Quat::from_xyzw(s, 0.0, 0.0, c)
}

/// glam's `Quat::from_rotation_y` through libm ([`quat_rotation_x`]).
#[inline]
pub fn quat_rotation_y(angle: f32) -> glam::Quat {
    let (s, c) = libm::sincosf(angle * 0.5);
    glam::Quat::from_xyzw(0.0, s, 0.0, c)
}

/// glam's `Quat::from_axis_angle` (`axis` of unit length) through libm ([`quat_rotation_x`]).
#[inline]
pub fn quat_axis_angle(axis: glam::Vec3, angle: f32) -> glam::Quat {
    let (s, c) = libm::sincosf(angle * 0.5);
    let v = axis * s;
    glam::Quat::from_xyzw(v.x, v.y, v.z, c)
}

/// glam's `from.slerp(to, s)` (both of unit length) with libm's sine: the shorter arc, a
/// normalised linear blend when they are almost the same rotation. The angle is glam's own
/// approximation of the arc cosine (`Quat::angle_between`, exact at half of it), no platform
/// function.
pub fn slerp(from: glam::Quat, mut to: glam::Quat, s: f32) -> glam::Quat {
    let mut dot = from.dot(to);
    if dot < 0.0 {
        to = -to;
        dot = -dot;
    }
    if dot > 1.0 - f32::EPSILON {
        return (from * (1.0 - s) + to * s).normalize();
    }
    let theta = from.angle_between(to) * 0.5;
    let (scale1, scale2) = (libm::sinf(theta * (1.0 - s)), libm::sinf(theta * s));
    ((from * scale1) + (to * scale2)) * (1.0 / libm::sinf(theta))
}
