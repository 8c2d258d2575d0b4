//! Leaf determinism (issue 4): a golden content hash per leaf preset (outline, triangulation,
//! veins, auxins, meshes, textures), pinned like the tree presets'. The wasm build must give the
//! same hashes (`npm run bench` compares them).

use sylva_core::leaf::presets::LEAF_PRESETS;
use sylva_core::leaf::Leaf;
use sylva_core::TreeParams;

/// The leaf of tree parameters `p`: its leaf parameters and Petiole Length.
fn generate(p: &TreeParams) -> Result<Leaf, sylva_core::SylvaError> {
    sylva_core::leaf::generate(&p.leaf, p.foliage.leaf_petiole)
}

const GOLDEN: &[(&str, &str)] = &[
    ("oak", "92fba69a8a7575d9"),
    ("black_oak", "a28dee747ce76287"),
    ("maple", "48d465c12d38349c"),
    ("birch", "359f6e9ab4b3df70"),
    ("aspen", "22dee3b7e892a6c3"),
    ("willow", "8250f969fa2c24dd"),
    ("tupelo", "d4024b2675e0d87b"),
    ("ginkgo", "fc0bebd1f956c591"),
    ("cherry", "6946e198f5d443c1"),
    ("apple", "045dc583950dd08d"),
    ("pine", "0427650aa9388f85"),
    ("fir", "810cb18ec87fd389"),
    ("cypress", "c1ef326598edb2d3"),
    ("superformula_oak", "70e4db4fbbcfab01"),
    ("superformula_maple", "9aa9b8ea0ac66148"),
    ("superformula_birch", "b7357091182e28ab"),
    ("superformula_willow", "f00d88cf2d7ed763"),
    ("superformula_pine", "a998de573e09c3c3"),
];

#[test]
fn golden_hash_per_leaf_preset() {
    let actual: Vec<(&str, String)> =
        LEAF_PRESETS.iter().map(|p| (p.name, generate(&p.params().unwrap()).unwrap().hash_hex())).collect();
    let expected: Vec<(&str, String)> = GOLDEN.iter().map(|(n, h)| (*n, h.to_string())).collect();
    let table: String = actual.iter().map(|(n, h)| format!("    (\"{n}\", \"{h}\"),\n")).collect();
    assert_eq!(actual, expected, "golden leaf hashes changed; if on purpose, paste:\n{table}");
}

#[test]
fn same_parameters_same_leaf_and_seeds_matter() {
    let p = LEAF_PRESETS[1].params().unwrap();
    let (a, b) = (generate(&p).unwrap(), generate(&p).unwrap());
    assert_eq!(a.hash, b.hash);
    assert_eq!(a.mesh, b.mesh);
    assert_eq!(a.veins, b.veins);
    let mut q = p.clone();
    q.leaf.leaf_vein_seed += 1;
    assert_ne!(generate(&q).unwrap().hash, a.hash, "the vein seed moves the auxins");
    let mut q = p.clone();
    q.leaf.leaf_asymmetry_seed = 9;
    assert_ne!(generate(&q).unwrap().hash, a.hash, "the asymmetry seed changes the outline");
    // The tree's own seed and parameters do not touch the leaf.
    let mut q = p.clone();
    q.skeleton.seed = 12345;
    q.skeleton.scale = 30.0;
    assert_eq!(generate(&q).unwrap().hash, a.hash);
}
