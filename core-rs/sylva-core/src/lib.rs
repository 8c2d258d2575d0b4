//! # Sylva core
//!
//! A pure Rust procedural tree generator. The pipeline is a chain of plain-data stages:
//!
//! ```text
//! TreeParams --validate--> skeleton::build --> mesh::tube::build --> mesh::holes::cut --> TreeMesh (+ hash, stats)
//!                                  \-----> foliage::place --> foliage::dress --> Foliage
//! ```
//!
//! [`session::Session`] keeps each stage's last result and reruns only from the first stage an
//! edit touches (the registry's [`params::Stage`]); [`generate`] is a cold session.
//!
//! * [`params`]: the parameter registry, the single source of truth for the UI, URLs and docs.
//! * [`rng`]: one portable PRNG with a named stream per stage.
//! * [`crown`]: Weber & Penn's ShapeRatio crown envelopes.
//! * [`skeleton`]: Weber & Penn stems.
//! * [`growth`]: space-colonization growth, an alternative source of stems.
//! * [`mesh`]: the output buffer type, the bark tube sweep, Bezier twigs and tree holes.
//! * [`export`]: GLB (glTF 2.0) and OBJ + MTL files of a generated tree.
//!
//! Same parameters and seed give byte-identical buffers on every target (see `math`).

// `define_params!` (params/macros.rs) sorts the registry's table into the stage structs one
// entry per recursion step: the table has more entries than the default limit of 128.
#![recursion_limit = "256"]

pub mod clock;
pub mod crown;
pub mod crown_shade;
pub mod error;
pub mod export;
pub mod foliage;
pub mod growth;
pub mod leaf;
pub mod lod;
pub mod math;
pub mod mesh;
pub mod par;
pub mod params;
pub mod presets;
pub mod rng;
pub mod session;
pub mod skeleton;

pub use clock::Clock;
pub use error::SylvaError;
pub use mesh::{Bounds, Material, MeshGroup, TreeMesh};
pub use params::{registry, CrownShape, ParamSpec, TreeParams};

use serde::Serialize;

/// Version of the core, reported by the CLI and the wasm binding.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

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
}

impl Generated {
    /// The hash as 16 hex digits, the form shown in the UI and printed by the CLI.
    pub fn hash_hex(&self) -> String {
        format!("{:016x}", self.hash)
    }

    /// Everything but the buffers as a JSON object (what `meta_json()` returns in wasm).
    pub fn meta_json(&self) -> String {
        let mut meta =
            tree_meta(&self.mesh, &self.foliage, &self.bounds, &self.envelope, self.stats.stems, self.stats.holes);
        meta["bark_type"] = serde_json::json!(self.bark as u8);
        meta["hash"] = serde_json::json!(self.hash_hex());
        let stage_ms: serde_json::Map<String, serde_json::Value> =
            self.stats.stage_ms.iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect();
        meta["stage_ms"] = serde_json::Value::Object(stage_ms);
        meta["total_ms"] = serde_json::json!(self.stats.total_ms);
        meta.to_string()
    }
}

/// The meta object shared by [`Generated::meta_json`] and the session's: counts, bounds,
/// material groups, envelope and leaf facts (no hash, no timings).
pub(crate) fn tree_meta(
    mesh: &TreeMesh,
    foliage: &foliage::Foliage,
    bounds: &Bounds,
    envelope: &[[f32; 2]],
    stems: usize,
    holes: usize,
) -> serde_json::Value {
    serde_json::json!({
        "vertices": mesh.vertex_count(),
        "triangles": mesh.triangle_count(),
        "stems": stems,
        "holes": holes,
        "bounds": bounds,
        "groups": mesh.groups,
        "envelope": envelope,
        "leaves": foliage.count(),
        "leaf_hash": format!("{:016x}", foliage.leaf_hash()),
        "leaf_texture": foliage.texture().map(|t| [t.width, t.height]),
    })
}

/// Number of heights in the envelope preview profile.
pub const ENVELOPE_SAMPLES: usize = 48;

/// Generate a tree: validate, build the skeleton, sweep the surfaces, hash the buffers.
///
/// ```
/// use sylva_core::{generate, TreeParams};
///
/// let mut params = TreeParams::default();
/// params.set("levels", 1.0)?; // the trunk and one branch level: quick
/// params.set("seed", 7.0)?;
/// let tree = generate(&params)?;
/// assert!(tree.mesh.vertex_count() > 0);
/// // The same parameters and seed give the same bytes, here and in wasm.
/// assert_eq!(generate(&params)?.hash_hex(), tree.hash_hex());
/// # Ok::<(), sylva_core::SylvaError>(())
/// ```
pub fn generate(params: &TreeParams) -> Result<Generated, SylvaError> {
    generate_with_clock(params, clock::default_clock().as_ref())
}

/// [`generate`] with an explicit clock for the stage timings.
pub fn generate_with_clock(params: &TreeParams, clock: &dyn Clock) -> Result<Generated, SylvaError> {
    generate_with_progress(params, clock, None)
}

/// [`generate_with_clock`] reporting the progress of growth (fraction 0..1 of the iteration cap)
/// to `progress` every few iterations; the tree is the same with or without it.
pub fn generate_with_progress(
    params: &TreeParams,
    clock: &dyn Clock,
    progress: Option<&mut dyn FnMut(f32)>,
) -> Result<Generated, SylvaError> {
    let mut session = session::Session::new();
    session.update(params, session::Quality::Full, clock, progress)?;
    Ok(session.into_generated(clock).expect("a full update gives a full tree"))
}
