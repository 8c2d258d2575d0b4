//! Leaf triangulation (issue 4): every preset and many random parameter sets triangulate into a
//! valid embedding of the blade (no inverted or overlapping triangles, area = outline area),
//! with the ring method where the outline is star-shaped and the robust method elsewhere.

mod leaf_common;

use leaf_common::{random_leaf_params, stages, try_stages};
use sylva_core::leaf::presets::LEAF_PRESETS;
use sylva_core::leaf::triangulate::{self, cdt, Method};
use sylva_core::rng::Rng;

#[test]
fn every_preset_triangulates_validly_with_both_methods() {
    for preset in LEAF_PRESETS {
        let p = preset.params().unwrap();
        let (outline, tri) = stages(&p);
        triangulate::validate(&outline.points, &tri).unwrap_or_else(|e| panic!("{}: {e}", preset.name));
        if preset.name.starts_with("superformula_") {
            assert_eq!(tri.method, Method::Rings, "{}: the superformula presets are star-shaped", preset.name);
        }
        let robust = cdt::build(&outline.points, p.leaf.leaf_rings);
        triangulate::validate(&outline.points, &robust).unwrap_or_else(|e| panic!("{} (robust): {e}", preset.name));
        if p.leaf.leaf_aspect >= 0.1 {
            assert!(robust.vertices.len() > outline.points.len(), "{}: interior points", preset.name);
        }
    }
}

#[test]
fn random_parameters_always_triangulate_validly() {
    let mut rng = Rng::new(2024, "leaf-triangulation-property");
    let (mut rings, mut robust, mut refused) = (0, 0, 0);
    for case in 0..600 {
        let p = random_leaf_params(&mut rng);
        let Ok((outline, tri)) = try_stages(&p) else {
            // Extreme superformula exponents can draw a blade without area: refused by name.
            refused += 1;
            continue;
        };
        if let Err(e) = triangulate::validate(&outline.points, &tri) {
            panic!(
                "case {case} ({:?}, {} points): {e}\nparams: {:?}",
                tri.method,
                outline.points.len(),
                p.non_defaults()
            );
        }
        match tri.method {
            Method::Rings => rings += 1,
            Method::Cdt => robust += 1,
        }
    }
    assert!(rings > 150 && robust > 15, "both methods exercised: {rings} rings, {robust} robust");
    assert!(refused < 8, "{refused} parameter sets refused");
}

#[test]
fn deep_lobes_on_a_waisted_spline_fall_back_to_the_robust_method() {
    let mut p = sylva_core::TreeParams::default();
    p.leaf.leaf_outline = sylva_core::params::LeafOutline::Spline;
    (p.leaf.leaf_angle1, p.leaf.leaf_l1, p.leaf.leaf_angle2, p.leaf.leaf_l2) = (90.0, 1.0, 10.0, 0.2);
    p.leaf.leaf_margin = sylva_core::params::LeafMargin::Lobed;
    (p.leaf.leaf_teeth, p.leaf.leaf_tooth_depth) = (9, 1.0);
    let (outline, tri) = stages(&p);
    assert_eq!(tri.method, Method::Cdt);
    triangulate::validate(&outline.points, &tri).unwrap();
}
