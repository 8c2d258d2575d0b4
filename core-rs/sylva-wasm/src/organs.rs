//! The tree's flowers, fruit, catkins and buds (`sylva_core::organs::OrganSet`, one set per kind
//! of part) for both APIs: [`crate::GeneratedTree`] and [`crate::Session`]. Only conversion.
//!
//! A tree has `organ_count()` sets, numbered `0..organ_count()`; an index out of range gives
//! empty arrays. Per set `i`:
//! - `organs_json()`: `[{"kind", "name", "color": [r, g, b], "roughness", "count"}]`, one object
//!   per set in index order: `kind` is `"petals"` | `"flower_centre"` | `"catkin"` | `"bud"` |
//!   `"fruit"` | `"fruit_part"` | `"stalk"`; `color` the material's base colour in sRGB (0..1);
//!   `roughness` 0..1; `count` the number of instances.
//! - `organ_positions(i)`: the part's mesh in metres, `x, y, z` per vertex (its attachment at
//!   the origin, pointing along `+y`).
//! - `organ_normals(i)`: unit normal per vertex, `x, y, z`.
//! - `organ_indices(i)`: the triangle list (u32, three per triangle). Draw both sides.
//! - `organ_matrices(i)`: per instance a 4×4 matrix, column-major, 16 floats (rotation × axis
//!   scale in the first three columns, translation in the fourth: the leaves' layout).
//! - `organ_colors(i)`: per instance an RGB tint, 3 floats, linear light, multiplying `color`.
//!
//! And `fallen()`: how many of the leaf instances, at the end of `leaf_matrices` and
//! `leaf_colors`, lie on the ground (**Fallen Leaves**); the ones before them are on the tree.

use crate::{GeneratedTree, Session};
use sylva_core::organs::OrganSet;
use wasm_bindgen::prelude::*;

/// The sets as the JSON of the module doc.
fn sets_json(sets: &[OrganSet]) -> String {
    let list: Vec<serde_json::Value> = sets
        .iter()
        .map(|s| {
            serde_json::json!({
                "kind": s.kind,
                "name": s.name,
                "color": s.color,
                "roughness": s.roughness,
                "count": s.count(),
            })
        })
        .collect();
    serde_json::Value::Array(list).to_string()
}

/// Set `i`'s arrays (empty for an index out of range).
fn field<T: Copy>(sets: &[OrganSet], i: usize, get: impl Fn(&OrganSet) -> &[T]) -> &[T] {
    sets.get(i).map(get).unwrap_or_default()
}

#[wasm_bindgen]
impl GeneratedTree {
    /// How many leaf instances, the last ones, lie on the ground (`Foliage::fallen`).
    pub fn fallen(&self) -> usize {
        self.0.foliage.fallen
    }
    /// Number of organ sets (see the module doc of `organs.rs` for every layout).
    pub fn organ_count(&self) -> usize {
        self.0.foliage.organs.len()
    }
    /// The sets' kind, name, sRGB colour, roughness and instance count as a JSON array.
    pub fn organs_json(&self) -> String {
        sets_json(&self.0.foliage.organs)
    }
    /// Set `i`'s mesh in metres, `x, y, z` per vertex.
    pub fn organ_positions(&self, i: usize) -> Vec<f32> {
        field(&self.0.foliage.organs, i, |s| &s.mesh.positions).to_vec()
    }
    /// Set `i`'s unit normals, `x, y, z` per vertex.
    pub fn organ_normals(&self, i: usize) -> Vec<f32> {
        field(&self.0.foliage.organs, i, |s| &s.mesh.normals).to_vec()
    }
    /// Set `i`'s triangle list (u32).
    pub fn organ_indices(&self, i: usize) -> Vec<u32> {
        field(&self.0.foliage.organs, i, |s| &s.mesh.indices).to_vec()
    }
    /// Set `i`'s per-instance 4×4 matrices, column-major, 16 floats each.
    pub fn organ_matrices(&self, i: usize) -> Vec<f32> {
        field(&self.0.foliage.organs, i, |s| &s.matrices).to_vec()
    }
    /// Set `i`'s per-instance RGB tints (linear, multiplying the set's colour), 3 floats each.
    pub fn organ_colors(&self, i: usize) -> Vec<f32> {
        field(&self.0.foliage.organs, i, |s| &s.colors).to_vec()
    }
}

#[wasm_bindgen]
impl Session {
    /// How many leaf instances of the current tree, the last ones, lie on the ground.
    pub fn fallen(&self) -> usize {
        self.fallen_leaves()
    }
    /// Number of organ sets of the current tree (0 before the first update).
    pub fn organ_count(&self) -> usize {
        self.organs().len()
    }
    /// The current sets' kind, name, sRGB colour, roughness and instance count as a JSON array.
    pub fn organs_json(&self) -> String {
        sets_json(self.organs())
    }
    /// Set `i`'s mesh in metres, `x, y, z` per vertex.
    pub fn organ_positions(&self, i: usize) -> js_sys::Float32Array {
        field(self.organs(), i, |s| &s.mesh.positions).into()
    }
    /// Set `i`'s unit normals, `x, y, z` per vertex.
    pub fn organ_normals(&self, i: usize) -> js_sys::Float32Array {
        field(self.organs(), i, |s| &s.mesh.normals).into()
    }
    /// Set `i`'s triangle list (u32).
    pub fn organ_indices(&self, i: usize) -> js_sys::Uint32Array {
        field(self.organs(), i, |s| &s.mesh.indices).into()
    }
    /// Set `i`'s per-instance 4×4 matrices, column-major, 16 floats each.
    pub fn organ_matrices(&self, i: usize) -> js_sys::Float32Array {
        field(self.organs(), i, |s| &s.matrices).into()
    }
    /// Set `i`'s per-instance RGB tints (linear, multiplying the set's colour), 3 floats each.
    pub fn organ_colors(&self, i: usize) -> js_sys::Float32Array {
        field(self.organs(), i, |s| &s.colors).into()
    }
}
