//! The sweep's [`Layout`]: where each stem's vertices and triangles are in the bark, which the
//! tree holes read instead of every triangle of the tree. What it claims must hold on every
//! preset (forks, welds and their fallbacks) and on trees with holes.

use sylva_core::mesh::tube::{build_laid_out, Layout};
use sylva_core::mesh::TreeMesh;
use sylva_core::params::{MeshParams, SkeletonParams};
use sylva_core::skeleton::{self, Skeleton};
use sylva_core::{presets::PRESETS, TreeParams};

/// Every claim of `l` about `mesh`, swept from `sk`.
fn assert_layout(mesh: &TreeMesh, l: &Layout, sk: &Skeleton, name: &str) {
    let n = sk.stems.len();
    assert_eq!((l.blocks.len(), l.tubes.len(), l.junctions.len()), (n, n, n), "{name}");
    let all = (mesh.indices.len() / 3) as u32;
    // The stems' and the junctions' ranges tile the triangles before `rest`, and `rest` is in the mesh.
    let mut ranges: Vec<_> = l.tubes.iter().chain(&l.junctions).filter(|r| !r.is_empty()).cloned().collect();
    ranges.sort_by_key(|r| r.start);
    let mut at = 0;
    for r in &ranges {
        assert_eq!(r.start, at, "{name}: a gap or an overlap at triangle {at}");
        at = r.end;
    }
    assert_eq!(at, l.rest, "{name}");
    assert!(l.rest <= all, "{name}");
    let tri = |k: u32| &mesh.indices[3 * k as usize..3 * k as usize + 3];
    let mut junctions = 0;
    for (i, s) in sk.stems.iter().enumerate() {
        let own = &l.blocks[i];
        for k in l.tubes[i].clone() {
            assert!(tri(k).iter().all(|v| own.contains(v)), "{name}: stem {i}'s triangle {k} leaves its block");
        }
        let parent = s.parent.map(|p| l.blocks[p as usize].clone());
        for k in l.junctions[i].clone() {
            let near = |v: &u32| own.contains(v) || parent.as_ref().is_some_and(|b| b.contains(v));
            assert!(tri(k).iter().all(near), "{name}: stem {i}'s junction triangle {k} uses a third stem");
        }
        junctions += usize::from(!l.junctions[i].is_empty());
    }
    assert!(junctions > 0 || !sk.stems.iter().any(|s| s.level > 0), "{name}: no junction recorded");
}

#[test]
fn every_presets_layout_holds_what_it_says() {
    for preset in PRESETS {
        let p = preset.params().unwrap();
        let sk = skeleton::build(&p.skeleton).unwrap();
        let (mesh, layout) = build_laid_out(&sk, &p.mesh).unwrap();
        assert_layout(&mesh, &layout, &sk, preset.name);
        assert_eq!(layout.eligible.iter().any(|&e| e), p.mesh.hole_count > 0, "{}", preset.name);
    }
}

#[test]
fn the_layout_holds_with_holes_on_many_seeds() {
    for seed in 0..8 {
        let p = TreeParams {
            skeleton: SkeletonParams { seed, ratio: 0.035, ..Default::default() },
            mesh: MeshParams { hole_count: 3, hole_min_radius: 0.1, ..Default::default() },
            ..TreeParams::default()
        };
        let sk = skeleton::build(&p.skeleton).unwrap();
        let (mesh, layout) = build_laid_out(&sk, &p.mesh).unwrap();
        assert_layout(&mesh, &layout, &sk, &format!("seed {seed}"));
    }
}
