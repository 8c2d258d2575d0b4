//! `sylva`: the command line of Sylva's core.
//!
//! ```text
//! sylva generate [--preset NAME] [--seed N] [--set id=value]... [--volumes FILE.json] [--out FILE.glb|FILE.obj]
//!                [--leaves instanced|baked|none] [--no-textures] [--no-tangents] [--no-wind]
//!                [--report skeleton|mesh]
//! sylva envelope --shape NAME [--samples N]
//! sylva params [--markdown]
//! sylva presets
//! sylva bench [--preset NAME] [--runs N] [--json] [--glb]
//! ```
//! `--out` writes the tree as glTF binary (`.glb`, `sylva_core::export::glb`) or Wavefront OBJ
//! (`.obj` plus `NAME.mtl` and `NAME_*.png` textures next to it, `sylva_core::export::obj`).
//! Errors (unknown flags, invalid parameters, budgets) print a message to stderr and exit 2.

mod leaf;

use std::process::ExitCode;
use sylva_core::export::{ExportOptions, LeafMode};
use sylva_core::params::{registry, ParamKind, TreeParams};
use sylva_core::{presets, SylvaError};

const USAGE: &str = "usage:
  sylva generate [--preset NAME] [--seed N] [--set id=value]... [--volumes FILE.json] [--out FILE.glb|FILE.obj]
                 [--leaves instanced|baked|none] [--no-textures] [--no-tangents] [--no-wind]
                 [--report skeleton|mesh]
  sylva envelope --shape NAME [--samples N]
  sylva params [--markdown]
  sylva presets
  sylva leaf-presets
  sylva bench [--preset NAME] [--runs N] [--json] [--glb]

export (generate --out):
  FILE.glb      glTF 2.0 binary: bark + leaf meshes, PBR materials, embedded PNG textures,
                tangents, vertex colours, wind attributes (_WIND_PIVOT, _WIND_PARAMS)
  FILE.obj      Wavefront OBJ + FILE.mtl + FILE_*.png textures (leaves baked)
  --leaves M    instanced (GLB: EXT_mesh_gpu_instancing, default), baked (one mesh), none
  --no-textures no images (plain material colours)
  --no-tangents GLB: no TANGENT (viewers compute them; faster export of big trees)
  --no-wind     no wind attributes
bench --glb: also time the GLB export (median into a fresh buffer, into a reused one on every
core and on one, and the first export with PNG encoding).";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(out) => {
            // A closed pipe (`sylva params | head`) is not an error worth a panic.
            use std::io::Write;
            let _ = writeln!(std::io::stdout().lock(), "{out}");
            ExitCode::SUCCESS
        }
        Err(msg) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &[String]) -> Result<String, String> {
    let (cmd, rest) = args.split_first().ok_or_else(|| USAGE.to_string())?;
    match cmd.as_str() {
        "generate" => generate(rest),
        "params" => Ok(if rest.iter().any(|a| a == "--markdown") {
            params_markdown()
        } else {
            sylva_core::params::registry_json()
        }),
        "presets" => Ok(presets::presets_json()),
        "leaf-presets" => Ok(sylva_core::leaf::presets::presets_json()),
        "envelope" => envelope(rest),
        "bench" => bench(rest),
        "leaf" | "bench-leaf" => leaf::run(cmd, rest),
        "--help" | "-h" | "help" => Ok(USAGE.to_string()),
        "--version" => Ok(sylva_core::VERSION.to_string()),
        other => Err(format!("unknown command '{other}'\n{USAGE}")),
    }
}

/// Flags shared by `generate` and `bench`.
struct Opts {
    params: TreeParams,
    out: Option<String>,
    runs: usize,
    json: bool,
    report: Vec<String>,
    export: ExportOptions,
    glb: bool,
}

fn parse(args: &[String]) -> Result<Opts, String> {
    let mut preset: Option<String> = None;
    let mut sets: Vec<(String, String)> = Vec::new();
    let mut out = None;
    let mut runs = 30;
    let mut json = false;
    let mut report = Vec::new();
    let mut volumes = None;
    let mut export = ExportOptions::default();
    let mut glb = false;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "--preset" => preset = Some(value("--preset")?),
            "--seed" => sets.push(("seed".into(), value("--seed")?)),
            "--set" => {
                let kv = value("--set")?;
                let (k, v) = kv.split_once('=').ok_or_else(|| format!("--set takes id=value, got '{kv}'"))?;
                sets.push((k.to_string(), v.to_string()));
            }
            "--volumes" => {
                let path = value("--volumes")?;
                let text = std::fs::read_to_string(&path).map_err(|e| format!("cannot read --volumes {path}: {e}"))?;
                volumes = Some(sylva_core::growth::primitives::from_json(&text).map_err(|e| e.to_string())?);
            }
            "--out" => out = Some(value("--out")?),
            "--runs" => runs = value("--runs")?.parse().map_err(|_| "--runs takes a whole number".to_string())?,
            "--json" => json = true,
            "--glb" => glb = true,
            "--leaves" => {
                let v = value("--leaves")?;
                export.leaves = LeafMode::from_name(&v)
                    .ok_or_else(|| format!("--leaves takes 'instanced', 'baked' or 'none', got '{v}'"))?;
            }
            "--no-textures" => export.textures = false,
            "--no-tangents" => export.tangents = false,
            "--no-wind" => export.wind = false,
            "--report" => {
                let what = value("--report")?;
                if what != "skeleton" && what != "mesh" {
                    return Err(format!("--report takes 'skeleton' or 'mesh', got '{what}'"));
                }
                report.push(what);
            }
            other => return Err(format!("unknown option '{other}'\n{USAGE}")),
        }
    }
    let mut params = match preset.as_deref() {
        Some(name) => presets::find(name)
            .ok_or_else(|| {
                let names: Vec<&str> = presets::PRESETS.iter().map(|p| p.name).collect();
                format!("unknown preset '{name}' (known: {})", names.join(", "))
            })?
            .params()
            .map_err(|e| e.to_string())?,
        None => TreeParams::default(),
    };
    for (k, v) in sets {
        let num = parse_value(&k, &v)?;
        params.set(&k, num).map_err(|e| e.to_string())?;
    }
    if let Some(v) = volumes {
        params.volumes = v;
    }
    Ok(Opts { params, out, runs: runs.max(1), json, report, export, glb })
}

/// A `--set` value: a number, `true`/`false`, or an enum option label.
fn parse_value(id: &str, v: &str) -> Result<f64, String> {
    if let Ok(n) = v.parse::<f64>() {
        return Ok(n);
    }
    match v {
        "true" => return Ok(1.0),
        "false" => return Ok(0.0),
        _ => {}
    }
    let spec = sylva_core::params::spec(id).ok_or_else(|| {
        SylvaError::UnknownParam { param: id.into(), message: format!("unknown parameter '{id}' (see `sylva params`)") }
            .to_string()
    })?;
    if spec.kind == ParamKind::Enum {
        let norm = |s: &str| s.chars().filter(|c| c.is_ascii_alphanumeric()).collect::<String>().to_ascii_lowercase();
        if let Some(i) = spec.options.iter().flatten().position(|o| norm(o) == norm(v)) {
            return Ok(i as f64);
        }
    }
    Err(format!("{id} ({}) must be a number, got '{v}'", spec.label))
}

fn generate(args: &[String]) -> Result<String, String> {
    let opts = parse(args)?;
    let g = sylva_core::generate(&opts.params).map_err(|e| e.to_string())?;
    let written = match &opts.out {
        Some(path) => Some(write_export(&g, &opts.export, path)?),
        None => None,
    };
    let ms: serde_json::Map<String, serde_json::Value> =
        g.stats.stage_ms.iter().map(|(k, v)| (k.to_string(), serde_json::json!(v))).collect();
    let mut out = serde_json::json!({
        "vertices": g.stats.vertices,
        "triangles": g.stats.triangles,
        "stems": g.stats.stems,
        "hash": g.hash_hex(),
        "ms": ms,
        "total_ms": g.stats.total_ms,
    });
    if let Some(files) = written {
        out["written"] = serde_json::json!(files);
    }
    if opts.report.iter().any(|r| r == "mesh") {
        let t = sylva_core::mesh::topology::topology(&g.mesh);
        out["non_manifold_edges"] = t.non_manifold_edges.into();
        out["boundary_edges"] = t.boundary_edges.into();
        out["holes"] = g.stats.holes.into();
        out["hole_list"] = g
            .holes
            .iter()
            .map(|h| {
                serde_json::json!({
                    "stem": h.stem,
                    "source": h.source,
                    "centre": h.centre.to_array(),
                    "normal": h.normal.to_array(),
                    "radius": h.radius,
                    "depth": h.depth,
                })
            })
            .collect::<Vec<_>>()
            .into();
        out["welds"] = g.stats.welds.welds.into();
        out["weld_fallbacks"] = g.stats.welds.weld_fallbacks.into();
        out["split_welds"] = g.stats.welds.split_welds.into();
        out["split_fallbacks"] = g.stats.welds.split_fallbacks.into();
        out["forks"] = g.stats.welds.forks.into();
    }
    if opts.report.iter().any(|r| r == "skeleton") {
        let stems: Vec<serde_json::Value> = g
            .skeleton
            .stems
            .iter()
            .map(|s| {
                serde_json::json!({
                    "level": s.level,
                    "parent": s.parent,
                    "base_height": s.base().y,
                    "length": s.length,
                    "radius": s.radius,
                    "down_angle": s.down_angle,
                    "split_clone": s.chain_start > 0.0,
                })
            })
            .collect();
        out["skeleton"] = serde_json::Value::Array(stems);
    }
    Ok(out.to_string())
}

/// Writes `g` to `path` as GLB or OBJ (+ MTL + PNGs, named after the OBJ's stem, next to it);
/// returns `[file, bytes]` of every file written.
fn write_export(g: &sylva_core::Generated, export: &ExportOptions, path: &str) -> Result<Vec<(String, usize)>, String> {
    let write = |file: &str, bytes: &[u8]| std::fs::write(file, bytes).map_err(|e| format!("cannot write {file}: {e}"));
    let lower = path.to_ascii_lowercase();
    if lower.ends_with(".glb") {
        let bytes = sylva_core::export::to_glb(g, export);
        write(path, &bytes)?;
        Ok(vec![(path.to_string(), bytes.len())])
    } else if lower.ends_with(".obj") {
        let p = std::path::Path::new(path);
        let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("tree").to_string();
        let dir = p.parent().unwrap_or(std::path::Path::new(""));
        let files = sylva_core::export::obj::write(g, export, &stem);
        let mut written = Vec::new();
        write(path, files.obj.as_bytes())?;
        written.push((path.to_string(), files.obj.len()));
        let mut side = vec![(format!("{stem}.mtl"), files.mtl.into_bytes())];
        side.extend(files.textures);
        for (name, bytes) in side {
            let file = dir.join(&name).to_string_lossy().into_owned();
            write(&file, &bytes)?;
            written.push((file, bytes.len()));
        }
        Ok(written)
    } else {
        Err(format!("--out: the file must end in .glb or .obj, got '{path}'"))
    }
}

/// `sylva envelope --shape NAME [--samples N]`: `[[r, ShapeRatio(r)], ...]`, r from 0 (top) to 1 (crown base).
fn envelope(args: &[String]) -> Result<String, String> {
    let mut shape = None;
    let mut samples = 101usize;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let v = it.next().ok_or_else(|| format!("{a} needs a value"))?;
        match a.as_str() {
            "--shape" => {
                let names = sylva_core::CrownShape::LABELS.join(", ");
                shape = Some(
                    sylva_core::CrownShape::from_name(v)
                        .ok_or_else(|| format!("unknown crown shape '{v}' (known: {names})"))?,
                );
            }
            "--samples" => {
                samples = v.parse().map_err(|_| "--samples takes a whole number".to_string())?;
                if !(2..=100_000).contains(&samples) {
                    return Err(format!("--samples must be between 2 and 100000, got {samples}"));
                }
            }
            other => return Err(format!("unknown option '{other}'\n{USAGE}")),
        }
    }
    let shape = shape.ok_or("--shape is required")?;
    serde_json::to_string(&sylva_core::crown::envelope_profile(shape, samples)).map_err(|e| e.to_string())
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn bench(args: &[String]) -> Result<String, String> {
    let opts = parse(args)?;
    let mut totals = Vec::with_capacity(opts.runs);
    let mut stages: Vec<(&'static str, Vec<f64>)> = Vec::new();
    let mut last = None;
    sylva_core::generate(&opts.params).map_err(|e| e.to_string())?; // warm-up
    for _ in 0..opts.runs {
        let g = sylva_core::generate(&opts.params).map_err(|e| e.to_string())?;
        totals.push(g.stats.total_ms);
        for (i, (name, ms)) in g.stats.stage_ms.iter().enumerate() {
            if stages.len() <= i {
                stages.push((name, Vec::new()));
            }
            stages[i].1.push(*ms);
        }
        last = Some(g);
    }
    let g = last.expect("runs >= 1");
    let glb = opts.glb.then(|| bench_glb(&g, &opts.export, opts.runs));
    let total = median(&mut totals);
    let stage: serde_json::Map<String, serde_json::Value> =
        stages.iter_mut().map(|(k, v)| (k.to_string(), serde_json::json!(median(v)))).collect();
    let vps = g.stats.vertices as f64 / (total / 1000.0);
    let mut report = serde_json::json!({
        "target": "native",
        "runs": opts.runs,
        "vertices": g.stats.vertices,
        "triangles": g.stats.triangles,
        "median_ms": total,
        "stage_median_ms": stage,
        "vertices_per_second": vps,
        "hash": g.hash_hex(),
    });
    if let Some(b) = &glb {
        report["glb"] = b.clone();
    }
    if opts.json {
        Ok(report.to_string())
    } else {
        let mut s = format!(
            "native: {} vertices, median {:.3} ms over {} runs ({:.1} M vertices/s)",
            g.stats.vertices,
            total,
            opts.runs,
            vps / 1e6
        );
        if let Some(b) = &glb {
            s.push_str(&format!(
                "\nGLB export: median {:.3} ms (reused buffer {:.3} ms), first (with PNG encoding) {:.3} ms, {} bytes",
                b["median_ms"].as_f64().unwrap_or(0.0),
                b["reused_buffer_median_ms"].as_f64().unwrap_or(0.0),
                b["first_ms"].as_f64().unwrap_or(0.0),
                b["bytes"]
            ));
        }
        Ok(s)
    }
}

/// Times `runs` GLB exports of `g`: the first (encodes the PNG textures, which later exports
/// reuse from the cache), the median of the rest (each into a fresh buffer, as `--out` does),
/// and the medians into one reused buffer (`write_into`) on every thread and on one.
fn bench_glb(g: &sylva_core::Generated, export: &ExportOptions, runs: usize) -> serde_json::Value {
    let now = std::time::Instant::now;
    let t0 = now();
    let first = sylva_core::export::to_glb(g, export);
    let first_ms = t0.elapsed().as_secs_f64() * 1000.0;
    let mut times = Vec::with_capacity(runs);
    let mut bytes = first.len();
    drop(first);
    for _ in 0..runs {
        let t = now();
        let b = sylva_core::export::to_glb(g, export);
        times.push(t.elapsed().as_secs_f64() * 1000.0);
        bytes = b.len();
    }
    // The same exports into one reused buffer (no fresh pages for the kernel to zero), on
    // every thread the machine offers, and on one (what wasm has).
    let mut buf = Vec::new();
    sylva_core::export::glb::write_into(g, export, &mut buf);
    let threads = sylva_core::par::threads();
    let mut reused = |threads: usize| {
        let mut ms: Vec<f64> = (0..runs)
            .map(|_| {
                let t = now();
                sylva_core::export::glb::write_into_threads(g, export, &mut buf, threads);
                t.elapsed().as_secs_f64() * 1000.0
            })
            .collect();
        median(&mut ms)
    };
    let (reuse, reuse_one) = (reused(threads), reused(1));
    serde_json::json!({
        "median_ms": median(&mut times),
        "reused_buffer_median_ms": reuse,
        "reused_buffer_one_thread_median_ms": reuse_one,
        "threads": threads,
        "first_ms": first_ms,
        "bytes": bytes,
        "runs": runs,
    })
}

/// The parameter reference for the README, generated from the registry.
fn params_markdown() -> String {
    let mut s =
        String::from("| id | group | type | default | range | unit | description |\n|---|---|---|---|---|---|---|\n");
    for p in registry() {
        let kind = match p.kind {
            ParamKind::Float => "float",
            ParamKind::Int => "int",
            ParamKind::Bool => "bool",
            ParamKind::Enum => "enum",
        };
        let range = match &p.options {
            Some(opts) => opts.iter().enumerate().map(|(i, o)| format!("{i} {o}")).collect::<Vec<_>>().join(", "),
            None => format!("{} to {}", p.min, p.max),
        };
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} | {} |\n",
            p.id, p.group, kind, p.default, range, p.unit, p.description
        ));
    }
    s
}
