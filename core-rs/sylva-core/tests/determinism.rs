//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "41088e503ac19c21"),
    ("quaking_aspen", "91b0baa6c862f71d"),
    ("black_tupelo", "f425d6d44ba6afca"),
    ("weeping_willow", "cb43ff9204212537"),
    ("ca_black_oak", "21a59d820a353756"),
    ("fir", "fd19447ede149177"),
    ("oak", "c26a650d6393dd09"),
    ("cypress", "00c3a2dc3c8d2663"),
    ("umbrella", "808b3529e27a0ea8"),
    ("weeping", "59ed23a398c41c55"),
    ("grown_broadleaf", "c52199d4c9015def"),
    ("grown_shrub", "cb51bb7fe018aa5f"),
    ("grown_hedgerow", "7f0eedd7a6e0491c"),
    ("grown_beside_wall", "14f2dd9b4794a6f4"),
    ("grown_bushy", "0f48cd8e2545c527"),
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
