//! Tests of the registry, validation and the wire values.

use super::*;

#[test]
fn registry_ids_unique_defaults_valid_groups_known() {
    let reg = registry();
    let mut ids: Vec<&str> = reg.iter().map(|s| s.id.as_str()).collect();
    ids.sort_unstable();
    let n = ids.len();
    ids.dedup();
    assert_eq!(ids.len(), n, "duplicate ids");
    for s in reg {
        s.check(s.default).unwrap_or_else(|e| panic!("default of {} invalid: {e}", s.id));
        assert!(GROUPS.contains(&s.group.as_str()), "{} has unknown group {}", s.id, s.group);
        assert!(s.min < s.max && s.step > 0.0, "{}: bad range", s.id);
        assert!(!s.description.is_empty());
    }
    TreeParams::default().validate().unwrap();
    assert!(TreeParams::default().non_defaults().is_empty());
}

#[test]
fn get_set_round_trip_every_param() {
    for s in registry() {
        let mut p = TreeParams::default();
        p.set(&s.id, s.max).unwrap();
        assert_eq!(
            p.get(&s.id),
            Some(if s.kind == ParamKind::Float { (s.max as f32) as f64 } else { s.max }),
            "{}",
            s.id
        );
    }
}

#[test]
fn out_of_range_names_field_and_range() {
    let e = TreeParams::from_values([("l1_length", 3.0)]).unwrap_err();
    assert_eq!(
        e,
        SylvaError::InvalidParam {
            param: "l1_length".into(),
            message: "l1_length (Length) is 3: allowed range is 0 to 2".into()
        }
    );
    let e = TreeParams::from_values([("scale", -1.0)]).unwrap_err();
    assert_eq!(e.message(), "scale (Scale) is -1: allowed range is 0.1 to 100 m");
    let e = TreeParams::from_values([("l2_branches", 2.5)]).unwrap_err();
    assert!(e.message().contains("must be a whole number"), "{e}");
    let e = TreeParams::from_values([("scale", f64::NAN)]).unwrap_err();
    assert!(e.message().contains("finite"), "{e}");
    let e = TreeParams::from_values([("shape", 9.0)]).unwrap_err();
    assert!(e.message().contains("Conical, Spherical"), "{e}");
}

#[test]
fn unknown_and_malformed_json() {
    assert!(matches!(TreeParams::from_json(r#"{"nope": 1}"#), Err(SylvaError::UnknownParam { .. })));
    assert!(matches!(TreeParams::from_json(r#"[1,2]"#), Err(SylvaError::Input { .. })));
    let e = TreeParams::from_json(r#"{"scale": "big"}"#).unwrap_err();
    assert_eq!(e.message(), r#"scale (Scale) must be a number, got "big""#);
    let p = TreeParams::from_json(r#"{"scale": 20, "seed": 9}"#).unwrap();
    assert_eq!((p.skeleton.scale, p.skeleton.seed), (20.0, 9));
    // The trunk has no down angle: l0_down_angle is not a parameter.
    assert!(matches!(TreeParams::from_json(r#"{"l0_down_angle": 1}"#), Err(SylvaError::UnknownParam { .. })));
}

#[test]
fn direct_struct_edits_are_validated() {
    let mut p = TreeParams::default();
    p.skeleton.level[2].curve_res = 0;
    assert!(p.validate().unwrap_err().message().starts_with("l2_curve_res"));
}
