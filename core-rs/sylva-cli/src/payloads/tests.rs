//! The table of [`super::INTERFACES`] is the core's payloads: real JSON of every payload (the
//! text the wasm module returns) has exactly the declared keys, of the declared kinds, and every
//! declared field occurs in some payload.

use super::*;
use std::collections::BTreeSet;
use sylva_core::mesh::bark;
use sylva_core::params::{BarkType, TreeParams};
use sylva_core::session::{Quality, Session};

/// Walks JSON values against the table, noting the fields it saw and every mismatch.
#[derive(Default)]
struct Checker {
    seen: BTreeSet<(&'static str, &'static str)>,
    errors: Vec<String>,
}

impl Checker {
    fn check(&mut self, v: &Value, ty: Ty, at: &str) {
        let ok = match ty {
            Ty::Number => v.is_number(),
            Ty::String => v.is_string(),
            Ty::Bool => v.is_boolean(),
            Ty::NumberRecord => v.as_object().is_some_and(|o| o.values().all(Value::is_number)),
            Ty::Nullable(t) => {
                if !v.is_null() {
                    self.check(v, *t, at);
                }
                true
            }
            Ty::Array(t) => {
                let items = v.as_array().map(Vec::as_slice).unwrap_or_default();
                items.iter().enumerate().for_each(|(i, x)| self.check(x, *t, &format!("{at}[{i}]")));
                v.is_array()
            }
            Ty::Tuple(ts) => {
                let items = v.as_array().map(Vec::as_slice).unwrap_or_default();
                items.iter().zip(ts).enumerate().for_each(|(i, (x, t))| self.check(x, *t, &format!("{at}[{i}]")));
                items.len() == ts.len()
            }
            Ty::Named(name) => self.named(v, name, at),
        };
        if !ok {
            self.errors.push(format!("{at}: {v} is not a {}", ts(ty)));
        }
    }

    fn named(&mut self, v: &Value, name: &'static str, at: &str) -> bool {
        if let Some(u) = UNIONS.iter().find(|u| u.name == name) {
            return v.as_str().is_some_and(|s| (u.values)().iter().any(|x| x == s));
        }
        let Some(i) = INTERFACES.iter().find(|i| i.name == name) else {
            self.errors.push(format!("{at}: no interface or union named {name}"));
            return true;
        };
        let Some(obj) = v.as_object() else { return false };
        for key in obj.keys().filter(|k| !i.fields.iter().any(|f| f.name == *k)) {
            self.errors.push(format!("{at}.{key}: the core sends it, interface {name} lacks it"));
        }
        for field in i.fields {
            match obj.get(field.name) {
                Some(x) => {
                    self.seen.insert((name, field.name));
                    self.check(x, field.ty, &format!("{at}.{}", field.name));
                }
                None if !field.optional => self.errors.push(format!("{at}.{}: missing", field.name)),
                None => {}
            }
        }
        true
    }
}

fn parse(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

fn params(json: &str) -> TreeParams {
    TreeParams::from_json(json).unwrap_or_else(|e| panic!("{json}: {e}"))
}

/// The JSON texts of every payload, by interface: trees with and without leaves, session
/// updates (cold, a bark edit, a drag), levels of detail, every error kind, every
/// bark style, a leaf inspection.
fn samples() -> Vec<(&'static str, Value)> {
    let mut out = Vec::new();
    let (leafy, bare) = (params(r#"{"levels": 2}"#), params(r#"{"levels": 2, "leaves": 0}"#));
    let cut = params(
        r#"{"levels": 2, "edits": [{"op": "cut", "at": [0, 30, 0]}, {"op": "cut", "at": [0, 3, 0], "year": 250}]}"#,
    );
    for p in [&leafy, &bare, &cut] {
        let g = sylva_core::generate(p).expect("a tree");
        out.push(("TreeMeta", parse(&g.meta_json())));
        let lods = sylva_core::lod::lods_of(g, &p.mesh).expect("levels");
        out.push(("LodMeta", parse(&lods.meta_json())));
    }
    let mut session = Session::new();
    let clock = sylva_core::clock::NoClock;
    for (p, quality) in [
        (&leafy, Quality::Full),
        (&params(r#"{"levels": 2, "bark_type": 1}"#), Quality::Full),
        (&params(r#"{"levels": 2, "bark_type": 1, "leaves": 10}"#), Quality::Preview { budget_ms: 0.0 }),
    ] {
        let current = session.update(p, quality, &clock, None).expect("an update");
        out.push(("TreeMeta", parse(&current.meta_json())));
    }
    let mut errors = sample_errors();
    errors.push(TreeParams::from_json(r#"{"nope": 1}"#).expect_err("an unknown id"));
    out.extend(errors.iter().map(|e| ("CoreError", parse(&e.to_json()))));
    out.extend(BarkType::ALL.iter().map(|&k| ("BarkStyle", parse(&bark::style_json(k)))));
    let leaf = sylva_core::leaf::generate(&leafy.leaf, leafy.foliage.leaf_petiole).expect("a leaf");
    let opts = sylva_core::leaf::svg::SvgOptions::default();
    out.push(("LeafInspection", parse(&sylva_core::leaf::svg::inspect_json(&leaf, &opts))));
    out
}

#[test]
fn every_payload_has_exactly_the_declared_fields_and_kinds() {
    let mut c = Checker::default();
    for (name, v) in &samples() {
        c.check(v, Ty::Named(name), name);
    }
    assert_eq!(c.errors, Vec::<String>::new(), "the TypeScript table and the core's payloads differ");
    // Both ways: every declared field, optional ones included, is something the core sends.
    let unseen: Vec<String> = INTERFACES
        .iter()
        .flat_map(|i| i.fields.iter().map(move |f| (i.name, f.name)))
        .filter(|k| !c.seen.contains(k))
        .map(|(i, f)| format!("{i}.{f}"))
        .collect();
    assert_eq!(unseen, Vec::<String>::new(), "declared fields no payload has");
}

#[test]
fn the_checker_reports_a_renamed_missing_or_mistyped_field() {
    let mut c = Checker::default();
    let bad = parse(r#"{"max": [1, 2, 3], "minimum": [0, 0, 0]}"#);
    c.check(&bad, Ty::Named("Bounds"), "b");
    c.check(&parse(r#"{"material": "wood", "start": "0", "count": 3}"#), Ty::Named("MeshGroup"), "g");
    assert_eq!(
        c.errors,
        [
            "b.minimum: the core sends it, interface Bounds lacks it",
            "b.min: missing",
            r#"g.material: "wood" is not a MaterialName"#,
            r#"g.start: "0" is not a number"#,
        ]
    );
}

#[test]
fn the_unions_are_the_rust_enums_values() {
    assert_eq!(stages(), ["skeleton", "mesh", "foliage", "leaf", "viewer"]);
    assert_eq!(materials(), ["bark", "leaves", "cut_face", "organ"]);
    assert_eq!(error_kinds(), ["invalid_param", "unknown_param", "budget", "input"]);
    // The registry's stages are the union's.
    let registry = serde_json::to_value(sylva_core::params::registry()).expect("the registry serialises");
    for p in registry.as_array().expect("an array") {
        assert!(stages().iter().any(|s| p["stage"] == s.as_str()), "{}", p["stage"]);
    }
}

#[test]
fn every_named_type_is_declared_once() {
    let mut names: Vec<&str> = UNIONS.iter().map(|u| u.name).chain(INTERFACES.iter().map(|i| i.name)).collect();
    let all = names.len();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), all, "a name declared twice");
    let module = payloads_module();
    for name in names {
        assert!(
            module.contains(&format!("export interface {name} {{"))
                || module.contains(&format!("export type {name} =")),
            "{name}"
        );
    }
}
