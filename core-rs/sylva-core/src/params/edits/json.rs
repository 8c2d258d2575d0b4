//! The edit list's JSON: the `"edits"` array of the parameters' JSON, and the document
//! `{"version": 1, "edits": [...]}` the CLI's `--edits FILE` and the app's export use. Strict:
//! unknown ops and fields, wrong types and counts past the limits are errors naming the edit and
//! field; the parsed list is then [`validate`](fn@super::validate)d.

use super::validate::{check_count, check_points, validate};
use super::{
    bad, too_long, Bend, Crown, Cut, Edit, Paint, MAX_JSON_BYTES, MAX_OUTLINE_POINTS, MAX_STROKE_POINTS, VERSION,
};
use crate::error::SylvaError;
use glam::{Vec2, Vec3};
use serde_json::{json, Map, Value};

/// Parse the JSON value of `"edits"` (an array of edits) and validate it.
pub fn from_json_value(value: &Value) -> Result<Vec<Edit>, SylvaError> {
    let items = value.as_array().ok_or_else(|| bad("edits", "edits must be an array of edits".into()))?;
    check_count(items.len())?;
    let edits = items.iter().enumerate().map(|(i, item)| edit(i, item)).collect::<Result<Vec<_>, _>>()?;
    validate(&edits)?;
    Ok(edits)
}

/// Parse an edit list document `{"version": 1, "edits": [...]}` (the CLI's `--edits FILE.json`,
/// the app's export); a bare array of edits is accepted too.
pub fn from_json(json: &str) -> Result<Vec<Edit>, SylvaError> {
    if json.len() > MAX_JSON_BYTES {
        return Err(too_long("the edit list", json.len()));
    }
    let value: Value = serde_json::from_str(json).map_err(|e| SylvaError::Input {
        message: format!("the edit list must be JSON like {{\"version\": 1, \"edits\": [...]}}: {e}"),
    })?;
    let Some(doc) = value.as_object() else {
        return from_json_value(&value);
    };
    for key in doc.keys() {
        if key != "version" && key != "edits" {
            let shown: String = key.chars().take(32).collect();
            return Err(bad(shown.clone(), format!("'{shown}' is not a field of the edit list (version, edits)")));
        }
    }
    match doc.get("version").and_then(Value::as_u64) {
        Some(v) if v == u64::from(VERSION) => {}
        _ => {
            return Err(bad(
                "version",
                format!("version must be {VERSION}, got {}", doc.get("version").unwrap_or(&Value::Null)),
            ))
        }
    }
    from_json_value(doc.get("edits").unwrap_or(&Value::Null))
}

/// The edits as the JSON array [`from_json_value`] reads.
pub fn to_json_value(edits: &[Edit]) -> Value {
    let v3 = |q: Vec3| q.to_array();
    Value::Array(
        edits
            .iter()
            .map(|e| match e {
                Edit::Paint(p) => json!({
                    "op": "paint", "points": p.points.iter().map(|&q| v3(q)).collect::<Vec<_>>(),
                    "radius": p.radius, "density": p.density, "segment": p.segment, "kill": p.kill,
                }),
                Edit::Crown(c) => {
                    json!({"op": "crown", "outline": c.outline.iter().map(|q| q.to_array()).collect::<Vec<_>>()})
                }
                Edit::Cut(c) => match c.year {
                    Some(year) => json!({"op": "cut", "at": v3(c.at), "year": year}),
                    None => json!({"op": "cut", "at": v3(c.at)}),
                },
                Edit::Bend(b) => json!({"op": "bend", "at": v3(b.at), "to": v3(b.to)}),
            })
            .collect(),
    )
}

/// The edit list document `{"version": 1, "edits": [...]}` that [`from_json`] reads.
pub fn to_json(edits: &[Edit]) -> String {
    json!({"version": VERSION, "edits": to_json_value(edits)}).to_string()
}

/// The fields each op takes.
fn fields(op: &str) -> Option<&'static [&'static str]> {
    Some(match op {
        "paint" => &["op", "points", "radius", "density", "segment", "kill"],
        "crown" => &["op", "outline"],
        "cut" => &["op", "at", "year"],
        "bend" => &["op", "at", "to"],
        _ => return None,
    })
}

/// One edit `edits[i]`.
fn edit(i: usize, item: &Value) -> Result<Edit, SylvaError> {
    let f = |name: &str| format!("edits[{i}].{name}");
    let o = item.as_object().ok_or_else(|| bad(format!("edits[{i}]"), format!("edits[{i}] must be an object")))?;
    let op = o.get("op").and_then(Value::as_str).unwrap_or("");
    let allowed = fields(op).ok_or_else(|| {
        let shown: String = op.chars().take(32).collect();
        bad(f("op"), format!("{} is '{shown}': it must be \"paint\", \"crown\", \"cut\" or \"bend\"", f("op")))
    })?;
    if let Some(key) = o.keys().find(|k| !allowed.contains(&k.as_str())) {
        let shown: String = key.chars().take(32).collect();
        return Err(bad(f(&shown), format!("{} is not a field of a {op} edit ({})", f(&shown), allowed.join(", "))));
    }
    Ok(match op {
        "paint" => {
            let items = array(o, "points", &f("points"))?;
            check_points(&f("points"), items.len(), MAX_STROKE_POINTS, 1)?;
            let points = items
                .iter()
                .enumerate()
                .map(|(k, v)| vec3(v, &format!("{}[{k}]", f("points"))))
                .collect::<Result<_, _>>()?;
            Edit::Paint(Paint {
                points,
                radius: scalar(o, "radius", &f("radius"))?,
                density: scalar(o, "density", &f("density"))?,
                segment: scalar(o, "segment", &f("segment"))?,
                kill: scalar(o, "kill", &f("kill"))?,
            })
        }
        "crown" => {
            let items = array(o, "outline", &f("outline"))?;
            check_points(&f("outline"), items.len(), MAX_OUTLINE_POINTS, 3)?;
            let outline = items
                .iter()
                .enumerate()
                .map(|(k, v)| vec2(v, &format!("{}[{k}]", f("outline"))))
                .collect::<Result<_, _>>()?;
            Edit::Crown(Crown { outline })
        }
        "cut" => Edit::Cut(Cut {
            at: vec3(required(o, "at", &f("at"))?, &f("at"))?,
            year: o.get("year").map(|v| number(v, &f("year"))).transpose()?,
        }),
        _ => Edit::Bend(Bend {
            at: vec3(required(o, "at", &f("at"))?, &f("at"))?,
            to: vec3(required(o, "to", &f("to"))?, &f("to"))?,
        }),
    })
}

fn required<'a>(o: &'a Map<String, Value>, key: &str, field: &str) -> Result<&'a Value, SylvaError> {
    o.get(key).ok_or_else(|| bad(field, format!("{field} is missing")))
}

fn array<'a>(o: &'a Map<String, Value>, key: &str, field: &str) -> Result<&'a Vec<Value>, SylvaError> {
    required(o, key, field)?.as_array().ok_or_else(|| bad(field, format!("{field} must be an array of points")))
}

fn number(v: &Value, field: &str) -> Result<f32, SylvaError> {
    v.as_f64().map(|x| x as f32).ok_or_else(|| bad(field, format!("{field} must be a number, got {}", short(v))))
}

fn scalar(o: &Map<String, Value>, key: &str, field: &str) -> Result<f32, SylvaError> {
    number(required(o, key, field)?, field)
}

fn coords<const N: usize>(v: &Value, field: &str) -> Result<[f32; N], SylvaError> {
    let a = v
        .as_array()
        .filter(|a| a.len() == N)
        .ok_or_else(|| bad(field, format!("{field} must be an array of {N} numbers, got {}", short(v))))?;
    let mut out = [0.0; N];
    for (k, x) in a.iter().enumerate() {
        out[k] = number(x, &format!("{field}[{k}]"))?;
    }
    Ok(out)
}

fn vec3(v: &Value, field: &str) -> Result<Vec3, SylvaError> {
    coords::<3>(v, field).map(Vec3::from_array)
}

fn vec2(v: &Value, field: &str) -> Result<Vec2, SylvaError> {
    coords::<2>(v, field).map(Vec2::from_array)
}

/// A JSON value for a message, cut to 40 characters.
fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s
    }
}
