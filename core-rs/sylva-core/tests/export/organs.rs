//! Flowers, fruit, catkins and buds in the exported files: an oak in September carries its
//! acorns, cups and stalks as one node, mesh and material per organ set, instanced (tints as
//! `_COLOR_0`, float for float) or baked (tints as `COLOR_0` bytes, every instance's copy of
//! the part), and in the OBJ as objects of their own; a tree without parts (July) writes no
//! organ node, and the parts only append to what the file held without them.

use super::*;
use sylva_core::export::organs::{bake_set, linear_color};

/// The oak preset bearing acorns (the Fruit parameter) in month `month`.
fn oak_params(month: f32) -> TreeParams {
    let mut p = presets::find("oak").unwrap().params().unwrap();
    p.foliage.season = month;
    p.foliage.fruit = sylva_core::params::Fruit::Acorns;
    p
}

fn oak_at(month: f32) -> Generated {
    let g = generate(&oak_params(month)).unwrap();
    assert!(g.foliage.organs.iter().any(|s| s.name == "acorns" && s.count() > 0), "the oak bears acorns");
    g
}

/// The material named `name`.
fn material<'a>(glb: &'a Glb, name: &str) -> &'a Value {
    glb.json["materials"].as_array().unwrap().iter().find(|m| m["name"] == name).unwrap()
}

/// Each set's material: its name, linear colour `base`, roughness, two-sided, untextured.
fn check_material(glb: &Glb, set: &sylva_core::organs::OrganSet, base: [f32; 3]) {
    let m = material(glb, set.name);
    assert_eq!(m["doubleSided"], true, "{}", set.name);
    let pbr = &m["pbrMetallicRoughness"];
    let factor: Vec<f32> =
        pbr["baseColorFactor"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap() as f32).collect();
    assert_eq!(factor, [base[0], base[1], base[2], 1.0], "{}", set.name);
    assert_eq!(pbr["roughnessFactor"].as_f64().unwrap() as f32, set.roughness);
    assert_eq!(pbr["metallicFactor"], 0.0);
    assert!(pbr.get("baseColorTexture").is_none());
}

#[test]
fn an_oak_in_september_exports_its_acorns_instanced() {
    let g = oak_at(9.5);
    let names: Vec<&str> = g.foliage.organs.iter().map(|s| s.name).collect();
    assert!(names.contains(&"acorns"), "{names:?}");
    assert!(g.foliage.organs.len() >= 3, "acorns, cups and stalks: {names:?}");
    let glb = parse(&export::to_glb(&g, &ExportOptions::default()));
    glb.check_layout();
    let used = glb.json["extensionsUsed"].as_array().unwrap();
    assert!(used.iter().any(|e| e == "EXT_mesh_gpu_instancing"));
    let children = glb.json["nodes"][0]["children"].as_array().unwrap();
    for set in &g.foliage.organs {
        let node = glb.node(set.name).unwrap_or_else(|| panic!("node {}", set.name));
        let k = glb.json["nodes"].as_array().unwrap().iter().position(|n| n == node).unwrap();
        assert!(children.iter().any(|c| c.as_u64() == Some(k as u64)), "{} under sylva_tree", set.name);
        let inst = &node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
        let t = glb.floats(inst["TRANSLATION"].as_u64().unwrap());
        assert_eq!(t.len(), set.count());
        for (p, m) in t.iter().zip(set.matrices.chunks_exact(16)) {
            assert_eq!(p[..], m[12..15]);
        }
        let tints: Vec<f32> = glb.floats(inst["_COLOR_0"].as_u64().unwrap()).concat();
        assert_eq!(tints, set.colors, "{}", set.name);
        // The mesh is the set's part, once: one primitive of the set's material.
        let mesh = glb.mesh_of(set.name);
        assert_eq!(mesh["name"], set.name);
        let prims = mesh["primitives"].as_array().unwrap();
        assert_eq!(prims.len(), 1);
        let pos = glb.accessor(prims[0]["attributes"]["POSITION"].as_u64().unwrap());
        assert_eq!(pos["count"].as_u64().unwrap() as usize, set.mesh.vertex_count());
        assert_eq!(glb.index_count(mesh) as usize, set.mesh.indices.len());
        assert_eq!(glb.json["materials"][prims[0]["material"].as_u64().unwrap() as usize]["name"], set.name);
        check_material(&glb, set, linear_color(set));
    }
    // Acorns are brown-green: more red than blue, in the file's linear factor too.
    let acorn = material(&glb, "acorns")["pbrMetallicRoughness"]["baseColorFactor"].clone();
    assert!(acorn[0].as_f64() > acorn[2].as_f64(), "{acorn}");
}

#[test]
fn an_oak_in_september_exports_its_acorns_baked_in_both_baked_modes() {
    let g = oak_at(9.5);
    let baked = ExportOptions { leaves: LeafMode::Baked, ..Default::default() };
    let strict = ExportOptions { strict: true, ..Default::default() };
    for opts in [baked, strict] {
        let glb = parse(&export::to_glb(&g, &opts));
        glb.check_layout();
        if opts.strict {
            assert!(glb.json.get("extensionsUsed").is_none(), "a strict file lists no extension");
        }
        for set in &g.foliage.organs {
            let b = bake_set(set);
            let node = glb.node(set.name).unwrap();
            assert!(node.get("extensions").is_none(), "{} is baked", set.name);
            let mesh = glb.mesh_of(set.name);
            let attrs = &mesh["primitives"][0]["attributes"];
            let nv = set.mesh.vertex_count();
            let pos = glb.floats(attrs["POSITION"].as_u64().unwrap());
            assert_eq!(pos.len(), nv * set.count(), "{}: every instance's copy", set.name);
            assert_eq!(pos.concat(), b.baked.mesh.positions);
            assert_eq!(glb.index_count(mesh) as usize, set.mesh.indices.len() * set.count());
            // The tints survive as vertex colours: each instance's vertices carry its tint.
            let a = glb.accessor(attrs["COLOR_0"].as_u64().unwrap());
            let v = &glb.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
            let at = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
            let scale = export::organs::tint_scale(set);
            for (k, tint) in set.colors.chunks_exact(3).enumerate() {
                let want: Vec<u8> =
                    tint.iter().zip(scale).map(|(&t, s)| ((t / s).clamp(0.0, 1.0) * 255.0 + 0.5) as u8).collect();
                for v in 0..nv {
                    assert_eq!(glb.bin[at + 4 * (k * nv + v)..][..3], want[..], "{} instance {k}", set.name);
                }
            }
            check_material(&glb, set, b.base);
        }
    }
}

#[test]
fn a_tree_in_july_writes_no_organ_and_parts_only_append() {
    let july = preset("oak");
    assert!(july.foliage.organs.is_empty());
    let september = oak_at(9.5);
    let mut without = september.clone();
    without.foliage.organs.clear();
    for opts in [
        ExportOptions::default(),
        ExportOptions { leaves: LeafMode::Baked, ..Default::default() },
        ExportOptions { strict: true, ..Default::default() },
    ] {
        let glb = parse(&export::to_glb(&july, &opts));
        let names: Vec<&str> =
            glb.json["nodes"].as_array().unwrap().iter().map(|n| n["name"].as_str().unwrap()).collect();
        assert_eq!(names, ["sylva_tree", "bark", "leaves"], "{opts:?}");
        assert_eq!(glb.json["materials"].as_array().unwrap().len(), 2);
        // The file with parts holds the file without them, then the parts.
        let (a, b) = (parse(&export::to_glb(&without, &opts)), parse(&export::to_glb(&september, &opts)));
        for key in ["nodes", "meshes", "materials"] {
            let (short, long) = (a.json[key].as_array().unwrap(), b.json[key].as_array().unwrap());
            let n = september.foliage.organs.len();
            assert_eq!(long.len(), short.len() + n, "{key}");
            if key != "nodes" {
                assert_eq!(long[..short.len()], short[..], "{key}");
            }
        }
    }
    // Leaves left out: no parts either.
    let bare = parse(&export::to_glb(&september, &ExportOptions { leaves: LeafMode::None, ..Default::default() }));
    assert!(september.foliage.organs.iter().all(|s| bare.node(s.name).is_none()));
}

#[test]
fn the_obj_has_an_object_and_a_material_per_set() {
    let g = oak_at(9.5);
    let o = ExportOptions::default();
    let files = export::obj::write(&g, &o, "oak");
    let leaves_only = {
        let mut w = g.clone();
        w.foliage.organs.clear();
        export::obj::obj(&w, &o, "oak")
    };
    let faces = |t: &str| t.lines().filter(|l| l.starts_with("f ")).count();
    let parts: usize = g.foliage.organs.iter().map(|s| s.mesh.triangle_count() * s.count()).sum();
    assert_eq!(faces(&files.obj), faces(&leaves_only) + parts);
    for set in &g.foliage.organs {
        let name = set.name.replace(' ', "_");
        assert!(files.obj.contains(&format!("\no {name}\n")), "{name}");
        assert!(files.obj.contains(&format!("\nusemtl {name}\n")), "{name}");
        assert!(files.mtl.contains(&format!("\nnewmtl {name}\n")), "{name}");
    }
    // The last face points at the last vertex written (indices global across objects).
    let verts = files.obj.lines().filter(|l| l.starts_with("v ")).count();
    let last = files.obj.lines().rev().find(|l| l.starts_with("f ")).unwrap();
    let max = last.split_whitespace().skip(1).map(|t| t.split('/').next().unwrap().parse::<usize>().unwrap()).max();
    assert!(max.unwrap() <= verts);
    assert!(files.obj.lines().filter(|l| l.starts_with("f ")).all(|l| {
        l.split_whitespace().skip(1).all(|t| t.split('/').next().unwrap().parse::<usize>().unwrap() <= verts)
    }));
    // July: no organ object or material.
    let july = export::obj::write(&preset("oak"), &o, "oak");
    assert!(!july.obj.contains("acorn") && !july.mtl.contains("acorn"));
}

#[test]
fn lod1_keeps_the_parts_and_lod2_drops_them() {
    let lods = sylva_core::lod::generate_lods(&oak_params(9.5)).unwrap();
    assert!(!lods.lod0.foliage.organs.is_empty());
    assert_eq!(lods.lod1.foliage.organs, lods.lod0.foliage.organs);
    assert!(lods.lod2.foliage.organs.is_empty());
    let glb = parse(&export::lod_level_glb(&lods, &ExportOptions::default(), "oak", 1));
    assert!(glb.node("acorns").is_some());
    let glb = parse(&export::lod_level_glb(&lods, &ExportOptions::default(), "oak", 2));
    assert!(glb.node("acorns").is_none());
}
