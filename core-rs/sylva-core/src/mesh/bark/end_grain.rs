//! Procedural end grain for the face of a cut stem ([`crate::mesh::cut_face`]), baked in the core
//! like the bark maps ([`super::bake`]): for each [`BarkType`] a disc-shaped colour map and a
//! matching tangent-space normal map, so the viewer and the GLB / OBJ exports show the same wood.
//!
//! ## Disc layout
//!
//! The face's UVs are disc coordinates, `uv = 0.5 + 0.49 (x, y) / r` in the cut plane ([`crate::mesh::cut_face`]):
//! texel `(i, j)` (row `j` bottom to top, `v` up as in the bark maps) lies at radius
//! `ρ = |((i + ½) / size − ½, (j + ½) / size − ½)| / 0.49` stem radii from the pith. Going out
//! from the centre:
//!
//! * the **pith**, a small dark spot at `ρ < 0.025`;
//! * the **growth rings** out to the cambium at [`CAMBIUM`]: each ring a pale earlywood band
//!   darkening into its latewood, which ends sharply at the next ring's earlywood. The ring widths
//!   vary irregularly (seeded lattice noise, wider near the pith), and the rings are slightly
//!   eccentric and wobbly (an angular noise displaces them, most half way out, not at the pith or
//!   the cambium, which follows the bark);
//! * **heartwood** (darker, the inner [`WoodStyle::heart`] share of the wood, its border following
//!   a ring loosely) and lighter **sapwood** around it;
//! * a few **radial checks** (drying cracks) from the pith, widest near it and tapering out;
//! * faint circular **saw marks** across the whole face (in the relief mostly);
//! * the thin pale **cambium** line, the **inner bark** (phloem) and, where the face meets the
//!   bark rim's chamfer (the face ends at `ρ = 1 − BEVEL = 0.92`), a band of outer bark.
//!
//! Alpha is the disc mask: 255 for `ρ ≤ 1`, falling to 0 over one texel outside it; the colour
//! outside the disc continues the outer bark's, so filtering and mipmaps never bleed another
//! colour into the rim. Nothing draws outside the disc (the face's UVs stay inside it).
//!
//! ## Colours by bark type
//!
//! The wood's colours follow the species each bark type stands for ([`BarkType::wood`]): the
//! smooth-banded barks (birch, aspen, cherry) have pale, almost uniform wood with faint rings;
//! the plated barks (pines, spruces, firs) reddish heartwood in cream sapwood with strong dark
//! latewood rings; the furrowed barks (oak, ash, locust) tan sapwood around a mid-brown
//! heartwood, ring-porous (pores dot the earlywood) with light medullary rays; the fibrous barks
//! (cedars, cypress, willow) pinkish red-brown heartwood in pale sapwood. The inner bark is the
//! type's young bark colour ([`super::BarkStyle::young_rgb`]) lightened, the outer bark band that
//! colour darkened. Colours are mixed in sRGB and written as sRGB bytes.
//!
//! Integer hashes, `+ * floor sqrt` and the portable [`crate::math`] functions only: the same bits
//! natively and in wasm.

use super::noise::{cells, fbm, lattice, smoothstep, value};
use super::{unorm8, BarkType, Texture};
use crate::math::{atan2, cos, pow, sin, PI, TAU};

/// The two maps of one bark type's end grain.
#[derive(Clone, Debug, PartialEq)]
pub struct EndGrainMaps {
    /// sRGB colour; alpha = the disc mask (module docs).
    pub color: Texture,
    /// Tangent-space normal (RGB = xyz * 0.5 + 0.5), alpha = height (0 bottom of a check, 1 top).
    pub normal: Texture,
}

/// Radius of the cambium (the outermost wood) in stem radii.
pub const CAMBIUM: f32 = 0.8;
/// Scale from disc UV offsets to stem radii (the face's UVs are `0.5 + 0.49 (x, y) / r`).
const UV_RADIUS: f32 = 0.49;
/// Roughness of the sawn end grain (the viewer's and the exports' material factor).
pub const ROUGHNESS: f32 = 0.85;

/// How one bark type's wood looks in section (module docs, "Colours by bark type").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WoodStyle {
    /// sRGB of the sapwood's earlywood.
    pub sap: [f32; 3],
    /// sRGB of the heartwood's earlywood.
    pub heart_rgb: [f32; 3],
    /// Share of the wood's radius that is heartwood.
    pub heart: f32,
    /// Growth rings between the pith and the cambium.
    pub rings: u32,
    /// How much darker the latewood is than the earlywood (0..1).
    pub latewood: f32,
    /// Share of a ring that is latewood.
    pub late_share: f32,
    /// Ring-porous: large pores dot each ring's earlywood (oak, ash).
    pub pores: bool,
    /// Strength of the pale medullary rays (0 none).
    pub rays: f32,
    /// sRGB of the outer bark in section (the band where the face meets the bark rim).
    pub bark_rgb: [f32; 3],
}

impl BarkType {
    /// The wood of this type in section (module docs).
    pub fn wood(self) -> WoodStyle {
        match self {
            // Oak / ash: tan sapwood, mid-brown heartwood, ring-porous, silver-grain rays.
            BarkType::Furrowed => WoodStyle {
                sap: [0.80, 0.66, 0.47],
                heart_rgb: [0.58, 0.42, 0.26],
                heart: 0.62,
                rings: 18,
                latewood: 0.22,
                late_share: 0.55,
                pores: true,
                rays: 0.1,
                bark_rgb: [0.30, 0.25, 0.21],
            },
            // Pine / spruce / fir: cream sapwood, reddish heartwood, dark distinct latewood.
            BarkType::Plated => WoodStyle {
                sap: [0.90, 0.77, 0.56],
                heart_rgb: [0.74, 0.50, 0.34],
                heart: 0.55,
                rings: 15,
                latewood: 0.34,
                late_share: 0.3,
                pores: false,
                rays: 0.0,
                bark_rgb: [0.40, 0.26, 0.19],
            },
            // Birch / aspen / cherry: pale, nearly uniform wood with faint rings.
            BarkType::SmoothBanded => WoodStyle {
                sap: [0.91, 0.85, 0.71],
                heart_rgb: [0.87, 0.79, 0.64],
                heart: 0.45,
                rings: 20,
                latewood: 0.13,
                late_share: 0.35,
                pores: false,
                rays: 0.0,
                bark_rgb: [0.62, 0.57, 0.52],
            },
            // Cedar / cypress / willow: pale sapwood, pinkish red-brown heartwood.
            BarkType::Fibrous => WoodStyle {
                sap: [0.88, 0.78, 0.62],
                heart_rgb: [0.70, 0.45, 0.35],
                heart: 0.6,
                rings: 16,
                latewood: 0.25,
                late_share: 0.35,
                pores: false,
                rays: 0.0,
                bark_rgb: [0.36, 0.29, 0.24],
            },
        }
    }
}

fn mix3(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t]
}

fn scale3(a: [f32; 3], s: f32) -> [f32; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// Linear RGB to sRGB (the young bark colours are linear).
fn to_srgb(c: [f32; 3]) -> [f32; 3] {
    c.map(|x| pow(x.clamp(0.0, 1.0), 1.0 / 2.2))
}

/// Ring boundaries in ring coordinate: `bounds[0] = 0` (pith) .. `bounds[n] = CAMBIUM`, the
/// widths irregular (lattice noise) and wider near the pith.
fn ring_bounds(style: &WoodStyle, seed: u32) -> Vec<f32> {
    let n = style.rings.max(1) as usize;
    let widths: Vec<f32> = (0..n)
        .map(|k| {
            let trend = 1.35 - 0.7 * k as f32 / n as f32;
            trend * (0.45 + 1.1 * lattice(k as i32, 0, 4096, 1, seed + 41))
        })
        .collect();
    let total: f32 = widths.iter().sum();
    let mut bounds = Vec::with_capacity(n + 1);
    let mut at = 0.0;
    bounds.push(0.0);
    for w in &widths {
        at += w * CAMBIUM / total;
        bounds.push(at);
    }
    bounds[n] = CAMBIUM;
    bounds
}

/// The ring at ring coordinate `t`: its index and the fraction of the way through it (0 at the
/// earlywood's inner edge, 1 at the latewood's outer edge).
fn ring_at(bounds: &[f32], t: f32) -> (usize, f32) {
    let k = bounds.partition_point(|&b| b <= t).clamp(1, bounds.len() - 1) - 1;
    let (a, b) = (bounds[k], bounds[k + 1]);
    (k, ((t - a) / (b - a)).clamp(0.0, 1.0))
}

/// The radial checks of one bake (drying cracks from the pith): each one's length (stem radii)
/// and its angle at the pith, from the bake's seed.
struct Checks {
    /// `(len, base)` of each check, 3 or 4 of them.
    each: Vec<(f32, f32)>,
    seed: u32,
}

/// Above this `ρ sin |d|` a point is more than 1.05 half widths from a check: the largest half
/// width is `0.02 max r^0.4 (1 − r)^1.2 = 0.02 × 0.4066 = 0.00813` (at `r = 0.25`; tested), so
/// there the check's term is over 1.05 and its crack, `1 − smoothstep(0.6, 1, ·)`, exactly 0.
const CHECK_FAR: f32 = 0.0086;

impl Checks {
    fn new(seed: u32) -> Checks {
        let count = 3 + (lattice(0, 0, 1, 1, seed + 61) * 2.0) as i32;
        let each = (0..count)
            .map(|i| {
                let len = 0.28 + 0.4 * lattice(i, 0, 16, 1, seed + 63);
                let base = TAU * (i as f32 + 0.25 + 0.5 * lattice(i, 0, 16, 1, seed + 65)) / count as f32;
                (len, base)
            })
            .collect();
        Checks { each, seed }
    }

    /// Distance (stem radii) from the point at `(ρ, θ)` to the checks, over the check's half
    /// width there: large away from every check (a term known to be over 1.05, [`CHECK_FAR`], is
    /// left out: it cannot change the crack).
    fn at(&self, rho: f32, theta: f32) -> f32 {
        let mut best = f32::MAX;
        for (i, &(len, base)) in self.each.iter().enumerate() {
            if rho > len {
                continue;
            }
            // The crack wanders a little as it runs out.
            let wander = (value(rho, i as f32 / 16.0, 3, 16, self.seed + 67) - 0.5) * 0.14;
            let mut d = theta - base - wander;
            d -= TAU * ((d + PI) / TAU).floor();
            if d.abs() > 0.5 * PI {
                continue;
            }
            let across = rho * sin(d.abs());
            if across > CHECK_FAR {
                continue;
            }
            let r = rho / len;
            let half = 0.02 * pow(r.max(0.0), 0.4) * pow((1.0 - r).max(0.0), 1.2) * smoothstep(0.0, 0.03, rho);
            if half > 0.0 {
                best = best.min(across / half);
            }
        }
        best
    }
}

/// What every texel of one bake shares: the style, rings, checks and colours that depend on the
/// bark type and seed alone.
struct Bake<'a> {
    style: &'a WoodStyle,
    bounds: &'a [f32],
    seed: u32,
    /// The rings' lean (radians).
    lean: f32,
    checks: Checks,
    /// The inner bark (phloem) colour, sRGB.
    inner: [f32; 3],
}

/// One texel: sRGB colour and height (0..1) at disc offset `(x, y)` in stem radii.
fn sample(b: &Bake, x: f32, y: f32) -> ([f32; 3], f32) {
    let (style, bounds, seed) = (b.style, b.bounds, b.seed);
    let rho = (x * x + y * y).sqrt();
    let theta = atan2(y, x);
    let (u, v) = (0.5 + x * 0.5, 0.5 + y * 0.5);
    // Eccentric, wobbly rings: an angular displacement, largest half way out, zero at the pith
    // and at the cambium.
    let a = theta / TAU + 0.5;
    let wob = 0.22 * cos(theta - b.lean)
        + (value(a, rho * 0.5, 7, 2, seed + 3) - 0.5) * 0.3
        + (fbm(a, rho * 0.5, 3, 1, seed + 5) - 0.5) * 0.3;
    let s = (rho / CAMBIUM).min(1.0);
    let t = CAMBIUM * (s + wob * s * (1.0 - s) * 1.6);
    let (ring, f) = ring_at(bounds, t);
    let late = smoothstep(1.0 - style.late_share - 0.1, 1.0 - style.late_share * 0.5, f)
        * (1.0 - smoothstep(0.93, 1.0, f) * 0.35);
    // Heartwood: its border follows a ring, loosely.
    let heart_edge = style.heart * CAMBIUM + (value(a, 0.0, 9, 1, seed + 9) - 0.5) * 0.04;
    let sapness = smoothstep(heart_edge - 0.03, heart_edge + 0.03, t);
    let grain = fbm(u * 2.0, v * 2.0, 24, 24, seed + 11);
    let ring_tone = 0.93 + 0.12 * lattice(ring as i32, 0, 4096, 1, seed + 13);
    let streaks = value(a, rho, 300, 3, seed + 25);
    let tone = ring_tone * (0.9 + 0.2 * grain) * (0.97 + 0.06 * streaks);
    let mut wood = scale3(mix3(style.heart_rgb, style.sap, sapness), tone);
    // Latewood: darker and more saturated (its red channel falls least).
    let lw = style.latewood;
    wood = mix3(wood, [wood[0] * (1.0 - 0.75 * lw), wood[1] * (1.0 - lw), wood[2] * (1.0 - 1.2 * lw)], late);
    let mut height = 0.62 + 0.1 * late + 0.04 * grain;
    if style.pores && f < 0.3 {
        let (p, _, _) = cells(u, v, 96, 96, seed + 15);
        let pore = (1.0 - smoothstep(0.12, 0.22, p)) * (1.0 - smoothstep(0.15, 0.3, f));
        wood = scale3(wood, 1.0 - 0.45 * pore);
        height -= 0.15 * pore;
    }
    if style.rays > 0.0 {
        let ray = smoothstep(0.72, 0.9, value(a, rho, 160, 12, seed + 17));
        wood = mix3(wood, scale3(style.sap, 1.08), ray * style.rays * 4.0 * (1.0 - late));
    }
    // The pith: a small dark, slightly sunken spot.
    let pith = 1.0 - smoothstep(0.015, 0.03, rho);
    wood = mix3(wood, scale3(style.heart_rgb, 0.55), pith);
    height -= 0.2 * pith;
    // Radial checks: dark, deep.
    let crack = 1.0 - smoothstep(0.6, 1.0, b.checks.at(rho, theta));
    wood = mix3(wood, scale3(style.heart_rgb, 0.25), crack);
    height *= 1.0 - crack * 0.95;
    // Cambium, inner bark, outer bark.
    let inner = b.inner;
    let outer = style.bark_rgb;
    let fibres = value(a, rho, 220, 4, seed + 21);
    let phloem = mix3(inner, scale3(inner, 0.85), fibres);
    let bark = mix3(phloem, outer, smoothstep(0.87, 0.9, rho));
    let cambium = smoothstep(CAMBIUM - 0.004, CAMBIUM + 0.004, rho);
    let line = smoothstep(CAMBIUM - 0.004, CAMBIUM + 0.004, rho) * (1.0 - smoothstep(0.812, 0.822, rho));
    let mut rgb = mix3(wood, bark, cambium);
    rgb = mix3(rgb, [0.86, 0.82, 0.6], 0.5 * line);
    let bark_h = 0.55 + 0.08 * fibres - 0.1 * smoothstep(0.87, 0.9, rho);
    height = height + (bark_h - height) * cambium;
    // Circular saw marks: fine arcs across the face, in the relief.
    let (sx, sy) = (x + 2.6, y - 0.4);
    let arc = (sx * sx + sy * sy).sqrt() * 60.0 + 2.0 * value(u, v, 5, 5, seed + 23);
    let mark = arc - arc.floor();
    height += 0.035 * (mark - 0.5);
    (rgb, height.clamp(0.0, 1.0))
}

/// Bake the end-grain maps of `kind`, `size` texels square (a power of two, at least 16).
pub fn bake(kind: BarkType, size: usize) -> EndGrainMaps {
    let size = size.next_power_of_two().max(16);
    let style = kind.wood();
    let seed = 7 + kind as u32 * 131;
    let bounds = ring_bounds(&style, seed);
    let texel = 1.0 / (size as f32 * UV_RADIUS);
    let offset = |i: usize| ((i as f32 + 0.5) / size as f32 - 0.5) / UV_RADIUS;
    let young = to_srgb(kind.style().young_rgb);
    let b = Bake {
        style: &style,
        bounds: &bounds,
        seed,
        lean: TAU * lattice(0, 0, 1, 1, seed + 1),
        checks: Checks::new(seed + 19),
        inner: mix3(young, style.sap, 0.45),
    };
    let samples = super::texels(size, |i| {
        let (x, y) = (offset(i % size), offset(i / size));
        // Outside the disc: the colour at the disc's edge in the same direction.
        let rho = (x * x + y * y).sqrt();
        let k = if rho > 1.0 { 1.0 / rho } else { 1.0 };
        sample(&b, x * k, y * k)
    });
    let at = |x: usize, y: usize| samples[y.min(size - 1) * size + x.min(size - 1)].1;
    // Relief depth: 0.6 % of the face's diameter per unit of height.
    let strength = 0.006 * size as f32 * 0.5;
    let n = size * size * 4;
    let (mut color, mut normal) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for y in 0..size {
        for x in 0..size {
            let (rgb, h) = samples[y * size + x];
            color.extend(rgb.iter().map(|&c| unorm8(c)));
            let (ox, oy) = (offset(x), offset(y));
            let rho = (ox * ox + oy * oy).sqrt();
            color.push(unorm8(1.0 - (rho - 1.0) / texel));
            let dx = (at(x + 1, y) - at(x.saturating_sub(1), y)) * strength;
            let dy = (at(x, y + 1) - at(x, y.saturating_sub(1))) * strength;
            let len = (dx * dx + dy * dy + 1.0).sqrt();
            normal.extend([-dx / len, -dy / len, 1.0 / len].iter().map(|c| unorm8(c * 0.5 + 0.5)));
            normal.push(unorm8(h));
        }
    }
    EndGrainMaps { color: Texture { size, rgba: color }, normal: Texture { size, rgba: normal } }
}

impl EndGrainMaps {
    /// Both maps in one buffer, what the wasm binding's `end_grain_maps` returns: with
    /// `s = size` and `n = 4 s²`,
    ///
    /// * bytes `0 .. n`: the colour map, `s` rows of `s` texels, row 0 at `v = 0` (the bottom of
    ///   the disc), texel `(i, j)` at byte `4 (j s + i)`: R, G, B the sRGB colour, A the disc
    ///   mask (255 inside the disc `ρ ≤ 1`, 0 outside);
    /// * bytes `n .. 2n`: the normal map in the same order: R, G, B the tangent-space normal
    ///   (`x, y, z` each as `(c * 0.5 + 0.5) * 255`, `x` along `u`, `y` along `v`, `z` out of the
    ///   face), A the height (0 the bottom of a check, 255 the highest wood).
    ///
    /// The length is `8 s²`, so `s = √(len / 8)`.
    pub fn to_bytes(&self) -> Vec<u8> {
        [&self.color.rgba[..], &self.normal.rgba[..]].concat()
    }
}

#[cfg(test)]
mod tests;
