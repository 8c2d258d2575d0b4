//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "9ebdd3672806c973"),
    ("quaking_aspen", "2ff232666a95a842"),
    ("black_tupelo", "a81e5183de9807a3"),
    ("weeping_willow", "19e420221ac203bf"),
    ("ca_black_oak", "df7ef830c88db7b3"),
    ("fir", "1c7fd4e10213a9cf"),
    ("oak", "d5a71fad198689fa"),
    ("cypress", "d5aada14de3ce6f2"),
    ("umbrella", "2ef1442501c748fa"),
    ("weeping", "4c3cf2395c261ad8"),
    ("grown_broadleaf", "bcdc35bd5259db15"),
    ("grown_shrub", "007d56c892a40513"),
    ("grown_hedgerow", "0f63f834ed25fdc9"),
    ("grown_beside_wall", "8c82a5e3185687fe"),
    ("grown_bushy", "be4baa5305595dd8"),
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
