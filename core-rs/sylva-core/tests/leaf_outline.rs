//! Leaf outline and margin (issue 4): the leaf frame, teeth visible in the outline, serrate
//! teeth leaning toward the tip, exact mirror symmetry for asymmetry seed 0, and the
//! curvature-adaptive sampling.

mod leaf_common;

use glam::Vec2;
use leaf_common::{random_leaf_params, stages};
use sylva_core::leaf::geom::polygon_area;
use sylva_core::leaf::presets::LEAF_PRESETS;
use sylva_core::leaf::{margin, outline, Outline};
use sylva_core::params::{LeafMargin, LeafOutline};
use sylva_core::rng::Rng;
use sylva_core::TreeParams;

fn outline_of(p: &TreeParams) -> Outline {
    margin::build(&p.leaf, &outline::build(&p.leaf)).unwrap()
}

/// The outline, or `None` for parameters refused for a blade without area.
fn try_outline(p: &TreeParams) -> Option<Outline> {
    margin::build(&p.leaf, &outline::build(&p.leaf)).ok()
}

/// A round blade (the superformula with m = 4, a = b = 1, n1 = n2 = n3 = 2 is a circle).
fn circle(margin: LeafMargin, teeth: u32, depth: f32) -> TreeParams {
    let mut p = TreeParams::default();
    p.leaf.leaf_outline = LeafOutline::Superformula;
    (p.leaf.leaf_m, p.leaf.leaf_a, p.leaf.leaf_b, p.leaf.leaf_n1, p.leaf.leaf_n2, p.leaf.leaf_n3, p.leaf.leaf_aspect) =
        (4.0, 1.0, 1.0, 2.0, 2.0, 2.0, 1.0);
    (p.leaf.leaf_margin, p.leaf.leaf_teeth, p.leaf.leaf_tooth_depth) = (margin, teeth, depth);
    p
}

/// Peaks of a closed profile that rise at least `delta` above the valleys on both sides.
fn count_peaks(values: &[f32], delta: f32) -> usize {
    let n = values.len();
    let start = (0..n).min_by(|&a, &b| values[a].total_cmp(&values[b])).unwrap();
    let (mut peaks, mut rising, mut lo, mut hi) = (0, true, values[start], values[start]);
    for k in 1..=n {
        let v = values[(start + k) % n];
        if rising {
            hi = hi.max(v);
            if hi - v >= delta && hi - lo >= delta {
                peaks += 1;
                rising = false;
                lo = v;
            }
        } else {
            lo = lo.min(v);
            if v - lo >= delta {
                rising = true;
                hi = v;
            }
        }
    }
    peaks
}

fn radii(o: &Outline) -> Vec<f32> {
    o.points.iter().map(|&q| (q - o.center).length()).collect()
}

#[test]
fn the_tooth_count_is_visible_in_the_outline() {
    for margin in [LeafMargin::Serrate, LeafMargin::Dentate, LeafMargin::Crenate, LeafMargin::Lobed] {
        for teeth in [3, 5, 8, 13, 24, 40] {
            let o = outline_of(&circle(margin, teeth, 0.15));
            let peaks = count_peaks(&radii(&o), 0.025);
            assert_eq!(peaks, teeth as usize, "{margin:?} with {teeth} teeth shows {peaks}");
        }
    }
    let entire = outline_of(&circle(LeafMargin::Entire, 12, 0.15));
    assert_eq!(count_peaks(&radii(&entire), 0.025), 0, "an entire margin has no teeth");
    // The lobed presets: the margin's lobes sit on the superformula's.
    for (name, lobes) in [("superformula_maple", 5), ("superformula_oak", 7)] {
        let o = outline_of(&sylva_core::leaf::presets::find(name).unwrap().params().unwrap());
        assert_eq!(count_peaks(&radii(&o), 0.05), lobes, "{name}");
    }
}

#[test]
fn serrate_teeth_lean_toward_the_tip() {
    let o = outline_of(&{
        let mut p = circle(LeafMargin::Serrate, 16, 0.2);
        p.leaf.leaf_tooth_sharpness = 0.8;
        p
    });
    // Along the left half from the tip: angle from the tip around the centre, and radius.
    let half = o.half(0);
    let prof: Vec<(f32, f32)> = half
        .iter()
        .map(|&q| {
            let d = q - o.center;
            (sylva_core::math::atan2(-d.x, d.y), d.length())
        })
        .collect();
    let mut checked = 0;
    let minima: Vec<usize> =
        (1..prof.len() - 1).filter(|&i| prof[i].1 < prof[i - 1].1 && prof[i].1 <= prof[i + 1].1).collect();
    for w in minima.windows(2) {
        let (a, b) = (w[0], w[1]);
        let apex = (a..=b).max_by(|&i, &j| prof[i].1.total_cmp(&prof[j].1)).unwrap();
        let (toward_tip, toward_base) = (prof[apex].0 - prof[a].0, prof[b].0 - prof[apex].0);
        assert!(toward_tip < 0.6 * toward_base, "tooth apex at {apex} is not hooked toward the tip");
        checked += 1;
    }
    assert!(checked >= 5, "{checked} teeth checked");
}

fn assert_mirrored(o: &Outline, what: &str) {
    let n = o.points.len();
    assert_eq!(o.base_index * 2, n, "{what}: the halves have the same number of points");
    for i in 1..o.base_index {
        let (l, r) = (o.points[i], o.points[n - i]);
        assert!(l.x == -r.x && l.y == r.y, "{what}: point {i} {l} is not the mirror of {r}");
    }
}

#[test]
fn asymmetry_seed_zero_is_exactly_mirror_symmetric() {
    // Every preset without an Asymmetry Seed (the oak has one: irregular lobes, halves apart).
    for preset in LEAF_PRESETS {
        let p = preset.params().unwrap();
        if p.leaf.leaf_asymmetry_seed == 0 {
            assert_mirrored(&outline_of(&p), preset.name);
        }
    }
    let mut rng = Rng::new(5, "leaf-symmetry");
    let mut asymmetric = 0;
    for case in 0..60 {
        let mut p = random_leaf_params(&mut rng);
        p.leaf.leaf_asymmetry_seed = 0;
        let Some(o) = try_outline(&p) else {
            asymmetric += 1;
            continue;
        };
        assert_mirrored(&o, &format!("case {case}"));
        p.leaf.leaf_asymmetry_seed = 1 + case;
        let Some(o) = try_outline(&p) else {
            asymmetric += 1;
            continue;
        };
        let n = o.points.len();
        let mirrored = o.base_index * 2 == n && (1..o.base_index).all(|i| o.points[i].x == -o.points[n - i].x);
        asymmetric += usize::from(!mirrored);
    }
    assert!(asymmetric >= 55, "a non-zero seed breaks the symmetry ({asymmetric} of 60)");
}

#[test]
fn the_leaf_frame_base_at_origin_tip_up_counter_clockwise() {
    let mut rng = Rng::new(11, "leaf-frame");
    for case in 0..120 {
        let p = random_leaf_params(&mut rng);
        let Some(o) = try_outline(&p) else {
            continue;
        };
        assert_eq!(o.points[0], Vec2::new(0.0, 1.0), "case {case}: tip");
        assert_eq!(o.points[o.base_index], Vec2::ZERO, "case {case}: base");
        assert!(polygon_area(&o.points) > 0.0, "case {case}: counter-clockwise");
        assert!(o.points[1..o.base_index].iter().all(|q| q.x <= 0.0), "case {case}: left half at x <= 0");
        assert!(o.points[o.base_index + 1..].iter().all(|q| q.x >= 0.0), "case {case}: right half at x >= 0");
        assert!(o.points.iter().all(|q| q.is_finite()));
        if p.leaf.leaf_outline == LeafOutline::Superformula && p.leaf.leaf_asymmetry_seed == 0 {
            let (lo, hi) = sylva_core::leaf::geom::bounds(&o.points);
            let aspect = (hi.x - lo.x) / (hi.y - lo.y);
            assert!(
                (aspect / p.leaf.leaf_aspect - 1.0).abs() < 0.05,
                "case {case}: width/height {aspect} for aspect {}",
                p.leaf.leaf_aspect
            );
        }
    }
}

#[test]
fn sampling_is_curvature_adaptive() {
    let (smooth, _) = stages(&circle(LeafMargin::Entire, 0, 0.0));
    let (toothed, _) = stages(&circle(LeafMargin::Dentate, 40, 0.1));
    assert!(toothed.points.len() > 3 * smooth.points.len(), "{} vs {}", toothed.points.len(), smooth.points.len());
    // Denser where the edge bends: on the willow blade (long, nearly straight flanks, a sharp
    // tip) the longest edge is many times the shortest, and no two edges turn by much more than
    // the 15° refinement limit away from the tip and the base.
    let o = outline_of(&sylva_core::leaf::presets::find("superformula_willow").unwrap().params().unwrap());
    let n = o.points.len();
    let edges: Vec<f32> = (0..n).map(|i| (o.points[(i + 1) % n] - o.points[i]).length()).collect();
    let (shortest, longest) = edges.iter().fold((f32::INFINITY, 0.0f32), |(a, b), &e| (a.min(e), b.max(e)));
    assert!(longest > 5.0 * shortest, "edges {shortest}..{longest}");
    for i in (0..n).filter(|&i| i != 0 && i != o.base_index) {
        let (a, b, c) = (o.points[(i + n - 1) % n], o.points[i], o.points[(i + 1) % n]);
        let (u, v) = ((b - a).normalize(), (c - b).normalize());
        assert!(u.dot(v) > 0.94, "vertex {i} turns by acos({})", u.dot(v));
    }
}
