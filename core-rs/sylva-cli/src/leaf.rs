//! `sylva leaf` and `sylva bench-leaf`: one leaf from a leaf preset and `--set` values.
//!
//! ```text
//! sylva leaf [--preset NAME] [--set id=value]... [--svg FILE] [--obj FILE] [--step N] [--triangulation]
//! sylva bench-leaf [--preset NAME] [--set id=value]... [--runs N] [--json]
//! ```
//! `leaf` prints the leaf as JSON (`sylva_core::leaf::json`) and writes the SVG drawing after
//! growth step N (default: finished), and `--obj` the blade mesh (LOD0, with the petiole) as OBJ. `bench-leaf` generates the leaf `--runs` times (default
//! 30) after a warm-up and reports median milliseconds per stage; without `--preset` it runs
//! Oak (Open venation) and Maple (Closed), and unless `--set leaf_vein_density=...` is given it
//! sets the density to the maximum, so each leaf gets the full 5,000 auxin sources.

use sylva_core::leaf::{self, presets, svg};
use sylva_core::params::TreeParams;

const USAGE: &str = "usage:
  sylva leaf [--preset NAME] [--set id=value]... [--svg FILE] [--obj FILE] [--step N] [--triangulation]
  sylva bench-leaf [--preset NAME] [--set id=value]... [--runs N] [--json]";

struct Opts {
    presets: Vec<String>,
    sets: Vec<(String, String)>,
    svg: Option<String>,
    obj: Option<String>,
    step: Option<u32>,
    triangulation: bool,
    runs: usize,
    json: bool,
}

fn parse(args: &[String]) -> Result<Opts, String> {
    let mut o = Opts {
        presets: Vec::new(),
        sets: Vec::new(),
        svg: None,
        obj: None,
        step: None,
        triangulation: false,
        runs: 30,
        json: false,
    };
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "--preset" => o.presets.push(value("--preset")?),
            "--set" => {
                let kv = value("--set")?;
                let (k, v) = kv.split_once('=').ok_or_else(|| format!("--set takes id=value, got '{kv}'"))?;
                o.sets.push((k.to_string(), v.to_string()));
            }
            "--svg" => o.svg = Some(value("--svg")?),
            "--obj" => o.obj = Some(value("--obj")?),
            "--step" => o.step = Some(value("--step")?.parse().map_err(|_| "--step takes a whole number".to_string())?),
            "--triangulation" => o.triangulation = true,
            "--runs" => o.runs = value("--runs")?.parse().map_err(|_| "--runs takes a whole number".to_string())?,
            "--json" => o.json = true,
            other => return Err(format!("unknown option '{other}'\n{USAGE}")),
        }
    }
    o.runs = o.runs.max(1);
    Ok(o)
}

/// The parameters of a leaf preset (or the defaults) with the `--set` values applied.
fn params(preset: Option<&str>, sets: &[(String, String)]) -> Result<TreeParams, String> {
    let mut p = match preset {
        Some(name) => presets::find(name)
            .ok_or_else(|| {
                let names: Vec<&str> = presets::LEAF_PRESETS.iter().map(|p| p.name).collect();
                format!("unknown leaf preset '{name}' (known: {})", names.join(", "))
            })?
            .params()
            .map_err(|e| e.to_string())?,
        None => TreeParams::default(),
    };
    for (k, v) in sets {
        let num = super::parse_value(k, v)?;
        p.set(k, num).map_err(|e| e.to_string())?;
    }
    leaf::validate(&p).map_err(|e| e.to_string())?;
    Ok(p)
}

/// Runs `leaf` or `bench-leaf`.
pub fn run(cmd: &str, args: &[String]) -> Result<String, String> {
    let o = parse(args)?;
    if o.presets.len() > 1 && cmd == "leaf" {
        return Err("sylva leaf takes one --preset".into());
    }
    if cmd == "bench-leaf" {
        return bench(&o);
    }
    let p = params(o.presets.first().map(String::as_str), &o.sets)?;
    let l = leaf::generate(&p).map_err(|e| e.to_string())?;
    if let Some(path) = &o.svg {
        let opts = svg::SvgOptions { triangulation: o.triangulation, step: o.step, ..svg::SvgOptions::default() };
        std::fs::write(path, svg::render(&l, &opts)).map_err(|e| format!("cannot write {path}: {e}"))?;
    }
    if let Some(path) = &o.obj {
        std::fs::write(path, l.mesh.to_obj()).map_err(|e| format!("cannot write {path}: {e}"))?;
    }
    Ok(leaf::json::to_json(&l))
}

fn bench(o: &Opts) -> Result<String, String> {
    let names: Vec<String> = if o.presets.is_empty() { vec!["oak".into(), "maple".into()] } else { o.presets.clone() };
    let mut sets = o.sets.clone();
    if !sets.iter().any(|(k, _)| k == "leaf_vein_density") {
        sets.push(("leaf_vein_density".into(), "20000".into()));
    }
    let mut results = Vec::new();
    let mut lines = Vec::new();
    for name in &names {
        let p = params(Some(name), &sets)?;
        let mut totals = Vec::with_capacity(o.runs);
        let mut stages: Vec<(&'static str, Vec<f64>)> = Vec::new();
        let mut last = leaf::generate(&p).map_err(|e| e.to_string())?;
        for _ in 0..o.runs {
            last = leaf::generate(&p).map_err(|e| e.to_string())?;
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
            p.leaf_venation.label(),
            last.veins.auxins.len(),
            g.nodes.len(),
            g.loops(),
            o.runs,
            stage.get("veins").and_then(|v| v.as_f64()).unwrap_or(0.0),
        ));
        results.push(serde_json::json!({
            "preset": name,
            "venation": p.leaf_venation.label(),
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
        Ok(serde_json::json!({"target": "native", "runs": o.runs, "results": results}).to_string())
    } else {
        Ok(lines.join("\n"))
    }
}
