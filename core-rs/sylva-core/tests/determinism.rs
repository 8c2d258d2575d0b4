//! Determinism (standing rule 5): golden content hashes per preset, pinned like rapier's
//! snapshot tests. The same hashes are checked against the wasm build by `scripts/wasm-parity.mjs`.
//! A hash change means every user's share URL now draws a different tree: change a golden
//! value only on purpose, and say so in the commit.

use sylva_core::params::SkeletonParams;
use sylva_core::{generate, presets::PRESETS, TreeParams};

const GOLDEN: &[(&str, &str)] = &[
    ("default", "30fa5813df2c837f"),
    ("quaking_aspen", "14b7394c730bf1b2"),
    ("black_tupelo", "f152a72d17b516b1"),
    ("weeping_willow", "f8611f674b7856e0"),
    ("ca_black_oak", "039431ee7c62e177"),
    ("fir", "c67f2b6ff88933b7"),
    ("oak", "4a112b7870f4654e"),
    ("cypress", "fe0bfcfb389de051"),
    ("umbrella", "b490dcf7ac471bdc"),
    ("weeping", "a567c59b121ad2ac"),
    ("cherry", "d52e4376d47b169d"),
    ("apple", "a1035edd3447c206"),
    ("grown_broadleaf", "654350748d87a769"),
    ("grown_shrub", "6bfc872f9c669d7b"),
    ("grown_hedgerow", "f283bda79442a16c"),
    ("grown_beside_wall", "4c09e556bb781e66"),
    ("grown_bushy", "082651432f9ef10a"),
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
    let c =
        generate(&TreeParams { skeleton: SkeletonParams { seed: 2, ..Default::default() }, ..TreeParams::default() })
            .unwrap();
    assert_ne!(a.hash, c.hash);
}
