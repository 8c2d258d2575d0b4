//! The stages of a [`super::Session`] update: the full and the preview bark, the
//! preview leaf's parameters, the bark and the leaf placement side by side
//! ([`bark_and_placements`]), and [`Fresh`], what one update ran, assembled into the next
//! [`Current`].

use super::{Bark, Changes, Current, SkeletonOut, StageTimes, PREVIEW_QUALITY};
use crate::clock::Clock;
use crate::crown_shade::CrownLight;
use crate::error::SylvaError;
use crate::foliage::Foliage;
use crate::mesh::{self, TreeMesh};
use crate::params::{LeafParams, MeshParams, Stage, TreeParams};
use crate::skeleton::Skeleton;

/// The stages an update ran; `None` = reuse the previous result.
pub(super) struct Fresh {
    pub(super) params: TreeParams,
    pub(super) skeleton: Option<SkeletonOut>,
    pub(super) bark: Option<Bark>,
    pub(super) placements: Option<(Foliage, Option<CrownLight>)>,
    /// [`Current::leaves_preview`] of the result.
    pub(super) leaves_preview: bool,
    pub(super) leaf: Option<LeafMesh>,
    /// [`Current::leaf_preview`] of the result.
    pub(super) leaf_preview: bool,
    /// The bark's new occlusion (with a new bark or new placements; empty for a preview).
    pub(super) shade: Option<Vec<u8>>,
    /// Whether the bark's occlusion is left from other leaves afterwards.
    pub(super) shade_stale: bool,
    pub(super) changes: Changes,
    pub(super) times: StageTimes,
    pub(super) from: Stage,
}

pub(super) type LeafMesh = (TreeMesh, Option<std::sync::Arc<crate::leaf::Leaf>>);

impl Fresh {
    /// The new current tree: fresh stages, the rest moved (not copied) out of `prev`.
    pub(super) fn assemble(self, prev: Option<Current>) -> Current {
        let (skeleton, mut bark, (mut foliage, light)) = match prev {
            Some(c) => (
                self.skeleton.unwrap_or(c.skeleton),
                self.bark.unwrap_or(c.bark),
                self.placements.unwrap_or((c.foliage, c.light)),
            ),
            None => (
                self.skeleton.expect("a first update builds the skeleton"),
                self.bark.expect("a first update sweeps the bark"),
                self.placements.expect("a first update places the leaves"),
            ),
        };
        if let Some((mesh, leaf)) = self.leaf {
            (foliage.mesh, foliage.leaf) = (mesh, leaf);
        }
        if let Some(shade) = self.shade {
            bark.mesh.shade = shade;
            bark.hash = None;
        }
        bark.shade_stale = self.shade_stale;
        Current {
            params: self.params,
            skeleton,
            bark,
            foliage,
            light,
            leaves_preview: self.leaves_preview,
            leaf_preview: self.leaf_preview,
            changes: self.changes,
            times: self.times,
            from: self.from,
        }
    }
}

/// The leaf parameters of a preview leaf: the texture one Texture Size level down (not below
/// the parameter's minimum).
pub(super) fn preview_leaf_params(p: &LeafParams) -> LeafParams {
    let mut q = p.clone();
    q.leaf_texture_level = p.leaf_texture_level.saturating_sub(1).max(PREVIEW_MIN_TEXTURE_LEVEL);
    q
}

/// Smallest Texture Size level a preview leaf goes down to (16 texels).
const PREVIEW_MIN_TEXTURE_LEVEL: u32 = 4;

/// The mesh stage at full quality: sweep and weld, then cut the holes.
pub(super) fn full_bark(skeleton: &Skeleton, p: &MeshParams) -> Result<Bark, SylvaError> {
    let built = mesh::tube::build_with_stats(skeleton, p)?;
    let mut mesh = built.mesh;
    let holes = mesh::holes::cut(&mut mesh, &built.layout, skeleton, p);
    let bounds = mesh.bounds();
    Ok(Bark { mesh, welds: built.welds, holes, bounds, preview: false, shade_stale: false, hash: None })
}

/// A preview bark: [`PREVIEW_QUALITY`] times the Mesh Quality, separate tubes, no holes.
pub(super) fn preview_bark(skeleton: &Skeleton, p: &MeshParams) -> Result<Bark, SylvaError> {
    let mut q = p.clone();
    q.mesh_quality = (p.mesh_quality * PREVIEW_QUALITY).max(0.25);
    q.weld = false;
    q.hole_count = 0;
    let mut bark = full_bark(skeleton, &q)?;
    bark.preview = true;
    Ok(bark)
}

/// Leaf placements and the crown's light field ([`crate::foliage::place_lit_by`]).
pub(super) type Placements = (Foliage, Option<CrownLight>);

/// What [`bark_and_placements`] gives: each result with its milliseconds, and how long the two
/// ran side by side.
pub(super) struct Sides {
    pub(super) bark: Option<Bark>,
    pub(super) mesh_ms: f64,
    pub(super) placements: Option<Placements>,
    pub(super) place_ms: f64,
    /// Of `mesh_ms` and `place_ms`, the milliseconds they overlapped (0 when run in order).
    pub(super) overlap_ms: f64,
}

/// The bark (`bark`) and the leaf placements (`place`), each left out when `None`. Both read
/// only the skeleton and their own parameters, and each draws from its own random stream, so
/// they run side by side when both are wanted, natively on a second thread
/// ([`crate::par::join`]) if the clock can be read from it; in order otherwise (wasm, one
/// thread, `sylva batch`). The same results either way; on two failures, the bark's error.
pub(super) fn bark_and_placements(
    clock: &dyn Clock,
    bark: Option<impl FnOnce() -> Result<Bark, SylvaError> + Send>,
    place: Option<impl FnOnce() -> Result<Placements, SylvaError> + Send>,
) -> Result<Sides, SylvaError> {
    let threads = if bark.is_some() && place.is_some() { crate::par::threads() } else { 1 };
    let (b, p, overlap_ms) = match clock.shared().filter(|_| threads > 1) {
        Some(c) => {
            let t0 = c.now_ms();
            // The bark's buffers are faulted in on the leaves' thread once the leaves are
            // placed ([`crate::par::prefault`]): the same bytes, fewer page faults on the bark's.
            let mailbox = std::sync::Arc::new(crate::par::prefault::Mailbox::default());
            let (b, p) = crate::par::join(
                threads,
                || crate::par::prefault::offering(&mailbox, || timed(c, bark)),
                || {
                    let p = timed(c, place);
                    mailbox.run();
                    p
                },
            );
            let overlap = (b.1 + p.1 - (c.now_ms() - t0)).max(0.0);
            (b, p, overlap)
        }
        None => {
            let b = timed(clock, bark);
            // In order, a failed bark places no leaves.
            let p = if matches!(b.0, Some(Err(_))) { (None, 0.0) } else { timed(clock, place) };
            (b, p, 0.0)
        }
    };
    Ok(Sides { bark: b.0.transpose()?, mesh_ms: b.1, placements: p.0.transpose()?, place_ms: p.1, overlap_ms })
}

/// `f()` if given, and its milliseconds (0 when not).
fn timed<R>(clock: &(impl Clock + ?Sized), f: Option<impl FnOnce() -> R>) -> (Option<R>, f64) {
    let Some(f) = f else { return (None, 0.0) };
    let t = clock.now_ms();
    let r = f();
    (Some(r), clock.now_ms() - t)
}
