//! The growth animation's part of the GLB ([`super::write_growth`]): morph targets on the bark
//! and leaf meshes and the animation `growth` that plays them.
//!
//! * Each target is a float `POSITION` accessor (deltas from the mesh's positions, with the
//!   `min`/`max` glTF requires) in a view of its own; every primitive of a mesh lists the same
//!   targets. The mesh gets `weights` (all 0: the tree as built) and `extras.targetNames`
//!   (`year 0`, `year 1`, ...; Blender and three.js name shape keys and morph targets after them).
//! * The animation has one sampler (`LINEAR`): input the key years in seconds (one second a
//!   year, `min` 0, `max` the Age), output per key the weights of every target, 1 for that key's
//!   target and 0 for the rest (all 0 at the keys of the tree as built); one `weights` channel
//!   per node with targets, sharing the sampler.

use super::data::Data;
use super::doc::{Acc, Doc};
use super::{ARRAY_BUFFER, FLOAT};
use crate::export::bake::BakedLeaves;
use crate::export::growth::{self, GrowthMorphs, LeafInput};
use crate::Generated;
use serde_json::{json, Value};

/// The growth morphs of `g` (built at `age`, Mature Age `mature`), with its `baked` leaves.
pub(super) fn morphs(
    g: &Generated,
    baked: Option<&BakedLeaves>,
    age: f32,
    mature: f32,
    threads: usize,
) -> GrowthMorphs {
    let leaves = baked.and_then(|b| {
        let f = &g.foliage;
        let records = super::baked::leaf_wind(g, threads)?;
        let petiole = f.leaf.as_deref().map_or(0.0, |l| l.petiole);
        let anchors = f.matrices.chunks_exact(16).map(|m| super::baked::attachment(m, petiole)).zip(records).collect();
        Some(LeafInput { positions: &b.mesh.positions, per_leaf: f.mesh.vertex_count(), anchors })
    });
    growth::morphs(g, age, mature, leaves.as_ref(), threads)
}

/// Adds `targets` (3 floats per vertex each, one per key year in `years`) to mesh `mesh`.
pub(super) fn targets<'a>(doc: &mut Doc<'a>, mesh: usize, targets: &'a [Vec<f32>], years: &[f32]) {
    if targets.is_empty() {
        return;
    }
    let mut list = Vec::new();
    for t in targets {
        let b = crate::mesh::Bounds::of(t);
        let acc = Acc { minmax: Some((b.min.to_vec(), b.max.to_vec())), ..Acc::new(FLOAT, "VEC3", t.len() / 3) };
        list.push(json!({"POSITION": doc.array(Data::F32(t), Some(ARRAY_BUFFER), acc)}));
    }
    let m = &mut doc.meshes[mesh];
    if let Some(prims) = m["primitives"].as_array_mut() {
        for p in prims {
            p["targets"] = Value::Array(list.clone());
        }
    }
    m["weights"] = json!(vec![0.0; targets.len()]);
    let names: Vec<String> = years[..targets.len()].iter().map(|y| format!("year {y}")).collect();
    if m.get("extras").is_none() {
        m["extras"] = json!({});
    }
    m["extras"]["targetNames"] = json!(names);
}

/// Adds the animation `growth` playing the targets of the nodes among `children` whose mesh has
/// them (final node indices: node 0, the tree's root, comes before `doc.nodes`).
pub(super) fn animation<'a>(doc: &mut Doc<'a>, children: &[usize], m: &'a GrowthMorphs) {
    let n = m.targets();
    let nodes: Vec<usize> = children
        .iter()
        .copied()
        .filter(|&k| {
            let mesh = doc.nodes[k - 1]["mesh"].as_u64().map(|i| &doc.meshes[i as usize]);
            mesh.is_some_and(|mesh| mesh.get("weights").is_some())
        })
        .collect();
    if n == 0 || nodes.is_empty() {
        return;
    }
    let (first, last) = (m.years[0], m.years[m.years.len() - 1]);
    let input = Acc { minmax: Some((vec![first], vec![last])), ..Acc::new(FLOAT, "SCALAR", m.years.len()) };
    let input = doc.array(Data::F32(&m.years), None, input);
    let output = Acc::new(FLOAT, "SCALAR", m.weights.len());
    let output = doc.array(Data::F32(&m.weights), None, output);
    let channels: Vec<Value> =
        nodes.iter().map(|&node| json!({"sampler": 0, "target": {"node": node, "path": "weights"}})).collect();
    doc.animations.push(json!({
        "name": "growth",
        "samplers": [{"input": input, "output": output, "interpolation": "LINEAR"}],
        "channels": channels,
        "extras": {"seconds_per_year": 1.0, "key_years": m.years},
    }));
}
