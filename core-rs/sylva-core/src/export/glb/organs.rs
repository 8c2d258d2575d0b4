//! The flowers, fruit, catkins and buds in the GLB ([`crate::organs`], module docs of `glb`):
//! per set a material (the set's name, its colour as `baseColorFactor` in linear light, its
//! roughness, metallic 0, `doubleSided`: petals and samara wings are single blades), a mesh of
//! one primitive, and a node named after the set under `sylva_tree`. Instanced files draw the
//! set's mesh through `EXT_mesh_gpu_instancing` as the leaves are (`TRANSLATION`, `ROTATION`,
//! `SCALE` and, with vertex colours, the tints as `_COLOR_0`); baked files
//! ([`LeafMode::Baked`](crate::export::LeafMode), strict files) hold every instance's copy in
//! one mesh with the tints as `COLOR_0` ([`crate::export::organs::bake_set`]).

use super::data::{Data, Part};
use super::doc::{Acc, Colors, Doc, VertexExtras};
use super::FLOAT;
use crate::export::organs::{linear_color, BakedSet};
use crate::organs::OrganSet;
use serde_json::{json, Map, Value};

/// The set's material: plain colour `base` (linear RGB), the set's roughness, two-sided.
fn material(doc: &mut Doc<'_>, set: &OrganSet, base: [f32; 3]) -> usize {
    let c = |v: f32| f64::from(v);
    doc.materials.push(json!({
        "name": set.name,
        "doubleSided": true,
        "pbrMetallicRoughness": {
            "baseColorFactor": [c(base[0]), c(base[1]), c(base[2]), 1.0],
            "metallicFactor": 0.0,
            "roughnessFactor": c(set.roughness),
        },
    }));
    doc.materials.len() - 1
}

/// The sets drawn through `EXT_mesh_gpu_instancing`; pushes their nodes' indices (1-based:
/// node 0 is `sylva_tree`) to `children`.
pub(super) fn instanced<'a>(doc: &mut Doc<'a>, sets: &[&'a OrganSet], colors: bool, children: &mut Vec<usize>) {
    for &set in sets {
        let mat = material(doc, set, linear_color(set));
        let mesh = doc.mesh(set.name, &set.mesh, &VertexExtras::default(), |_| mat);
        let n = set.count();
        let mut attrs = Map::new();
        let mut trs = |key: &str, part: Part, kind: &'static str| {
            attrs.insert(key.into(), json!(doc.array(Data::Trs(&set.matrices, part), None, Acc::new(FLOAT, kind, n))));
        };
        trs("TRANSLATION", Part::Translation, "VEC3");
        trs("ROTATION", Part::Rotation, "VEC4");
        trs("SCALE", Part::Scale, "VEC3");
        if colors {
            let acc = Acc::new(FLOAT, "VEC3", n);
            attrs.insert("_COLOR_0".into(), json!(doc.array(Data::F32(&set.colors), None, acc)));
        }
        doc.nodes.push(json!({
            "name": set.name,
            "mesh": mesh,
            "extensions": {"EXT_mesh_gpu_instancing": {"attributes": Value::Object(attrs)}},
        }));
        children.push(doc.nodes.len());
    }
}

/// The sets baked into one mesh each (tints as `COLOR_0` with `colors`); pushes their nodes.
pub(super) fn baked<'a>(doc: &mut Doc<'a>, sets: &'a [BakedSet<'a>], colors: bool, children: &mut Vec<usize>) {
    for b in sets {
        // Without vertex colours the tints are gone: the plain colour, unscaled.
        let mat = material(doc, b.set, if colors { b.base } else { linear_color(b.set) });
        let extra =
            VertexExtras { colors: colors.then_some(Colors::Bytes(&b.baked.colors)), ..VertexExtras::default() };
        let mesh = doc.mesh(b.set.name, &b.baked.mesh, &extra, |_| mat);
        doc.nodes.push(json!({"name": b.set.name, "mesh": mesh}));
        children.push(doc.nodes.len());
    }
}
