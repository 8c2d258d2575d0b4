//! Foliage: leaves only on the last stem level, the orientation rule of *Modeling the Mighty
//! Maple for Web*, the leaf budget, determinism, and the grown-tree case.
#![allow(clippy::disallowed_methods, reason = "the test's own measures, not output bytes")]

use glam::Vec3;
use sylva_core::foliage::{self, face_up, lower};
use sylva_core::params::LeafLod;
use sylva_core::params::{FoliageParams, LeafParams, SkeletonParams};
use sylva_core::{generate, params::GrowthMode, SylvaError, TreeParams};

fn small() -> TreeParams {
    let mut p = TreeParams::default();
    p.skeleton.level[1].branches = 8;
    p.skeleton.level[2].branches = 6;
    p
}

/// Columns of leaf `i`'s matrix: (x axis, y axis = direction, z axis = front, position).
fn frame(m: &[f32], i: usize) -> [Vec3; 4] {
    let c = |k: usize| Vec3::new(m[16 * i + 4 * k], m[16 * i + 4 * k + 1], m[16 * i + 4 * k + 2]);
    [c(0), c(1), c(2), c(3)]
}

#[test]
fn default_tree_has_leaves_only_on_the_last_level() {
    let p = small();
    let g = generate(&p).unwrap();
    let n = g.foliage.count();
    assert!(n > 0, "the default tree carries leaves");
    assert_eq!(g.foliage.matrices.len(), n * 16);
    assert_eq!(g.foliage.colors.len(), n * 3);
    assert!(g.foliage.mesh.triangle_count() > 0);
    assert!(g.foliage.texture().is_some());
    let last = g.skeleton.stems.iter().map(|s| s.level).max().unwrap();
    // Every leaf sits on the axis of some last-level stem (within its sampling tolerance) and
    // on no stem of a lower level only.
    let on_stem = |pos: Vec3, level: u8| {
        g.skeleton.stems.iter().filter(|s| s.level == level).any(|s| {
            (0..=200).any(|k| (s.sample(k as f32 / 200.0).0 - pos).length() < 0.02 * s.length.max(0.05) + 1e-3)
        })
    };
    assert!(p.foliage.leaf_petiole > 0.0, "the default leaf (aspen) has a long petiole");
    for i in (0..n).step_by((n / 40).max(1)) {
        // The blade's base hangs Petiole Length (leaf y) beyond the stem: the petiole starts on it.
        let [_, dir, _, blade] = frame(&g.foliage.matrices, i);
        let pos = blade - dir * p.foliage.leaf_petiole;
        assert!(on_stem(pos, last), "leaf {i}'s petiole at {pos} is not on a level-{last} stem");
        assert!(!on_stem(blade, last) || p.foliage.leaf_petiole * dir.length() < 0.02, "the blade hangs off the stem");
    }
    // Leaves per stem: Leaves on each whole last-level stem (split records share them).
    let stems = g.skeleton.stems.iter().filter(|s| s.level == last).count();
    assert!(n <= stems * p.foliage.leaves as usize + stems, "{n} leaves on {stems} stems");
}

#[test]
fn orientation_follows_the_top_oriented_rule() {
    // The rule itself.
    let t = Vec3::new(0.3, 0.9, 0.1).normalize();
    let l = lower(t);
    let expect = Vec3::new(t.x, t.y * (1.0 - t.y * t.y), t.z).normalize();
    assert!((l - expect).length() < 1e-6);
    assert!(l.y < t.y, "lowered");
    let up = face_up(l);
    assert!(up.dot(l).abs() < 1e-5, "front perpendicular to the direction");
    assert!(up.y > 0.0, "front faces the sky");
    // No other unit front perpendicular to l faces up more.
    for k in 0..36 {
        let a = k as f32 * 0.1745;
        let side = l.cross(up);
        let other = up * a.cos() + side * a.sin();
        assert!(other.y <= up.y + 1e-6);
    }
    // Every leaf of a tree obeys it: directions are lowered (the largest y a lowered unit
    // vector can have is the maximum of lower() over the vertical plane) and fronts are world
    // up made perpendicular to the direction.
    let max_y = (0..=2000)
        .map(|k| {
            let a = k as f32 / 2000.0 * std::f32::consts::FRAC_PI_2;
            lower(Vec3::new(a.cos(), a.sin(), 0.0)).y
        })
        .fold(0.0f32, f32::max);
    assert!(max_y < 0.8, "{max_y}");
    let g = generate(&small()).unwrap();
    let m = &g.foliage.matrices;
    for i in 0..g.foliage.count() {
        let [x, y, z, _] = frame(m, i);
        let (d, f) = (y.normalize(), z.normalize());
        assert!(d.y <= max_y + 1e-4, "leaf {i} points up too steeply: {d}");
        assert!(d.dot(f).abs() < 1e-4);
        assert!(f.y >= -1e-5, "leaf {i} faces down: {f}");
        assert!((f - face_up(d)).length() < 1e-4);
        assert!(x.dot(d).abs() < 1e-4 * x.length().max(1.0));
    }
}

#[test]
fn leaf_budget_is_a_clear_error() {
    let mut p = small();
    p.foliage.max_leaves = 10;
    let e = generate(&p).unwrap_err();
    assert!(matches!(e, SylvaError::Budget { ref param, .. } if param == "max_leaves"), "{e:?}");
    assert!(e.message().contains("max_leaves budget of 10"), "{}", e.message());
    let need = foliage::budget_error(11, 10);
    assert!(need.message().contains("11 leaves"));
}

#[test]
fn foliage_is_deterministic_and_seeded_and_counts() {
    let p = small();
    let a = generate(&p).unwrap();
    let b = generate(&p).unwrap();
    assert_eq!(a.foliage.matrices, b.foliage.matrices);
    assert_eq!(a.foliage.colors, b.foliage.colors);
    assert_eq!(a.hash, b.hash);
    let c = generate(&TreeParams { skeleton: SkeletonParams { seed: 7, ..p.skeleton.clone() }, ..p.clone() }).unwrap();
    assert_ne!(a.foliage.matrices, c.foliage.matrices);
    // Leaves change the tree hash; a bare tree has none.
    let bare =
        generate(&TreeParams { foliage: FoliageParams { leaves: 0, ..p.foliage.clone() }, ..p.clone() }).unwrap();
    assert_eq!(bare.foliage.count(), 0);
    assert_ne!(bare.hash, a.hash);
    // Leaves never change the bark's geometry, only its shade: the crown darkens the bark inside it.
    let unshaded = |m: &sylva_core::TreeMesh| sylva_core::TreeMesh { shade: Vec::new(), ..m.clone() };
    assert_eq!(unshaded(&bare.mesh), unshaded(&a.mesh), "leaves never change the bark");
    assert!(bare.mesh.shade.iter().all(|&s| s == 255), "no leaves, no crown shade");
    let darkest = a.mesh.shade.iter().min().copied();
    assert!(darkest.is_some_and(|s| s < 230), "the crown shades some bark: darkest {darkest:?}");
    // Twigs of three: three leaves per site.
    let three =
        generate(&TreeParams { foliage: FoliageParams { foliage_twigs3: true, ..p.foliage.clone() }, ..p.clone() })
            .unwrap();
    assert_eq!(three.foliage.count(), 3 * a.foliage.count());
    // Leaf Mesh: the card is two triangles, the blade is the leaf's LOD0, Auto keeps the
    // foliage under its triangle budget.
    let cards =
        generate(&TreeParams { leaf: LeafParams { foliage_lod: LeafLod::Card, ..p.leaf.clone() }, ..p.clone() })
            .unwrap();
    assert_eq!(cards.foliage.mesh.triangle_count(), 2);
    let blade = generate(&TreeParams { leaf: LeafParams { foliage_lod: LeafLod::Blade, ..p.leaf }, ..p }).unwrap();
    assert_eq!(
        blade.foliage.mesh,
        sylva_core::leaf::generate(&TreeParams::default().leaf, TreeParams::default().foliage.leaf_petiole)
            .unwrap()
            .mesh
    );
    let auto = generate(&TreeParams::default()).unwrap();
    let tris = auto.foliage.mesh.triangle_count() as u64 * auto.foliage.count() as u64;
    assert!(tris <= foliage::AUTO_TRIANGLES, "{tris}");
}

#[test]
fn grown_trees_get_leaves_on_their_outermost_internodes() {
    let p = TreeParams {
        skeleton: SkeletonParams { growth_mode: GrowthMode::SpaceColonization, markers: 300, ..Default::default() },
        ..TreeParams::default()
    };
    let g = generate(&p).unwrap();
    assert!(g.foliage.count() > 0);
    let tips: Vec<Vec3> = g.skeleton.stems.iter().filter(|s| s.level > 0).map(|s| s.tip()).collect();
    for i in 0..g.foliage.count() {
        let pos = frame(&g.foliage.matrices, i)[3];
        let near = tips.iter().map(|t| (*t - pos).length()).fold(f32::INFINITY, f32::min);
        assert!(near <= 3.5 * p.skeleton.internode + 1e-3, "leaf {i} is {near} m from any shoot tip");
    }
}
