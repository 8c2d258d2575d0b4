//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "f8604965f3dcb5e4"),
    ("quaking_aspen", "ffcf97061e516815"),
    ("black_tupelo", "b94a0ce247cf74f5"),
    ("weeping_willow", "1951b7036e71d0c7"),
    ("ca_black_oak", "371956810a71d21c"),
    ("fir", "390499712995ad75"),
    ("oak", "bd41319917b9264f"),
    ("cypress", "ef4e755937d4726d"),
    ("umbrella", "29f954fd46562601"),
    ("weeping", "8a0faba003cdd746"),
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
