//! Geometry invariants (standing rule 6) on every preset and on a spread of seeds.

mod common;

use common::{assert_mesh_invariants, edge_uses};
use sylva_core::mesh::tube::sides_for;
use sylva_core::{generate, presets::PRESETS, TreeParams};

#[test]
fn every_preset_satisfies_the_invariants() {
    for preset in PRESETS {
        let g = generate(&preset.params().unwrap()).unwrap();
        assert_mesh_invariants(&g, preset.name);
    }
}

#[test]
fn many_seeds_satisfy_the_invariants() {
    for seed in 0..12 {
        let p = TreeParams { seed, ..TreeParams::default() };
        assert_mesh_invariants(&generate(&p).unwrap(), &format!("seed {seed}"));
    }
}

#[test]
fn tips_are_closed_only_buried_bases_stay_open() {
    for preset in PRESETS {
        let p = preset.params().unwrap();
        let g = generate(&p).unwrap();
        let edges = edge_uses(&g.mesh);
        assert!(edges.values().all(|&u| u <= 2), "{}: an edge is shared by more than two triangles", preset.name);
        let open = edges.values().filter(|&&u| u == 1).count();
        // Each child stem's base ring (inside its parent) is the only open loop; the trunk is closed.
        let expected: usize = g
            .skeleton
            .stems
            .iter()
            .filter(|s| s.parent.is_some())
            .map(|s| sides_for(s.radius, p.mesh_quality, 0) as usize)
            .sum();
        assert_eq!(open, expected, "{}: open edges besides the buried stem bases", preset.name);
    }
}

#[test]
fn uv_v_is_continuous_and_increasing_along_stems() {
    let g = generate(&TreeParams::default()).unwrap();
    // Along each ring column (same u), v never decreases from one ring to the next.
    let uv = &g.mesh.uvs;
    let mut checked = 0;
    for t in g.mesh.indices.chunks_exact(6).take(20_000) {
        // Quads are (a, b, c), (a, c, d) with d one ring above a.
        let (a, d) = (t[0] as usize, t[5] as usize);
        if uv[a * 2] == uv[d * 2] {
            assert!(uv[d * 2 + 1] >= uv[a * 2 + 1], "v decreases along a stem");
            checked += 1;
        }
    }
    assert!(checked > 1000);
}

#[test]
fn quality_changes_resolution_and_budget_stops_runaways() {
    let lo = generate(&TreeParams { mesh_quality: 0.5, ..TreeParams::default() }).unwrap();
    let hi = generate(&TreeParams { mesh_quality: 2.0, ..TreeParams::default() }).unwrap();
    assert!(hi.stats.vertices > lo.stats.vertices * 2);
    let e = generate(&TreeParams { max_vertices: 10_000, ..TreeParams::default() }).unwrap_err();
    assert_eq!(e.to_json().split('"').nth(3), Some("budget"), "{e:?}");
    assert!(e.message().contains("max_vertices budget of 10000"), "{e}");
}

// Regressions: each found while bringing up the Weeping Willow preset.

#[test]
fn regression_trunk_cap_faces_down_under_strong_flare() {
    // The base fan once reused the flared ring's up-tilted side normals: wound against them.
    let g = generate(&TreeParams { flare: 5.0, ..TreeParams::default() }).unwrap();
    assert_mesh_invariants(&g, "flare 5");
}

#[test]
fn regression_split_clones_never_coincide_with_their_original() {
    // With the split angle clamped to 0 and strong downward attraction, clones once landed
    // exactly on top of their originals (edges shared by four triangles).
    let mut p = TreeParams { attraction_up: -10.0, ..TreeParams::default() };
    p.level[1].seg_splits = 0.5;
    p.level[2].seg_splits = 0.5;
    p.level[2].curve_v = 0.0;
    let g = generate(&p).unwrap();
    assert!(edge_uses(&g.mesh).values().all(|&u| u <= 2));
    assert_mesh_invariants(&g, "clones");
}

#[test]
fn regression_stems_pruned_to_nothing_are_dropped() {
    // Pruning with a tiny envelope once left zero-length stems whose rings collapsed.
    let g = generate(&TreeParams { prune_ratio: 1.0, prune_width: 0.02, ..TreeParams::default() }).unwrap();
    assert_mesh_invariants(&g, "pruned");
    assert!(g.skeleton.stems.iter().all(|s| s.length > 0.0));
}
