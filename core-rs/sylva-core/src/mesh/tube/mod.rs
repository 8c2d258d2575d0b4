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

mod rings;
mod sweep;

pub(crate) use rings::drop_close;
pub use sweep::{stem_winds, StemWind};

use super::{fork, fork_rows, holes, twig, weld, Material, MeshBuilder, TreeMesh};
use crate::error::SylvaError;
use crate::math::TAU;
use crate::params::TreeParams;
use crate::skeleton::{budget_error, Skeleton, StemKind};
use glam::Vec3;
use rings::plan_rings;
use std::ops::Range;
use sweep::{circle, emit, sweep, sweep_trunk, TrunkProfile};

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

/// Number of sides around a stem of base radius `r` (m) at the given quality.
pub fn sides_for(r: f32, quality: f32, lobes: u32) -> u32 {
    let base = (quality * (3.0 + 30.0 * r.max(0.0).sqrt())).round() as u32;
    base.max((4 * lobes).min(96)).clamp(3, 96)
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
            let split = |j: usize| weld::is_candidate(stems, j) && stems[j].kind == StemKind::SplitClone;
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
            let fork = junctions[i].filter(|j| j.fork).map(|j| fork_rows::rows(&j, &stems[j.parent as usize], q));
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
        return Err(budget_error(p, "", vertices));
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
    let is_clone = |i: usize| stems[i].kind == StemKind::SplitClone;
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
                let rows = fork_rows::row_choices(j, &stems[j.parent as usize], q);
                start.is_some()
                    && rows
                        .into_iter()
                        .any(|rows| fork::join(&join, rows, &mut claimed, &mut out, &mut bridges, &mut scratch.tris))
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
