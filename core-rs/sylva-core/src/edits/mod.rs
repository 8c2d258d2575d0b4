//! Applying the hand edit list ([`crate::params::edits`]) to a built skeleton, in order: a paint
//! stroke grows new shoots toward it by space colonization from the existing stems ([`paint`]);
//! each cut or bend first finds its stem by position ([`resolve`]), then truncates it ([`cut`])
//! or bends it ([`bend`]). A drawn crown ([`crown`]) acts before the stems are built instead:
//! the skeleton stage passes the list's last crown edit to the builders (the *Drawn* crown
//! shape of a Weber & Penn tree, the marker volume of a grown one). The skeleton stage runs this right after the stems are built, so every
//! later stage (bark, leaves) sees the edited stems, and a session reruns it whenever the
//! skeleton stage reruns. Each edit is reported as resolved or not ([`EditReport`]): an edit
//! whose point no longer lies on a branch (after a change of seed or parameters) is listed as
//! unresolved and leaves the tree as it was, never dropped silently.

pub mod bend;
pub mod crown;
pub mod cut;
pub mod paint;
pub mod resolve;
pub(crate) mod stems;

use crate::error::SylvaError;
use crate::params::{Crown, Edit};
use crate::skeleton::Skeleton;
use serde::Serialize;

/// What became of one edit of the list.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EditReport {
    /// The edit's op (`"paint"`, `"crown"`, `"cut"`, `"bend"`).
    pub op: &'static str,
    /// Whether the edit found its stem and was applied.
    pub resolved: bool,
    /// Why not, when unresolved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
    /// The year of a dated cut the tree is too young for: it has not happened yet (the branch
    /// is whole) and happens when the tree's Age reaches this year.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pending_year: Option<f32>,
}

impl EditReport {
    /// An edit that was applied.
    pub fn resolved(op: &'static str) -> EditReport {
        EditReport { op, resolved: true, why: None, pending_year: None }
    }

    /// An edit that found nothing to apply to, and why.
    pub fn unresolved(op: &'static str, why: String) -> EditReport {
        EditReport { op, resolved: false, why: Some(why), pending_year: None }
    }
}

/// The crown drawn by hand: the last crown edit of the list (it shapes the crown before the
/// stems are built, wherever it stands in the list).
pub fn drawn_crown(edits: &[Edit]) -> Option<&Crown> {
    edits.iter().rev().find_map(|e| if let Edit::Crown(c) = e { Some(c) } else { None })
}

/// Apply `edits` to `skeleton` in order; the markers of paint strokes are appended to
/// `markers` (for Show Markers). Unresolved cuts and bends are reported and change nothing, and so does a
/// dated cut the tree is too young for (reported as pending); a
/// bend whose target is further from its stem's base than the stem is long (a bend across the
/// tree) is an error naming the edit, and so is a stroke past the budgets.
pub fn apply(
    skeleton: &mut Skeleton,
    edits: &[Edit],
    markers: &mut Vec<glam::Vec3>,
) -> Result<Vec<EditReport>, SylvaError> {
    edits.iter().enumerate().map(|(i, e)| apply_one(skeleton, e, i, markers)).collect()
}

/// Apply `edit`, entry `index` of its list, to `skeleton`: one step of [`apply`], which applies
/// the edits of a list one after another, each to the tree the ones before it left (so a
/// session may resume from the tree after the first `k` edits).
pub fn apply_one(
    skeleton: &mut Skeleton,
    edit: &Edit,
    index: usize,
    markers: &mut Vec<glam::Vec3>,
) -> Result<EditReport, SylvaError> {
    Ok(match edit {
        Edit::Paint(stroke) => {
            let (seed, budget) = (skeleton.seed, skeleton.max_vertices);
            let grown = paint::paint(skeleton, stroke, seed, index, budget)?;
            markers.extend(grown.markers);
            EditReport::resolved(edit.op())
        }
        // Applied before the stems are built (`drawn_crown`).
        Edit::Crown(_) => EditReport::resolved(edit.op()),
        Edit::Cut(c) if c.year.is_some_and(|year| skeleton.age < year) => {
            EditReport { pending_year: c.year, ..EditReport::resolved(edit.op()) }
        }
        Edit::Cut(c) => match resolve::nearest(skeleton, c.at) {
            Ok(hit) => {
                let years = c.year.map_or(0.0, |year| skeleton.age - year);
                cut::cut(skeleton, hit.stem, hit.t, years);
                EditReport::resolved(edit.op())
            }
            Err(why) => EditReport::unresolved(edit.op(), why),
        },
        Edit::Bend(b) => match resolve::nearest(skeleton, b.at) {
            Ok(hit) => {
                bend::bend(skeleton, hit.stem, hit.t, b.to, index)?;
                EditReport::resolved(edit.op())
            }
            Err(why) => EditReport::unresolved(edit.op(), why),
        },
    })
}
