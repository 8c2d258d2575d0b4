//! Issue 3: crown shapes, Angle Spread and the envelope preview, checked on the formulas and on
//! generated trees (silhouettes rather than exact floats).
#![allow(clippy::disallowed_methods, reason = "the test's own measures, not output bytes")]

use sylva_core::crown::profile_radius;
use sylva_core::params::SkeletonParams;
use sylva_core::skeleton::preview_profile;
use sylva_core::skeleton::{self, Skeleton};
use sylva_core::{CrownShape, TreeParams};

/// Weber & Penn's ShapeRatio table (1995, §4.3), written out independently of `CrownShape::ratio`.
fn reference(shape: usize, r: f64) -> f64 {
    use std::f64::consts::PI;
    match shape {
        0 => 0.2 + 0.8 * r,
        1 => 0.2 + 0.8 * (PI * r).sin(),
        2 => 0.2 + 0.8 * (PI * r / 2.0).sin(),
        3 => 1.0,
        4 => 0.5 + 0.5 * r,
        5 => {
            if r <= 0.7 {
                r / 0.7
            } else {
                (1.0 - r) / 0.3
            }
        }
        6 => 1.0 - 0.8 * r,
        7 => {
            if r <= 0.7 {
                0.5 + 0.5 * r / 0.7
            } else {
                0.5 + 0.5 * (1.0 - r) / 0.3
            }
        }
        // Drawn without an outline: Cylindrical.
        8 => 1.0,
        _ => unreachable!(),
    }
}

#[test]
fn shape_ratio_matches_the_formulas_at_201_points() {
    for (i, shape) in CrownShape::ALL.iter().enumerate() {
        for k in 0..=200 {
            let r = k as f32 / 200.0;
            let got = f64::from(shape.ratio(r));
            let want = reference(i, f64::from(r));
            assert!((got - want).abs() < 1e-5, "{shape:?} at r={r}: {got} vs {want}");
        }
    }
}

fn tree(shape: CrownShape, tweak: impl Fn(&mut TreeParams)) -> (TreeParams, Skeleton) {
    let mut p =
        TreeParams { skeleton: SkeletonParams { shape, levels: 2, ..Default::default() }, ..TreeParams::default() };
    p.skeleton.level[1].length_v = 0.0;
    p.skeleton.level[1].branches = 60;
    tweak(&mut p);
    let s = skeleton::build(&p.skeleton).unwrap();
    (p, s)
}

/// Mean level-1 length in the lowest and highest thirds of the crown, and the crown position
/// (r, 1 = base) of the longest branch.
fn thirds(s: &Skeleton) -> (f32, f32, f32) {
    let trunk = s.stems[0].length;
    let span = trunk - s.crown_base;
    let mut low = Vec::new();
    let mut high = Vec::new();
    let mut longest = (0.0f32, 0.0f32);
    for st in s.stems.iter().filter(|x| x.level == 1) {
        let r = (trunk - st.offset) / span;
        if r > 2.0 / 3.0 {
            low.push(st.length);
        } else if r < 1.0 / 3.0 {
            high.push(st.length);
        }
        if st.length > longest.0 {
            longest = (st.length, r);
        }
    }
    let mean = |v: &[f32]| v.iter().sum::<f32>() / v.len() as f32;
    (mean(&low), mean(&high), longest.1)
}

#[test]
fn silhouettes_look_like_their_names() {
    let (_, s) = tree(CrownShape::Conical, |_| {});
    let (low, high, _) = thirds(&s);
    assert!(low > 1.8 * high, "Conical: low {low} high {high}");
    let (_, s) = tree(CrownShape::InverseConical, |_| {});
    let (low, high, _) = thirds(&s);
    assert!(high > 1.8 * low, "Inverse Conical: low {low} high {high}");
    let (_, s) = tree(CrownShape::Spherical, |_| {});
    let (low, high, r) = thirds(&s);
    assert!((0.35..0.65).contains(&r), "Spherical: longest at r={r}");
    assert!((low / high - 1.0).abs() < 0.25, "Spherical is symmetric: {low} vs {high}");
    let (_, s) = tree(CrownShape::Flame, |_| {});
    let (_, _, r) = thirds(&s);
    assert!((r - 0.7).abs() < 0.06, "Flame: widest at r={r}");
    let (_, s) = tree(CrownShape::Cylindrical, |_| {});
    let (low, high, _) = thirds(&s);
    assert!((low - high).abs() < 1e-3, "Cylindrical: {low} vs {high}");
}

#[test]
fn every_level1_tip_is_inside_the_preview_envelope() {
    for (i, shape) in CrownShape::ALL.iter().enumerate() {
        for seed in 0..3 {
            let (p, s) = tree(*shape, |p| {
                p.skeleton.seed = seed;
                p.skeleton.level[1].length_v = 0.1;
                p.skeleton.level[1].curve_v = 90.0;
            });
            let prof = preview_profile(&s, &p.skeleton, sylva_core::ENVELOPE_SAMPLES);
            assert!(!prof.is_empty());
            for st in s.stems.iter().filter(|x| x.level == 1) {
                let tip = st.tip();
                let allowed = profile_radius(&prof, tip.y);
                let d = (tip.x * tip.x + tip.z * tip.z).sqrt();
                assert!(d <= allowed * 1.02 + 0.05, "shape {i} seed {seed}: tip at {tip} outside ({d} > {allowed})");
            }
        }
    }
}

/// Mean angle between level-1 branches (base to tip direction) and the vertical.
fn mean_declination(s: &Skeleton, top: bool) -> f32 {
    let trunk = s.stems[0].length;
    let span = trunk - s.crown_base;
    let v: Vec<f32> = s
        .stems
        .iter()
        .filter(|x| x.level == 1)
        .filter(|x| ((trunk - x.offset) / span < 0.25) == top && ((trunk - x.offset) / span > 0.75) != top)
        .map(|x| (x.tip() - x.base()).normalize().y.acos().to_degrees())
        .collect();
    v.iter().sum::<f32>() / v.len() as f32
}

#[test]
fn angle_spread_tilts_top_up_and_base_down() {
    let flat = |p: &mut TreeParams| {
        p.skeleton.level[1].curve = 0.0;
        p.skeleton.level[1].curve_v = 0.0;
        p.skeleton.level[1].down_angle_v = 0.0;
    };
    let (_, s0) = tree(CrownShape::Cylindrical, flat);
    let (_, sp) = tree(CrownShape::Cylindrical, |p| {
        flat(p);
        p.skeleton.angle_spread = 30.0;
    });
    let (_, sn) = tree(CrownShape::Cylindrical, |p| {
        flat(p);
        p.skeleton.angle_spread = -30.0;
    });
    assert!(mean_declination(&sp, true) < mean_declination(&s0, true) - 10.0, "positive: top more upright");
    assert!(mean_declination(&sp, false) > mean_declination(&s0, false) + 10.0, "positive: base more outward");
    assert!(mean_declination(&sn, true) > mean_declination(&s0, true) + 10.0, "negative: the opposite");
}

#[test]
fn splits_helix_and_pruning_do_what_they_say() {
    // Base splits make extra trunk records from the first joint.
    let (_, s) = tree(CrownShape::Cylindrical, |p| p.skeleton.base_splits = 2);
    assert_eq!(s.stems.iter().filter(|x| x.level == 0).count(), 3);
    // Negative CurveV winds the stem: its tip is much closer to the base than its length.
    let (_, s) = tree(CrownShape::Cylindrical, |p| {
        p.skeleton.level[1].curve_v = -60.0;
        p.skeleton.level[1].curve_res = 12;
    });
    let st = s.stems.iter().find(|x| x.level == 1).unwrap();
    assert!(st.tip().distance(st.base()) < 0.8 * st.length, "helix did not wind");
    // Pruning keeps every branch point inside the pruning envelope.
    let (p, s) = tree(CrownShape::Cylindrical, |p| {
        p.skeleton.prune_ratio = 1.0;
        p.skeleton.prune_width = 0.3;
    });
    let (_, unpruned) = tree(CrownShape::Cylindrical, |_| {});
    let total = |s: &Skeleton| s.stems.iter().filter(|x| x.level == 1).map(|x| x.length).sum::<f32>();
    assert!(total(&s) < 0.9 * total(&unpruned), "pruning shortened nothing");
    for st in s.stems.iter().filter(|x| x.level == 1) {
        for q in &st.points {
            let ratio = (s.scale - q.y) / (s.scale * (1.0 - p.skeleton.base_size));
            let w = p.skeleton.prune_width
                * sylva_core::crown::prune_envelope(
                    ratio,
                    p.skeleton.prune_width_peak,
                    p.skeleton.prune_power_low,
                    p.skeleton.prune_power_high,
                );
            assert!((q.x * q.x + q.z * q.z).sqrt() / s.scale <= w + 0.02, "pruned branch leaves the envelope");
        }
    }
}

#[test]
fn preview_lines_trace_the_profile() {
    let prof = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 0.0]];
    let lines = sylva_core::crown::preview_lines(&prof, 4, 8);
    // Two rings (r > 0) of 8 segments plus 4 meridians of 3 segments, 2 points of 3 floats each.
    assert_eq!(lines.len(), (2 * 8 + 4 * 3) * 6);
    for p in lines.chunks_exact(3) {
        let r = (p[0] * p[0] + p[2] * p[2]).sqrt();
        assert!(r <= profile_radius(&prof, p[1]) + 1e-4, "point {p:?} outside the profile");
    }
}

#[test]
fn the_weeping_preset_hangs_curtains() {
    // Inverse Conical with a negative Attraction Up (the weeping tree of Mtree's *Crown Shape User Guide*): its
    // twigs must hang, and far enough to read as curtains. With short, curved twigs they fell
    // 0.08 of the tree's height and the crown read as an upright cone.
    let p = sylva_core::presets::find("weeping").unwrap().params().unwrap();
    let s = skeleton::build(&p.skeleton).unwrap();
    let twigs: Vec<_> = s.stems.iter().filter(|st| st.level == 2 && st.points.len() >= 2).collect();
    let drop = |st: &&sylva_core::skeleton::Stem| st.points[0].y - st.points.last().unwrap().y;
    let hanging = twigs.iter().filter(|st| drop(st) > 0.0).count() as f32 / twigs.len() as f32;
    let mean_drop = twigs.iter().map(drop).sum::<f32>() / twigs.len() as f32;
    let top = s.stems.iter().flat_map(|st| st.points.iter()).map(|q| q.y).fold(0.0f32, f32::max);
    assert!(hanging > 0.9, "{hanging} of the twigs hang");
    assert!(mean_drop > 0.14 * top, "twigs fall {mean_drop} m of a {top} m tree");
}
