//! # Leaf margin
//!
//! Stage 2, the margin (Mtree's *Leaf Generation Guide* §2): teeth as a modulation of the
//! outline by `1 + depth · A · wave(f)`, radial about the superformula centre or sideways from
//! the midrib for the spline outline, so the edge stays a simple polygon for every depth. For the
//! superformula the tooth is added at the half's mean radius, `r + depth · A · wave · r_mean`
//! (the additive form of the guide's `r (1 + depth · wave)`), because the formula's centre can sit
//! near one end of the blade and `r · depth` would give huge teeth at one end and none at the
//! other; for the spline, `x (1 + depth · A · wave)` lets teeth fade toward petiole and tip.
//!
//! `f = s(t) · teeth / 2 + f_peak` counts teeth from the tip along each half (`t` = 0 at the
//! tip, 1 at the base; `s` the fraction of the margin-free half's arc length from the tip, so
//! teeth are evenly spaced along the edge, and lobes of a symmetric superformula, whose arcs are
//! congruent, line up with the margin's lobes; `teeth` teeth around the whole margin). `f_peak`
//! puts a tooth apex exactly at the tip. Waves over `f' = frac(f)`:
//!
//! | margin  | wave(f')                                                     | apex at |
//! |---------|--------------------------------------------------------------|---------|
//! | Entire  | 0                                                            | -       |
//! | Serrate | `f'/p` rising, `(1 - f')/(1 - p)` falling, `p = (1 - sharpness)/2` | `p` |
//! | Dentate | `1 - 2 |f' - 0.5|`                                           | 0.5     |
//! | Crenate | `(1 + sin 2πf')/2`                                           | 0.25    |
//! | Lobed   | `(1 + cos 2πf')/2`                                           | 0       |
//!
//! `f` grows from the tip toward the base, so a serrate apex close to its tooth's apical sinus
//! (small `p`) leans the tooth toward the tip. **Asymmetry**: a non-zero seed draws per-tooth
//! amplitude jitter `A = 1 + J(f) sin(πt)` (`J` piecewise linear between seeded knots in ±0.5)
//! and a per-side width change `1 ± 0.06 sin(πt)`, both zero at tip and base so the halves still
//! meet; seed 0 draws nothing and the two halves are exact mirror images.
//!
//! The margin stage then fixes the leaf frame (base at the origin, tip at `(0, 1)`, width =
//! aspect × height for the superformula) and resamples each half adaptively, seeded with the
//! outline stage's parameters, every kink of the wave and ten samples per tooth.

use crate::error::SylvaError;
use crate::leaf::geom;
use crate::leaf::geom::DVec2;
use crate::leaf::outline::{self, BaseOutline, Shape};
use crate::params::LeafParams;
use crate::params::{LeafMargin, LeafOutline};
use crate::rng::Rng;
use glam::Vec2;

const PI: f64 = std::f64::consts::PI;

/// The margin modulation of both halves.
#[derive(Clone, Debug)]
pub struct MarginProfile {
    kind: LeafMargin,
    teeth: f64,
    depth: f64,
    /// Serrate apex position within a tooth.
    peak: f64,
    /// `f` at the tip.
    f_peak: f64,
    /// Amplitude jitter knots per side (index = tooth number from the tip).
    knots: [Vec<f64>; 2],
    /// Width change per side.
    side_w: [f64; 2],
    /// Arc-length fraction `s` at evenly spaced `t` (`ARC + 1` values), and `t` at evenly
    /// spaced `s`.
    s_of_t: Vec<f64>,
    t_of_s: Vec<f64>,
}

const ARC: usize = 512;

/// Linear lookup in a table evenly spaced over [0, 1].
fn lookup(table: &[f64], x: f64) -> f64 {
    let n = table.len() - 1;
    let f = x.clamp(0.0, 1.0) * n as f64;
    let i = (f as usize).min(n - 1);
    table[i] + (table[i + 1] - table[i]) * (f - i as f64)
}

/// Arc-length tables of one margin-free half.
fn arc_tables(shape: &Shape) -> (Vec<f64>, Vec<f64>) {
    let mut s_of_t = Vec::with_capacity(ARC + 1);
    let mut len = 0.0;
    let mut prev = shape.raw(0.0, 0.0, 1.0);
    s_of_t.push(0.0);
    for i in 1..=ARC {
        let q = shape.raw(i as f64 / ARC as f64, 0.0, 1.0);
        len += (q - prev).length();
        s_of_t.push(len);
        prev = q;
    }
    if len <= 0.0 {
        let id: Vec<f64> = (0..=ARC).map(|i| i as f64 / ARC as f64).collect();
        return (id.clone(), id);
    }
    for v in &mut s_of_t {
        *v /= len;
    }
    let mut t_of_s = Vec::with_capacity(ARC + 1);
    let mut j = 0;
    for k in 0..=ARC {
        let target = k as f64 / ARC as f64;
        while j + 1 < ARC && s_of_t[j + 1] < target {
            j += 1;
        }
        let span = s_of_t[j + 1] - s_of_t[j];
        let f = if span > 0.0 { ((target - s_of_t[j]) / span).clamp(0.0, 1.0) } else { 0.0 };
        t_of_s.push((j as f64 + f) / ARC as f64);
    }
    (s_of_t, t_of_s)
}

impl MarginProfile {
    /// The profile chosen by the parameters (`leaf_margin`, `leaf_teeth`, `leaf_tooth_depth`,
    /// `leaf_tooth_sharpness`, `leaf_asymmetry_seed`).
    pub fn from_params(p: &LeafParams, shape: &Shape) -> MarginProfile {
        let kind = if p.leaf_teeth == 0 { LeafMargin::Entire } else { p.leaf_margin };
        let teeth = f64::from(p.leaf_teeth);
        let peak = (0.5 * (1.0 - f64::from(p.leaf_tooth_sharpness))).clamp(0.03, 0.5);
        let f_peak = match kind {
            LeafMargin::Entire | LeafMargin::Lobed => 0.0,
            LeafMargin::Serrate => peak,
            LeafMargin::Dentate => 0.5,
            LeafMargin::Crenate => 0.25,
        };
        let mut knots = [Vec::new(), Vec::new()];
        let mut side_w = [0.0; 2];
        if p.leaf_asymmetry_seed != 0 {
            let mut rng = Rng::new(u64::from(p.leaf_asymmetry_seed), "leaf-margin");
            let n = (teeth * 0.5 + f_peak) as usize + 2;
            for (side, k) in knots.iter_mut().enumerate() {
                *k = (0..n).map(|_| f64::from(rng.var(0.5))).collect();
                side_w[side] = f64::from(rng.var(0.06));
            }
        }
        let (s_of_t, t_of_s) = if kind == LeafMargin::Entire { (Vec::new(), Vec::new()) } else { arc_tables(shape) };
        MarginProfile { kind, teeth, depth: f64::from(p.leaf_tooth_depth), peak, f_peak, knots, side_w, s_of_t, t_of_s }
    }

    /// The wave (0..1) at tooth phase `fr` in [0, 1).
    fn wave(&self, fr: f64) -> f64 {
        match self.kind {
            LeafMargin::Entire => 0.0,
            LeafMargin::Serrate => {
                if fr < self.peak {
                    fr / self.peak
                } else {
                    (1.0 - fr) / (1.0 - self.peak)
                }
            }
            LeafMargin::Dentate => 1.0 - 2.0 * (fr - 0.5).abs(),
            LeafMargin::Crenate => 0.5 * (1.0 + libm::sin(2.0 * PI * fr)),
            LeafMargin::Lobed => 0.5 * (1.0 + libm::cos(2.0 * PI * fr)),
        }
    }

    /// The tooth height (`depth · A · wave`, a fraction of the tooth scale) and the width
    /// factor of half `side` (0 = left, 1 = right) at `t` (0 = tip, 1 = base).
    pub fn at(&self, side: usize, t: f64) -> (f64, f64) {
        let s = libm::sin(PI * t.clamp(0.0, 1.0));
        let width = 1.0 + self.side_w[side] * s;
        if self.kind == LeafMargin::Entire {
            return (0.0, width);
        }
        let f = lookup(&self.s_of_t, t) * self.teeth * 0.5 + self.f_peak;
        let k = f.floor();
        let amp = match self.knots[side].as_slice() {
            [] => 1.0,
            knots => {
                let i = (k as usize).min(knots.len() - 2);
                let j = knots[i] + (knots[i + 1] - knots[i]) * (f - i as f64).clamp(0.0, 1.0);
                1.0 + j * s
            }
        };
        (self.depth * amp * self.wave(f - k), width)
    }

    /// Parameters `t` in (0, 1) where the wave has a kink or a tooth boundary.
    pub fn kinks(&self) -> Vec<f64> {
        let marks: &[f64] = match self.kind {
            LeafMargin::Entire => return Vec::new(),
            LeafMargin::Serrate => &[0.0, self.peak],
            LeafMargin::Dentate => &[0.0, 0.5],
            LeafMargin::Crenate | LeafMargin::Lobed => &[0.0],
        };
        let mut out = Vec::new();
        let last = (self.teeth * 0.5 + self.f_peak).ceil() as i64;
        for k in 0..=last {
            for &m in marks {
                let a = (k as f64 + m - self.f_peak) * 2.0 / self.teeth;
                if a > 0.0 && a < 1.0 {
                    out.push(lookup(&self.t_of_s, a));
                }
            }
        }
        out
    }

    /// Ten parameters per tooth, evenly spaced along the arc (the sampling seeds of the teeth).
    fn tooth_seeds(&self) -> Vec<f64> {
        if self.kind == LeafMargin::Entire {
            return Vec::new();
        }
        let n = (5.0 * self.teeth).ceil().min(3000.0) as usize;
        (1..n).map(|i| lookup(&self.t_of_s, i as f64 / n as f64)).collect()
    }
}

/// Maps a raw half point into the leaf frame.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    y0: f64,
    ylen: f64,
    sx: f64,
}

impl Frame {
    /// Leaf-frame point of half `sign` (-1 left, +1 right).
    pub fn apply(&self, raw: DVec2, sign: f64) -> DVec2 {
        DVec2::new(sign * raw.x * self.sx, (raw.y - self.y0) / self.ylen)
    }
}

/// The final blade outline in the leaf frame.
///
/// **Leaf frame**: leaf units (the base-to-tip distance is 1), the petiole attaches at the
/// origin, the tip is at `(0, 1)`, `+x` is the blade's right half seen from the front, and the
/// front face looks along `+z`. Basal lobes (maple) may reach below `y = 0`.
#[derive(Clone, Debug)]
pub struct Outline {
    /// The outline, counter-clockwise, starting at the tip: down the left half (`x < 0`) to the
    /// base, then up the right half. No repeated points, none on the line through its neighbours.
    pub points: Vec<Vec2>,
    /// Index of the base point (`(0, 0)`).
    pub base_index: usize,
    /// Per point: `t` along its half (0 = tip, 1 = base).
    pub params: Vec<f32>,
    /// A point every ray from which crosses the outline once (superformula centre), or the
    /// middle of the midrib (spline outline).
    pub center: Vec2,
    /// The margin-free outline in the same frame (counter-clockwise), for overlays.
    pub base_outline: Vec<Vec2>,
}

impl Outline {
    /// One half from tip to base: 0 = left, 1 = right.
    pub fn half(&self, side: usize) -> Vec<Vec2> {
        if side == 0 {
            self.points[..=self.base_index].to_vec()
        } else {
            let mut out = vec![self.points[0]];
            out.extend(self.points[self.base_index..].iter().rev());
            out
        }
    }
}

/// Stage 2: modulate the outline by the margin, fix the leaf frame, and sample the final
/// outline adaptively. Refuses parameters whose blade has almost no area (extreme superformula
/// exponents draw needle-thin spikes around an empty centre): less than 0.1% of its bounding
/// box, or fewer than six outline points.
pub fn build(p: &LeafParams, base: &BaseOutline) -> Result<Outline, SylvaError> {
    let shape = &base.shape;
    let profile = MarginProfile::from_params(p, shape);
    let radial = shape.is_radial();
    let frame = frame(p, shape, &profile);
    let detail = f64::from(p.leaf_detail);
    let mut extra = base.ts.clone();
    extra.extend(profile.kinks());
    extra.extend(profile.tooth_seeds());
    let seeds = outline::seeds(1, &extra);
    let tol = 0.0008 / detail;
    let half = |side: usize| {
        let sign = if side == 0 { -1.0 } else { 1.0 };
        let eval = |t: f64| {
            let (tooth, width) = profile.at(side, t);
            frame.apply(shape.raw(t, tooth, width), sign)
        };
        outline::adaptive(&eval, &seeds, tol, 6000)
    };
    let left = half(0);
    let right = if profile.side_w == [0.0; 2] {
        left.iter().map(|&(t, q)| (t, DVec2::new(-q.x, q.y))).collect()
    } else {
        half(1)
    };
    let center = if radial { frame.apply(DVec2::ZERO, 1.0) } else { DVec2::new(0.0, 0.5) };
    let (points, params, base_index) = assemble(&left, &right, radial.then_some(center.as_vec2()));
    let base_half: Vec<DVec2> = base.raw.iter().map(|&r| frame.apply(r, -1.0)).collect();
    let mut base_outline: Vec<Vec2> = base_half.iter().map(|q| q.as_vec2()).collect();
    base_outline.extend(
        base_half
            .iter()
            .rev()
            .skip(1)
            .take(base_half.len().saturating_sub(2))
            .map(|q| Vec2::new(-q.x as f32, q.y as f32)),
    );
    let (lo, hi) = geom::bounds(&points);
    let box_area = f64::from((hi.x - lo.x) * (hi.y - lo.y));
    if points.len() < 6 || geom::polygon_area(&points) < 1e-3 * box_area {
        let what = match p.leaf_outline {
            LeafOutline::Superformula => format!(
                "the superformula m={}, a={}, b={}, n1={}, n2={}, n3={}",
                p.leaf_m, p.leaf_a, p.leaf_b, p.leaf_n1, p.leaf_n2, p.leaf_n3
            ),
            LeafOutline::Spline => {
                format!("the spline outline {}°/{}, {}°/{}", p.leaf_angle1, p.leaf_l1, p.leaf_angle2, p.leaf_l2)
            }
            LeafOutline::Pinnate | LeafOutline::Palmate => {
                format!("the {} outline with Aspect Ratio {}", p.leaf_outline.label(), p.leaf_aspect)
            }
        };
        return Err(SylvaError::InvalidParam {
            param: "leaf_outline".into(),
            message: format!(
                "leaf_outline (Leaf Outline): {what} draws a blade with almost no area (needle-thin spikes); raise n1 or lower n2 and n3"
            ),
        });
    }
    Ok(Outline { points, base_index, params, center: center.as_vec2(), base_outline })
}

/// The frame: base to the origin, tip to `(0, 1)`, and for the superformula the width scaled to
/// `aspect ×` the height (measured on a coarse pre-scan of both halves).
fn frame(p: &LeafParams, shape: &Shape, profile: &MarginProfile) -> Frame {
    if !shape.is_radial() {
        return Frame { y0: 0.0, ylen: 1.0, sx: 1.0 };
    }
    let at = |side: usize, t: f64| {
        let (tooth, width) = profile.at(side, t);
        shape.raw(t, tooth, width)
    };
    let tip = at(0, 0.0);
    let base = at(0, 1.0);
    let (y0, ylen) = (base.y, tip.y - base.y);
    let (mut ymin, mut ymax, mut w) = (base.y, tip.y, [0.0f64; 2]);
    const SCAN: usize = 256;
    for (side, wmax) in w.iter_mut().enumerate() {
        for i in 0..=SCAN {
            let t = i as f64 / SCAN as f64;
            let q = at(side, t);
            *wmax = wmax.max(q.x);
            ymin = ymin.min(q.y);
            ymax = ymax.max(q.y);
        }
    }
    let height = (ymax - ymin) / ylen;
    let width = w[0] + w[1];
    let sx = if width > 1e-12 { f64::from(p.leaf_aspect) * height / width } else { 1.0 / ylen };
    Frame { y0, ylen, sx }
}

/// One half from tip to base without points closer than 1e-5 to their predecessor, on the line
/// through their neighbours, or at the tip of a needle-thin spike (the tip and the base always stay). Each half is cleaned
/// on its own, so mirror-image halves stay mirror images.
///
/// Each kept point must also advance: by angle about `center` (counter-clockwise for the left
/// half `sign = 1`, clockwise for the right half `sign = -1`) for a radial outline, or downward
/// for the spline's. The raw curve does so exactly; this keeps it so after rounding to `f32`, so
/// the polygon is simple (and star-shaped about the centre for the superformula).
fn clean_half(half: &[(f64, DVec2)], center: Option<Vec2>, sign: f64) -> Vec<(Vec2, f32)> {
    const EPS: f32 = 1e-5;
    let n = half.len();
    let mut pts: Vec<(Vec2, f32)> = half.iter().map(|&(t, q)| (q.as_vec2(), t as f32)).collect();
    pts[0].0 = Vec2::new(0.0, 1.0);
    pts[n - 1].0 = Vec2::ZERO;
    let base = pts[n - 1];
    let mut kept: Vec<(Vec2, f32)> = Vec::with_capacity(n);
    kept.push(pts[0]);
    let advances = |prev: Vec2, q: Vec2| match center {
        Some(c) => {
            let o = sign * geom::orient(c, prev, q);
            o > 1e-7 * f64::from((prev - c).length() * (q - c).length())
        }
        None => q.y < prev.y,
    };
    for &pt in &pts[1..n - 1] {
        let last = kept.last().expect("the tip").0;
        if (pt.0 - last).length() > EPS
            && (pt.0 - base.0).length() > EPS
            && advances(last, pt.0)
            && advances(pt.0, base.0)
        {
            kept.push(pt);
        }
    }
    kept.push(base);
    loop {
        let before = kept.len();
        let mut out = Vec::with_capacity(before);
        out.push(kept[0]);
        for i in 1..before - 1 {
            let (a, b, c) = (kept[i - 1].0, kept[i].0, kept[i + 1].0);
            // Twice the triangle's area against its longer edge squared: points on a straight
            // run, or at the tip of a needle-thin spike (turning by almost 180°, as extreme
            // superformula exponents make), add no area, only rounding trouble.
            let longer = f64::from((b - a).length_squared().max((c - b).length_squared()));
            if geom::orient(a, b, c).abs() > 1e-6 * longer {
                out.push(kept[i]);
            }
        }
        out.push(kept[before - 1]);
        kept = out;
        if kept.len() == before {
            return kept;
        }
    }
}

/// Joins the halves (each from tip to base) into one counter-clockwise polygon starting at the
/// tip: the left half down, then the right half up.
fn assemble(left: &[(f64, DVec2)], right: &[(f64, DVec2)], center: Option<Vec2>) -> (Vec<Vec2>, Vec<f32>, usize) {
    let (l, r) = (clean_half(left, center, 1.0), clean_half(right, center, -1.0));
    let mut pts: Vec<(Vec2, f32)> = l.clone();
    pts.extend(r[1..r.len() - 1].iter().rev());
    (pts.iter().map(|q| q.0).collect(), pts.iter().map(|q| q.1).collect(), l.len() - 1)
}
