//! Age: every preset at its default Age is today's tree; a younger tree is the mature tree's
//! earlier self (fewer, shorter, thinner stems, the unborn ones absent), its bounds growing
//! monotonically with Age; the growth curve and birth years behave as documented; an Age
//! outside the range is refused by name.

mod common;

use sylva_core::age::{birth_years, length_fraction, time_to_length, BUD_DELAY};
use sylva_core::params::TreeParams;
use sylva_core::presets::PRESETS;
use sylva_core::skeleton::StemKind;
use sylva_core::{generate, SylvaError};

fn at_age(preset: &str, age: f32) -> sylva_core::Generated {
    let mut p = sylva_core::presets::find(preset).expect("a preset").params().unwrap();
    p.skeleton.age = age;
    generate(&p).expect("a tree at that age")
}

#[test]
fn every_preset_defaults_to_its_mature_age_and_today_s_tree() {
    for preset in PRESETS {
        let p = preset.params().unwrap();
        assert_eq!(p.skeleton.age, p.skeleton.maturity, "{}: default Age = Mature Age", preset.name);
        // Past the Mature Age the tree keeps its mature form but for the life over decades
        // (`sylva_core::life`): with shedding, thickening and drooping off, it is the same tree.
        let mut older = p.clone();
        older.skeleton.age = p.skeleton.maturity + 20.0;
        if preset.name == "default" || preset.name == "oak" {
            assert_ne!(generate(&older).unwrap().hash, generate(&p).unwrap().hash, "{}", preset.name);
            (older.skeleton.shed_light, older.skeleton.ring_width, older.skeleton.droop) = (0.0, 0.0, 0.0);
            assert_eq!(generate(&older).unwrap().hash, generate(&p).unwrap().hash, "{}", preset.name);
        }
    }
}

#[test]
fn the_growth_curve_runs_from_zero_to_one_and_inverts() {
    assert_eq!(length_fraction(0.0), 0.0);
    assert_eq!(length_fraction(1.0), 1.0);
    let mut last = 0.0;
    for k in 1..=100 {
        let tau = k as f32 / 100.0;
        let f = length_fraction(tau);
        assert!(f > last, "g rises: g({tau}) = {f}");
        // Fast first, slowing down: more than linear before maturity.
        assert!(k == 100 || f > tau, "g({tau}) = {f}");
        assert!((time_to_length(f) - tau).abs() < 1e-3, "inverse at {tau}");
        last = f;
    }
}

#[test]
fn a_young_tree_is_smaller_and_its_bounds_grow_with_age() {
    for preset in ["default", "black_tupelo", "grown_broadleaf"] {
        let mature = sylva_core::presets::find(preset).unwrap().params().unwrap().skeleton.maturity;
        let mut last: Option<sylva_core::Generated> = None;
        for k in 1..=8 {
            let age = mature * k as f32 / 8.0;
            let g = at_age(preset, age);
            common::assert_mesh_invariants(&g, &format!("{preset} at {age}"));
            let open = common::edge_uses(&g.mesh).values().filter(|&&u| u != 2).count();
            assert_eq!(open, 0, "{preset} at {age}: the bark stays closed");
            if let Some(prev) = &last {
                // A young stem's centre curve is the mature curve resampled at its own points:
                // where it bends most, the spline through them may fall short by millimetres.
                let tol = 0.01;
                for axis in 0..3 {
                    assert!(g.bounds.max[axis] >= prev.bounds.max[axis] - tol, "{preset} {age}: max[{axis}]");
                    assert!(g.bounds.min[axis] <= prev.bounds.min[axis] + tol, "{preset} {age}: min[{axis}]");
                }
                assert!(g.stats.stems >= prev.stats.stems, "{preset} {age}: stems only appear");
                assert!(g.foliage.count() >= prev.foliage.count(), "{preset} {age}: leaves only appear");
            }
            last = Some(g);
        }
        let young = at_age(preset, mature * 0.25);
        let old = at_age(preset, mature);
        let height = |g: &sylva_core::Generated| g.bounds.max[1];
        assert!(height(&young) < 0.8 * height(&old), "{preset}: {} vs {}", height(&young), height(&old));
        assert!(
            young.stats.stems < old.stats.stems / 2,
            "{preset}: {} vs {} stems",
            young.stats.stems,
            old.stats.stems
        );
        assert!(young.skeleton.stems[0].radius < 0.5 * old.skeleton.stems[0].radius, "{preset}: a thinner trunk");
    }
}

#[test]
fn birth_years_follow_the_level_and_the_offset_along_the_parent() {
    let g = generate(&TreeParams::default()).unwrap();
    let sk = &g.skeleton;
    let births = birth_years(sk, 40.0);
    assert_eq!(births[0], 0.0);
    for (i, s) in sk.stems.iter().enumerate() {
        let Some(p) = s.parent else { continue };
        let (b, bp) = (births[i], births[p as usize]);
        assert!(b >= bp && b < 40.0, "stem {i}: born {b}, its parent {bp}");
        if s.kind == StemKind::Branch {
            assert!(
                b >= bp + BUD_DELAY.min(39.0 - bp) - 1e-4,
                "stem {i} born {b} before its parent {bp} could carry it"
            );
        }
    }
    // Along a parent, branches higher up are born later.
    let trunk_children: Vec<(f32, f32)> = sk
        .stems
        .iter()
        .enumerate()
        .filter(|(_, s)| s.parent == Some(0) && s.kind == StemKind::Branch)
        .map(|(i, s)| (s.offset, births[i]))
        .collect();
    assert!(trunk_children.len() > 10);
    for w in trunk_children.windows(2) {
        if w[1].0 > w[0].0 {
            assert!(w[1].1 >= w[0].1, "{w:?}");
        }
    }
}

#[test]
fn an_age_outside_the_range_is_refused_by_name() {
    let e = TreeParams::from_json(r#"{"age": 0}"#).unwrap_err();
    assert!(
        matches!(&e, SylvaError::InvalidParam { param, message } if param == "age" && message.contains("1 to 300")),
        "{e:?}"
    );
    let e = TreeParams::from_json(r#"{"maturity": 1000}"#).unwrap_err();
    assert!(matches!(&e, SylvaError::InvalidParam { param, .. } if param == "maturity"), "{e:?}");
}

#[test]
fn a_grown_tree_grows_in_annual_flushes_and_dates_its_wood() {
    let p = sylva_core::presets::find("grown_broadleaf").unwrap().params().unwrap();
    let mature = p.skeleton.maturity;
    let mut last = 0usize;
    for age in [mature * 0.25, mature * 0.5, mature * 0.75] {
        let g = at_age("grown_broadleaf", age);
        // The same tree as showing that fraction of the growth iterations (Growth Age).
        let mut q = p.clone();
        q.skeleton.growth_age = p.skeleton.growth_age * age / mature;
        assert_eq!(g.hash, generate(&q).unwrap().hash, "Age {age} is the flushes of its years");
        let n = g.skeleton.stems.len();
        assert!(n >= last, "stems only come with the years");
        last = n;
        // (Whole iterations: the last one may reach a little into the next year.)
        for s in &g.skeleton.stems {
            assert!(s.born <= s.tip_year && s.tip_year <= age + 1.0, "{} .. {} at {age}", s.born, s.tip_year);
        }
        // The trunk grew from the first year, and some tip grew in the last one.
        assert_eq!(g.skeleton.stems[0].born, 0.0);
        assert!(g.skeleton.stems.iter().any(|s| s.tip_year > age - 1.0), "this year's flush at {age}");
    }
    // Leafy Years bares the old wood of a grown tree too.
    let mut q = p.clone();
    q.foliage.leaf_years = 5.0;
    assert!(generate(&q).unwrap().foliage.count() < generate(&p).unwrap().foliage.count());
}
