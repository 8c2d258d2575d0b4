//! The edit list's JSON: round trip, and a message naming the edit and field for every hostile
//! input (counts, types, NaN and out-of-range values, crossing outlines, cuts on the ground).

use super::*;

const ISSUE_EXAMPLE: &str = r#"{"version": 1, "edits": [
  {"op": "paint", "points": [[1.2, 6.0, 0.3], [1.9, 6.4, 0.2]], "radius": 0.6, "density": 400, "segment": 0.25, "kill": 0.4},
  {"op": "crown", "outline": [[0, 2], [2.5, 4], [2, 8], [0, 9]]},
  {"op": "cut", "at": [0.8, 4.1, -0.2]},
  {"op": "bend", "at": [2.0, 5.5, 0.0], "to": [2.3, 4.6, 0.0]}
]}"#;

fn err(json: &str) -> SylvaError {
    from_json(json).expect_err(json)
}

fn one(edit: &str) -> SylvaError {
    err(&format!(r#"{{"version": 1, "edits": [{edit}]}}"#))
}

#[test]
fn the_document_round_trips() {
    let edits = from_json(ISSUE_EXAMPLE).unwrap();
    assert_eq!(edits.iter().map(Edit::op).collect::<Vec<_>>(), ["paint", "crown", "cut", "bend"]);
    assert_eq!(from_json(&to_json(&edits)).unwrap(), edits);
    assert_eq!(from_json_value(&to_json_value(&edits)).unwrap(), edits);
    // Through the parameters' JSON too, and into the stage struct's equality.
    let value: serde_json::Value = serde_json::from_str(ISSUE_EXAMPLE).unwrap();
    let json = format!(r#"{{"seed": 3, "edits": {}}}"#, value["edits"]);
    let p = crate::TreeParams::from_json(&json).unwrap();
    assert_eq!(p.skeleton.edits, edits);
    assert_ne!(p.skeleton, crate::TreeParams::from_json(r#"{"seed": 3}"#).unwrap().skeleton);
    p.validate().unwrap();
    // A bare array is the same list.
    assert_eq!(from_json(&value["edits"].to_string()).unwrap(), edits);
}

#[test]
fn hostile_edits_get_messages_naming_the_edit_and_field() {
    let paint = |radius: &str, extra: &str| {
        format!(
            r#"{{"op": "paint", "points": [[1, 6, 0]], "radius": {radius}, "density": 400, "segment": 0.25, "kill": 0.4{extra}}}"#
        )
    };
    let cut = r#"{"op": "cut", "at": [1, 5, 0]}"#;
    let cases: Vec<(String, &str)> = vec![
        (one(&paint("0", "")).to_string(), "edits[0].radius is 0: allowed range is 0.02 to 10 m"),
        (one(&paint("1000", "")).to_string(), "edits[0].radius is 1000: allowed range is 0.02 to 10 m"),
        (one(&paint("1e400", "")).to_string(), "the edit list must be JSON"),
        (one(&paint("1e39", "")).to_string(), "edits[0].radius is inf: allowed range is 0.02 to 10 m"),
        (one(&paint("\"big\"", "")).to_string(), "edits[0].radius must be a number, got \"big\""),
        (one(&paint("1", r#", "colour": 1"#)).to_string(), "edits[0].colour is not a field of a paint edit"),
        (
            one(r#"{"op": "paint", "points": [[1, 6, 0]], "radius": 1, "density": 400, "segment": 0.5, "kill": 0.2}"#)
                .to_string(),
            "edits[0].kill is 0.2: it must be at least the segment length 0.5 m",
        ),
        (
            one(r#"{"op": "paint", "points": [[1, 6, 0]], "radius": 1, "density": 0, "segment": 0.25, "kill": 0.4}"#)
                .to_string(),
            "edits[0].density is 0: allowed range is 1 to 5000",
        ),
        (
            one(r#"{"op": "paint", "points": [[1, 6]], "radius": 1, "density": 4, "segment": 0.25, "kill": 0.4}"#)
                .to_string(),
            "edits[0].points[0] must be an array of 3 numbers",
        ),
        (
            one(r#"{"op": "paint", "points": [], "radius": 1, "density": 4, "segment": 0.25, "kill": 0.4}"#)
                .to_string(),
            "edits[0].points has 0 points: at least 1 are needed",
        ),
        (one(r#"{"op": "prune", "at": [1, 5, 0]}"#).to_string(), "edits[0].op is 'prune': it must be"),
        (one(r#"{"op": "cut", "at": [1, 0.05, 0]}"#).to_string(), "edits[0].at is on the ground"),
        (
            one(r#"{"op": "cut", "at": [250, 5, 0]}"#).to_string(),
            "edits[0].at[0] is 250: allowed range is -200 to 200 m",
        ),
        (one(r#"{"op": "cut"}"#).to_string(), "edits[0].at is missing"),
        (
            one(r#"{"op": "bend", "at": [1, 5, 0], "to": [1, 5, -1e30]}"#).to_string(),
            "edits[0].to[2] is -1000000000000000000000000000000",
        ),
        (
            one(r#"{"op": "crown", "outline": [[0, 2], [2, 4]]}"#).to_string(),
            "edits[0].outline has 2 points: at least 3 are needed",
        ),
        (
            one(r#"{"op": "crown", "outline": [[0, 2], [2, 8], [2, 2], [0, 8]]}"#).to_string(),
            "edits[0].outline crosses itself",
        ),
        (
            one(r#"{"op": "crown", "outline": [[-1, 2], [2, 8], [0, 8]]}"#).to_string(),
            "edits[0].outline[0][0] is -1: allowed range is 0 to 200 m",
        ),
        (one("3").to_string(), "edits[0] must be an object"),
        (err(r#"{"version": 2, "edits": []}"#).to_string(), "version must be 1, got 2"),
        (err(r#"{"version": 1, "edits": [], "more": 1}"#).to_string(), "'more' is not a field of the edit list"),
        (err(r#"{"version": 1, "edits": {}}"#).to_string(), "edits must be an array of edits"),
        (
            err(&format!(r#"{{"version": 1, "edits": [{}]}}"#, vec![cut; MAX_EDITS + 1].join(","))).to_string(),
            "edits has 1001 edits: at most 1000 are allowed",
        ),
    ];
    for (got, want) in &cases {
        assert!(got.starts_with(want), "{got:?} does not start with {want:?}");
    }
    // Error fields name the edit: `param` is the path.
    assert_eq!(
        one(&paint("0", "")),
        bad("edits[0].radius", "edits[0].radius is 0: allowed range is 0.02 to 10 m".into())
    );
    // Millions of points stop at the stroke's limit before they are read.
    let many = vec!["[1, 6, 0]"; MAX_STROKE_POINTS + 1].join(",");
    let e = one(&format!(
        r#"{{"op": "paint", "points": [{many}], "radius": 1, "density": 4, "segment": 0.25, "kill": 0.4}}"#
    ));
    assert_eq!(e.message(), "edits[0].points has 4097 points: at most 4096 are allowed");
    // The total over all strokes has its own limit.
    let full = vec!["[1, 6, 0]"; MAX_STROKE_POINTS].join(",");
    let stroke =
        format!(r#"{{"op": "paint", "points": [{full}], "radius": 1, "density": 4, "segment": 0.25, "kill": 0.4}}"#);
    let e = err(&format!(r#"{{"version": 1, "edits": [{}]}}"#, vec![stroke.as_str(); 17].join(",")));
    assert!(e.message().starts_with("the edits hold more than 65536 points in all (at edits[16])"), "{e}");
    // The same checks hold for a list built in code.
    let mut p = crate::TreeParams::default();
    p.skeleton.edits = vec![Edit::Cut(Cut { at: Vec3::new(f32::NAN, 5.0, 0.0), year: None })];
    assert_eq!(p.validate().unwrap_err().message(), "edits[0].at[0] is NaN: allowed range is -200 to 200 m");
}

#[test]
fn outlines_cross_only_when_they_do() {
    use super::validate::first_crossing;
    let v = |p: &[[f32; 2]]| p.iter().map(|&q| Vec2::from_array(q)).collect::<Vec<_>>();
    assert_eq!(first_crossing(&v(&[[0.0, 2.0], [2.5, 4.0], [2.0, 8.0], [0.0, 9.0]])), None);
    assert_eq!(first_crossing(&v(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])), None);
    assert!(first_crossing(&v(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]])).is_some());
    // Folding back along the previous edge.
    assert!(first_crossing(&v(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 3.0]])).is_some());
}

/// Regression: a link or file with a million brush points (11 MB of JSON) was parsed whole before
/// the point count refused it: 9.7 s in wasm. Text past 4 MiB is refused before it is parsed.
#[test]
fn json_past_four_mebibytes_is_refused_before_it_is_parsed() {
    let points = vec!["[1.25,5.5,0.75]"; 300_000].join(",");
    let list =
        format!(r#"[{{"op":"paint","radius":0.6,"density":400,"segment":0.25,"kill":0.4,"points":[{points}]}}]"#);
    assert!(list.len() > super::MAX_JSON_BYTES);
    let e = super::from_json(&list).unwrap_err();
    assert!(
        matches!(&e, SylvaError::InvalidParam { param, message } if param == "edits" && message.contains("more than 4 MB")),
        "{e:?}"
    );
    let e = crate::TreeParams::from_json(&format!(r#"{{"edits":{list}}}"#)).unwrap_err();
    assert!(
        matches!(&e, SylvaError::InvalidParam { param, message } if param == "edits" && message.contains("parameters")),
        "{e:?}"
    );
    // The longest valid list, every point at full precision, still fits.
    let point = "[-123.45678901234567,67.891234567891234,-12.345678901234567]";
    let stroke = format!(
        r#"{{"op":"paint","radius":0.6,"density":400,"segment":0.25,"kill":0.4,"points":[{}]}}"#,
        vec![point; super::MAX_STROKE_POINTS].join(",")
    );
    let full = format!("[{}]", vec![stroke; super::MAX_POINTS / super::MAX_STROKE_POINTS].join(","));
    assert!(full.len() < super::MAX_JSON_BYTES, "{} bytes", full.len());
}
