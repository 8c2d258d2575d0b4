//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "e7d19e9bb4466827"),
    ("quaking_aspen", "ff80a5db3ea2da5b"),
    ("black_tupelo", "8afa194cab056338"),
    ("weeping_willow", "31a9726d507dbbfc"),
    ("ca_black_oak", "a22c26af66b60024"),
    ("fir", "5327545399bb634b"),
    ("oak", "728fbafa9153ebf2"),
    ("cypress", "fb3f643013029ed8"),
    ("umbrella", "10d26da62b6b2cf7"),
    ("weeping", "23bdca4475358959"),
    ("grown_broadleaf", "b407898ad46f3ff8"),
    ("grown_shrub", "201cf4b3a01a9792"),
    ("grown_hedgerow", "5380c8c008b93283"),
    ("grown_beside_wall", "f8bea739e2b5f4f7"),
    ("grown_bushy", "1b358ec0246268f3"),
];

#[test]
fn golden_hash_per_preset() {
    let actual: Vec<(&str, String)> =
        PRESETS.iter().map(|p| (p.name, generate(&p.params().unwrap()).unwrap().hash_hex())).collect();
    let expected: Vec<(&str, String)> = GOLDEN.iter().map(|(n, h)| (*n, h.to_string())).collect();
    let table: String = actual.iter().map(|(n, h)| format!("    (\"{n}\", \"{h}\"),\n")).collect();
    assert_eq!(actual, expected, "golden hashes changed; if on purpose, paste:\n{table}");
}

#[test]
fn same_input_same_bytes_and_seed_matters() {
    let a = generate(&TreeParams::default()).unwrap();
    let b = generate(&TreeParams::default()).unwrap();
    assert_eq!(a.mesh, b.mesh);
    let c = generate(&TreeParams { seed: 2, ..TreeParams::default() }).unwrap();
    assert_ne!(a.hash, c.hash);
}
