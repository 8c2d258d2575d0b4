//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "0f519801ed6ae1dc"),
    ("quaking_aspen", "1d5d018be98dc89a"),
    ("black_tupelo", "ee848675035e756d"),
    ("weeping_willow", "534b3559fddb59ee"),
    ("ca_black_oak", "7975c61141e7d5ae"),
    ("fir", "157328651c5181e6"),
    ("oak", "84c9e46f0016bd2c"),
    ("cypress", "a9c340745147facd"),
    ("umbrella", "36b7d2a82798da6d"),
    ("weeping", "8eb43928a82fc8e5"),
    ("grown_broadleaf", "a725b3c584701a0f"),
    ("grown_shrub", "c6d7085ea588fca0"),
    ("grown_hedgerow", "1a489bbca0ef0469"),
    ("grown_beside_wall", "fafc2a5e6ed10071"),
    ("grown_bushy", "d9d5d0641d449b58"),
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
