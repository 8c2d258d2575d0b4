//! The drawn crown (`sylva_core::edits::crown`): Crown Shape *Drawn* sets the level-1 branch
//! lengths of a Weber & Penn tree from the outline and its envelope preview holds them; without
//! an outline it is Cylindrical; a grown tree's markers fill the outline's solid of revolution.

use glam::{Vec2, Vec3};
use sylva_core::crown::profile_radius;
use sylva_core::edits::crown::{drawn_volume, self_crossing, DrawnCrown};
use sylva_core::params::{Crown, SkeletonParams};
use sylva_core::skeleton::{self, preview_profile, preview_profile_with_crown, Skeleton};
use sylva_core::{growth, presets, CrownShape, TreeParams};

fn params(shape: CrownShape) -> TreeParams {
    let mut p =
        TreeParams { skeleton: SkeletonParams { shape, levels: 2, ..Default::default() }, ..TreeParams::default() };
    p.skeleton.level[1].length_v = 0.0;
    p.skeleton.level[1].branches = 60;
    p
}

fn outline(points: &[[f32; 2]]) -> Crown {
    Crown { outline: points.iter().map(|&[r, y]| Vec2::new(r, y)).collect() }
}

/// The bits of every stem point of a skeleton.
fn bits(s: &Skeleton) -> Vec<u32> {
    s.stems.iter().flat_map(|st| st.points.iter().flat_map(|q| q.to_array())).map(f32::to_bits).collect()
}

/// The outline of a crown as tall as `base`'s trunk: widest near the crown base when `wide_low`,
/// near the top otherwise.
fn crown_for(base: &Skeleton, wide_low: bool) -> Crown {
    let (lo, hi) = (base.crown_base, base.stems[0].tip().y);
    let (a, b) = if wide_low { (3.0, 0.6) } else { (0.6, 3.0) };
    outline(&[[0.0, lo - 0.5], [a, lo + 0.5], [b, hi - 0.5], [0.0, hi + 0.5]])
}

#[test]
fn drawn_without_an_outline_is_cylindrical() {
    let (drawn, cyl) = (params(CrownShape::Drawn), params(CrownShape::Cylindrical));
    let (a, b) = (skeleton::build(&drawn.skeleton).unwrap(), skeleton::build(&cyl.skeleton).unwrap());
    assert_eq!(bits(&a), bits(&b));
    assert_eq!(preview_profile(&a, &drawn.skeleton, 32), preview_profile(&b, &cyl.skeleton, 32));
    // An outline is used only with the Drawn shape.
    let crown = crown_for(&b, true);
    assert_eq!(bits(&skeleton::build_with_crown(&cyl.skeleton, Some(&crown)).unwrap()), bits(&b));
}

#[test]
fn drawn_branch_lengths_follow_the_outline() {
    let p = params(CrownShape::Drawn);
    let plain = skeleton::build(&p.skeleton).unwrap();
    for wide_low in [true, false] {
        let crown = crown_for(&plain, wide_low);
        let d = DrawnCrown::new(&crown).unwrap();
        let s = skeleton::build_with_crown(&p.skeleton, Some(&crown)).unwrap();
        let trunk_len = s.stems[0].chain_length;
        let (lo, hi) = (s.crown_base, s.stems[0].tip().y);
        let (mut low, mut high) = (Vec::new(), Vec::new());
        for st in s.stems.iter().filter(|x| x.level == 1) {
            // L = L_trunk * l1_length * ShapeRatio, the ratio from the outline at the attachment height.
            let y = st.base().y;
            let want = trunk_len * p.skeleton.level[1].length * d.ratio_at_height(y);
            assert!((st.chain_length - want).abs() <= 1e-4 * want.max(1.0), "at {y} m: {} vs {want}", st.chain_length);
            let f = (y - lo) / (hi - lo);
            if f < 0.3 {
                low.push(st.chain_length);
            } else if f > 0.7 {
                high.push(st.chain_length);
            }
        }
        let mean = |v: &[f32]| v.iter().sum::<f32>() / v.len() as f32;
        let (l, h) = (mean(&low), mean(&high));
        assert!(!low.is_empty() && !high.is_empty());
        if wide_low {
            assert!(l > 2.0 * h, "wide at the bottom: low {l} high {h}");
        } else {
            assert!(h > 2.0 * l, "wide at the top: low {l} high {h}");
        }
        // The preview draws the drawn envelope: wider where the outline is, and it holds every
        // level-1 branch.
        let profile = preview_profile_with_crown(&s, &p.skeleton, Some(&crown), 64);
        let at = |f: f32| profile_radius(&profile, lo + f * (hi - lo));
        assert_eq!(wide_low, at(0.15) > at(0.85), "preview {:?}", (at(0.15), at(0.85)));
        for st in s.stems.iter().filter(|x| x.level == 1) {
            for q in st.points.iter() {
                let r = (q.x * q.x + q.z * q.z).sqrt();
                assert!(r <= profile_radius(&profile, q.y) + 0.05, "branch point {q} outside the preview");
            }
        }
    }
}

#[test]
fn a_grown_tree_fills_the_drawn_crown() {
    let p = presets::find("grown_broadleaf").unwrap().params().unwrap();
    let crown = outline(&[[0.0, 3.0], [4.0, 4.0], [1.5, 7.0], [3.0, 10.0], [0.0, 11.0]]);
    assert_eq!(self_crossing(&crown.outline), None);
    let g = growth::grow_with_crown(&p.skeleton, Some(&crown), None).unwrap();
    let inside = drawn_volume(&crown.outline);
    assert!(g.markers.len() > 200, "{} markers", g.markers.len());
    assert!(g.markers.iter().all(|m| inside(*m)), "a marker outside the drawn crown");
    // Every marker lies within the outline's width at its height, and the bulges are filled
    // out to near their width (the waist at 7 m is 1.5 m wide, the bulge at 4 m 4 m).
    let d = DrawnCrown::new(&crown).unwrap();
    let rho = |m: &Vec3| Vec3::new(m.x, 0.0, m.z).length();
    assert!(g.markers.iter().all(|m| rho(m) <= d.width_at(m.y) + 1e-4));
    let far = |y0: f32, y1: f32| g.markers.iter().filter(|m| m.y > y0 && m.y < y1).map(rho).fold(0.0f32, f32::max);
    assert!(far(6.9, 7.1) < 1.6 && far(3.8, 4.2) > 3.0, "{} {}", far(6.9, 7.1), far(3.8, 4.2));
    let sk = growth::skeleton(&p.skeleton, &g);
    assert!(sk.stems.len() > 10);
    let plain = growth::grow(&p.skeleton).unwrap();
    assert_ne!(plain.markers, g.markers);
}

#[test]
fn self_crossing_finds_a_bow_tie() {
    let bow_tie = outline(&[[0.0, 2.0], [2.0, 6.0], [2.0, 2.0], [0.0, 6.0]]);
    assert_eq!(self_crossing(&bow_tie.outline), Some((0, 2)));
    let convex = outline(&[[0.0, 2.0], [2.5, 4.0], [2.0, 8.0], [0.0, 9.0]]);
    assert_eq!(self_crossing(&convex.outline), None);
}
