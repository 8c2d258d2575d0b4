//! `sylva leaf` and `sylva bench-leaf` end to end: the JSON shape, the SVG file, and exit code 2
//! with a message naming the field for invalid parameters.

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
    serde_json::from_str(s).unwrap_or_else(|e| panic!("not JSON ({e}): {}", &s[..s.len().min(200)]))
}

#[test]
fn leaf_prints_the_leaf_as_json_and_writes_the_svg() {
    let dir = std::env::temp_dir().join(format!("sylva-leaf-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("maple.svg");
    let (code, out, err) =
        sylva(&["leaf", "--preset", "maple", "--svg", svg.to_str().unwrap(), "--step", "40", "--triangulation"]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    assert_eq!(v["hash"].as_str().unwrap().len(), 16);
    let outline = v["outline"].as_array().unwrap();
    assert!(outline.len() > 50 && outline[0] == serde_json::json!([0.0, 1.0]));
    let tri = &v["triangulation"];
    assert!(tri["triangles"].as_array().unwrap().len() > 100);
    assert!(["rings", "cdt"].contains(&tri["method"].as_str().unwrap()));
    let auxins = v["auxins"].as_array().unwrap();
    assert!(auxins.len() > 100 && auxins[0].as_array().unwrap().len() == 3);
    let nodes = v["veins"]["nodes"].as_array().unwrap();
    assert!(nodes[0]["parent"].is_null() && nodes[1]["parent"].as_u64().is_some());
    for key in ["x", "y", "born", "width", "tips"] {
        assert!(nodes[1][key].is_number(), "node field {key}");
    }
    assert!(v["loops"].as_u64().unwrap() > 0, "maple has closed venation");
    assert_eq!(v["veins"]["links"].as_array().unwrap().len() as u64, v["loops"].as_u64().unwrap());
    assert_eq!(v["veins"]["edges"].as_array().unwrap().len(), nodes.len() - 1 + v["loops"].as_u64().unwrap() as usize);
    for stage in ["outline", "margin", "triangulation", "uvs", "veins", "deformation", "texture", "lod"] {
        assert!(v["ms"][stage].as_f64().is_some(), "missing stage {stage}");
    }
    let drawing = std::fs::read_to_string(&svg).unwrap();
    assert!(drawing.starts_with("<?xml") && drawing.trim_end().ends_with("</svg>"));
    assert!(drawing.contains("step 40 of"), "the SVG shows growth step 40");
}

#[test]
fn leaf_without_preset_uses_the_defaults_and_set_values() {
    let (code, out, err) =
        sylva(&["leaf", "--set", "leaf_margin=serrate", "--set", "leaf_teeth=30", "--set", "leaf_venation=none"]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    assert!(v["veins"]["nodes"].as_array().unwrap().is_empty());
    assert!(v["auxins"].as_array().unwrap().is_empty());
}

#[test]
fn invalid_leaf_parameters_exit_2_naming_the_field() {
    let (code, out, err) = sylva(&["leaf", "--preset", "oak", "--set", "leaf_kill=1"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert_eq!(err.trim(), "error: leaf_kill (Kill Distance) is 1: allowed range is 0.002 to 0.05");
    let (code, _, err) = sylva(&["leaf", "--set", "leaf_kill=0.04", "--set", "leaf_attraction=0.03"]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: leaf_attraction (Attraction Distance)"), "{err}");
    let (code, _, err) = sylva(&["leaf", "--set", "leaf_margin=wavy"]);
    assert_eq!(code, 2);
    assert!(err.contains("leaf_margin (Margin)"), "{err}");
    let (code, _, err) = sylva(&["leaf", "--preset", "baobab"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown leaf preset 'baobab'") && err.contains("maple"), "{err}");
    let (code, _, err) = sylva(&["leaf", "--frobnicate"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown option '--frobnicate'"), "{err}");
}

#[test]
fn bench_leaf_reports_medians_with_5000_sources() {
    let (code, out, err) = sylva(&["bench-leaf", "--preset", "oak", "--runs", "2", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v = json(&out);
    let r = &v["results"][0];
    assert_eq!(r["preset"], "oak");
    assert_eq!(r["auxins"], 5001, "5,000 sources plus the apex source");
    assert!(r["median_ms"].as_f64().unwrap() > 0.0);
    assert!(r["stage_median_ms"]["veins"].as_f64().is_some());
    let (code, out, _) = sylva(&["bench-leaf", "--runs", "1"]);
    assert_eq!(code, 0);
    assert!(out.contains("oak (Open)") && out.contains("maple (Closed)"), "{out}");
}

#[test]
fn leaf_presets_lists_the_species_and_leaf_obj_writes_the_blade() {
    let (code, out, err) = sylva(&["leaf-presets"]);
    assert_eq!(code, 0, "{err}");
    let names: Vec<String> =
        json(&out).as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap().to_string()).collect();
    for species in ["oak", "maple", "birch", "aspen", "willow", "ginkgo", "pine", "fir"] {
        assert!(names.iter().any(|n| n == species), "{species} missing from {names:?}");
    }
    let dir = std::env::temp_dir().join(format!("sylva-leaf-obj-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("oak.obj");
    let (code, _, err) = sylva(&["leaf", "--preset", "oak", "--obj", obj.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&obj).unwrap();
    let vertices = text.lines().filter(|l| l.starts_with("v ")).count();
    let faces = text.lines().filter(|l| l.starts_with("f ")).count();
    assert!(vertices > 50 && faces > 50, "{vertices} vertices, {faces} faces");
    std::fs::remove_dir_all(&dir).ok();
}
