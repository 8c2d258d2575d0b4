//! The exported GLB carries the seasonal leaf colours: the instanced file's `_COLOR_0` is the
//! October tint, float for float; the baked file's `COLOR_0` is the tint divided by the
//! per-channel scale of the tints over 1 and its leaf texture is multiplied by that scale, so
//! their product is the tint times the texture (autumn reds are over 1, which bytes cannot hold).

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
    let scale = export::tint_scale(&october.foliage);
    assert!(scale[0] > 1.5, "October's reds are over 1: {scale:?}");
    let (mut red, mut green) = (0u64, 0u64);
    for (k, tint) in october.foliage.colors.chunks_exact(3).enumerate() {
        let c = &baked.bin[base + 4 * k * nv..][..4];
        let want: Vec<u8> =
            tint.iter().zip(scale).map(|(&t, s)| ((t / s).clamp(0.0, 1.0) * 255.0 + 0.5) as u8).collect();
        assert_eq!(&c[..3], &want[..], "leaf {k}");
        // Colour times scale is the tint, to a byte's step times the scale.
        for ((&b, &t), s) in c.iter().zip(tint).zip(scale) {
            assert!((f32::from(b) / 255.0 * s - t.max(0.0)).abs() <= s / 255.0 + 1e-4, "leaf {k}: {b} * {s} vs {t}");
        }
        (red, green) = (red + u64::from(c[0]), green + u64::from(c[1]));
    }
    assert!(red * 2 > green, "the baked October maple stays red: {red} {green}");
    // The leaf texture in the file is the scaled one.
    let material = &baked.json["materials"].as_array().unwrap().iter().find(|m| m["name"] == "leaves").unwrap();
    let tex = &baked.json["textures"]
        [material["pbrMetallicRoughness"]["baseColorTexture"]["index"].as_u64().unwrap() as usize];
    let img = &baked.json["images"][tex["source"].as_u64().unwrap() as usize];
    let v = &baked.json["bufferViews"][img["bufferView"].as_u64().unwrap() as usize];
    let at = v["byteOffset"].as_u64().unwrap_or(0) as usize;
    let png = &baked.bin[at..at + v["byteLength"].as_u64().unwrap() as usize];
    assert_eq!(png, &export::leaf_pngs_scaled(&october.foliage, scale).unwrap().color[..]);
    assert_ne!(png, &export::leaf_pngs(&october.foliage).unwrap().color[..]);
    // July's tints reach a little over 1 (the yellow variation): a scale of a few per cent.
    let summer = export::tint_scale(&july.foliage);
    assert!(summer.iter().all(|&s| (1.0..1.15).contains(&s)), "{summer:?}");
}

#[test]
fn the_texture_scale_is_a_plain_multiply_and_one_changes_nothing() {
    let texels = [10u8, 100, 200, 255, 0, 255, 128, 7];
    assert_eq!(export::scale_texels(&texels, [1.0; 3]), texels);
    assert_eq!(export::scale_texels(&texels, [2.0, 1.5, 1.0]), [20, 150, 200, 255, 0, 255, 128, 7]);
}
