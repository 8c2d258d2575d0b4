//! Sweeping one stem into its tube (the bark surface stage, [`super`]): rings are oriented by
//! parallel transport so tubes never twist. Normals are the smooth surface normals of a tapered
//! tube (`radial - dr/ds * tangent`, normalised); `u` runs around the stem with the seam
//! duplicated, `v` along it at one unit per circumference, so bark textures stay square and
//! continuous. Each tip closes with a small cone to an apex vertex and the trunk's base with a
//! fan; a complex trunk's rings take their outline from [`crate::mesh::trunk`]. Also the per-stem
//! wind constants the sweep records, and the index pass writing each stem's quads (skipping
//! claimed ones) and fans.

use crate::math::{self, cos, sin, unit_or, TAU};
use crate::mesh::stem::{Base, Frame, StemMesh, StemWind};
use crate::mesh::trunk::{ring_circles, union_outline};
use crate::mesh::{cut_face, MeshBuilder, Tail, VertexBlock, VertexSink, WIND_STRIDE};
use crate::params::MeshParams;
use crate::rng::Rng;
use crate::skeleton::{Skeleton, Stem};
use glam::Vec3;

/// Unit circle table for `sides`: `(cos, sin, u)` per column, with the seam point repeated at
/// the end (bit-identical position, `u = 1`).
pub(super) fn circle(sides: u32) -> Vec<(f32, f32, f32)> {
    let mut t: Vec<(f32, f32, f32)> = (0..sides)
        .map(|j| {
            let a = TAU * j as f32 / sides as f32;
            (cos(a), sin(a), j as f32 / sides as f32)
        })
        .collect();
    t.push((t[0].0, t[0].1, 1.0));
    t
}

/// The quad claims of stem `m` (one per quad, row by row).
fn claims_of<'c>(m: &StemMesh, claimed: &'c [bool]) -> &'c [bool] {
    &claimed[m.claim..m.claim + (m.rings as usize - 1) * m.sides as usize]
}

/// The triangles of stem `m`'s tip fan (or a cut end's rim: two triangles a side) and base fan.
fn fan_triangles(m: &StemMesh) -> (usize, usize) {
    let s = m.sides as usize;
    let tip = s * m.cut.map_or(1, cut_face::rim_triangles);
    (tip, if matches!(m.base, Base::Welded | Base::Open) { 0 } else { s })
}

/// How many indices [`emit`] writes for stem `m`.
pub(super) fn index_count(m: &StemMesh, claimed: &[bool]) -> usize {
    let free = claims_of(m, claimed).iter().filter(|&&c| !c).count();
    let (tip, base) = fan_triangles(m);
    free * 6 + (tip + base) * 3
}

/// Indices of one swept stem into `idx` (exactly [`index_count`] of them): quads between rings
/// (except those a child's junction claimed), the tip fan, and the base cap.
pub(super) fn emit(m: &StemMesh, claimed: &[bool], idx: &mut Tail<u32>) {
    let s = m.sides;
    let st = s + 1;
    let claims = claims_of(m, claimed);
    debug_assert!(m.base != Base::Open, "a base is welded or closed before the index pass");
    for (i, row_claims) in claims.chunks_exact(s as usize).enumerate() {
        let row = m.first + i as u32 * st;
        for (j, &c) in row_claims.iter().enumerate() {
            if c {
                continue;
            }
            let (a, b) = (row + j as u32, row + j as u32 + 1);
            let (c, d) = (b + st, a + st);
            idx.push([a, b, c, a, c, d]);
        }
    }
    let row = m.first + (m.rings - 1) * st;
    match m.cut {
        Some(end) => cut_face::rim_indices(m, end, idx),
        None => {
            for j in 0..s {
                idx.push([row + j, row + j + 1, m.apex]);
            }
        }
    }
    match m.base {
        Base::Trunk(cap) => {
            let centre = cap + st;
            for j in 0..s {
                idx.push([cap + j + 1, cap + j, centre]);
            }
        }
        Base::Cap(centre) => {
            for j in 0..s {
                idx.push([m.first + j + 1, m.first + j, centre]);
            }
        }
        Base::Welded | Base::Open => {}
    }
}

/// Wind constants of every stem: phases from the `"wind"` stream (one draw per stem, in stem
/// order), base distances from the parent's base distance plus the offset along it.
pub fn stem_winds(skeleton: &Skeleton, seed: u32) -> Vec<StemWind> {
    let mut rng = Rng::new(u64::from(seed), "wind");
    let trunk_radius = skeleton.stems.first().map_or(1.0, |s| s.radius).max(1e-6);
    let mut out: Vec<StemWind> = Vec::with_capacity(skeleton.stems.len());
    for s in &skeleton.stems {
        let distance = s.parent.map_or(0.0, |i| out[i as usize].distance + s.offset);
        out.push(StemWind {
            pivot: s.base(),
            level: f32::from(s.level),
            phase: rng.next_f32(),
            distance,
            trunk_radius,
        });
    }
    out
}

#[allow(
    clippy::too_many_arguments,
    reason = "separate borrows of one sweep: stem, rings, circle, wind, frames, output"
)]
pub(super) fn sweep(
    stem: &Stem,
    ts: &[f32],
    circle: &[(f32, f32, f32)],
    lobes: Option<(u32, f32)>,
    wind: &StemWind,
    frames: &mut [Frame],
    start: Option<(Vec3, f32)>,
    out: &mut MeshBuilder,
) -> StemMesh {
    match lobes {
        Some((n, depth)) => {
            let sides = circle.len() - 1;
            let lobe: Vec<f32> =
                (0..=sides).map(|j| 1.0 + depth * sin(n as f32 * TAU * (j % sides) as f32 / sides as f32)).collect();
            sweep_with(stem, ts, circle, Some(&|_, j| lobe[j]), wind, frames, start, out)
        }
        None => sweep_with(stem, ts, circle, None, wind, frames, start, out),
    }
}

/// Sweep one stem whose ring `r`, column `j` sits at `factor(r, j)` times the ring radius (at
/// the radius itself without a `factor`: a round tube, most stems, with no call per vertex).
/// Where the factor varies around the ring, the in-plane normal follows the outline's tangent.
#[allow(
    clippy::too_many_arguments,
    reason = "separate borrows of one sweep: stem, rings, circle, wind, frames, output"
)]
fn sweep_with(
    stem: &Stem,
    ts: &[f32],
    circle: &[(f32, f32, f32)],
    factor: Option<&dyn Fn(usize, usize) -> f32>,
    wind: &StemWind,
    frames: &mut [Frame],
    start: Option<(Vec3, f32)>,
    out: &mut MeshBuilder,
) -> StemMesh {
    let sides = circle.len() - 1;
    let stride = sides + 1;
    let rings = ts.len();
    let trunk = stem.parent.is_none();
    let cap = if trunk { stride + 1 } else { 0 };
    let extra = cap + if stem.cut_end { cut_face::rings(stem) * stride } else { 0 };
    // Only a tube with factors (most are round) needs them: no allocation per round tube.
    let room = if factor.is_some() { stride } else { 0 };
    let mut ring_factor = vec![1.0f32; room];
    let mut plane_normal = vec![(0.0f32, 0.0f32); room];
    let mut seg = (0, stem.segment(0));
    let (_, t0) = seg.1.eval(0.0);
    // `start`: a fork's clone takes its original's frame normal and `v` at the split.
    let (reference, v_base) = start.unwrap_or((stem.base_normal, 0.0));
    let mut normal = unit_or(reference - t0 * reference.dot(t0), || t0.any_orthonormal_vector());
    // A welded stem starts at its junction ring: v starts where the full stem would have it.
    let v0 = v_base + ts[0] * stem.length / (TAU * stem.radius.max(1e-6));
    let mut v = v0;
    let mut prev: Option<(f32, f32)> = None; // (t, radius) of the previous ring
    let mut last_center = Vec3::ZERO;
    let mut last_radius = stem.radius;
    let mut last_nominal = stem.radius;
    // The rings, front to back; then the apex, the trunk's cap and a cut end (which read the
    // first and the last ring back).
    let first = out.append_vertices(rings * stride, |sink| {
        for (r, &t) in ts.iter().enumerate() {
            let (i, u) = stem.locate(t);
            if seg.0 != i {
                seg = (i, stem.segment(i));
            }
            let (c, tan) = seg.1.eval(u);
            normal = unit_or(normal - tan * normal.dot(tan), || tan.any_orthonormal_vector());
            let binormal = tan.cross(normal);
            frames[r] = Frame { centre: c, tangent: tan, normal };
            // Never thinner than 5% of the base radius: the last ring before a pointed tip stays a ring.
            let radius = math::max(stem.radius_at(t), 0.05 * stem.radius);
            let slope = stem.radius_slope(t);
            let inv = 1.0 / (1.0 + slope * slope).sqrt();
            if let Some((pt, pr)) = prev {
                v += (t - pt) * stem.length / (TAU * math::max(0.5 * (radius + pr), 0.25 * stem.radius));
            }
            if let Some(factor) = factor {
                for (j, f) in ring_factor.iter_mut().enumerate() {
                    *f = factor(r, j);
                }
            }
            let ring = Ring { centre: c, normal, binormal, radius, tilt: tan * slope, inv, v };
            write_ring(
                sink,
                circle,
                factor.is_some().then_some(ring_factor.as_slice()),
                &mut plane_normal,
                &ring,
                &wind.record(stem, t, radius),
            );
            prev = Some((t, radius));
            last_nominal = radius;
            last_center = c;
            last_radius = radius;
        }
        sink.first
    });
    // Tip: a short cone to an apex at the stem end (a little beyond it if the tip is blunt).
    let last_seg = stem.points.len() - 2;
    if seg.0 != last_seg {
        seg = (last_seg, stem.segment(last_seg));
    }
    let (tip, tip_tan) = seg.1.eval(1.0);
    let end_r = stem.radius_at(1.0);
    let apex_pos = tip + tip_tan * (0.5 * end_r).max(0.05 * last_radius);
    let v_apex = v + (apex_pos - last_center).length() / (TAU * last_radius.max(1e-6));
    let apex_slot = rings * stride;
    let mut block = out.block_from(first, 1 + extra);
    block.write(apex_slot, apex_pos, tip_tan, [0.5, v_apex]);
    block.wind[apex_slot * WIND_STRIDE..(apex_slot + 1) * WIND_STRIDE].copy_from_slice(&wind.record(stem, 1.0, end_r));
    let apex = first + apex_slot as u32;
    if trunk {
        write_trunk_cap(&mut block, apex_slot + 1, circle, stem.base(), -t0);
    }
    let cut = stem.cut_end.then(|| {
        let slot = apex_slot + 1 + cap;
        let last = (rings - 1) * stride;
        let record = wind.record(stem, 1.0, end_r);
        let frame = &frames[rings - 1];
        let radius = (last_nominal, stem.callus);
        cut_face::write(&mut block, slot, apex_slot, (last, stride), frame, radius, v, (tip, tip_tan), &record);
        cut_face::CutEnd { first: first + slot as u32, callus: stem.callus > 0.0 }
    });
    out.rings(first, rings as u32, stride as u32);
    StemMesh {
        first,
        rings: rings as u32,
        sides: sides as u32,
        ring0: 0,
        apex,
        base: if trunk { Base::Trunk(apex + 1) } else { Base::Open },
        claim: 0,
        v0,
        cut,
    }
}

/// Where one ring of a sweep lies: its centre and frame, radius, the surface's tilt along the
/// stem (`tangent × dr/ds`) with `1 / sqrt(1 + slope²)`, and its bark `v`.
struct Ring {
    centre: Vec3,
    normal: Vec3,
    binormal: Vec3,
    radius: f32,
    tilt: Vec3,
    inv: f32,
    v: f32,
}

/// Appends one ring's vertices to `sink`: column `j` at `factors[j]` times
/// the radius (a round ring without factors or when every factor is 1; else the in-plane
/// normals, kept in `plane_normal`, are perpendicular to the chord between neighbouring
/// columns).
fn write_ring(
    sink: &mut VertexSink,
    circle: &[(f32, f32, f32)],
    factors: Option<&[f32]>,
    plane_normal: &mut [(f32, f32)],
    g: &Ring,
    record: &[f32; WIND_STRIDE],
) {
    let stride = circle.len();
    let sides = stride - 1;
    sink.push_wind(record, stride);
    let (c, normal, binormal, v) = (g.centre, g.normal, g.binormal, g.v);
    let Some(factors) = factors.filter(|f| f.iter().any(|&f| f != 1.0)) else {
        sink.extend(circle.iter().map(|&(cs, sn, u)| {
            let radial = normal * cs + binormal * sn;
            (c + radial * g.radius, (radial - g.tilt) * g.inv, [u, v])
        }));
        return;
    };
    // In-plane outline normals: perpendicular to the chord between neighbouring columns.
    let at = |j: usize| {
        let (cs, sn, _) = circle[j];
        (cs * factors[j], sn * factors[j])
    };
    for (j, n2) in plane_normal.iter_mut().enumerate() {
        let (a, b) = (at(if j == 0 { sides - 1 } else { j - 1 }), at(if j == sides { 1 } else { j + 1 }));
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let len = (dx * dx + dy * dy).sqrt().max(1e-12);
        *n2 = (dy / len, -dx / len);
    }
    sink.extend(circle.iter().zip(factors.iter().zip(plane_normal.iter())).map(|(&(cs, sn, u), (&f, &(nx, ny)))| {
        let radial = normal * cs + binormal * sn;
        let outward = normal * nx + binormal * ny;
        (c + radial * (g.radius * f), unit_or(outward - g.tilt, || radial), [u, v])
    }));
}

/// Trunk base: a flat cap from vertex `cap` of `block`, its own copy of the bottom ring facing
/// `down` (a hard edge), then the centre at `centre`; they sway like the bottom ring.
fn write_trunk_cap(block: &mut VertexBlock, cap: usize, circle: &[(f32, f32, f32)], centre: Vec3, down: Vec3) {
    for (j, &(cs, sn, _)) in circle.iter().enumerate() {
        let src = j * 3;
        let ring0 = Vec3::new(block.positions[src], block.positions[src + 1], block.positions[src + 2]);
        block.write(cap + j, ring0, down, [0.5 + 0.5 * cs, 0.5 + 0.5 * sn]);
    }
    let middle = cap + circle.len();
    block.write(middle, centre, down, [0.5, 0.5]);
    let record: [f32; WIND_STRIDE] = block.wind[..WIND_STRIDE].try_into().expect("ring 0 exists");
    for w in block.wind[cap * WIND_STRIDE..(middle + 1) * WIND_STRIDE].chunks_exact_mut(WIND_STRIDE) {
        w.copy_from_slice(&record);
    }
}

/// Cross-section settings of a complex trunk (see [`crate::mesh::trunk`]): refinement circles whose
/// offset and radius vary smoothly with height, Weber & Penn lobes on top, and the base
/// ripple of *Modeling the Mighty Maple for Web*, `R(u) = R0 (1 + a sin(7 theta))` fading out over the flare zone.
pub(super) struct TrunkProfile {
    offset: f32,
    radius: f32,
    /// Relative variation of each refinement circle's (offset, radius) at `KEYS` heights.
    keys: Vec<Vec<[f32; 2]>>,
    phase: f32,
    ripple: f32,
    lobes: Option<(u32, f32)>,
}

/// Heights (evenly spaced along the trunk) at which refinement circles get new random variation.
const KEYS: usize = 9;

impl TrunkProfile {
    /// The profile of the trunk of a tree of Seed `seed`.
    pub(super) fn new(p: &MeshParams, seed: u32, lobes: Option<(u32, f32)>) -> Self {
        let mut rng = Rng::new(u64::from(seed), "trunk-profile");
        let n = p.refine_curves as usize;
        let v = p.refine_variation;
        let keys = (0..KEYS).map(|_| (0..n).map(|_| [rng.var(v), rng.var(v)]).collect()).collect();
        TrunkProfile {
            offset: p.refine_offset,
            radius: p.refine_radius,
            keys,
            phase: rng.uniform(0.0, TAU),
            ripple: p.base_ripple,
            lobes,
        }
    }

    /// Per-circle variation at fraction `t` of the trunk (linear between keys).
    fn jitter_at(&self, t: f32, out: &mut Vec<[f32; 2]>) {
        let f = t.clamp(0.0, 1.0) * (KEYS - 1) as f32;
        let i = (f as usize).min(KEYS - 2);
        let u = f - i as f32;
        out.clear();
        out.extend(
            self.keys[i]
                .iter()
                .zip(&self.keys[i + 1])
                .map(|(a, b)| [a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u]),
        );
    }
}

/// Sweep of the trunk record with a complex cross-section: each ring's outline is the union of
/// its circles resampled per column (then lobes and the base ripple), as factors on the radius.
#[allow(
    clippy::too_many_arguments,
    reason = "separate borrows of one sweep: stem, rings, circle, wind, frames, output"
)]
pub(super) fn sweep_trunk(
    stem: &Stem,
    ts: &[f32],
    circle: &[(f32, f32, f32)],
    tp: &TrunkProfile,
    wind: &StemWind,
    frames: &mut [Frame],
    start: Option<(Vec3, f32)>,
    out: &mut MeshBuilder,
) -> StemMesh {
    let sides = circle.len() - 1;
    let dirs: Vec<(f32, f32)> = circle.iter().map(|&(c, s, _)| (c, s)).collect();
    let mut jitter = Vec::new();
    let mut rho = Vec::with_capacity(circle.len());
    let mut rings: Vec<Vec<f32>> = Vec::with_capacity(ts.len());
    for &t in ts {
        let radius = math::max(stem.radius_at(t), 0.05 * stem.radius);
        tp.jitter_at(t, &mut jitter);
        let circles = ring_circles(radius, tp.offset, tp.radius, tp.phase, &jitter);
        union_outline(&circles, &dirs, &mut rho);
        let fade = (1.0 - t / 0.125).max(0.0);
        for (j, r) in rho.iter_mut().enumerate() {
            let theta = TAU * (j % sides) as f32 / sides as f32;
            if let Some((n, depth)) = tp.lobes {
                *r *= 1.0 + depth * sin(n as f32 * theta);
            }
            *r *= 1.0 + tp.ripple * fade * sin(7.0 * theta);
            *r /= radius;
        }
        rings.push(rho.clone());
    }
    sweep_with(stem, ts, circle, Some(&|r, j| rings[r][j]), wind, frames, start, out)
}
