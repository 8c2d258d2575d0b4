//! What an export contains ([`ExportOptions`], with [`LeafMode`] for the leaves): the one place
//! the defaults live, and their JSON form. A module of its own so that the writers ([`super::glb`],
//! [`super::obj`]) read it without importing back from [`super`], which calls them.

use crate::error::SylvaError;

/// How the leaves are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LeafMode {
    /// One leaf mesh drawn once per leaf (GLB: `EXT_mesh_gpu_instancing`, per-leaf TRS and
    /// colour). OBJ has no instancing and writes the leaves baked instead.
    #[default]
    Instanced,
    /// Every leaf transformed into one mesh, with the per-leaf colour as a vertex colour.
    Baked,
    /// No leaves.
    None,
}

impl LeafMode {
    /// The mode for a name: `instanced`, `baked` or `none` (any case).
    pub fn from_name(name: &str) -> Option<LeafMode> {
        match name.to_ascii_lowercase().as_str() {
            "instanced" => Some(LeafMode::Instanced),
            "baked" => Some(LeafMode::Baked),
            "none" => Some(LeafMode::None),
            _ => None,
        }
    }
}

/// What an export contains. The defaults ([`ExportOptions::default`]) give the complete file.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportOptions {
    /// How leaves are written. Default [`LeafMode::Instanced`].
    pub leaves: LeafMode,
    /// Write the wind attributes (`_WIND_PIVOT`, `_WIND_PARAMS`) when the mesh has wind data.
    /// Default `true`.
    pub wind: bool,
    /// Embed (GLB) or reference (OBJ) the baked textures. Default `true`.
    pub textures: bool,
    /// With `textures`: the normal maps. Default `true`.
    pub normal_maps: bool,
    /// With `normal_maps`: per-vertex tangents (GLB `TANGENT`, 4 bytes per vertex). Default
    /// `true`. Without them viewers compute their own (the glTF 2.0 specification asks for
    /// MikkTSpace; the Khronos validator warns that such a tangent space may differ between
    /// implementations); computing them is the most expensive part of a big export.
    pub tangents: bool,
    /// Per-vertex colours (`COLOR_0`): bark tint, baked leaf colours. Default `true`.
    pub vertex_colors: bool,
    /// Edge of the square bark textures in texels, a power of two from 16 to 2048. Default 512.
    pub bark_texture_size: u32,
    /// GLB only: a file that needs no glTF extension, for strict importers (Godot, engines
    /// without `KHR_mesh_quantization`): `NORMAL` and `TANGENT` as floats (16 more bytes per
    /// vertex with tangents, 8 without) and [`LeafMode::Instanced`] leaves written baked
    /// (`EXT_mesh_gpu_instancing` is an extension too); no `extensionsUsed` or
    /// `extensionsRequired`. Default `false`.
    pub strict: bool,
}

impl Default for ExportOptions {
    fn default() -> Self {
        ExportOptions {
            leaves: LeafMode::Instanced,
            wind: true,
            textures: true,
            normal_maps: true,
            tangents: true,
            vertex_colors: true,
            bark_texture_size: 512,
            strict: false,
        }
    }
}

impl ExportOptions {
    /// Options from a JSON object; missing fields keep their defaults, e.g.
    /// `{"leaves": "baked", "wind": false, "bark_texture_size": 256, "strict": true}`. An empty string means
    /// all defaults. Unknown fields and wrong types are errors.
    pub fn from_json(json: &str) -> Result<ExportOptions, SylvaError> {
        let mut o = ExportOptions::default();
        if json.trim().is_empty() {
            return Ok(o);
        }
        let bad = |message: String| SylvaError::Input { message };
        let v: serde_json::Value =
            serde_json::from_str(json).map_err(|e| bad(format!("export options are not JSON: {e}")))?;
        let map = v.as_object().ok_or_else(|| bad("export options must be a JSON object".into()))?;
        for (k, v) in map {
            let flag = || v.as_bool().ok_or_else(|| bad(format!("export option '{k}' must be true or false")));
            match k.as_str() {
                "leaves" => {
                    o.leaves = v.as_str().and_then(LeafMode::from_name).ok_or_else(|| {
                        bad(format!("export option 'leaves' must be \"instanced\", \"baked\" or \"none\", got {v}"))
                    })?
                }
                "wind" => o.wind = flag()?,
                "textures" => o.textures = flag()?,
                "normal_maps" => o.normal_maps = flag()?,
                "tangents" => o.tangents = flag()?,
                "vertex_colors" => o.vertex_colors = flag()?,
                "strict" => o.strict = flag()?,
                "bark_texture_size" => {
                    o.bark_texture_size =
                        v.as_u64().filter(|&s| (16..=2048).contains(&s) && s.is_power_of_two()).ok_or_else(|| {
                            bad(format!("export option 'bark_texture_size' must be a power of two 16..2048, got {v}"))
                        })? as u32
                }
                other => return Err(bad(format!("unknown export option '{other}'"))),
            }
        }
        Ok(o)
    }
}
