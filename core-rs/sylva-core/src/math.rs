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

/// Lengths and unit vectors through the square-root instruction. glam is built with `libm` (for
/// portable trigonometry), so its `length` and `normalize` take their square root in
/// `libm::sqrtf`, a software loop in wasm. These are glam's arithmetic with `f32::sqrt`: the same
/// values (an IEEE square root is exact everywhere) at instruction speed, for the hot loops.
pub trait HwSqrt: Copy {
    /// glam's `length()`.
    fn length_hw(self) -> f32;
    /// glam's `normalize()`.
    fn normalize_hw(self) -> Self;
}

impl HwSqrt for glam::Vec3 {
    #[inline]
    fn length_hw(self) -> f32 {
        self.length_squared().sqrt()
    }
    #[inline]
    fn normalize_hw(self) -> Self {
        self * (1.0 / self.length_hw())
    }
}

impl HwSqrt for glam::Quat {
    #[inline]
    fn length_hw(self) -> f32 {
        glam::Vec4::from(self).length_squared().sqrt()
    }
    #[inline]
    fn normalize_hw(self) -> Self {
        glam::Quat::from_vec4(glam::Vec4::from(self) * (1.0 / self.length_hw()))
    }
}

/// glam's `v.normalize_or(fallback)` through [`HwSqrt`].
#[inline]
pub fn normalize_or_hw(v: glam::Vec3, fallback: glam::Vec3) -> glam::Vec3 {
    let rcp = 1.0 / v.length_hw();
    if rcp.is_finite() && rcp > 0.0 {
        v * rcp
    } else {
        fallback
    }
}
