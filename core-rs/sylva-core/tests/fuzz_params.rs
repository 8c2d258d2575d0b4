//! Property tests of `TreeParams::from_json` on hostile input: arbitrary text, arbitrary JSON,
//! and objects of registry ids with values of every JSON type (in and out of range, huge,
//! tiny, fractional counts, strings, nulls, nested values). It never panics, accepts exactly
//! the valid objects, and every refusal names the offending field.
//!
//! Cases per property: `PROPTEST_CASES` (default below); `PROPTEST_RNG_SEED` replays a run.

use proptest::prelude::*;
use serde_json::{json, Map, Value};
use sylva_core::params::{registry, ParamKind, ParamSpec};
use sylva_core::{SylvaError, TreeParams};

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig { cases, failure_persistence: None, ..ProptestConfig::default() }
}

fn spec_of(id: &str) -> Option<&'static ParamSpec> {
    registry().iter().find(|s| s.id == id)
}

/// A finite f64 `v` that the field would store (f32 fields round to f32).
fn stored(spec: &ParamSpec, v: f64) -> f64 {
    if spec.kind == ParamKind::Float {
        f64::from(v as f32)
    } else {
        v
    }
}

/// Whether the core must accept `value` for `spec`: any finite number within [min, max] as
/// written in the registry (what the UI and share links send), whole for non-floats.
fn acceptable(spec: &ParamSpec, value: &Value) -> bool {
    let v = match value {
        Value::Number(n) => match n.as_f64() {
            Some(v) => v,
            None => return false,
        },
        Value::Bool(b) => f64::from(u8::from(*b)),
        _ => return false,
    };
    // The registry range, widened only by the f32 rounding of the bounds of float fields.
    let (lo, hi) = if spec.kind == ParamKind::Float {
        (spec.min.min(f64::from(spec.min as f32)), spec.max.max(f64::from(spec.max as f32)))
    } else {
        (spec.min, spec.max)
    };
    v.is_finite() && v >= lo && v <= hi && (spec.kind == ParamKind::Float || v.fract() == 0.0)
}

/// Any JSON value, nested a few levels deep.
fn any_json() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        any::<i64>().prop_map(|i| json!(i)),
        any::<u64>().prop_map(|i| json!(i)),
        any::<f64>().prop_map(|f| json!(f)), // NaN and infinities become null
        ".{0,12}".prop_map(Value::String),
    ];
    leaf.prop_recursive(3, 24, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(Value::Array),
            prop::collection::btree_map(".{0,8}", inner, 0..4).prop_map(|m| Value::Object(m.into_iter().collect())),
        ]
    })
}

/// A value aimed at one parameter: valid ones, boundary ones, and every kind of invalid one.
fn value_for(spec: &'static ParamSpec) -> BoxedStrategy<Value> {
    let (lo, hi) = (spec.min, spec.max);
    let span = hi - lo;
    prop_oneof![
        3 => (0.0..=1.0f64).prop_map(move |t| json!(lo + t * span)),
        3 => (lo as i64..=hi as i64).prop_map(|i| json!(i)),
        2 => prop::sample::select(vec![lo, hi, spec.default, 0.0, -0.0, 1.0, -1.0]).prop_map(|v| json!(v)),
        1 => prop::sample::select(vec![
            lo - 1e-9, hi + 1e-9, lo - span, hi + span, 1e300, -1e300, f64::MIN_POSITIVE, 5e-324,
            hi + 0.5, 0.5, 2.5, u32::MAX as f64 + 1.0, 1e21,
        ])
        .prop_map(|v| json!(v)),
        1 => any::<f64>().prop_map(|v| json!(v)),
        1 => any::<bool>().prop_map(Value::Bool),
        1 => prop::sample::select(vec![
            json!(null), json!("1"), json!(""), json!("<script>alert(1)</script>"), json!([1]),
            json!({"value": 1}), json!("NaN"), json!("Infinity"), json!([]),
        ]),
    ]
    .boxed()
}

/// A valid wire value for one parameter, bounds and defaults included.
fn valid_value_for(spec: &'static ParamSpec) -> BoxedStrategy<Value> {
    let (lo, hi) = (spec.min, spec.max);
    if spec.kind == ParamKind::Float {
        prop_oneof![
            2 => (lo..=hi).prop_map(|v| json!(v)),
            1 => prop::sample::select(vec![lo, hi, spec.default]).prop_map(|v| json!(v)),
        ]
        .boxed()
    } else {
        prop_oneof![
            2 => (lo as u64..=hi as u64).prop_map(|i| json!(i)),
            1 => prop::sample::select(vec![lo, hi, spec.default]).prop_map(|v| json!(v)),
        ]
        .boxed()
    }
}

/// An object of valid values for a few parameters.
fn valid_object() -> impl Strategy<Value = Vec<(String, Value)>> {
    let ids: Vec<&'static ParamSpec> = registry().iter().collect();
    let entry = prop::sample::select(ids).prop_flat_map(|s| valid_value_for(s).prop_map(move |v| (s.id.clone(), v)));
    prop::collection::vec(entry, 0..6)
}

/// An object of mostly registry ids (plus the odd unknown key) with hostile values.
fn params_object() -> impl Strategy<Value = Vec<(String, Value)>> {
    let ids: Vec<&'static ParamSpec> = registry().iter().collect();
    let entry = prop_oneof![
        12 => prop::sample::select(ids).prop_flat_map(|s| value_for(s).prop_map(move |v| (s.id.clone(), v))),
        1 => (prop::sample::select(vec!["", "l9_length", "l0_down_angle", "__proto__", "Seed", "seed "]), any_json())
            .prop_map(|(k, v)| (k.to_string(), v)),
        1 => (".{0,80}", any_json()),
    ];
    prop::collection::vec(entry, 0..12)
}

/// Checks the contract on one JSON text that holds an object (`entries`, last duplicate wins).
fn check_object(entries: &[(String, Value)]) -> Result<(), TestCaseError> {
    let mut map = Map::new();
    for (k, v) in entries {
        map.insert(k.clone(), v.clone());
    }
    let text = Value::Object(map.clone()).to_string();
    let result = TreeParams::from_json(&text);
    let all_valid = map.iter().all(|(k, v)| spec_of(k).is_some_and(|s| acceptable(s, v)));
    match result {
        Ok(p) => {
            prop_assert!(all_valid, "accepted an invalid object: {text}");
            // What is accepted is what generation validates again: no field may fail there.
            prop_assert_eq!(p.validate(), Ok(()), "accepted {} but validate() refuses it", text);
            for (k, v) in &map {
                let spec = spec_of(k).expect("known id");
                let want = match v {
                    Value::Bool(b) => f64::from(u8::from(*b)),
                    _ => v.as_f64().expect("number"),
                };
                prop_assert_eq!(p.get(k), Some(stored(spec, want)), "{} in {}", k, text);
            }
            // The non-default values are enough to rebuild the same params.
            let rebuilt = TreeParams::from_values(p.non_defaults());
            prop_assert_eq!(rebuilt.as_ref(), Ok(&p));
        }
        Err(e) => {
            prop_assert!(!all_valid, "refused a valid object {text}: {e}");
            match &e {
                SylvaError::InvalidParam { param, message } => {
                    let spec = spec_of(param);
                    prop_assert!(spec.is_some(), "error names an unknown id {param:?}");
                    let value = map.get(param);
                    prop_assert!(value.is_some(), "error names {param:?}, which is not in {text}");
                    prop_assert!(
                        !acceptable(spec.expect("checked"), value.expect("checked")),
                        "error names {param:?}, whose value is valid: {text}"
                    );
                    prop_assert!(message.starts_with(param.as_str()), "message does not name {param}: {message}");
                }
                SylvaError::UnknownParam { param, message } => {
                    prop_assert!(
                        map.keys().any(|k| spec_of(k).is_none() && k.chars().take(64).collect::<String>() == *param),
                        "unknown-param error for {param:?}, not an unknown key of {text}"
                    );
                    prop_assert!(message.contains(param.as_str()));
                }
                other => prop_assert!(false, "an object gave {other:?}"),
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(2000))]

    #[test]
    fn arbitrary_text_never_panics(text in ".{0,200}") {
        let r = TreeParams::from_json(&text);
        if let Err(e) = r {
            prop_assert!(!e.message().is_empty());
        }
    }

    #[test]
    fn json_like_text_never_panics(text in r#"[{}\[\]":,0-9a-z_.eE+\- ]{0,80}"#) {
        if let Err(e) = TreeParams::from_json(&text) {
            prop_assert!(!e.message().is_empty());
        }
    }

    #[test]
    fn arbitrary_json_never_panics_and_objects_follow_the_contract(value in any_json()) {
        let text = value.to_string();
        match &value {
            Value::Object(map) => {
                let entries: Vec<(String, Value)> = map.iter().map(|(k, v)| (k.clone(), v.clone())).collect();
                check_object(&entries)?;
            }
            _ => {
                let e = TreeParams::from_json(&text);
                prop_assert!(matches!(e, Err(SylvaError::Input { .. })), "{text} gave {e:?}");
            }
        }
    }

    #[test]
    fn valid_values_are_accepted_and_pass_validation(entries in valid_object()) {
        check_object(&entries)?;
    }

    #[test]
    fn hostile_values_for_registry_ids_are_refused_naming_the_field(entries in params_object()) {
        check_object(&entries)?;
    }
}

/// Every parameter at both ends of its registry range, as the UI sliders and share links send them.
#[test]
fn regression_f32_params_accept_their_registry_bounds() {
    // `ratio` = 0.2 was stored as the f32 0.2000000030 and then refused by validate() ("ratio is
    // 0.20000000298023224: allowed range is 0.001 to 0.2"); `prune_width` = 0.01 the same at its min.
    for spec in registry() {
        for v in [spec.min, spec.max] {
            let p = TreeParams::from_values([(spec.id.as_str(), v)])
                .unwrap_or_else(|e| panic!("{} = {v} refused: {e}", spec.id));
            p.validate().unwrap_or_else(|e| panic!("{} = {v} accepted, then refused: {e}", spec.id));
            // ...and what is stored there can be set again (`non_defaults` -> `from_values`).
            let again = TreeParams::from_values(p.non_defaults())
                .unwrap_or_else(|e| panic!("{} = {v} stored, then refused as a value: {e}", spec.id));
            assert_eq!(again, p);
        }
    }
    let p = TreeParams::from_json(r#"{"ratio": 0.2, "prune_width": 0.01}"#).unwrap();
    assert_eq!(p.validate(), Ok(()));
    // Just past the bound is still refused, naming the field.
    let e = TreeParams::from_json(r#"{"ratio": 0.2000001}"#).unwrap_err();
    assert!(e.message().starts_with("ratio (Radius Ratio) is 0.2000001"), "{e}");
    let e = TreeParams::from_json(r#"{"prune_width": 0.0099999}"#).unwrap_err();
    assert!(e.message().starts_with("prune_width"), "{e}");
}
