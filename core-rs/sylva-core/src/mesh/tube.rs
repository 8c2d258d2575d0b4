//! Bark surface stage: sweeps every stem of the skeleton into a tube. Rings follow the
//! Catmull-Rom centre curve, are added where the stem bends (and through the trunk flare and
//! rounded tips), and are oriented by parallel transport so tubes never twist. Normals are the
//! smooth surface normals of a tapered tube (`radial - dr/ds * tangent`, normalised); `u` runs
//! around the stem with the seam duplicated, `v` along it at one unit per circumference, so bark
//! textures stay square and continuous. Each tip closes with a small cone to an apex vertex and
//! the trunk's base with a fan, so the only open edges are the buried bases of child stems.

use super::{Material, MeshBuilder, TreeMesh};
use crate::error::SylvaError;
use crate::math::{cos, rad, sin, TAU};
use crate::params::TreeParams;
use crate::skeleton::{budget_error, Skeleton, Stem};
use glam::Vec3;

/// How one stem will be meshed: its ring positions along the stem and its number of sides.
struct StemPlan {
    /// Range into the shared ring-parameter buffer.
    rings: std::ops::Range<usize>,
    sides: u32,
}

impl StemPlan {
    fn vertices(&self, trunk: bool) -> u64 {
        let ring = u64::from(self.sides) + 1;
        // Rings, the apex, and for the trunk a bottom cap (its own ring copy facing down + centre).
        self.rings.len() as u64 * ring + 1 + if trunk { ring + 1 } else { 0 }
    }
}

/// Number of sides around a stem of base radius `r` (m) at the given quality.
pub fn sides_for(r: f32, quality: f32, lobes: u32) -> u32 {
    let base = (quality * (3.0 + 30.0 * r.max(0.0).sqrt())).round() as u32;
    base.max((4 * lobes).min(96)).clamp(3, 96)
}

/// Ring positions (fractions 0..1 of the stem) for one stem, appended to `out`. The last ring
/// sits just short of the tip; the apex closes the stem at t = 1.
fn plan_rings(stem: &Stem, quality: f32, out: &mut Vec<f32>) {
    let start = out.len();
    let segs = stem.points.len() - 1;
    let dirs: Vec<Vec3> = stem.points.windows(2).map(|w| (w[1] - w[0]).normalize_or(Vec3::Y)).collect();
    for i in 0..segs {
        // Subdivide a segment by the bend at its ends: about one ring per 12° of turn on thick
        // stems; thin stems tolerate more, since the chord error is what shows against the radius.
        let turn_in = if i > 0 { dirs[i - 1].angle_between(dirs[i]) } else { 0.0 };
        let turn_out = if i + 1 < segs { dirs[i].angle_between(dirs[i + 1]) } else { 0.0 };
        let per_ring = rad(12.0) / (stem.radius / 0.02).sqrt().clamp(0.25, 1.0);
        let k = ((quality * turn_in.max(turn_out) / per_ring).ceil() as usize).clamp(1, 8);
        for j in 0..k {
            out.push((i as f32 + j as f32 / k as f32) / segs as f32);
        }
    }
    if stem.flare > 0.0 {
        // The flare lives in the lowest eighth and rises steeply: rings packed toward the ground.
        let m = ((6.0 * quality).ceil() as usize).max(2);
        for j in 1..m {
            let f = j as f32 / m as f32;
            out.push(0.125 * f * f);
        }
    }
    if stem.taper > 1.0 {
        // Rounded tips and periodic bulges change radius within one radius of length.
        let spacing = (0.5 * stem.radius / stem.length).max(1.0 / 128.0);
        let from = if stem.taper < 2.0 { (1.0 - 1.5 * stem.radius / stem.length).max(0.0) } else { 0.0 };
        let mut t = from;
        while t < 1.0 {
            out.push(t);
            t += spacing;
        }
    }
    let rings = &mut out[start..];
    rings.sort_by(f32::total_cmp);
    let mut n = 0;
    for i in 0..rings.len() {
        if n == 0 || rings[i] - rings[n - 1] > 1e-4 {
            rings[n] = rings[i];
            n += 1;
        }
    }
    out.truncate(start + n);
    // Close to the tip (a quarter of the last spacing before it), leaving room for the apex.
    let last = *out.last().expect("at least one ring");
    out.push(last + 0.75 * (1.0 - last));
}

/// Unit circle table for `sides`, with the seam point repeated at the end (bit-identical).
fn circle(sides: u32) -> Vec<(f32, f32)> {
    let mut t: Vec<(f32, f32)> = (0..sides)
        .map(|j| {
            let a = TAU * j as f32 / sides as f32;
            (cos(a), sin(a))
        })
        .collect();
    t.push(t[0]);
    t
}

/// Sweep all stems into bark tubes. Fails with a budget error before allocating if the exact
/// vertex count would pass `max_vertices`.
pub fn build(skeleton: &Skeleton, p: &TreeParams) -> Result<TreeMesh, SylvaError> {
    let q = p.mesh_quality;
    let mut ts = Vec::with_capacity(skeleton.stems.len() * 8);
    let plans: Vec<StemPlan> = skeleton
        .stems
        .iter()
        .map(|s| {
            let start = ts.len();
            plan_rings(s, q, &mut ts);
            let lobes = if s.lobed { p.lobes } else { 0 };
            StemPlan { rings: start..ts.len(), sides: sides_for(s.radius, q, lobes) }
        })
        .collect();
    let vertices: u64 = plans.iter().zip(&skeleton.stems).map(|(pl, s)| pl.vertices(s.parent.is_none())).sum();
    if vertices > u64::from(p.max_vertices) {
        return Err(budget_error("", vertices, p.max_vertices));
    }
    let indices: u64 = plans.iter().map(|pl| pl.rings.len() as u64 * u64::from(pl.sides) * 6).sum();
    let mut out = MeshBuilder::with_capacity(vertices as usize, indices as usize);
    out.begin_group(Material::Bark);
    let mut tables: Vec<Option<Vec<(f32, f32)>>> = vec![None; 97];
    for (stem, plan) in skeleton.stems.iter().zip(&plans) {
        let table = tables[plan.sides as usize].get_or_insert_with(|| circle(plan.sides));
        let lobes = if stem.lobed && p.lobes > 0 && p.lobe_depth > 0.0 { Some((p.lobes, p.lobe_depth)) } else { None };
        sweep(stem, &ts[plan.rings.clone()], table, lobes, &mut out);
    }
    Ok(out.finish())
}

fn sweep(stem: &Stem, ts: &[f32], circle: &[(f32, f32)], lobes: Option<(u32, f32)>, out: &mut MeshBuilder) {
    let sides = circle.len() - 1;
    let stride = sides as u32 + 1;
    let first = out.next_index();
    let lobe_scale: Vec<f32> = match lobes {
        Some((n, depth)) => {
            (0..=sides).map(|j| 1.0 + depth * sin(n as f32 * TAU * (j % sides) as f32 / sides as f32)).collect()
        }
        None => Vec::new(),
    };
    let (_, t0) = stem.sample(0.0);
    let mut normal = (stem.base_normal - t0 * stem.base_normal.dot(t0)).normalize_or(t0.any_orthonormal_vector());
    let mut v = 0.0f32;
    let mut prev: Option<(f32, f32)> = None; // (t, radius) of the previous ring
    let mut last_center = Vec3::ZERO;
    let mut last_radius = stem.radius;
    for &t in ts {
        let (c, tan) = stem.sample(t);
        normal = (normal - tan * normal.dot(tan)).normalize_or(tan.any_orthonormal_vector());
        let binormal = tan.cross(normal);
        // Never thinner than 5% of the base radius: the last ring before a pointed tip stays a ring.
        let r = stem.radius_at(t).max(0.05 * stem.radius);
        let eps = 1e-3f32;
        let (ta, tb) = ((t - eps).max(0.0), (t + eps).min(1.0));
        let slope = (stem.radius_at(tb) - stem.radius_at(ta)) / ((tb - ta) * stem.length);
        let inv = 1.0 / (1.0 + slope * slope).sqrt();
        if let Some((pt, pr)) = prev {
            v += (t - pt) * stem.length / (TAU * (0.5 * (r + pr)).max(0.25 * stem.radius));
        }
        for (j, &(cs, sn)) in circle.iter().enumerate() {
            let radial = normal * cs + binormal * sn;
            let rr = if lobe_scale.is_empty() { r } else { r * lobe_scale[j] };
            let pos = c + radial * rr;
            let n = (radial - tan * slope) * inv;
            out.vertex(pos.to_array(), n.to_array(), [j as f32 / sides as f32, v]);
        }
        prev = Some((t, r));
        last_center = c;
        last_radius = r;
    }
    let rings = ts.len() as u32;
    for i in 0..rings - 1 {
        let row = first + i * stride;
        for j in 0..sides as u32 {
            let (a, b) = (row + j, row + j + 1);
            let (c, d) = (b + stride, a + stride);
            out.triangle(a, b, c);
            out.triangle(a, c, d);
        }
    }
    // Tip: a short cone to an apex at the stem end (a little beyond it if the tip is blunt).
    let (tip, tip_tan) = stem.sample(1.0);
    let end_r = stem.radius_at(1.0);
    let apex_pos = tip + tip_tan * (0.5 * end_r).max(0.05 * last_radius);
    let v_apex = v + (apex_pos - last_center).length() / (TAU * last_radius.max(1e-6));
    let apex = out.vertex(apex_pos.to_array(), tip_tan.to_array(), [0.5, v_apex]);
    let row = first + (rings - 1) * stride;
    for j in 0..sides as u32 {
        out.triangle(row + j, row + j + 1, apex);
    }
    if stem.parent.is_none() {
        // Trunk base: a flat cap with its own downward-facing copy of the bottom ring (a hard edge).
        let down = (-t0).to_array();
        let cap = out.next_index();
        for j in 0..=sides as u32 {
            let k = ((first + j) * 3) as usize;
            let pos = [out.position(k), out.position(k + 1), out.position(k + 2)];
            out.vertex(pos, down, [0.5 + 0.5 * circle[j as usize].0, 0.5 + 0.5 * circle[j as usize].1]);
        }
        let centre = out.vertex(stem.base().to_array(), down, [0.5, 0.5]);
        for j in 0..sides as u32 {
            out.triangle(cap + j + 1, cap + j, centre);
        }
    }
}
