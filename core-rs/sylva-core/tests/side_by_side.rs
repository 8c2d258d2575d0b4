//! The bark and the leaf placement of an update run side by side natively (two threads, see
//! `session/stages.rs`): every preset's buffers must be the bytes of the same update run on one
//! thread (`par::serial`), and a failing side must give the error the one-thread order gives.

use sylva_core::Generated;
use sylva_core::{generate, par, presets::PRESETS, TreeParams};

/// Every buffer of a generation, as bytes, in a fixed order (timings left out).
fn bytes(g: &Generated) -> Vec<u8> {
    let f = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let mut out = Vec::new();
    for v in [&g.mesh.positions, &g.mesh.normals, &g.mesh.uvs, &g.mesh.wind, &g.foliage.matrices, &g.foliage.colors] {
        out.extend(f(v));
    }
    out.extend(g.mesh.indices.iter().flat_map(|x| x.to_le_bytes()));
    out.extend(&g.mesh.shade);
    out.extend(g.hash.to_le_bytes());
    out
}

#[test]
fn side_by_side_gives_the_one_thread_bytes_for_every_preset() {
    assert!(par::threads() > 1 || cfg!(target_arch = "wasm32"), "this test needs two cores to mean anything");
    for p in PRESETS {
        let params = p.params().unwrap();
        let both = generate(&params).unwrap();
        let one = par::serial(|| generate(&params)).unwrap();
        assert_eq!(both.hash, one.hash, "{}", p.name);
        assert!(bytes(&both) == bytes(&one), "{}: buffers differ", p.name);
        // The overlap shows in the total: never more than the stages' sum.
        let sum: f64 = both.stats.stage_ms.iter().map(|(_, ms)| ms).sum();
        assert!(both.stats.total_ms <= sum + 1e-9, "{}: total {} over the stages' {sum}", p.name, both.stats.total_ms);
    }
}

#[test]
fn a_failing_side_gives_the_one_thread_error() {
    // The bark over its vertex budget, then the leaves over theirs, then both: the error is the
    // one the stages give in order (the bark's first).
    let mut bark = TreeParams::default();
    bark.skeleton.max_vertices = 1_000;
    let mut leaves = TreeParams::default();
    leaves.foliage.max_leaves = 1_000;
    let mut both = bark.clone();
    both.foliage.max_leaves = 1_000;
    for params in [bark, leaves, both] {
        let side = generate(&params).err().map(|e| e.to_string());
        let one = par::serial(|| generate(&params)).err().map(|e| e.to_string());
        assert!(side.is_some(), "over budget");
        assert_eq!(side, one);
    }
}
