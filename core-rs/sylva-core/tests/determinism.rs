//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "c9ffeacab08f8a76"),
    ("quaking_aspen", "10b445fa84b25196"),
    ("black_tupelo", "527c11f38d54d529"),
    ("weeping_willow", "18c450af130f2cf4"),
    ("ca_black_oak", "8df0cc8f6b026b23"),
    ("fir", "afcccfc9573a5438"),
    ("oak", "4f1198b299881caa"),
    ("cypress", "9d3dd43f71380fed"),
    ("umbrella", "67f2a34e31445d13"),
    ("weeping", "fb9f9ab2e2273d71"),
    ("grown_broadleaf", "f3a478a31ca15414"),
    ("grown_shrub", "c4744761aa0e4891"),
    ("grown_hedgerow", "6a8921a9ab10b7d1"),
    ("grown_beside_wall", "4a3d0087b6887de0"),
    ("grown_bushy", "6e500d6b0b27fba1"),
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
