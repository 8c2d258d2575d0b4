//! Levels of detail: every level comes from the one skeleton, triangle counts fall strictly from
//! LOD0 to LOD2 on every preset, LOD1 keeps the leaf area, the cloud is sane, and all of it is
//! deterministic.

use glam::Vec3;
use sylva_core::lod::{self, eigen_symmetric, generate_lods, leaf_box_area, main_stems, QUAD_FLOATS};
use sylva_core::{presets, TreeParams};

fn preset(name: &str) -> TreeParams {
    presets::find(name).expect("preset exists").params().expect("preset params are valid")
}

#[test]
fn every_level_uses_the_same_skeleton() {
    let p = preset("quaking_aspen");
    let l = generate_lods(&p).unwrap();
    let sk = &l.lod0.skeleton;
    assert_eq!(l.lod1.stems, sk.stems.len(), "LOD1 sweeps every stem");
    let main = main_stems(sk);
    let expected = sk.stems.iter().filter(|s| s.level <= 1).count();
    assert!(expected > 1, "the aspen has main branches");
    assert_eq!(l.lod2.stems, expected, "LOD2 sweeps the trunk and the level-1 stems");
    // The kept stems are the skeleton's own stems, point for point, with parents remapped.
    let mut kept = main.stems.iter();
    for s in sk.stems.iter().filter(|s| s.level <= 1) {
        let k = kept.next().unwrap();
        assert_eq!(k.points, s.points);
        assert_eq!(k.radius, s.radius);
        if let Some(parent) = k.parent {
            assert_eq!(main.stems[parent as usize].level + 1, k.level);
        }
    }
    // LOD1 covers the same volume as LOD0 (same stems, coarser tubes).
    let (b0, b1, b2) = (l.lod0.mesh.bounds(), l.lod1.mesh.bounds(), l.lod2.mesh.bounds());
    let size = (0..3).map(|k| b0.max[k] - b0.min[k]).fold(0.0f32, f32::max);
    for k in 0..3 {
        assert!((b0.min[k] - b1.min[k]).abs() < 0.05 * size, "LOD1 bounds {b1:?} vs {b0:?}");
        assert!((b0.max[k] - b1.max[k]).abs() < 0.05 * size, "LOD1 bounds {b1:?} vs {b0:?}");
        assert!(b2.min[k] >= b0.min[k] - 0.02 * size && b2.max[k] <= b0.max[k] + 0.02 * size);
    }
    // LOD1 leaves sit exactly where LOD0 leaves sit (a subset of them).
    let pos = |m: &[f32], i: usize| [m[16 * i + 12], m[16 * i + 13], m[16 * i + 14]];
    let f0 = &l.lod0.foliage;
    let f1 = &l.lod1.foliage;
    assert!(f1.count() > 0);
    for i in 0..f1.count() {
        assert_eq!(pos(&f1.matrices, i), pos(&f0.matrices, i * lod::LOD1_LEAF_STRIDE));
    }
    // The cloud's centres lie inside the leaves' bounding box.
    let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for i in 0..f0.count() {
        let p = Vec3::from(pos(&f0.matrices, i));
        lo = lo.min(p);
        hi = hi.max(p);
    }
    for q in l.lod2.cloud.chunks_exact(QUAD_FLOATS) {
        let c = Vec3::new(q[0], q[1], q[2]);
        assert!(c.cmpge(lo - 1e-3).all() && c.cmple(hi + 1e-3).all(), "cloud centre {c} outside {lo}..{hi}");
    }
}

#[test]
fn triangle_counts_fall_strictly_on_every_preset() {
    for preset in presets::PRESETS {
        let p = preset.params().unwrap();
        let l = generate_lods(&p).unwrap();
        let [t0, t1, t2] = l.triangles();
        assert!(t0 > t1 && t1 > t2 && t2 > 0, "{}: triangles {t0} > {t1} > {t2} fails", preset.name);
        assert_eq!(
            l.level(0).triangles(),
            l.lod0.stats.triangles + l.lod0.foliage.mesh.triangle_count() * l.lod0.foliage.count()
        );
        // Bark alone falls too (fewer rings and sides, then fewer stems).
        let (b0, b1, b2) = (l.lod0.mesh.triangle_count(), l.lod1.mesh.triangle_count(), l.lod2.mesh.triangle_count());
        assert!(b0 > b1 && b1 >= b2, "{}: bark {b0} > {b1} >= {b2} fails", preset.name);
        assert!(l.lod1.foliage.count() <= l.lod0.foliage.count());
        assert_eq!(l.lod2.foliage.count(), 0, "LOD2 leaves are the cloud");
        if l.lod0.foliage.count() > 0 {
            assert!(l.lod2.quads() > 0, "{}: a leafy tree has a cloud", preset.name);
        }
    }
}

#[test]
fn lod1_has_fewer_larger_leaves_covering_the_same_area() {
    for name in ["default", "quaking_aspen", "ca_black_oak", "grown_broadleaf"] {
        let l = generate_lods(&preset(name)).unwrap();
        let (n0, n1) = (l.lod0.foliage.count(), l.lod1.foliage.count());
        assert!(n0 > 10, "{name}: leafy");
        assert_eq!(n1, n0.div_ceil(lod::LOD1_LEAF_STRIDE), "{name}: every third leaf");
        let (a0, a1) = (leaf_box_area(&l.lod0.foliage), leaf_box_area(&l.lod1.foliage));
        let ratio = a1 / a0;
        assert!((0.75..=1.25).contains(&ratio), "{name}: LOD1 leaf area {a1} vs LOD0 {a0} (ratio {ratio})");
        // Larger: the kept leaves are √(n0/n1) times their LOD0 size.
        let len = |m: &[f32], i: usize| Vec3::new(m[16 * i + 4], m[16 * i + 5], m[16 * i + 6]).length();
        let s = len(&l.lod1.foliage.matrices, 1) / len(&l.lod0.foliage.matrices, lod::LOD1_LEAF_STRIDE);
        assert!((s - (n0 as f32 / n1 as f32).sqrt()).abs() < 1e-3, "{name}: scale {s}");
        // A lighter leaf mesh, never a heavier one.
        assert!(l.lod1.foliage.mesh.triangle_count() <= l.lod0.foliage.mesh.triangle_count());
    }
}

#[test]
fn cloud_quads_are_finite_orthogonal_and_tinted() {
    let l = generate_lods(&preset("ca_black_oak")).unwrap();
    let cloud = &l.lod2.cloud;
    assert_eq!(cloud.len() % QUAD_FLOATS, 0);
    let quads = cloud.len() / QUAD_FLOATS;
    assert_eq!(quads % lod::QUADS_PER_CLUSTER, 0);
    assert!(quads / lod::QUADS_PER_CLUSTER <= lod::CLOUD_CLUSTERS_MAX);
    assert!(cloud.iter().all(|v| v.is_finite()));
    for q in cloud.chunks_exact(QUAD_FLOATS) {
        let u = Vec3::new(q[3], q[4], q[5]);
        let v = Vec3::new(q[6], q[7], q[8]);
        assert!(u.length() > 0.0 && v.length() > 0.0);
        assert!(u.dot(v).abs() < 1e-3 * u.length() * v.length(), "half-axes are orthogonal");
        assert!(q[9] > 0.0 && q[10] > 0.0 && q[11] >= 0.0, "tint {:?}", &q[9..12]);
        assert!((0.05..=1.0).contains(&q[12]), "density {}", q[12]);
    }
    // The cloud covers at least the leaf box area of the leaves' cross-section (it is not a dot).
    let cloud_area: f32 = cloud
        .chunks_exact(QUAD_FLOATS)
        .map(|q| 4.0 * Vec3::new(q[3], q[4], q[5]).length() * Vec3::new(q[6], q[7], q[8]).length())
        .sum();
    assert!(cloud_area > 0.05 * leaf_box_area(&l.lod0.foliage), "cloud area {cloud_area}");
}

#[test]
fn bare_tree_has_no_cloud_and_still_falls() {
    let mut p = TreeParams::default();
    p.foliage.leaves = 0;
    let l = generate_lods(&p).unwrap();
    assert_eq!(l.lod0.foliage.count(), 0);
    assert!(l.lod2.cloud.is_empty());
    let [t0, t1, t2] = l.triangles();
    assert!(t0 > t1 && t1 > t2, "{t0} > {t1} > {t2}");
}

#[test]
fn lods_are_deterministic() {
    let p = preset("default");
    let a = generate_lods(&p).unwrap();
    let b = generate_lods(&p).unwrap();
    assert_eq!(a.meta_json(), b.meta_json());
    for i in 0..3 {
        let (x, y) = (a.level(i), b.level(i));
        assert_eq!(x.mesh.content_hash(), y.mesh.content_hash(), "LOD{i} mesh");
        assert_eq!(x.foliage.hash_into(0), y.foliage.hash_into(0), "LOD{i} foliage");
        let bits = |c: &[f32]| c.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(x.cloud), bits(y.cloud), "LOD{i} cloud");
    }
    // LOD0 is exactly what `generate` gives.
    assert_eq!(a.lod0.hash, sylva_core::generate(&p).unwrap().hash);
}

#[test]
fn meta_json_lists_three_levels() {
    let l = generate_lods(&preset("default")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&l.meta_json()).unwrap();
    let levels = v["levels"].as_array().unwrap();
    assert_eq!(levels.len(), 3);
    let t: Vec<u64> = levels.iter().map(|x| x["triangles"].as_u64().unwrap()).collect();
    assert_eq!(t, l.triangles().map(|x| x as u64).to_vec());
    assert_eq!(v["hash"], l.lod0.hash_hex());
}

#[test]
fn jacobi_eigen_decomposition() {
    // A rotated diagonal matrix diag(9, 4, 1).
    let (c, s) = (0.6f32, 0.8f32);
    let r = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
    let d = [9.0f32, 4.0, 1.0];
    let mut m = [[0.0f32; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = (0..3).map(|k| r[i][k] * d[k] * r[j][k]).sum();
        }
    }
    let (axes, vals) = eigen_symmetric(m);
    for k in 0..3 {
        assert!((vals[k] - d[k]).abs() < 1e-4, "eigenvalue {k}: {} vs {}", vals[k], d[k]);
        let expected = Vec3::new(r[0][k], r[1][k], r[2][k]);
        assert!(axes[k].dot(expected).abs() > 0.9999, "axis {k}: {} vs {expected}", axes[k]);
    }
    assert!((axes[0].cross(axes[1]) - axes[2]).length() < 1e-5, "right-handed");
}

/// Regression: the LOD1 and LOD2 barks had no occlusion, which the viewer's bark shader read as
/// 0 (a black bark at LOD1, 11% off LOD0's colour). They carry one byte per vertex, shaded by the
/// same crown as LOD0 (mean within 10% of LOD0's).
#[test]
fn reduced_barks_carry_the_crowns_occlusion() {
    let p = preset("quaking_aspen");
    let l = generate_lods(&p).unwrap();
    let mean = |shade: &[u8]| shade.iter().map(|&b| f64::from(b)).sum::<f64>() / shade.len() as f64;
    let base = mean(&l.lod0.mesh.shade);
    assert_eq!(l.lod0.mesh.shade.len(), l.lod0.mesh.vertex_count());
    for level in [&l.lod1, &l.lod2] {
        assert_eq!(level.mesh.shade.len(), level.mesh.vertex_count());
        let m = mean(&level.mesh.shade);
        assert!(m < 254.0, "the crown shades the reduced bark (mean {m:.1})");
        assert!((m / base - 1.0).abs() < 0.1, "mean occlusion {m:.1} vs LOD0 {base:.1}");
    }
}
