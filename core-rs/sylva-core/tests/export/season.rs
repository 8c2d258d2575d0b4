//! The exported GLB carries the seasonal leaf colours: the instanced file's `_COLOR_0` is the
//! October tint, float for float, and the baked file's `COLOR_0` its bytes (clamped to 0..1).

use super::*;

#[test]
fn glb_leaf_colours_are_the_seasons() {
    let mut p = presets::find("umbrella").unwrap().params().unwrap();
    p.foliage.season = 10.5;
    let october = generate(&p).unwrap();
    let july = preset("umbrella");
    assert_ne!(october.foliage.colors, july.foliage.colors);
    let glb = parse(&export::to_glb(&october, &ExportOptions::default()));
    let node = glb.node("leaves").unwrap();
    let inst = &node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
    let tints: Vec<f32> = glb.floats(inst["_COLOR_0"].as_u64().unwrap()).concat();
    assert_eq!(tints, october.foliage.colors);

    let baked = parse(&export::to_glb(&october, &ExportOptions { leaves: LeafMode::Baked, ..Default::default() }));
    let attrs = &baked.mesh_of("leaves")["primitives"][0]["attributes"];
    let a = baked.accessor(attrs["COLOR_0"].as_u64().unwrap());
    let v = &baked.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
    let base = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
    let nv = october.foliage.mesh.vertex_count();
    let (mut red, mut green) = (0u64, 0u64);
    for (k, tint) in october.foliage.colors.chunks_exact(3).enumerate() {
        let c = &baked.bin[base + 4 * k * nv..][..4];
        let want: Vec<u8> = tint.iter().map(|&t| (t.clamp(0.0, 1.0) * 255.0).round() as u8).collect();
        assert_eq!(&c[..3], &want[..], "leaf {k}");
        (red, green) = (red + u64::from(c[0]), green + u64::from(c[1]));
    }
    assert!(red > green, "the baked October maple is redder than green: {red} {green}");
}
