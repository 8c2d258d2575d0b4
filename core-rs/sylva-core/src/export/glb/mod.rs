//! # GLB writer
//!
//! glTF 2.0 binary (GLB), following the Khronos glTF 2.0 specification (§3 concepts, §4.4 GLB
//! file format) and the `EXT_mesh_gpu_instancing` extension.
//!
//! ## File layout
//!
//! A 12-byte header (`glTF`, version 2, total length), a JSON chunk padded with
//! spaces to 4 bytes, a BIN chunk padded with zeros to 4 bytes. One buffer (the BIN chunk);
//! every buffer view starts on a 4-byte boundary and holds one tightly packed array, except the
//! normal views (`byteStride` 4: three bytes and one of padding, or 8 with the tangent) and the
//! wind view (below). Vertex views have `target` 34962 (ARRAY_BUFFER), index views 34963
//! (ELEMENT_ARRAY_BUFFER); image and instancing views have none.
//!
//! ## Scene, meshes and materials
//!
//! Node 0 `sylva_tree` (identity) with children `bark` and `leaves`.
//!
//! * **Bark** mesh: one primitive per material group of [`TreeMesh`], sharing the attributes
//!   `POSITION` (float, with min/max), `NORMAL`, `TEXCOORD_0` (float: bark UVs run past 1),
//!   `TANGENT` (with normal maps, unless [`ExportOptions::tangents`] is off), `COLOR_0` (RGBA8
//!   normalised, see [`super::bark_colors`]) and the wind attributes; indices are `u16` when
//!   there are at most 65,535 vertices, `u32` otherwise.
//! * **Quantisation** (`KHR_mesh_quantization`, in `extensionsUsed` and `extensionsRequired`
//!   whenever there is a mesh): `NORMAL` is a normalised `i8` `VEC3` (padded to 4 bytes) and
//!   `TANGENT` a normalised `i8` `VEC4` (`w` = ±127), in every mesh. Each vector is rounded to
//!   nearest and, where that leaves it off unit length by more than the glTF validator allows
//!   for quantised data (0.00674), replaced by the floor/ceiling combination closest to unit
//!   length. This saves 20 of the 28 bytes per vertex the float normal and tangent took, the
//!   bytes a big export spends most of its time writing. The bark's tangents are computed
//!   straight into the output ([`super::frames_snorm8_write`]): on the mesh's tube rings
//!   (`TreeMesh::rings`, nearly every bark vertex) from the ring neighbours, elsewhere by
//!   Lengyel's method over the triangles touching those vertices ([`super::mesh_tangents`]).
//! * **Strict** ([`ExportOptions::strict`]): no extension used or required. `NORMAL` and
//!   `TANGENT` are floats, each in a view of its own (the bark's tangents from
//!   [`super::mesh_tangents`], the same directions the quantised file rounds), and
//!   [`LeafMode::Instanced`] leaves are written as [`LeafMode::Baked`].
//! * **Wind** (when the mesh carries it, see `TreeMesh::wind`): the 8 values per vertex as
//!   normalised `u16`, interleaved in one view with `byteStride` 16 right after the colours,
//!   read by two `VEC4` accessors: `_WIND_PIVOT` = `pivot_x, pivot_y, pivot_z` (m, the base of
//!   the vertex's stem), `level` (0 trunk, 1, 2, 3); `_WIND_PARAMS` = `phase` (0..1, per stem),
//!   `stiffness` (0..1, 1 = rigid trunk base), `distance` (m, path length from the root),
//!   `radius` (m). Component `k` of an attribute decodes as `offset[k] + scale[k] · q / 65535`
//!   (`q` the stored integer; `q / 65535` is what a GPU reads from a normalised attribute), with
//!   `offset` and `scale` in the bark mesh's `extras.wind_attributes` (next to a description of
//!   the fields): the pivot, distance and radius span the mesh's range (a step of 0.46 mm per
//!   30 m of range), `level` spans 0..3 (levels are exactly 0, 21845, 43690, 65535), `phase` and
//!   `stiffness` 0..1 (`WindCodec`). Custom attribute names start with `_` as glTF requires;
//!   three.js's GLTFLoader loads them as `_wind_pivot` and `_wind_params` geometry attributes
//!   (normalised) and the mesh's extras as `userData`.
//! * **Leaves**, [`LeafMode::Instanced`]: the leaf mesh (leaf units) on a node with
//!   `EXT_mesh_gpu_instancing` (`TRANSLATION`, `ROTATION`, `SCALE` decomposed from the foliage
//!   matrices, `_COLOR_0` the per-leaf RGB tint, float, as three.js reads it into
//!   `instanceColor`). The extension is listed in `extensionsUsed` but not required: a viewer
//!   without it shows the single leaf mesh at the origin. [`LeafMode::Baked`] (the file for
//!   editors, which import the extension as one object per leaf): all leaves transformed into
//!   one mesh (`baked.rs`) with the tint as `COLOR_0` (RGBA8, divided per channel by the tints'
//!   largest value over 1, which the leaf texture takes: `bake::tint_scale`) and, with
//!   wind, each leaf's twig's wind record, coded as the bark's (the bark's codec and
//!   `extras`); indices `u32` past 65,535 vertices, as the bark's.
//! * **Flowers, fruit, catkins and buds** (`organs.rs`, [`crate::organs`]): after the leaves,
//!   one node, mesh and material per organ set, named after the set (`"acorns"`), with the
//!   set's colour as `baseColorFactor` (linear), its roughness and `doubleSided`; instanced as
//!   the leaves are (`_COLOR_0` = the per-instance tints) or, where the leaves are baked, baked
//!   with the tints as `COLOR_0`. Left out with [`LeafMode::None`] and from the growth
//!   animation. Their materials come after the others, so a tree without parts (every preset
//!   in July) keeps every index and byte.
//! * **Materials** (metallic-roughness, metallic 0; `materials.rs`): `bark` (roughness 0.9, bark colour map,
//!   bark normal map, textures REPEAT-wrapped: bark UVs run past 1 along the stems); `leaves`
//!   (roughness 0.7, leaf colour map with `alphaMode` MASK, cutoff 0.5, `doubleSided`, leaf
//!   normal map, CLAMP_TO_EDGE); and, only when the bark has a [`Material::CutFace`] group (a
//!   cut stem), `cut_face` last (roughness 0.85, the end-grain colour and normal maps of
//!   [`crate::mesh::bark::end_grain`] in the faces' disc UVs, CLAMP_TO_EDGE, opaque), which the
//!   bark mesh's cut-face primitive uses. Without textures the base colours are plain factors.
//!   Images: PNG in buffer views ([`super::png`]); row 0 of a baked texture is `v = 0`, which
//!   is the top of a glTF image, so UVs are written unchanged.
//!
//! ## Determinism
//!
//! `asset.generator` is `"Sylva <version>"`; `scene.extras.sylva_hash` is the tree's content
//! hash. The JSON is built with `serde_json` maps (sorted keys), floats are written from `f64`
//! so an `f32` min/max reads back exactly: equal trees give equal bytes.
//!
//! ## Writing
//!
//! The JSON is laid out first, then the output is sized at once (a reused buffer
//! keeps its bytes, a new one comes zeroed from the allocator, no fill) and every byte of it is
//! written once: the header and JSON, the padding, and each view into its own region. Views of
//! 256 KiB or more are split into as many parts as there are threads ([`crate::par`], one in
//! wasm), each part a range of the view's items (vertices, values, matrices) written on its
//! own; no byte depends on the split, so any number of threads writes the same file. Float and
//! index arrays are one `memcpy` per part (a `memory.copy` in wasm); nothing else is buffered
//! except the tangent sums of the vertices on no tube ring. The colours and the wind share one
//! pass over the wind records. The bounds and the wind ranges are found in one pass split the
//! same way, with plain comparisons; square roots are IEEE ones: no libm calls, which are
//! function calls in wasm. [`write_into`] reuses the caller's allocation.
//!
//! ## Code
//!
//! This file lays the file out (`write_into`, `assemble`); `doc.rs` builds the JSON
//! (views, accessors, meshes), `data.rs` holds the BIN chunk's arrays and their encoders.

mod baked;
mod data;
mod doc;
mod growth;
mod materials;
pub mod merge;
mod organs;

use super::options::{ExportOptions, LeafMode};
use super::textures::TexturePngs;
use crate::foliage::Foliage;
use crate::mesh::{merge_ranges, ranges, Bounds, Material, TreeMesh, WIND_STRIDE};
use crate::Generated;
use data::{Data, Part, WindCodec};
use doc::{Acc, Colors, Doc, VertexExtras};
use materials::{material, BARK, CUT_FACE, LEAVES};
use serde_json::{json, Map, Value};
use std::ops::Range;
use std::sync::Arc;

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const BYTE: u32 = 5120;
const UNSIGNED_BYTE: u32 = 5121;
const UNSIGNED_SHORT: u32 = 5123;
const UNSIGNED_INT: u32 = 5125;
const FLOAT: u32 = 5126;
const LINEAR: u32 = 9729;
const LINEAR_MIPMAP_LINEAR: u32 = 9987;
const REPEAT: u32 = 10497;
const CLAMP_TO_EDGE: u32 = 33071;

/// GLB magic `glTF`, chunk types `JSON` and `BIN\0` (little-endian u32).
const MAGIC: u32 = 0x4654_6c67;
const CHUNK_JSON: u32 = 0x4e4f_534a;
const CHUNK_BIN: u32 = 0x004e_4942;

/// Description of the wind attributes, stored in the bark mesh's `extras`.
const WIND_PIVOT_DOC: &str = "pivot_x, pivot_y, pivot_z (m, base of the vertex's stem), level (0 trunk, 1, 2, 3)";
const WIND_DECODE_DOC: &str = "both attributes are normalized unsigned shorts: component k = offset[k] + scale[k] * (q / 65535), q the stored integer (what a GPU reads as 0..1 times scale, plus offset)";
const WIND_PARAMS_DOC: &str =
    "phase (0..1, per stem), stiffness (0..1, 1 = rigid trunk base), distance (m, path length from the root), radius (m)";
/// Everything computed (not borrowed from the tree) before the document is laid out.
struct Owned {
    bark_pngs: Option<Arc<TexturePngs>>,
    leaf_pngs: Option<Arc<TexturePngs>>,
    grain_pngs: Option<Arc<TexturePngs>>,
    baked: Option<super::bake::BakedLeaves>,
    leaf_tangents: Option<Vec<f32>>,
    /// The bark's tangents as floats ([`super::mesh_tangents`]), for [`ExportOptions::strict`].
    bark_tangents: Option<Vec<f32>>,
}

/// The GLB file of a generated tree (layout: module docs).
pub fn write(g: &Generated, opts: &ExportOptions) -> Vec<u8> {
    let mut out = Vec::new();
    write_into(g, opts, &mut out);
    out
}

/// [`write()`] into `out` (its contents replaced), reusing its allocation: repeated exports of
/// big trees into the same `Vec` skip the operating system's zeroing of fresh pages.
pub fn write_into(g: &Generated, opts: &ExportOptions, out: &mut Vec<u8>) {
    write_into_threads(g, opts, out, crate::par::threads());
}

/// [`write_into`] on at most `threads` threads ([`crate::par`]): the same bytes on any number.
pub fn write_into_threads(g: &Generated, opts: &ExportOptions, out: &mut Vec<u8>, threads: usize) {
    write_with(g, opts, out, threads, None);
}

/// The GLB of `g` with its growth animation ([`crate::export::growth`]; docs/formats.md,
/// "Growth animation"): `g` generated at Age `age` with Mature Age `mature`. Leaves are baked
/// (instances cannot morph; `LeafMode::None` leaves them out); everything else follows `opts`
/// as in [`write()`], plus morph targets on the bark and leaf meshes and one animation, `growth`,
/// from year 0 to `age` at one second a year.
pub fn write_growth(g: &Generated, opts: &ExportOptions, age: f32, mature: f32) -> Vec<u8> {
    let mut out = Vec::new();
    write_with(g, opts, &mut out, crate::par::threads(), Some((age, mature)));
    out
}

/// [`write_into_threads`], with the growth animation of a tree built at `growth` = (Age, Mature
/// Age) when given.
fn write_with(g: &Generated, opts: &ExportOptions, out: &mut Vec<u8>, threads: usize, growth: Option<(f32, f32)>) {
    let bark = &g.mesh;
    let f = &g.foliage;
    let has_bark = bark.vertex_count() > 0 && !bark.indices.is_empty();
    // Instancing is an extension: a strict file bakes the leaves, and so does a growing one.
    let bake = (opts.strict || growth.is_some()) && opts.leaves == LeafMode::Instanced;
    let leaves = if bake { LeafMode::Baked } else { opts.leaves };
    let has_leaves = leaves != LeafMode::None && f.count() > 0 && !f.mesh.indices.is_empty();
    let normal_maps = opts.textures && opts.normal_maps;
    // Tangents only for the normal maps, and only when asked for.
    let tangents = normal_maps && opts.tangents;
    let instanced = has_leaves && leaves == LeafMode::Instanced;
    // Baked colours are bytes: tints over 1 (autumn) move into the texture (`tint_scale`).
    let scale = if has_leaves && leaves == LeafMode::Baked { super::bake::tint_scale(f) } else { [1.0; 3] };
    let leaf_pngs = if opts.textures && has_leaves { super::textures::leaf_pngs_scaled(f, scale) } else { None };
    let has_cut = has_bark && bark.groups.iter().any(|g| g.material == Material::CutFace && g.count > 0);
    let owned = Owned {
        bark_pngs: (has_bark && opts.textures).then(|| super::textures::bark_pngs(g.bark, opts.bark_texture_size)),
        grain_pngs: (has_cut && opts.textures).then(|| super::textures::end_grain_pngs(g.bark, opts.bark_texture_size)),
        baked: (has_leaves && leaves == LeafMode::Baked)
            .then(|| baked::bake(g, tangents && leaf_pngs.is_some(), opts.wind && has_bark, threads, scale)),
        leaf_tangents: (instanced && tangents && leaf_pngs.is_some())
            .then(|| super::frames::tangents(&f.mesh.positions, &f.mesh.normals, &f.mesh.uvs, &f.mesh.indices)),
        bark_tangents: (opts.strict && has_bark && tangents && opts.textures)
            .then(|| super::frames::mesh_tangents(bark)),
        leaf_pngs,
    };
    // The parts follow the leaves' mode; a growing file has none (they could not grow).
    let organ_sets = if growth.is_some() { Vec::new() } else { super::organs::exported(g, opts) };
    let organs_baked = leaves == LeafMode::Baked;
    let baked_sets: Vec<_> =
        if organs_baked { organ_sets.iter().map(|s| super::organs::bake_set(s)).collect() } else { Vec::new() };
    let morphs = growth.map(|(age, mature)| growth::morphs(g, owned.baked.as_ref(), age, mature, threads));
    let mut doc = Doc { strict: opts.strict, ..Doc::default() };
    let samplers = json!([
        {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": REPEAT, "wrapT": REPEAT},
        {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": CLAMP_TO_EDGE, "wrapT": CLAMP_TO_EDGE},
    ]);
    let mut children = Vec::new();
    let mut used_samplers = [false; 2];
    let bark_material =
        has_bark.then(|| material(&mut doc, &BARK, owned.bark_pngs.as_deref(), normal_maps, &mut used_samplers));
    let leaf_material = (has_leaves || bark.groups.iter().any(|g| g.material == Material::Leaves))
        .then(|| material(&mut doc, &LEAVES, owned.leaf_pngs.as_deref(), normal_maps, &mut used_samplers));
    // Last, so that a tree without a cut keeps every index (and byte) it had.
    let cut_material =
        has_cut.then(|| material(&mut doc, &CUT_FACE, owned.grain_pngs.as_deref(), normal_maps, &mut used_samplers));
    let pick = |m: Material| match m {
        Material::CutFace => cut_material.or(bark_material).or(leaf_material).unwrap_or(0),
        Material::Bark => bark_material.or(leaf_material).unwrap_or(0),
        // The bark mesh never carries organ groups; organs get their own materials.
        Material::Leaves | Material::Organ => leaf_material.or(bark_material).unwrap_or(0),
    };
    let mut bark_wind = None;
    if has_bark {
        let wind = opts.wind && bark.wind.len() == bark.vertex_count() * WIND_STRIDE;
        let (bounds, wind) = bark_ranges(bark, wind, threads);
        bark_wind = wind;
        let extra = VertexExtras {
            tangents: (tangents && owned.bark_pngs.is_some())
                .then(|| owned.bark_tangents.as_deref().map_or(Data::Frames(bark), Data::F32)),
            colors: opts.vertex_colors.then_some(Colors::Bark(bounds)),
            wind,
            bounds: Some(bounds),
        };
        let mesh = doc.mesh("bark", bark, &extra, pick);
        if let Some(m) = &morphs {
            growth::targets(&mut doc, mesh, &m.bark, &m.years);
        }
        doc.nodes.push(json!({"name": "bark", "mesh": mesh}));
        children.push(doc.nodes.len());
    }
    if let Some(b) = &owned.baked {
        let extra = VertexExtras {
            tangents: (!b.tangents.is_empty()).then_some(Data::FramesOf(&b.mesh.normals, &b.tangents)),
            colors: opts.vertex_colors.then_some(Colors::Bytes(&b.colors)),
            // Copies of bark records: the bark's codec covers them, and a leaf's quantised
            // record is its twig's.
            wind: bark_wind.filter(|_| !b.mesh.wind.is_empty()),
            bounds: None,
        };
        let mesh = doc.mesh("leaves", &b.mesh, &extra, pick);
        if let Some(m) = morphs.as_ref().filter(|m| !m.leaves.is_empty()) {
            growth::targets(&mut doc, mesh, &m.leaves, &m.years);
        }
        doc.nodes.push(json!({"name": "leaves", "mesh": mesh}));
        children.push(doc.nodes.len());
    }
    if instanced {
        let mesh = doc.mesh("leaf", &f.mesh, &extra_of(owned.leaf_tangents.as_deref(), f), |_| pick(Material::Leaves));
        instanced_leaves_node(&mut doc, f, mesh, opts.vertex_colors);
        children.push(doc.nodes.len());
    }
    if organs_baked {
        organs::baked(&mut doc, &baked_sets, opts.vertex_colors, &mut children);
    } else {
        organs::instanced(&mut doc, &organ_sets, opts.vertex_colors, &mut children);
    }
    if let Some(m) = &morphs {
        growth::animation(&mut doc, &children, m);
    }
    let instancing = instanced || (!organs_baked && !organ_sets.is_empty());
    assemble(doc, g, samplers, used_samplers, instancing, children, out, threads);
}

/// The instanced leaf mesh's extra vertex data: its tangents, when computed.
fn extra_of<'a>(tangents: Option<&'a [f32]>, f: &'a Foliage) -> VertexExtras<'a> {
    VertexExtras { tangents: tangents.map(|t| Data::FramesOf(&f.mesh.normals, t)), ..VertexExtras::default() }
}

/// The node drawing `mesh` once per leaf through `EXT_mesh_gpu_instancing` (translation,
/// rotation, scale and, with `colors`, the leaf tint as `_COLOR_0`).
fn instanced_leaves_node<'a>(doc: &mut Doc<'a>, f: &'a Foliage, mesh: usize, colors: bool) {
    let m = &f.matrices[..];
    let n = f.count();
    let mut attrs = Map::new();
    let mut trs = |key: &str, part: Part, kind: &'static str| {
        attrs.insert(key.into(), json!(doc.array(Data::Trs(m, part), None, Acc::new(FLOAT, kind, n))));
    };
    trs("TRANSLATION", Part::Translation, "VEC3");
    trs("ROTATION", Part::Rotation, "VEC4");
    trs("SCALE", Part::Scale, "VEC3");
    if colors {
        attrs.insert("_COLOR_0".into(), json!(doc.array(Data::F32(&f.colors), None, Acc::new(FLOAT, "VEC3", n))));
    }
    doc.nodes.push(json!({
        "name": "leaves",
        "mesh": mesh,
        "extensions": {"EXT_mesh_gpu_instancing": {"attributes": Value::Object(attrs)}},
    }));
}

/// The bark's bounds and, when `wind`, the codec of its wind data: one pass over the positions
/// and the wind records, split between the threads (smallest and largest values are the same
/// whichever way the vertices are split).
fn bark_ranges(bark: &TreeMesh, wind: bool, threads: usize) -> (Bounds, Option<WindCodec>) {
    let parts = crate::par::ranges(bark.vertex_count(), threads);
    let scans = crate::par::map(parts, threads, |r| {
        let b = Bounds::of(&bark.positions[3 * r.start..3 * r.end]);
        let w = wind.then(|| ranges::<WIND_STRIDE>(&bark.wind[WIND_STRIDE * r.start..WIND_STRIDE * r.end]));
        ((b.min, b.max), w)
    });
    let mut bounds = None;
    let mut w = None;
    for (b, r) in scans {
        bounds = Some(bounds.map_or(b, |a| merge_ranges(a, b)));
        w = r.map(|r| w.map_or(r, |a| merge_ranges(a, r)));
    }
    let (min, max) = bounds.unwrap_or_default();
    (Bounds { min, max }, w.map(|(lo, hi)| WindCodec::over(lo, hi)))
}

/// Lays out the JSON and the BIN chunk and writes the GLB bytes.
#[allow(clippy::too_many_arguments, reason = "the parts `write` built, each used once here")]
fn assemble(
    doc: Doc<'_>,
    g: &Generated,
    samplers: Value,
    used_samplers: [bool; 2],
    instanced: bool,
    children: Vec<usize>,
    out: &mut Vec<u8>,
    threads: usize,
) {
    let mut root = Map::new();
    root.insert("asset".into(), json!({"version": "2.0", "generator": format!("Sylva {}", crate::VERSION)}));
    root.insert("scene".into(), json!(0));
    root.insert("scenes".into(), json!([{"name": "Sylva", "nodes": [0], "extras": {"sylva_hash": g.hash_hex()}}]));
    let mut nodes = vec![json!({"name": "sylva_tree", "children": children})];
    nodes.extend(doc.nodes);
    root.insert("nodes".into(), Value::Array(nodes));
    if !doc.meshes.is_empty() {
        root.insert("meshes".into(), Value::Array(doc.meshes));
    }
    if !doc.materials.is_empty() {
        root.insert("materials".into(), Value::Array(doc.materials));
    }
    if !doc.textures.is_empty() {
        // Keep sampler indices stable: write both when any texture uses the clamped one.
        let keep = if used_samplers[1] { 2 } else { 1 };
        let s: Vec<Value> = samplers.as_array().map(|a| a[..keep].to_vec()).unwrap_or_default();
        root.insert("samplers".into(), Value::Array(s));
        root.insert("images".into(), Value::Array(doc.images));
        root.insert("textures".into(), Value::Array(doc.textures));
    }
    if !doc.animations.is_empty() {
        root.insert("animations".into(), Value::Array(doc.animations));
    }
    if !doc.accessors.is_empty() {
        root.insert("accessors".into(), Value::Array(doc.accessors));
        root.insert("bufferViews".into(), Value::Array(doc.views));
        root.insert("buffers".into(), json!([{"byteLength": doc.bin_len}]));
    }
    let mut used = Vec::new();
    if instanced {
        used.push("EXT_mesh_gpu_instancing");
    }
    if doc.quantized {
        used.push("KHR_mesh_quantization");
        root.insert("extensionsRequired".into(), json!(["KHR_mesh_quantization"]));
    }
    if !used.is_empty() {
        root.insert("extensionsUsed".into(), json!(used));
    }
    let json = Value::Object(root).to_string();
    let json_len = json.len().next_multiple_of(4);
    let bin_len = doc.bin_len.next_multiple_of(4);
    let has_bin = doc.bin_len > 0;
    let total = 12 + 8 + json_len + if has_bin { 8 + bin_len } else { 0 };
    let bin_start = 12 + 8 + json_len + 8;
    let mut header = Vec::with_capacity(bin_start);
    let mut word = |w: u32| header.extend_from_slice(&w.to_le_bytes());
    word(MAGIC);
    word(2);
    word(total as u32);
    word(json_len as u32);
    word(CHUNK_JSON);
    header.extend_from_slice(json.as_bytes());
    header.resize(20 + json_len, b' ');
    if has_bin {
        header.extend_from_slice(&(bin_len as u32).to_le_bytes());
        header.extend_from_slice(&CHUNK_BIN.to_le_bytes());
    }
    resize_for_overwrite(out, total);
    let (head, bin) = out.split_at_mut(header.len());
    head.copy_from_slice(&header);
    // The BIN chunk: each view's region split into parts for the threads, the padding zeroed.
    let mut jobs = Vec::new();
    let (mut rest, mut at) = (bin, 0);
    for &(offset, d) in &doc.data {
        let (pad, r) = rest.split_at_mut(offset - at);
        pad.fill(0);
        let (region, r) = r.split_at_mut(d.byte_len());
        (rest, at) = (r, offset + d.byte_len());
        let parts = if d.byte_len() < MIN_SPLIT_BYTES { 1 } else { threads.max(1) };
        split(d, region, parts, &mut jobs);
    }
    rest.fill(0);
    crate::par::run(jobs, threads, |(d, items, out)| d.write(items, out));
}

/// Views smaller than this are written by one thread.
const MIN_SPLIT_BYTES: usize = 1 << 18;

/// A part of a view for one thread: the data, a range of its items, and where they go (one
/// slice per plane, [`Data::widths`]).
type Job<'a, 'o> = (Data<'a>, Range<usize>, [&'o mut [u8]; 2]);

/// Adds the jobs writing `d` into `region` (its bytes, [`Data::byte_len`]) in `parts` parts of
/// about equal item counts.
fn split<'a, 'o>(d: Data<'a>, region: &'o mut [u8], parts: usize, jobs: &mut Vec<Job<'a, 'o>>) {
    let ([wa, wb], n) = (d.widths(), d.items());
    let (mut a, mut b) = region.split_at_mut(n * wa);
    for p in 0..parts {
        let items = n * p / parts..n * (p + 1) / parts;
        let (pa, ra) = std::mem::take(&mut a).split_at_mut(items.len() * wa);
        let (pb, rb) = std::mem::take(&mut b).split_at_mut(items.len() * wb);
        (a, b) = (ra, rb);
        jobs.push((d, items, [pa, pb]));
    }
}

/// Makes `out` `total` bytes long for the writers to overwrite every byte of: a fresh zeroed
/// allocation (pages the operating system zeroes as they are first touched, no fill) when its
/// capacity is short, else its allocation and old bytes kept (only what lies past its old
/// length zeroed).
fn resize_for_overwrite(out: &mut Vec<u8>, total: usize) {
    if out.capacity() < total {
        *out = vec![0; total];
    } else {
        out.truncate(total);
        out.resize(total, 0);
    }
}
