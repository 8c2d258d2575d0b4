//! Leaf surface, textures and LOD (issue 4): bounded deformation, planar UVs, the baked vein
//! textures (layout, powers of two, veins visible), card, billboard cloud and impostor views.

mod leaf_common;

use leaf_common::random_leaf_params;
use sylva_core::leaf::deform;
use sylva_core::leaf::presets::{find, LEAF_PRESETS};
use sylva_core::leaf::Leaf;
use sylva_core::mesh::Material;
use sylva_core::params::LeafPrimaries;
use sylva_core::rng::Rng;
use sylva_core::TreeParams;

/// The leaf of tree parameters `p`: its leaf parameters and Petiole Length.
fn generate(p: &TreeParams) -> Result<Leaf, sylva_core::SylvaError> {
    sylva_core::leaf::generate(&p.leaf, p.foliage.leaf_petiole)
}

fn vertices(l: &Leaf) -> impl Iterator<Item = &[f32]> {
    l.mesh.positions.chunks_exact(3)
}

#[test]
fn deformation_is_bounded_and_moves_only_along_z() {
    let mut rng = Rng::new(77, "leaf-deformation");
    let mut cases = 0;
    while cases < 40 {
        let mut p = random_leaf_params(&mut rng);
        p.leaf.leaf_venation = sylva_core::params::LeafVenation::Spline;
        p.leaf.leaf_fascicle = 1; // a blade (needles are tested in leaf_species.rs)
        p.leaf.leaf_shoot = 0; // one blade, not a conifer shoot
        let Ok(l) = generate(&p) else { continue };
        cases += 1;
        let (w, y) = deform::extents(&l.outline.points);
        let bound = deform::bound(&p.leaf, y, w);
        for (q, flat) in vertices(&l).zip(&l.triangulation.vertices) {
            assert_eq!((q[0], q[1]), (flat.x, flat.y), "x and y stay in the leaf plane");
            assert!(q[2].is_finite() && q[2].abs() <= bound + 1e-5, "|z| = {} over the bound {bound}", q[2]);
        }
        for n in l.mesh.normals.chunks_exact(3) {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-4, "unit normals");
        }
    }
    // Each term does what it says: the tip lifts with the midrib curvature, the edges with the
    // cross curvature, the veins raise ridges.
    let mut p = find("superformula_birch").unwrap().params().unwrap();
    (p.leaf.leaf_midrib_curvature, p.leaf.leaf_cross_curvature, p.leaf.leaf_edge_curl, p.leaf.leaf_vein_displacement) =
        (0.5, 0.0, 0.0, 0.0);
    let l = generate(&p).unwrap();
    assert!((l.mesh.positions[2] - 0.25).abs() < 1e-6, "the tip (vertex 0) rises by midrib / 2");
    (p.leaf.leaf_midrib_curvature, p.leaf.leaf_vein_displacement) = (0.0, 0.02);
    let l = generate(&p).unwrap();
    let zs: Vec<f32> = vertices(&l).map(|q| q[2]).collect();
    assert!(zs.iter().all(|&z| (0.0..=0.02).contains(&z)), "vein ridges only rise, at most by the displacement");
    assert!(zs.iter().any(|&z| z > 0.005) && zs.contains(&0.0), "ridges on veins, flat between them");
}

#[test]
fn thicker_veins_raise_higher_and_wider_ridges() {
    use glam::Vec2;
    use sylva_core::leaf::field;
    use sylva_core::leaf::uv::UvFrame;
    use sylva_core::leaf::veins::{VeinGraph, VeinNode, NONE};
    // A thick vein along x = 0.25 and a thin one along x = 0.75 (widths by the pipe model:
    // 9 tips below the first, 1 below the second).
    let node =
        |x: f32, y: f32, parent: u32, width: f32| VeinNode { pos: Vec2::new(x, y), parent, born: 0, width, tips: 1 };
    let g = VeinGraph {
        nodes: vec![
            node(0.25, 0.0, NONE, 0.06),
            node(0.25, 1.0, 0, 0.06),
            node(0.75, 0.0, NONE, 0.02),
            node(0.75, 1.0, 2, 0.02),
        ],
        ..VeinGraph::default()
    };
    let f = field::build(&g, &UvFrame { lo: Vec2::ZERO, size: Vec2::ONE }, 256, 256);
    let profile = |x0: f32| {
        let h: Vec<f32> = (0..200).map(|i| f.sample(Vec2::new(x0 - 0.2 + i as f32 * 0.002, 0.5))).collect();
        let peak = h.iter().copied().fold(0.0f32, f32::max);
        let wide = h.iter().filter(|&&v| v > 0.1 * peak).count();
        (peak, wide)
    };
    let ((thick_peak, thick_width), (thin_peak, thin_width)) = (profile(0.25), profile(0.75));
    assert!(thick_peak > 0.95 && thin_peak < 0.5 * thick_peak, "heights {thick_peak} vs {thin_peak}");
    assert!(thick_width > 2 * thin_width, "widths {thick_width} vs {thin_width}");
}

#[test]
fn uvs_are_planar_over_the_blade() {
    let l = generate(&find("superformula_maple").unwrap().params().unwrap()).unwrap();
    let (mut umin, mut umax) = ([1.0f32; 2], [0.0f32; 2]);
    for (uv, v) in l.mesh.uvs.chunks_exact(2).zip(&l.triangulation.vertices) {
        let want = l.uv_frame.uv(*v);
        assert_eq!((uv[0], uv[1]), (want.x, want.y));
        for k in 0..2 {
            umin[k] = umin[k].min(uv[k]);
            umax[k] = umax[k].max(uv[k]);
        }
    }
    assert_eq!((umin, umax), ([0.0, 0.0], [1.0, 1.0]), "the blade spans the whole 0..1 square");
}

#[test]
fn textures_are_power_of_two_rgba8_with_visible_veins() {
    for preset in LEAF_PRESETS {
        let p = preset.params().unwrap();
        let l = generate(&p).unwrap();
        let t = &l.texture;
        assert!(t.width.is_power_of_two() && t.height.is_power_of_two(), "{}", preset.name);
        assert_eq!(t.height, 1 << p.leaf.leaf_texture_level);
        assert_eq!(t.color.len(), (t.width * t.height * 4) as usize);
        assert_eq!(t.normal.len(), t.color.len());
        // Alpha covers the blade: the inside fraction matches the outline's share of the box.
        let inside = t.color.chunks_exact(4).filter(|c| c[3] == 255).count() as f64 / f64::from(t.width * t.height);
        let box_area = f64::from(l.uv_frame.size.x * l.uv_frame.size.y);
        if l.shoot.is_empty() {
            let share = sylva_core::leaf::geom::polygon_area(&l.outline.points) / box_area;
            assert!(
                (inside - share).abs() < 0.05 + 0.1 * share,
                "{}: alpha {inside} vs area share {share}",
                preset.name
            );
        } else {
            // A shoot: its needles overlap, so alpha covers at most their summed area, and the
            // twig plus at least half of that (they do not all lie on each other).
            let sum: f64 =
                l.shoot.iter().map(|n| sylva_core::leaf::geom::polygon_area(n).abs()).sum::<f64>() / box_area;
            assert!(inside < sum + 0.05 && inside > 0.5 * sum, "{}: alpha {inside} vs needles {sum}", preset.name);
        }
        assert!(t.color.chunks_exact(4).all(|c| c[3] == 0 || c[3] == 255));
        assert!(t.normal.chunks_exact(4).all(|n| n[2] >= 128), "{}: normals face the front", preset.name);
        if l.veins.graph.nodes.is_empty() {
            continue;
        }
        // Veins are lighter than the blade and carry the ridge height in the normal map's alpha.
        let blade = t.color.chunks_exact(4).filter(|c| c[3] == 255).map(|c| u32::from(c[1])).min().unwrap();
        let vein = t.color.chunks_exact(4).map(|c| u32::from(c[1])).max().unwrap();
        assert!(vein > blade + 40, "{}: veins visible in the colour map", preset.name);
        let one_midrib = !matches!(p.leaf.leaf_primary_veins, LeafPrimaries::Palmate | LeafPrimaries::Dichotomous);
        assert!(!one_midrib || t.normal.chunks_exact(4).any(|n| n[3] >= 200), "{}: the midrib crest", preset.name);
        let tilted = t.normal.chunks_exact(4).filter(|n| n[0] != 128 || n[1] != 128).count();
        assert!(tilted > 100, "{}: the vein ridges tilt the normals ({tilted} texels)", preset.name);
    }
}

#[test]
fn lod_card_billboards_and_impostor_views() {
    let mut p: TreeParams = find("superformula_oak").unwrap().params().unwrap();
    p.leaf.leaf_impostor_grid = 6;
    let l = generate(&p).unwrap();
    let card = &l.lod.card;
    assert_eq!((card.vertex_count(), card.triangle_count()), (4, 2));
    let mut uvs: Vec<(f32, f32)> = card.uvs.chunks_exact(2).map(|u| (u[0], u[1])).collect();
    uvs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(uvs, vec![(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0)]);
    assert_eq!(card.groups[0].material, Material::Leaves);
    let cloud = &l.lod.billboards;
    assert_eq!((cloud.vertex_count(), cloud.triangle_count()), (16, 8), "four quads");
    // The quads follow the bent surface: their corners' heights differ like the blade's.
    let zs: Vec<f32> = cloud.positions.chunks_exact(3).map(|q| q[2]).collect();
    let spread =
        zs.iter().copied().fold(f32::NEG_INFINITY, f32::max) - zs.iter().copied().fold(f32::INFINITY, f32::min);
    assert!(spread > 0.02, "billboards follow the curvature ({spread})");
    assert_eq!(l.lod.impostor_views.len(), 36);
    for v in &l.lod.impostor_views {
        let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-5 && v[2] >= 0.0, "unit views over the front hemisphere");
    }
    let near_pole = l.lod.impostor_views.iter().filter(|v| v[2] > 0.9).count();
    let near_horizon = l.lod.impostor_views.iter().filter(|v| v[2] < 0.3).count();
    assert!(near_pole > 0 && near_horizon > 0, "views spread from the pole to the horizon");
}
