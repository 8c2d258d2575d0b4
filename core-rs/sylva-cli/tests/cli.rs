//! The `sylva` binary end to end: output shapes, exit codes and messages (the generated
//! references and the help are checked in `docs.rs`).

use std::process::Command;

fn sylva(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_sylva")).args(args).output().expect("run sylva");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

fn json(s: &str) -> serde_json::Value {
    serde_json::from_str(s).unwrap_or_else(|e| panic!("not JSON ({e}): {s}"))
}

#[test]
fn generate_prints_one_json_object() {
    let (code, out, _) = sylva(&["generate", "--preset", "fir", "--seed", "3"]);
    assert_eq!(code, 0);
    let v = json(&out);
    assert!(v["vertices"].as_u64().unwrap() > 1000);
    assert!(v["triangles"].as_u64().unwrap() > 1000);
    assert_eq!(v["hash"].as_str().unwrap().len(), 16);
    for stage in ["skeleton", "mesh", "hash"] {
        assert!(v["ms"][stage].as_f64().is_some(), "missing stage {stage}");
    }
}

#[test]
fn bench_glb_reports_the_export_times_and_the_file_size() {
    // `npm run bench` reads these keys; the size is that of the file `--out` writes.
    let (code, out, err) = sylva(&["bench", "--preset", "grown_bushy", "--runs", "2", "--json", "--glb"]);
    assert_eq!(code, 0, "{err}");
    let glb = &json(&out)["glb"];
    for key in ["first_ms", "median_ms", "reused_buffer_median_ms", "reused_buffer_one_thread_median_ms"] {
        assert!(glb[key].as_f64().is_some_and(|ms| ms > 0.0), "{key}: {glb}");
    }
    assert!(glb["threads"].as_u64().is_some_and(|t| t >= 1), "{glb}");
    let path = std::env::temp_dir().join(format!("sylva-bench-{}.glb", std::process::id()));
    let (code, _, err) = sylva(&["generate", "--preset", "grown_bushy", "--out", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let size = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
    let _ = std::fs::remove_file(&path);
    assert_eq!(glb["bytes"].as_u64(), Some(size));
}

#[test]
fn invalid_parameters_exit_2_with_the_validation_message() {
    let (code, out, err) = sylva(&["generate", "--set", "l1_length=3"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert_eq!(err.trim(), "error: l1_length (Length) is 3: allowed range is 0 to 2");
    let (code, _, err) = sylva(&["generate", "--set", "nope=1"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown parameter 'nope'"), "{err}");
    let (code, _, err) = sylva(&["generate", "--preset", "baobab"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown preset 'baobab'") && err.contains("weeping_willow"), "{err}");
    let (code, _, err) = sylva(&["generate", "--set", "max_vertices=1000"]);
    assert_eq!(code, 2);
    assert!(err.contains("max_vertices budget of 1000"), "{err}");
}

#[test]
fn enum_values_by_name_and_obj_output() {
    let dir = std::env::temp_dir().join(format!("sylva-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("t.obj");
    let p = path.to_str().unwrap();
    // Bark only: the OBJ has exactly the tree's vertices and triangles.
    let (code, out, err) =
        sylva(&["generate", "--set", "shape=inverse-conical", "--set", "levels=2", "--leaves", "none", "--out", p]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    let obj = std::fs::read_to_string(&path).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count() as u64, v["vertices"].as_u64().unwrap());
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count() as u64, v["triangles"].as_u64().unwrap());
    assert!(obj.contains("mtllib t.mtl"));
    assert!(std::fs::read_to_string(dir.join("t.mtl")).unwrap().contains("map_Kd t_bark_color.png"));
    assert!(std::fs::read(dir.join("t_bark_color.png")).unwrap().starts_with(b"\x89PNG"));
    // GLB, and a wrong extension is refused.
    let glb = dir.join("t.glb");
    let (code, out, err) = sylva(&["generate", "--set", "levels=2", "--out", glb.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let bytes = std::fs::read(&glb).unwrap();
    assert!(bytes.starts_with(b"glTF"));
    assert_eq!(json(&out)["written"][0][1].as_u64().unwrap(), bytes.len() as u64);
    let (code, _, err) = sylva(&["generate", "--out", "tree.stl"]);
    assert_eq!(code, 2);
    assert!(err.contains(".glb or .obj"), "{err}");
    let (code, _, err) = sylva(&["generate", "--leaves", "sideways"]);
    assert_eq!(code, 2);
    assert!(err.contains("--leaves"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn report_foliage_lists_the_parts_of_the_season() {
    let (code, out, _) = sylva(&["generate", "--preset", "oak", "--set", "season=9.5", "--report", "foliage"]);
    assert_eq!(code, 0);
    let f = &json(&out)["foliage"];
    assert!(f["leaves"].as_u64().unwrap() > 1000);
    assert_eq!(f["fallen"], 0);
    let names: Vec<&str> = f["organs"].as_array().unwrap().iter().map(|o| o["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["acorn stalks", "acorns", "acorn cups"]);
    let acorns = &f["organs"][1];
    assert_eq!(acorns["kind"], "fruit");
    assert_eq!(acorns["origins"].as_array().unwrap().len() as u64, acorns["count"].as_u64().unwrap());
}

#[test]
fn report_skeleton_lists_stems() {
    let (code, out, _) = sylva(&["generate", "--preset", "weeping", "--report", "skeleton"]);
    assert_eq!(code, 0);
    let v = json(&out);
    let stems = v["skeleton"].as_array().unwrap();
    assert_eq!(stems.len() as u64, v["stems"].as_u64().unwrap());
    assert_eq!(stems[0]["level"], 0);
    let l1 = stems.iter().find(|s| s["level"] == 1).unwrap();
    for key in ["base_height", "length", "down_angle"] {
        assert!(l1[key].as_f64().is_some(), "{key}");
    }
}

#[test]
fn envelope_prints_pairs_of_the_shape_ratio() {
    let (code, out, _) = sylva(&["envelope", "--shape", "Conical", "--samples", "3"]);
    assert_eq!(code, 0);
    assert_eq!(json(&out), json("[[0.0,0.2],[0.5,0.6],[1.0,1.0]]"));
    let (code, _, err) = sylva(&["envelope", "--shape", "blob"]);
    assert_eq!(code, 2);
    assert!(err.contains("Tend Flame"), "{err}");
}

#[test]
fn params_and_presets_are_json() {
    let (_, out, _) = sylva(&["params"]);
    let reg = json(&out);
    assert!(reg.as_array().unwrap().iter().any(|p| p["id"] == "l1_down_angle"));
    let (_, out, _) = sylva(&["presets"]);
    let names: Vec<String> =
        json(&out).as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap().to_string()).collect();
    for want in [
        "quaking_aspen",
        "black_tupelo",
        "weeping_willow",
        "ca_black_oak",
        "fir",
        "oak",
        "cypress",
        "umbrella",
        "weeping",
    ] {
        assert!(names.iter().any(|n| n == want), "missing preset {want}");
    }
}

#[test]
fn report_mesh_counts_open_and_non_manifold_edges() {
    let (code, out, err) = sylva(&["generate", "--preset", "fir", "--report", "mesh"]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    assert_eq!(v["non_manifold_edges"], 0);
    // Welded junctions and capped separate tubes: the surface is closed.
    assert_eq!(v["boundary_edges"], 0);
    assert_eq!(v["holes"], 0);
    let (welds, fallbacks) = (v["welds"].as_u64().unwrap(), v["weld_fallbacks"].as_u64().unwrap());
    assert!(welds > 1000 && fallbacks < welds / 2, "{welds} welds, {fallbacks} fallbacks");
    // Without welding: nothing welded, nothing counted as a fallback, still closed.
    let (code, out, err) = sylva(&["generate", "--preset", "fir", "--set", "weld=false", "--report", "mesh"]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    assert_eq!(
        (v["welds"].as_u64(), v["weld_fallbacks"].as_u64(), v["boundary_edges"].as_u64()),
        (Some(0), Some(0), Some(0))
    );
    // Holes: counted, listed (where, which method, how big), and the surface stays closed.
    let (code, out, err) = sylva(&["generate", "--preset", "oak", "--set", "hole_count=3", "--report", "mesh"]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    let list = v["hole_list"].as_array().unwrap();
    assert_eq!(v["holes"].as_u64().unwrap(), list.len() as u64);
    assert!(!list.is_empty());
    for h in list {
        assert!(["surface", "junction", "root"].contains(&h["source"].as_str().unwrap()), "{h}");
        assert!(h["radius"].as_f64().unwrap() > 0.0 && h["depth"].as_f64().unwrap() > 0.0, "{h}");
        assert_eq!(h["centre"].as_array().unwrap().len(), 3);
    }
    assert_eq!((v["boundary_edges"].as_u64(), v["non_manifold_edges"].as_u64()), (Some(0), Some(0)));
    let (code, _, err) = sylva(&["generate", "--report", "everything"]);
    assert_eq!(code, 2);
    assert!(err.contains("--report takes 'skeleton', 'mesh' or 'foliage'"), "{err}");
}

/// A fresh, empty folder under the system's temporary folder.
fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("sylva-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn batch_writes_the_bytes_generate_writes_and_a_manifest() {
    let dir = temp_dir("batch");
    let d = dir.to_str().unwrap();
    let (code, out, err) =
        sylva(&["batch", "--preset", "grown_bushy", "--preset", "fir", "--seeds", "3-4", "--threads", "2", "--out", d]);
    assert_eq!(code, 0, "{err}");
    let printed = json(&out);
    let written = json(&std::fs::read_to_string(dir.join("manifest.json")).expect("manifest.json"));
    assert_eq!(printed, written);
    assert_eq!(printed["count"], 4);
    assert_eq!(printed["failed"], 0);
    assert!(printed["trees_per_second"].as_f64().is_some_and(|t| t > 0.0));
    let trees = printed["trees"].as_array().unwrap();
    let names: Vec<&str> = trees.iter().map(|t| t["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["grown_bushy_3", "grown_bushy_4", "fir_3", "fir_4"]);
    for t in trees {
        let (preset, seed) = (t["preset"].as_str().unwrap(), t["seed"].to_string());
        let one = dir.join(format!("one-{preset}-{seed}.glb"));
        let (code, gen, err) =
            sylva(&["generate", "--preset", preset, "--seed", &seed, "--out", one.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
        let gen = json(&gen);
        assert_eq!(t["hash"], gen["hash"]);
        assert_eq!(t["vertices"], gen["vertices"]);
        let file = t["file"].as_str().unwrap();
        assert!(file.ends_with(&format!("{preset}_{seed}.glb")), "{file}");
        let (a, b) = (std::fs::read(file).unwrap(), std::fs::read(&one).unwrap());
        assert!(a == b, "{file}: {} bytes, generate wrote {}", a.len(), b.len());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn batch_takes_a_json_list_and_reports_failures_after_the_others() {
    let dir = temp_dir("batch-list");
    std::fs::create_dir_all(&dir).unwrap();
    let (good, bad) = (dir.join("good.json"), dir.join("bad.json"));
    let fir = r#"{"preset": "fir", "seed": 5, "set": {"levels": 2, "shape": "conical"}, "name": "small_fir"}"#;
    std::fs::write(&good, format!("[{fir}]")).unwrap();
    std::fs::write(&bad, format!(r#"[{fir}, {{"seed": 2, "set": {{"max_vertices": 10000}}}}]"#)).unwrap();
    // The list's tree is the one `generate` makes with the same values.
    let (code, out, err) = sylva(&["batch", "--list", good.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let (code, gen, err) =
        sylva(&["generate", "--preset", "fir", "--seed", "5", "--set", "levels=2", "--set", "shape=conical"]);
    assert_eq!(code, 0, "{err}");
    let first = &json(&out)["trees"][0];
    assert_eq!(first["name"], "small_fir");
    assert!(first["file"].is_null(), "no --out, no file: {first}");
    assert_eq!(first["hash"], json(&gen)["hash"]);
    // A tree over its budget fails; the others are still made, and the batch exits 2.
    let (code, _, err) = sylva(&["batch", "--list", bad.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("1 of 2 trees failed") && err.contains("max_vertices"), "{err}");
    let manifest = json(&std::fs::read_to_string(dir.join("manifest.json")).unwrap());
    assert!(manifest["trees"][1]["error"].as_str().is_some_and(|e| e.contains("max_vertices")), "{manifest}");
    assert!(dir.join("small_fir.glb").exists());
    let (code, _, err) = sylva(&["batch", "--seeds", "1,1"]);
    assert_eq!(code, 2);
    assert!(err.contains("two trees named 'default_1'"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
