//! `sylva generate` and `sylva bench`: one tree from a command line, its JSON report and export
//! files, and its timings.

use crate::cli::{BenchArgs, ExportArgs, GenerateArgs};
use crate::{median, tree_params};
use sylva_core::export::ExportOptions;

/// The export options of a command line.
pub(crate) fn export_options(a: &ExportArgs) -> ExportOptions {
    let mut export = ExportOptions::default();
    if let Some(leaves) = a.leaves {
        export.leaves = leaves;
    }
    export.textures = !a.no_textures;
    export.tangents = !a.no_tangents;
    export.wind = !a.no_wind;
    export.strict = a.strict;
    export
}

/// `sylva generate`: one JSON object, and the export files of `--out`.
pub fn generate(a: &GenerateArgs) -> Result<String, String> {
    let params = tree_params(&a.tree)?;
    let g = sylva_core::generate(&params).map_err(|e| match &a.tree.edits {
        Some(path) if e.message().starts_with("edits") => format!("--edits {path}: {e}"),
        _ => e.to_string(),
    })?;
    for (i, r) in g.edits.iter().enumerate().filter(|(_, r)| !r.resolved) {
        eprintln!("edits[{i}] ({}) is unresolved: {}", r.op, r.why.as_deref().unwrap_or("no stem found"));
    }
    let (g, written) = match &a.out {
        Some(path) if a.lods => {
            let l = sylva_core::lod::lods_of(g, &params.mesh).map_err(|e| e.to_string())?;
            let files = write_lods(&l, &export_options(&a.export), path)?;
            (l.lod0, Some(files))
        }
        Some(path) if a.growth_animation => {
            let files = write_growth(&g, &params, &export_options(&a.export), path)?;
            (g, Some(files))
        }
        Some(path) => {
            let files = write_export(&g, &export_options(&a.export), path)?;
            (g, Some(files))
        }
        None => (g, None),
    };
    let written = match &a.growth_years {
        Some(path) => {
            if !path.to_ascii_lowercase().ends_with(".zip") {
                return Err(format!("--growth-years: the file must end in .zip, got '{path}'"));
            }
            let bytes = sylva_core::export::growth::years::years_zip(&params, &export_options(&a.export))
                .map_err(|e| format!("--growth-years: {e}"))?;
            std::fs::write(path, &bytes).map_err(|e| format!("cannot write {path}: {e}"))?;
            Some(written.unwrap_or_default().into_iter().chain([(path.clone(), bytes.len())]).collect())
        }
        None => written,
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
    if !g.edits.is_empty() {
        out["edits"] = serde_json::json!(g.edits);
    }
    if let Some(files) = written {
        out["written"] = serde_json::json!(files);
    }
    if a.report.iter().any(|r| r == "mesh") {
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
    if a.report.iter().any(|r| r == "foliage") {
        out["foliage"] = foliage_report(&g.foliage);
    }
    if a.report.iter().any(|r| r == "skeleton") {
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
                    "split_clone": s.kind == sylva_core::skeleton::StemKind::SplitClone,
                })
            })
            .collect();
        out["skeleton"] = serde_json::Value::Array(stems);
    }
    Ok(out.to_string())
}

/// `--report foliage`: the leaves on the tree and on the ground, and each set of parts with the
/// origins of its instances.
fn foliage_report(f: &sylva_core::foliage::Foliage) -> serde_json::Value {
    let organs: Vec<serde_json::Value> = f
        .organs
        .iter()
        .map(|s| {
            let origins: Vec<[f32; 3]> = s.matrices.chunks_exact(16).map(|m| [m[12], m[13], m[14]]).collect();
            serde_json::json!({"name": s.name, "kind": s.kind, "count": s.count(), "origins": origins})
        })
        .collect();
    serde_json::json!({"leaves": f.on_tree(), "fallen": f.fallen, "organs": organs})
}

/// Writes the levels of `l` to `path` as one GLB ([`sylva_core::export::lods_glb`]), its nodes
/// named after the file's stem; returns `[file, bytes]`.
fn write_lods(
    l: &sylva_core::lod::TreeLods,
    export: &ExportOptions,
    path: &str,
) -> Result<Vec<(String, usize)>, String> {
    if !path.to_ascii_lowercase().ends_with(".glb") {
        return Err(format!("--lods: the file must end in .glb, got '{path}'"));
    }
    let p = std::path::Path::new(path);
    let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("tree");
    let bytes = sylva_core::export::lods_glb(l, export, stem);
    std::fs::write(path, &bytes).map_err(|e| format!("cannot write {path}: {e}"))?;
    Ok(vec![(path.to_string(), bytes.len())])
}

/// Writes `g` (generated from `params`) to `path` as the GLB with its growth animation
/// ([`sylva_core::export::glb::write_growth`]); returns `[file, bytes]`.
fn write_growth(
    g: &sylva_core::Generated,
    params: &sylva_core::TreeParams,
    export: &ExportOptions,
    path: &str,
) -> Result<Vec<(String, usize)>, String> {
    if !path.to_ascii_lowercase().ends_with(".glb") {
        return Err(format!("--growth-animation: the file must end in .glb, got '{path}'"));
    }
    let bytes = sylva_core::export::glb::write_growth(g, export, params.skeleton.age, params.skeleton.maturity);
    std::fs::write(path, &bytes).map_err(|e| format!("cannot write {path}: {e}"))?;
    Ok(vec![(path.to_string(), bytes.len())])
}

/// Writes `g` to `path` as GLB or OBJ (+ MTL + PNGs, named after the OBJ's stem, next to it);
/// returns `[file, bytes]` of every file written.
pub(crate) fn write_export(
    g: &sylva_core::Generated,
    export: &ExportOptions,
    path: &str,
) -> Result<Vec<(String, usize)>, String> {
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

/// `sylva bench`: the median generation time (and GLB export times with `--glb`).
pub fn bench(a: &BenchArgs) -> Result<String, String> {
    let params = tree_params(&a.tree)?;
    let runs = a.runs.max(1);
    let mut totals = Vec::with_capacity(runs);
    let mut stages: Vec<(&'static str, Vec<f64>)> = Vec::new();
    let mut last = None;
    sylva_core::generate(&params).map_err(|e| e.to_string())?; // warm-up
    for _ in 0..runs {
        let g = sylva_core::generate(&params).map_err(|e| e.to_string())?;
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
    let glb = a.glb.then(|| bench_glb(&g, &export_options(&a.export), runs));
    let total = median(&mut totals);
    let stage: serde_json::Map<String, serde_json::Value> =
        stages.iter_mut().map(|(k, v)| (k.to_string(), serde_json::json!(median(v)))).collect();
    let vps = g.stats.vertices as f64 / (total / 1000.0);
    let mut report = serde_json::json!({
        "target": "native",
        "runs": runs,
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
    if a.json {
        Ok(report.to_string())
    } else {
        let mut s = format!(
            "native: {} vertices, median {:.3} ms over {} runs ({:.1} M vertices/s)",
            g.stats.vertices,
            total,
            runs,
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
