//! # Bezier twigs
//!
//! Bezier twigs, after the WebGL page *Modeling the Mighty Maple for Web* (ibiblio.org/e-notes)
//! (following Bloomenthal's "Modeling the Mighty Maple"): the thinnest stems are meshed as Bezier
//! cylinders, the tensor product of a circle and a quadratic Bezier spline. Three control circles
//! sit on the control polygon: R0 at the base, R2 at the tip, and the middle one with the page's
//! linear interpolation `R1 = (l0 R0 + l1 R2) / (l0 + l1)`, where `l0`, `l1` are the two leg
//! lengths. The middle circle is turned by `θ/2`, half the bend `θ` between the legs, and the tip
//! circle by `θ`, so each circle lies across its leg (the base one across the first leg, like the
//! tube's first ring). A ring at curve parameter `u` is the Bernstein blend of the three circles,
//! and its normals are the exact surface normals `∂S/∂φ × ∂S/∂u` of the patch.
//!
//! Which stems are twigs ([`mask`]): stems of the deepest level (`level == levels - 1`, with
//! `levels >= 2`, parametric trees only) that carry nothing (no child, no split clone), have a
//! linear radius profile (taper <= 1, no flare, no per-point radii) and that one quadratic span
//! represents faithfully: the span through the base, the centre curve's midpoint and the tip must
//! stay within half the base radius of the centre curve (checked at a quarter and three quarters,
//! so leaves placed on the centre curve still sit on the twig), bend by at most 90°, and have
//! both legs at least a tenth of the chord. Other stems stay tubes. Roots are never twigs.
//!
//! Resolution: the page steps along its control circle by `stu = 1, 2, 4, 8` to coarsen small
//! twigs; here the finest step (1) has four times the sides a tube of the same radius gets
//! ([`super::tube::sides_for`]), so step 4 (the default) matches the tube and 8 halves it (never
//! fewer than 3 sides). Rings along the curve follow its bend like the tube's (about one per 12°
//! on thick stems), the last ring sits a quarter span short of the tip and a small cone closes
//! the tip at an apex, exactly as the tube does, so the only open edges stay the buried base ring.

use super::stem::{sides_for, Base, StemMesh, StemWind};
use super::MeshBuilder;
use crate::math::{acos, cos, rad, sin, unit_or, TAU};
use crate::params::{GrowthMode, MeshParams, TwigDetail};
use crate::skeleton::{Skeleton, Stem, StemKind};
use glam::Vec3;

impl TwigDetail {
    /// The step: 1, 2, 4 or 8.
    pub fn step(self) -> u32 {
        1 << self as u32
    }
}

/// Sides around a twig of base radius `r` (m): four times the tube's sides divided by the step.
pub fn sides(r: f32, quality: f32, detail: TwigDetail) -> u32 {
    let full = 4 * sides_for(r, quality, 0);
    ((full as f32 / detail.step() as f32).round() as u32).clamp(3, 96)
}

/// The page's middle control radius: `R1 = (l0 R0 + l1 R2) / (l0 + l1)`.
pub fn middle_radius(l0: f32, l1: f32, r0: f32, r2: f32) -> f32 {
    let l = l0 + l1;
    if l > 0.0 {
        (l0 * r0 + l1 * r2) / l
    } else {
        0.5 * (r0 + r2)
    }
}

/// The quadratic Bezier span of a stem: control points and circle radii.
#[derive(Clone, Copy, Debug)]
pub struct Span {
    /// Control points: base, middle, tip.
    pub p: [Vec3; 3],
    /// Control circle radii R0, R1, R2.
    pub r: [f32; 3],
}

impl Span {
    /// The span of `stem`: through its base, the midpoint of its centre curve and its tip.
    pub fn fit(stem: &Stem) -> Span {
        let (p0, p2) = (stem.base(), stem.tip());
        let (mid, _) = stem.sample(0.5);
        let p1 = 2.0 * mid - 0.5 * (p0 + p2);
        let (r0, r2) = (stem.radius_at(0.0), stem.radius_at(1.0).max(0.0));
        let r1 = middle_radius((p1 - p0).length(), (p2 - p1).length(), r0, r2);
        Span { p: [p0, p1, p2], r: [r0, r1, r2] }
    }

    /// Point on the curve at `u`.
    pub fn point(&self, u: f32) -> Vec3 {
        let w = bernstein(u);
        self.p[0] * w[0] + self.p[1] * w[1] + self.p[2] * w[2]
    }

    /// Unit leg directions and the bend angle between them (radians).
    fn legs(&self) -> (Vec3, Vec3, f32) {
        let d0 = unit_or(self.p[1] - self.p[0], || unit_or(self.p[2] - self.p[0], || Vec3::Y));
        let d1 = unit_or(self.p[2] - self.p[1], || d0);
        (d0, d1, acos(d0.dot(d1)))
    }
}

fn bernstein(u: f32) -> [f32; 3] {
    let v = 1.0 - u;
    [v * v, 2.0 * u * v, u * u]
}

/// Which stems of `skeleton` are meshed as Bezier twigs (the rule in the module docs).
pub fn mask(skeleton: &Skeleton) -> Vec<bool> {
    let n = skeleton.stems.len();
    if skeleton.levels < 2 || skeleton.mode != GrowthMode::Parametric {
        return vec![false; n];
    }
    let deepest = (skeleton.levels - 1) as u8;
    let mut parent_of_something = vec![false; n];
    for s in &skeleton.stems {
        if let Some(i) = s.parent {
            parent_of_something[i as usize] = true;
        }
    }
    skeleton
        .stems
        .iter()
        .enumerate()
        .map(|(i, s)| {
            s.level == deepest
                && s.kind != StemKind::Root
                && !parent_of_something[i]
                && s.taper <= 1.0
                && s.flare == 0.0
                && s.radii.is_none()
                && !s.cut_end
                && faithful(s)
        })
        .collect()
}

/// Whether one quadratic span represents the stem's centre curve (see the module docs).
fn faithful(stem: &Stem) -> bool {
    let span = Span::fit(stem);
    let (_, _, theta) = span.legs();
    let chord = (span.p[2] - span.p[0]).length();
    let (l0, l1) = ((span.p[1] - span.p[0]).length(), (span.p[2] - span.p[1]).length());
    let tol = 0.5 * stem.radius_at(0.0);
    theta <= rad(90.0)
        && l0 >= 0.1 * chord
        && l1 >= 0.1 * chord
        && [0.25f32, 0.75].iter().all(|&t| (stem.point(t) - span.point(t)).length() <= tol)
}

/// Ring parameters (Bezier `u`, 0..1) of a twig appended to `out`; returns its number of sides.
pub(crate) fn plan(stem: &Stem, p: &MeshParams, out: &mut Vec<f32>) -> u32 {
    let span = Span::fit(stem);
    let (_, _, theta) = span.legs();
    // The tube's rule: about one ring per 12° of bend on thick stems, more tolerance on thin ones.
    let per_ring = rad(12.0) / (stem.radius / 0.02).sqrt().clamp(0.25, 1.0);
    let n = ((p.mesh_quality * theta / per_ring).ceil() as usize).clamp(1, 8);
    for k in 0..n {
        out.push(k as f32 / n as f32);
    }
    out.push((n as f32 - 0.25) / n as f32);
    sides(stem.radius, p.mesh_quality, p.twig_detail)
}

/// `v` turned by `angle` about the unit `axis` (Rodrigues).
fn turn(v: Vec3, axis: Vec3, angle: f32) -> Vec3 {
    let (s, c) = (sin(angle), cos(angle));
    v * c + axis.cross(v) * s + axis * (axis.dot(v) * (1.0 - c))
}

/// Mesh one twig's vertices: `us` from [`plan`] (at `ring0` in the shared ring buffer), `circle`
/// the tube's circle table for its sides; its base is capped. Returns it for the index emitter.
pub(crate) fn sweep(
    stem: &Stem,
    us: &[f32],
    ring0: usize,
    circle: &[(f32, f32, f32)],
    wind: &StemWind,
    out: &mut MeshBuilder,
) -> StemMesh {
    let span = Span::fit(stem);
    let (d0, d1, theta) = span.legs();
    let n0 = unit_or(stem.base_normal - d0 * stem.base_normal.dot(d0), || d0.any_orthonormal_vector());
    let b0 = d0.cross(n0);
    let axis = d0.cross(d1);
    let (ns, bs) = if axis.length_squared() > 1e-12 {
        let a = axis.normalize();
        let h = 0.5 * theta;
        ([n0, turn(n0, a, h), turn(n0, a, theta)], [b0, turn(b0, a, h), turn(b0, a, theta)])
    } else {
        ([n0; 3], [b0; 3])
    };
    let sides = circle.len() - 1;
    let stride = sides + 1;
    let rings = us.len();
    let floor = 0.05 * span.r[0];
    let mut v = 0.0f32;
    let mut prev: Option<(Vec3, f32)> = None;
    let (mut last_c, mut last_rho) = (span.p[0], span.r[0]);
    let first = out.append_vertices(rings * stride + 1, |sink| {
        for &u in us {
            let w = bernstein(u);
            let dw = [-2.0 * (1.0 - u), 2.0 * (1.0 - 2.0 * u), 2.0 * u];
            let mut c = Vec3::ZERO;
            let mut dc = Vec3::ZERO;
            let (mut nn, mut bb, mut dn, mut db) = (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
            let mut rho = 0.0f32;
            for i in 0..3 {
                c += span.p[i] * w[i];
                dc += span.p[i] * dw[i];
                nn += ns[i] * (w[i] * span.r[i]);
                bb += bs[i] * (w[i] * span.r[i]);
                dn += ns[i] * (dw[i] * span.r[i]);
                db += bs[i] * (dw[i] * span.r[i]);
                rho += w[i] * span.r[i];
            }
            if rho < floor {
                // Never thinner than 5% of the base radius, like the tube's last ring.
                let s = floor / rho.max(1e-12);
                (nn, bb, dn, db, rho) = (nn * s, bb * s, dn * s, db * s, floor);
            }
            if let Some((pc, pr)) = prev {
                v += (c - pc).length() / (TAU * (0.5 * (rho + pr)).max(0.25 * span.r[0]));
            }
            sink.extend(circle.iter().map(|&(cs, sn, tu)| {
                let radial = nn * cs + bb * sn;
                let d_phi = bb * cs - nn * sn;
                let d_u = dc + dn * cs + db * sn;
                (c + radial, unit_or(d_phi.cross(d_u), || unit_or(radial, || d0)), [tu, v])
            }));
            // The wind record of the ring: `u` is the Bezier parameter, close enough to the
            // fraction of the stem's length for the distance from the root.
            sink.push_wind(&wind.record(stem, u, rho), stride);
            prev = Some((c, rho));
            (last_c, last_rho) = (c, rho);
        }
        // Tip: a short cone to an apex at the curve's end (a little beyond it if the tip is blunt).
        let apex_pos = span.p[2] + d1 * (0.5 * span.r[2]).max(0.05 * last_rho);
        let v_apex = v + (apex_pos - last_c).length() / (TAU * last_rho.max(1e-6));
        sink.push(apex_pos, d1, [0.5, v_apex]);
        sink.push_wind(&wind.record(stem, 1.0, last_rho), 1);
        sink.first
    });
    let apex_slot = rings * stride;
    let apex = first + apex_slot as u32;
    // A twig sits on its parent as a separate tube: its base is closed by a shallow cone to a
    // centre a quarter radius inside (like the tube's capped bases), so the twig is closed.
    let r0 = span.r[0];
    let centre = span.p[0] - d0 * (0.25 * r0);
    let cap = out.vertex_with_wind(centre.to_array(), (-d0).to_array(), [0.5, 0.0], &wind.record(stem, 0.0, r0));
    out.rings(first, rings as u32, stride as u32);
    // Indices come later from the tube's emitter, like every swept stem.
    StemMesh {
        first,
        rings: rings as u32,
        sides: sides as u32,
        ring0,
        apex,
        base: Base::Cap(cap),
        claim: 0,
        v0: 0.0,
        cut: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn middle_radius_is_the_leg_weighted_mean() {
        assert_eq!(middle_radius(1.0, 1.0, 0.2, 0.0), 0.1);
        // l0 = 3, l1 = 1: R1 = (3 * 0.4 + 1 * 0.2) / 4 = 0.35.
        assert!((middle_radius(3.0, 1.0, 0.4, 0.2) - 0.35).abs() < 1e-7);
        assert!((middle_radius(0.0, 0.0, 0.4, 0.2) - 0.3).abs() < 1e-7);
    }

    #[test]
    fn steps_are_one_two_four_eight_and_change_the_sides() {
        let steps: Vec<u32> = (0..4).map(|i| TwigDetail::from_index(i).step()).collect();
        assert_eq!(steps, [1, 2, 4, 8]);
        let r = 0.004;
        let s: Vec<u32> = (0..4).map(|i| sides(r, 1.0, TwigDetail::from_index(i))).collect();
        assert_eq!(s[2], sides_for(r, 1.0, 0), "step 4 is the tube's resolution");
        assert!(s.windows(2).all(|w| w[0] > w[1]), "{s:?}");
    }

    #[test]
    fn turning_keeps_length_and_maps_the_first_leg_onto_the_second() {
        let (d0, d1) = (Vec3::Y, Vec3::new(1.0, 1.0, 0.0).normalize());
        let a = d0.cross(d1).normalize();
        let t = turn(d0, a, acos(d0.dot(d1)));
        assert!((t - d1).length() < 1e-6);
        let n = turn(Vec3::X, a, 0.3);
        assert!((n.length() - 1.0).abs() < 1e-6);
    }
}
