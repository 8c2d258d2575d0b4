//! The GLB for strict importers (`ExportOptions::strict`): no glTF extension used or required,
//! float normals and tangents equal to the quantised file's within a byte's rounding, the
//! leaves baked.

use super::*;

#[test]
fn strict_glb_needs_no_extension() {
    let g = preset("default");
    let opts = ExportOptions { strict: true, ..Default::default() };
    let strict = parse(&export::to_glb(&g, &opts));
    strict.check_layout();
    assert!(strict.json.get("extensionsUsed").is_none(), "{}", strict.json["extensionsUsed"]);
    assert!(strict.json.get("extensionsRequired").is_none());
    assert!(strict.json["nodes"].as_array().unwrap().iter().all(|n| n.get("extensions").is_none()));
    // Instanced leaves come out baked: one leaf mesh with every leaf.
    let leaves = strict.mesh_of("leaves");
    assert_eq!(strict.index_count(leaves), (g.foliage.mesh.indices.len() * g.foliage.count()) as u64);
    // Every NORMAL and TANGENT is float, not normalised; the bark's equal the quantised file's.
    let quantized = parse(&export::to_glb(&g, &ExportOptions::default()));
    for node in ["bark", "leaves"] {
        let attrs = &strict.mesh_of(node)["primitives"][0]["attributes"];
        for key in ["NORMAL", "TANGENT"] {
            let a = strict.accessor(attrs[key].as_u64().unwrap());
            assert_eq!((a["componentType"].as_u64(), a.get("normalized")), (Some(5126), None), "{node} {key}");
        }
        let n = strict.floats(attrs["NORMAL"].as_u64().unwrap());
        assert!(n.iter().all(|v| ((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt() - 1.0).abs() < 1e-4));
        let t = strict.floats(attrs["TANGENT"].as_u64().unwrap());
        assert!(t.iter().all(|v| v[3].abs() == 1.0), "{node}: tangent w is ±1");
    }
    let (s, q) = (
        &strict.mesh_of("bark")["primitives"][0]["attributes"],
        &quantized.mesh_of("bark")["primitives"][0]["attributes"],
    );
    for key in ["NORMAL", "TANGENT"] {
        let (fs, qs) = (strict.floats(s[key].as_u64().unwrap()), quantized.snorm8(q[key].as_u64().unwrap()));
        assert_eq!(fs.len(), qs.len());
        for (a, b) in fs.iter().zip(&qs) {
            assert!(a.iter().zip(b).all(|(x, y)| (x - y).abs() < 0.02), "{key}: {a:?} vs {b:?}");
        }
    }
}

#[test]
fn strict_glb_without_tangents_or_textures() {
    let g = preset("grown_bushy");
    for opts in [
        ExportOptions { strict: true, tangents: false, ..Default::default() },
        ExportOptions { strict: true, textures: false, leaves: LeafMode::Baked, ..Default::default() },
    ] {
        let glb = parse(&export::to_glb(&g, &opts));
        glb.check_layout();
        assert!(glb.json.get("extensionsUsed").is_none());
        let attrs = &glb.mesh_of("bark")["primitives"][0]["attributes"];
        assert!(attrs.get("TANGENT").is_none());
        assert_eq!(glb.floats(attrs["NORMAL"].as_u64().unwrap()).len(), g.mesh.vertex_count());
    }
}
