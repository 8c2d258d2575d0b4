//! The JSON objects the core returns beside the buffers, as typed structs: a tree's meta
//! ([`TreeMeta`], with a session update's [`Changes`]), the levels of detail's ([`LodMeta`],
//! [`LodLevelMeta`]) and the leaf inspector's counts ([`LeafInspection`]). The others describe
//! themselves: [`crate::SylvaError`], [`crate::mesh::bark::BarkStyle`], the registry's
//! [`crate::ParamSpec`].
//!
//! **Wire form.** [`to_json`] writes a payload through a [`serde_json::Value`]: object keys come
//! out sorted and `f32` numbers widened to `f64` (`0.1f32` is `0.10000000149011612`), the form
//! these objects have always had (they were built with `serde_json::json!`), so the bytes of a
//! meta never change with the order of a struct's fields. `sylva params --payloads` describes
//! these structs to TypeScript; its test serialises real values and checks every key and value
//! kind against that description.

use crate::mesh::{Bounds, MeshGroup};
use crate::params::Stage;
use serde::Serialize;
use std::collections::BTreeMap;

/// `value` as the core's JSON text (see the module docs: sorted keys, `f32` widened).
pub fn to_json<T: Serialize>(value: &T) -> String {
    // Only maps with non-string keys fail to serialise, and no payload has one.
    serde_json::to_value(value).map(|v| v.to_string()).unwrap_or_else(|e| panic!("a payload serialises: {e}"))
}

/// What a session update changed, relative to the previous successful update of the session.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Changes {
    /// The stems (and envelope, markers) were rebuilt.
    pub skeleton: bool,
    /// The bark buffers differ.
    pub bark: bool,
    /// The leaf matrices or tints differ.
    pub placements: bool,
    /// The leaf mesh drawn per leaf differs.
    pub leaf_mesh: bool,
    /// The leaf shape (texture) differs.
    pub leaf: bool,
    /// The bark's occlusion ([`crate::TreeMesh::shade`]) was computed again (new bark or new
    /// leaves).
    pub shade: bool,
}

impl Changes {
    /// Whether anything at all changed.
    pub fn any(&self) -> bool {
        self.skeleton || self.bark || self.placements || self.leaf_mesh || self.leaf || self.shade
    }
}

/// A tree's meta: everything but the buffers. [`crate::Generated::meta_json`] sets `hash`; a
/// session update ([`crate::session::Current::meta_json`]) sets `preview`, `from` and `changes`
/// instead (its hash comes later, [`crate::session::Session::hash`]). Absent fields are left out
/// of the JSON.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TreeMeta {
    /// Bark vertices.
    pub vertices: usize,
    /// Bark triangles.
    pub triangles: usize,
    /// Stems in the skeleton.
    pub stems: usize,
    /// Tree holes cut into the bark.
    pub holes: usize,
    /// Bounds of the bark.
    pub bounds: Bounds,
    /// The index ranges of the bark mesh by material.
    pub groups: Vec<MeshGroup>,
    /// Crown envelope preview: `[height, radius]` pairs.
    pub envelope: Vec<[f32; 2]>,
    /// Leaves (instances); 0 for a bare tree.
    pub leaves: usize,
    /// Hash of the leaf shape as 16 hex digits.
    pub leaf_hash: String,
    /// Size of the baked leaf texture `[width, height]`, `None` (JSON `null`) when bare.
    pub leaf_texture: Option<[u32; 2]>,
    /// The `bark_type` parameter's index.
    pub bark_type: u8,
    /// Milliseconds per stage, by stage name.
    pub stage_ms: BTreeMap<&'static str, f64>,
    /// Milliseconds of the whole generation or update.
    pub total_ms: f64,
    /// Content hash of the buffers as 16 hex digits (a generation; not a session update).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hash: Option<String>,
    /// A session update: the tree is a drag's preview ([`crate::session::Current::is_preview`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub preview: Option<bool>,
    /// A session update: the first stage it reran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub from: Option<Stage>,
    /// A session update: which buffers differ from the previous update's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub changes: Option<Changes>,
    /// What became of each hand edit, in list order (absent when the tree has no edits).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub edits: Vec<crate::edits::EditReport>,
}

/// One level of detail's counts ([`LodMeta::levels`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LodLevelMeta {
    /// Triangles drawn: bark, plus the leaf mesh's per leaf, plus 2 per cloud quad.
    pub triangles: usize,
    /// Bark vertices.
    pub vertices: usize,
    /// Bark triangles.
    pub bark_triangles: usize,
    /// Leaves (instances).
    pub leaves: usize,
    /// Triangles of the leaf mesh drawn per leaf.
    pub leaf_triangles: usize,
    /// Billboard-cloud quads.
    pub quads: usize,
    /// Stems swept into the bark.
    pub stems: usize,
    /// The index ranges of the bark mesh by material.
    pub groups: Vec<MeshGroup>,
}

/// A tree's levels of detail ([`crate::lod::TreeLods::meta_json`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LodMeta {
    /// Content hash of LOD0 as 16 hex digits (the hash `generate` gives the same parameters).
    pub hash: String,
    /// Bounds of LOD0's bark.
    pub bounds: Bounds,
    /// LOD0, LOD1, LOD2.
    pub levels: Vec<LodLevelMeta>,
    /// Hash of the leaf shape as 16 hex digits.
    pub leaf_hash: String,
    /// Size of the baked leaf texture `[width, height]`, `None` (JSON `null`) when bare.
    pub leaf_texture: Option<[u32; 2]>,
}

/// The leaf inspector's drawing and counts ([`crate::leaf::svg::inspect_json`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LeafInspection {
    /// The SVG drawing.
    pub svg: String,
    /// Vein growth iterations.
    pub iterations: u32,
    /// Vein graph nodes.
    pub nodes: usize,
    /// Vein loop links.
    pub links: usize,
    /// Vein segments drawn at the requested step.
    pub segments: usize,
    /// Auxin sources.
    pub auxins: usize,
    /// Triangles of the leaf blade.
    pub triangles: usize,
    /// Hash of the leaf as 16 hex digits.
    pub hash: String,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wire_form_sorts_keys_and_widens_f32() {
        let b = Bounds { min: [0.1, 0.0, -2.5], max: [1.0, 2.0, 3.0] };
        assert_eq!(to_json(&b), r#"{"max":[1.0,2.0,3.0],"min":[0.10000000149011612,0.0,-2.5]}"#);
        // `serde_json::to_string` would keep the declaration order and print `0.1`.
        assert_eq!(serde_json::to_string(&b).ok().as_deref(), Some(r#"{"min":[0.1,0.0,-2.5],"max":[1.0,2.0,3.0]}"#));
    }
}
