//! Exports of a tree with a cut stem: the GLB gets a third material, `cut_face` (the end grain's
//! colour and normal maps, clamped), which the bark mesh's cut-face primitive uses; the MTL a
//! `cut_face` material with its two texture files, which the OBJ's cut faces use. A tree without
//! a cut exports no trace of it.

use serde_json::Value;
use sylva_core::export::{self, ExportOptions, LeafMode};
use sylva_core::params::{Cut, Edit, SkeletonParams};
use sylva_core::{generate, Generated, Material, TreeParams};

/// The default tree with its first long main branch cut 15 % of the way out.
fn cut_tree() -> Generated {
    let g0 = generate(&TreeParams::default()).unwrap();
    let s = g0.skeleton.stems.iter().find(|s| s.level == 1 && s.length > 2.0).expect("a main branch");
    let (at, _) = s.point_at(0.15 * s.length);
    let edits = vec![Edit::Cut(Cut { at, year: None })];
    let g = generate(&TreeParams { skeleton: SkeletonParams { edits, ..Default::default() }, ..TreeParams::default() })
        .unwrap();
    assert!(g.edits[0].resolved);
    g
}

/// The JSON chunk of a GLB.
fn json_of(glb: &[u8]) -> Value {
    let len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    serde_json::from_str(std::str::from_utf8(&glb[20..20 + len]).unwrap().trim_end()).unwrap()
}

/// The bytes of image `i` (a buffer view of the BIN chunk).
fn image_bytes<'a>(glb: &'a [u8], json: &Value, i: usize) -> &'a [u8] {
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let bin = &glb[20 + json_len + 8..];
    let view = &json["bufferViews"][json["images"][i]["bufferView"].as_u64().unwrap() as usize];
    let (at, len) = (view["byteOffset"].as_u64().unwrap_or(0) as usize, view["byteLength"].as_u64().unwrap() as usize);
    &bin[at..at + len]
}

fn material_names(json: &Value) -> Vec<&str> {
    json["materials"].as_array().unwrap().iter().map(|m| m["name"].as_str().unwrap()).collect()
}

#[test]
fn a_cut_tree_exports_a_third_material_for_its_faces() {
    let g = cut_tree();
    let opts = ExportOptions::default();
    let glb = export::glb::write(&g, &opts);
    let json = json_of(&glb);
    assert_eq!(material_names(&json), ["bark", "leaves", "cut_face"]);
    // The bark mesh: one primitive per group, the cut faces' with material 2, the bark's with 0.
    let bark = json["meshes"].as_array().unwrap().iter().find(|m| m["name"] == "bark").unwrap();
    let prims = bark["primitives"].as_array().unwrap();
    let groups: Vec<_> = g.mesh.groups.iter().filter(|gr| gr.count > 0).collect();
    assert_eq!(prims.len(), groups.len());
    for (p, gr) in prims.iter().zip(&groups) {
        let want = if gr.material == Material::CutFace { 2 } else { 0 };
        assert_eq!(p["material"], want, "{:?}", gr.material);
        let count = json["accessors"][p["indices"].as_u64().unwrap() as usize]["count"].as_u64().unwrap();
        assert_eq!(count, u64::from(gr.count));
    }
    assert_eq!(groups.iter().filter(|gr| gr.material == Material::CutFace).count(), 1);
    // Its textures: the end grain's colour and normal, clamped (sampler 1), embedded as PNG.
    let m = &json["materials"][2];
    assert_eq!(m["pbrMetallicRoughness"]["roughnessFactor"], 0.85);
    let pngs = export::end_grain_pngs(g.bark, opts.bark_texture_size);
    for (key, png) in
        [(&m["pbrMetallicRoughness"]["baseColorTexture"], &pngs.color), (&m["normalTexture"], &pngs.normal)]
    {
        let t = &json["textures"][key["index"].as_u64().unwrap() as usize];
        assert_eq!(t["sampler"], 1);
        assert_eq!(image_bytes(&glb, &json, t["source"].as_u64().unwrap() as usize), &png[..]);
    }
    assert_eq!(json["samplers"][1]["wrapS"], 33071);
    // The same in the baked-leaves file, and plain colours without textures.
    let baked = json_of(&export::glb::write(&g, &ExportOptions { leaves: LeafMode::Baked, ..opts.clone() }));
    assert_eq!(material_names(&baked), ["bark", "leaves", "cut_face"]);
    let plain = json_of(&export::glb::write(&g, &ExportOptions { textures: false, ..opts }));
    assert_eq!(plain["materials"][2]["pbrMetallicRoughness"]["baseColorFactor"][0], 0.586);
    assert!(plain.get("textures").is_none());
}

#[test]
fn without_a_cut_no_cut_face_material() {
    let g = generate(&TreeParams::default()).unwrap();
    assert!(g.mesh.groups.iter().all(|gr| gr.material != Material::CutFace));
    let glb = export::glb::write(&g, &ExportOptions::default());
    let json = json_of(&glb);
    assert_eq!(material_names(&json), ["bark", "leaves"]);
    assert!(!String::from_utf8_lossy(&glb[..glb.len().min(200_000)]).contains("cut_face"));
    let obj = export::obj::write(&g, &ExportOptions::default(), "tree");
    assert!(!obj.mtl.contains("cut_face") && !obj.obj.contains("cut_face"));
    assert!(obj.textures.iter().all(|(n, _)| !n.contains("cut_face")));
}

#[test]
fn obj_cut_faces_use_the_cut_face_material_and_its_textures() {
    let g = cut_tree();
    let files = export::obj::write(&g, &ExportOptions::default(), "tree");
    assert!(files.mtl.contains(
        "newmtl cut_face\nKd 1 1 1\nKs 0 0 0\nNs 8\nd 1\nillum 2\nmap_Kd tree_cut_face_color.png\nnorm tree_cut_face_normal.png\n"
    ));
    // One `usemtl cut_face` run, of the cut faces' triangles.
    let faces = g.mesh.groups.iter().find(|gr| gr.material == Material::CutFace).unwrap();
    let run = files.obj.split("usemtl cut_face\n").nth(1).unwrap();
    let tris = run.lines().take_while(|l| l.starts_with("f ")).count();
    assert_eq!(tris as u32, faces.count / 3);
    assert_eq!(files.obj.matches("usemtl cut_face").count(), 1);
    let names: Vec<&str> = files.textures.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names[names.len() - 2..], ["tree_cut_face_color.png", "tree_cut_face_normal.png"]);
    // Rows flipped for OBJ's bottom-up `vt`, as the bark's: the PNG is of the flipped bake.
    let m = sylva_core::mesh::bark::end_grain::bake(g.bark, 512);
    let flipped: Vec<u8> = m.color.rgba.chunks_exact(512 * 4).rev().flatten().copied().collect();
    assert_eq!(files.textures[names.len() - 2].1, export::png::encode_rgba(512, 512, &flipped));
    // Untextured: a plain wood colour, no files.
    let plain = export::obj::write(&g, &ExportOptions { textures: false, ..ExportOptions::default() }, "tree");
    assert!(plain.mtl.contains("newmtl cut_face\nKd 0.784 0.647 0.478\n") && plain.textures.is_empty());
}
