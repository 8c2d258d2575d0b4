//! A level's leaves baked into one mesh by the core's exporter (`sylva_core::export::bake_leaves`,
//! what a GLB's `--leaves baked` holds): the forest draws each tree's leaves as one geometry
//! (three.js cannot instance an `InstancedMesh`), and the LOD worker hands it over ready to wrap.

use crate::GeneratedLods;
use sylva_core::export::{bake_leaves, BakedLeaves};
use wasm_bindgen::prelude::*;

/// Baked leaves: tree-space positions, unit normals, uvs, the triangle list, and each leaf's
/// RGB tint repeated on its vertices.
#[wasm_bindgen]
pub struct BakedLeafMesh {
    baked: BakedLeaves,
    colors: Vec<f32>,
}

#[wasm_bindgen]
impl BakedLeafMesh {
    /// `x, y, z` per vertex (metres, tree space).
    pub fn positions(&self) -> js_sys::Float32Array {
        self.baked.mesh.positions.as_slice().into()
    }
    /// Unit normals (transformed by each leaf's inverse transpose).
    pub fn normals(&self) -> js_sys::Float32Array {
        self.baked.mesh.normals.as_slice().into()
    }
    /// `u, v` per vertex (the leaf texture's).
    pub fn uvs(&self) -> js_sys::Float32Array {
        self.baked.mesh.uvs.as_slice().into()
    }
    /// The triangle list (u32).
    pub fn indices(&self) -> js_sys::Uint32Array {
        self.baked.mesh.indices.as_slice().into()
    }
    /// RGB per vertex: its leaf's tint as the instanced leaves have it (floats, not the GLB's
    /// RGBA8, so the picture is the instanced one's).
    pub fn colors(&self) -> js_sys::Float32Array {
        self.colors.as_slice().into()
    }
}

#[wasm_bindgen]
impl GeneratedLods {
    /// The leaves of `level` (0, 1, 2) baked into one mesh ([`BakedLeafMesh`]; empty for LOD2
    /// and bare trees).
    pub fn baked_leaves(&self, level: usize) -> BakedLeafMesh {
        let foliage = &self.0.level(level).foliage;
        let baked = bake_leaves(foliage, false);
        let per_leaf = foliage.mesh.positions.len() / 3;
        let colors =
            foliage.colors.chunks_exact(3).flat_map(|rgb| rgb.iter().copied().cycle().take(3 * per_leaf)).collect();
        BakedLeafMesh { baked, colors }
    }
}
