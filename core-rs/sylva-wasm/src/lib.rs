//! WebAssembly binding of `sylva-core`. It only converts between JS and the core: JSON strings
//! in, typed arrays and JSON strings out. Errors are thrown as a JSON string of
//! `sylva_core::SylvaError` (`{"kind", "param"?, "message"}`); a Rust panic traps the instance
//! after the panic hook stored its message, which `take_panic()` hands to the worker so it can
//! report it and start a fresh instance.

use std::sync::Mutex;
use sylva_core::{mesh::bark, params::BarkType, params::TreeParams, presets, Clock, Generated};
use wasm_bindgen::prelude::*;

mod baked;
mod lod_glb;
mod organs;
mod session;

pub use baked::BakedLeafMesh;
pub use session::Session;

static LAST_PANIC: Mutex<Option<String>> = Mutex::new(None);

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = performance, js_name = now)]
    fn performance_now() -> f64;
}

struct PerfClock;
impl Clock for PerfClock {
    fn now_ms(&self) -> f64 {
        performance_now()
    }
    /// Readable from any thread: in the module built with atomics a helper reads its own
    /// worker's `performance.now()`, whose origin differs, so only durations are taken on it
    /// (the core never compares readings of two threads).
    fn shared(&self) -> Option<&(dyn Clock + Sync)> {
        Some(self)
    }
}

/// The body of a helper thread, in the module built with atomics: the host calls it once in a
/// worker that instantiated this module on the generating instance's shared memory; it runs
/// the jobs the core hands out (`sylva_core::par::helpers`) and never returns.
#[cfg(target_feature = "atomics")]
#[wasm_bindgen(js_name = helperLoop)]
pub fn helper_loop() {
    sylva_core::par::helpers::helper_loop();
}

/// Jobs the helper threads ran since the module started (the module built with atomics).
#[cfg(target_feature = "atomics")]
#[wasm_bindgen(js_name = helperJobs)]
pub fn helper_jobs() -> f64 {
    sylva_core::par::helpers::helper_jobs() as f64
}

/// The threads a generation uses: 1, plus the helper threads started (the module built with
/// atomics; none in the single-threaded one).
#[wasm_bindgen]
pub fn threads() -> usize {
    sylva_core::par::threads()
}

/// Runs when the module is instantiated: installs the panic hook. It keeps the first panic's
/// message (a helper thread's, when the thread waiting for it panics in turn) and, in the
/// module built with atomics, wakes the threads waiting for a helper's job
/// (`sylva_core::par::helpers::poison`).
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        let msg = info.to_string();
        if let Ok(mut slot) = LAST_PANIC.lock() {
            slot.get_or_insert(msg);
        }
        #[cfg(target_feature = "atomics")]
        sylva_core::par::helpers::poison();
    }));
}

/// The message of the last Rust panic, if any (cleared by reading).
#[wasm_bindgen]
pub fn take_panic() -> Option<String> {
    LAST_PANIC.lock().ok().and_then(|mut s| s.take())
}

/// Panics on purpose, to test the worker's recovery path. Only in a build with the
/// `debug-hooks` feature (the tests' debug worker): the shipped module exports no test hooks.
#[cfg(feature = "debug-hooks")]
#[wasm_bindgen]
pub fn debug_panic() {
    panic!("debug_panic: deliberate panic requested by a test");
}

/// Panics on a helper thread while the calling thread waits for it (the module built with
/// atomics, with a helper started; otherwise it panics on the calling thread). Only with the
/// `debug-hooks` feature.
#[cfg(feature = "debug-hooks")]
#[wasm_bindgen]
pub fn debug_panic_on_helper() {
    use std::sync::atomic::{AtomicBool, Ordering};
    let taken = AtomicBool::new(false);
    let t0 = performance_now();
    sylva_core::par::join(
        2,
        // Wait (at most 5 s) for the helper to take the other closure, so that it panics there.
        || {
            while !taken.load(Ordering::Acquire) && performance_now() - t0 < 5000.0 {
                std::hint::spin_loop();
            }
        },
        || {
            taken.store(true, Ordering::Release);
            panic!("debug_panic_on_helper: deliberate panic requested by a test");
        },
    );
}

/// The vertices of `positions` (3 floats each) that `sylva_core::mesh::holes::near_x` hands its
/// test, in order, after the number of vertices it scanned: `[n, v...]` (its `simd128` lanes,
/// checked against the scalar rule by a test). Only with the `debug-hooks` feature.
#[cfg(feature = "debug-hooks")]
#[wasm_bindgen]
pub fn debug_near_x(positions: Vec<f32>, lo: f32, hi: f32) -> Vec<u32> {
    let mut seen = Vec::new();
    let n = sylva_core::mesh::holes::near_x(&positions, lo, hi, &mut |v| seen.push(v as u32));
    std::iter::once(n as u32).chain(seen).collect()
}

/// Version of the core.
#[wasm_bindgen]
pub fn core_version() -> String {
    sylva_core::VERSION.to_string()
}

/// The parameter registry as JSON (`ParamSpec[]`).
#[wasm_bindgen]
pub fn registry_json() -> String {
    sylva_core::params::registry_json()
}

/// The presets as JSON.
#[wasm_bindgen]
pub fn presets_json() -> String {
    presets::presets_json()
}

/// The procedural bark maps of bark type `kind` (the `bark_type` parameter's index), `size`²
/// texels each, rows bottom to top, one after the other: colour (sRGB RGBA8), normal (RGB =
/// tangent-space normal, A = height) and occlusion-roughness-metal (R, G, B).
#[wasm_bindgen]
pub fn bark_maps(kind: u32, size: usize) -> Vec<u8> {
    let m = bark::bake(BarkType::from_index(kind as usize), size.clamp(16, 1024));
    [m.color.rgba, m.normal.rgba, m.orm.rgba].concat()
}

/// The procedural end grain of bark type `kind` for the faces of cut stems, `size`² texels per
/// map: the colour map then the normal map (layout:
/// `sylva_core::mesh::bark::end_grain::EndGrainMaps::to_bytes`).
#[wasm_bindgen]
pub fn end_grain_maps(kind: u32, size: usize) -> Vec<u8> {
    bark::end_grain::bake(BarkType::from_index(kind as usize), size.clamp(16, 1024)).to_bytes()
}

/// How bark type `kind` is laid on a stem (`sylva_core::mesh::bark::BarkStyle`) as JSON.
#[wasm_bindgen]
pub fn bark_style_json(kind: u32) -> String {
    bark::style_json(BarkType::from_index(kind as usize))
}

/// A generated tree. Each getter returns a fresh typed-array copy whose buffer the worker can
/// transfer. Layout of the buffers: see `sylva_core::TreeMesh`.
#[wasm_bindgen]
pub struct GeneratedTree(Generated);

#[wasm_bindgen]
impl GeneratedTree {
    /// `x, y, z` per vertex.
    pub fn positions(&self) -> Vec<f32> {
        self.0.mesh.positions.clone()
    }
    /// Unit normal per vertex.
    pub fn normals(&self) -> Vec<f32> {
        self.0.mesh.normals.clone()
    }
    /// `u, v` per vertex.
    pub fn uvs(&self) -> Vec<f32> {
        self.0.mesh.uvs.clone()
    }
    /// Triangle list (u32).
    pub fn indices(&self) -> Vec<u32> {
        self.0.mesh.indices.clone()
    }
    /// Wind attributes, 8 floats per bark vertex: `pivot_x, pivot_y, pivot_z, level, phase,
    /// stiffness, distance, radius` (pivot = the stem's base point; level 0 = trunk; phase 0..1
    /// per stem; stiffness 0..1, `sqrt(min(1, radius / trunk base radius))`; distance = path length
    /// from the root in m; radius = local stem radius in m). See `sylva_core::TreeMesh::wind`.
    pub fn wind(&self) -> Vec<f32> {
        self.0.mesh.wind.clone()
    }
    /// Bark occlusion, one byte per vertex (0 = no light, 255 = open sky; crown depth and tree
    /// holes, see `sylva_core::mesh::shade`), or empty.
    pub fn shade(&self) -> Vec<u8> {
        self.0.mesh.shade.clone()
    }
    /// Growth mode: the markers sampled in the crown (`x, y, z` per marker; empty otherwise).
    pub fn markers(&self) -> Vec<f32> {
        self.0.markers.iter().flat_map(|m| m.to_array()).collect()
    }
    /// The crown envelope preview as line segments (`x, y, z` pairs of points).
    pub fn envelope_lines(&self) -> Vec<f32> {
        sylva_core::crown::preview_lines(&self.0.envelope, 16, 48)
    }
    /// Counts, hash, bounds, groups and timings as JSON.
    pub fn meta_json(&self) -> String {
        self.0.meta_json()
    }
    /// The leaf mesh (leaf units): `x, y, z` per vertex (empty when the tree is bare).
    pub fn leaf_positions(&self) -> Vec<f32> {
        self.0.foliage.mesh.positions.clone()
    }
    /// The leaf mesh's unit normals.
    pub fn leaf_normals(&self) -> Vec<f32> {
        self.0.foliage.mesh.normals.clone()
    }
    /// The leaf mesh's `u, v` per vertex (over the baked leaf texture).
    pub fn leaf_uvs(&self) -> Vec<f32> {
        self.0.foliage.mesh.uvs.clone()
    }
    /// The leaf mesh's triangle list (u32).
    pub fn leaf_indices(&self) -> Vec<u32> {
        self.0.foliage.mesh.indices.clone()
    }
    /// Per-leaf 4x4 matrices, column-major, 16 floats per leaf.
    pub fn leaf_matrices(&self) -> Vec<f32> {
        self.0.foliage.matrices.clone()
    }
    /// Per-leaf RGB tint, 3 floats per leaf.
    pub fn leaf_colors(&self) -> Vec<f32> {
        self.0.foliage.colors.clone()
    }
    /// The baked leaf colour texture (RGBA8, row 0 = v 0; size in `meta_json().leaf_texture`).
    pub fn leaf_texture(&self) -> Vec<u8> {
        self.0.foliage.texture().map(|t| t.color.clone()).unwrap_or_default()
    }
    /// The tree as a glTF 2.0 binary (`.glb`, see `sylva_core::export::glb`). `options_json` is
    /// a JSON object of `sylva_core::export::ExportOptions` fields (`leaves`: `"instanced"` |
    /// `"baked"` | `"none"`, `wind`, `textures`, `normal_maps`, `vertex_colors`,
    /// `bark_texture_size`); `""` or `"{}"` takes the defaults. Throws a JSON `SylvaError` string
    /// on bad options.
    pub fn to_glb(&self, options_json: &str) -> Result<Vec<u8>, JsValue> {
        let opts = export_options(options_json)?;
        Ok(sylva_core::export::to_glb(&self.0, &opts))
    }
    /// [`GeneratedTree::to_glb`] left in the module's memory, for JS to read without the copy
    /// `to_glb` makes: `new Uint8Array(file.memory().buffer, file.ptr(), file.byte_length())`,
    /// then `file.free()`. Read the view (e.g. into a `Blob`) before calling the module again:
    /// a call that grows the memory detaches the buffer. Freed files leave their memory to the
    /// next export, which then writes into pages already mapped.
    pub fn to_glb_file(&self, options_json: &str) -> Result<GlbFile, JsValue> {
        let opts = export_options(options_json)?;
        Ok(GlbFile(sylva_core::export::to_glb(&self.0, &opts)))
    }
    /// The GLB with the tree's growth animation (`sylva_core::export::glb::write_growth`,
    /// docs/formats.md "Growth animation"), for a tree generated at Age `age` with Mature Age
    /// `maturity` (the `age` and `maturity` values it was generated with), left in the module's
    /// memory as [`GeneratedTree::to_glb_file`]'s. Leaves are baked; the other options as there.
    pub fn to_growth_glb_file(&self, options_json: &str, age: f32, maturity: f32) -> Result<GlbFile, JsValue> {
        let opts = export_options(options_json)?;
        Ok(GlbFile(sylva_core::export::glb::write_growth(&self.0, &opts, age, maturity)))
    }
    /// The tree as Wavefront OBJ text (bark and baked leaves; `mtllib NAME.mtl`, see
    /// `sylva_core::export::obj`). `name` is the file stem the OBJ refers to.
    pub fn to_obj(&self, name: &str, options_json: &str) -> Result<String, JsValue> {
        let opts = export_options(options_json)?;
        Ok(sylva_core::export::obj::obj(&self.0, &opts, name))
    }
    /// The MTL text for [`GeneratedTree::to_obj`] (texture files named `NAME_bark_color.png`, ...).
    pub fn to_mtl(&self, name: &str, options_json: &str) -> Result<String, JsValue> {
        let opts = export_options(options_json)?;
        Ok(sylva_core::export::obj::mtl(&self.0, &opts, name))
    }
    /// The names of the PNG files the MTL refers to (`NAME_bark_color.png`, ...), in the order
    /// of [`GeneratedTree::obj_texture`]'s indices.
    pub fn obj_texture_names(&self, name: &str, options_json: &str) -> Result<Vec<String>, JsValue> {
        let opts = export_options(options_json)?;
        Ok(sylva_core::export::obj::texture_names(&self.0, &opts, name))
    }
    /// PNG file `index` of [`GeneratedTree::obj_texture_names`] (empty when out of range).
    pub fn obj_texture(&self, options_json: &str, index: usize) -> Result<Vec<u8>, JsValue> {
        let opts = export_options(options_json)?;
        Ok(sylva_core::export::obj::texture_png(&self.0, &opts, index).unwrap_or_default())
    }
}

/// An exported file in the module's memory ([`GeneratedTree::to_glb_file`]).
#[wasm_bindgen]
pub struct GlbFile(Vec<u8>);

#[wasm_bindgen]
impl GlbFile {
    /// Byte offset of the file in `memory().buffer`.
    pub fn ptr(&self) -> usize {
        self.0.as_ptr() as usize
    }
    /// Length of the file in bytes.
    pub fn byte_length(&self) -> usize {
        self.0.len()
    }
    /// The module's `WebAssembly.Memory`.
    pub fn memory(&self) -> JsValue {
        wasm_bindgen::memory()
    }
}

fn export_options(json: &str) -> Result<sylva_core::export::ExportOptions, JsValue> {
    sylva_core::export::ExportOptions::from_json(json).map_err(|e| JsValue::from_str(&e.to_json()))
}

/// The growth as a zip of one GLB per whole year up to the Age of `params_json` (as for
/// [`generate`]), each the tree generated at that Age and written with `options_json` (as for
/// [`GeneratedTree::to_glb`]): `sylva_core::export::growth::years::years_zip`, the bytes `sylva generate
/// --growth-years` writes. Throws a JSON `SylvaError` string.
#[wasm_bindgen]
pub fn growth_years_zip(params_json: &str, options_json: &str) -> Result<Vec<u8>, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    let opts = export_options(options_json)?;
    sylva_core::export::growth::years::years_zip(&params, &opts).map_err(|e| JsValue::from_str(&e.to_json()))
}

/// Generate a tree from a JSON object of parameter values (`{"id": number}`); missing ids take
/// their defaults. Throws a JSON `SylvaError` string on invalid input or a budget overrun.
#[wasm_bindgen]
pub fn generate(params_json: &str) -> Result<GeneratedTree, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    sylva_core::generate_with_clock(&params, &PerfClock).map(GeneratedTree).map_err(|e| JsValue::from_str(&e.to_json()))
}

#[wasm_bindgen]
extern "C" {
    /// A JS function `(fraction: number) => void` that receives growth progress.
    #[wasm_bindgen(typescript_type = "(fraction: number) => void")]
    pub type ProgressFn;
    #[wasm_bindgen(method, js_name = call)]
    fn call_with(this: &ProgressFn, this_arg: &JsValue, fraction: f32);
}

/// [`generate`], calling `progress(fraction)` every few growth iterations (growth mode only),
/// so the worker can post progress while it is busy.
#[wasm_bindgen]
pub fn generate_with_progress(params_json: &str, progress: &ProgressFn) -> Result<GeneratedTree, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    let mut report = |f: f32| progress.call_with(&JsValue::NULL, f);
    sylva_core::generate_with_progress(&params, &PerfClock, Some(&mut report))
        .map(GeneratedTree)
        .map_err(|e| JsValue::from_str(&e.to_json()))
}

/// A leaf as JSON (outline, triangulation, auxins, vein graph, loops, timings): the same object
/// `sylva leaf` prints (`sylva_core::leaf::json`). `params_json` is `{"id": number}` over the
/// registry (the `leaf_*` ids shape the leaf); throws a JSON `SylvaError` string on bad input.
#[wasm_bindgen]
pub fn leaf_json(params_json: &str) -> Result<String, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    let leaf = sylva_core::leaf::generate_with_clock(&params.leaf, params.foliage.leaf_petiole, &PerfClock)
        .map_err(|e| JsValue::from_str(&e.to_json()))?;
    Ok(sylva_core::leaf::json::to_json(&leaf))
}

/// The leaf as an SVG drawing after growth step `step` (a negative step draws the finished
/// network): outline, margin, triangulation, auxin sources and veins with pipe widths.
#[wasm_bindgen]
pub fn leaf_svg(params_json: &str, step: i32) -> Result<String, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    let leaf = sylva_core::leaf::generate_with_clock(&params.leaf, params.foliage.leaf_petiole, &PerfClock)
        .map_err(|e| JsValue::from_str(&e.to_json()))?;
    let opts = sylva_core::leaf::svg::SvgOptions {
        triangulation: true,
        step: u32::try_from(step).ok(),
        ..sylva_core::leaf::svg::SvgOptions::default()
    };
    Ok(sylva_core::leaf::svg::render(&leaf, &opts))
}

/// The leaf for the inspector in one call: `{"svg": string, "iterations", "nodes", "links",
/// "segments", "auxins", "triangles", "hash"}` where `segments` counts the vein segments drawn
/// at `step` (a negative step draws the finished network). `triangulation` draws the triangles.
#[wasm_bindgen]
pub fn leaf_inspect(params_json: &str, step: i32, triangulation: bool) -> Result<String, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    let leaf = sylva_core::leaf::generate_with_clock(&params.leaf, params.foliage.leaf_petiole, &PerfClock)
        .map_err(|e| JsValue::from_str(&e.to_json()))?;
    let step = u32::try_from(step).ok();
    let opts =
        sylva_core::leaf::svg::SvgOptions { triangulation, step, ..sylva_core::leaf::svg::SvgOptions::default() };
    Ok(sylva_core::leaf::svg::inspect_json(&leaf, &opts))
}

/// The leaf presets as JSON (`[{name, label, description, values}]`).
#[wasm_bindgen]
pub fn leaf_presets_json() -> String {
    sylva_core::leaf::presets::presets_json()
}

/// A generated tree with its levels of detail (`sylva_core::lod`): LOD0 is the tree `generate`
/// gives, LOD1 and LOD2 come from its skeleton. Getters take the level (0, 1, 2) and return fresh
/// typed-array copies the worker can transfer.
#[wasm_bindgen]
pub struct GeneratedLods(sylva_core::lod::TreeLods);

#[wasm_bindgen]
impl GeneratedLods {
    /// Bark `x, y, z` per vertex of `level`.
    pub fn positions(&self, level: usize) -> Vec<f32> {
        self.0.level(level).mesh.positions.clone()
    }
    /// Bark unit normals of `level`.
    pub fn normals(&self, level: usize) -> Vec<f32> {
        self.0.level(level).mesh.normals.clone()
    }
    /// Bark `u, v` of `level`.
    pub fn uvs(&self, level: usize) -> Vec<f32> {
        self.0.level(level).mesh.uvs.clone()
    }
    /// Bark triangle list (u32) of `level`.
    pub fn indices(&self, level: usize) -> Vec<u32> {
        self.0.level(level).mesh.indices.clone()
    }
    /// Bark occlusion of `level`, one byte per vertex (0 = no sky, 255 = open sky).
    pub fn shade(&self, level: usize) -> Vec<u8> {
        self.0.level(level).mesh.shade.clone()
    }
    /// The leaf mesh of `level` (leaf units; empty for LOD2 and bare trees).
    pub fn leaf_positions(&self, level: usize) -> Vec<f32> {
        self.0.level(level).foliage.mesh.positions.clone()
    }
    /// The leaf mesh's unit normals.
    pub fn leaf_normals(&self, level: usize) -> Vec<f32> {
        self.0.level(level).foliage.mesh.normals.clone()
    }
    /// The leaf mesh's `u, v`.
    pub fn leaf_uvs(&self, level: usize) -> Vec<f32> {
        self.0.level(level).foliage.mesh.uvs.clone()
    }
    /// The leaf mesh's triangle list (u32).
    pub fn leaf_indices(&self, level: usize) -> Vec<u32> {
        self.0.level(level).foliage.mesh.indices.clone()
    }
    /// Per-leaf 4x4 matrices of `level`, column-major.
    pub fn leaf_matrices(&self, level: usize) -> Vec<f32> {
        self.0.level(level).foliage.matrices.clone()
    }
    /// Per-leaf RGB tint of `level`.
    pub fn leaf_colors(&self, level: usize) -> Vec<f32> {
        self.0.level(level).foliage.colors.clone()
    }
    /// Billboard-cloud quads of `level` (12 floats each: centre, u, v half-axes, rgb).
    pub fn cloud(&self, level: usize) -> Vec<f32> {
        self.0.level(level).cloud.to_vec()
    }
    /// The baked leaf colour texture (RGBA8; size in `meta_json().leaf_texture`).
    pub fn leaf_texture(&self) -> Vec<u8> {
        self.0.lod0.foliage.texture().map(|t| t.color.clone()).unwrap_or_default()
    }
    /// Hash, bounds and per-level counts as JSON (`sylva_core::lod::TreeLods::meta_json`).
    pub fn meta_json(&self) -> String {
        self.0.meta_json()
    }
}

/// [`generate`] plus the levels of detail from the same skeleton. Throws like [`generate`].
#[wasm_bindgen]
pub fn generate_lods(params_json: &str) -> Result<GeneratedLods, JsValue> {
    let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
    sylva_core::generate_with_clock(&params, &PerfClock)
        .and_then(|g| sylva_core::lod::lods_of(g, &params.mesh))
        .map(GeneratedLods)
        .map_err(|e| JsValue::from_str(&e.to_json()))
}
