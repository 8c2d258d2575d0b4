//! What the registry says of one parameter ([`ParamSpec`], [`ParamKind`]), how a typed value
//! goes to and from its wire number ([`ParamValue`]), and the panel's groups ([`GROUPS`]).

use crate::error::SylvaError;
use serde::Serialize;

/// How a parameter's value is typed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ParamKind {
    /// A real number.
    Float,
    /// A whole number.
    Int,
    /// 0 or 1.
    Bool,
    /// An index into `options`.
    Enum,
}

/// The pipeline stages, in order: the first one a parameter affects is declared in the registry
/// ([`ParamSpec::stage`]), and the parameter lives in that stage's struct of
/// [`crate::TreeParams`]. An edit reruns that stage and every later one and reuses the results of
/// the earlier ones ([`crate::session::Session`]); a `Viewer` parameter regenerates nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Stage {
    /// The stems: Weber & Penn's skeleton or space-colonization growth (and the crown envelope).
    Skeleton,
    /// The bark surface swept, welded and cut from the skeleton.
    Mesh,
    /// Where the leaves sit: per-leaf matrices and tints.
    Foliage,
    /// The leaf itself: outline, veins, surface, texture and the leaf mesh drawn per leaf.
    Leaf,
    /// Nothing is regenerated: the viewer only shows or hides something.
    Viewer,
}

/// One parameter's description, as exported to JS (`registry_json`) and `sylva params`.
#[derive(Clone, Debug, Serialize)]
pub struct ParamSpec {
    /// Stable id used in share URLs, JSON and the CLI (`scale`, `l1_length`).
    pub id: String,
    /// Panel section, in display order (see [`GROUPS`]).
    pub group: String,
    /// Short label for the panel.
    pub label: String,
    /// Value type.
    pub kind: ParamKind,
    /// Default value.
    pub default: f64,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Slider step.
    pub step: f64,
    /// Unit shown next to the value (`m`, `°`, or empty).
    pub unit: String,
    /// One line saying what the parameter does.
    pub description: String,
    /// Option labels for enums (value = index).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub options: Option<Vec<String>>,
    /// The first pipeline stage the parameter affects: the stage struct of
    /// [`crate::TreeParams`] that holds it.
    pub stage: Stage,
}

impl ParamSpec {
    /// The accepted range. Float fields are stored as f32, so a bound like 0.2 is stored as
    /// 0.2000000030 (and 0.01 as 0.0099999998): the f32-rounded bounds are accepted as well, or a
    /// value set at its bound would fail validation once stored.
    pub fn bounds(&self) -> (f64, f64) {
        if self.kind == ParamKind::Float {
            (self.min.min(f64::from(self.min as f32)), self.max.max(f64::from(self.max as f32)))
        } else {
            (self.min, self.max)
        }
    }

    /// Check one value against this spec; the error names the field and the allowed range.
    pub fn check(&self, v: f64) -> Result<(), SylvaError> {
        // The range's text only for an error: a valid value costs no formatting.
        let range = || match self.kind {
            ParamKind::Bool => "0 or 1".to_string(),
            ParamKind::Enum => {
                format!("0 to {} ({})", self.max, self.options.as_deref().unwrap_or_default().join(", "))
            }
            _ => format!("{} to {}{}", fmt_num(self.min), fmt_num(self.max), unit_suffix(&self.unit)),
        };
        let bad = |why: &str| SylvaError::InvalidParam {
            param: self.id.clone(),
            message: format!("{} ({}) {}: allowed range is {}", self.id, self.label, why, range()),
        };
        if !v.is_finite() {
            return Err(bad("must be a finite number"));
        }
        let (lo, hi) = self.bounds();
        if v < lo || v > hi {
            return Err(bad(&format!("is {}", fmt_num(v))));
        }
        if self.kind != ParamKind::Float && v.fract() != 0.0 {
            return Err(bad(&format!("must be a whole number, got {}", fmt_num(v))));
        }
        Ok(())
    }
}

fn unit_suffix(unit: &str) -> String {
    match unit {
        "" => String::new(),
        "°" => "°".into(),
        u => format!(" {u}"),
    }
}

fn fmt_num(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        format!("{v}")
    }
}

/// Conversion between a typed field and its wire number. Values are validated before
/// `from_wire` is called, so it only has to map, never to check.
pub trait ParamValue: Copy {
    /// The kind reported in the registry.
    const KIND: ParamKind;
    /// Field value as a wire number.
    fn to_wire(self) -> f64;
    /// Wire number (already validated) as a field value.
    fn from_wire(v: f64) -> Self;
    /// Enum option labels.
    fn options() -> Option<Vec<String>> {
        None
    }
}

impl ParamValue for f32 {
    const KIND: ParamKind = ParamKind::Float;
    fn to_wire(self) -> f64 {
        f64::from(self)
    }
    fn from_wire(v: f64) -> Self {
        v as f32
    }
}
impl ParamValue for u32 {
    const KIND: ParamKind = ParamKind::Int;
    fn to_wire(self) -> f64 {
        f64::from(self)
    }
    fn from_wire(v: f64) -> Self {
        v as u32
    }
}
impl ParamValue for bool {
    const KIND: ParamKind = ParamKind::Bool;
    fn to_wire(self) -> f64 {
        f64::from(u8::from(self))
    }
    fn from_wire(v: f64) -> Self {
        v != 0.0
    }
}
/// Panel sections in display order. Every parameter's group is one of these.
pub const GROUPS: [&str; 17] = [
    "Tree",
    "Life",
    "Crown",
    "Trunk",
    "Level 1",
    "Level 2",
    "Level 3",
    "Growth",
    "Growth Volume",
    "Environment",
    "Foliage",
    "Flowers & Fruit",
    "Quality",
    "Budget",
    "Leaf",
    "Leaf Veins",
    "Leaf Surface",
];
