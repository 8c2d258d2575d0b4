//! The glTF JSON under construction ([`Doc`]): buffer views, accessors, images, textures,
//! materials, meshes and nodes, with the BIN chunk's arrays ([`Data`]) laid out as they are
//! added.

use super::data::{floats, Data, WindCodec};
use super::{ARRAY_BUFFER, BYTE, ELEMENT_ARRAY_BUFFER, FLOAT, UNSIGNED_BYTE, UNSIGNED_INT, UNSIGNED_SHORT};
use super::{WIND_DECODE_DOC, WIND_PARAMS_DOC, WIND_PIVOT_DOC};
use crate::mesh::{Bounds, Material, TreeMesh};
use serde_json::{json, Map, Value};

/// The glTF document under construction: JSON arrays plus the views' data, laid out as added.
#[derive(Default)]
pub(super) struct Doc<'a> {
    pub(super) data: Vec<(usize, Data<'a>)>,
    pub(super) views: Vec<Value>,
    pub(super) accessors: Vec<Value>,
    pub(super) images: Vec<Value>,
    pub(super) textures: Vec<Value>,
    pub(super) materials: Vec<Value>,
    pub(super) meshes: Vec<Value>,
    pub(super) nodes: Vec<Value>,
    /// Animations (the growth animation's; none in the other files).
    pub(super) animations: Vec<Value>,
    pub(super) bin_len: usize,
    /// Whether an accessor needs `KHR_mesh_quantization`.
    pub(super) quantized: bool,
    /// Float normals and tangents, no quantisation ([`crate::export::ExportOptions::strict`]).
    pub(super) strict: bool,
}

/// One accessor's description.
pub(super) struct Acc {
    pub(super) component: u32,
    pub(super) kind: &'static str,
    pub(super) count: usize,
    pub(super) normalized: bool,
    pub(super) offset: usize,
    pub(super) minmax: Option<(Vec<f32>, Vec<f32>)>,
}

impl Acc {
    pub(super) fn new(component: u32, kind: &'static str, count: usize) -> Acc {
        Acc { component, kind, count, normalized: false, offset: 0, minmax: None }
    }
}

impl<'a> Doc<'a> {
    /// Adds `d` to the BIN chunk (4-byte aligned); returns its offset.
    pub(super) fn data(&mut self, d: Data<'a>) -> usize {
        let offset = self.bin_len.next_multiple_of(4);
        self.bin_len = offset + d.byte_len();
        self.data.push((offset, d));
        offset
    }

    /// Adds a buffer view of `len` bytes at `offset`; returns its index.
    pub(super) fn view_at(&mut self, offset: usize, len: usize, target: Option<u32>, stride: Option<usize>) -> usize {
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
    pub(super) fn view(&mut self, d: Data<'a>, target: Option<u32>, stride: Option<usize>) -> usize {
        let len = d.byte_len();
        let offset = self.data(d);
        self.view_at(offset, len, target, stride)
    }

    pub(super) fn accessor(&mut self, view: usize, a: Acc) -> usize {
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
    pub(super) fn array(&mut self, d: Data<'a>, target: Option<u32>, a: Acc) -> usize {
        let view = self.view(d, target, None);
        self.accessor(view, a)
    }

    /// An embedded PNG image and a texture sampling it with `sampler`; returns the texture index.
    pub(super) fn texture(&mut self, png: &'a [u8], name: &str, sampler: usize) -> usize {
        let view = self.view(Data::Bytes(png), None, None);
        self.images.push(json!({"bufferView": view, "mimeType": "image/png", "name": name}));
        self.textures.push(json!({"sampler": sampler, "source": self.images.len() - 1, "name": name}));
        self.textures.len() - 1
    }

    /// The vertex attributes of a mesh (shared by its primitives).
    pub(super) fn attributes(&mut self, m: &'a TreeMesh, extra: &VertexExtras<'a>) -> Map<String, Value> {
        let n = m.vertex_count();
        let b = extra.bounds.unwrap_or_else(|| crate::mesh::Bounds::of(&m.positions));
        let mut at = Map::new();
        let pos = Acc { minmax: Some((b.min.to_vec(), b.max.to_vec())), ..Acc::new(FLOAT, "VEC3", n) };
        at.insert("POSITION".into(), json!(self.array(Data::F32(&m.positions), Some(ARRAY_BUFFER), pos)));
        if self.strict {
            self.float_frames(m, extra.tangents, &mut at);
        } else {
            self.quantized_frames(m, extra.tangents, &mut at);
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

    /// `NORMAL`, `TEXCOORD_0` and (with `tangents`) `TANGENT` quantised (`KHR_mesh_quantization`):
    /// normals and tangents as normalised bytes, interleaved when both are written (normal 3
    /// bytes + 1 padding, tangent 4), else the normals alone.
    fn quantized_frames(&mut self, m: &'a TreeMesh, tangents: Option<Data<'a>>, at: &mut Map<String, Value>) {
        let n = m.vertex_count();
        self.quantized = true;
        let (view, stride) = match tangents {
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
    }

    /// `NORMAL`, `TEXCOORD_0` and (with `tangents`, given as [`Data::F32`] or
    /// [`Data::FramesOf`]) `TANGENT` as plain floats, each in a view of its own (core glTF).
    fn float_frames(&mut self, m: &'a TreeMesh, tangents: Option<Data<'a>>, at: &mut Map<String, Value>) {
        let n = m.vertex_count();
        let normal = Acc::new(FLOAT, "VEC3", n);
        at.insert("NORMAL".into(), json!(self.array(Data::F32(&m.normals), Some(ARRAY_BUFFER), normal)));
        at.insert(
            "TEXCOORD_0".into(),
            json!(self.array(Data::F32(&m.uvs), Some(ARRAY_BUFFER), Acc::new(FLOAT, "VEC2", n))),
        );
        let tangents = match tangents {
            Some(Data::FramesOf(_, t)) | Some(Data::F32(t)) => Some(t),
            _ => None,
        };
        if let Some(t) = tangents {
            let acc = Acc::new(FLOAT, "VEC4", n);
            at.insert("TANGENT".into(), json!(self.array(Data::F32(t), Some(ARRAY_BUFFER), acc)));
        }
    }

    /// A mesh with one primitive per non-empty group of `m`; `material` maps a group's material
    /// to a glTF material index. Returns the mesh index.
    pub(super) fn mesh(
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
pub(super) struct VertexExtras<'a> {
    pub(super) tangents: Option<Data<'a>>,
    pub(super) colors: Option<Colors<'a>>,
    /// The wind attributes (the mesh's `wind`) and their encoding.
    pub(super) wind: Option<WindCodec>,
    /// The mesh's bounds when already known.
    pub(super) bounds: Option<Bounds>,
}

/// Where a mesh's `COLOR_0` comes from.
#[derive(Clone, Copy)]
pub(super) enum Colors<'a> {
    /// RGBA8 per vertex.
    Bytes(&'a [u8]),
    /// The bark tint of the mesh with these bounds ([`BarkTint`](crate::export::tint::BarkTint)).
    Bark(Bounds),
}
