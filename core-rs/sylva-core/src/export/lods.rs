//! # Levels of detail as GLB
//!
//! [`lods_glb`]: the three mesh levels of [`crate::lod`] in one file, each written as its own
//! GLB ([`super::glb::write`], same options) and merged ([`super::glb::merge`]) under one root
//! node: `<name>_LOD0`, `<name>_LOD1`, `<name>_LOD2`, the names Unity's model importer turns
//! into a LODGroup (docs/formats.md says how each engine takes them). [`lod_level_glb`]: one
//! level alone, the same root node and `extras` with that level's node only (the app's LOD
//! zip holds one such file per level).
//!
//! * **LOD0**: the tree as [`super::glb::write`] writes it.
//! * **LOD1**: the lighter bark sweep and every third leaf (larger), same materials, and every
//!   flower, fruit, catkin and bud (the organ sets of LOD0).
//! * Organ sets are left out of LOD2 ([`crate::lod`]).
//! * **LOD2**: the trunk and main branches, and the billboard cloud as leaves: each quad one
//!   "leaf" (corners `centre ± u ± v`, the cluster's tint as its colour) on an untextured
//!   double-sided `leaves` material (the app paints a leaf-clump texture on the cloud in the
//!   browser; the file has none, and leaves out the quads' `density`).
//!
//! The root node's `extras.sylva_lod` holds the screen-size thresholds ([`LOD_SCREEN_SIZES`])
//! and how they are measured; each level node's `extras.sylva_lod` its level and the screen
//! size down to which it is shown. The impostor (an atlas the app bakes with WebGL) is not in
//! this file.

use super::glb::merge::{merge, Part};
use super::ExportOptions;
use crate::foliage::Foliage;
use crate::lod::{TreeLods, QUAD_FLOATS};
use crate::mesh::{Material, MeshGroup, TreeMesh};
use crate::Generated;
use serde_json::json;

/// Screen sizes below which LOD0, LOD1 and LOD2 give way to the next level (LOD2 to the
/// impostor, or nothing): the viewer's thresholds (`VIEWER_THRESHOLDS` in
/// web/src/lod/selection.ts). The measure is the bounding radius over the half height of the
/// view at the tree's distance, `R / (d · tan(fov / 2))`: the tree's height on screen as a
/// fraction of the screen's, which is what Unity's LODGroup transition heights are.
pub const LOD_SCREEN_SIZES: [f32; 3] = [0.6, 0.4, 0.28];

/// How [`LOD_SCREEN_SIZES`] are measured, written next to them.
const MEASURE: &str = "screen size = bounding radius / (distance * tan(vertical fov / 2)), about the tree's height on screen over the screen height (Unity LODGroup transition height); a level is shown down to its screen_size, then the next one";

/// The levels of `l` as one GLB (module docs); `name` names the root node and prefixes the
/// level nodes.
pub fn lods_glb(l: &TreeLods, opts: &ExportOptions, name: &str) -> Vec<u8> {
    let parts: Vec<Part> = (0..3).map(|i| level_part(l, opts, name, i)).collect();
    merge(name, root_extras(), &parts)
}

/// Level `level` (0, 1 or 2; larger is taken as 2) of `l` alone as a GLB: root node `name`
/// (with the screen sizes in `extras.sylva_lod`, as in [`lods_glb`]) whose one child
/// `<name>_LOD<level>` holds the level's `bark` and `leaves` nodes and its own `extras`.
pub fn lod_level_glb(l: &TreeLods, opts: &ExportOptions, name: &str, level: usize) -> Vec<u8> {
    merge(name, root_extras(), &[level_part(l, opts, name, level.min(2))])
}

/// The root node's `extras`: the screen-size thresholds and how they are measured.
fn root_extras() -> serde_json::Value {
    let sizes: Vec<f64> = LOD_SCREEN_SIZES.iter().map(|&s| decimal(s)).collect();
    json!({"sylva_lod": {"screen_sizes": sizes, "measure": MEASURE}})
}

/// Level `i` (0, 1, 2) written as its own GLB, named `<name>_LOD<i>`, with its `extras`.
fn level_part(l: &TreeLods, opts: &ExportOptions, name: &str, i: usize) -> Part {
    let g = &l.lod0;
    let glb = match i {
        0 => super::glb::write(g, opts),
        1 => super::glb::write(&level_tree(g, l.lod1.mesh.clone(), l.lod1.foliage.clone()), opts),
        _ => super::glb::write(&level_tree(g, l.lod2.mesh.clone(), cloud_foliage(&l.lod2.cloud)), opts),
    };
    Part {
        name: format!("{name}_LOD{i}"),
        extras: json!({"sylva_lod": {"level": i, "screen_size": decimal(LOD_SCREEN_SIZES[i])}}),
        glb,
    }
}

/// `x` as the decimal it is written as (0.6, not 0.6000000238418579, the `f32`'s exact value).
fn decimal(x: f32) -> f64 {
    x.to_string().parse().unwrap_or(f64::from(x))
}

/// A tree to write for a reduced level: `lod0`'s skeleton, bark type and hash with the level's
/// bark and leaves.
fn level_tree(lod0: &Generated, mesh: TreeMesh, foliage: Foliage) -> Generated {
    Generated {
        mesh,
        foliage,
        skeleton: lod0.skeleton.clone(),
        bounds: lod0.bounds,
        hash: lod0.hash,
        stats: lod0.stats.clone(),
        envelope: Vec::new(),
        markers: Vec::new(),
        holes: Vec::new(),
        bark: lod0.bark,
        edits: Vec::new(),
    }
}

/// The billboard cloud ([`QUAD_FLOATS`] floats per quad) as foliage: a unit quad (corners
/// `(±1, ±1, 0)`, normal +z) placed by one matrix per quad with columns `u`, `v`, their unit
/// normal and the centre, tinted with the quad's colour; no leaf texture.
fn cloud_foliage(cloud: &[f32]) -> Foliage {
    let mesh = TreeMesh {
        positions: vec![-1.0, -1.0, 0.0, 1.0, -1.0, 0.0, 1.0, 1.0, 0.0, -1.0, 1.0, 0.0],
        normals: [0.0, 0.0, 1.0].repeat(4),
        uvs: vec![0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
        indices: vec![0, 1, 2, 0, 2, 3],
        groups: vec![MeshGroup { material: Material::Leaves, start: 0, count: 6 }],
        ..TreeMesh::default()
    };
    let (mut matrices, mut colors) = (Vec::new(), Vec::new());
    for q in cloud.chunks_exact(QUAD_FLOATS) {
        let (c, u, v) =
            (glam::Vec3::from_slice(&q[0..3]), glam::Vec3::from_slice(&q[3..6]), glam::Vec3::from_slice(&q[6..9]));
        let n = crate::math::unit_or(u.cross(v), || glam::Vec3::Y);
        matrices.extend_from_slice(
            &glam::Mat4::from_cols(u.extend(0.0), v.extend(0.0), n.extend(0.0), c.extend(1.0)).to_cols_array(),
        );
        colors.extend_from_slice(&q[9..12]);
    }
    Foliage { mesh, matrices, colors, ..Foliage::bare() }
}
