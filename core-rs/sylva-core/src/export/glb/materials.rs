//! The materials of the GLB (metallic-roughness, metallic 0; the module docs of `glb` list
//! them): what differs between the bark's, the leaves' and the cut faces' ([`MaterialSpec`]),
//! and the JSON of one, with its textures ([`material`]).

use super::doc::Doc;
use crate::export::textures::TexturePngs;
use serde_json::{json, Map, Value};

/// What differs between the bark's, the leaves' and the cut faces' materials.
pub(super) struct MaterialSpec {
    name: &'static str,
    roughness: f64,
    /// Sampler index: 0 repeats (bark), 1 clamps (the leaf texture, the end-grain disc).
    sampler: usize,
    /// Two-sided and alpha-masked (leaves).
    leaves: bool,
    color_name: &'static str,
    orm_name: &'static str,
    normal_name: &'static str,
    /// Linear RGBA without textures.
    fallback: [f64; 4],
}

pub(super) const BARK: MaterialSpec = MaterialSpec {
    name: "bark",
    roughness: 0.9,
    sampler: 0,
    leaves: false,
    color_name: "bark_color",
    orm_name: "bark_orm",
    normal_name: "bark_normal",
    // The viewer's plain bark colour #5b3d26, in linear RGB.
    fallback: [0.1046, 0.0467, 0.0194, 1.0],
};

pub(super) const LEAVES: MaterialSpec = MaterialSpec {
    name: "leaves",
    roughness: 0.7,
    sampler: 1,
    leaves: true,
    color_name: "leaf_color",
    orm_name: "leaf_orm",
    normal_name: "leaf_normal",
    // The leaf texture's blade green (0.30, 0.52, 0.18 in sRGB), in linear RGB.
    fallback: [0.0742, 0.2346, 0.0273, 1.0],
};

pub(super) const CUT_FACE: MaterialSpec = MaterialSpec {
    name: "cut_face",
    roughness: 0.85,
    sampler: 1,
    leaves: false,
    color_name: "cut_face_color",
    orm_name: "cut_face_orm",
    normal_name: "cut_face_normal",
    // The viewer's plain cut-face wood #c8a57a, in linear RGB.
    fallback: [0.586, 0.3838, 0.1975, 1.0],
};

/// A material as `spec` says (textures when `pngs`); returns its index.
pub(super) fn material<'a>(
    doc: &mut Doc<'a>,
    spec: &MaterialSpec,
    pngs: Option<&'a TexturePngs>,
    normal_maps: bool,
    used_samplers: &mut [bool; 2],
) -> usize {
    let mut pbr = Map::new();
    pbr.insert("metallicFactor".into(), json!(0.0));
    pbr.insert("roughnessFactor".into(), json!(spec.roughness));
    let mut mat = Map::new();
    mat.insert("name".into(), json!(spec.name));
    if spec.leaves {
        mat.insert("doubleSided".into(), json!(true));
    }
    if let Some(p) = pngs {
        used_samplers[spec.sampler] = true;
        let color = doc.texture(&p.color, spec.color_name, spec.sampler);
        pbr.insert("baseColorTexture".into(), json!({"index": color}));
        if spec.leaves {
            mat.insert("alphaMode".into(), json!("MASK"));
            mat.insert("alphaCutoff".into(), json!(0.5));
        }
        if let Some(orm) = p.orm.as_ref().filter(|_| !spec.leaves) {
            // One packed map: glTF reads roughness from G (metalness B = 0) and occlusion from R.
            let orm = doc.texture(orm, spec.orm_name, spec.sampler);
            pbr.insert("metallicRoughnessTexture".into(), json!({"index": orm}));
            pbr.insert("roughnessFactor".into(), json!(1.0));
            mat.insert("occlusionTexture".into(), json!({"index": orm}));
        }
        if normal_maps {
            let normal = doc.texture(&p.normal, spec.normal_name, spec.sampler);
            mat.insert("normalTexture".into(), json!({"index": normal}));
        }
    } else {
        pbr.insert("baseColorFactor".into(), json!(spec.fallback));
    }
    mat.insert("pbrMetallicRoughness".into(), Value::Object(pbr));
    doc.materials.push(Value::Object(mat));
    doc.materials.len() - 1
}
