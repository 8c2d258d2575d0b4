//! Applying the hand edit list ([`crate::params::edits`]) to a built skeleton, in order: each
//! cut or bend first finds its stem by position ([`resolve`]), then truncates it ([`cut`]) or
//! bends it ([`bend`]). The skeleton stage runs this right after the stems are built, so every
//! later stage (bark, leaves) sees the edited stems, and a session reruns it whenever the
//! skeleton stage reruns. Each edit is reported as resolved or not ([`EditReport`]): an edit
//! whose point no longer lies on a branch (after a change of seed or parameters) is listed as
//! unresolved and leaves the tree as it was, never dropped silently.

pub mod bend;
pub mod cut;
pub mod resolve;
mod stems;

use crate::error::SylvaError;
use crate::params::Edit;
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
}

impl EditReport {
    fn resolved(op: &'static str) -> EditReport {
        EditReport { op, resolved: true, why: None }
    }
}

/// Apply `edits` to `skeleton` in order. Unresolved cuts and bends are reported and change
/// nothing; a bend whose target is further from its stem's base than the stem is long (a bend
/// across the tree) is an error naming the edit.
pub fn apply(skeleton: &mut Skeleton, edits: &[Edit]) -> Result<Vec<EditReport>, SylvaError> {
    let mut reports = Vec::with_capacity(edits.len());
    for (i, e) in edits.iter().enumerate() {
        let report = match e {
            // Applied by edits::paint (paint-growth branch).
            Edit::Paint(_) | Edit::Crown(_) => EditReport::resolved(e.op()),
            Edit::Cut(c) => match resolve::nearest(skeleton, c.at) {
                Ok(hit) => {
                    cut::cut(skeleton, hit.stem, hit.t);
                    EditReport::resolved(e.op())
                }
                Err(why) => EditReport { op: e.op(), resolved: false, why: Some(why) },
            },
            Edit::Bend(b) => match resolve::nearest(skeleton, b.at) {
                Ok(hit) => {
                    bend::bend(skeleton, hit.stem, hit.t, b.to, i)?;
                    EditReport::resolved(e.op())
                }
                Err(why) => EditReport { op: e.op(), resolved: false, why: Some(why) },
            },
        };
        reports.push(report);
    }
    Ok(reports)
}
