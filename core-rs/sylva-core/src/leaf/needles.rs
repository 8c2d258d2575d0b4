//! Needles as foliage geometry (pines carry needles in fascicles of 2 to 5 from
//! one sheath; firs single flat needles along the twig), and the petiole.
//!
//! * [`fascicle`] (Needles per Fascicle 2–5): `n` round needles instead of the flat blade.
//!   Together their cross-sections make a disc of radius Aspect Ratio / 2 (leaf units, the
//!   needle's length is 1): needle `i` has the sector `2π/n` wide about the azimuth `2πi/n`, as
//!   in a real fascicle, where each needle is a half-disc (2), a third (3), ... of a cylinder.
//!   Each needle leaves the sheath at the origin splayed [`SPLAY`] from the fascicle's axis
//!   (`+y`) toward its azimuth and bends a little further outward along its length
//!   (Midrib Curvature), tapering to a point over the last [`TIP`] of its length. Vertices are
//!   shared along each needle (area-weighted normals); every face winds counter-clockwise seen
//!   from outside. UVs all sample the middle of the blade texture (the needle's colour).
//! * [`petiole`] (Petiole Length): the leaf stalk from `(0, −L)` to the blade's base as one
//!   two-sided quad, [`PETIOLE_WIDTH`] wide, lying in the blade's plane, or across it (in the
//!   `y`–`z` plane) when Flat Petiole is on: a stalk flattened sideways is what lets an aspen
//!   leaf swing in the lightest wind.

use crate::leaf::uv::UvFrame;
use crate::mesh::MeshBuilder;
use crate::params::LeafParams;
use glam::{Vec2, Vec3};

/// Angle (radians) between a needle and the fascicle's axis at the sheath.
pub const SPLAY: f32 = 0.12;
/// Fraction of a needle's length over which it tapers to its point.
pub const TIP: f32 = 0.2;
/// Rings along a needle (the point is one more vertex).
const RINGS: usize = 6;
/// Width of the petiole quad, in leaf lengths.
pub const PETIOLE_WIDTH: f32 = 0.03;

/// A small indexed surface in the leaf frame.
#[derive(Clone, Debug, Default)]
pub struct Surface {
    /// Positions.
    pub positions: Vec<Vec3>,
    /// Unit normals.
    pub normals: Vec<Vec3>,
    /// Texture coordinates.
    pub uvs: Vec<Vec2>,
    /// Counter-clockwise triangles seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

/// The cross-section of needle `i` of `n` (radius 1): the axis point then arc points.
fn section(i: usize, n: usize) -> Vec<Vec2> {
    let tau = std::f32::consts::TAU;
    let width = tau / n as f32;
    let mid = tau * i as f32 / n as f32;
    let arc = if n == 2 { 5 } else { 3 };
    let mut out = vec![Vec2::ZERO];
    out.extend((0..arc).map(|k| {
        let a = mid - 0.5 * width + width * k as f32 / (arc - 1) as f32;
        Vec2::new(crate::math::cos(a), crate::math::sin(a))
    }));
    out
}

/// The fascicle of `leaf_fascicle` needles (see the module docs).
pub fn fascicle(p: &LeafParams, frame: &UvFrame) -> Surface {
    let n = p.leaf_fascicle.max(1) as usize;
    let r0 = 0.5 * p.leaf_aspect;
    let uv = frame.uv(Vec2::new(0.0, 0.5));
    let mut s = Surface::default();
    for i in 0..n {
        let sec = section(i, n);
        let mid = std::f32::consts::TAU * i as f32 / n as f32;
        let out = Vec3::new(crate::math::cos(mid), 0.0, crate::math::sin(mid));
        let axis = |t: f32| {
            let splay = SPLAY + 0.5 * p.leaf_midrib_curvature.abs() * t;
            Vec3::Y * t + out * (crate::math::sin(splay) * t)
        };
        let first = s.positions.len() as u32;
        for k in 0..RINGS {
            let t = k as f32 / RINGS as f32;
            let r = r0 * ((1.0 - t) / TIP).min(1.0);
            let c = axis(t);
            s.positions.extend(sec.iter().map(|q| c + Vec3::new(q.x * r, 0.0, q.y * r)));
        }
        let tip = first + (RINGS * sec.len()) as u32;
        s.positions.push(axis(1.0));
        let m = sec.len() as u32;
        for k in 0..RINGS as u32 {
            for j in 0..m {
                let (a, b) = (first + k * m + j, first + k * m + (j + 1) % m);
                if k + 1 < RINGS as u32 {
                    s.triangles.push([a, b + m, b]);
                    s.triangles.push([a, a + m, b + m]);
                } else {
                    s.triangles.push([a, tip, b]);
                }
            }
        }
        // Orient every face away from the needle's axis at its height.
        let end = s.triangles.len();
        let start = end + sec.len() - 2 * RINGS * sec.len();
        for t in &mut s.triangles[start..end] {
            let [a, b, c] = t.map(|v| s.positions[v as usize]);
            let centre = (a + b + c) / 3.0;
            let to_axis = centre - axis(centre.y.clamp(0.0, 1.0));
            if (b - a).cross(c - a).dot(to_axis) < 0.0 {
                t.swap(1, 2);
            }
        }
    }
    s.normals = crate::leaf::deform::normals(&s.positions, &s.triangles);
    s.uvs = vec![uv; s.positions.len()];
    s
}

/// Appends the petiole quad of length `len` (nothing for Petiole Length 0).
pub fn petiole(p: &LeafParams, len: f32, frame: &UvFrame, b: &mut MeshBuilder) {
    if len <= 0.0 {
        return;
    }
    let h = 0.5 * PETIOLE_WIDTH;
    let (side, normal) = if p.leaf_petiole_flat { (Vec3::Z * h, Vec3::X) } else { (Vec3::X * h, Vec3::Z) };
    let uv = frame.uv(Vec2::new(0.0, 0.02)).to_array();
    let first = b.next_index();
    for q in [-Vec3::Y * len - side, -Vec3::Y * len + side, side, -side] {
        b.vertex(q.to_array(), normal.to_array(), uv);
    }
    if p.leaf_petiole_flat {
        b.triangle(first, first + 2, first + 1);
        b.triangle(first, first + 3, first + 2);
    } else {
        b.triangle(first, first + 1, first + 2);
        b.triangle(first, first + 2, first + 3);
    }
}
