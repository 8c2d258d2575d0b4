//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "80ecc94291028c1f"),
    ("quaking_aspen", "7fd9784428ed8a7d"),
    ("black_tupelo", "c564f4e5aa040179"),
    ("weeping_willow", "b77d221dd25c1c85"),
    ("ca_black_oak", "2fe6277b70df5bec"),
    ("fir", "f68448f72f16a40f"),
    ("oak", "cf450eda4db81da0"),
    ("cypress", "4603bc3fc2ef27f4"),
    ("umbrella", "52ce5df6d8686db1"),
    ("weeping", "8f971e366eadb8cc"),
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
