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

mod halves;
mod plan;
mod rings;
mod sweep;

pub use super::layout::Layout;
pub use super::stem::{sides_for, StemWind};
pub use sweep::stem_winds;

use super::stem::{Base, Frame, StemMesh};
use super::{fork, fork_rows, twig, weld, Material, MeshBuilder, Tail, TreeMesh};
use crate::error::SylvaError;
use crate::params::MeshParams;
use crate::skeleton::{Skeleton, Stem, StemKind};
use glam::Vec3;
use plan::Plan;
use std::ops::Range;
use sweep::{circle, emit, index_count, sweep, sweep_trunk, TrunkProfile};

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

impl WeldStats {
    /// Adds `other`'s counts.
    fn add(&mut self, other: WeldStats) {
        self.welds += other.welds;
        self.weld_fallbacks += other.weld_fallbacks;
        self.split_welds += other.split_welds;
        self.split_fallbacks += other.split_fallbacks;
        self.forks += other.forks;
    }

    /// Counts one junction: welded or fallen back, of a split clone or not, forked or not.
    fn count(&mut self, welded: bool, clone: bool, fork: bool) {
        if welded {
            self.welds += 1;
            self.split_welds += usize::from(clone);
            self.forks += usize::from(fork);
        } else {
            self.weld_fallbacks += 1;
            self.split_fallbacks += usize::from(clone);
        }
    }
}

/// Sweep all stems into bark tubes. Fails with a budget error before allocating if the vertex
/// count would pass `max_vertices`.
pub fn build(skeleton: &Skeleton, p: &MeshParams) -> Result<TreeMesh, SylvaError> {
    build_with_stats(skeleton, p).map(|b| b.mesh)
}

/// [`build`] with where each stem is in the mesh ([`Layout`], which [`super::holes::cut`] reads).
pub fn build_laid_out(skeleton: &Skeleton, p: &MeshParams) -> Result<(TreeMesh, Layout), SylvaError> {
    build_with_stats(skeleton, p).map(|b| (b.mesh, b.layout))
}

/// What [`build_with_stats`] returns.
pub struct Built {
    /// The bark mesh.
    pub mesh: TreeMesh,
    /// Welded junctions and fallbacks.
    pub welds: WeldStats,
    /// Where each stem is in the mesh's buffers.
    pub layout: Layout,
}

/// [`build`], also counting the welded junctions and the fallbacks, and returning the stems'
/// vertex blocks. The deepest level's simple stems become Bezier twigs ([`twig`]) unless they are
/// welded; stems that may get tree holes are swept densely enough for them ([`super::holes::densify`]).
pub fn build_with_stats(skeleton: &Skeleton, p: &MeshParams) -> Result<Built, SylvaError> {
    let threads = halves::threads();
    build_on(skeleton, p, threads, (threads > 1).then_some((halves::MIN_VERTICES, 0)))
}

/// [`build_with_stats`] on up to `threads` threads, the deepest level in two parts
/// ([`halves`]) when it plans at least `halves.0` vertices (never without; the helper waiting
/// until this thread has taken `halves.1` of the level's stems, for the tests): side by side if
/// a helper comes while this thread sweeps the level, else all on this thread. The same bytes
/// either way.
fn build_on(
    skeleton: &Skeleton,
    p: &MeshParams,
    threads: usize,
    halves: Option<(usize, usize)>,
) -> Result<Built, SylvaError> {
    let plan = Plan::new(skeleton, p)?;
    let mut out = MeshBuilder::with_wind(plan.vertices as usize, (plan.indices + plan.bridges) as usize);
    out.prefault(plan.indices as usize);
    out.begin_group(Material::Bark);
    // Circle tables by number of sides.
    let mut tables: Vec<Option<Vec<(f32, f32, f32)>>> = vec![None; 97];
    for s in &plan.stems {
        tables[s.sides as usize].get_or_insert_with(|| circle(s.sides));
    }
    let winds = stem_winds(skeleton, skeleton.seed);
    // Level by level (parents still come first): a split clone, planned before its original's
    // children, also opens its original before them.
    let order = by_level(&skeleton.stems);
    let cuts = halves.and_then(|(min, wait)| Some((halves::cuts(skeleton, &plan, &order, min)?, wait)));
    let mut sweep = Sweep::new(skeleton, p, plan, out, &tables, &winds);
    match cuts {
        Some((cuts, wait)) => {
            order[..cuts.level].iter().for_each(|&i| sweep.stem(i));
            halves::sweep(&mut sweep, &order[cuts.level..], &cuts, threads, wait);
        }
        None => order.iter().for_each(|&i| sweep.stem(i)),
    }
    let Sweep { mut out, meshes, claimed, bridges, stats, blocks, junctions, plan, .. } = sweep;
    // The index pass runs on every thread, the one faulting in the buffers too.
    out.end_prefault();
    let tubes = emit_all(&meshes, &claimed, &mut out);
    let bridges_at = out.triangle_count();
    out.extend_indices(&bridges);
    let junctions = junctions.into_iter().map(|r| r.start + bridges_at..r.end + bridges_at).collect();
    let rest = out.triangle_count();
    super::cut_face::emit_faces(&meshes, &mut out);
    let layout = Layout { blocks, tubes, junctions, rest, eligible: plan.dense };
    Ok(Built { mesh: out.finish(), welds: stats, layout })
}

/// The stems' indices level by level, each level in stem order (one stable sort by level, as
/// a counting sort).
fn by_level(stems: &[Stem]) -> Vec<usize> {
    let levels = stems.iter().map(|s| s.level as usize + 1).max().unwrap_or(0);
    let mut start = vec![0usize; levels + 1];
    for s in stems {
        start[s.level as usize + 1] += 1;
    }
    for l in 0..levels {
        start[l + 1] += start[l];
    }
    let mut order = vec![0; stems.len()];
    for (i, s) in stems.iter().enumerate() {
        order[start[s.level as usize]] = i;
        start[s.level as usize] += 1;
    }
    order
}

/// Index writes below which [`emit_all`] stays on one thread.
const PARALLEL_INDICES: usize = 1 << 17;

/// Every stem's indices ([`emit`]), in stem order: each stem's count first, then the stems'
/// slices of one allocation written in runs of about equal size on [`crate::par::threads`]
/// (the helper threads in wasm). The same indices on any number of threads. Returns each stem's
/// range of triangles ([`Layout::tubes`]).
fn emit_all(meshes: &[Option<StemMesh>], claimed: &[bool], out: &mut MeshBuilder) -> Vec<Range<u32>> {
    let stems: Vec<&StemMesh> = meshes.iter().flatten().collect();
    let counts: Vec<usize> = stems.iter().map(|m| index_count(m, claimed)).collect();
    let total: usize = counts.iter().sum();
    let mut at = out.triangle_count();
    let mut sized = counts.iter();
    let tubes = meshes
        .iter()
        .map(|m| {
            let n = if m.is_some() { sized.next().map_or(0, |&n| (n / 3) as u32) } else { 0 };
            at += n;
            at - n..at
        })
        .collect();
    let threads = if total >= PARALLEL_INDICES { crate::par::threads() } else { 1 };
    out.append_indices(&counts, |tails| {
        // Runs of stems, each about `total / parts` indices, with their tails.
        let parts = threads * 4;
        let mut runs: Vec<Vec<(&StemMesh, &mut Tail<u32>)>> = Vec::with_capacity(parts);
        let (mut run, mut written) = (Vec::new(), 0);
        for ((m, &n), tail) in stems.into_iter().zip(&counts).zip(tails) {
            run.push((m, tail));
            written += n;
            if written * parts >= total * (runs.len() + 1) {
                runs.push(std::mem::take(&mut run));
            }
        }
        runs.push(run);
        crate::par::run(runs, threads, |run| {
            for (m, idx) in run {
                emit(m, claimed, idx);
            }
        });
    });
    tubes
}

/// Circle tables ([`circle`]) by number of sides.
type Tables = [Option<Vec<(f32, f32, f32)>>];

/// The sweep of a whole tree, stem by stem: what has been written so far.
struct Sweep<'a> {
    skeleton: &'a Skeleton,
    p: &'a MeshParams,
    plan: Plan,
    out: MeshBuilder,
    /// Circle tables by number of sides.
    tables: &'a Tables,
    /// Every stem's wind constants.
    winds: &'a [StemWind],
    /// Frames of every ring of [`Plan::ts`].
    frames: Vec<Frame>,
    meshes: Vec<Option<StemMesh>>,
    /// Quads left out of the index pass (a junction's hole), per stem from [`StemMesh::claim`].
    claimed: Vec<bool>,
    /// The junctions' triangles.
    bridges: Vec<u32>,
    scratch: weld::Scratch,
    fork_scratch: fork::Scratch,
    stats: WeldStats,
    /// Each stem's block of vertices.
    blocks: Vec<Range<u32>>,
    /// Each stem's triangles in `bridges` (counted in triangles).
    junctions: Vec<Range<u32>>,
}

impl<'a> Sweep<'a> {
    fn new(
        skeleton: &'a Skeleton,
        p: &'a MeshParams,
        plan: Plan,
        out: MeshBuilder,
        tables: &'a Tables,
        winds: &'a [StemWind],
    ) -> Sweep<'a> {
        let n = skeleton.stems.len();
        Sweep {
            skeleton,
            p,
            tables,
            winds,
            frames: vec![Frame::default(); plan.ts.len()],
            meshes: (0..n).map(|_| None).collect(),
            claimed: Vec::with_capacity(plan.indices as usize / 6),
            bridges: Vec::with_capacity(plan.bridges as usize),
            scratch: weld::Scratch::default(),
            fork_scratch: fork::Scratch::default(),
            stats: WeldStats::default(),
            blocks: vec![0..0; n],
            junctions: vec![0..0; n],
            plan,
            out,
        }
    }

    /// Sweeps stem `i` (a twig, or a tube welded into its parent, or a closed tube).
    fn stem(&mut self, i: usize) {
        let (skeleton, p, tables, winds) = (self.skeleton, self.p, self.tables, self.winds);
        let block_start = self.out.next_index();
        let bridges_start = (self.bridges.len() / 3) as u32;
        let table = tables[self.plan.stems[i].sides as usize].as_deref().expect("a table per planned sides");
        let stem = &skeleton.stems[i];
        let m = if self.plan.twigs[i] {
            let rings = self.plan.stems[i].rings.clone();
            twig::sweep(stem, &self.plan.ts[rings.clone()], rings.start, table, &winds[i], &mut self.out)
        } else {
            let lobes = (stem.lobed && p.lobes > 0 && p.lobe_depth > 0.0).then_some((p.lobes, p.lobe_depth));
            let profile = (stem.lobed && (p.refine_curves > 0 || p.base_ripple > 0.0))
                .then(|| TrunkProfile::new(p, skeleton.seed, lobes));
            let tube = Tube { stem, table, lobes, profile, wind: &winds[i] };
            let mut m = self.tube(i, &tube);
            if m.base == Base::Open {
                m.base = cap_base(stem, &tube, &self.plan.ts, &self.frames, &m, &mut self.out);
            }
            m
        };
        self.finish(i, m, block_start);
        self.junctions[i] = bridges_start..(self.bridges.len() / 3) as u32;
    }

    /// Sweeps tube `i` and welds it into its parent; where the weld fails, sweeps it again as a
    /// separate tube from its parent's axis, as if never welded. Its base is still open unless
    /// it is welded or the trunk's.
    fn tube(&mut self, i: usize, tube: &Tube) -> StemMesh {
        let (skeleton, junction) = (self.skeleton, self.plan.junctions[i]);
        let stems = &skeleton.stems;
        // A fork's clone starts from its original's frame and bark at the split.
        let start = junction.filter(|j| j.fork).and_then(|j| {
            let parent = self.meshes[j.parent as usize].as_ref()?;
            fork::clone_start(&j, parent, &self.plan.ts, &self.frames, &self.out)
        });
        let rings = self.plan.stems[i].rings.clone();
        let mut m = tube.sweep(&self.plan.ts, rings, &mut self.frames, start, &mut self.out);
        let clone = stems[i].kind == StemKind::SplitClone;
        let Some(j) = junction else {
            if weld::is_candidate(stems, i) && self.p.weld {
                self.stats.count(false, clone, false);
            }
            return m;
        };
        if self.weld(&j, &m, tube, start.is_some()) {
            m.base = Base::Welded;
            self.stats.count(true, clone, j.fork);
            return m;
        }
        // Fall back to a closed tube from the parent's axis, as if never welded.
        self.out.truncate_vertices(m.first);
        let mut ts = std::mem::take(&mut self.plan.ts);
        let from = ts.len();
        self.plan.tube_rings(skeleton, self.p, i, 0.0, &mut ts);
        self.frames.resize(ts.len(), Frame::default());
        self.plan.stems[i].rings = from..ts.len();
        self.plan.ts = ts;
        self.stats.count(false, clone, false);
        tube.sweep(&self.plan.ts, from..self.plan.ts.len(), &mut self.frames, None, &mut self.out)
    }

    /// Welds the swept child `m` into its parent at junction `j` (a fork when `j.fork`, which
    /// needs the clone to have started from its original's ring: `forked`).
    fn weld(&mut self, j: &weld::Junction, m: &StemMesh, tube: &Tube, forked: bool) -> bool {
        let skeleton = self.skeleton;
        let parent_stem = &skeleton.stems[j.parent as usize];
        let parent = self.meshes[j.parent as usize].as_ref().expect("parents are swept first");
        let loops = weld::collar_loops(self.p.mesh_quality);
        let join = weld::Join {
            junction: j,
            parent,
            parent_stem,
            child: m,
            child_stem: tube.stem,
            ts: &self.plan.ts,
            frames: &self.frames,
            wind: tube.wind,
            loops,
        };
        let (claimed, out, bridges) = (&mut self.claimed, &mut self.out, &mut self.bridges);
        if j.fork {
            let sc = &mut self.fork_scratch;
            forked
                && fork_rows::row_choices(j, parent_stem, self.p.mesh_quality)
                    .any(|rows| fork::join(&join, rows, claimed, out, bridges, sc))
        } else {
            weld::join(&join, claimed, out, bridges, &mut self.scratch)
        }
    }

    /// Records stem `i`'s swept mesh `m`, written from vertex `block_start` on, and reserves its
    /// quads in the claimed-quad bitmap.
    fn finish(&mut self, i: usize, mut m: StemMesh, block_start: u32) {
        m.claim = self.claimed.len();
        self.claimed.resize(self.claimed.len() + (m.rings as usize - 1) * m.sides as usize, false);
        self.meshes[i] = Some(m);
        self.blocks[i] = block_start..self.out.next_index();
    }
}

/// One tube's sweep settings: its circle table, the trunk's lobes or complex cross-section, its
/// wind constants.
struct Tube<'a> {
    stem: &'a Stem,
    table: &'a [(f32, f32, f32)],
    lobes: Option<(u32, f32)>,
    profile: Option<TrunkProfile>,
    wind: &'a StemWind,
}

impl Tube<'_> {
    /// Sweeps the rings `ts[rings]` (their frames into `frames[rings]`), from `start` (a fork
    /// clone's frame normal and `v`) if given.
    fn sweep(
        &self,
        ts: &[f32],
        rings: Range<usize>,
        frames: &mut [Frame],
        start: Option<(Vec3, f32)>,
        out: &mut MeshBuilder,
    ) -> StemMesh {
        let (ts, frames_of) = (&ts[rings.clone()], &mut frames[rings.clone()]);
        let mut m = match &self.profile {
            Some(tp) => sweep_trunk(self.stem, ts, self.table, tp, self.wind, frames_of, start, out),
            None => sweep(self.stem, ts, self.table, self.lobes, self.wind, frames_of, start, out),
        };
        m.ring0 = rings.start;
        m
    }
}

/// Closes the base of a separate tube with a shallow cone to a centre vertex a quarter radius
/// inside (so clones leaving one split point never share their cap centres).
fn cap_base(stem: &Stem, tube: &Tube, ts: &[f32], frames: &[Frame], m: &StemMesh, out: &mut MeshBuilder) -> Base {
    let f = frames[m.ring0];
    let r0 = stem.radius_at(ts[m.ring0]).max(0.05 * stem.radius);
    let record = tube.wind.record(stem, ts[m.ring0], r0);
    let centre = f.centre - f.tangent * (0.25 * r0);
    Base::Cap(out.vertex_with_wind(centre.to_array(), (-f.tangent).to_array(), [0.5, m.v0], &record))
}

#[cfg(test)]
mod tests {
    #[test]
    fn stems_go_level_by_level_as_a_stable_sort_puts_them() {
        for preset in crate::presets::PRESETS {
            let params = preset.params().expect("preset");
            let Ok(sk) = crate::skeleton::build(&params.skeleton) else { continue };
            let mut sorted: Vec<usize> = (0..sk.stems.len()).collect();
            sorted.sort_by_key(|&i| sk.stems[i].level);
            assert_eq!(super::by_level(&sk.stems), sorted, "{}", preset.name);
        }
        assert!(super::by_level(&[]).is_empty());
    }
}
