//! Stage 1, the outline (Mtree's *Leaf Generation Guide* §1; Michel Anders 2013, "A OSL leaf
//! shape shader for Cycles", blog.michelanders.nl).
//!
//! * **Superformula** (Gielis 2003): `r(φ) = (|cos(mφ/4)/a|^n2 + |sin(mφ/4)/b|^n3)^(-1/n1)`,
//!   evaluated in log space (so extreme exponents neither overflow nor underflow) and divided by
//!   its largest value. The leaf's midrib is the formula's symmetry axis: the **tip** is the
//!   point at `φ = π`, the **base** the point at `φ = 0` (odd `m` then puts a lobe at the tip and
//!   a sinus at the petiole, as in maple and oak). Each half is swept by `θ = π t` from the tip
//!   (`t = 0`) to the base (`t = 1`) and mirrored, so the curve always closes.
//! * **Spline**: one cubic Bézier `P0 = (0, 0)`, `P1 = L1 (cos A1, sin A1)`,
//!   `P2 = (1 - L2 cos A2, L2 sin A2)`, `P3 = (1, 0)` (x along the midrib, y half-width),
//!   mirrored about the midrib. With `A ∈ [5°, 90°]` and `L ∈ [0.05, 1]` the curve is monotone
//!   along the midrib, so the outline is always a simple polygon.
//!
//! * **Pinnate** and **Palmate**: the lobed blades of [`crate::leaf::lobes`] (a profile along
//!   the midrib with lobes along it; lobes radiating from the petiole junction).
//!
//! All halves are sampled over `t` with curvature-adaptive refinement ([`adaptive`]): an
//! interval is split while its midpoint strays from the chord (sagitta) or the curve turns
//! more than 15° across it, so flat stretches stay sparse and tight bends get points.

use crate::leaf::geom::DVec2;
use crate::leaf::lobes;
use crate::params::LeafOutline;
use crate::params::LeafParams;

const PI: f64 = std::f64::consts::PI;

/// A prepared outline curve: evaluates one half of the blade before normalisation.
#[derive(Clone, Debug)]
pub enum Shape {
    /// Superformula, radial about its centre (the origin of the raw frame).
    Superformula {
        /// Symmetry number `m`.
        m: f64,
        /// `a`.
        a: f64,
        /// `b`.
        b: f64,
        /// `n1`.
        n1: f64,
        /// `n2`.
        n2: f64,
        /// `n3`.
        n3: f64,
        /// `ln` of the largest radius over the half-turn (radii are divided by it).
        ln_max: f64,
        /// Mean radius over the half-turn (after the division): the margin's tooth scale.
        r_mean: f64,
    },
    /// Cubic spline, scaled sideways from the midrib.
    Spline {
        /// Control points `P0..P3` (x along the midrib, y half-width).
        p: [DVec2; 4],
        /// Bézier parameter at evenly spaced arc lengths from the tip (`ARC_SAMPLES + 1` values).
        arc: Vec<f64>,
    },
    /// A profile along the midrib with lobes along it.
    Pinnate(lobes::Pinnate),
    /// Lobes radiating from the petiole junction (radial about it).
    Palmate(lobes::Palmate),
}

const ARC_SAMPLES: usize = 256;

impl Shape {
    /// The curve chosen by `leaf_outline` with its parameters.
    pub fn from_params(p: &LeafParams) -> Shape {
        match p.leaf_outline {
            LeafOutline::Superformula => {
                let mut s = Shape::Superformula {
                    m: f64::from(p.leaf_m),
                    a: f64::from(p.leaf_a),
                    b: f64::from(p.leaf_b),
                    n1: f64::from(p.leaf_n1),
                    n2: f64::from(p.leaf_n2),
                    n3: f64::from(p.leaf_n3),
                    ln_max: 0.0,
                    r_mean: 1.0,
                };
                let ln_r: Vec<f64> = (0..=360).map(|i| s.ln_radius(PI * i as f64 / 360.0)).collect();
                let ln_max = ln_r.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                let mean = ln_r.iter().map(|&l| libm::exp(l - ln_max)).sum::<f64>() / ln_r.len() as f64;
                if let Shape::Superformula { ln_max: l, r_mean, .. } = &mut s {
                    *l = ln_max;
                    *r_mean = mean;
                }
                s
            }
            LeafOutline::Spline => {
                let (a1, a2) = (f64::from(p.leaf_angle1).to_radians(), f64::from(p.leaf_angle2).to_radians());
                let (l1, l2) = (f64::from(p.leaf_l1), f64::from(p.leaf_l2));
                let pts = [
                    DVec2::ZERO,
                    DVec2::new(libm::cos(a1), libm::sin(a1)) * l1,
                    DVec2::new(1.0 - libm::cos(a2) * l2, libm::sin(a2) * l2),
                    DVec2::new(1.0, 0.0),
                ];
                Shape::Spline { arc: arc_table(&pts), p: pts }
            }
            LeafOutline::Pinnate => Shape::Pinnate(lobes::Pinnate::from_params(p)),
            LeafOutline::Palmate => Shape::Palmate(lobes::Palmate::from_params(p)),
        }
    }

    /// `t` of the lobe apices of one half, from the tip down (lobed outlines; empty otherwise).
    pub fn lobe_tips(&self) -> Vec<f64> {
        match self {
            Shape::Pinnate(s) => s.lobe_tips(),
            Shape::Palmate(s) => s.lobe_tips(),
            _ => Vec::new(),
        }
    }

    /// `ln r(φ)` of the superformula (0 for the spline).
    fn ln_radius(&self, phi: f64) -> f64 {
        let Shape::Superformula { m, a, b, n1, n2, n3, .. } = *self else {
            return 0.0;
        };
        let q = m * phi / 4.0;
        let term = |v: f64, n: f64| if v > 0.0 { n * libm::log(v) } else { f64::NEG_INFINITY };
        let t2 = term((libm::cos(q) / a).abs(), n2);
        let t3 = term((libm::sin(q) / b).abs(), n3);
        let hi = t2.max(t3);
        let lse = hi + libm::log(libm::exp(t2 - hi) + libm::exp(t3 - hi));
        -lse / n1
    }

    /// Whether margins scale the radius about the centre (superformula) or the half-width
    /// (spline).
    pub fn is_radial(&self) -> bool {
        matches!(self, Shape::Superformula { .. } | Shape::Palmate(_))
    }

    /// One half of the blade at `t` (0 = tip, 1 = base) in the raw frame: `x ≥ 0` is the
    /// half-width, `y` runs toward the tip. The margin adds `tooth` (≥ 0, a fraction of the
    /// tooth scale) and multiplies by `width`: the superformula's radius becomes
    /// `(r + tooth · r_mean) · width` (teeth of one size all along the edge), the spline's
    /// half-width `x · (1 + tooth) · width` (teeth fading toward the petiole and the tip).
    pub fn raw(&self, t: f64, tooth: f64, width: f64) -> DVec2 {
        match self {
            Shape::Superformula { ln_max, r_mean, .. } => {
                let theta = PI * t;
                let r = (libm::exp(self.ln_radius(PI - theta) - ln_max) + tooth * r_mean) * width;
                let x = if t <= 0.0 || t >= 1.0 { 0.0 } else { r * libm::sin(theta) };
                DVec2::new(x, r * libm::cos(theta))
            }
            Shape::Spline { p, arc } => {
                let tau = lookup(arc, 1.0 - t.clamp(0.0, 1.0));
                let q = bezier(p, tau);
                let x = if t <= 0.0 || t >= 1.0 { 0.0 } else { q.y * (1.0 + tooth) * width };
                DVec2::new(x, q.x)
            }
            Shape::Pinnate(s) => s.raw(t, tooth, width),
            Shape::Palmate(s) => s.raw(t, tooth, width),
        }
    }
}

/// Cubic Bézier point.
pub fn bezier(p: &[DVec2; 4], t: f64) -> DVec2 {
    let u = 1.0 - t;
    p[0] * (u * u * u) + p[1] * (3.0 * u * u * t) + p[2] * (3.0 * u * t * t) + p[3] * (t * t * t)
}

/// Bézier parameters at evenly spaced arc-length fractions measured from the base.
fn arc_table(p: &[DVec2; 4]) -> Vec<f64> {
    const FINE: usize = 1024;
    let mut cum = Vec::with_capacity(FINE + 1);
    let mut len = 0.0;
    let mut prev = p[0];
    cum.push(0.0);
    for i in 1..=FINE {
        let q = bezier(p, i as f64 / FINE as f64);
        len += (q - prev).length();
        cum.push(len);
        prev = q;
    }
    let mut out = Vec::with_capacity(ARC_SAMPLES + 1);
    let mut j = 0;
    for k in 0..=ARC_SAMPLES {
        let target = len * k as f64 / ARC_SAMPLES as f64;
        while j + 1 < FINE && cum[j + 1] < target {
            j += 1;
        }
        let span = cum[j + 1] - cum[j];
        let f = if span > 0.0 { ((target - cum[j]) / span).clamp(0.0, 1.0) } else { 0.0 };
        out.push((j as f64 + f) / FINE as f64);
    }
    out[ARC_SAMPLES] = 1.0;
    out
}

/// Linear lookup in an evenly spaced table over [0, 1].
fn lookup(table: &[f64], s: f64) -> f64 {
    let n = table.len() - 1;
    let x = s.clamp(0.0, 1.0) * n as f64;
    let i = (x as usize).min(n - 1);
    let f = x - i as f64;
    table[i] + (table[i + 1] - table[i]) * f
}

/// Refinement stops at this depth below the seed intervals.
const MAX_DEPTH: u32 = 12;
/// cos 15°: a sample pair turning more than this is split.
const COS_TURN: f64 = 0.965_925_826;

/// Curvature-adaptive sampling of a curve `eval(t)` over the sorted parameters `seeds` (which
/// must include the ends and every kink): returns `(t, point)` in order. Splits an interval
/// while its midpoint is more than `tol` from the chord or the curve turns more than 15° across
/// it, up to `max_points` points.
pub fn adaptive(eval: &dyn Fn(f64) -> DVec2, seeds: &[f64], tol: f64, max_points: usize) -> Vec<(f64, DVec2)> {
    let mut out: Vec<(f64, DVec2)> = Vec::with_capacity(seeds.len() * 2);
    let mut budget = max_points.saturating_sub(seeds.len());
    let mut prev = (seeds[0], eval(seeds[0]));
    out.push(prev);
    for &t in &seeds[1..] {
        let next = (t, eval(t));
        refine(eval, prev, next, 0, tol, &mut budget, &mut out);
        prev = next;
    }
    out
}

fn refine(
    eval: &dyn Fn(f64) -> DVec2,
    a: (f64, DVec2),
    b: (f64, DVec2),
    depth: u32,
    tol: f64,
    budget: &mut usize,
    out: &mut Vec<(f64, DVec2)>,
) {
    let tm = 0.5 * (a.0 + b.0);
    let pm = eval(tm);
    if depth < MAX_DEPTH && *budget > 0 && needs_split(a.1, pm, b.1, tol) {
        *budget -= 1;
        refine(eval, a, (tm, pm), depth + 1, tol, budget, out);
        refine(eval, (tm, pm), b, depth + 1, tol, budget, out);
    } else {
        out.push(b);
    }
}

fn needs_split(a: DVec2, m: DVec2, b: DVec2, tol: f64) -> bool {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 { ((m - a).dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    if (m - (a + ab * t)).length() > tol {
        return true;
    }
    let (u, v) = (m - a, b - m);
    let (lu, lv) = (u.length(), v.length());
    lu > 2.0 * tol && lv > 2.0 * tol && u.dot(v) < COS_TURN * lu * lv
}

/// Evenly spaced parameters over [0, 1] merged with `extra` (sorted, duplicates removed).
pub fn seeds(segments: usize, extra: &[f64]) -> Vec<f64> {
    let mut s: Vec<f64> = (0..=segments).map(|i| i as f64 / segments as f64).collect();
    s.extend(extra.iter().copied().filter(|t| (0.0..=1.0).contains(t)));
    s.sort_by(f64::total_cmp);
    s.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    s
}

/// What the outline stage hands to the margin stage.
#[derive(Clone, Debug)]
pub struct BaseOutline {
    /// The prepared curve.
    pub shape: Shape,
    /// Adaptive parameters of one half (`t`, 0 = tip, 1 = base): the seeds of the margin stage.
    pub ts: Vec<f64>,
    /// Raw points of one half at `ts` (margin-free, before normalisation).
    pub raw: Vec<DVec2>,
}

/// Stage 1: prepare the curve chosen by the parameters and sample one half adaptively.
/// `detail` scales the sampling density (`leaf_detail`).
pub fn build(p: &LeafParams) -> BaseOutline {
    let shape = Shape::from_params(p);
    let detail = f64::from(p.leaf_detail);
    let eval = |t: f64| shape.raw(t, 0.0, 1.0);
    let (segments, extra) = match &shape {
        Shape::Pinnate(s) => (24 + 4 * p.leaf_lobes as usize, s.seeds()),
        Shape::Palmate(s) => (24 + 4 * p.leaf_lobes as usize, s.seeds()),
        _ => (12 + 2 * (f64::from(p.leaf_m).ceil() as usize), Vec::new()),
    };
    let samples = adaptive(&eval, &seeds(segments, &extra), 0.0015 / detail, 4000);
    let (ts, raw) = samples.into_iter().unzip();
    BaseOutline { shape, ts, raw }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_superformula_has_unit_radius_and_tip_up() {
        let mut p = LeafParams::default();
        p.leaf_outline = LeafOutline::Superformula;
        (p.leaf_m, p.leaf_a, p.leaf_b, p.leaf_n1, p.leaf_n2, p.leaf_n3) = (4.0, 1.0, 1.0, 2.0, 2.0, 2.0);
        let s = Shape::from_params(&p);
        for i in 0..=10 {
            let q = s.raw(i as f64 / 10.0, 0.0, 1.0);
            assert!((q.length() - 1.0).abs() < 1e-9, "{q:?}");
        }
        assert!((s.raw(0.0, 0.0, 1.0) - DVec2::new(0.0, 1.0)).length() < 1e-12);
    }

    #[test]
    fn spline_half_is_monotone_along_the_midrib() {
        let mut p = LeafParams::default();
        p.leaf_outline = LeafOutline::Spline;
        (p.leaf_angle1, p.leaf_l1, p.leaf_angle2, p.leaf_l2) = (10.0, 1.0, 10.0, 1.0);
        let s = Shape::from_params(&p);
        let ys: Vec<f64> = (0..=200).map(|i| s.raw(i as f64 / 200.0, 0.0, 1.0).y).collect();
        assert!(ys.windows(2).all(|w| w[1] <= w[0] + 1e-12), "y must fall from tip to base");
        assert_eq!(s.raw(0.0, 0.0, 1.0), DVec2::new(0.0, 1.0));
        assert_eq!(s.raw(1.0, 0.0, 1.0), DVec2::ZERO);
    }

    #[test]
    fn adaptive_refines_bends_not_lines() {
        let line = adaptive(&|t| DVec2::new(t, 2.0 * t), &seeds(4, &[]), 1e-3, 1000);
        assert_eq!(line.len(), 5);
        let circle = adaptive(&|t| DVec2::new(libm::cos(PI * t), libm::sin(PI * t)), &seeds(4, &[]), 1e-3, 1000);
        assert!(circle.len() > 20, "{}", circle.len());
    }
}
