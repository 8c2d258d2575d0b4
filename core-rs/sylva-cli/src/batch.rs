//! `sylva batch`: many trees (presets × seeds, or a JSON list) generated on every core, each
//! written as the GLB `sylva generate --out` writes for the same tree, with a manifest.
//!
//! Every tree is independent: a worker thread takes the next tree of the list, generates it and
//! writes its file, with [`sylva_core::par::serial`] keeping the core's own writers on that one
//! thread (the batch already fills the cores). The bytes of a tree do not depend on the thread.

use crate::cli::BatchArgs;
use crate::tree::{export_options, write_export};
use crate::{parse_value, preset_with_sets};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;
use sylva_core::params::TreeParams;
use sylva_core::presets;

/// One tree of a batch: its file name (without `.glb`), preset, and parameters.
struct Job {
    name: String,
    preset: Option<String>,
    params: TreeParams,
}

/// `sylva batch`: the manifest as one JSON object (also written to `DIR/manifest.json` with `--out`).
pub fn batch(a: &BatchArgs) -> Result<String, String> {
    let jobs = match &a.list {
        Some(path) => list_jobs(path)?,
        None => grid_jobs(a)?,
    };
    if let Some(dir) = &a.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create --out {dir}: {e}"))?;
    }
    let threads = a.threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let threads = threads.clamp(1, jobs.len().max(1));
    let export = export_options(&a.export);
    let next = AtomicUsize::new(0);
    let t0 = Instant::now();
    let work = || {
        let mut done = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(job) = jobs.get(i) else { return done };
            let t = Instant::now();
            let r = sylva_core::par::serial(|| one_tree(job, a.out.as_deref(), &export));
            done.push((i, r, t.elapsed().as_secs_f64() * 1000.0));
        }
    };
    let mut results: Vec<_> = std::thread::scope(|s| {
        let helpers: Vec<_> = (1..threads).map(|_| s.spawn(work)).collect();
        let mut all = work();
        for h in helpers {
            all.extend(h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        }
        all
    });
    let total_ms = t0.elapsed().as_secs_f64() * 1000.0;
    results.sort_by_key(|(i, ..)| *i);
    let failed = results.iter().filter(|(_, r, _)| r.is_err()).count();
    let trees: Vec<serde_json::Value> = results.into_iter().map(|(i, r, ms)| entry(&jobs[i], r, ms)).collect();
    let manifest = serde_json::json!({
        "trees": trees,
        "count": jobs.len(),
        "failed": failed,
        "threads": threads,
        "total_ms": total_ms,
        "trees_per_second": jobs.len() as f64 / (total_ms / 1000.0),
    });
    let text = serde_json::to_string_pretty(&manifest).map_err(|e| e.to_string())?;
    if let Some(dir) = &a.out {
        let path = std::path::Path::new(dir).join("manifest.json");
        std::fs::write(&path, &text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    if failed > 0 {
        let first = trees.iter().find_map(|t| t["error"].as_str().map(|e| format!("{}: {e}", t["name"])));
        return Err(format!("{failed} of {} trees failed; {}", jobs.len(), first.unwrap_or_default()));
    }
    serde_json::to_string(&manifest).map_err(|e| e.to_string())
}

/// What one tree gives: its file (with `--out`), hash, counts and the generation's time.
struct Made {
    file: Option<String>,
    hash: String,
    vertices: usize,
    triangles: usize,
    leaves: usize,
    generate_ms: f64,
}

/// Generates `job` and writes `DIR/NAME.glb` when `dir` is given.
fn one_tree(job: &Job, dir: Option<&str>, export: &sylva_core::export::ExportOptions) -> Result<Made, String> {
    let g = sylva_core::generate(&job.params).map_err(|e| e.to_string())?;
    let file = match dir {
        Some(dir) => {
            let path = std::path::Path::new(dir).join(format!("{}.glb", job.name)).to_string_lossy().into_owned();
            write_export(&g, export, &path)?;
            Some(path)
        }
        None => None,
    };
    Ok(Made {
        file,
        hash: g.hash_hex(),
        vertices: g.stats.vertices,
        triangles: g.stats.triangles,
        leaves: g.foliage.count(),
        generate_ms: g.stats.total_ms,
    })
}

/// One tree's record in the manifest.
fn entry(job: &Job, r: Result<Made, String>, ms: f64) -> serde_json::Value {
    let mut v = serde_json::json!({
        "name": job.name,
        "preset": job.preset,
        "seed": job.params.skeleton.seed,
        "ms": ms,
    });
    match r {
        Ok(m) => {
            v["file"] = serde_json::json!(m.file);
            v["hash"] = m.hash.into();
            v["vertices"] = m.vertices.into();
            v["triangles"] = m.triangles.into();
            v["leaves"] = m.leaves.into();
            v["generate_ms"] = m.generate_ms.into();
        }
        Err(e) => v["error"] = e.into(),
    }
    v
}

/// Every preset of `--preset` (the defaults without one) with every seed of `--seeds` (the
/// preset's own seed without it), then the `--set` values.
fn grid_jobs(a: &BatchArgs) -> Result<Vec<Job>, String> {
    let presets: Vec<Option<&str>> =
        if a.preset.is_empty() { vec![None] } else { a.preset.iter().map(|p| Some(p.as_str())).collect() };
    let seeds = match &a.seeds {
        Some(s) => seed_list(s)?.into_iter().map(Some).collect(),
        None => vec![None],
    };
    let mut jobs = Vec::new();
    for &preset in &presets {
        for &seed in &seeds {
            let mut sets: Vec<(String, String)> =
                seed.map(|s: u32| ("seed".to_string(), s.to_string())).into_iter().collect();
            sets.extend(a.set.set.iter().cloned());
            let params = params_of(preset, &sets)?;
            let name = format!("{}_{}", preset.unwrap_or("default"), params.skeleton.seed);
            jobs.push(Job { name, preset: preset.map(str::to_string), params });
        }
    }
    unique(jobs)
}

/// `preset` (or the defaults) with `sets` applied in order.
fn params_of(preset: Option<&str>, sets: &[(String, String)]) -> Result<TreeParams, String> {
    let known: Vec<&str> = presets::PRESETS.iter().map(|p| p.name).collect();
    preset_with_sets(preset, "preset", &known, |n| presets::find(n).map(|p| p.params()), sets)
}

/// `--seeds`: `N`, `A-B` (inclusive) or a comma-separated list of both.
fn seed_list(s: &str) -> Result<Vec<u32>, String> {
    let bad = || format!("--seeds takes N, A-B or a comma-separated list of them, got '{s}'");
    let mut out = Vec::new();
    for part in s.split(',').map(str::trim) {
        match part.split_once('-') {
            Some((lo, hi)) => {
                let (lo, hi): (u32, u32) =
                    (lo.trim().parse().map_err(|_| bad())?, hi.trim().parse().map_err(|_| bad())?);
                if lo > hi {
                    return Err(bad());
                }
                out.extend(lo..=hi);
            }
            None => out.push(part.parse().map_err(|_| bad())?),
        }
    }
    Ok(out)
}

/// `--list FILE.json`: an array of `{"preset", "seed", "set": {id: value}, "name"}`, each key
/// optional; a value is a number, `true`/`false`, or an enum option's name.
fn list_jobs(path: &str) -> Result<Vec<Job>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read --list {path}: {e}"))?;
    let list: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("--list {path}: {e}"))?;
    let items = list.as_array().ok_or_else(|| format!("--list {path}: expected a JSON array of trees"))?;
    let mut jobs = Vec::new();
    for (i, item) in items.iter().enumerate() {
        let at = |msg: String| format!("--list {path}: tree {i}: {msg}");
        let obj = item.as_object().ok_or_else(|| at("expected an object".into()))?;
        let preset = obj
            .get("preset")
            .map(|p| p.as_str().map(str::to_string).ok_or_else(|| at("preset: expected a name".into())));
        let preset = preset.transpose()?;
        let mut sets = Vec::new();
        let word = |v: &serde_json::Value| v.as_str().map_or_else(|| v.to_string(), str::to_string);
        if let Some(seed) = obj.get("seed") {
            sets.push(("seed".to_string(), word(seed)));
        }
        if let Some(set) = obj.get("set") {
            let set = set.as_object().ok_or_else(|| at("set: expected an object of id: value".into()))?;
            for (id, v) in set {
                parse_value(id, &word(v)).map_err(at)?;
                sets.push((id.clone(), word(v)));
            }
        }
        let params = params_of(preset.as_deref(), &sets).map_err(at)?;
        let name = match obj.get("name") {
            Some(n) => {
                n.as_str().filter(|n| valid_name(n)).ok_or_else(|| at("name: expected a file name".into()))?.to_string()
            }
            None => format!("{}_{}", preset.as_deref().unwrap_or("default"), params.skeleton.seed),
        };
        jobs.push(Job { name, preset, params });
    }
    unique(jobs)
}

/// A name usable as a file name in the output folder.
fn valid_name(n: &str) -> bool {
    !n.is_empty() && !n.starts_with('.') && n.chars().all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c))
}

/// `jobs`, unless two would write the same file.
fn unique(jobs: Vec<Job>) -> Result<Vec<Job>, String> {
    let mut names: Vec<&str> = jobs.iter().map(|j| j.name.as_str()).collect();
    names.sort_unstable();
    if let Some(w) = names.windows(2).find(|w| w[0] == w[1]) {
        return Err(format!("two trees named '{}': give them different seeds or names", w[0]));
    }
    if jobs.is_empty() {
        return Err("no trees to generate".into());
    }
    Ok(jobs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_lists_take_numbers_ranges_and_both() {
        assert_eq!(seed_list("7").unwrap(), vec![7]);
        assert_eq!(seed_list("1-4").unwrap(), vec![1, 2, 3, 4]);
        assert_eq!(seed_list("1-2, 9").unwrap(), vec![1, 2, 9]);
        assert!(seed_list("4-1").is_err());
        assert!(seed_list("x").is_err());
    }
}
