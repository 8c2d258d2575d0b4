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
//! * [`age`]: a tree's growth replayed to a younger Age.
//! * [`growth`]: space-colonization growth, an alternative source of stems.
//! * [`mesh`]: the output buffer type, the bark tube sweep, Bezier twigs and tree holes.
//! * [`organs`]: flowers, fruit, catkins and winter buds through the Season.
//! * [`season`]: the Season's spring flush, autumn colours, leaf fall and bare winter trees.
//! * [`export`]: GLB (glTF 2.0) and OBJ + MTL files of a generated tree.
//!
//! Same parameters and seed give byte-identical buffers on every target (see `math`).

// `define_params!` (params/macros.rs) sorts the registry's table into the stage structs one
// entry per recursion step: the table has more entries than the default limit of 128.
#![recursion_limit = "256"]

pub mod age;
pub mod clock;
pub mod crown;
pub mod crown_shade;
pub mod edits;
pub mod error;
pub mod export;
pub mod foliage;
mod generated;
pub mod growth;
pub mod leaf;
pub mod life;
pub mod lod;
pub mod math;
pub mod mesh;
pub mod meta;
pub mod organs;
pub mod par;
pub mod params;
pub mod presets;
pub mod rng;
pub mod season;
pub mod session;
pub mod share;
pub mod skeleton;

pub use clock::Clock;
pub use error::SylvaError;
pub use generated::{Generated, Stats, ENVELOPE_SAMPLES};
pub use mesh::{Bounds, Material, MeshGroup, TreeMesh};
pub use params::{registry, CrownShape, ParamSpec, TreeParams};

/// Version of the core, reported by the CLI and the wasm binding.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

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
    let mut session = session::Session::one_shot();
    session.update(params, session::Quality::Full, clock, progress)?;
    Ok(session.into_generated(clock).expect("a full update gives a full tree"))
}
