//! Property tests of `generate()` on random *valid* parameters over the full registry ranges,
//! extremes included: it never panics, it either succeeds or stops on the vertex budget, every
//! buffer value is finite, every index is in range, and the vertex count stays within
//! `max_vertices`. A smallish `max_vertices` is drawn as well, which bounds the runtime (the
//! skeleton stops as soon as its lower bound passes the budget).
//!
//! Cases: `PROPTEST_CASES` (default 2000 per property) within `SYLVA_FUZZ_SECONDS` (default 20)
//! per property; `PROPTEST_RNG_SEED` replays a run.

use proptest::prelude::*;
use proptest::test_runner::TestRunner;
use std::cell::Cell;
use std::time::{Duration, Instant};
use sylva_core::params::{registry, ParamKind, ParamSpec};
use sylva_core::{generate, Generated, SylvaError, TreeParams};

/// Largest budget drawn: keeps one parametric tree to a few milliseconds.
const MAX_BUDGET: u32 = 60_000;
/// Wall-clock budget of one property (see [`check_many`]): `SYLVA_FUZZ_SECONDS`, default 20.
fn time_budget() -> Duration {
    let seconds = std::env::var("SYLVA_FUZZ_SECONDS").ok().and_then(|v| v.parse().ok()).unwrap_or(20);
    Duration::from_secs(seconds)
}
/// Fewest cases a property must get through within its time budget.
const MIN_CASES: u32 = 25;

/// Cases per property: `PROPTEST_CASES`, default 2000 (the time budget usually ends it first).
fn cases() -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(2000)
}

/// A valid wire value for `spec`: often a bound or the default, else uniform in the range.
fn value_for(spec: &'static ParamSpec) -> BoxedStrategy<f64> {
    let (lo, hi, d) = (spec.min, spec.max, spec.default);
    let uniform: BoxedStrategy<f64> = if spec.kind == ParamKind::Float {
        (lo..=hi).boxed()
    } else {
        (lo as u64..=hi as u64).prop_map(|i| i as f64).boxed()
    };
    prop_oneof![
        2 => Just(lo),
        2 => Just(hi),
        3 => Just(d),
        5 => uniform,
    ]
    .boxed()
}

/// Whether `spec` is a count that multiplies the work (branches, markers, iterations): an int
/// with a wide range that is not a seed.
fn is_count(spec: &ParamSpec) -> bool {
    spec.kind == ParamKind::Int && spec.max >= 100.0 && !spec.id.ends_with("seed") && spec.id != "max_vertices"
}

/// Random valid params: every registry value drawn, then a smallish vertex budget. `tame` draws
/// the counts ([`is_count`]) from the lowest 4 % of their range, so that most trees fit the
/// budget and the mesh stage runs; otherwise most wild trees stop on the budget early.
fn valid_params(tame: bool) -> impl Strategy<Value = Vec<(&'static str, f64)>> {
    let specs: Vec<BoxedStrategy<(&'static str, f64)>> = registry()
        .iter()
        // The leaf's own shape (groups Leaf, Leaf Veins, Leaf Surface) stays at its defaults: it
        // has its own property tests, and one cached leaf keeps every case fast (a fresh leaf at
        // the vein density maximum takes seconds in a debug build). Foliage params are drawn.
        .filter(|s| s.id != "max_vertices" && !s.group.starts_with("Leaf"))
        .map(|s| {
            let values = if tame && is_count(s) {
                (s.min as u32..=(s.min + (s.max - s.min) / 25.0) as u32).prop_map(f64::from).boxed()
            } else {
                value_for(s)
            };
            values.prop_map(move |v| (s.id.as_str(), v)).boxed()
        })
        .collect();
    let budget =
        prop_oneof![1 => Just(1_000u32), 6 => 1_000u32..=MAX_BUDGET].prop_map(|b| ("max_vertices", f64::from(b)));
    (specs, budget).prop_map(|(mut values, budget)| {
        values.push(budget);
        values
    })
}

/// The buffer contract the viewer relies on.
fn check_buffers(g: &Generated, max_vertices: u32) -> Result<(), TestCaseError> {
    let m = &g.mesh;
    let n = m.vertex_count();
    prop_assert!(n <= max_vertices as usize, "{n} vertices > max_vertices {max_vertices}");
    prop_assert_eq!(m.positions.len(), n * 3);
    prop_assert_eq!(m.normals.len(), n * 3);
    prop_assert_eq!(m.uvs.len(), n * 2);
    prop_assert_eq!(m.indices.len() % 3, 0);
    prop_assert!(m.positions.iter().all(|v| v.is_finite()), "non-finite position");
    prop_assert!(m.normals.iter().all(|v| v.is_finite()), "non-finite normal");
    prop_assert!(m.uvs.iter().all(|v| v.is_finite()), "non-finite uv");
    prop_assert!(m.indices.iter().all(|&i| (i as usize) < n), "index out of range");
    let covered: u64 = m.groups.iter().map(|gr| u64::from(gr.count)).sum();
    prop_assert_eq!(covered, m.indices.len() as u64, "groups do not cover the indices");
    prop_assert!(g.bounds.min.iter().chain(&g.bounds.max).all(|v| v.is_finite()));
    prop_assert!(g.envelope.iter().flatten().all(|v| v.is_finite()), "non-finite envelope");
    prop_assert_eq!(g.stats.vertices, n);
    for (i, nm) in m.normals.chunks_exact(3).enumerate() {
        let len = (nm[0] * nm[0] + nm[1] * nm[1] + nm[2] * nm[2]).sqrt();
        prop_assert!((len - 1.0).abs() < 1e-3, "normal {} has length {}", i, len);
    }
    Ok(())
}

fn run(values: &[(&'static str, f64)]) -> Result<(), TestCaseError> {
    let p = match TreeParams::from_values(values.iter().copied()) {
        Ok(p) => p,
        Err(e) => return Err(TestCaseError::fail(format!("a valid value was refused: {e}"))),
    };
    match generate(&p) {
        Ok(g) => check_buffers(&g, p.skeleton.max_vertices),
        Err(SylvaError::Budget { param, message }) => {
            // The vertex budget, or the leaf budget (foliage).
            prop_assert!(param == "max_vertices" || param == "max_leaves", "{}", param);
            prop_assert!(message.contains(&format!("{param} budget")), "{}", message);
            Ok(())
        }
        // A leaf the registry ranges allow but the leaf rules refuse (leaf::validate, a blade
        // of almost no area): the tree's foliage reports it, naming the leaf parameter.
        Err(SylvaError::InvalidParam { param, .. }) if param.starts_with("leaf_") && p.foliage.leaves > 0 => Ok(()),
        Err(e) => Err(TestCaseError::fail(format!("valid params refused: {e:?}"))),
    }
}

/// Runs one property over `cases` random params, or until the time budget has passed (cases after
/// that pass without generating): some corners of the parameter space take seconds, and the
/// suite must stay fast on a small shared machine. At least `MIN_CASES` must have run.
fn check_many(tame: bool, cases: u32) {
    let config = ProptestConfig { cases, failure_persistence: None, ..ProptestConfig::default() };
    let mut runner = TestRunner::new(config);
    let budget = time_budget();
    let start = Instant::now();
    let ran = Cell::new(0u32);
    let result = runner.run(&valid_params(tame), |values| {
        if start.elapsed() > budget {
            return Ok(());
        }
        ran.set(ran.get() + 1);
        run(&values)
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    eprintln!("{} generations in {:.1} s", ran.get(), start.elapsed().as_secs_f64());
    assert!(ran.get() >= MIN_CASES.min(runner.config().cases), "only {} cases ran", ran.get());
}

#[test]
fn random_valid_params_give_finite_in_range_buffers_within_budget() {
    check_many(false, cases());
}

#[test]
fn random_valid_params_with_small_counts_mostly_mesh() {
    check_many(true, cases());
}

/// Every parameter alone at each end of its range (with the budget that makes it affordable).
#[test]
fn every_param_alone_at_its_extremes() {
    for spec in registry().iter().filter(|s| s.id != "max_vertices") {
        for v in [spec.min, spec.max] {
            let values = [(spec.id.as_str(), v), ("max_vertices", f64::from(MAX_BUDGET))];
            if let Err(e) = run(&values) {
                panic!("{} = {v}: {e}", spec.id);
            }
        }
    }
}
