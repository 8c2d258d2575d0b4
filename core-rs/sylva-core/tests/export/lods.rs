//! The levels of detail in one GLB (`export::lods_glb`): nodes `NAME_LOD0..2` under one root,
//! each level's meshes and counts, the screen sizes in `extras`, shared textures stored once.

use super::*;
use sylva_core::export::{lod_level_glb, lods_glb, LOD_SCREEN_SIZES};
use sylva_core::lod::{lods_of, TreeLods};

fn lods(name: &str) -> TreeLods {
    let p = presets::find(name).expect("preset").params().expect("params");
    lods_of(generate(&p).expect("generate"), &p.mesh).expect("lods")
}

/// The children of node `i`, as node values.
fn children(glb: &Glb, i: usize) -> Vec<&Value> {
    let nodes = glb.json["nodes"].as_array().unwrap();
    nodes[i]["children"].as_array().unwrap().iter().map(|c| &nodes[c.as_u64().unwrap() as usize]).collect()
}

#[test]
fn lod_glb_has_the_three_levels_as_named_nodes() {
    let l = lods("grown_bushy");
    let bytes = lods_glb(&l, &ExportOptions::default(), "oak");
    assert!(bytes == lods_glb(&l, &ExportOptions::default(), "oak"), "deterministic");
    let glb = parse(&bytes);
    glb.check_layout();
    let root = &glb.json["nodes"][0];
    assert_eq!(glb.json["scenes"][0]["nodes"], serde_json::json!([0]));
    assert_eq!(root["name"], "oak");
    let sizes: Vec<f32> = root["extras"]["sylva_lod"]["screen_sizes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap() as f32)
        .collect();
    assert_eq!(sizes, LOD_SCREEN_SIZES);
    let levels = children(&glb, 0);
    let names: Vec<&str> = levels.iter().map(|n| n["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["oak_LOD0", "oak_LOD1", "oak_LOD2"]);
    let json_nodes = glb.json["nodes"].as_array().unwrap();
    for (i, level) in levels.iter().enumerate() {
        assert_eq!(level["extras"]["sylva_lod"]["level"], i);
        let kids: Vec<&Value> =
            level["children"].as_array().unwrap().iter().map(|c| &json_nodes[c.as_u64().unwrap() as usize]).collect();
        let mesh = |name: &str| {
            let n = kids.iter().find(|n| n["name"] == name).unwrap_or_else(|| panic!("LOD{i} {name}"));
            &glb.json["meshes"][n["mesh"].as_u64().unwrap() as usize]
        };
        let lvl = l.level(i);
        assert_eq!(glb.index_count(mesh("bark")), lvl.mesh.indices.len() as u64, "LOD{i} bark");
        // Leaves: instanced, one instance per leaf (LOD2: per cloud quad).
        let leaves = kids.iter().find(|n| n["name"] == "leaves").unwrap();
        let translation =
            leaves["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"].as_u64().unwrap();
        let count = if i == 2 { lvl.cloud.len() / sylva_core::lod::QUAD_FLOATS } else { lvl.foliage.count() };
        assert!(count > 0);
        assert_eq!(glb.accessor(translation)["count"], count, "LOD{i} leaves");
    }
    // The levels share the bark and leaf textures: each image's bytes are stored once.
    let images = glb.json["images"].as_array().unwrap();
    let mut views: Vec<u64> = images.iter().map(|i| i["bufferView"].as_u64().unwrap()).collect();
    views.sort_unstable();
    views.dedup();
    let lod0 = parse(&export::to_glb(&l.lod0, &ExportOptions::default()));
    assert_eq!(views.len(), lod0.json["images"].as_array().unwrap().len());
    let bark = images.iter().filter(|i| i["name"].as_str().unwrap().starts_with("bark")).count();
    assert_eq!(images.len(), 2 * views.len() + bark / 3, "LOD0 and LOD1 have every texture, LOD2 the bark's");
}

#[test]
fn strict_lod_glb_needs_no_extension() {
    let l = lods("grown_bushy");
    let glb = parse(&lods_glb(&l, &ExportOptions { strict: true, ..Default::default() }, "tree"));
    glb.check_layout();
    assert!(glb.json.get("extensionsUsed").is_none() && glb.json.get("extensionsRequired").is_none());
    let cloud = l.lod2.cloud.len() / sylva_core::lod::QUAD_FLOATS;
    let lod2 = children(&glb, 0)[2]["children"].as_array().unwrap().clone();
    let leaves = lod2.iter().map(|c| &glb.json["nodes"][c.as_u64().unwrap() as usize]).find(|n| n["name"] == "leaves");
    let mesh = &glb.json["meshes"][leaves.unwrap()["mesh"].as_u64().unwrap() as usize];
    assert_eq!(glb.index_count(mesh), 6 * cloud as u64, "two triangles per cloud quad");
}

#[test]
fn lod_screen_sizes_are_the_viewers() {
    let ts = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../web/src/lod/selection.ts")).unwrap();
    let line = ts.lines().find(|l| l.contains("VIEWER_THRESHOLDS:")).expect("VIEWER_THRESHOLDS");
    let inner = &line[line.rfind('[').unwrap() + 1..line.rfind(']').unwrap()];
    let values: Vec<f32> = inner.split(',').map(|v| v.trim().parse().unwrap()).collect();
    assert_eq!(values, LOD_SCREEN_SIZES);
}

#[test]
fn one_level_glb_holds_that_level_alone() {
    let l = lods("grown_bushy");
    let opts = ExportOptions::default();
    let mut bark_vertices = Vec::new();
    for i in 0..3 {
        let bytes = lod_level_glb(&l, &opts, "oak", i);
        assert!(bytes == lod_level_glb(&l, &opts, "oak", i), "deterministic");
        let glb = parse(&bytes);
        glb.check_layout();
        let root = &glb.json["nodes"][0];
        assert_eq!(root["name"], "oak");
        assert_eq!(root["extras"]["sylva_lod"]["screen_sizes"].as_array().unwrap().len(), 3);
        let levels = children(&glb, 0);
        assert_eq!(levels.len(), 1);
        assert_eq!(levels[0]["name"], format!("oak_LOD{i}"));
        assert_eq!(levels[0]["extras"]["sylva_lod"]["level"], i);
        let bark = levels[0]["children"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| &glb.json["nodes"][c.as_u64().unwrap() as usize])
            .find(|n| n["name"] == "bark")
            .expect("bark node");
        let mesh = &glb.json["meshes"][bark["mesh"].as_u64().unwrap() as usize];
        assert_eq!(glb.index_count(mesh), l.level(i).mesh.indices.len() as u64, "LOD{i} bark");
        let position = mesh["primitives"][0]["attributes"]["POSITION"].as_u64().unwrap();
        bark_vertices.push(glb.accessor(position)["count"].as_u64().unwrap());
    }
    assert!(bark_vertices[0] > bark_vertices[1] && bark_vertices[1] > bark_vertices[2], "{bark_vertices:?}");
    // A larger level is LOD2; strict files need no extension.
    assert!(lod_level_glb(&l, &opts, "oak", 7) == lod_level_glb(&l, &opts, "oak", 2));
    let strict = parse(&lod_level_glb(&l, &ExportOptions { strict: true, ..Default::default() }, "tree", 1));
    strict.check_layout();
    assert!(strict.json.get("extensionsUsed").is_none() && strict.json.get("extensionsRequired").is_none());
}
