//! The exporters (`sylva_core::export`): GLB structure read back with a small test-side parser
//! (header, chunk alignment and padding, buffer views, accessors, min/max, counts), the three
//! leaf modes, the wind attributes, determinism, and the OBJ/MTL text.

use serde_json::Value;
use sylva_core::export::{self, ExportOptions, LeafMode};
use sylva_core::{generate, presets, Generated, TreeParams};

fn preset(name: &str) -> Generated {
    generate(&presets::find(name).expect("preset").params().expect("params")).expect("generate")
}

/// A parsed GLB: the JSON and the BIN chunk.
struct Glb {
    json: Value,
    bin: Vec<u8>,
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(b[at..at + 4].try_into().unwrap())
}

/// Parses and checks the container: header, chunk types, lengths, 4-byte alignment, padding.
fn parse(bytes: &[u8]) -> Glb {
    assert_eq!(&bytes[0..4], b"glTF");
    assert_eq!(u32_at(bytes, 4), 2, "version");
    assert_eq!(u32_at(bytes, 8) as usize, bytes.len(), "total length");
    let json_len = u32_at(bytes, 12) as usize;
    assert_eq!(&bytes[16..20], b"JSON");
    assert_eq!(json_len % 4, 0, "JSON chunk aligned");
    let text = std::str::from_utf8(&bytes[20..20 + json_len]).unwrap();
    assert!(text.ends_with('}') || text.ends_with(' '), "JSON padded with spaces");
    let json: Value = serde_json::from_str(text.trim_end_matches(' ')).unwrap();
    let at = 20 + json_len;
    let bin = if at < bytes.len() {
        let bin_len = u32_at(bytes, at) as usize;
        assert_eq!(&bytes[at + 4..at + 8], b"BIN\0");
        assert_eq!(bin_len % 4, 0, "BIN chunk aligned");
        assert_eq!(at + 8 + bin_len, bytes.len());
        bytes[at + 8..].to_vec()
    } else {
        Vec::new()
    };
    let buffer_len = json["buffers"][0]["byteLength"].as_u64().unwrap_or(0) as usize;
    assert!(buffer_len <= bin.len() && bin.len() <= buffer_len + 3, "buffer {buffer_len} in chunk {}", bin.len());
    assert!(bin[buffer_len..].iter().all(|&b| b == 0), "BIN padded with zeros");
    Glb { json, bin }
}

fn component_size(ct: u64) -> usize {
    match ct {
        5120 | 5121 => 1,
        5123 => 2,
        5125 | 5126 => 4,
        other => panic!("component type {other}"),
    }
}

fn components(kind: &str) -> usize {
    match kind {
        "SCALAR" => 1,
        "VEC2" => 2,
        "VEC3" => 3,
        "VEC4" => 4,
        other => panic!("type {other}"),
    }
}

impl Glb {
    fn accessor(&self, i: u64) -> &Value {
        &self.json["accessors"][i as usize]
    }

    /// The float values of a float accessor, element by element.
    fn floats(&self, i: u64) -> Vec<Vec<f32>> {
        let a = self.accessor(i);
        assert_eq!(a["componentType"], 5126);
        let v = &self.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let n = components(a["type"].as_str().unwrap());
        let stride = v["byteStride"].as_u64().map_or(n * 4, |s| s as usize);
        let base = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
        (0..a["count"].as_u64().unwrap() as usize)
            .map(|e| {
                (0..n)
                    .map(|k| f32::from_le_bytes(self.bin[base + e * stride + 4 * k..][..4].try_into().unwrap()))
                    .collect()
            })
            .collect()
    }

    /// The values of a normalised `i8` accessor (KHR_mesh_quantization), dequantised as glTF
    /// says (`max(c / 127, -1)`), element by element.
    fn snorm8(&self, i: u64) -> Vec<Vec<f32>> {
        let a = self.accessor(i);
        assert_eq!((a["componentType"].as_u64(), a["normalized"].as_bool()), (Some(5120), Some(true)));
        let v = &self.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let n = components(a["type"].as_str().unwrap());
        let stride = v["byteStride"].as_u64().map_or(n, |s| s as usize);
        let base = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
        (0..a["count"].as_u64().unwrap() as usize)
            .map(|e| (0..n).map(|k| (f32::from(self.bin[base + e * stride + k] as i8) / 127.0).max(-1.0)).collect())
            .collect()
    }

    /// The raw values of a normalised `u16` accessor, element by element.
    fn unorm16(&self, i: u64) -> Vec<Vec<u16>> {
        let a = self.accessor(i);
        assert_eq!((a["componentType"].as_u64(), a["normalized"].as_bool()), (Some(5123), Some(true)));
        let v = &self.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let n = components(a["type"].as_str().unwrap());
        let stride = v["byteStride"].as_u64().map_or(n * 2, |s| s as usize);
        let base = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
        (0..a["count"].as_u64().unwrap() as usize)
            .map(|e| {
                (0..n)
                    .map(|k| u16::from_le_bytes(self.bin[base + e * stride + 2 * k..][..2].try_into().unwrap()))
                    .collect()
            })
            .collect()
    }

    /// Every view and accessor fits, is aligned and is consistent.
    fn check_layout(&self) {
        let views = self.json["bufferViews"].as_array().cloned().unwrap_or_default();
        for v in &views {
            let (o, l) = (v["byteOffset"].as_u64().unwrap() as usize, v["byteLength"].as_u64().unwrap() as usize);
            assert_eq!(o % 4, 0, "view offset aligned: {v}");
            assert!(o + l <= self.bin.len());
            if let Some(s) = v["byteStride"].as_u64() {
                assert!(s % 4 == 0 && (4..=252).contains(&s), "{v}");
            }
        }
        for a in self.json["accessors"].as_array().cloned().unwrap_or_default() {
            let v = &views[a["bufferView"].as_u64().unwrap() as usize];
            let size = component_size(a["componentType"].as_u64().unwrap()) * components(a["type"].as_str().unwrap());
            let stride = v["byteStride"].as_u64().map_or(size, |s| s as usize);
            let offset = a["byteOffset"].as_u64().unwrap_or(0) as usize;
            let count = a["count"].as_u64().unwrap() as usize;
            assert!(count > 0, "{a}");
            assert_eq!(offset % 4, 0, "accessor offset aligned {a}");
            assert!(offset + stride * (count - 1) + size <= v["byteLength"].as_u64().unwrap() as usize, "{a} in {v}");
        }
    }

    fn node(&self, name: &str) -> Option<&Value> {
        self.json["nodes"].as_array().unwrap().iter().find(|n| n["name"] == name)
    }

    fn mesh_of(&self, node: &str) -> &Value {
        &self.json["meshes"][self.node(node).unwrap()["mesh"].as_u64().unwrap() as usize]
    }

    /// Total index count over a mesh's primitives.
    fn index_count(&self, mesh: &Value) -> u64 {
        mesh["primitives"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| self.accessor(p["indices"].as_u64().unwrap())["count"].as_u64().unwrap())
            .sum()
    }
}

#[test]
fn glb_container_layout_and_counts() {
    let g = preset("default");
    let bytes = export::to_glb(&g, &ExportOptions::default());
    let glb = parse(&bytes);
    glb.check_layout();
    let j = &glb.json;
    assert_eq!(j["asset"]["version"], "2.0");
    assert_eq!(j["asset"]["generator"], format!("Sylva {}", sylva_core::VERSION));
    assert_eq!(j["scenes"][0]["extras"]["sylva_hash"], g.hash_hex());
    // Bark: counts, min/max exactly the data's bounds, u32 indices (more than 65,535 vertices).
    let bark = glb.mesh_of("bark");
    let attrs = &bark["primitives"][0]["attributes"];
    let pos = attrs["POSITION"].as_u64().unwrap();
    assert_eq!(glb.accessor(pos)["count"], g.mesh.vertex_count());
    let b = g.mesh.bounds();
    let min: Vec<f32> =
        glb.accessor(pos)["min"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap() as f32).collect();
    let max: Vec<f32> =
        glb.accessor(pos)["max"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap() as f32).collect();
    assert_eq!((min.as_slice(), max.as_slice()), (&b.min[..], &b.max[..]));
    let back = glb.floats(pos);
    assert_eq!(back.len() * 3, g.mesh.positions.len());
    assert_eq!(back[17], g.mesh.positions[51..54].to_vec());
    assert_eq!(glb.index_count(bark), g.mesh.indices.len() as u64);
    assert_eq!(glb.accessor(bark["primitives"][0]["indices"].as_u64().unwrap())["componentType"], 5125);
    for key in ["NORMAL", "TEXCOORD_0", "TANGENT", "COLOR_0"] {
        assert_eq!(glb.accessor(attrs[key].as_u64().unwrap())["count"], g.mesh.vertex_count(), "{key}");
    }
    // Normals and tangents: normalised i8 (KHR_mesh_quantization, required), interleaved in one
    // view (normal + 1 byte of padding, tangent); unit within the validator's tolerance, close to
    // the mesh's normals and to the float tangents (`export::mesh_tangents`), perpendicular,
    // w = ±1.
    let (ta, na) = (glb.accessor(attrs["TANGENT"].as_u64().unwrap()), glb.accessor(attrs["NORMAL"].as_u64().unwrap()));
    assert_eq!(ta["bufferView"], na["bufferView"]);
    assert_eq!((na["byteOffset"].as_u64().unwrap_or(0), ta["byteOffset"].as_u64()), (0, Some(4)));
    assert_eq!(j["bufferViews"][na["bufferView"].as_u64().unwrap() as usize]["byteStride"], 8);
    let (t, n) = (glb.snorm8(attrs["TANGENT"].as_u64().unwrap()), glb.snorm8(attrs["NORMAL"].as_u64().unwrap()));
    let len = |v: &[f32]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let exact = export::mesh_tangents(&g.mesh);
    for (k, ((t, n), e)) in t.iter().zip(&n).zip(exact.chunks_exact(4)).enumerate() {
        assert!((len(n) - 1.0).abs() <= 0.00674 && (len(t) - 1.0).abs() <= 0.00674, "{k}: {n:?} {t:?}");
        assert!((t[0] * n[0] + t[1] * n[1] + t[2] * n[2]).abs() < 0.03 && t[3].abs() == 1.0, "{k}: {n:?} {t:?}");
        let m = &g.mesh.normals[3 * k..3 * k + 3];
        assert!((0..3).all(|i| (n[i] - m[i]).abs() <= 1.0 / 127.0), "{k}: {n:?} vs {m:?}");
        assert!((0..3).all(|i| (t[i] - e[i]).abs() <= 1.0 / 127.0) && t[3] == e[3], "{k}: {t:?} vs {e:?}");
    }
    // Without tangents (option): the normals alone, 4 bytes each, the same bytes.
    let plain = parse(&export::to_glb(&g, &ExportOptions { tangents: false, ..Default::default() }));
    plain.check_layout();
    let attrs = &plain.mesh_of("bark")["primitives"][0]["attributes"];
    assert!(attrs.get("TANGENT").is_none());
    let na = plain.accessor(attrs["NORMAL"].as_u64().unwrap());
    assert_eq!(plain.json["bufferViews"][na["bufferView"].as_u64().unwrap() as usize]["byteStride"], 4);
    assert_eq!(plain.snorm8(attrs["NORMAL"].as_u64().unwrap()), n);
    // Leaves, instanced: one TRS + colour per leaf, unit quaternions.
    let leaves = glb.node("leaves").unwrap();
    let inst = &leaves["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
    for key in ["TRANSLATION", "ROTATION", "SCALE", "_COLOR_0"] {
        assert_eq!(glb.accessor(inst[key].as_u64().unwrap())["count"], g.foliage.count(), "{key}");
    }
    for q in glb.floats(inst["ROTATION"].as_u64().unwrap()) {
        assert!(((q.iter().map(|x| x * x).sum::<f32>()).sqrt() - 1.0).abs() < 1e-5);
    }
    let t = glb.floats(inst["TRANSLATION"].as_u64().unwrap());
    assert_eq!(t[3], g.foliage.matrices[3 * 16 + 12..3 * 16 + 15].to_vec());
    assert_eq!(j["extensionsUsed"], serde_json::json!(["EXT_mesh_gpu_instancing", "KHR_mesh_quantization"]));
    assert_eq!(j["extensionsRequired"], serde_json::json!(["KHR_mesh_quantization"]));
    // Materials and embedded PNG images.
    let mats = j["materials"].as_array().unwrap();
    assert_eq!(mats[0]["name"], "bark");
    assert_eq!(mats[0]["pbrMetallicRoughness"]["metallicFactor"], 0.0);
    assert_eq!(mats[1]["alphaMode"], "MASK");
    assert_eq!(mats[1]["doubleSided"], true);
    // Bark colour, normal and occlusion-roughness-metal (one texture for both slots), leaf colour, normal.
    assert_eq!(j["images"].as_array().unwrap().len(), 5);
    let orm = &mats[0]["pbrMetallicRoughness"]["metallicRoughnessTexture"]["index"];
    assert_eq!(orm, &mats[0]["occlusionTexture"]["index"]);
    assert_eq!(j["textures"][orm.as_u64().unwrap() as usize]["name"], "bark_orm");
    for img in j["images"].as_array().unwrap() {
        let v = &j["bufferViews"][img["bufferView"].as_u64().unwrap() as usize];
        assert_eq!(img["mimeType"], "image/png");
        assert!(v.get("byteStride").is_none() && v.get("target").is_none());
        assert_eq!(&glb.bin[v["byteOffset"].as_u64().unwrap() as usize..][..8], b"\x89PNG\r\n\x1a\n");
    }
    assert_eq!(j["samplers"][0]["wrapS"], 10497);
    // Deterministic bytes, and write_into gives the same bytes into a reused buffer.
    assert_eq!(export::to_glb(&g, &ExportOptions::default()), bytes);
    let mut reused = vec![7u8; 100];
    export::glb::write_into(&g, &ExportOptions::default(), &mut reused);
    assert_eq!(reused, bytes);
}

#[test]
fn glb_bytes_do_not_depend_on_threads_or_the_reused_buffer() {
    // The writer splits big views between threads: any number of threads writes the same bytes,
    // and a reused buffer's old bytes (longer, or full of garbage) never show through, in
    // padding or anywhere else.
    for (name, leaves) in [("default", LeafMode::Instanced), ("weeping_willow", LeafMode::Baked)] {
        let g = preset(name);
        let opts = ExportOptions { leaves, ..Default::default() };
        let mut one = Vec::new();
        export::glb::write_into_threads(&g, &opts, &mut one, 1);
        assert!(one.len() > 4 << 20, "{name}: big enough to split");
        for threads in [2, 3, 8] {
            let mut garbage = vec![0xab; one.len() + 1000];
            export::glb::write_into_threads(&g, &opts, &mut garbage, threads);
            assert!(garbage == one, "{name}, {threads} threads");
        }
    }
}

#[test]
fn glb_leaf_modes_and_options() {
    let g = preset("grown_bushy");
    // Small tree: u16 indices.
    let inst = parse(&export::to_glb(&g, &ExportOptions::default()));
    let bark = inst.mesh_of("bark");
    assert_eq!(inst.accessor(bark["primitives"][0]["indices"].as_u64().unwrap())["componentType"], 5123);
    // Baked: one mesh with every leaf, COLOR_0 from the leaf tints.
    let baked = parse(&export::to_glb(&g, &ExportOptions { leaves: LeafMode::Baked, ..Default::default() }));
    baked.check_layout();
    let leaves = baked.mesh_of("leaves");
    let attrs = &leaves["primitives"][0]["attributes"];
    let nv = g.foliage.mesh.vertex_count() * g.foliage.count();
    assert!(nv > 0);
    assert_eq!(baked.accessor(attrs["POSITION"].as_u64().unwrap())["count"], nv);
    assert_eq!(baked.accessor(attrs["COLOR_0"].as_u64().unwrap())["normalized"], true);
    assert_eq!(baked.index_count(leaves), (g.foliage.mesh.indices.len() * g.foliage.count()) as u64);
    assert_eq!(baked.json["extensionsUsed"], serde_json::json!(["KHR_mesh_quantization"]));
    // Baked positions are the instance matrices applied to the leaf mesh.
    let p = baked.floats(attrs["POSITION"].as_u64().unwrap());
    let m = glam::Mat4::from_cols_slice(&g.foliage.matrices[16..32]);
    let q = m.transform_point3(glam::Vec3::from_slice(&g.foliage.mesh.positions[0..3]));
    let got = &p[g.foliage.mesh.vertex_count()];
    assert!((q - glam::Vec3::new(got[0], got[1], got[2])).length() < 1e-5);
    // None: no leaf node, no leaf material.
    let none = parse(&export::to_glb(&g, &ExportOptions { leaves: LeafMode::None, ..Default::default() }));
    assert!(none.node("leaves").is_none());
    assert_eq!(none.json["materials"].as_array().unwrap().len(), 1);
    // No textures: no images, samplers or tangents; plain colour factors.
    let plain =
        parse(&export::to_glb(&g, &ExportOptions { textures: false, vertex_colors: false, ..Default::default() }));
    plain.check_layout();
    assert!(plain.json.get("images").is_none() && plain.json.get("samplers").is_none());
    let attrs = &plain.mesh_of("bark")["primitives"][0]["attributes"];
    assert!(attrs.get("TANGENT").is_none() && attrs.get("COLOR_0").is_none());
    // Without tangents the normals have a view of their own, 4 bytes per vertex.
    let normals = plain.accessor(attrs["NORMAL"].as_u64().unwrap());
    assert_eq!(plain.json["bufferViews"][normals["bufferView"].as_u64().unwrap() as usize]["byteStride"], 4);
    assert_eq!(plain.snorm8(attrs["NORMAL"].as_u64().unwrap()).len(), g.mesh.vertex_count());
    assert!(plain.json["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"].is_array());
}

/// The wind attributes of `glb`'s bark decoded as the mesh's `extras.wind_attributes` say:
/// 8 values per vertex, and the step (`scale / 65535`) of each component.
fn decoded_wind(glb: &Glb) -> (Vec<[f32; 8]>, [f32; 8]) {
    let bark = glb.mesh_of("bark");
    let attrs = &bark["primitives"][0]["attributes"];
    let doc = &bark["extras"]["wind_attributes"];
    let mut out: Vec<[f32; 8]> = Vec::new();
    let mut step = [0.0; 8];
    for (half, key) in ["_WIND_PIVOT", "_WIND_PARAMS"].iter().enumerate() {
        let f = |name: &str| -> Vec<f32> {
            doc[key][name].as_array().unwrap().iter().map(|v| v.as_f64().unwrap() as f32).collect()
        };
        let (offset, scale) = (f("offset"), f("scale"));
        for (e, q) in glb.unorm16(attrs[key].as_u64().unwrap()).iter().enumerate() {
            if half == 0 {
                out.push([0.0; 8]);
            }
            for k in 0..4 {
                out[e][4 * half + k] = offset[k] + scale[k] * (f32::from(q[k]) / 65_535.0);
            }
        }
        for k in 0..4 {
            step[4 * half + k] = scale[k] / 65_535.0;
        }
    }
    (out, step)
}

#[test]
fn glb_wind_attributes_share_one_strided_view() {
    let mut g = preset("grown_bushy");
    let n = g.mesh.vertex_count();
    // Synthetic wind data: 8 distinct values per vertex, levels 0..3, phase and stiffness 0..1.
    g.mesh.wind = (0..n * 8)
        .map(|i| match i % 8 {
            3 => (i / 8 % 4) as f32,
            4 | 5 => (i / 8 % 1000) as f32 / 999.0,
            k => i as f32 * 0.25 - k as f32,
        })
        .collect();
    let glb = parse(&export::to_glb(&g, &ExportOptions::default()));
    glb.check_layout();
    let bark = glb.mesh_of("bark");
    let attrs = &bark["primitives"][0]["attributes"];
    let (pivot, params) = (attrs["_WIND_PIVOT"].as_u64().unwrap(), attrs["_WIND_PARAMS"].as_u64().unwrap());
    let (a, b) = (glb.accessor(pivot), glb.accessor(params));
    // Normalised u16 VEC4 x 2 over one view, 16 bytes per vertex, right after the colours.
    assert_eq!(a["bufferView"], b["bufferView"]);
    let view = &glb.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
    assert_eq!(view["byteStride"], 16);
    assert_eq!((a["byteOffset"].as_u64().unwrap_or(0), b["byteOffset"].as_u64().unwrap()), (0, 8));
    assert_eq!((a["type"].as_str(), a["count"].as_u64()), (Some("VEC4"), Some(n as u64)));
    let colors = &glb.json["bufferViews"]
        [glb.accessor(attrs["COLOR_0"].as_u64().unwrap())["bufferView"].as_u64().unwrap() as usize];
    assert_eq!(
        colors["byteOffset"].as_u64().unwrap() + colors["byteLength"].as_u64().unwrap(),
        view["byteOffset"].as_u64().unwrap()
    );
    assert_eq!(glb.json["extensionsRequired"], serde_json::json!(["KHR_mesh_quantization"]));
    // Decoded within half a step (plus float rounding) of the mesh's values; levels exact, the
    // fixed ranges as documented.
    let (wind, step) = decoded_wind(&glb);
    for (v, (w, m)) in wind.iter().zip(g.mesh.wind.chunks_exact(8)).enumerate() {
        for k in 0..8 {
            assert!(
                (w[k] - m[k]).abs() <= step[k] * 0.5 + m[k].abs() * 2e-7 + 1e-6,
                "vertex {v} [{k}]: {} vs {}",
                w[k],
                m[k]
            );
        }
        assert_eq!(w[3].round(), m[3]);
    }
    let doc = &bark["extras"]["wind_attributes"];
    assert_eq!(doc["_WIND_PIVOT"]["scale"][3], 3.0);
    assert_eq!(
        (doc["_WIND_PARAMS"]["offset"][0].as_f64(), doc["_WIND_PARAMS"]["scale"][1].as_f64()),
        (Some(0.0), Some(1.0))
    );
    assert!(doc["_WIND_PARAMS"]["fields"].as_str().unwrap().contains("stiffness"));
    assert!(doc["decode"].as_str().unwrap().contains("65535"));
    // The levels 0..3 are 0, 21845, 43690, 65535.
    let q = glb.unorm16(pivot);
    assert!((0..4).all(|e| u32::from(q[e][3]) == 21_845 * (e as u32 % 4)));
    // Off by option; and an empty `wind` writes nothing.
    let off = parse(&export::to_glb(&g, &ExportOptions { wind: false, ..Default::default() }));
    assert!(off.mesh_of("bark")["primitives"][0]["attributes"].get("_WIND_PIVOT").is_none());
    let only = parse(&export::to_glb(&g, &ExportOptions { vertex_colors: false, ..Default::default() }));
    only.check_layout();
    assert_eq!(decoded_wind(&only).0, wind, "the same wind without the colours");
    g.mesh.wind.clear();
    let none = parse(&export::to_glb(&g, &ExportOptions::default()));
    assert!(none.mesh_of("bark")["primitives"][0]["attributes"].get("_WIND_PARAMS").is_none());
}

#[test]
fn glb_wind_of_the_presets_within_a_millimetre() {
    // The generator's own wind data: pivots, distances and radii within 1 mm on every preset
    // with wind, phase and stiffness within 1/65535.
    for name in presets::PRESETS.iter().map(|p| p.name) {
        let g = preset(name);
        if g.mesh.wind.is_empty() {
            continue;
        }
        let glb = parse(&export::to_glb(&g, &ExportOptions { textures: false, ..Default::default() }));
        let (wind, step) = decoded_wind(&glb);
        assert!(
            step.iter().enumerate().all(|(k, s)| *s <= if k == 4 || k == 5 { 1.0 / 65_535.0 } else { 0.002 }),
            "{name}: {step:?}"
        );
        let mut worst = [0f32; 8];
        for (w, m) in wind.iter().zip(g.mesh.wind.chunks_exact(8)) {
            for k in 0..8 {
                worst[k] = worst[k].max((w[k] - m[k]).abs());
            }
        }
        assert!(worst.iter().all(|e| *e <= 0.001), "{name}: {worst:?}");
    }
}

#[test]
fn ring_tangents_agree_with_lengyel_on_every_preset() {
    // The GLB's tangents (`export::mesh_tangents`: ring vertices from their ring neighbours,
    // the rest by Lengyel's method) against Lengyel's everywhere (`export::tangents`): all unit
    // and perpendicular to the normal; on at least 99% of the vertices the triangles use, the
    // same handedness and within about 25° (dot > 0.9). (Vertices no triangle uses, such as a
    // parent's ring vertices inside a junction's hole, have no tangent to agree with: Lengyel's
    // method gives them any perpendicular vector.)
    for name in presets::PRESETS.iter().map(|p| p.name) {
        let g = preset(name);
        let m = &g.mesh;
        let fast = export::mesh_tangents(m);
        let slow = export::tangents(&m.positions, &m.normals, &m.uvs, &m.indices);
        assert_eq!(fast.len(), slow.len(), "{name}");
        let mut used = vec![false; m.vertex_count()];
        for &i in &m.indices {
            used[i as usize] = true;
        }
        let (mut count, mut agree) = (0, 0);
        for (k, (f, s)) in fast.chunks_exact(4).zip(slow.chunks_exact(4)).enumerate() {
            let nn = &m.normals[3 * k..3 * k + 3];
            let len = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
            let perp = f[0] * nn[0] + f[1] * nn[1] + f[2] * nn[2];
            assert!((len - 1.0).abs() < 1e-5 && perp.abs() < 1e-3, "{name} vertex {k}: {f:?} (normal {nn:?})");
            assert!(f[3].abs() == 1.0, "{name} vertex {k}: {f:?}");
            if used[k] {
                count += 1;
                agree += usize::from(f[3] == s[3] && f[0] * s[0] + f[1] * s[1] + f[2] * s[2] > 0.9);
            }
        }
        assert!(agree * 100 >= count * 99, "{name}: {agree} of {count} tangents agree with Lengyel's");
        // Most bark vertices are on rings (the rest: collars, zips, forks, caps, holes).
        let on_rings: usize = m.rings.iter().map(|r| r[1] as usize).sum();
        assert!(on_rings * 10 >= m.vertex_count() * 7, "{name}: {on_rings} of {} vertices on rings", m.vertex_count());
    }
}

#[test]
fn bare_tree_exports_without_leaves() {
    let mut p = TreeParams::default();
    p.foliage.leaves = 0;
    let g = generate(&p).unwrap();
    assert_eq!(g.foliage.count(), 0);
    let glb = parse(&export::to_glb(&g, &ExportOptions::default()));
    glb.check_layout();
    assert!(glb.node("leaves").is_none());
    assert_eq!(glb.json["extensionsUsed"], serde_json::json!(["KHR_mesh_quantization"]));
    assert_eq!(glb.json["images"].as_array().unwrap().len(), 3);
}

#[test]
fn bark_type_changes_the_exported_textures_and_the_hash() {
    let mut p = TreeParams::default();
    p.foliage.leaves = 0;
    let opts = ExportOptions::from_json(r#"{"bark_texture_size":32}"#).unwrap();
    let mut seen = Vec::new();
    for &kind in sylva_core::params::BarkType::ALL {
        p.mesh.bark_type = kind;
        let g = generate(&p).unwrap();
        let glb = parse(&export::to_glb(&g, &opts));
        let img = &glb.json["images"][0];
        let v = &glb.json["bufferViews"][img["bufferView"].as_u64().unwrap() as usize];
        let (at, len) = (v["byteOffset"].as_u64().unwrap() as usize, v["byteLength"].as_u64().unwrap() as usize);
        let color = glb.bin[at..at + len].to_vec();
        let obj_png = export::obj::texture_png(&g, &opts, 0).unwrap();
        for (h, c, o) in &seen {
            assert_ne!(*h, g.hash, "{kind:?}: same hash");
            assert_ne!(c, &color, "{kind:?}: same GLB colour map");
            assert_ne!(o, &obj_png, "{kind:?}: same OBJ colour map");
        }
        seen.push((g.hash, color, obj_png));
    }
}

#[test]
fn obj_and_mtl() {
    let g = preset("grown_bushy");
    let o = ExportOptions::default();
    let files = export::obj::write(&g, &o, "bush");
    let lines = |p: &str| files.obj.lines().filter(|l| l.starts_with(p)).count();
    let leaf_v = g.foliage.mesh.vertex_count() * g.foliage.count();
    let leaf_t = g.foliage.mesh.triangle_count() * g.foliage.count();
    assert_eq!(lines("v "), g.mesh.vertex_count() + leaf_v);
    assert_eq!(lines("vt "), g.mesh.vertex_count() + leaf_v);
    assert_eq!(lines("vn "), g.mesh.vertex_count() + leaf_v);
    assert_eq!(lines("f "), g.mesh.triangle_count() + leaf_t);
    assert!(files.obj.contains("mtllib bush.mtl\n") && files.obj.contains("usemtl leaves\n"));
    // Faces index within range (1-based, global).
    let total = (g.mesh.vertex_count() + leaf_v) as u64;
    for l in files.obj.lines().filter(|l| l.starts_with("f ")) {
        for c in l[2..].split(' ') {
            let i: u64 = c.split('/').next().unwrap().parse().unwrap();
            assert!((1..=total).contains(&i), "{l}");
        }
    }
    // Vertex colours as three extra numbers; positions read back exactly.
    let first = files.obj.lines().find(|l| l.starts_with("v ")).unwrap();
    let nums: Vec<f32> = first[2..].split(' ').map(|x| x.parse().unwrap()).collect();
    assert_eq!(nums.len(), 6);
    assert_eq!(nums[..3], g.mesh.positions[..3]);
    for name in ["bush_bark_color.png", "bush_bark_normal.png", "bush_leaf_color.png", "bush_leaf_normal.png"] {
        assert!(files.mtl.contains(name), "{name} in\n{}", files.mtl);
        let png = &files.textures.iter().find(|(n, _)| n == name).unwrap().1;
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    }
    assert_eq!(export::obj::write(&g, &o, "bush"), files, "deterministic");
    // Leaves none: bark only.
    let bare = export::obj::obj(&g, &ExportOptions { leaves: LeafMode::None, ..o }, "bush");
    assert_eq!(bare.lines().filter(|l| l.starts_with("f ")).count(), g.mesh.triangle_count());
}

/// Baked leaves: the tint and the wind records of every leaf vertex.
#[path = "export/baked.rs"]
mod baked;
/// The season's leaf colours in both GLBs.
#[path = "export/season.rs"]
mod season;

#[path = "export/strict.rs"]
mod strict;

/// Flowers, fruit, catkins and buds in the GLB (both modes), the OBJ and the LODs.
#[path = "export/organs.rs"]
mod organs;

#[path = "export/lods.rs"]
mod lods;

/// The growth animation GLB and the zip of one GLB per year.
#[path = "export/growth.rs"]
mod growth;
