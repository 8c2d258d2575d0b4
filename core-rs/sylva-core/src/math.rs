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
/// Degrees to radians.
#[inline]
pub fn rad(deg: f32) -> f32 {
    deg * (PI / 180.0)
}
