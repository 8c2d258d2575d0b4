//! Hand edits: the ordered edit list that shapes a tree by hand (paint growth, draw the crown,
//! cut a branch, bend a branch). Like the growth volumes, the list is structured data beside the
//! scalar parameters: `SkeletonParams::edits`, in JSON the `"edits"` array of
//!
//! ```json
//! {"version": 1, "edits": [
//!   {"op": "paint", "points": [[1.2, 6.0, 0.3], [1.9, 6.4, 0.2]], "radius": 0.6, "density": 400, "segment": 0.25, "kill": 0.4},
//!   {"op": "crown", "outline": [[0, 2], [2.5, 4], [2, 8], [0, 9]]},
//!   {"op": "cut", "at": [0.8, 4.1, -0.2]},
//!   {"op": "bend", "at": [2.0, 5.5, 0.0], "to": [2.3, 4.6, 0.0]}
//! ]}
//! ```
//!
//! All coordinates are in tree space: metres, y up, the origin at the trunk's base. A cut or a
//! bend names its branch by a point, not by an index, so an edit survives a change of seed or
//! parameters while that point still lies on a branch (the stem nearest to it within a
//! tolerance); one that finds no stem is reported as unresolved, never dropped silently.
//!
//! This file holds the data model only; applying the edits is the skeleton stage's work
//! (`crate::edits`).

use crate::error::SylvaError;
use glam::{Vec2, Vec3};

mod json;
mod validate;

pub use json::{from_json, from_json_value, to_json, to_json_value};
pub use validate::validate;

/// Most edits one tree may carry.
pub const MAX_EDITS: usize = 1_000;
/// Most points in one paint stroke.
pub const MAX_STROKE_POINTS: usize = 4_096;
/// Most points in one crown outline (checked for self-crossings pair by pair).
pub const MAX_OUTLINE_POINTS: usize = 1_024;
/// Most points in all strokes and outlines together.
pub const MAX_POINTS: usize = 65_536;
/// Longest JSON text read for parameters or an edit list (bytes): 4 MiB holds [`MAX_POINTS`]
/// brush points written at full precision; longer text is refused before it is parsed (a
/// hostile link or file with millions of points answers at once instead of parsing for seconds).
pub const MAX_JSON_BYTES: usize = 4 << 20;

/// An error for JSON text past [`MAX_JSON_BYTES`]: `what` is what it was to hold.
pub(crate) fn too_long(what: &str, len: usize) -> SylvaError {
    bad(
        "edits",
        format!(
            "{what} is {:.1} MB of JSON, more than {} MB: an edit list holds at most {MAX_POINTS} points (split the work, or paint fewer, shorter strokes)",
            len as f64 / 1_048_576.0,
            MAX_JSON_BYTES >> 20
        ),
    )
}
/// Largest distance of any coordinate from the origin along any axis (m).
pub const MAX_COORD: f32 = 200.0;
/// Allowed paint brush radius (m).
pub const RADIUS_RANGE: (f32, f32) = (0.02, 10.0);
/// Allowed paint density (markers per cubic metre).
pub const DENSITY_RANGE: (f32, f32) = (1.0, 5_000.0);
/// Allowed paint segment length (m).
pub const SEGMENT_RANGE: (f32, f32) = (0.02, 2.0);
/// Allowed paint kill distance (m); it must also be at least the stroke's segment length.
pub const KILL_RANGE: (f32, f32) = (0.02, 10.0);
/// Allowed year of a dated cut (years; the range of the Age parameter, and year 0).
pub const YEAR_RANGE: (f32, f32) = (0.0, 300.0);
/// A cut or bend at or below this height names the ground, not a branch (m).
pub const GROUND: f32 = 0.05;
/// The version of the edit list document (`{"version": 1, "edits": [...]}`).
pub const VERSION: u32 = 1;

/// The error of a field of an edit: `param` is the field's path, e.g. `edits[3].radius`.
pub(crate) fn bad(field: impl Into<String>, message: String) -> SylvaError {
    SylvaError::InvalidParam { param: field.into(), message }
}

/// One paint stroke: markers scattered in a tube around the stroke, which the tree grows toward
/// by space colonization from its existing stems (Runions, Lane & Prusinkiewicz 2007, *Modeling
/// Trees with a Space Colonization Algorithm*), with the stroke's own segment length and kill
/// distance, so a bushy section and a sparse one can sit in the same tree.
#[derive(Clone, Debug, PartialEq)]
pub struct Paint {
    /// The brush points along the stroke, in drawing order (m, tree space).
    pub points: Vec<Vec3>,
    /// Radius of the tube around the stroke that holds the markers (m).
    pub radius: f32,
    /// Markers per cubic metre of the tube.
    pub density: f32,
    /// Length of one new internode (m).
    pub segment: f32,
    /// A marker dies when a node comes this close (m).
    pub kill: f32,
}

/// A drawn crown outline: `[radius, height]` pairs (m) of a closed profile drawn from the side,
/// revolved about the trunk axis. For a Weber & Penn tree it is the *Drawn* crown shape's
/// envelope; for a grown tree it is the marker volume.
#[derive(Clone, Debug, PartialEq)]
pub struct Crown {
    /// The outline's points, `[radius from the trunk axis, height]`, in drawing order.
    pub outline: Vec<Vec2>,
}

/// Cut the stem nearest to `at` there: everything beyond goes, with its leaves, and the stump
/// shows a cut face.
///
/// A cut may carry the **year** it was made in (the tree's Age then; the studio records it).
/// A dated cut has not happened while the tree is younger: the branch is whole. From that year
/// on the branch is cut, and the years since then close the wound: woundwood rolls in over the
/// face from the bark rim ([`crate::mesh::cut_face`]). An undated cut is a fresh cut at any Age.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cut {
    /// A point on the branch where it is cut (m, tree space).
    pub at: Vec3,
    /// The tree's Age when the cut was made (years, within [`YEAR_RANGE`]), if dated.
    pub year: Option<f32>,
}

/// Bend the stem nearest to `at` so that its point at `at` follows to `to`; the bend is spread
/// smoothly along the stem from its base, the children ride along, and the length is kept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bend {
    /// The point of the branch that is dragged (m, tree space).
    pub at: Vec3,
    /// Where that point goes (m, tree space).
    pub to: Vec3,
}

/// One entry of the edit list.
#[derive(Clone, Debug, PartialEq)]
pub enum Edit {
    /// Paint growth.
    Paint(Paint),
    /// Draw the crown.
    Crown(Crown),
    /// Cut a branch.
    Cut(Cut),
    /// Bend a branch.
    Bend(Bend),
}

impl Edit {
    /// The `"op"` name on the wire.
    pub fn op(&self) -> &'static str {
        match self {
            Edit::Paint(_) => "paint",
            Edit::Crown(_) => "crown",
            Edit::Cut(_) => "cut",
            Edit::Bend(_) => "bend",
        }
    }
}

#[cfg(test)]
mod tests;
