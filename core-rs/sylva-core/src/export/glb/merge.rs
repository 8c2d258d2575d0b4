//! Several GLB files as one ([`merge`]): each file's scene root becomes a named node under one
//! root node, its arrays appended to the merged file's (every index re-based), its buffer views
//! copied into one BIN chunk. Embedded images with the same bytes are stored once (the levels of
//! detail share their bark and leaf textures). Used for the levels-of-detail file
//! ([`super::super::lods`]).

use serde_json::{json, Map, Value};
use std::collections::HashMap;

/// One file to merge: the name and `extras` its root node gets, and its GLB bytes (one scene
/// with one root node, one buffer: what [`super::write`] writes).
pub struct Part {
    /// The name its root node gets.
    pub name: String,
    /// The `extras` its root node gets.
    pub extras: Value,
    /// The file.
    pub glb: Vec<u8>,
}

/// The JSON and BIN chunks of a GLB written by [`super::write`].
fn chunks(glb: &[u8]) -> (Map<String, Value>, &[u8]) {
    let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().expect("4 bytes")) as usize;
    let json_len = word(12);
    let text = std::str::from_utf8(&glb[20..20 + json_len]).expect("UTF-8 JSON");
    let json: Value = serde_json::from_str(text.trim_end_matches(' ')).expect("the writer's JSON");
    let bin = if 20 + json_len < glb.len() { &glb[20 + json_len + 8..] } else { &[][..] };
    (json.as_object().cloned().unwrap_or_default(), bin)
}

/// The array `key` of `doc` (empty when absent).
fn array(doc: &Map<String, Value>, key: &str) -> Vec<Value> {
    doc.get(key).and_then(Value::as_array).cloned().unwrap_or_default()
}

/// Adds `by` to the index at `v[key]`, when there is one.
fn shift(v: &mut Value, key: &str, by: usize) {
    if let Some(i) = v.get(key).and_then(Value::as_u64) {
        v[key] = json!(i as usize + by);
    }
}

/// Adds `by` to every index in the object `v` (an attributes map).
fn shift_all(v: &mut Value, by: usize) {
    if let Some(m) = v.as_object_mut() {
        m.values_mut().for_each(|i| *i = json!(i.as_u64().unwrap_or(0) as usize + by));
    }
}

/// Adds `by` to the texture index of every `…Texture` entry of the material object `v`.
fn shift_textures(v: &mut Value, by: usize) {
    if let Some(o) = v.as_object_mut() {
        o.iter_mut().filter(|(k, _)| k.ends_with("Texture")).for_each(|(_, t)| shift(t, "index", by));
    }
}

/// The merged arrays under construction.
#[derive(Default)]
struct Merged {
    arrays: Map<String, Value>,
    bin: Vec<u8>,
    /// Where each distinct image's bytes went (its buffer view).
    images: HashMap<Vec<u8>, usize>,
    extensions: [Vec<Value>; 2],
}

impl Merged {
    fn list(&mut self, key: &str) -> &mut Vec<Value> {
        let v = self.arrays.entry(key).or_insert_with(|| json!([]));
        v.as_array_mut().expect("an array")
    }

    /// Copies a view's bytes into the BIN chunk (4-byte aligned); returns its new index.
    fn view(&mut self, mut view: Value, bytes: &[u8]) -> usize {
        let at = self.bin.len().next_multiple_of(4);
        self.bin.resize(at, 0);
        self.bin.extend_from_slice(bytes);
        view["byteOffset"] = json!(at);
        view["buffer"] = json!(0);
        self.list("bufferViews").push(view);
        self.list("bufferViews").len() - 1
    }

    /// Appends one file; returns its root node's new index.
    fn add(&mut self, part: &Part) -> usize {
        let (doc, bin) = chunks(&part.glb);
        let base = |m: &mut Merged, key: &str| m.list(key).len();
        let (acc, tex, mat, mesh, node, samp, img) = (
            base(self, "accessors"),
            base(self, "textures"),
            base(self, "materials"),
            base(self, "meshes"),
            base(self, "nodes"),
            base(self, "samplers"),
            base(self, "images"),
        );
        let image_views: Vec<u64> = array(&doc, "images").iter().filter_map(|i| i["bufferView"].as_u64()).collect();
        let mut views = Vec::new();
        for (k, v) in array(&doc, "bufferViews").into_iter().enumerate() {
            let (o, l) =
                (v["byteOffset"].as_u64().unwrap_or(0) as usize, v["byteLength"].as_u64().unwrap_or(0) as usize);
            let bytes = &bin[o..o + l];
            let index = if image_views.contains(&(k as u64)) {
                match self.images.get(bytes) {
                    Some(&i) => i,
                    None => {
                        let i = self.view(v, bytes);
                        self.images.insert(bytes.to_vec(), i);
                        i
                    }
                }
            } else {
                self.view(v, bytes)
            };
            views.push(index);
        }
        let view_of = |v: &mut Value| {
            if let Some(i) = v.get("bufferView").and_then(Value::as_u64) {
                v["bufferView"] = json!(views[i as usize]);
            }
        };
        for mut a in array(&doc, "accessors") {
            view_of(&mut a);
            self.list("accessors").push(a);
        }
        for mut i in array(&doc, "images") {
            view_of(&mut i);
            self.list("images").push(i);
        }
        self.list("samplers").extend(array(&doc, "samplers"));
        for mut t in array(&doc, "textures") {
            shift(&mut t, "sampler", samp);
            shift(&mut t, "source", img);
            self.list("textures").push(t);
        }
        for mut m in array(&doc, "materials") {
            shift_textures(&mut m, tex);
            if let Some(pbr) = m.get_mut("pbrMetallicRoughness") {
                shift_textures(pbr, tex);
            }
            self.list("materials").push(m);
        }
        for mut m in array(&doc, "meshes") {
            for p in m["primitives"].as_array_mut().into_iter().flatten() {
                shift_all(&mut p["attributes"], acc);
                shift(p, "indices", acc);
                shift(p, "material", mat);
            }
            self.list("meshes").push(m);
        }
        for mut n in array(&doc, "nodes") {
            shift(&mut n, "mesh", mesh);
            if let Some(c) = n.get_mut("children").and_then(Value::as_array_mut) {
                c.iter_mut().for_each(|i| *i = json!(i.as_u64().unwrap_or(0) as usize + node));
            }
            if let Some(a) = n.pointer_mut("/extensions/EXT_mesh_gpu_instancing/attributes") {
                shift_all(a, acc);
            }
            self.list("nodes").push(n);
        }
        for (k, key) in ["extensionsUsed", "extensionsRequired"].into_iter().enumerate() {
            for e in array(&doc, key) {
                if !self.extensions[k].contains(&e) {
                    self.extensions[k].push(e);
                }
            }
        }
        let root = node + doc["scenes"][0]["nodes"][0].as_u64().unwrap_or(0) as usize;
        let r = &mut self.list("nodes")[root];
        r["name"] = json!(part.name);
        r["extras"] = part.extras.clone();
        root
    }
}

/// One GLB holding every part: node 0 `name` (with `extras`) whose children are the parts' root
/// nodes, renamed and given extras as each [`Part`] says. The asset and the scene's `extras` are
/// the first part's; the extensions used and required are the union of the parts'.
pub fn merge(name: &str, extras: Value, parts: &[Part]) -> Vec<u8> {
    let mut m = Merged::default();
    m.list("nodes").push(json!({"name": name, "extras": extras}));
    let roots: Vec<usize> = parts.iter().map(|p| m.add(p)).collect();
    m.list("nodes")[0]["children"] = json!(roots);
    let first = parts.first().map(|p| chunks(&p.glb).0).unwrap_or_default();
    let mut root = Map::new();
    root.insert("asset".into(), first.get("asset").cloned().unwrap_or_else(|| json!({"version": "2.0"})));
    root.insert("scene".into(), json!(0));
    let scene_extras = first.get("scenes").and_then(|s| s[0].get("extras")).cloned().unwrap_or(json!({}));
    root.insert("scenes".into(), json!([{"name": "Sylva", "nodes": [0], "extras": scene_extras}]));
    let bin_len = m.bin.len();
    for (key, v) in std::mem::take(&mut m.arrays) {
        if v.as_array().is_some_and(|a| !a.is_empty()) {
            root.insert(key, v);
        }
    }
    if bin_len > 0 {
        root.insert("buffers".into(), json!([{"byteLength": bin_len}]));
    }
    let [used, required] = std::mem::take(&mut m.extensions);
    if !used.is_empty() {
        root.insert("extensionsUsed".into(), Value::Array(used));
    }
    if !required.is_empty() {
        root.insert("extensionsRequired".into(), Value::Array(required));
    }
    container(&Value::Object(root).to_string(), &m.bin)
}

/// The GLB container (glTF 2.0 §4.4): header, JSON chunk padded with spaces, BIN chunk (when
/// not empty) padded with zeros.
fn container(json: &str, bin: &[u8]) -> Vec<u8> {
    let (json_len, bin_len) = (json.len().next_multiple_of(4), bin.len().next_multiple_of(4));
    let total = 20 + json_len + if bin.is_empty() { 0 } else { 8 + bin_len };
    let mut out = Vec::with_capacity(total);
    for w in [super::MAGIC, 2, total as u32, json_len as u32, super::CHUNK_JSON] {
        out.extend_from_slice(&w.to_le_bytes());
    }
    out.extend_from_slice(json.as_bytes());
    out.resize(20 + json_len, b' ');
    if !bin.is_empty() {
        out.extend_from_slice(&(bin_len as u32).to_le_bytes());
        out.extend_from_slice(&super::CHUNK_BIN.to_le_bytes());
        out.extend_from_slice(bin);
        out.resize(total, 0);
    }
    out
}
