//! One level of detail as a GLB (`sylva_core::export::lod_level_glb`): the app's LOD zip holds
//! LOD0, LOD1 and LOD2 as three files, written here from the levels `generate_lods` made.

use crate::{export_options, GeneratedLods};
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
impl GeneratedLods {
    /// Level `level` (0, 1, 2) as a glTF 2.0 binary: root node `name` with child
    /// `<name>_LOD<level>` (screen sizes in `extras.sylva_lod`, docs/formats.md). `options_json`
    /// takes the same fields as `GeneratedTree.to_glb` (`leaves`, `strict`, ...). Throws a JSON
    /// `SylvaError` string on bad options.
    pub fn to_glb_level(&self, level: usize, name: &str, options_json: &str) -> Result<Vec<u8>, JsValue> {
        let opts = export_options(options_json)?;
        Ok(sylva_core::export::lod_level_glb(&self.0, &opts, name, level))
    }
}
