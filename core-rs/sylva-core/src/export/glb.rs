//! glTF 2.0 binary (GLB) writer, following the Khronos glTF 2.0 specification (§3 concepts,
//! §4.4 GLB file format) and the `EXT_mesh_gpu_instancing` extension.
//!
//! **File layout**: 12-byte header (`glTF`, version 2, total length), a JSON chunk padded with
//! spaces to 4 bytes, a BIN chunk padded with zeros to 4 bytes. One buffer (the BIN chunk);
//! every buffer view starts on a 4-byte boundary and holds one tightly packed array, except the
//! wind view (below). Vertex views have `target` 34962 (ARRAY_BUFFER), index views 34963
//! (ELEMENT_ARRAY_BUFFER); image and instancing views have none.
//!
//! **Scene**: node 0 `sylva_tree` (identity) with children `bark` and `leaves`.
//!
//! * **Bark** mesh: one primitive per material group of [`TreeMesh`], sharing the attributes
//!   `POSITION` (with min/max), `NORMAL`, `TEXCOORD_0`, `TANGENT` (with normal maps),
//!   `COLOR_0` (RGBA8 normalised, see [`super::bark_colors`]) and the wind attributes;
//!   indices are `u16` when there are at most 65,535 vertices, `u32` otherwise.
//! * **Wind** (when the mesh carries it, see `TreeMesh::wind`): the 8 floats per vertex stay
//!   interleaved in one view with `byteStride` 32, read by two `VEC4` float accessors:
//!   `_WIND_PIVOT` = `pivot_x, pivot_y, pivot_z` (m, the base of the vertex's stem), `level`
//!   (0 trunk, 1, 2, 3); `_WIND_PARAMS` = `phase` (0..1, per stem), `stiffness` (0..1, 1 =
//!   rigid trunk base), `distance` (m, path length from the root), `radius` (m). Custom
//!   attribute names start with `_` as glTF requires; the mesh's `extras.wind_attributes`
//!   repeats this description. three.js's GLTFLoader loads them as `_wind_pivot` and
//!   `_wind_params` geometry attributes.
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

use super::{ExportOptions, LeafMode, TexturePngs};
use crate::mesh::{Material, TreeMesh, WIND_STRIDE};
use crate::Generated;
use serde_json::{json, Map, Value};
use std::sync::Arc;

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
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
    /// Tangents of a mesh, computed into the output ([`super::tangents_into`]).
    Tangents(&'a TreeMesh),
    /// Bark tint of a mesh, computed into the output ([`super::bark_colors_into`]).
    BarkColors(&'a TreeMesh),
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

impl Data<'_> {
    fn byte_len(&self) -> usize {
        match self {
            Data::F32(s) => s.len() * 4,
            Data::U32(s) => s.len() * 4,
            Data::U16(s) => s.len() * 2,
            Data::Bytes(s) => s.len(),
            Data::Tangents(m) => m.vertex_count() * 16,
            Data::BarkColors(m) => m.vertex_count() * 4,
            Data::Trs(m, part) => m.len() / 16 * if *part == Part::Rotation { 16 } else { 12 },
        }
    }

    /// Appends the little-endian bytes to `out`, in blocks small enough to stay in cache
    /// between the zero-fill of `resize` and the write that replaces it.
    fn append(&self, out: &mut Vec<u8>) {
        const BLOCK: usize = 16 * 1024;
        let mut put = |len: usize, write: &dyn Fn(&mut [u8])| {
            let at = out.len();
            out.resize(at + len, 0);
            write(&mut out[at..]);
        };
        match *self {
            Data::F32(s) => s.chunks(BLOCK).for_each(|c| put(c.len() * 4, &|d| Data::F32(c).write(d))),
            Data::U32(s) => s.chunks(BLOCK).for_each(|c| put(c.len() * 4, &|d| Data::U32(c).write(d))),
            Data::U16(s) => s.chunks(BLOCK).for_each(|c| put(c.len() * 2, &|d| Data::U16(c).write(d))),
            Data::Bytes(s) => out.extend_from_slice(s),
            Data::Tangents(_) | Data::BarkColors(_) | Data::Trs(..) => put(self.byte_len(), &|d| self.write(d)),
        }
    }

    /// Writes the little-endian bytes into `dst` (exactly `byte_len` bytes).
    fn write(&self, dst: &mut [u8]) {
        match self {
            Data::F32(s) => {
                dst.chunks_exact_mut(4).zip(s.iter()).for_each(|(d, v)| d.copy_from_slice(&v.to_le_bytes()))
            }
            Data::U32(s) => {
                dst.chunks_exact_mut(4).zip(s.iter()).for_each(|(d, v)| d.copy_from_slice(&v.to_le_bytes()))
            }
            Data::U16(s) => {
                dst.chunks_exact_mut(2).zip(s.iter()).for_each(|(d, &v)| d.copy_from_slice(&(v as u16).to_le_bytes()))
            }
            Data::Bytes(s) => dst.copy_from_slice(s),
            Data::Tangents(m) => {
                dst.fill(0);
                super::tangents_into(&m.positions, &m.normals, &m.uvs, &m.indices, dst)
            }
            Data::BarkColors(m) => super::bark_colors_into(m, dst),
            Data::Trs(m, part) => {
                let width = if *part == Part::Rotation { 16 } else { 12 };
                for (d, m) in dst.chunks_exact_mut(width).zip(m.chunks_exact(16)) {
                    let v: &[f32] = match part {
                        Part::Translation => &m[12..15],
                        Part::Rotation => &super::decompose(m).1,
                        Part::Scale => &super::decompose_scale(m),
                    };
                    d.chunks_exact_mut(4).zip(v).for_each(|(d, x)| d.copy_from_slice(&x.to_le_bytes()));
                }
            }
        }
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
    /// Adds a buffer view (4-byte aligned) holding `d`; returns its index.
    fn view(&mut self, d: Data<'a>, target: Option<u32>, stride: Option<usize>) -> usize {
        let offset = self.bin_len.next_multiple_of(4);
        let len = d.byte_len();
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
        self.data.push((offset, d));
        self.bin_len = offset + len;
        self.views.len() - 1
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
        let b = m.bounds();
        let mut at = Map::new();
        let pos = Acc { minmax: Some((b.min.to_vec(), b.max.to_vec())), ..Acc::new(FLOAT, "VEC3", n) };
        at.insert("POSITION".into(), json!(self.array(Data::F32(&m.positions), Some(ARRAY_BUFFER), pos)));
        at.insert(
            "NORMAL".into(),
            json!(self.array(Data::F32(&m.normals), Some(ARRAY_BUFFER), Acc::new(FLOAT, "VEC3", n))),
        );
        at.insert(
            "TEXCOORD_0".into(),
            json!(self.array(Data::F32(&m.uvs), Some(ARRAY_BUFFER), Acc::new(FLOAT, "VEC2", n))),
        );
        if let Some(t) = extra.tangents {
            at.insert("TANGENT".into(), json!(self.array(t, Some(ARRAY_BUFFER), Acc::new(FLOAT, "VEC4", n))));
        }
        if let Some(c) = extra.colors {
            let acc = Acc { normalized: true, ..Acc::new(UNSIGNED_BYTE, "VEC4", n) };
            at.insert("COLOR_0".into(), json!(self.array(c, Some(ARRAY_BUFFER), acc)));
        }
        if let Some(w) = extra.wind {
            let view = self.view(Data::F32(w), Some(ARRAY_BUFFER), Some(WIND_STRIDE * 4));
            at.insert("_WIND_PIVOT".into(), json!(self.accessor(view, Acc::new(FLOAT, "VEC4", n))));
            let params = Acc { offset: 16, ..Acc::new(FLOAT, "VEC4", n) };
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
        if extra.wind.is_some() {
            mesh.insert(
                "extras".into(),
                json!({"wind_attributes": {"_WIND_PIVOT": WIND_PIVOT_DOC, "_WIND_PARAMS": WIND_PARAMS_DOC}}),
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
    colors: Option<Data<'a>>,
    wind: Option<&'a [f32]>,
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

/// [`write`] into `out` (cleared first), reusing its allocation: repeated exports of big trees
/// then skip the operating system's zeroing of fresh pages.
pub fn write_into(g: &Generated, opts: &ExportOptions, out: &mut Vec<u8>) {
    let bark = &g.mesh;
    let f = &g.foliage;
    let has_bark = bark.vertex_count() > 0 && !bark.indices.is_empty();
    let has_leaves = opts.leaves != LeafMode::None && f.count() > 0 && !f.mesh.indices.is_empty();
    let normal_maps = opts.textures && opts.normal_maps;
    let leaf_pngs = if opts.textures && has_leaves { super::leaf_pngs(f) } else { None };
    let instanced = has_leaves && opts.leaves == LeafMode::Instanced;
    let owned = Owned {
        bark_pngs: (has_bark && opts.textures).then(|| super::bark_pngs(opts.bark_texture_size)),
        baked: (has_leaves && opts.leaves == LeafMode::Baked)
            .then(|| super::bake_leaves(f, normal_maps && leaf_pngs.is_some())),
        leaf_tangents: (instanced && normal_maps && leaf_pngs.is_some())
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
        let wind = (opts.wind && bark.wind.len() == bark.vertex_count() * WIND_STRIDE).then_some(&bark.wind[..]);
        let extra = VertexExtras {
            tangents: (normal_maps && owned.bark_pngs.is_some()).then_some(Data::Tangents(bark)),
            colors: opts.vertex_colors.then_some(Data::BarkColors(bark)),
            wind,
        };
        let mesh = doc.mesh("bark", bark, &extra, pick);
        doc.nodes.push(json!({"name": "bark", "mesh": mesh}));
        children.push(doc.nodes.len());
    }
    if let Some(b) = &owned.baked {
        let extra = VertexExtras {
            tangents: (!b.tangents.is_empty()).then_some(Data::F32(&b.tangents)),
            colors: opts.vertex_colors.then_some(Data::Bytes(&b.colors)),
            wind: None,
        };
        let mesh = doc.mesh("leaves", &b.mesh, &extra, pick);
        doc.nodes.push(json!({"name": "leaves", "mesh": mesh}));
        children.push(doc.nodes.len());
    }
    if instanced {
        let m = &f.matrices[..];
        let extra = VertexExtras { tangents: owned.leaf_tangents.as_deref().map(Data::F32), ..VertexExtras::default() };
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
    if instanced {
        root.insert("extensionsUsed".into(), json!(["EXT_mesh_gpu_instancing"]));
    }
    let json = Value::Object(root).to_string();
    let json_len = json.len().next_multiple_of(4);
    let bin_len = doc.bin_len.next_multiple_of(4);
    let has_bin = doc.bin_len > 0;
    let total = 12 + 8 + json_len + if has_bin { 8 + bin_len } else { 0 };
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
        let bin_start = out.len();
        for (offset, d) in &doc.data {
            out.resize(bin_start + offset, 0); // alignment padding
            d.append(out);
        }
        out.resize(bin_start + bin_len, 0);
    }
    debug_assert_eq!(out.len(), total);
}
