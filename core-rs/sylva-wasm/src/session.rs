//! The live session's binding: [`Session`] keeps the last result of every stage of
//! `sylva_core::session::Session` and hands the current tree's buffers to the worker.

use crate::{PerfClock, ProgressFn};
use sylva_core::params::TreeParams;
use wasm_bindgen::prelude::*;

/// An incremental generator (`sylva_core::session::Session`): it keeps the last result of every
/// stage and reruns only from the first stage an edit touches. The worker owns one; buffer
/// getters copy the current tree's arrays straight into new typed arrays (one copy, which the
/// worker then transfers). Layout of the buffers: see `sylva_core::TreeMesh` and
/// `sylva_core::foliage::Foliage`.
#[wasm_bindgen]
pub struct Session(sylva_core::session::Session);

impl Default for Session {
    fn default() -> Self {
        Session::new()
    }
}

#[wasm_bindgen]
impl Session {
    /// An empty session (the first update generates cold).
    #[wasm_bindgen(constructor)]
    pub fn new() -> Session {
        Session(sylva_core::session::Session::new())
    }

    /// Brings the tree to the parameters of `params_json` (as for [`crate::generate`]) and
    /// returns its meta JSON (`sylva_core::session::Current::meta_json`: counts, `changes`,
    /// `preview`, ...). `preview_budget_ms` >= 0 allows a preview bark when the full one is
    /// predicted to take longer (a slider drag); a negative value asks for the full tree.
    /// `progress` is called with the growth fraction (growth mode). Throws a JSON `SylvaError`
    /// string; the previous tree stays current.
    pub fn update(
        &mut self,
        params_json: &str,
        preview_budget_ms: f64,
        progress: Option<ProgressFn>,
    ) -> Result<String, JsValue> {
        let params = TreeParams::from_json(params_json).map_err(|e| JsValue::from_str(&e.to_json()))?;
        let quality = if preview_budget_ms >= 0.0 {
            sylva_core::session::Quality::Preview { budget_ms: preview_budget_ms }
        } else {
            sylva_core::session::Quality::Full
        };
        let mut report = |f: f32| {
            if let Some(p) = &progress {
                p.call_with(&JsValue::NULL, f);
            }
        };
        self.0
            .update(&params, quality, &PerfClock, Some(&mut report))
            .map(|c| c.meta_json())
            .map_err(|e| JsValue::from_str(&e.to_json()))
    }

    /// The content hash of the current full tree as 16 hex digits (undefined before the first
    /// update or while the bark is a preview).
    pub fn hash(&mut self) -> Option<String> {
        self.0.hash().map(|h| format!("{h:016x}"))
    }

    /// Forgets every cached stage.
    pub fn clear(&mut self) {
        self.0.clear();
    }

    /// The current tree's organ sets (none before the first update).
    pub(crate) fn organs(&self) -> &[sylva_core::organs::OrganSet] {
        self.0.current().map(|c| c.foliage.organs.as_slice()).unwrap_or_default()
    }

    /// How many of the current tree's leaf instances lie on the ground (0 before the first update).
    pub(crate) fn fallen_leaves(&self) -> usize {
        self.0.current().map_or(0, |c| c.foliage.fallen)
    }

    fn current(&self) -> Result<&sylva_core::session::Current, JsValue> {
        self.0.current().ok_or_else(|| JsValue::from_str("no tree yet: call update() first"))
    }

    /// Bark `x, y, z` per vertex.
    pub fn positions(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.bark.mesh.positions.as_slice().into())
    }
    /// Bark unit normals.
    pub fn normals(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.bark.mesh.normals.as_slice().into())
    }
    /// Bark `u, v`.
    pub fn uvs(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.bark.mesh.uvs.as_slice().into())
    }
    /// Bark triangle list (u32).
    pub fn indices(&self) -> Result<js_sys::Uint32Array, JsValue> {
        Ok(self.current()?.bark.mesh.indices.as_slice().into())
    }
    /// Bark wind attributes, 8 floats per vertex ([`crate::GeneratedTree::wind`]).
    pub fn wind(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.bark.mesh.wind.as_slice().into())
    }
    /// The bark's pick boxes: 6 floats per run of 64 triangles, `min x, y, z, max x, y, z`
    /// (`sylva_core::mesh::pick`).
    pub fn pick_boxes(&self) -> Result<js_sys::Float32Array, JsValue> {
        let mesh = &self.current()?.bark.mesh;
        Ok(sylva_core::mesh::pick::pick_boxes(&mesh.positions, &mesh.indices).as_slice().into())
    }
    /// Bark occlusion, one byte per vertex ([`crate::GeneratedTree::shade`]), or empty (a preview).
    pub fn shade(&self) -> Result<js_sys::Uint8Array, JsValue> {
        Ok(self.current()?.bark.mesh.shade.as_slice().into())
    }
    /// Growth mode: the markers (`x, y, z` each).
    pub fn markers(&self) -> Result<js_sys::Float32Array, JsValue> {
        let m = &self.current()?.skeleton.markers;
        let flat: Vec<f32> = m.iter().flat_map(|v| v.to_array()).collect();
        Ok(flat.as_slice().into())
    }
    /// The crown envelope preview as line segments.
    pub fn envelope_lines(&self) -> Result<js_sys::Float32Array, JsValue> {
        let lines = sylva_core::crown::preview_lines(&self.current()?.skeleton.envelope, 16, 48);
        Ok(lines.as_slice().into())
    }
    /// The leaf mesh (leaf units).
    pub fn leaf_positions(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.foliage.mesh.positions.as_slice().into())
    }
    /// The leaf mesh's unit normals.
    pub fn leaf_normals(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.foliage.mesh.normals.as_slice().into())
    }
    /// The leaf mesh's `u, v`.
    pub fn leaf_uvs(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.foliage.mesh.uvs.as_slice().into())
    }
    /// The leaf mesh's triangle list (u32).
    pub fn leaf_indices(&self) -> Result<js_sys::Uint32Array, JsValue> {
        Ok(self.current()?.foliage.mesh.indices.as_slice().into())
    }
    /// Per-leaf 4x4 matrices, column-major.
    pub fn leaf_matrices(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.foliage.matrices.as_slice().into())
    }
    /// Per-leaf RGB tint.
    pub fn leaf_colors(&self) -> Result<js_sys::Float32Array, JsValue> {
        Ok(self.current()?.foliage.colors.as_slice().into())
    }
    /// The baked leaf colour texture (RGBA8; size in the meta's `leaf_texture`; empty when bare).
    pub fn leaf_texture(&self) -> Result<js_sys::Uint8Array, JsValue> {
        let t = self.current()?.foliage.texture().map(|t| t.color.as_slice()).unwrap_or_default();
        Ok(t.into())
    }
}
