//! What a generation returns: the buffers and what the UI and tools report about them
//! ([`Generated`], [`Stats`]), and the meta ([`Generated::meta`], a [`TreeMeta`]) it shares with
//! the session's. A module of its own so that the session builds these without importing back from the
//! crate root, which calls the session.

use crate::mesh::{Bounds, TreeMesh};
use crate::meta::TreeMeta;
use crate::{foliage, mesh, params, skeleton};
use serde::Serialize;
use std::collections::BTreeMap;

/// Counts and timings of one generation.
#[derive(Clone, Debug, Serialize)]
pub struct Stats {
    /// Number of vertices.
    pub vertices: usize,
    /// Number of triangles.
    pub triangles: usize,
    /// Number of stems in the skeleton.
    pub stems: usize,
    /// Number of tree holes cut into the bark ([`mesh::holes`]).
    pub holes: usize,
    /// Junctions welded into their parent's surface, and those that fell back to closed separate
    /// tubes ([`mesh::tube::WeldStats`]).
    pub welds: mesh::tube::WeldStats,
    /// Milliseconds per stage, in pipeline order (`skeleton`, `mesh`, `hash`).
    pub stage_ms: Vec<(&'static str, f64)>,
    /// Milliseconds for the whole generation.
    pub total_ms: f64,
}

/// A generated tree: the buffers plus what the UI and tools report about them.
#[derive(Clone, Debug)]
pub struct Generated {
    /// The mesh buffers.
    pub mesh: TreeMesh,
    /// The skeleton the mesh was swept from.
    pub skeleton: skeleton::Skeleton,
    /// Bounds of the mesh.
    pub bounds: Bounds,
    /// Content hash of the buffers ([`TreeMesh::content_hash`]).
    pub hash: u64,
    /// Counts and timings.
    pub stats: Stats,
    /// Crown envelope for the viewer's preview: `[height, radius]` pairs ([`skeleton::preview_profile`]).
    pub envelope: Vec<[f32; 2]>,
    /// Growth mode only: the markers sampled in the crown at the start (for display).
    pub markers: Vec<glam::Vec3>,
    /// The leaves: one leaf mesh plus per-instance matrices and colours ([`foliage`]).
    pub foliage: foliage::Foliage,
    /// The tree holes cut into the bark (where, how big, found by which method).
    pub holes: Vec<mesh::holes::Hole>,
    /// The bark pattern ([`mesh::bark`]): the exporters bake its textures.
    pub bark: params::BarkType,
    /// What became of each hand edit ([`crate::edits`]): resolved or not, in list order.
    pub edits: Vec<crate::edits::EditReport>,
}

impl Generated {
    /// The hash as 16 hex digits, the form shown in the UI and printed by the CLI.
    pub fn hash_hex(&self) -> String {
        format!("{:016x}", self.hash)
    }

    /// Everything but the buffers ([`TreeMeta`] with the hash), as the JSON `meta_json()`
    /// returns in wasm.
    pub fn meta_json(&self) -> String {
        crate::meta::to_json(&self.meta())
    }

    /// Everything but the buffers: counts, bounds, groups, envelope, leaf facts, the bark type,
    /// the hash and the stage times.
    pub fn meta(&self) -> TreeMeta {
        let mut meta =
            tree_meta(&self.mesh, &self.foliage, &self.bounds, &self.envelope, self.stats.stems, self.stats.holes);
        meta.bark_type = self.bark as u8;
        meta.hash = Some(self.hash_hex());
        meta.stage_ms = self.stats.stage_ms.iter().copied().collect();
        meta.total_ms = self.stats.total_ms;
        meta.edits = self.edits.clone();
        meta
    }
}

/// The meta shared by [`Generated::meta`] and the session's: counts, bounds, material groups,
/// envelope and leaf facts (bark type 0, no hash, no timings: the caller sets them).
pub(crate) fn tree_meta(
    mesh: &TreeMesh,
    foliage: &foliage::Foliage,
    bounds: &Bounds,
    envelope: &[[f32; 2]],
    stems: usize,
    holes: usize,
) -> TreeMeta {
    TreeMeta {
        vertices: mesh.vertex_count(),
        triangles: mesh.triangle_count(),
        stems,
        holes,
        bounds: *bounds,
        groups: mesh.groups.clone(),
        envelope: envelope.to_vec(),
        leaves: foliage.count(),
        leaf_hash: format!("{:016x}", foliage.leaf_hash()),
        leaf_texture: foliage.texture().map(|t| [t.width, t.height]),
        bark_type: 0,
        stage_ms: BTreeMap::new(),
        total_ms: 0.0,
        hash: None,
        preview: None,
        from: None,
        changes: None,
        edits: Vec::new(),
    }
}

/// Number of heights in the envelope preview profile.
pub const ENVELOPE_SAMPLES: usize = 48;
