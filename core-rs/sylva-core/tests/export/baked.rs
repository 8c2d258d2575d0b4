//! The GLB for editors (`LeafMode::Baked`): every leaf in one mesh, each vertex with its
//! leaf's tint (`COLOR_0`, clamped to 0..1) and the wind record of the twig it hangs on
//! (`_WIND_PIVOT`, `_WIND_PARAMS`, coded as the bark's); sound geometry on every preset.

use super::*;
use glam::Vec3;
use sylva_core::skeleton::Stem;

fn baked(g: &Generated) -> Glb {
    let glb = parse(&export::to_glb(g, &ExportOptions { leaves: LeafMode::Baked, ..Default::default() }));
    glb.check_layout();
    glb
}

/// The raw values of a normalised `u8` accessor, element by element.
fn unorm8(glb: &Glb, i: u64) -> Vec<[u8; 4]> {
    let a = glb.accessor(i);
    assert_eq!(
        (a["componentType"].as_u64(), a["normalized"].as_bool(), a["type"].as_str()),
        (Some(5121), Some(true), Some("VEC4"))
    );
    let v = &glb.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
    let base = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
    (0..a["count"].as_u64().unwrap() as usize).map(|e| glb.bin[base + 4 * e..][..4].try_into().unwrap()).collect()
}

/// A mesh's wind records as stored: the 8 `u16` of `_WIND_PIVOT` and `_WIND_PARAMS` per vertex.
fn raw_wind(glb: &Glb, mesh: &Value) -> Vec<[u16; 8]> {
    let attrs = &mesh["primitives"][0]["attributes"];
    let (pivot, params) =
        (glb.unorm16(attrs["_WIND_PIVOT"].as_u64().unwrap()), glb.unorm16(attrs["_WIND_PARAMS"].as_u64().unwrap()));
    pivot.iter().zip(&params).map(|(a, b)| std::array::from_fn(|k| if k < 4 { a[k] } else { b[k - 4] })).collect()
}

/// Where leaf `k` meets its stem: leaf point (0, -petiole, 0) under its matrix.
fn attachment(g: &Generated, k: usize) -> Vec3 {
    let petiole = g.foliage.leaf.as_deref().map_or(0.0, |l| l.petiole);
    let m = glam::Mat4::from_cols_slice(&g.foliage.matrices[16 * k..16 * k + 16]);
    m.transform_point3(Vec3::new(0.0, -petiole, 0.0))
}

/// How near `stem`'s centre curve passes to `p`: sampled 64 times per point, then around the
/// nearest sample 256 times finer (a 7 m twig's coarse samples are 12 mm apart, more than the
/// tolerance the tests allow).
fn curve_distance(stem: &Stem, p: Vec3) -> f32 {
    let n = 64 * stem.points.len();
    let at = |t: f32| stem.point(t.clamp(0.0, 1.0)).distance(p);
    let (j, _) =
        (0..=n).map(|j| (j, at(j as f32 / n as f32))).fold((0, f32::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    let fine = 256;
    (0..=2 * fine).map(|i| at((j as f32 - 1.0 + i as f32 / fine as f32) / n as f32)).fold(f32::INFINITY, f32::min)
}

/// The stems whose centre curves pass within 2 mm of the nearest one to `p`.
fn stems_at(g: &Generated, p: Vec3) -> Vec<usize> {
    let near: Vec<(usize, f32)> = g
        .skeleton
        .stems
        .iter()
        .enumerate()
        .filter(|(_, s)| s.points.iter().any(|q| q.distance(p) <= s.length + 0.05))
        .map(|(i, s)| (i, curve_distance(s, p)))
        .collect();
    let best = near.iter().map(|n| n.1).fold(f32::INFINITY, f32::min);
    assert!(best < 0.005, "the leaf at {p} is {best} m from every stem");
    near.iter().filter(|n| n.1 <= best + 0.002).map(|n| n.0).collect()
}

#[test]
fn baked_leaves_carry_their_tint_and_their_twigs_wind() {
    for (name, sample) in [("grown_bushy", 1), ("default", 97)] {
        let g = preset(name);
        let glb = baked(&g);
        let (f, nv) = (&g.foliage, g.foliage.mesh.vertex_count());
        let leaves = glb.mesh_of("leaves");
        let attrs = &leaves["primitives"][0]["attributes"];
        assert_eq!(glb.accessor(attrs["POSITION"].as_u64().unwrap())["count"], nv * f.count(), "{name}");
        assert!(glb.json["extensionsUsed"].as_array().unwrap().iter().all(|e| e != "EXT_mesh_gpu_instancing"));
        // One node and one mesh for every leaf.
        assert_eq!(glb.json["nodes"].as_array().unwrap().len(), 3, "{name}: sylva_tree, bark, leaves");
        assert_eq!(glb.json["meshes"].as_array().unwrap().len(), 2, "{name}");
        // The tint: the instanced file's (`_COLOR_0`, the crown's shade included) as bytes,
        // divided by the scale of the tints over 1, which the leaf texture takes (`tint_scale`).
        let scale = sylva_core::export::tint_scale(f);
        let colors = unorm8(&glb, attrs["COLOR_0"].as_u64().unwrap());
        assert_eq!(colors.len(), nv * f.count(), "{name}");
        for (k, tint) in f.colors.chunks_exact(3).enumerate() {
            let want: [u8; 4] = std::array::from_fn(|i| {
                tint.get(i).map_or(255, |&c| ((c / scale[i]).clamp(0.0, 1.0) * 255.0 + 0.5) as u8)
            });
            assert!(colors[k * nv..(k + 1) * nv].iter().all(|c| *c == want), "{name} leaf {k}: {want:?}");
        }
        assert!(leaves["extras"].get("leaf_tint_scale").is_none());
        // The wind: coded as the bark's, one record per leaf, the record of the bark of the stem
        // it hangs on where it meets it.
        let bark = glb.mesh_of("bark");
        assert_eq!(leaves["extras"]["wind_attributes"], bark["extras"]["wind_attributes"], "{name}");
        let (leaf_wind, bark_wind) = (raw_wind(&glb, leaves), raw_wind(&glb, bark));
        let deepest = g.skeleton.stems.iter().map(|s| s.level).max().unwrap();
        for k in (0..f.count()).step_by(sample) {
            let record = leaf_wind[k * nv];
            assert!(leaf_wind[k * nv..(k + 1) * nv].iter().all(|r| *r == record), "{name} leaf {k}");
            let p = attachment(&g, k);
            let expected: Vec<[u16; 8]> = stems_at(&g, p)
                .into_iter()
                .map(|i| {
                    let s = &g.skeleton.stems[i];
                    // The stem's bark: the vertices whose record has its base and level.
                    let own = |v: &usize| {
                        let w = &g.mesh.wind[8 * v..8 * v + 8];
                        w[..3] == s.base().to_array() && w[3] == f32::from(s.level)
                    };
                    let at = |v: usize| Vec3::from_slice(&g.mesh.positions[3 * v..3 * v + 3]).distance(p);
                    let v = (0..g.mesh.vertex_count()).filter(own).min_by(|a, b| at(*a).total_cmp(&at(*b))).unwrap();
                    bark_wind[v]
                })
                .collect();
            assert!(expected.contains(&record), "{name} leaf {k}: {record:?} not in {expected:?}");
            if name == "default" {
                // Weber & Penn: leaves hang on the deepest level (level 2 is 43690 of 65535).
                assert_eq!(u32::from(record[3]), 21_845 * u32::from(deepest), "{name} leaf {k}");
            }
        }
    }
}

/// The indices of a primitive, widened: `u16` up to 65,535 vertices, `u32` past that.
fn indices(glb: &Glb, primitive: &Value, vertices: usize) -> Vec<u32> {
    let a = glb.accessor(primitive["indices"].as_u64().unwrap());
    let wide = vertices > 65_535;
    assert_eq!(a["componentType"], if wide { 5125 } else { 5123 }, "{vertices} vertices");
    let v = &glb.json["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
    let base = v["byteOffset"].as_u64().unwrap() as usize + a["byteOffset"].as_u64().unwrap_or(0) as usize;
    let count = a["count"].as_u64().unwrap() as usize;
    if wide {
        (0..count).map(|i| u32_at(&glb.bin, base + 4 * i)).collect()
    } else {
        (0..count).map(|i| u32::from(u16::from_le_bytes(glb.bin[base + 2 * i..][..2].try_into().unwrap()))).collect()
    }
}

#[test]
fn baked_leaves_hang_on_a_stem_on_every_preset() {
    // Sound geometry: one copy of the leaf mesh per leaf, a colour and a wind record on every
    // vertex, finite positions, unit normals (within the validator's 0.00674 for quantised
    // ones), indices in range (`u32` past 65,535 vertices). And each leaf's pivot is the base of
    // a stem whose centre curve passes within 5 mm of the leaf's foot (the pivot decoded within
    // a millimetre), at that stem's level.
    for name in presets::PRESETS.iter().map(|p| p.name) {
        let g = preset(name);
        let glb = parse(&export::to_glb(
            &g,
            &ExportOptions { leaves: LeafMode::Baked, textures: false, ..Default::default() },
        ));
        glb.check_layout();
        let leaves = glb.mesh_of("leaves");
        let prim = &leaves["primitives"][0];
        let attrs = &prim["attributes"];
        let n = g.foliage.count() * g.foliage.mesh.vertex_count();
        for key in ["POSITION", "NORMAL", "TEXCOORD_0", "COLOR_0", "_WIND_PIVOT", "_WIND_PARAMS"] {
            assert_eq!(glb.accessor(attrs[key].as_u64().unwrap())["count"], n, "{name} {key}");
        }
        let positions = glb.floats(attrs["POSITION"].as_u64().unwrap());
        assert!(positions.iter().flatten().all(|c| c.is_finite()), "{name}");
        for (v, normal) in glb.snorm8(attrs["NORMAL"].as_u64().unwrap()).iter().enumerate() {
            let len = normal.iter().map(|c| c * c).sum::<f32>().sqrt();
            assert!((len - 1.0).abs() <= 0.00674, "{name} vertex {v}: |n| = {len}");
        }
        let idx = indices(&glb, prim, n);
        assert_eq!(idx.len(), g.foliage.count() * g.foliage.mesh.indices.len(), "{name}");
        assert!(idx.iter().all(|&i| (i as usize) < n), "{name}");
        let doc = &leaves["extras"]["wind_attributes"]["_WIND_PIVOT"];
        let decode = |q: &[u16], c: usize| {
            doc["offset"][c].as_f64().unwrap() as f32
                + doc["scale"][c].as_f64().unwrap() as f32 * f32::from(q[c]) / 65_535.0
        };
        let wind = raw_wind(&glb, leaves);
        let nv = g.foliage.mesh.vertex_count();
        for k in (0..g.foliage.count()).step_by((g.foliage.count() / 150).max(1)) {
            let q = &wind[k * nv];
            let pivot = Vec3::new(decode(q, 0), decode(q, 1), decode(q, 2));
            let p = attachment(&g, k);
            let hangs = g.skeleton.stems.iter().any(|s| {
                s.base().distance(pivot) < 0.001
                    && decode(q, 3).round() == f32::from(s.level)
                    && curve_distance(s, p) < 0.005
            });
            assert!(hangs, "{name} leaf {k} at {p}: no stem from {pivot}");
        }
    }
}

#[test]
fn baked_leaves_without_wind_or_colours() {
    let g = preset("grown_bushy");
    let glb = parse(&export::to_glb(
        &g,
        &ExportOptions { leaves: LeafMode::Baked, wind: false, vertex_colors: false, ..Default::default() },
    ));
    glb.check_layout();
    let leaves = glb.mesh_of("leaves");
    let attrs = &leaves["primitives"][0]["attributes"];
    assert!(attrs.get("_WIND_PIVOT").is_none() && attrs.get("COLOR_0").is_none(), "{attrs}");
    assert!(leaves.get("extras").is_none(), "{leaves}");
    // A tree whose bark has no wind data: leaves without it, the colours still there.
    let mut bare = preset("grown_bushy");
    bare.mesh.wind.clear();
    let glb = baked(&bare);
    let attrs = &glb.mesh_of("leaves")["primitives"][0]["attributes"];
    assert!(attrs.get("_WIND_PARAMS").is_none() && attrs.get("COLOR_0").is_some());
}
