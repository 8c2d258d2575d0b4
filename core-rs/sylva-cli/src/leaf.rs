//! `sylva leaf` and `sylva bench-leaf`: one leaf from a leaf preset and `--set` values.
//!
//! Their options are declared in [`crate::cli`]. `leaf` prints the leaf as JSON (`sylva_core::leaf::json`) and writes the SVG drawing after
//! growth step N (default: finished). `bench-leaf` generates the leaf `--runs` times (default
//! 30) after a warm-up and reports median milliseconds per stage; without `--preset` it runs
//! Oak (Open venation) and Maple (Closed), and unless `--set leaf_vein_density=...` is given it
//! sets the density to the maximum, so each leaf gets the full 5,000 auxin sources.

use crate::cli::{BenchLeafArgs, LeafArgs};
use sylva_core::leaf::{self, presets, svg};
use sylva_core::params::TreeParams;

/// The parameters of a leaf preset (or the defaults) with the `--set` values applied.
fn params(preset: Option<&str>, sets: &[(String, String)]) -> Result<TreeParams, String> {
    let known: Vec<&str> = presets::LEAF_PRESETS.iter().map(|p| p.name).collect();
    let find = |name: &str| presets::find(name).map(|p| p.params());
    let p = super::preset_with_sets(preset, "leaf preset", &known, find, sets)?;
    leaf::validate(&p.leaf, p.foliage.leaf_petiole).map_err(|e| e.to_string())?;
    Ok(p)
}

/// `sylva leaf`: the leaf as JSON, its SVG drawing with `--svg`, its blade as OBJ with `--obj`.
pub fn leaf(a: &LeafArgs) -> Result<String, String> {
    let p = params(a.preset.as_deref(), &a.set.set)?;
    let l = leaf::generate(&p.leaf, p.foliage.leaf_petiole).map_err(|e| e.to_string())?;
    if let Some(path) = &a.svg {
        let opts = svg::SvgOptions { triangulation: a.triangulation, step: a.step, ..svg::SvgOptions::default() };
        std::fs::write(path, svg::render(&l, &opts)).map_err(|e| format!("cannot write {path}: {e}"))?;
    }
    if let Some(path) = &a.obj {
        std::fs::write(path, l.mesh.to_obj()).map_err(|e| format!("cannot write {path}: {e}"))?;
    }
    Ok(leaf::json::to_json(&l))
}

/// `sylva bench-leaf`: median times per stage, per preset.
pub fn bench(o: &BenchLeafArgs) -> Result<String, String> {
    let names: Vec<String> = if o.preset.is_empty() { vec!["oak".into(), "maple".into()] } else { o.preset.clone() };
    let runs = o.runs.max(1);
    let mut sets = o.set.set.clone();
    if !sets.iter().any(|(k, _)| k == "leaf_vein_density") {
        sets.push(("leaf_vein_density".into(), "20000".into()));
    }
    let mut results = Vec::new();
    let mut lines = Vec::new();
    for name in &names {
        let p = params(Some(name), &sets)?;
        let mut totals = Vec::with_capacity(runs);
        let mut stages: Vec<(&'static str, Vec<f64>)> = Vec::new();
        let mut last = leaf::generate(&p.leaf, p.foliage.leaf_petiole).map_err(|e| e.to_string())?;
        for _ in 0..runs {
            last = leaf::generate(&p.leaf, p.foliage.leaf_petiole).map_err(|e| e.to_string())?;
            totals.push(last.stats.total_ms);
            for (i, (stage, ms)) in last.stats.stage_ms.iter().enumerate() {
                if stages.len() <= i {
                    stages.push((stage, Vec::new()));
                }
                stages[i].1.push(*ms);
            }
        }
        let median_ms = super::median(&mut totals);
        let stage: serde_json::Map<String, serde_json::Value> =
            stages.iter_mut().map(|(k, v)| (k.to_string(), serde_json::json!(super::median(v)))).collect();
        let g = &last.veins.graph;
        lines.push(format!(
            "native leaf {name} ({}): {} auxins, {} vein nodes, {} loops, median {median_ms:.3} ms over {} runs (veins {:.3} ms)",
            p.leaf.leaf_venation.label(),
            last.veins.auxins.len(),
            g.nodes.len(),
            g.loops(),
            runs,
            stage.get("veins").and_then(|v| v.as_f64()).unwrap_or(0.0),
        ));
        results.push(serde_json::json!({
            "preset": name,
            "venation": p.leaf.leaf_venation.label(),
            "auxins": last.veins.auxins.len(),
            "vein_nodes": g.nodes.len(),
            "loops": g.loops(),
            "triangles": last.mesh.triangle_count(),
            "median_ms": median_ms,
            "stage_median_ms": stage,
            "hash": last.hash_hex(),
            "params": serde_json::Value::Object(p.non_defaults().into_iter().filter(|(k, _)| k.starts_with("leaf_")).map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect()),
        }));
    }
    if o.json {
        Ok(serde_json::json!({"target": "native", "runs": runs, "results": results}).to_string())
    } else {
        Ok(lines.join("\n"))
    }
}
