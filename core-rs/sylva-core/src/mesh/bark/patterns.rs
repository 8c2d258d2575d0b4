//! The four bark patterns of `docs/look.md` ("Bark types"), each a tileable height field with its colour and
//! roughness at a point of the unit tile (`u` around the stem, `v` along it):
//!
//! * **Furrowed** (oaks, ash, black locust): flat-topped ridges that meander and interlace along
//!   the stem, separated by deep narrow V fissures, broken into long blocks by a few cross cracks.
//! * **Plated** (pines, spruces, firs): irregular plates (cells of a Worley diagram, taller than
//!   wide) separated by dark cracks, each plate its own tone, with thin flaking layers.
//! * **Smooth-banded** (birch, cherry, young aspen): a smooth pale skin with short horizontal
//!   lenticels (dark dashes) and faint horizontal bands.
//! * **Fibrous** (willows, cedars, cypress): long strips that cross each other in a shallow
//!   diamond network, with fine fibres along the stem.

use super::noise::{cells, fbm, lattice, smoothstep, value};
use crate::params::BarkType;

/// One texel of a pattern: height 0 (deepest) to 1, linear RGB 0..1, roughness 0..1.
#[derive(Clone, Copy, Debug)]
pub struct Sample {
    /// Height (0 = bottom of a fissure, 1 = top of a plate).
    pub height: f32,
    /// Linear RGB albedo.
    pub rgb: [f32; 3],
    /// PBR roughness.
    pub rough: f32,
}

fn mix3(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t]
}

fn scale3(a: [f32; 3], s: f32) -> [f32; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// Distance from the nearest integer of `phase`, 0 (on it) to 1 (half way between).
fn ridge_t(phase: f32) -> f32 {
    let f = phase - phase.floor();
    2.0 * f.min(1.0 - f)
}

/// The pattern of `kind` at (u, v).
pub fn sample(kind: BarkType, u: f32, v: f32, seed: u32) -> Sample {
    match kind {
        BarkType::Furrowed => furrowed(u, v, seed),
        BarkType::Plated => plated(u, v, seed),
        BarkType::SmoothBanded => smooth_banded(u, v, seed),
        BarkType::Fibrous => fibrous(u, v, seed),
    }
}

fn furrowed(u: f32, v: f32, seed: u32) -> Sample {
    const RIDGES: f32 = 6.0;
    // Meander: slow along the stem, so ridges wander, merge and part again.
    let warp = (fbm(u, v, 3, 3, seed) - 0.5) * 1.8 + (value(u, v, 6, 8, seed + 5) - 0.5) * 0.6;
    let phase = u * RIDGES + warp;
    let width = 0.35 + 0.4 * value(u, v, 6, 5, seed + 7);
    let ridge = smoothstep(0.0, width, ridge_t(phase));
    // Cross cracks: each ridge column (period RIDGES around) has its own cracks along v.
    let col = phase.floor() as i32;
    let fc = v * 5.0 + lattice(col, 0, 6, 1, seed + 9) + 0.3 * value(u, v, 12, 5, seed + 10);
    let row = fc.floor() as i32;
    let crack = if lattice(col, row, 6, 5, seed + 11) > 0.4 { 1.0 - smoothstep(0.0, 0.08, ridge_t(fc)) } else { 0.0 };
    let fine = fbm(u, v, 32, 6, seed + 13);
    let height = (0.72 * ridge * (1.0 - 0.75 * crack) + 0.28 * fine * ridge).clamp(0.0, 1.0);
    let tone = fbm(u, v, 4, 6, seed + 15);
    let top = scale3(mix3([0.17, 0.12, 0.08], [0.3, 0.21, 0.13], tone), 0.8 + 0.4 * fine);
    let rgb = mix3([0.035, 0.025, 0.018], top, smoothstep(0.05, 0.6, height));
    Sample { height, rgb, rough: 0.97 - 0.12 * height }
}

fn plated(u: f32, v: f32, seed: u32) -> Sample {
    let (f1, f2, id) = cells(u, v, 6, 3, seed);
    let crack = smoothstep(0.04, 0.2, f2 - f1);
    let (g1, g2, _) = cells(u, v, 16, 10, seed + 3);
    let flake = 1.0 - smoothstep(0.0, 0.08, g2 - g1);
    let dome = 1.0 - 0.3 * f1 * f1;
    let grain = fbm(u, v, 12, 8, seed + 5);
    let plate = (0.7 + 0.3 * grain) * dome - 0.2 * flake;
    let height = (crack * plate).clamp(0.0, 1.0);
    let warm = mix3([0.27, 0.15, 0.09], [0.33, 0.25, 0.2], id);
    let top = scale3(warm, 0.75 + 0.45 * grain - 0.2 * flake);
    let rgb = mix3([0.03, 0.025, 0.022], top, smoothstep(0.1, 0.6, crack));
    Sample { height, rgb, rough: 0.98 - 0.12 * crack }
}

/// Short horizontal dashes, one chance per cell of a `8 × 24` grid: 1 inside a lenticel.
fn lenticels(u: f32, v: f32, seed: u32) -> f32 {
    let (px, py) = (8, 24);
    let (x, y) = (u * px as f32, v * py as f32);
    let (xi, yi) = (x.floor() as i32, y.floor() as i32);
    let mut mask = 0.0f32;
    for dy in -1..=1 {
        for dx in -2..=2 {
            let (cx, cy) = (xi + dx, yi + dy);
            if lattice(cx, cy, px, py, seed + 2) > 0.35 {
                continue;
            }
            let fx = cx as f32 + lattice(cx, cy, px, py, seed);
            let fy = cy as f32 + 0.5;
            let a = 0.25 + 0.35 * lattice(cx, cy, px, py, seed + 1);
            let b = 0.1 + 0.1 * lattice(cx, cy, px, py, seed + 3);
            let (ex, ey) = ((x - fx) / a, (y - fy) / b);
            mask = mask.max(1.0 - smoothstep(0.6, 1.0, ex * ex + ey * ey));
        }
    }
    mask
}

fn smooth_banded(u: f32, v: f32, seed: u32) -> Sample {
    let len = lenticels(u, v, seed);
    let band = value(0.0, v, 1, 7, seed + 4);
    let skin = fbm(u, v, 6, 6, seed + 6);
    let height = (0.78 + 0.12 * skin - 0.06 * smoothstep(0.55, 0.9, band) - 0.35 * len).clamp(0.0, 1.0);
    let pale = scale3([0.80, 0.79, 0.74], 0.92 + 0.1 * skin - 0.12 * smoothstep(0.55, 0.9, band));
    let rgb = mix3(pale, [0.16, 0.14, 0.13], len);
    Sample { height, rgb, rough: 0.55 + 0.35 * len + 0.05 * skin }
}

fn fibrous(u: f32, v: f32, seed: u32) -> Sample {
    const STRIPS: f32 = 6.0;
    const CROSS: f32 = 2.0;
    let w1 = (fbm(u, v, 3, 3, seed) - 0.5) * 0.9;
    let w2 = (fbm(u, v, 3, 3, seed + 3) - 0.5) * 0.9;
    // Two families of narrow fissures leaning either way: long diamonds of strips between them.
    let a = smoothstep(0.0, 0.3, ridge_t(u * STRIPS + v * CROSS + w1));
    let b = smoothstep(0.0, 0.22, ridge_t(u * STRIPS - v * CROSS + w2 + 0.5));
    let fibres = value(u, v, 96, 3, seed + 5);
    let strips = a * (0.35 + 0.65 * b);
    let height = (0.8 * strips + 0.2 * fibres * strips).clamp(0.0, 1.0);
    let tone = fbm(u, v, 5, 3, seed + 7);
    let top = scale3(mix3([0.2, 0.16, 0.13], [0.3, 0.26, 0.21], tone), 0.8 + 0.35 * fibres);
    let rgb = mix3([0.04, 0.03, 0.025], top, smoothstep(0.1, 0.75, height));
    Sample { height, rgb, rough: 0.96 - 0.1 * height }
}
