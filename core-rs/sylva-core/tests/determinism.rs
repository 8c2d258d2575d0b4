//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "3dede5a4b2fee07d"),
    ("quaking_aspen", "9bb77dd4c1cc1201"),
    ("black_tupelo", "ab3abfa995a37c6d"),
    ("weeping_willow", "33655607de27dfb5"),
    ("ca_black_oak", "0c488f23e610471b"),
    ("fir", "5696f5cf3b5026d1"),
    ("oak", "a9545c52dc740453"),
    ("cypress", "9eea0d106b059a1a"),
    ("umbrella", "5db452b385874075"),
    ("weeping", "d8fa5e003c0154f1"),
    ("grown_broadleaf", "f14639c078d44fe7"),
    ("grown_shrub", "839c9205f41e4c18"),
    ("grown_hedgerow", "2c72c177817fce61"),
    ("grown_beside_wall", "1b1d6e9ee09b5ce5"),
    ("grown_bushy", "f0810a70a52776ab"),
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
