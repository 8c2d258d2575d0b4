//! The generated references stay true: docs/cli.md, docs/parameters.md, the docs page's
//! `web/src/docs/cli.json` and the TypeScript types of the registry and presets
//! (`packages/sylva-trees/src/core/generated/params.ts`) and of the core's JSON payloads
//! (`packages/sylva-trees/src/core/generated/payloads.ts`) and the Python package's type stub
//! (`core-rs/sylva-py/python/sylva_trees/__init__.pyi`) are exactly what the binary prints
//! (`npm run docs` writes them), and `sylva help` describes every command and option the CLI
//! accepts.

use std::process::Command;

fn sylva(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_sylva")).args(args).output().expect("run sylva");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

/// The repository file `path`.
fn file(path: &str) -> String {
    let full = format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("cannot read {path} ({e}): run `npm run docs`"))
}

#[test]
fn generated_docs_are_what_the_binary_prints() {
    let mut stale = Vec::new();
    for (args, path) in [
        (&["cli-reference"][..], "docs/cli.md"),
        (&["cli-reference", "--json"][..], "web/src/docs/cli.json"),
        (&["params", "--markdown"][..], "docs/parameters.md"),
        (&["params", "--typescript"][..], "packages/sylva-trees/src/core/generated/params.ts"),
        (&["params", "--payloads"][..], "packages/sylva-trees/src/core/generated/payloads.ts"),
        (&["params", "--python-stub"][..], "core-rs/sylva-py/python/sylva_trees/__init__.pyi"),
    ] {
        let (code, out, err) = sylva(args);
        assert_eq!(code, 0, "sylva {args:?}: {err}");
        if file(path) != out {
            stale.push(path);
        }
    }
    assert!(stale.is_empty(), "stale generated docs {stale:?}: run `npm run docs`");
}

#[test]
fn the_parameter_reference_has_every_parameter_without_float_noise() {
    let (_, reg, _) = sylva(&["params"]);
    let reg: serde_json::Value = serde_json::from_str(&reg).expect("JSON");
    let doc = file("docs/parameters.md");
    for p in reg.as_array().expect("an array") {
        let id = p["id"].as_str().expect("an id");
        assert!(doc.contains(&format!("| `{id}` |")), "{id} missing");
    }
    assert!(doc.contains("| `ratio` | Radius Ratio | float | 0.015 | 0.001 to 0.2 |"), "ratio's row");
    // f32 noise such as 0.014999999664723873: seven or more digits after a decimal point.
    let noisy = doc.split('.').skip(1).find(|after| after.len() >= 7 && after[..7].bytes().all(|b| b.is_ascii_digit()));
    assert_eq!(noisy.map(|s| &s[..20.min(s.len())]), None, "float noise in docs/parameters.md");
}

#[test]
fn the_typescript_types_have_every_parameter_and_preset() {
    let (_, reg, _) = sylva(&["params"]);
    let (_, presets, _) = sylva(&["presets"]);
    let module = file("packages/sylva-trees/src/core/generated/params.ts");
    assert!(module.starts_with("// @generated"), "the header marks the file as generated");
    let reg: serde_json::Value = serde_json::from_str(&reg).expect("JSON");
    for p in reg.as_array().expect("an array") {
        let id = p["id"].as_str().expect("an id");
        assert!(module.contains(&format!("\n  {id}: {{")), "{id} missing from PARAM_SPECS");
        if let Some(options) = p["options"].as_array() {
            let first = options[0].as_str().expect("a label");
            assert!(module.contains(&format!("  {id}:")) && module.contains(&format!("'{first}'")), "{id}'s options");
        }
    }
    assert!(module.contains("  ratio: {\n    label: 'Radius Ratio',"), "ratio's entry");
    assert!(module.contains("    default: 0.014999999664723873,"), "defaults are the registry's f32 values");
    let presets: serde_json::Value = serde_json::from_str(&presets).expect("JSON");
    for p in presets.as_array().expect("an array") {
        let name = p["name"].as_str().expect("a name");
        assert!(module.contains(&format!("\n  '{name}',")), "{name} missing from PRESET_IDS");
        assert!(module.contains(&format!("\n  {name}: {{")), "{name} missing from PRESET_VALUES");
    }
}

#[test]
fn help_lists_every_command_and_option() {
    let (code, help, _) = sylva(&["help"]);
    assert_eq!(code, 0);
    assert_eq!(sylva(&["--help"]).1, help);
    let reference: serde_json::Value = serde_json::from_str(&file("web/src/docs/cli.json")).expect("JSON");
    let commands = reference["commands"].as_array().expect("commands");
    let names: Vec<&str> = commands.iter().map(|c| c["name"].as_str().expect("a name")).collect();
    for want in ["generate", "params", "presets", "envelope", "bench", "leaf", "bench-leaf", "cli-reference"] {
        assert!(names.contains(&want), "{want} not in the reference");
    }
    for c in commands {
        let name = c["name"].as_str().expect("a name");
        assert!(help.contains(&format!("  {name} ")), "sylva help lacks {name}");
        let (code, own, _) = sylva(&[name, "--help"]);
        assert_eq!(code, 0);
        for o in c["options"].as_array().expect("options") {
            let flag = o["flag"].as_str().expect("a flag").split(' ').next().expect("a flag");
            assert!(own.contains(flag), "sylva {name} --help lacks {flag}");
            assert!(c["synopsis"].as_str().expect("a synopsis").contains(flag), "{name} synopsis lacks {flag}");
        }
    }
    let (_, generate, _) = sylva(&["generate", "--help"]);
    for flag in ["--volumes FILE.json", "--no-tangents", "--no-wind", "--leaves instanced|baked|none"] {
        assert!(generate.contains(flag), "generate --help lacks {flag}");
    }
}

#[test]
fn usage_errors_keep_their_messages_and_exit_2() {
    for (args, want) in [
        (&["generate", "--preset"][..], "error: --preset needs a value"),
        (&["envelope"][..], "error: --shape is required"),
        (
            &["envelope", "--shape", "flame", "--samples", "1"][..],
            "error: --samples must be between 2 and 100000, got 1",
        ),
        (&["generate", "--set", "levels"][..], "error: --set takes id=value, got 'levels'"),
        (&["bench", "--runs", "many"][..], "error: --runs takes a whole number"),
        (&["leaf", "--step", "x"][..], "error: --step takes a whole number"),
        (&["generate", "--json"][..], "error: unknown option '--json'"),
        (&["grow"][..], "error: unknown command 'grow'"),
        (&[][..], "error: no command given"),
    ] {
        let (code, out, err) = sylva(args);
        assert_eq!(code, 2, "sylva {args:?}");
        assert!(out.is_empty(), "sylva {args:?} printed {out}");
        assert!(err.starts_with(want), "sylva {args:?}: {err}");
    }
    let (code, out, _) = sylva(&["--version"]);
    assert_eq!((code, out.trim()), (0, env!("CARGO_PKG_VERSION")));
}

#[test]
fn seed_and_set_seed_apply_in_the_order_given() {
    let hash = |args: &[&str]| {
        let (code, out, err) = sylva(&[&["generate", "--set", "levels=1", "--leaves", "none"][..], args].concat());
        assert_eq!(code, 0, "{err}");
        serde_json::from_str::<serde_json::Value>(&out).expect("JSON")["hash"].clone()
    };
    assert_eq!(hash(&["--seed", "3", "--set", "seed=5"]), hash(&["--seed", "5"]));
    assert_eq!(hash(&["--set", "seed=5", "--seed", "3"]), hash(&["--seed", "3"]));
    assert_ne!(hash(&["--seed", "3"]), hash(&["--seed", "5"]));
}
