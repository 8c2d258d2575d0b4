//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "63826ee10c07a122"),
    ("quaking_aspen", "a289df8833c65358"),
    ("black_tupelo", "cdefeef3530a1d6c"),
    ("weeping_willow", "41f2b8d4fa73267a"),
    ("ca_black_oak", "a253462c34b548b2"),
    ("fir", "8f057da952805b67"),
    ("oak", "b26ca9ab4b59f903"),
    ("cypress", "e6ac28872dbac5c2"),
    ("umbrella", "5619d35b037050af"),
    ("weeping", "845c62d24d6e2b0c"),
    ("grown_broadleaf", "f6cd8d805c39f75a"),
    ("grown_shrub", "4723ce49887f4996"),
    ("grown_hedgerow", "6179717aeb513a8b"),
    ("grown_beside_wall", "f06a15bfc45146a3"),
    ("grown_bushy", "37d4c4ae7639486f"),
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
