//! glTF 2.0 binary (GLB) writer, following the Khronos glTF 2.0 specification (§3 concepts,
//! §4.4 GLB file format) and the `EXT_mesh_gpu_instancing` extension.
//!
//! **File layout**: 12-byte header (`glTF`, version 2, total length), a JSON chunk padded with
//! spaces to 4 bytes, a BIN chunk padded with zeros to 4 bytes. One buffer (the BIN chunk);
//! every buffer view starts on a 4-byte boundary and holds one tightly packed array, except the
//! normal views (`byteStride` 4: three bytes and one of padding, or 8 with the tangent) and the
//! wind view (below). Vertex views have `target` 34962 (ARRAY_BUFFER), index views 34963
//! (ELEMENT_ARRAY_BUFFER); image and instancing views have none.
//!
//! **Scene**: node 0 `sylva_tree` (identity) with children `bark` and `leaves`.
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
//!   straight into the output ([`super::frames_snorm8_append`]): on the mesh's tube rings
//!   (`TreeMesh::rings`, nearly every bark vertex) from the ring neighbours, elsewhere by
//!   Lengyel's method over the triangles touching those vertices ([`super::mesh_tangents`]).
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
//!   without it shows the single leaf mesh at the origin. [`LeafMode::Baked`]: all leaves
//!   transformed into one mesh ([`super::bake_leaves`]) with the tint as `COLOR_0`.
//! * **Materials** (metallic-roughness, metallic 0): `bark` (roughness 0.9, bark colour map,
//!   bark normal map, textures REPEAT-wrapped: bark UVs run past 1 along the stems); `leaves`
//!   (roughness 0.7, leaf colour map with `alphaMode` MASK, cutoff 0.5, `doubleSided`, leaf
//!   normal map, CLAMP_TO_EDGE). Without textures the base colours are plain factors.
//!   Images: PNG in buffer views ([`super::png`]); row 0 of a baked texture is `v = 0`, which
//!   is the top of a glTF image, so UVs are written unchanged.
//!
//! `asset.generator` is `"Sylva <version>"`; `scene.extras.sylva_hash` is the tree's content
//! hash. The JSON is built with `serde_json` maps (sorted keys), floats are written from `f64`
//! so an `f32` min/max reads back exactly: equal trees give equal bytes.
//!
//! **Writing**: one pass per view, appended in order into a buffer reserved at its final size:
//! float and index arrays as one `memcpy` each (a `memory.copy` in wasm), the rest through a
//! small stack block (no zero fill of the big arrays and no temporary arrays, except the tangent
//! sums of the vertices on no tube ring and the colours, zeroed in the output itself); the
//! colours and the wind share one pass over the wind records. Ranges (bounds, wind) are found with plain comparisons and
//! square roots are IEEE ones: no libm calls, which are function calls in wasm.
//! [`write_into`] reuses the caller's allocation.

use super::quant::{Unorm16, LANES};
use super::{ExportOptions, LeafMode, TexturePngs};
use crate::mesh::{Bounds, Material, TreeMesh, WIND_STRIDE};
use crate::Generated;
use serde_json::{json, Map, Value};
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

/// A borrowed array for the BIN chunk.
#[derive(Clone, Copy)]
enum Data<'a> {
    F32(&'a [f32]),
    U32(&'a [u32]),
    /// `u32` values written as `u16` (all known to fit).
    U16(&'a [u32]),
    Bytes(&'a [u8]),
    /// Unit vectors (3 floats each) as normalised `i8` `VEC3` padded to 4 bytes
    /// ([`super::normals_snorm8_append`]).
    Snorm3(&'a [f32]),
    /// Normals and tangents of a mesh interleaved, 8 bytes per vertex: the normal as in
    /// [`Data::Snorm3`], then the tangent (computed into the output,
    /// [`super::frames_snorm8_append`]) as a normalised `i8` `VEC4`.
    Frames(&'a TreeMesh),
    /// [`Data::Frames`] from given normals (3 floats each) and tangents (4 floats, `w` = ±1).
    FramesOf(&'a [f32], &'a [f32]),
    /// The bark's colours (4 bytes per vertex, [`super::BarkTint`], when `Some(bounds)`)
    /// followed by its wind data (16 bytes per vertex, [`WindCodec`], when `Some`): two views
    /// written in one pass over the wind records.
    BarkExtras(&'a TreeMesh, Option<Bounds>, Option<WindCodec>),
    /// Instance matrices (16 floats each) decomposed ([`super::decompose`]) into the output:
    /// translation (`VEC3`), rotation (`VEC4`) or scale (`VEC3`).
    Trs(&'a [f32], Part),
}

/// Which part of a decomposed matrix [`Data::Trs`] writes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Part {
    Translation,
    Rotation,
    Scale,
}

/// Bytes of the stack block the writers fill before appending it to the output.
const BLOCK: usize = 4096;

/// Appends `f(item)`, `W` bytes per item of `E` values of `src`, to `out` through a stack block:
/// `out` only ever grows by copies of written bytes (no zero fill, one pass over the data).
#[inline(always)]
fn emit<T: Copy, const E: usize, const W: usize>(out: &mut Vec<u8>, src: &[T], f: impl Fn(&[T; E]) -> [u8; W]) {
    let per = BLOCK / W;
    let mut block = [0u8; BLOCK];
    for c in src.chunks(per * E) {
        let k = c.len() / E;
        for (d, x) in block[..k * W].chunks_exact_mut(W).zip(c.chunks_exact(E)) {
            let x: &[T; E] = x.try_into().expect("E values");
            d.copy_from_slice(&f(x));
        }
        out.extend_from_slice(&block[..k * W]);
    }
}

/// Appends 4-byte words as little-endian bytes: one `memcpy` (a `memory.copy` in wasm) of the
/// array's bytes on little-endian targets, a loop over the values elsewhere.
#[inline(always)]
fn copy_words<T: bytemuck::Pod>(out: &mut Vec<u8>, src: &[T], le: impl Fn(T) -> [u8; 4]) {
    if cfg!(target_endian = "little") {
        out.extend_from_slice(bytemuck::cast_slice(src));
    } else {
        for x in src {
            out.extend_from_slice(&le(*x));
        }
    }
}

/// `N` floats as little-endian bytes (`B` = 4 `N`).
#[inline(always)]
fn le<const N: usize, const B: usize>(v: [f32; N]) -> [u8; B] {
    let mut o = [0u8; B];
    for (d, x) in o.chunks_exact_mut(4).zip(v) {
        d.copy_from_slice(&x.to_le_bytes());
    }
    o
}

/// The `u16` encodings of the 8 wind values of a mesh (`TreeMesh::wind`): `pivot_x`, `pivot_y`,
/// `pivot_z`, `distance` and `radius` over the range the mesh's values span; `level` over 0..3
/// (levels 0, 1, 2, 3 are exactly 0, 21845, 43690, 65535), `phase` and `stiffness` over 0..1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct WindCodec(pub [Unorm16; WIND_STRIDE]);

impl WindCodec {
    /// The codec of `wind` (8 floats per vertex): one pass for the ranges. Every value lies in
    /// its component's range, so the encoding never clamps: the fixed ranges are used only when
    /// the data fits them (they always do for the generator's meshes), else the data's range.
    pub fn of(wind: &[f32]) -> WindCodec {
        let (lo, hi) = super::ranges::<WIND_STRIDE>(wind);
        let fixed = |k: usize, max: f32| {
            if lo[k] >= 0.0 && hi[k] <= max {
                Unorm16 { offset: 0.0, scale: max }
            } else {
                Unorm16::over(lo[k], hi[k])
            }
        };
        let data = |k: usize| Unorm16::over(lo[k], hi[k]);
        WindCodec([data(0), data(1), data(2), fixed(3, 3.0), fixed(4, 1.0), fixed(5, 1.0), data(6), data(7)])
    }

    /// `offset` and `scale` of components `k..k + 4` as JSON.
    fn json(&self, k: usize) -> Value {
        let c = &self.0[k..k + 4];
        json!({
            "offset": floats(&c.iter().map(|e| e.offset).collect::<Vec<_>>()),
            "scale": floats(&c.iter().map(|e| e.scale).collect::<Vec<_>>()),
        })
    }
}

impl Data<'_> {
    fn byte_len(&self) -> usize {
        match self {
            Data::F32(s) => s.len() * 4,
            Data::U32(s) => s.len() * 4,
            Data::U16(s) => s.len() * 2,
            Data::Bytes(s) => s.len(),
            Data::Snorm3(s) => s.len() / 3 * 4,
            Data::Frames(m) => m.vertex_count() * 8,
            Data::FramesOf(n, _) => n.len() / 3 * 8,
            Data::BarkExtras(m, colors, wind) => {
                m.vertex_count() * (if colors.is_some() { 4 } else { 0 } + if wind.is_some() { 16 } else { 0 })
            }
            Data::Trs(m, part) => m.len() / 16 * if *part == Part::Rotation { 16 } else { 12 },
        }
    }

    /// Appends the little-endian bytes to `out`.
    fn append(&self, out: &mut Vec<u8>) {
        match *self {
            Data::F32(s) => copy_words(out, s, f32::to_le_bytes),
            Data::U32(s) => copy_words(out, s, u32::to_le_bytes),
            Data::U16(s) => emit::<_, 1, 2>(out, s, |v| (v[0] as u16).to_le_bytes()),
            Data::Bytes(s) => out.extend_from_slice(s),
            Data::Snorm3(s) => super::normals_snorm8_append(s, out),
            Data::Frames(m) => super::frames_snorm8_append(m, out),
            Data::FramesOf(n, t) => super::frames_of_snorm8_append(n, t, out),
            Data::BarkExtras(m, colors, wind) => bark_extras_append(m, colors, wind, out),
            Data::Trs(m, Part::Translation) => emit::<_, 16, 12>(out, m, |m| le([m[12], m[13], m[14]])),
            Data::Trs(m, Part::Rotation) => emit::<_, 16, 16>(out, m, |m| le(super::decompose_rotation(m))),
            Data::Trs(m, Part::Scale) => emit::<_, 16, 12>(out, m, |m| le(super::decompose_scale(m))),
        }
    }
}

/// [`Data::BarkExtras`]: the colours are written into their (zeroed) view block by block while
/// the wind records of the same block are appended after it, so the wind array is read once.
fn bark_extras_append(m: &TreeMesh, colors: Option<Bounds>, wind: Option<WindCodec>, out: &mut Vec<u8>) {
    let n = m.vertex_count();
    let tint = colors.map(|b| super::BarkTint::new(m, &b));
    let at = out.len();
    if tint.is_some() {
        out.resize(at + 4 * n, 0);
    }
    let w = if m.wind.len() == n * WIND_STRIDE { &m.wind[..] } else { &[][..] };
    let codec = wind.map(|c| (c.0.map(|e| e.offset), c.0.map(|e| e.factor())));
    let mut block = [0u8; 16 * LANES];
    let mut base = 0;
    while base < n {
        let k = LANES.min(n - base);
        if let Some(t) = &tint {
            t.write(m, base, &mut out[at + 4 * base..at + 4 * (base + k)]);
        }
        if let Some((offset, factor)) = &codec {
            let rec = w[WIND_STRIDE * base..WIND_STRIDE * (base + k)].chunks_exact(WIND_STRIDE);
            for (d, r) in block.chunks_exact_mut(16).zip(rec) {
                for c in 0..WIND_STRIDE {
                    d[2 * c..2 * c + 2].copy_from_slice(&Unorm16::encode(offset[c], factor[c], r[c]).to_le_bytes());
                }
            }
            out.extend_from_slice(&block[..16 * k]);
        }
        base += k;
    }
}

/// The glTF document under construction: JSON arrays plus the views' data, laid out as added.
#[derive(Default)]
struct Doc<'a> {
    data: Vec<(usize, Data<'a>)>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    images: Vec<Value>,
    textures: Vec<Value>,
    materials: Vec<Value>,
    meshes: Vec<Value>,
    nodes: Vec<Value>,
    bin_len: usize,
    /// Whether an accessor needs `KHR_mesh_quantization`.
    quantized: bool,
}

/// One accessor's description.
struct Acc {
    component: u32,
    kind: &'static str,
    count: usize,
    normalized: bool,
    offset: usize,
    minmax: Option<(Vec<f32>, Vec<f32>)>,
}

impl Acc {
    fn new(component: u32, kind: &'static str, count: usize) -> Acc {
        Acc { component, kind, count, normalized: false, offset: 0, minmax: None }
    }
}

fn floats(v: &[f32]) -> Value {
    Value::Array(v.iter().map(|&x| json!(f64::from(x))).collect())
}

impl<'a> Doc<'a> {
    /// Adds `d` to the BIN chunk (4-byte aligned); returns its offset.
    fn data(&mut self, d: Data<'a>) -> usize {
        let offset = self.bin_len.next_multiple_of(4);
        self.bin_len = offset + d.byte_len();
        self.data.push((offset, d));
        offset
    }

    /// Adds a buffer view of `len` bytes at `offset`; returns its index.
    fn view_at(&mut self, offset: usize, len: usize, target: Option<u32>, stride: Option<usize>) -> usize {
        let mut v = Map::new();
        v.insert("buffer".into(), json!(0));
        v.insert("byteOffset".into(), json!(offset));
        v.insert("byteLength".into(), json!(len));
        if let Some(s) = stride {
            v.insert("byteStride".into(), json!(s));
        }
        if let Some(t) = target {
            v.insert("target".into(), json!(t));
        }
        self.views.push(Value::Object(v));
        self.views.len() - 1
    }

    /// Adds a buffer view (4-byte aligned) holding `d`; returns its index.
    fn view(&mut self, d: Data<'a>, target: Option<u32>, stride: Option<usize>) -> usize {
        let len = d.byte_len();
        let offset = self.data(d);
        self.view_at(offset, len, target, stride)
    }

    fn accessor(&mut self, view: usize, a: Acc) -> usize {
        let mut v = Map::new();
        v.insert("bufferView".into(), json!(view));
        if a.offset > 0 {
            v.insert("byteOffset".into(), json!(a.offset));
        }
        v.insert("componentType".into(), json!(a.component));
        v.insert("count".into(), json!(a.count));
        v.insert("type".into(), json!(a.kind));
        if a.normalized {
            v.insert("normalized".into(), json!(true));
        }
        if let Some((min, max)) = a.minmax {
            v.insert("min".into(), floats(&min));
            v.insert("max".into(), floats(&max));
        }
        self.accessors.push(Value::Object(v));
        self.accessors.len() - 1
    }

    /// A view plus one accessor over all of it.
    fn array(&mut self, d: Data<'a>, target: Option<u32>, a: Acc) -> usize {
        let view = self.view(d, target, None);
        self.accessor(view, a)
    }

    /// An embedded PNG image and a texture sampling it with `sampler`; returns the texture index.
    fn texture(&mut self, png: &'a [u8], name: &str, sampler: usize) -> usize {
        let view = self.view(Data::Bytes(png), None, None);
        self.images.push(json!({"bufferView": view, "mimeType": "image/png", "name": name}));
        self.textures.push(json!({"sampler": sampler, "source": self.images.len() - 1, "name": name}));
        self.textures.len() - 1
    }

    /// The vertex attributes of a mesh (shared by its primitives).
    fn attributes(&mut self, m: &'a TreeMesh, extra: &VertexExtras<'a>) -> Map<String, Value> {
        let n = m.vertex_count();
        let b = extra.bounds.unwrap_or_else(|| super::bounds_of(&m.positions));
        let mut at = Map::new();
        let pos = Acc { minmax: Some((b.min.to_vec(), b.max.to_vec())), ..Acc::new(FLOAT, "VEC3", n) };
        at.insert("POSITION".into(), json!(self.array(Data::F32(&m.positions), Some(ARRAY_BUFFER), pos)));
        // KHR_mesh_quantization: normals and tangents as normalised bytes, interleaved when
        // both are written (normal 3 bytes + 1 padding, tangent 4), else the normals alone.
        self.quantized = true;
        let (view, stride) = match extra.tangents {
            Some(t) => (self.view(t, Some(ARRAY_BUFFER), Some(8)), 8),
            None => (self.view(Data::Snorm3(&m.normals), Some(ARRAY_BUFFER), Some(4)), 4),
        };
        let normal = Acc { normalized: true, ..Acc::new(BYTE, "VEC3", n) };
        at.insert("NORMAL".into(), json!(self.accessor(view, normal)));
        at.insert(
            "TEXCOORD_0".into(),
            json!(self.array(Data::F32(&m.uvs), Some(ARRAY_BUFFER), Acc::new(FLOAT, "VEC2", n))),
        );
        if stride == 8 {
            let tangent = Acc { normalized: true, offset: 4, ..Acc::new(BYTE, "VEC4", n) };
            at.insert("TANGENT".into(), json!(self.accessor(view, tangent)));
        }
        let color = Acc { normalized: true, ..Acc::new(UNSIGNED_BYTE, "VEC4", n) };
        let mut wind_view = None;
        match extra.colors {
            Some(Colors::Bytes(c)) => {
                at.insert("COLOR_0".into(), json!(self.array(Data::Bytes(c), Some(ARRAY_BUFFER), color)));
            }
            Some(Colors::Bark(b)) => {
                let offset = self.data(Data::BarkExtras(m, Some(b), extra.wind));
                let view = self.view_at(offset, 4 * n, Some(ARRAY_BUFFER), None);
                at.insert("COLOR_0".into(), json!(self.accessor(view, color)));
                wind_view = extra.wind.map(|_| self.view_at(offset + 4 * n, 16 * n, Some(ARRAY_BUFFER), Some(16)));
            }
            None => {}
        }
        if let Some(w) = extra.wind {
            let view = wind_view
                .unwrap_or_else(|| self.view(Data::BarkExtras(m, None, Some(w)), Some(ARRAY_BUFFER), Some(16)));
            let pivot = Acc { normalized: true, ..Acc::new(UNSIGNED_SHORT, "VEC4", n) };
            at.insert("_WIND_PIVOT".into(), json!(self.accessor(view, pivot)));
            let params = Acc { normalized: true, offset: 8, ..Acc::new(UNSIGNED_SHORT, "VEC4", n) };
            at.insert("_WIND_PARAMS".into(), json!(self.accessor(view, params)));
        }
        at
    }

    /// A mesh with one primitive per non-empty group of `m`; `material` maps a group's material
    /// to a glTF material index. Returns the mesh index.
    fn mesh(
        &mut self,
        name: &str,
        m: &'a TreeMesh,
        extra: &VertexExtras<'a>,
        material: impl Fn(Material) -> usize,
    ) -> usize {
        let attributes = self.attributes(m, extra);
        let small = m.vertex_count() <= usize::from(u16::MAX);
        let mut primitives = Vec::new();
        for g in m.groups.iter().filter(|g| g.count > 0) {
            let idx = &m.indices[g.start as usize..(g.start + g.count) as usize];
            let (d, ct) = if small { (Data::U16(idx), UNSIGNED_SHORT) } else { (Data::U32(idx), UNSIGNED_INT) };
            let acc = self.array(d, Some(ELEMENT_ARRAY_BUFFER), Acc::new(ct, "SCALAR", idx.len()));
            primitives.push(json!({
                "attributes": Value::Object(attributes.clone()),
                "indices": acc,
                "material": material(g.material),
                "mode": 4,
            }));
        }
        let mut mesh = Map::new();
        mesh.insert("name".into(), json!(name));
        mesh.insert("primitives".into(), Value::Array(primitives));
        if let Some(w) = &extra.wind {
            let (mut pivot, mut params) = (w.json(0), w.json(4));
            pivot["fields"] = json!(WIND_PIVOT_DOC);
            params["fields"] = json!(WIND_PARAMS_DOC);
            mesh.insert(
                "extras".into(),
                json!({"wind_attributes": {"_WIND_PIVOT": pivot, "_WIND_PARAMS": params, "decode": WIND_DECODE_DOC}}),
            );
        }
        self.meshes.push(Value::Object(mesh));
        self.meshes.len() - 1
    }
}

/// Optional per-vertex arrays of a mesh.
#[derive(Default)]
struct VertexExtras<'a> {
    tangents: Option<Data<'a>>,
    colors: Option<Colors<'a>>,
    /// The wind attributes (the mesh's `wind`) and their encoding.
    wind: Option<WindCodec>,
    /// The mesh's bounds when already known.
    bounds: Option<Bounds>,
}

/// Where a mesh's `COLOR_0` comes from.
#[derive(Clone, Copy)]
enum Colors<'a> {
    /// RGBA8 per vertex.
    Bytes(&'a [u8]),
    /// The bark tint of the mesh with these bounds ([`super::BarkTint`]).
    Bark(Bounds),
}

/// Everything computed (not borrowed from the tree) before the document is laid out.
struct Owned {
    bark_pngs: Option<Arc<TexturePngs>>,
    leaf_pngs: Option<Arc<TexturePngs>>,
    baked: Option<super::BakedLeaves>,
    leaf_tangents: Option<Vec<f32>>,
}

/// The GLB file of a generated tree (layout: module docs).
pub fn write(g: &Generated, opts: &ExportOptions) -> Vec<u8> {
    let mut out = Vec::new();
    write_into(g, opts, &mut out);
    out
}

/// [`write()`] into `out` (cleared first), reusing its allocation: repeated exports of big trees
/// then skip the operating system's zeroing of fresh pages.
pub fn write_into(g: &Generated, opts: &ExportOptions, out: &mut Vec<u8>) {
    let bark = &g.mesh;
    let f = &g.foliage;
    let has_bark = bark.vertex_count() > 0 && !bark.indices.is_empty();
    let has_leaves = opts.leaves != LeafMode::None && f.count() > 0 && !f.mesh.indices.is_empty();
    let normal_maps = opts.textures && opts.normal_maps;
    // Tangents only for the normal maps, and only when asked for.
    let tangents = normal_maps && opts.tangents;
    let leaf_pngs = if opts.textures && has_leaves { super::leaf_pngs(f) } else { None };
    let instanced = has_leaves && opts.leaves == LeafMode::Instanced;
    let owned = Owned {
        bark_pngs: (has_bark && opts.textures).then(|| super::bark_pngs(opts.bark_texture_size)),
        baked: (has_leaves && opts.leaves == LeafMode::Baked)
            .then(|| super::bake_leaves(f, tangents && leaf_pngs.is_some())),
        leaf_tangents: (instanced && tangents && leaf_pngs.is_some())
            .then(|| super::tangents(&f.mesh.positions, &f.mesh.normals, &f.mesh.uvs, &f.mesh.indices)),
        leaf_pngs,
    };
    let mut doc = Doc::default();
    let samplers = json!([
        {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": REPEAT, "wrapT": REPEAT},
        {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": CLAMP_TO_EDGE, "wrapT": CLAMP_TO_EDGE},
    ]);
    let mut children = Vec::new();
    let mut used_samplers = [false; 2];
    let mut bark_material = None;
    if has_bark {
        let mut pbr = Map::new();
        pbr.insert("metallicFactor".into(), json!(0.0));
        pbr.insert("roughnessFactor".into(), json!(0.9));
        let mut mat = Map::new();
        mat.insert("name".into(), json!("bark"));
        if let Some(p) = &owned.bark_pngs {
            used_samplers[0] = true;
            let color = doc.texture(&p.color, "bark_color", 0);
            pbr.insert("baseColorTexture".into(), json!({"index": color}));
            if normal_maps {
                let normal = doc.texture(&p.normal, "bark_normal", 0);
                mat.insert("normalTexture".into(), json!({"index": normal}));
            }
        } else {
            // The viewer's plain bark colour #5b3d26, in linear RGB.
            pbr.insert("baseColorFactor".into(), json!([0.1046, 0.0467, 0.0194, 1.0]));
        }
        mat.insert("pbrMetallicRoughness".into(), Value::Object(pbr));
        doc.materials.push(Value::Object(mat));
        bark_material = Some(doc.materials.len() - 1);
    }
    let mut leaf_material = None;
    if has_leaves || bark.groups.iter().any(|g| g.material == Material::Leaves) {
        let mut pbr = Map::new();
        pbr.insert("metallicFactor".into(), json!(0.0));
        pbr.insert("roughnessFactor".into(), json!(0.7));
        let mut mat = Map::new();
        mat.insert("name".into(), json!("leaves"));
        mat.insert("doubleSided".into(), json!(true));
        if let Some(p) = &owned.leaf_pngs {
            used_samplers[1] = true;
            let color = doc.texture(&p.color, "leaf_color", 1);
            pbr.insert("baseColorTexture".into(), json!({"index": color}));
            mat.insert("alphaMode".into(), json!("MASK"));
            mat.insert("alphaCutoff".into(), json!(0.5));
            if normal_maps {
                let normal = doc.texture(&p.normal, "leaf_normal", 1);
                mat.insert("normalTexture".into(), json!({"index": normal}));
            }
        } else {
            // The leaf texture's blade green (0.30, 0.52, 0.18 in sRGB), in linear RGB.
            pbr.insert("baseColorFactor".into(), json!([0.0742, 0.2346, 0.0273, 1.0]));
        }
        mat.insert("pbrMetallicRoughness".into(), Value::Object(pbr));
        doc.materials.push(Value::Object(mat));
        leaf_material = Some(doc.materials.len() - 1);
    }
    let pick = |m: Material| match m {
        Material::Bark => bark_material.or(leaf_material).unwrap_or(0),
        Material::Leaves => leaf_material.or(bark_material).unwrap_or(0),
    };
    if has_bark {
        let wind =
            (opts.wind && bark.wind.len() == bark.vertex_count() * WIND_STRIDE).then(|| WindCodec::of(&bark.wind));
        let bounds = super::bounds_of(&bark.positions);
        let extra = VertexExtras {
            tangents: (tangents && owned.bark_pngs.is_some()).then_some(Data::Frames(bark)),
            colors: opts.vertex_colors.then_some(Colors::Bark(bounds)),
            wind,
            bounds: Some(bounds),
        };
        let mesh = doc.mesh("bark", bark, &extra, pick);
        doc.nodes.push(json!({"name": "bark", "mesh": mesh}));
        children.push(doc.nodes.len());
    }
    if let Some(b) = &owned.baked {
        let extra = VertexExtras {
            tangents: (!b.tangents.is_empty()).then_some(Data::FramesOf(&b.mesh.normals, &b.tangents)),
            colors: opts.vertex_colors.then_some(Colors::Bytes(&b.colors)),
            wind: None,
            bounds: None,
        };
        let mesh = doc.mesh("leaves", &b.mesh, &extra, pick);
        doc.nodes.push(json!({"name": "leaves", "mesh": mesh}));
        children.push(doc.nodes.len());
    }
    if instanced {
        let m = &f.matrices[..];
        let extra = VertexExtras {
            tangents: owned.leaf_tangents.as_deref().map(|t| Data::FramesOf(&f.mesh.normals, t)),
            ..VertexExtras::default()
        };
        let mesh = doc.mesh("leaf", &f.mesh, &extra, |_| pick(Material::Leaves));
        let n = f.count();
        let mut attrs = Map::new();
        let mut trs = |key: &str, part: Part, kind: &'static str| {
            attrs.insert(key.into(), json!(doc.array(Data::Trs(m, part), None, Acc::new(FLOAT, kind, n))));
        };
        trs("TRANSLATION", Part::Translation, "VEC3");
        trs("ROTATION", Part::Rotation, "VEC4");
        trs("SCALE", Part::Scale, "VEC3");
        if opts.vertex_colors {
            attrs.insert("_COLOR_0".into(), json!(doc.array(Data::F32(&f.colors), None, Acc::new(FLOAT, "VEC3", n))));
        }
        doc.nodes.push(json!({
            "name": "leaves",
            "mesh": mesh,
            "extensions": {"EXT_mesh_gpu_instancing": {"attributes": Value::Object(attrs)}},
        }));
        children.push(doc.nodes.len());
    }
    assemble(doc, g, samplers, used_samplers, instanced, children, out);
}

/// Lays out the JSON and the BIN chunk and writes the GLB bytes.
fn assemble(
    doc: Doc<'_>,
    g: &Generated,
    samplers: Value,
    used_samplers: [bool; 2],
    instanced: bool,
    children: Vec<usize>,
    out: &mut Vec<u8>,
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
    out.clear();
    out.reserve_exact(total);
    let word = |out: &mut Vec<u8>, w: u32| out.extend_from_slice(&w.to_le_bytes());
    word(out, MAGIC);
    word(out, 2);
    word(out, total as u32);
    word(out, json_len as u32);
    word(out, CHUNK_JSON);
    out.extend_from_slice(json.as_bytes());
    out.resize(20 + json_len, b' ');
    if has_bin {
        word(out, bin_len as u32);
        word(out, CHUNK_BIN);
        debug_assert_eq!(out.len(), bin_start);
        for (offset, d) in &doc.data {
            out.resize(bin_start + offset, 0); // alignment padding
            d.append(out);
        }
        out.resize(bin_start + bin_len, 0);
    }
    debug_assert_eq!(out.len(), total);
}
