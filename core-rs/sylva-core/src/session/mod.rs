//! # Session: staged, incremental regeneration
//!
//! A [`Session`] keeps the last result of every pipeline [`Stage`] and reruns only from the
//! first stage whose parameter struct an edit changed ([`TreeParams::first_difference`]: the
//! [`TreeParams`] holds one struct per stage, `old.mesh != new.mesh`):
//!
//! | stage      | what it makes                                   | reused by a later-stage edit |
//! |------------|-------------------------------------------------|------------------------------|
//! | `skeleton` | stems (Weber & Penn or growth), crown envelope  | mesh, foliage, leaf edits    |
//! | `mesh`     | the bark: swept, welded, holes cut              | foliage, leaf edits          |
//! | `foliage`  | leaf placements (matrices, tints)               | leaf edits                   |
//! | `leaf`     | the leaf and the mesh drawn per leaf            | —                            |
//! | `viewer`   | nothing                                         | everything                   |
//!
//! Stages run in that order and each takes only its own parameter struct and what the earlier
//! stages made (the [`Skeleton`] carries the Seed, Levels and Max Vertices the later stages
//! need; the leaf gets the Petiole Length the leaves were placed with), so a rerun from stage S
//! gives the same bytes as a cold generation (tested for every parameter in
//! `tests/incremental.rs`).
//!
//! **Preview.** While a slider is dragged the caller may allow a [`Quality::Preview`]: when the
//! bark would take longer than the budget (judged by the last full run), the bark is swept at a
//! lower Mesh Quality without welds or holes and marked as a preview; when placing the leaves
//! would take over half the budget, only every other leaf site is placed (each leaf √2 larger, so
//! the crown keeps its leaf area; the leaves kept sit where the full tree has them) and the new
//! leaves are darkened by the previous leaves' light field ([`crate::crown_shade`]) instead of
//! their own; when the last leaf took over half the budget, a drag of the leaf's shape gets a
//! leaf whose texture is one Texture Size level down. The skeleton is always full and cached. The next [`Quality::Full`] update with the same parameters redoes only what was
//! previewed (the bark, the leaf placements, the leaf and the bark's occlusion).
//!
//! **Hash.** The content hash ([`Session::hash`]) is computed on demand, after the buffers went
//! out, and only describes a full result.

use crate::clock::Clock;
use crate::crown_shade::CrownLight;
use crate::error::SylvaError;
use crate::foliage::{self, Foliage};
use crate::generated::{Generated, Stats};
use crate::mesh::holes::Hole;
use crate::mesh::tube::WeldStats;
use crate::mesh::{self, Bounds, TreeMesh};
use crate::meta::TreeMeta;
use crate::params::{LeafParams, Stage, TreeParams};
use crate::skeleton::Skeleton;

mod edit_cache;
mod stages;
use edit_cache::EditCache;
pub use edit_cache::Resume;
use stages::{bark_and_placements, full_bark, preview_bark, preview_leaf_params, Fresh, LeafMesh};

/// Mesh Quality factor of a preview bark (never below the parameter's minimum).
pub const PREVIEW_QUALITY: f32 = 0.5;

/// How good the answer to an update must be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Quality {
    /// The full tree, byte-identical to [`crate::generate`].
    Full,
    /// A preview bark is allowed when the full bark is predicted to take longer than
    /// `budget_ms` (from the last full sweep's time).
    Preview {
        /// Longest the bark may take before a preview is drawn instead (ms).
        budget_ms: f64,
    },
}

impl Quality {
    /// Whether a stage whose last full run took `last` ms gets a preview: a drag (`Preview`)
    /// and that run over half the budget.
    fn over_half_budget(self, last: Option<f64>) -> bool {
        match self {
            Quality::Preview { budget_ms } => last.is_some_and(|ms| ms > budget_ms / 2.0),
            Quality::Full => false,
        }
    }
}

pub use crate::meta::Changes;

/// The stems and what the viewer draws of them.
#[derive(Clone, Debug)]
pub struct SkeletonOut {
    /// The stems.
    pub skeleton: Skeleton,
    /// Growth mode: the markers sampled at the start.
    pub markers: Vec<glam::Vec3>,
    /// Crown envelope profile ([`crate::skeleton::preview_profile`]).
    pub envelope: Vec<[f32; 2]>,
    /// What became of each hand edit ([`crate::edits`]), in list order.
    pub edits: Vec<crate::edits::EditReport>,
}

/// The bark of the current tree.
#[derive(Clone, Debug)]
pub struct Bark {
    /// The buffers.
    pub mesh: TreeMesh,
    /// Weld counts.
    pub welds: WeldStats,
    /// Holes cut.
    pub holes: Vec<Hole>,
    /// Bounds of `mesh`.
    pub bounds: Bounds,
    /// A preview sweep (lower quality, no welds, no holes), not the full bark.
    pub preview: bool,
    /// The occlusion (`mesh.shade`) is left from the previous leaves: a drag deferred it.
    pub shade_stale: bool,
    /// `mesh.content_hash()`, once computed.
    hash: Option<u64>,
}

/// Milliseconds of the stages the last update ran (0 for the reused ones).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StageTimes {
    /// Skeleton (or growth).
    pub skeleton: f64,
    /// Bark sweep, welds, holes.
    pub mesh: f64,
    /// Leaf placements plus the leaf (the `foliage` figure of [`Stats`]).
    pub foliage: f64,
    /// Of `mesh` and `foliage`, the milliseconds the bark and the leaf placement ran side by
    /// side (natively, when both ran); the update took `skeleton + mesh + foliage - overlap`.
    pub overlap: f64,
}

impl StageTimes {
    /// Milliseconds of the whole update (the stages' sum less their overlap).
    pub fn total(&self) -> f64 {
        self.skeleton + self.mesh + self.foliage - self.overlap
    }
}

/// The current tree of a session.
#[derive(Clone, Debug)]
pub struct Current {
    /// The parameters of the last update.
    pub params: TreeParams,
    /// Stems, markers, envelope.
    pub skeleton: SkeletonOut,
    /// The bark.
    pub bark: Bark,
    /// The leaves.
    pub foliage: Foliage,
    /// The leaves' light field (it darkened their tints and shades the bark); `None` when bare.
    pub light: Option<CrownLight>,
    /// The leaves are a drag's preview: one site in [`foliage::preview_thin`] placed (larger),
    /// their tints darkened by the previous leaves' light field, not their own.
    pub leaves_preview: bool,
    /// The leaf is a drag's preview: its texture one Texture Size level down.
    pub leaf_preview: bool,
    /// What the last update changed.
    pub changes: Changes,
    /// Stage times of the last update.
    pub times: StageTimes,
    /// The first stage the last update reran (`Viewer`: none).
    pub from: Stage,
}

impl Current {
    /// Whether this is a preview: a preview bark, or a bark shaded for the previous leaves.
    pub fn is_preview(&self) -> bool {
        self.bark.preview || self.bark.shade_stale || self.leaves_preview || self.leaf_preview
    }

    /// Everything but the buffers as JSON: [`Current::meta`].
    pub fn meta_json(&self) -> String {
        crate::meta::to_json(&self.meta())
    }

    /// Everything but the buffers: the fields of [`Generated::meta`] except the hash
    /// ([`Session::hash`] comes after the buffers), the stage times of this update, and
    /// `preview`, `from` (the first stage rerun) and `changes` (which buffers differ from the
    /// previous update's).
    pub fn meta(&self) -> TreeMeta {
        let b = &self.bark;
        let stems = self.skeleton.skeleton.stems.len();
        let mut meta = crate::generated::tree_meta(
            &b.mesh,
            &self.foliage,
            &b.bounds,
            &self.skeleton.envelope,
            stems,
            b.holes.len(),
        );
        let t = self.times;
        meta.stage_ms = [("skeleton", t.skeleton), ("mesh", t.mesh), ("foliage", t.foliage)].into_iter().collect();
        meta.total_ms = t.total();
        meta.preview = Some(self.is_preview());
        meta.bark_type = self.params.mesh.bark_type as u8;
        meta.from = Some(self.from);
        meta.changes = Some(self.changes);
        meta.edits = self.skeleton.edits.clone();
        meta
    }
}

/// Incremental generator state: the last result of every stage. See the module docs.
#[derive(Debug, Default)]
pub struct Session {
    current: Option<Current>,
    /// Time of the last full bark sweep (ms), the predictor of the next one.
    last_full_mesh_ms: Option<f64>,
    /// Time of the last bark occlusion (ms): a drag defers it when it is over half its budget.
    last_shade_ms: Option<f64>,
    /// Time of the last leaf placement with its own light field (ms): a drag lights the new
    /// leaves by the previous field when it is over half the budget.
    last_place_ms: Option<f64>,
    /// Time of the last full leaf generation (ms): a drag of the leaf's shape gets a preview
    /// leaf when it is over half the budget.
    last_leaf_ms: Option<f64>,
    /// The skeleton stage's stems and hand edits, resumed where the last edit list left off.
    edits: EditCache,
}

/// What the leaf stage reads: its parameters, the Petiole Length the leaves were placed with
/// (a foliage parameter), how many leaves there are, and whether its inputs changed.
struct LeafJob<'a> {
    params: &'a LeafParams,
    petiole: f32,
    count: usize,
    stale: bool,
    /// Milliseconds the leaf took when the placement made it ahead (it is cached by then).
    made_ahead_ms: Option<f64>,
}

impl Session {
    /// An empty session: the first update generates cold.
    pub fn new() -> Session {
        Session::default()
    }

    /// A session for one tree ([`crate::generate`]): its stems are not copied into the caches
    /// an interactive session keeps for its next update (a second update builds them again).
    pub fn one_shot() -> Session {
        Session { edits: EditCache::one_shot(), ..Session::default() }
    }

    /// The current tree, if an update succeeded.
    pub fn current(&self) -> Option<&Current> {
        self.current.as_ref()
    }

    /// Forgets every cached stage (the next update generates cold).
    pub fn clear(&mut self) {
        self.current = None;
        self.last_full_mesh_ms = None;
        self.last_shade_ms = None;
        self.last_place_ms = None;
        self.last_leaf_ms = None;
        self.edits.clear();
    }

    /// Brings the tree to `params`, rerunning from the first stage that changed. On an error
    /// the previous tree stays current, unchanged.
    pub fn update(
        &mut self,
        params: &TreeParams,
        quality: Quality,
        clock: &dyn Clock,
        progress: Option<&mut dyn FnMut(f32)>,
    ) -> Result<&Current, SylvaError> {
        params.validate()?;
        let prev = self.current.take();
        match self.compute(prev.as_ref(), params.clone(), quality, clock, progress) {
            Ok(fresh) => self.current = Some(fresh.assemble(prev)),
            Err(e) => {
                self.current = prev;
                return Err(e);
            }
        }
        Ok(self.current.as_ref().expect("just set"))
    }

    /// Runs the stages `params` needs on top of `prev`, borrowing what it reuses; each stage
    /// gets its own parameter struct.
    fn compute(
        &mut self,
        prev: Option<&Current>,
        params: TreeParams,
        quality: Quality,
        clock: &dyn Clock,
        progress: Option<&mut dyn FnMut(f32)>,
    ) -> Result<Fresh, SylvaError> {
        let p = &params;
        let from = prev.map_or(Stage::Skeleton, |c| c.params.first_difference(p));
        let want_preview = match quality {
            Quality::Full => false,
            Quality::Preview { budget_ms } => self.last_full_mesh_ms.is_some_and(|ms| ms > budget_ms),
        };
        let mut times = StageTimes::default();

        let t0 = clock.now_ms();
        let skeleton = (from <= Stage::Skeleton).then(|| self.edits.build(&p.skeleton, progress)).transpose()?;
        let skel = skeleton.as_ref().or(prev.map(|c| &c.skeleton)).expect("a first update builds the skeleton");
        let t1 = clock.now_ms();
        times.skeleton = t1 - t0;

        // The bark is swept again when its inputs changed, or when the bark shown is a preview
        // and a full answer is wanted.
        let bark_stale = from <= Stage::Mesh || prev.is_some_and(|c| c.bark.preview && !want_preview);
        let sweep =
            || if want_preview { preview_bark(&skel.skeleton, &p.mesh) } else { full_bark(&skel.skeleton, &p.mesh) };
        // Placed again when their inputs changed, or when their tints were lit by the previous
        // leaves (a drag) and a full answer is wanted. A drag's placement is a preview: every
        // other leaf site (or fewer, for a dense crown), lit by the previous field.
        let over = |last: Option<f64>| quality.over_half_budget(last);
        let by_previous = over(self.last_place_ms).then(|| prev.and_then(|c| c.light.as_ref())).flatten();
        let place_stale = from <= Stage::Foliage || prev.is_some_and(|c| c.leaves_preview && by_previous.is_none());
        // A new leaf shape the leaf stage will want in full (a first tree, a preset) is made
        // (and cached) right after the placement, on the placement's thread: beside the bark
        // when both run side by side. The same leaf either way (a pure function of its
        // parameters); none for a leafless placement.
        let leaf_key = foliage::LeafKey::of(&p.leaf, p.foliage.leaf_petiole);
        let warm_leaf = !over(self.last_leaf_ms)
            && prev.is_none_or(|c| foliage::LeafKey::of(&c.params.leaf, c.params.foliage.leaf_petiole) != leaf_key);
        let (shared, made_ahead) = (clock.shared(), std::sync::Mutex::new(None));
        let place = || {
            let placed = foliage::place_lit_by(&skel.skeleton, &p.foliage, by_previous, by_previous.is_some());
            if let Some(c) = shared.filter(|_| warm_leaf && placed.as_ref().is_ok_and(|(f, _)| f.count() > 0)) {
                let t = c.now_ms();
                // An error here is the leaf stage's to report, when it asks again.
                let _ = foliage::cached_leaf(&p.leaf, p.foliage.leaf_petiole);
                *made_ahead.lock().unwrap_or_else(std::sync::PoisonError::into_inner) = Some(c.now_ms() - t);
            }
            placed
        };
        let sides = bark_and_placements(clock, bark_stale.then_some(sweep), place_stale.then_some(place))?;
        let t2 = clock.now_ms();
        times.mesh = sides.mesh_ms;
        times.overlap = sides.overlap_ms;
        let (bark, placements) = (sides.bark, sides.placements);
        if bark.as_ref().is_some_and(|b| !b.preview) {
            self.last_full_mesh_ms = Some(times.mesh);
        }
        if placements.is_some() && by_previous.is_none() {
            self.last_place_ms = Some(sides.place_ms);
        }
        let leaves_preview = match placements {
            Some(_) => by_previous.is_some(),
            None => prev.is_some_and(|c| c.leaves_preview),
        };
        let (placed, light) = match (&placements, prev) {
            (Some((f, l)), _) => (f, l.as_ref()),
            (None, Some(c)) => (&c.foliage, c.light.as_ref()),
            (None, None) => unreachable!("a first update places the leaves"),
        };
        let job = LeafJob {
            params: &p.leaf,
            petiole: p.foliage.leaf_petiole,
            count: placed.count(),
            stale: from <= Stage::Leaf || placements.is_some(),
            made_ahead_ms: made_ahead.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner),
        };
        let (leaf, leaf_preview) = self.dress(prev, &job, quality, clock)?;
        // The bark's occlusion reads the bark, its holes and the leaves: again when any changed.
        // A preview bark goes without it; a drag of the leaves keeps the old one meanwhile
        // (a preview) when computing it would take over half the budget.
        let b = bark.as_ref().or(prev.map(|c| &c.bark)).expect("a first update sweeps the bark");
        let stale = bark.is_none() && prev.is_some_and(|c| c.bark.shade_stale);
        let defer = over(self.last_shade_ms) || leaves_preview;
        let shade = if b.preview {
            bark.is_some().then(Vec::new)
        } else if bark.is_none() && ((placements.is_none() && !stale) || defer) {
            // Nothing it reads changed (or a drag defers it): the bark keeps its occlusion.
            None
        } else {
            let t = clock.now_ms();
            let shade = mesh::shade::occlusion_with(&b.mesh, &b.holes, light, p.mesh.hole_size);
            self.last_shade_ms = Some(clock.now_ms() - t);
            Some(shade)
        };
        let shade_stale = !b.preview && shade.is_none() && (stale || (bark.is_none() && placements.is_some()));
        times.foliage = sides.place_ms + (clock.now_ms() - t2);

        let changes = match prev {
            None => Changes { skeleton: true, bark: true, placements: true, leaf_mesh: true, leaf: true, shade: true },
            Some(c) => Changes {
                skeleton: skeleton.is_some(),
                bark: bark.is_some(),
                placements: placements.as_ref().is_some_and(|(f, _)| {
                    f.matrices != c.foliage.matrices || f.colors != c.foliage.colors || f.organs != c.foliage.organs
                }),
                leaf_mesh: leaf.as_ref().is_some_and(|(m, _)| *m != c.foliage.mesh),
                leaf: leaf.as_ref().is_some_and(|(_, l)| l.as_ref().map_or(0, |l| l.hash) != c.foliage.leaf_hash()),
                shade: shade.as_ref().is_some_and(|s| *s != c.bark.mesh.shade),
            },
        };
        Ok(Fresh {
            params,
            skeleton,
            bark,
            placements,
            leaves_preview,
            leaf,
            leaf_preview,
            shade,
            shade_stale,
            changes,
            times,
            from,
        })
    }

    /// The leaf stage: the mesh drawn per leaf for `job.count` leaves, dressed again when
    /// `job.stale` (new leaf parameters or new placements; the leaf itself is cached). A drag of the leaf's
    /// shape whose last leaf took over half the budget gets a preview leaf, its texture one size
    /// down (a quarter of the texels to vein, raster and bake). Returns the mesh (`None`: keep
    /// the previous one) and whether the leaf is a preview.
    fn dress(
        &mut self,
        prev: Option<&Current>,
        job: &LeafJob,
        quality: Quality,
        clock: &dyn Clock,
    ) -> Result<(Option<LeafMesh>, bool), SylvaError> {
        let over = quality.over_half_budget(self.last_leaf_ms);
        let was_preview = prev.is_some_and(|c| c.leaf_preview);
        let key = foliage::LeafKey::of(job.params, job.petiole);
        let shape_changed =
            prev.is_none_or(|c| foliage::LeafKey::of(&c.params.leaf, c.params.foliage.leaf_petiole) != key);
        let preview = over && (shape_changed || was_preview);
        if !job.stale && was_preview == preview {
            return Ok((None, preview));
        }
        if preview {
            return Ok((Some(foliage::leaf_mesh(job.count, &preview_leaf_params(job.params), job.petiole)?), true));
        }
        let t = clock.now_ms();
        let dressed = foliage::leaf_mesh(job.count, job.params, job.petiole)?;
        if shape_changed || was_preview {
            self.last_leaf_ms = Some(clock.now_ms() - t + job.made_ahead_ms.unwrap_or(0.0));
        }
        Ok((Some(dressed), false))
    }

    /// Where the last update's skeleton stage resumed on the hand edit list (the stems built
    /// again or not, how many edits were not applied again, a stroke extended): for tests and
    /// the benchmarks.
    pub fn skeleton_resume(&self) -> Resume {
        self.edits.resume
    }

    /// The content hash of the current full tree (bark, then leaves; [`Generated::hash`]),
    /// computed once per bark and cheap for leaf-only edits. `None` before the first update or
    /// while the bark is a preview.
    pub fn hash(&mut self) -> Option<u64> {
        let c = self.current.as_mut()?;
        if c.is_preview() {
            return None;
        }
        let bark = *c.bark.hash.get_or_insert_with(|| c.bark.mesh.content_hash());
        Some(mesh::bark::hash_into(c.params.mesh.bark_type, c.foliage.hash_into(bark)))
    }

    /// Moves the current full tree out as a [`Generated`] without copying its buffers.
    pub fn into_generated(mut self, clock: &dyn Clock) -> Option<Generated> {
        let t0 = clock.now_ms();
        let hash = self.hash()?;
        let hash_ms = clock.now_ms() - t0;
        let c = self.current?;
        let t = c.times;
        let stats = Stats {
            vertices: c.bark.mesh.vertex_count(),
            triangles: c.bark.mesh.triangle_count(),
            stems: c.skeleton.skeleton.stems.len(),
            holes: c.bark.holes.len(),
            welds: c.bark.welds,
            stage_ms: vec![("skeleton", t.skeleton), ("mesh", t.mesh), ("foliage", t.foliage), ("hash", hash_ms)],
            total_ms: t.total() + hash_ms,
        };
        Some(Generated {
            mesh: c.bark.mesh,
            skeleton: c.skeleton.skeleton,
            bounds: c.bark.bounds,
            hash,
            stats,
            envelope: c.skeleton.envelope,
            markers: c.skeleton.markers,
            edits: c.skeleton.edits,
            foliage: c.foliage,
            holes: c.bark.holes,
            bark: c.params.mesh.bark_type,
        })
    }
}
