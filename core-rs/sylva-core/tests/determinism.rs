//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "d2b61999edbf23df"),
    ("quaking_aspen", "c50cf1807a9a9ae3"),
    ("black_tupelo", "507cfd5373a069d3"),
    ("weeping_willow", "da49d8cef0f8ff90"),
    ("ca_black_oak", "91dfe3e01ebaca00"),
    ("fir", "299e7018761dc5de"),
    ("oak", "82190e7a40a5f91d"),
    ("cypress", "cc4b0063bb99008f"),
    ("umbrella", "9b9b3ba4ae758390"),
    ("weeping", "5f025018215fc10b"),
    ("grown_broadleaf", "9a06df8265303b9f"),
    ("grown_shrub", "04fd4947b16ac80e"),
    ("grown_hedgerow", "d9bd855ced25316d"),
    ("grown_beside_wall", "a4e6551b0317927d"),
    ("grown_bushy", "2ebb34802634c975"),
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
