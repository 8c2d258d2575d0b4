//! Bark surface stage: sweeps every stem of the skeleton into a tube. Rings follow the
//! Catmull-Rom centre curve, are added where the stem bends (and through the trunk flare and
//! rounded tips), and are oriented by parallel transport so tubes never twist. Normals are the
//! smooth surface normals of a tapered tube (`radial - dr/ds * tangent`, normalised); `u` runs
//! around the stem with the seam duplicated, `v` along it at one unit per circumference, so bark
//! textures stay square and continuous. Each tip closes with a small cone to an apex vertex and
//! the trunk's base with a fan. Children of levels 1 and 2 and split clones are welded into their
//! parent's surface ([`super::weld`]: the parent gets extra rings across each footprint, the
//! child starts at its junction ring, the hole's quads are left out); the other children sit in
//! their parent as separate tubes whose base is closed by a shallow cone. The surface is closed.
//!
//! Order of work: plan junctions and rings, check the vertex budget (conservatively, counting a
//! fallback for every junction), sweep each stem's vertices parents first (welding each child
//! right after its sweep, or sweeping it again as a capped tube), then write every stem's
//! indices (skipping claimed quads) and the junctions' triangles.

use super::trunk::{ring_circles, union_outline};
use super::{fork, holes, twig, weld, Material, MeshBuilder, TreeMesh, WIND_STRIDE};
use crate::error::SylvaError;
use crate::math::{cos, rad, sin, unit_or, TAU};
use crate::params::TreeParams;
use crate::rng::Rng;
use crate::skeleton::{budget_error, Skeleton, Stem};
use glam::Vec3;
use std::ops::Range;

/// How one stem will be meshed: its ring positions along the stem and its number of sides.
struct StemPlan {
    /// Range into the shared ring-parameter buffer.
    rings: std::ops::Range<usize>,
    sides: u32,
}

/// What one stem's sweep wrote, for the junctions of its children and the index pass.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StemMesh {
    /// First vertex of ring 0.
    pub first: u32,
    /// Number of rings.
    pub rings: u32,
    /// Sides per ring (a ring holds `sides + 1` vertices, the seam duplicated).
    pub sides: u32,
    /// Index of ring 0 in the shared ring-parameter and frame buffers.
    pub ring0: usize,
    /// The apex closing the tip.
    pub apex: u32,
    /// How the base is closed.
    pub base: Base,
    /// Offset of this stem's quads in the claimed-quad bitmap (`(rings - 1) * sides` entries).
    pub claim: usize,
    /// `v` of ring 0.
    pub v0: f32,
}

impl StemMesh {
    /// The seam twin of ring vertex `i` a whole turn of `u` on (`turns` = 1: a ring's first
    /// vertex, `u` 0, to its last, `u` 1; -1 the other way), if `i` is one of this stem's.
    pub(crate) fn seam_twin(&self, i: u32, turns: i32) -> Option<u32> {
        let stride = self.sides + 1;
        let k = i.checked_sub(self.first).filter(|&k| k < self.rings * stride)?;
        match (k % stride, turns) {
            (0, 1) => Some(i + self.sides),
            (c, -1) if c == self.sides => Some(i - self.sides),
            _ => None,
        }
    }
}

/// How a stem's base ring is closed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Base {
    /// The trunk: a flat downward cap on its own copy of ring 0 (first vertex of the copy).
    Trunk(u32),
    /// A fan from ring 0 to this centre vertex (a separate tube sitting in its parent).
    Cap(u32),
    /// Welded into the parent's surface ([`super::weld`]).
    Welded,
}

/// Centre and orientation of one swept ring: column `j` of the ring lies along
/// `normal cos(2πj/sides) + (tangent × normal) sin(2πj/sides)`.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Frame {
    /// Ring centre.
    pub centre: Vec3,
    /// Unit tangent of the centre curve.
    pub tangent: Vec3,
    /// Unit normal, transported along the stem.
    pub normal: Vec3,
}

/// Counts of the junction pass.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct WeldStats {
    /// Junctions welded into their parent's surface.
    pub welds: usize,
    /// Stems that should have been welded (levels 1 and 2 on their parents, split clones up to
    /// level 2) but sit on their parent as closed separate tubes instead.
    pub weld_fallbacks: usize,
    /// Of the welds, split clones joined to their original (a Y).
    pub split_welds: usize,
    /// Of the fallbacks, split clones.
    pub split_fallbacks: usize,
    /// Of the split welds, shallow splits built as a smooth Y fork ([`super::fork`]).
    pub forks: usize,
}

/// Insert `t` into the sorted `out[first..]`.
fn insert_sorted(out: &mut Vec<f32>, first: usize, t: f32) {
    let k = out[first..].partition_point(|&x| x < t);
    out.insert(first + k, t);
}

/// Number of sides around a stem of base radius `r` (m) at the given quality.
pub fn sides_for(r: f32, quality: f32, lobes: u32) -> u32 {
    let base = (quality * (3.0 + 30.0 * r.max(0.0).sqrt())).round() as u32;
    base.max((4 * lobes).min(96)).clamp(3, 96)
}

/// Ring positions (fractions 0..1 of the stem) for one stem, appended to `out`. `feet` are the
/// junctions of its welded children, sorted by `t_lo`: each footprint needs a ring at most
/// [`weld::REACH`] footprint lengths below and above it, and gets one at its end where none is
/// that close; two footprints side by side around the stem (`pad`: one column) that no ring
/// separates get one between them, so that their holes never share a quad. A welded stem starts
/// at `start` (its junction ring) instead of 0. The last ring sits just short of the tip; the
/// apex closes the stem at t = 1. Returns how many planned rings the junction ring replaced.
fn plan_rings(stem: &Stem, quality: f32, feet: &[weld::Junction], pad: f32, start: f32, out: &mut Vec<f32>) -> usize {
    let first = out.len();
    let pts = &stem.points;
    let segs = pts.len() - 1;
    let dir = |i: usize| (pts[i + 1] - pts[i]).normalize_or(Vec3::Y);
    let per_ring = rad(12.0) / (stem.radius / 0.02).sqrt().clamp(0.25, 1.0);
    let mut turn_in = 0.0f32;
    let mut d = dir(0);
    for i in 0..segs {
        // Subdivide a segment by the bend at its ends: about one ring per 12° of turn on thick
        // stems; thin stems tolerate more, since the chord error is what shows against the radius.
        let next = if i + 1 < segs { Some(dir(i + 1)) } else { None };
        // Turn angle from the chord between unit directions, c = 2 sin(θ/2): θ ≈ c (1 + c²/24),
        // within 0.5% up to 90°, which is all a ring count needs (and no acos per joint).
        let turn_out = next.map_or(0.0, |n| {
            let c = (n - d).length();
            c * (1.0 + c * c / 24.0)
        });
        let k = ((quality * turn_in.max(turn_out) / per_ring).ceil() as usize).clamp(1, 8);
        for j in 0..k {
            out.push((i as f32 + j as f32 / k as f32) / segs as f32);
        }
        turn_in = turn_out;
        if let Some(n) = next {
            d = n;
        }
    }
    let extra = stem.flare > 0.0 || stem.taper > 1.0;
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
    let rings = &mut out[first..];
    if extra {
        rings.sort_by(f32::total_cmp);
    }
    let mut n = 0;
    for i in 0..rings.len() {
        if n == 0 || rings[i] - rings[n - 1] > 1e-4 {
            rings[n] = rings[i];
            n += 1;
        }
    }
    out.truncate(first + n);
    let has_ring = |out: &[f32], lo: f32, hi: f32| {
        let k = out.partition_point(|&x| x < lo);
        k < out.len() && out[k] <= hi
    };
    for (i, f) in feet.iter().enumerate() {
        let reach = weld::REACH * (f.t_hi - f.t_lo);
        if !has_ring(&out[first..], f.t_lo - reach, f.t_lo) {
            insert_sorted(out, first, f.t_lo);
        }
        if !has_ring(&out[first..], f.t_hi, f.t_hi + reach) {
            insert_sorted(out, first, f.t_hi);
        }
        for e in &feet[..i] {
            if e.t_hi <= f.t_lo && f.side_by_side(e, pad) && !has_ring(&out[first..], e.t_hi, f.t_lo) {
                insert_sorted(out, first, 0.5 * (e.t_hi + f.t_lo));
            }
        }
    }
    let mut dropped = 0;
    if start > 0.0 {
        // Drop the rings the junction replaces; the junction ring is the first.
        let keep = out[first..].partition_point(|&t| t <= start + 1e-4) + first;
        out.drain(first..keep);
        out.insert(first, start);
        dropped = keep - first;
    }
    // Close to the tip (a quarter of the last spacing before it), leaving room for the apex.
    let last = *out.last().expect("at least one ring");
    out.push(last + 0.75 * (1.0 - last));
    dropped
}

/// Unit circle table for `sides`: `(cos, sin, u)` per column, with the seam point repeated at
/// the end (bit-identical position, `u = 1`).
fn circle(sides: u32) -> Vec<(f32, f32, f32)> {
    let mut t: Vec<(f32, f32, f32)> = (0..sides)
        .map(|j| {
            let a = TAU * j as f32 / sides as f32;
            (cos(a), sin(a), j as f32 / sides as f32)
        })
        .collect();
    t.push((t[0].0, t[0].1, 1.0));
    t
}

/// Sweep all stems into bark tubes. Fails with a budget error before allocating if the vertex
/// count would pass `max_vertices`.
pub fn build(skeleton: &Skeleton, p: &TreeParams) -> Result<TreeMesh, SylvaError> {
    build_with_stats(skeleton, p).map(|b| b.mesh)
}

/// [`build`] with each stem's block of vertices (skeleton order), which [`super::holes::cut`] needs.
pub fn build_blocks(skeleton: &Skeleton, p: &TreeParams) -> Result<(TreeMesh, Vec<Range<u32>>), SylvaError> {
    build_with_stats(skeleton, p).map(|b| (b.mesh, b.blocks))
}

/// What [`build_with_stats`] returns.
pub struct Built {
    /// The bark mesh.
    pub mesh: TreeMesh,
    /// Welded junctions and fallbacks.
    pub welds: WeldStats,
    /// Each stem's contiguous block of vertices, in skeleton order.
    pub blocks: Vec<Range<u32>>,
}

/// [`build`], also counting the welded junctions and the fallbacks, and returning the stems'
/// vertex blocks. The deepest level's simple stems become Bezier twigs ([`twig`]) unless they are
/// welded; stems that may get tree holes are swept densely enough for them ([`holes::densify`]).
pub fn build_with_stats(skeleton: &Skeleton, p: &TreeParams) -> Result<Built, SylvaError> {
    let q = p.mesh_quality;
    let stems = &skeleton.stems;
    let n = stems.len();
    let twig_candidates = twig::mask(skeleton, p);
    let dense = holes::eligible(skeleton, p, &twig_candidates);
    let is_dense = |i: usize| dense.get(i) == Some(&true);
    let sides: Vec<u32> = stems
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let plain = sides_for(s.radius, q, if s.lobed { p.lobes } else { 0 });
            if is_dense(i) {
                holes::dense_sides(plain, p)
            } else {
                plain
            }
        })
        .collect();
    let mut sides = sides;
    if p.weld {
        // Forks need an even number of sides on both branches of a split.
        for (i, s) in stems.iter().enumerate() {
            let split = |j: usize| {
                weld::is_candidate(stems, j)
                    && stems[j].parent.is_some_and(|q| stems[q as usize].level == stems[j].level)
            };
            if split(i) {
                let o = s.parent.map_or(i, |q| q as usize);
                sides[o] += sides[o] % 2;
                sides[i] += sides[i] % 2;
            }
        }
    }
    let junctions = if p.weld { weld::plan(skeleton, p, &sides) } else { vec![None; n] };
    // A fork's clone has its original's sides (column k of both points the same way).
    for i in 0..n {
        if let Some(j) = junctions[i].filter(|j| j.fork) {
            sides[i] = sides[j.parent as usize];
        }
    }
    // Welding wins: a twig candidate with a junction is swept as a tube and welded.
    let twigs: Vec<bool> = twig_candidates.iter().zip(&junctions).map(|(&t, j)| t && j.is_none()).collect();
    // The junctions of each parent's welded children, grouped by parent, sorted along it.
    let mut inserted: Vec<weld::Junction> = junctions.iter().flatten().copied().collect();
    inserted.sort_by(|a, b| a.parent.cmp(&b.parent).then(a.t_lo.total_cmp(&b.t_lo)));
    let mut extra = Vec::with_capacity(n);
    let mut at = 0;
    for i in 0..n as u32 {
        let from = at;
        while at < inserted.len() && inserted[at].parent == i {
            at += 1;
        }
        extra.push(from..at);
    }
    let mut ts = Vec::with_capacity(n * 8);
    let mut plans: Vec<StemPlan> = Vec::with_capacity(n);
    // Conservative vertex count: tubes, apexes, caps, the collar loops of every junction, and
    // for each junction the rings a fallback to a buried tube would add back.
    let mut vertices = 0u64;
    let mut indices = 0u64;
    let mut bridges_len = 0u64;
    let parent_of = |i: usize| stems[i].parent.map_or(0, |p| p as usize);
    let loops = weld::collar_loops(q);
    let mut fallback: Vec<f32> = Vec::new();
    for (i, s) in stems.iter().enumerate() {
        let start = ts.len();
        if twigs[i] {
            let sides = twig::plan(s, p, &mut ts);
            let rings = (ts.len() - start) as u64;
            // Rings, the apex and the cap centre; quads and two fans.
            vertices += rings * (u64::from(sides) + 1) + 2;
            indices += (rings + 1) * u64::from(sides) * 6;
            plans.push(StemPlan { rings: start..ts.len(), sides });
            continue;
        }
        let t0 = junctions[i].map_or(0.0, |j| j.t_start);
        let feet = &inserted[extra[i].clone()];
        let pad = TAU / sides[i] as f32;
        plan_rings(s, q, feet, pad, t0, &mut ts);
        if is_dense(i) {
            holes::densify(s, sides[i], p, &mut ts, start);
        }
        fork::keep_gaps(feet, &mut ts, start);
        let plan = StemPlan { rings: start..ts.len(), sides: sides[i] };
        let ring = u64::from(plan.sides) + 1;
        vertices += plan.rings.len() as u64 * ring + 2 + if s.parent.is_none() { ring + 1 } else { 0 };
        // Quads, tip fan and base fan; a junction's zip and collar quads.
        indices += (plan.rings.len() as u64 + 1) * u64::from(plan.sides) * 6;
        if junctions[i].is_some() {
            // Either the footprint loop and the collar loops, or a fallback swept from the
            // parent's axis: planned here as it would be (densified for holes too), so that the
            // budget holds either way.
            fallback.clear();
            plan_rings(s, q, feet, pad, 0.0, &mut fallback);
            if is_dense(i) {
                holes::densify(s, sides[i], p, &mut fallback, 0);
            }
            fork::keep_gaps(feet, &mut fallback, 0);
            let more = fallback.len().saturating_sub(plan.rings.len());
            let fork = junctions[i].filter(|j| j.fork).map(|j| fork::rows(&j, &stems[j.parent as usize], q));
            let joined = match fork {
                Some(rows) => fork::vertices(sides[i], rows) as u64,
                // The footprint loop twice, the collar loops, and up to a ring of copies across
                // the parent's seam (`MeshBuilder::unwrap_u`).
                None => (loops as u64 + 3) * ring,
            };
            vertices += (more as u64 * ring).max(joined);
            bridges_len += fork.map_or(0, |rows| fork::indices(sides[i], rows) as u64);
            bridges_len += (2 * u64::from(plan.sides) * (loops as u64 + 1)
                + 4 * (MAX_ROWS_BOUND + u64::from(sides[parent_of(i)])))
                * 3;
        }
        plans.push(plan);
    }
    if vertices > u64::from(p.max_vertices) {
        return Err(budget_error("", vertices, p.max_vertices));
    }
    let mut out = MeshBuilder::with_wind(vertices as usize, (indices + bridges_len) as usize);
    out.begin_group(Material::Bark);
    let mut tables: Vec<Option<Vec<(f32, f32, f32)>>> = vec![None; 97];
    let winds = stem_winds(skeleton, p.seed);
    let mut frames: Vec<Frame> = vec![Frame::default(); ts.len()];
    let mut meshes: Vec<Option<StemMesh>> = (0..n).map(|_| None).collect();
    let mut claimed: Vec<bool> = Vec::with_capacity(indices as usize / 6);
    let mut bridges: Vec<u32> = Vec::with_capacity(bridges_len as usize);
    let mut scratch = weld::Scratch::default();
    let mut stats = WeldStats::default();
    let is_clone = |i: usize| stems[i].parent.is_some_and(|p| stems[p as usize].level == stems[i].level);
    let mut blocks: Vec<Range<u32>> = vec![0..0; n];
    // Level by level (parents still come first): a split clone, planned before its original's
    // children, also opens its original before them.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&i| stems[i].level);
    for &i in &order {
        let stem = &stems[i];
        let plan = &mut plans[i];
        let table = tables[plan.sides as usize].get_or_insert_with(|| circle(plan.sides));
        let block_start = out.next_index();
        if twigs[i] {
            let mut m = twig::sweep(stem, &ts[plan.rings.clone()], plan.rings.start, table, &winds[i], &mut out);
            m.claim = claimed.len();
            claimed.resize(claimed.len() + (m.rings as usize - 1) * m.sides as usize, false);
            meshes[i] = Some(m);
            blocks[i] = block_start..out.next_index();
            continue;
        }
        let lobes = if stem.lobed && p.lobes > 0 && p.lobe_depth > 0.0 { Some((p.lobes, p.lobe_depth)) } else { None };
        let profile = (stem.lobed && (p.refine_curves > 0 || p.base_ripple > 0.0)).then(|| TrunkProfile::new(p, lobes));
        let wind = &winds[i];
        let sweep_plan = |ts: &[f32],
                          rings: std::ops::Range<usize>,
                          frames: &mut [Frame],
                          start: Option<(Vec3, f32)>,
                          out: &mut MeshBuilder| {
            let (ts, frames) = (&ts[rings.clone()], &mut frames[rings.clone()]);
            let mut m = match &profile {
                Some(tp) => sweep_trunk(stem, ts, table, tp, wind, frames, start, out),
                None => sweep(stem, ts, table, lobes, wind, frames, start, out),
            };
            m.ring0 = rings.start;
            m
        };
        // A fork's clone starts from its original's frame and bark at the split.
        let start = junctions[i].filter(|j| j.fork).and_then(|j| {
            let parent = meshes[j.parent as usize].as_ref()?;
            fork::clone_start(&j, parent, &ts, &frames, &out)
        });
        let mut m = sweep_plan(&ts, plan.rings.clone(), &mut frames, start, &mut out);
        if let Some(j) = &junctions[i] {
            let parent = meshes[j.parent as usize].as_ref().expect("parents are swept first");
            let join = weld::Join {
                junction: j,
                parent,
                parent_stem: &stems[j.parent as usize],
                child: &m,
                child_stem: stem,
                ts: &ts,
                frames: &frames,
                wind,
                loops,
            };
            let ok = if j.fork {
                let rows = fork::rows(j, &stems[j.parent as usize], q);
                start.is_some() && fork::join(&join, rows, &mut claimed, &mut out, &mut bridges, &mut scratch.tris)
            } else {
                weld::join(&join, &mut claimed, &mut out, &mut bridges, &mut scratch)
            };
            if ok {
                m.base = Base::Welded;
                stats.welds += 1;
                stats.split_welds += usize::from(is_clone(i));
                stats.forks += usize::from(j.fork);
            } else {
                // Fall back to a closed tube from the parent's axis, as if never welded.
                out.truncate_vertices(m.first);
                let start = ts.len();
                let feet = &inserted[extra[i].clone()];
                plan_rings(stem, q, feet, TAU / sides[i] as f32, 0.0, &mut ts);
                if is_dense(i) {
                    holes::densify(stem, sides[i], p, &mut ts, start);
                }
                fork::keep_gaps(feet, &mut ts, start);
                frames.resize(ts.len(), Frame::default());
                plan.rings = start..ts.len();
                m = sweep_plan(&ts, plan.rings.clone(), &mut frames, None, &mut out);
                stats.weld_fallbacks += 1;
                stats.split_fallbacks += usize::from(is_clone(i));
            }
        } else if weld::is_candidate(stems, i) && p.weld {
            stats.weld_fallbacks += 1;
            stats.split_fallbacks += usize::from(is_clone(i));
        }
        if m.base == PENDING_CAP {
            // A separate tube: close its base with a shallow cone to a centre vertex a quarter
            // radius inside (so clones leaving one split point never share their cap centres).
            let f = frames[m.ring0];
            let r0 = stem.radius_at(ts[m.ring0]).max(0.05 * stem.radius);
            let record = wind.record(stem, ts[m.ring0], r0);
            let centre = f.centre - f.tangent * (0.25 * r0);
            m.base = Base::Cap(out.vertex_with_wind(centre.to_array(), (-f.tangent).to_array(), [0.5, m.v0], &record));
        }
        m.claim = claimed.len();
        claimed.resize(claimed.len() + (m.rings as usize - 1) * m.sides as usize, false);
        meshes[i] = Some(m);
        blocks[i] = block_start..out.next_index();
    }
    for m in meshes.iter().flatten() {
        emit(m, &claimed, &mut out);
    }
    out.extend_indices(&bridges);
    Ok(Built { mesh: out.finish(), welds: stats, blocks })
}

/// The base of a swept branch before its cap's centre vertex exists.
const PENDING_CAP: Base = Base::Cap(u32::MAX);

/// Bound on the rows of a junction's hole, for the index capacity estimate.
const MAX_ROWS_BOUND: u64 = 8;

/// Indices of one swept stem: quads between rings (except those a child's junction claimed),
/// the tip fan, and the base cap.
fn emit(m: &StemMesh, claimed: &[bool], out: &mut MeshBuilder) {
    let s = m.sides;
    let st = s + 1;
    let rows = m.rings as usize - 1;
    let claims = &claimed[m.claim..m.claim + rows * s as usize];
    let free = claims.iter().filter(|&&c| !c).count();
    let fans = s as usize * if matches!(m.base, Base::Welded) { 1 } else { 2 };
    let idx = out.alloc_indices(free * 6 + fans * 3);
    let (quad_idx, fan_idx) = idx.split_at_mut(free * 6);
    let mut q = quad_idx.chunks_exact_mut(6);
    for (i, row_claims) in claims.chunks_exact(s as usize).enumerate() {
        let row = m.first + i as u32 * st;
        for (j, &c) in row_claims.iter().enumerate() {
            if c {
                continue;
            }
            let (a, b) = (row + j as u32, row + j as u32 + 1);
            let (c, d) = (b + st, a + st);
            q.next().expect("sized above").copy_from_slice(&[a, b, c, a, c, d]);
        }
    }
    let mut f = fan_idx.chunks_exact_mut(3);
    let row = m.first + (m.rings - 1) * st;
    for j in 0..s {
        f.next().expect("sized above").copy_from_slice(&[row + j, row + j + 1, m.apex]);
    }
    match m.base {
        Base::Trunk(cap) => {
            let centre = cap + st;
            for j in 0..s {
                f.next().expect("sized above").copy_from_slice(&[cap + j + 1, cap + j, centre]);
            }
        }
        Base::Cap(centre) => {
            for j in 0..s {
                f.next().expect("sized above").copy_from_slice(&[m.first + j + 1, m.first + j, centre]);
            }
        }
        Base::Welded => {}
    }
}

/// Per-stem constants of the wind attributes ([`TreeMesh::wind`]).
#[derive(Clone, Copy, Debug)]
pub struct StemWind {
    /// The stem's base point (the pivot it sways about).
    pub pivot: Vec3,
    /// Branch level.
    pub level: f32,
    /// Random phase 0..1, one per stem.
    pub phase: f32,
    /// Path length from the root to the stem's base (m).
    pub distance: f32,
    /// Trunk base radius (m), the reference for stiffness.
    pub trunk_radius: f32,
}

impl StemWind {
    /// The wind record of a ring at fraction `t` of `stem` with local radius `radius`.
    /// Stiffness is `sqrt(min(1, radius / trunk_radius))`: 1 at the trunk base (and in the flare),
    /// about 0.3 where a stem is a tenth of the trunk, 0.1 at a hundredth: thin twigs sway most.
    #[inline]
    pub fn record(&self, stem: &Stem, t: f32, radius: f32) -> [f32; WIND_STRIDE] {
        let stiffness = (radius / self.trunk_radius).clamp(0.0, 1.0).sqrt();
        let p = self.pivot;
        [p.x, p.y, p.z, self.level, self.phase, stiffness, self.distance + t * stem.length, radius]
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

fn sweep(
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
            sweep_with(stem, ts, circle, &|_, j| lobe[j], wind, frames, start, out)
        }
        None => sweep_with(stem, ts, circle, &|_, _| 1.0, wind, frames, start, out),
    }
}

/// Sweep one stem whose ring `r`, column `j` sits at `factor(r, j)` times the ring radius.
/// Where the factor varies around the ring, the in-plane normal follows the outline's tangent.
fn sweep_with(
    stem: &Stem,
    ts: &[f32],
    circle: &[(f32, f32, f32)],
    factor: &dyn Fn(usize, usize) -> f32,
    wind: &StemWind,
    frames: &mut [Frame],
    start: Option<(Vec3, f32)>,
    out: &mut MeshBuilder,
) -> StemMesh {
    let sides = circle.len() - 1;
    let stride = sides + 1;
    let rings = ts.len();
    let trunk = stem.parent.is_none();
    let count = rings * stride + 1 + if trunk { stride + 1 } else { 0 };
    let block = out.alloc_vertices(count);
    let (first, pos, nrm, uv, wnd) = (block.first, block.positions, block.normals, block.uvs, block.wind);
    let mut ring_factor = vec![1.0f32; stride];
    let mut plane_normal = vec![(0.0f32, 0.0f32); stride];
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
        let radius = stem.radius_at(t).max(0.05 * stem.radius);
        let slope = stem.radius_slope(t);
        let inv = 1.0 / (1.0 + slope * slope).sqrt();
        if let Some((pt, pr)) = prev {
            v += (t - pt) * stem.length / (TAU * (0.5 * (radius + pr)).max(0.25 * stem.radius));
        }
        let block = r * stride;
        let ring_pos = pos[block * 3..(block + stride) * 3].chunks_exact_mut(3);
        let ring_nrm = nrm[block * 3..(block + stride) * 3].chunks_exact_mut(3);
        let ring_uv = uv[block * 2..(block + stride) * 2].chunks_exact_mut(2);
        let record = wind.record(stem, t, radius);
        for w in wnd[block * WIND_STRIDE..(block + stride) * WIND_STRIDE].chunks_exact_mut(WIND_STRIDE) {
            w.copy_from_slice(&record);
        }
        let tilt = tan * slope;
        for (j, f) in ring_factor.iter_mut().enumerate() {
            *f = factor(r, j);
        }
        if ring_factor.iter().all(|&f| f == 1.0) {
            for (((p3, n3), t2), &(cs, sn, u)) in ring_pos.zip(ring_nrm).zip(ring_uv).zip(circle) {
                let radial = normal * cs + binormal * sn;
                let p = c + radial * radius;
                let n = (radial - tilt) * inv;
                p3.copy_from_slice(&[p.x, p.y, p.z]);
                n3.copy_from_slice(&[n.x, n.y, n.z]);
                t2.copy_from_slice(&[u, v]);
            }
        } else {
            // In-plane outline normals: perpendicular to the chord between neighbouring columns.
            let at = |j: usize| {
                let (cs, sn, _) = circle[j];
                (cs * ring_factor[j], sn * ring_factor[j])
            };
            for (j, n2) in plane_normal.iter_mut().enumerate() {
                let (a, b) = (at(if j == 0 { sides - 1 } else { j - 1 }), at(if j == sides { 1 } else { j + 1 }));
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let len = (dx * dx + dy * dy).sqrt().max(1e-12);
                *n2 = (dy / len, -dx / len);
            }
            for ((((p3, n3), t2), &(cs, sn, u)), (&f, &(nx, ny))) in
                ring_pos.zip(ring_nrm).zip(ring_uv).zip(circle).zip(ring_factor.iter().zip(&plane_normal))
            {
                let radial = normal * cs + binormal * sn;
                let p = c + radial * (radius * f);
                let outward = normal * nx + binormal * ny;
                let n = unit_or(outward - tilt, || radial);
                p3.copy_from_slice(&[p.x, p.y, p.z]);
                n3.copy_from_slice(&[n.x, n.y, n.z]);
                t2.copy_from_slice(&[u, v]);
            }
        }
        prev = Some((t, radius));
        last_center = c;
        last_radius = radius;
    }
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
    pos[apex_slot * 3..apex_slot * 3 + 3].copy_from_slice(&apex_pos.to_array());
    nrm[apex_slot * 3..apex_slot * 3 + 3].copy_from_slice(&tip_tan.to_array());
    uv[apex_slot * 2..apex_slot * 2 + 2].copy_from_slice(&[0.5, v_apex]);
    wnd[apex_slot * WIND_STRIDE..(apex_slot + 1) * WIND_STRIDE].copy_from_slice(&wind.record(stem, 1.0, end_r));
    let apex = first + apex_slot as u32;
    if trunk {
        // Trunk base: a flat cap with its own downward-facing copy of the bottom ring (a hard edge).
        let down = (-t0).to_array();
        let cap = apex_slot + 1;
        for (j, &(cs, sn, _)) in circle.iter().enumerate() {
            let (src, dst) = (j * 3, (cap + j) * 3);
            let ring0 = [pos[src], pos[src + 1], pos[src + 2]];
            pos[dst..dst + 3].copy_from_slice(&ring0);
            nrm[dst..dst + 3].copy_from_slice(&down);
            uv[(cap + j) * 2..(cap + j) * 2 + 2].copy_from_slice(&[0.5 + 0.5 * cs, 0.5 + 0.5 * sn]);
        }
        let centre = cap + stride;
        pos[centre * 3..centre * 3 + 3].copy_from_slice(&stem.base().to_array());
        nrm[centre * 3..centre * 3 + 3].copy_from_slice(&down);
        uv[centre * 2..centre * 2 + 2].copy_from_slice(&[0.5, 0.5]);
        // The cap's ring copy and centre sway like the bottom ring.
        let record: [f32; WIND_STRIDE] = wnd[..WIND_STRIDE].try_into().expect("ring 0 exists");
        for w in wnd[cap * WIND_STRIDE..(centre + 1) * WIND_STRIDE].chunks_exact_mut(WIND_STRIDE) {
            w.copy_from_slice(&record);
        }
    }
    out.rings(first, rings as u32, stride as u32);
    StemMesh {
        first,
        rings: rings as u32,
        sides: sides as u32,
        ring0: 0,
        apex,
        base: if trunk { Base::Trunk(apex + 1) } else { PENDING_CAP },
        claim: 0,
        v0,
    }
}

/// Cross-section settings of a complex trunk (see [`super::trunk`]): refinement circles whose
/// offset and radius vary smoothly with height, W&P lobes on top, and the maple page's base
/// ripple `R(u) = R0 (1 + a sin(7 theta))` fading out over the flare zone.
struct TrunkProfile {
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
    fn new(p: &TreeParams, lobes: Option<(u32, f32)>) -> Self {
        let mut rng = Rng::new(u64::from(p.seed), "trunk-profile");
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
fn sweep_trunk(
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
        let radius = stem.radius_at(t).max(0.05 * stem.radius);
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
    sweep_with(stem, ts, circle, &|r, j| rings[r][j], wind, frames, start, out)
}
