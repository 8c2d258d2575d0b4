//! # Lobed leaf outlines
//!
//! Lobed outlines that follow the botany of real leaves (Ellis et al. 2009, *Manual of Leaf
//! Architecture*) rather than the
//! superformula's radial symmetry (Mtree's *Leaf Generation Guide* §1 draws an oak as a seven-pointed
//! star). Two models, both evaluated per half from the tip (`t = 0`) to the base (`t = 1`) like
//! the other outlines, so the margin stage adds teeth to them unchanged:
//!
//! * [`Pinnate`]: a blade **profile along the midrib** with lobes placed along it (pinnately
//!   lobed oak; unlobed ovate birch, orbicular aspen, lanceolate willow). At `y = 1 − t` the
//!   half-width is `x = W · e(y) · (1 − d (1 − g(u)))`:
//!   * `e(y) = y^p (1 − y)^q / (y*^p (1 − y*)^q)`, the envelope, 1 at its widest point
//!     `y* = p / (p + q)` (`p` Base Shape, `q` Tip Shape: exponents below 1 round the end,
//!     1 makes it wedge-shaped, above 1 draws it out); `W` = Aspect Ratio / 2;
//!   * lobes: `φ = (y − y₀) / (1 − y₀) · (n + ½)` counts `n` lobes per side from `y₀` (near the
//!     petiole) up to a terminal half-lobe at the tip; `u = frac(φ)` (with an Asymmetry Seed:
//!     the fraction of a period of irregular width, ±30 %, each sinus ±30 % deeper and each
//!     lobe reaching ±12 % further, as no two lobes of a real oak leaf match), skewed so the apex sits
//!     at `u_p = 0.62 + 0.2 · point` (lobes lean toward the tip, pointed ones more);
//!     `g(s) = (1 − point) · (1 − cos⁴(πs)) + point · tri(s)^1.5` (`s` the skewed `u`) is 1 at a
//!     lobe's apex and 0 in a sinus, a rounded lobe over a rounded U sinus; `d` (Sinus Depth)
//!     is how far the sinus cuts toward the midrib (0.5 = halfway).
//! * [`Palmate`]: lobes **radiating from the petiole junction** (maple; ginkgo's notched fan
//!   as two broad lobes), a polar radius `r(θ)` about the junction, `θ = π t` from the tip:
//!   lobe `k` at angle `α_k` (spread evenly up to ±Lobe Spread; an odd count puts one at the
//!   tip, an even count a notch) with length `L_k = 1 − f (α_k / spread)²` (`f` = 0.45 with
//!   three or more lobes, lower lobes shorter as in maple) and half-width `h` (half the lobe
//!   spacing); its profile is `L_k (1 − d |u|^e)` for `|u| = |θ − α_k| / h ≤ 1` (`e` from 3,
//!   flat-topped rounded lobes, to 0.7, pointed lobes with concave sides), fading to 0 over
//!   the next 0.6 half-width beyond the outermost lobe; lobes join by a smooth maximum
//!   (`(Σ r_k⁸)^⅛`, rounded sinuses) above a floor of 0.06 (the base sinus at the petiole).
//!   Two lobes make a notched fan (ginkgo): the outer flanks keep 88 % of their length to the
//!   edge and end within 0.12 half-widths, straight sides into the petiole, floor 0.015; they
//!   join by the plain maximum, a clean V notch.
//!   Lobe Teeth adds that many large saw teeth to each flank of every lobe (over `|u|` from
//!   0.2 to 0.85, apex toward the lobe's tip, height 0.09 of the lobe's length).
//!   Teeth of the margin stage are weighted by how close a point is to a lobe's top, so the
//!   sinuses stay entire as on a Norway maple.

use crate::leaf::geom::DVec2;
use crate::params::LeafParams;

const PI: f64 = std::f64::consts::PI;
/// Where the lowest pinnate lobe starts along the midrib.
const PINNATE_Y0: f64 = 0.04;
/// A rounded pinnate lobe's apex within its period (½ = upright; above, leaning to the tip).
const PINNATE_LEAN: f64 = 0.62;
/// Smooth-maximum exponent joining palmate lobes.
const SMOOTH_MAX: f64 = 8.0;
/// The palmate radius never falls below this (the base sinus around the petiole).
const PALMATE_FLOOR: f64 = 0.06;
/// Beyond the outermost palmate lobe the radius fades to the floor over this many half-widths.
const FADE: f64 = 0.6;
/// A two-lobed fan (ginkgo): its outer flanks lose this fraction of their length toward the
/// edge, fade out over [`FAN_FADE`] half-widths past it, and the floor is [`FAN_FLOOR`] (no
/// knob around the petiole, whose half-width is 0.015).
const FAN_SHOULDER: f64 = 0.12;
/// See [`FAN_SHOULDER`].
const FAN_FADE: f64 = 0.12;
/// See [`FAN_SHOULDER`].
const FAN_FLOOR: f64 = 0.015;
/// Height of a palmate lobe tooth, a fraction of the lobe's length.
const LOBE_TOOTH: f64 = 0.09;

/// A pinnate blade: profile along the midrib, lobes along it.
#[derive(Clone, Debug)]
pub struct Pinnate {
    half_width: f64,
    p: f64,
    q: f64,
    norm: f64,
    lobes: u32,
    depth: f64,
    point: f64,
    /// Where each lobe period starts along the phase (`k` for regular lobes), `lobes + 2`
    /// entries: periods of irregular widths (Asymmetry Seed), the terminal half-lobe last.
    starts: Vec<f64>,
    /// Per sinus (`lobes + 2`): how much deeper or shallower than Sinus Depth it cuts.
    sinus: Vec<f64>,
    /// Per lobe (`lobes + 1`): how much further out or less far its apex reaches.
    reach: Vec<f64>,
}

/// Irregular pinnate lobes (Asymmetry Seed ≠ 0): a lobe period's width varies by up to this
/// fraction, a sinus's depth by [`SINUS_JITTER`], a lobe's reach by [`REACH_JITTER`].
const PERIOD_JITTER: f64 = 0.3;
/// See [`PERIOD_JITTER`].
const SINUS_JITTER: f64 = 0.3;
/// See [`PERIOD_JITTER`].
const REACH_JITTER: f64 = 0.12;

/// `x^e` for `x ≥ 0` (0 at 0).
fn pw(x: f64, e: f64) -> f64 {
    if x <= 0.0 {
        0.0
    } else {
        libm::pow(x, e)
    }
}

impl Pinnate {
    /// The blade of the `leaf_*` parameters.
    pub fn from_params(p: &LeafParams) -> Pinnate {
        let (bp, bq) = (f64::from(p.leaf_base_shape), f64::from(p.leaf_tip_shape));
        let ys = bp / (bp + bq);
        Pinnate {
            half_width: 0.5 * f64::from(p.leaf_aspect),
            p: bp,
            q: bq,
            norm: pw(ys, bp) * pw(1.0 - ys, bq),
            lobes: p.leaf_lobes,
            depth: f64::from(p.leaf_lobe_depth),
            point: f64::from(p.leaf_lobe_point),
            starts: Vec::new(),
            sinus: Vec::new(),
            reach: Vec::new(),
        }
        .irregular(p.leaf_asymmetry_seed)
    }

    /// Draws the irregular lobes of `seed` (stream `"leaf-lobes"`); seed 0 keeps them regular.
    /// The periods keep their total (the tip and the lowest lobe stay where they were); the
    /// terminal half-lobe, the tip's sinus depth and the ends stay as drawn by the parameters.
    fn irregular(mut self, seed: u32) -> Pinnate {
        let n = self.lobes as usize;
        self.starts = (0..=n + 1).map(|k| k as f64).collect();
        self.sinus = vec![0.0; n + 2];
        self.reach = vec![0.0; n + 1];
        if seed == 0 || n == 0 {
            return self;
        }
        let mut rng = crate::rng::Rng::new(u64::from(seed), "leaf-lobes");
        let widths: Vec<f64> = (0..n).map(|_| 1.0 + PERIOD_JITTER * f64::from(rng.var(1.0))).collect();
        let total: f64 = widths.iter().sum();
        let mut at = 0.0;
        for (k, w) in widths.iter().enumerate() {
            self.starts[k] = at;
            at += w * n as f64 / total;
        }
        self.starts[n] = n as f64;
        self.starts[n + 1] = n as f64 + 1.0;
        for k in 1..n {
            self.sinus[k] = SINUS_JITTER * f64::from(rng.var(1.0));
        }
        for k in 0..n {
            self.reach[k] = REACH_JITTER * f64::from(rng.var(1.0));
        }
        self
    }

    /// The lobe `k` and the fraction `u` of its period at phase `phi` (the last period, the
    /// terminal half-lobe, is a regular one).
    fn period(&self, phi: f64) -> (usize, f64) {
        let n = self.lobes as usize;
        let k = self.starts[..=n].partition_point(|&s| s <= phi).saturating_sub(1).min(n);
        let (a, b) = (self.starts[k], self.starts[k + 1]);
        (k, ((phi - a) / (b - a)).clamp(0.0, 1.0))
    }

    /// The phase of fraction `u` of lobe `k`'s period.
    fn phase_of(&self, k: usize, u: f64) -> f64 {
        self.starts[k] + u * (self.starts[k + 1] - self.starts[k])
    }

    /// The envelope's half-width at `y` (before lobes).
    pub fn envelope(&self, y: f64) -> f64 {
        let y = y.clamp(0.0, 1.0);
        self.half_width * pw(y, self.p) * pw(1.0 - y, self.q) / self.norm
    }

    /// Apex of a lobe within its period: past the middle, so lobes lean toward the tip, and
    /// more so when pointed.
    fn apex(&self) -> f64 {
        PINNATE_LEAN + 0.2 * self.point
    }

    /// Lobe phase at `y`: `None` below the first lobe or without lobes.
    fn phase(&self, y: f64) -> Option<f64> {
        if self.lobes == 0 || y < PINNATE_Y0 {
            return None;
        }
        Some((y - PINNATE_Y0) / (1.0 - PINNATE_Y0) * (f64::from(self.lobes) + 0.5))
    }

    /// The lobe factor at `y`, in `[1 − depth, 1]`.
    pub fn lobe(&self, y: f64) -> f64 {
        let Some(phi) = self.phase(y) else {
            return if self.lobes == 0 { 1.0 } else { 1.0 - self.depth };
        };
        let (k, u) = self.period(phi);
        let up = self.apex();
        // Skew: the apex at `up` maps to the middle of the profile.
        let s = if u < up { 0.5 * u / up } else { 0.5 + 0.5 * (u - up) / (1.0 - up) };
        // A rounded lobe over a rounded U sinus: `1 − cos⁴(π s)` is round at the apex and curves
        // through the sinus's bottom (no slit where two lobes meet).
        let c2 = libm::cos(PI * s) * libm::cos(PI * s);
        let round = 1.0 - c2 * c2;
        let tri = pw(1.0 - (2.0 * s - 1.0).abs(), 1.5);
        let g = (1.0 - self.point) * round + self.point * tri;
        // Irregular lobes: the sinus depth blends from this period's lower sinus to its upper
        // one, and the lobe's reach scales only its raised part (g), so the outline is continuous.
        let depth = self.depth * (1.0 + self.sinus[k] * (1.0 - u) + self.sinus[k + 1] * u);
        (1.0 - depth.min(0.95) * (1.0 - g)) * (1.0 + self.reach[k] * g)
    }

    /// One half at `t` (0 tip, 1 base); `tooth` widens it by that fraction, `width` scales it.
    pub fn raw(&self, t: f64, tooth: f64, width: f64) -> DVec2 {
        let y = 1.0 - t.clamp(0.0, 1.0);
        let x = if t <= 0.0 || t >= 1.0 { 0.0 } else { self.envelope(y) * self.lobe(y) * (1.0 + tooth) * width };
        DVec2::new(x, y)
    }

    /// `t` of every lobe apex, from the tip down (the terminal lobe at the tip excluded).
    pub fn lobe_tips(&self) -> Vec<f64> {
        let n = f64::from(self.lobes);
        (0..self.lobes as usize)
            .rev()
            .map(|k| 1.0 - (PINNATE_Y0 + self.phase_of(k, self.apex()) / (n + 0.5) * (1.0 - PINNATE_Y0)))
            .collect()
    }

    /// `t` of every sinus and lobe apex (sampling seeds: the profile has kinks there).
    pub fn seeds(&self) -> Vec<f64> {
        let n = f64::from(self.lobes);
        let mut out = self.lobe_tips();
        out.extend(
            (0..=self.lobes as usize).map(|k| 1.0 - (PINNATE_Y0 + self.starts[k] / (n + 0.5) * (1.0 - PINNATE_Y0))),
        );
        out
    }
}

/// A palmate blade: lobes radiating from the petiole junction.
#[derive(Clone, Debug)]
pub struct Palmate {
    /// `(angle from the tip's direction, length)` of the lobes on one half (angle ≥ 0).
    lobes: Vec<(f64, f64)>,
    h: f64,
    depth: f64,
    e: f64,
    teeth: u32,
    /// Two lobes: a notched fan (ginkgo), whose sides run straight into the petiole.
    fan: bool,
    /// Mean radius over the half-turn: the margin's tooth scale.
    pub r_mean: f64,
}

impl Palmate {
    /// The blade of the `leaf_*` parameters.
    pub fn from_params(p: &LeafParams) -> Palmate {
        let n = p.leaf_lobes.max(1);
        let spread = f64::from(p.leaf_lobe_spread) * PI / 180.0;
        let (angles, h): (Vec<f64>, f64) = if n == 1 {
            (vec![0.0], spread.max(0.3))
        } else {
            let spacing = 2.0 * spread / f64::from(n - 1);
            let first = if n % 2 == 1 { 0.0 } else { 0.5 * spacing };
            ((0..n.div_ceil(2)).map(|k| first + f64::from(k) * spacing).collect(), 0.5 * spacing)
        };
        let falloff = if n >= 3 { 0.45 } else { 0.0 };
        let lobes = angles
            .iter()
            .map(|&a| {
                let f = a / spread.max(1e-6);
                (a, 1.0 - falloff * f * f)
            })
            .collect();
        let point = f64::from(p.leaf_lobe_point);
        let mut s = Palmate {
            lobes,
            h,
            depth: f64::from(p.leaf_lobe_depth),
            e: 3.0 + (0.7 - 3.0) * point,
            teeth: p.leaf_lobe_teeth,
            fan: n == 2,
            r_mean: 1.0,
        };
        let samples = 256;
        s.r_mean = (0..=samples).map(|i| s.radius(PI * f64::from(i) / f64::from(samples)).0).sum::<f64>()
            / f64::from(samples + 1);
        s
    }

    /// The lobe teeth's height at `u` (0 on the lobe's axis, 1 at the sinus), a fraction of the
    /// lobe's length: `teeth` saw teeth over `u ∈ [0.2, 0.85]`, apex toward the lobe's tip.
    fn tooth(&self, u: f64) -> f64 {
        let tau = (u - 0.2) / 0.65 * f64::from(self.teeth);
        if self.teeth == 0 || !(0.0..f64::from(self.teeth)).contains(&tau) {
            return 0.0;
        }
        let fr = tau - libm::floor(tau);
        let wave = if fr < 0.3 { fr / 0.3 } else { (1.0 - fr) / 0.7 };
        LOBE_TOOTH * (1.0 - 0.5 * u) * wave
    }

    /// One lobe's radius at angular offset `du` (radians) from its axis (`outward`: on its side
    /// away from the tip's direction).
    fn profile(&self, len: f64, du: f64, outermost: bool, outward: bool) -> f64 {
        let u = du.abs() / self.h;
        if self.fan && outermost && outward {
            // A fan's outer flank keeps nearly its length to the edge, then ends within a few
            // degrees: straight sides into the petiole instead of round shoulders.
            let fade = ((1.0 + FAN_FADE - u) / FAN_FADE).clamp(0.0, 1.0);
            return len * (1.0 - FAN_SHOULDER * u.min(1.0) * u.min(1.0)) * fade;
        }
        if u <= 1.0 {
            len * (1.0 - self.depth * pw(u, self.e) + self.tooth(u))
        } else if outermost {
            let fade = ((1.0 + FADE - u) / FADE).max(0.0);
            len * (1.0 - self.depth) * fade * fade
        } else {
            0.0
        }
    }

    /// The radius at `θ` (0 = the tip's direction, π = the petiole) and how close `θ` is to a
    /// lobe's top (1 on top, 0 in a sinus).
    pub fn radius(&self, theta: f64) -> (f64, f64) {
        let last = self.lobes.len() - 1;
        let (mut sum, mut top, mut max) = (0.0, 0.0f64, 0.0f64);
        for (k, &(a, len)) in self.lobes.iter().enumerate() {
            for axis in [a, -a] {
                // Outward: on the side of the lobe away from the tip's direction.
                let r = self.profile(len, theta - axis, k == last, (theta - axis) * axis > 0.0);
                sum += pw(r, SMOOTH_MAX);
                max = max.max(r);
                let u = (theta - axis).abs() / self.h;
                top = top.max(1.0 - u.min(1.0));
                if a == 0.0 {
                    break;
                }
            }
        }
        // A fan's notch is where its two lobes meet: there the smooth maximum of the two (each
        // at the end of its profile) stood 2^⅛ above either, a spike in the notch; the plain
        // maximum cuts a clean V.
        let (r, floor) = if self.fan { (max, FAN_FLOOR) } else { (pw(sum, 1.0 / SMOOTH_MAX), PALMATE_FLOOR) };
        (r.max(floor), libm::sqrt(top))
    }

    /// One half at `t` (0 tip, 1 base) about the junction's polar centre: `tooth` (a fraction of
    /// the mean radius) is added where the lobes stand out, `width` scales the radius.
    pub fn raw(&self, t: f64, tooth: f64, width: f64) -> DVec2 {
        let theta = PI * t.clamp(0.0, 1.0);
        let (r, top) = self.radius(theta);
        let r = (r + tooth * top * self.r_mean) * width;
        let x = if t <= 0.0 || t >= 1.0 { 0.0 } else { r * libm::sin(theta) };
        DVec2::new(x, r * libm::cos(theta))
    }

    /// `t` of every lobe apex on one half, from the tip down.
    pub fn lobe_tips(&self) -> Vec<f64> {
        self.lobes.iter().map(|&(a, _)| a / PI).collect()
    }

    /// `t` of every lobe apex and sinus (sampling seeds).
    pub fn seeds(&self) -> Vec<f64> {
        let mut out = self.lobe_tips();
        out.extend(self.lobes.iter().map(|&(a, _)| (a + self.h) / PI));
        out.extend(self.lobes.iter().map(|&(a, _)| (a - self.h) / PI));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pinnate_envelope_is_widest_at_base_over_base_plus_tip() {
        let mut p = LeafParams::default();
        (p.leaf_base_shape, p.leaf_tip_shape, p.leaf_aspect, p.leaf_lobes) = (1.5, 0.5, 0.6, 0);
        let b = Pinnate::from_params(&p);
        let ys = 0.75;
        assert!((b.envelope(ys) - 0.3).abs() < 1e-6);
        assert!(b.envelope(ys - 0.05) < 0.3 && b.envelope(ys + 0.05) < 0.3);
        assert_eq!(b.raw(0.0, 0.0, 1.0), DVec2::new(0.0, 1.0));
        assert_eq!(b.raw(1.0, 0.0, 1.0), DVec2::ZERO);
    }

    #[test]
    fn palmate_odd_lobes_put_one_at_the_tip_and_even_a_notch() {
        let mut p = LeafParams::default();
        (p.leaf_lobes, p.leaf_lobe_depth, p.leaf_lobe_spread) = (5, 0.5, 120.0);
        let five = Palmate::from_params(&p);
        assert_eq!(five.lobe_tips().len(), 3);
        assert!(five.radius(0.0).0 > five.radius(30f64.to_radians()).0);
        p.leaf_lobes = 2;
        let two = Palmate::from_params(&p);
        assert!(two.radius(0.0).0 < two.radius(120f64.to_radians()).0, "a notch at the tip");
    }
}
