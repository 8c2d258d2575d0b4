//! User volume primitives (the SCA add-on's groups as structured input): spheres, boxes and
//! upright cylinders in the **crown** group (their union holds the markers when Crown Volume is
//! *Primitives*), the **shadow** group (no markers) or the **exclusion** group (no markers, and
//! branches stop at their surface). They travel beside the scalar parameters as
//! `SkeletonParams::volumes`, in JSON as `"volumes": [{"kind": "sphere", "group": "crown",
//! "centre": [x, y, z], "radius": r}, {"kind": "box", ..., "size": [w, h, d]},
//! {"kind": "cylinder", ..., "radius": r, "height": h}]`.

use crate::error::SylvaError;
use glam::Vec3;

/// Most primitives one tree may carry.
pub const MAX_VOLUMES: usize = 32;
/// Largest distance of a primitive's centre from the origin along any axis (m).
pub const MAX_CENTRE: f32 = 100.0;
/// Allowed radius, height and box extent (m).
pub const SIZE_RANGE: (f32, f32) = (0.05, 100.0);

/// What a primitive does to growth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VolumeGroup {
    /// Part of the crown: markers fill the union of the crown group.
    Crown,
    /// No markers inside.
    Shadow,
    /// No markers inside, and branches stop at its surface.
    Exclusion,
}

impl VolumeGroup {
    /// Name on the wire.
    pub fn name(self) -> &'static str {
        match self {
            VolumeGroup::Crown => "crown",
            VolumeGroup::Shadow => "shadow",
            VolumeGroup::Exclusion => "exclusion",
        }
    }
}

/// One user primitive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VolumePrimitive {
    /// Which group it belongs to.
    pub group: VolumeGroup,
    /// Its shape and placement.
    pub shape: Primitive,
}

/// A user primitive's shape (the SCA add-on's volume objects), centred on `centre`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive {
    /// A ball.
    Sphere {
        /// Centre (m).
        centre: Vec3,
        /// Radius (m).
        radius: f32,
    },
    /// An axis-aligned box of full extents `size`.
    Box {
        /// Centre (m).
        centre: Vec3,
        /// Full width, height and depth (m).
        size: Vec3,
    },
    /// An upright cylinder of `radius` and full `height`.
    Cylinder {
        /// Centre (m; the axis runs from `centre.y - height / 2` to `centre.y + height / 2`).
        centre: Vec3,
        /// Radius (m).
        radius: f32,
        /// Full height (m).
        height: f32,
    },
}

fn bad(field: String, message: String) -> SylvaError {
    SylvaError::InvalidParam { param: field, message }
}

fn check_size(field: String, v: f32) -> Result<(), SylvaError> {
    let (lo, hi) = SIZE_RANGE;
    if !v.is_finite() || !(lo..=hi).contains(&v) {
        return Err(bad(field.clone(), format!("{field} is {v}: allowed range is {lo} to {hi} m")));
    }
    Ok(())
}

/// Check a list of primitives: at most [`MAX_VOLUMES`], finite centres within
/// ±[`MAX_CENTRE`], sizes in [`SIZE_RANGE`]. Errors name the field, e.g. `volumes[2].radius`.
pub fn validate(volumes: &[VolumePrimitive]) -> Result<(), SylvaError> {
    if volumes.len() > MAX_VOLUMES {
        return Err(bad(
            "volumes".into(),
            format!("volumes has {} primitives: at most {MAX_VOLUMES} are allowed", volumes.len()),
        ));
    }
    for (i, v) in volumes.iter().enumerate() {
        let f = |name: &str| format!("volumes[{i}].{name}");
        let centre = match v.shape {
            Primitive::Sphere { centre, .. } | Primitive::Box { centre, .. } | Primitive::Cylinder { centre, .. } => {
                centre
            }
        };
        for (axis, c) in ["x", "y", "z"].iter().zip(centre.to_array()) {
            if !c.is_finite() || c.abs() > MAX_CENTRE {
                let field = format!("{}.{axis}", f("centre"));
                return Err(bad(
                    field.clone(),
                    format!("{field} is {c}: allowed range is -{MAX_CENTRE} to {MAX_CENTRE} m"),
                ));
            }
        }
        match v.shape {
            Primitive::Sphere { radius, .. } => check_size(f("radius"), radius)?,
            Primitive::Box { size, .. } => {
                for (k, s) in size.to_array().into_iter().enumerate() {
                    check_size(format!("{}[{k}]", f("size")), s)?;
                }
            }
            Primitive::Cylinder { radius, height, .. } => {
                check_size(f("radius"), radius)?;
                check_size(f("height"), height)?;
            }
        }
    }
    Ok(())
}

fn number(v: &serde_json::Value, field: &str) -> Result<f32, SylvaError> {
    match v.as_f64() {
        Some(x) => Ok(x as f32),
        None => Err(bad(field.into(), format!("{field} must be a number, got {v}"))),
    }
}

fn vec3(v: Option<&serde_json::Value>, field: &str) -> Result<Vec3, SylvaError> {
    let arr = v
        .and_then(|v| v.as_array())
        .filter(|a| a.len() == 3)
        .ok_or_else(|| bad(field.into(), format!("{field} must be an array of 3 numbers")))?;
    Ok(Vec3::new(
        number(&arr[0], &format!("{field}[0]"))?,
        number(&arr[1], &format!("{field}[1]"))?,
        number(&arr[2], &format!("{field}[2]"))?,
    ))
}

fn scalar(o: &serde_json::Map<String, serde_json::Value>, key: &str, field: &str) -> Result<f32, SylvaError> {
    let v = o.get(key).ok_or_else(|| bad(field.into(), format!("{field} is missing")))?;
    number(v, field)
}

/// Parse the JSON value of `"volumes"` (an array of objects) and validate it.
pub fn from_json_value(value: &serde_json::Value) -> Result<Vec<VolumePrimitive>, SylvaError> {
    let items =
        value.as_array().ok_or_else(|| bad("volumes".into(), "volumes must be an array of primitives".into()))?;
    if items.len() > MAX_VOLUMES {
        return Err(bad(
            "volumes".into(),
            format!("volumes has {} primitives: at most {MAX_VOLUMES} are allowed", items.len()),
        ));
    }
    let mut out = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let f = |name: &str| format!("volumes[{i}].{name}");
        let o =
            item.as_object().ok_or_else(|| bad(format!("volumes[{i}]"), format!("volumes[{i}] must be an object")))?;
        for key in o.keys() {
            if !["kind", "group", "centre", "radius", "size", "height"].contains(&key.as_str()) {
                let shown: String = key.chars().take(32).collect();
                return Err(bad(
                    f(&shown),
                    format!("{} is not a primitive field (kind, group, centre, radius, size, height)", f(&shown)),
                ));
            }
        }
        let group = match o.get("group").and_then(|g| g.as_str()) {
            Some("crown") => VolumeGroup::Crown,
            Some("shadow") => VolumeGroup::Shadow,
            Some("exclusion") => VolumeGroup::Exclusion,
            _ => return Err(bad(f("group"), format!("{} must be \"crown\", \"shadow\" or \"exclusion\"", f("group")))),
        };
        let centre = vec3(o.get("centre"), &f("centre"))?;
        let shape = match o.get("kind").and_then(|k| k.as_str()) {
            Some("sphere") => Primitive::Sphere { centre, radius: scalar(o, "radius", &f("radius"))? },
            Some("box") => Primitive::Box { centre, size: vec3(o.get("size"), &f("size"))? },
            Some("cylinder") => Primitive::Cylinder {
                centre,
                radius: scalar(o, "radius", &f("radius"))?,
                height: scalar(o, "height", &f("height"))?,
            },
            _ => return Err(bad(f("kind"), format!("{} must be \"sphere\", \"box\" or \"cylinder\"", f("kind")))),
        };
        out.push(VolumePrimitive { group, shape });
    }
    validate(&out)?;
    Ok(out)
}

/// Parse a JSON text holding an array of primitives (the CLI's `--volumes FILE.json`).
pub fn from_json(json: &str) -> Result<Vec<VolumePrimitive>, SylvaError> {
    let value: serde_json::Value = serde_json::from_str(json)
        .map_err(|e| SylvaError::Input { message: format!("volumes must be a JSON array of primitives: {e}") })?;
    from_json_value(&value)
}

/// The primitives as the JSON array [`from_json_value`] reads.
pub fn to_json_value(volumes: &[VolumePrimitive]) -> serde_json::Value {
    let items: Vec<serde_json::Value> = volumes
        .iter()
        .map(|v| match v.shape {
            Primitive::Sphere { centre, radius } => serde_json::json!({
                "kind": "sphere", "group": v.group.name(), "centre": centre.to_array(), "radius": radius,
            }),
            Primitive::Box { centre, size } => serde_json::json!({
                "kind": "box", "group": v.group.name(), "centre": centre.to_array(), "size": size.to_array(),
            }),
            Primitive::Cylinder { centre, radius, height } => serde_json::json!({
                "kind": "cylinder", "group": v.group.name(), "centre": centre.to_array(), "radius": radius, "height": height,
            }),
        })
        .collect();
    serde_json::Value::Array(items)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_round_trip_and_messages() {
        let json = r#"[{"kind":"sphere","group":"crown","centre":[0,5,0],"radius":3},
            {"kind":"box","group":"shadow","centre":[1,2,3],"size":[1,2,3]},
            {"kind":"cylinder","group":"exclusion","centre":[-2,1,0],"radius":0.5,"height":4}]"#;
        let v = from_json(json).unwrap();
        assert_eq!(v.len(), 3);
        assert_eq!(from_json_value(&to_json_value(&v)).unwrap(), v);
        let e = |j: &str| from_json(j).unwrap_err();
        let err = e(r#"[{"kind":"sphere","group":"crown","centre":[0,5,0],"radius":3},
            {"kind":"sphere","group":"crown","centre":[0,5,0],"radius":3},
            {"kind":"cylinder","group":"crown","centre":[0,5,0],"radius":-1,"height":2}]"#);
        assert_eq!(
            err,
            SylvaError::InvalidParam {
                param: "volumes[2].radius".into(),
                message: "volumes[2].radius is -1: allowed range is 0.05 to 100 m".into()
            }
        );
        assert!(e(r#"[{"kind":"cone","group":"crown","centre":[0,0,0]}]"#).message().contains("volumes[0].kind"));
        assert!(e(r#"[{"kind":"box","group":"sun","centre":[0,0,0]}]"#).message().contains("volumes[0].group"));
        assert!(e(r#"[{"kind":"box","group":"crown","centre":[0,0]}]"#).message().contains("volumes[0].centre"));
        assert!(e(r#"[{"kind":"box","group":"crown","centre":[0,0,1e9],"size":[1,1,1]}]"#)
            .message()
            .contains("volumes[0].centre.z"));
        assert!(e(r#"[{"kind":"sphere","group":"crown","centre":[0,0,0],"radius":"x"}]"#)
            .message()
            .contains("volumes[0].radius must be a number"));
        assert!(e(r#"[{"kind":"sphere","group":"crown","centre":[0,0,0],"radius":1,"evil":1}]"#)
            .message()
            .contains("volumes[0].evil"));
        let many =
            format!("[{}]", vec![r#"{"kind":"sphere","group":"crown","centre":[0,1,0],"radius":1}"#; 33].join(","));
        assert!(e(&many).message().contains("at most 32"));
        assert!(e("{}").message().contains("array"));
    }
}
