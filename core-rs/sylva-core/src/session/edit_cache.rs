//! The skeleton stage of a [`super::Session`], incremental over the hand edit list: a stroke
//! being drawn, a cut or a bend added, or the last edit undone does not rebuild the stems or
//! replay the edits before it.
//!
//! The cache keeps the stems as built (before any edit, for the parameters other than the edit
//! list and for the list's drawn crown, which shapes them) and the tree after the first `k`
//! edits for the last list, for `k` = 0 and for the last few lengths ([`KEEP`]). An update
//! resumes from the longest kept prefix its list shares with the last one and applies only the
//! edits after it, each to the tree the ones before left ([`crate::edits::apply_one`], the same
//! order and the same indices as [`crate::edits::apply`], so the result is the same tree).
//! When the list differs from the last one only in its last edit, a paint stroke with the same
//! brush whose points continue the last one's (a stroke being drawn), the growth of that stroke
//! ([`PaintGrowth`]) is extended by the new brush points only: by the incremental rule of
//! [`crate::edits::paint`] that ends exactly where growing the whole stroke does.

use super::SkeletonOut;
use crate::edits::paint::PaintGrowth;
use crate::edits::{self, EditReport};
use crate::error::SylvaError;
use crate::generated::ENVELOPE_SAMPLES;
use crate::growth;
use crate::params::{Edit, GrowthMode, Paint, SkeletonParams};
use crate::skeleton::{self, Skeleton};
use glam::Vec3;

/// How many prefixes of the edit list are kept besides the empty one: the tree before the last
/// edit and after it, and a few more for undo.
const KEEP: usize = 4;

/// The tree after the first `edits` edits of the list.
#[derive(Clone)]
struct Prefix {
    edits: usize,
    skeleton: Skeleton,
    markers: Vec<Vec3>,
    reports: Vec<EditReport>,
}

impl Prefix {
    /// This tree with the next edit, the stroke whose growth (from this tree) is `growth`.
    fn grown(&self, growth: &PaintGrowth) -> Result<Prefix, SylvaError> {
        let mut after = self.clone();
        growth.apply(&mut after.skeleton)?;
        after.markers.extend_from_slice(growth.markers());
        after.reports.push(EditReport::resolved("paint"));
        after.edits += 1;
        Ok(after)
    }
}

/// The growth of the list's last edit, a stroke, from the tree before it.
struct Stroke {
    /// The prefix it grew from: the list's length minus one.
    from: usize,
    growth: PaintGrowth,
    /// The stroke with its points so far.
    paint: Paint,
}

/// Where the last skeleton stage resumed ([`super::Session::skeleton_resume`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Resume {
    /// The stems were built again (new parameters or a new drawn crown).
    pub rebuilt: bool,
    /// How many edits at the start of the list were not applied again.
    pub reused_edits: usize,
    /// The stroke being drawn was extended by its new brush points (not grown again).
    pub extended_stroke: bool,
}

/// See the module doc.
#[derive(Default)]
pub(super) struct EditCache {
    /// Where the last build resumed.
    pub(super) resume: Resume,
    /// The parameters the stems were built with: the edit list reduced to its drawn crown.
    base: Option<SkeletonParams>,
    /// The stems at the Mature Age for `base` without its Age ([`ageless`]), kept when the
    /// edit list changes: an Age drag only replays them.
    mature: Option<(SkeletonParams, Mature)>,
    /// The last edit list.
    edits: Vec<Edit>,
    /// Kept prefixes of `edits`, shortest first; the first is always the empty one (`edits: 0`).
    prefixes: Vec<Prefix>,
    stroke: Option<Stroke>,
    /// The session makes one tree and ends ([`EditCache::one_shot`]): the stems are handed on
    /// as built, not copied for a next update.
    one_shot: bool,
}

impl std::fmt::Debug for EditCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("EditCache")
            .field("edits", &self.edits.len())
            .field("prefixes", &self.prefixes.iter().map(|p| p.edits).collect::<Vec<_>>())
            .field("stroke", &self.stroke.as_ref().map(|s| s.paint.points.len()))
            .finish()
    }
}

/// `p` with its edit list reduced to what shapes the stems as built: the drawn crown.
fn base_params(p: &SkeletonParams) -> SkeletonParams {
    let crown = edits::drawn_crown(&p.edits).cloned();
    SkeletonParams { edits: crown.map(Edit::Crown).into_iter().collect(), ..p.clone() }
}

/// Whether stroke `new` continues stroke `old`: the same brush, and `old`'s points first.
fn continues(old: &Paint, new: &Paint) -> bool {
    let brush = |p: &Paint| (p.radius, p.density, p.segment, p.kill);
    brush(old) == brush(new) && new.points.len() >= old.points.len() && new.points[..old.points.len()] == old.points[..]
}

/// The stems as built at the Mature Age, before the Age brings them to their year: what an Age
/// drag reuses (a Weber & Penn tree's dated stems, a grown tree's growth).
enum Mature {
    Parametric(Skeleton),
    Grown(growth::Growth),
}

/// The stems as built from `p` (before any edit but the drawn crown), at its Age ([`crate::age`]),
/// and a grown tree's markers; `mature` is the tree before its Age, built when `None`.
fn build_stems(
    p: &SkeletonParams,
    mature: &mut Option<Mature>,
    one_shot: bool,
    progress: Option<&mut dyn FnMut(f32)>,
) -> Result<(Skeleton, Vec<Vec3>), SylvaError> {
    let crown = edits::drawn_crown(&p.edits);
    if mature.is_none() {
        *mature = Some(match p.growth_mode {
            GrowthMode::Parametric => {
                let mut skeleton = skeleton::build_with_crown(p, crown)?;
                crate::age::date(&mut skeleton, p.maturity);
                Mature::Parametric(skeleton)
            }
            GrowthMode::SpaceColonization => Mature::Grown(growth::grow_with_crown(p, crown, progress)?),
        });
    }
    let at_age = |mut skeleton: Skeleton| {
        skeleton.age = p.age;
        crate::age::replay(&mut skeleton, p.age, p.maturity);
        (skeleton, Vec::new())
    };
    // A one-shot session keeps nothing for a next update: the dated stems themselves.
    let (mut skeleton, markers) = match mature.take_if(|m| one_shot && matches!(m, Mature::Parametric(_))) {
        Some(Mature::Parametric(dated)) => at_age(dated),
        _ => match mature.as_ref().expect("just built") {
            Mature::Parametric(dated) => at_age(dated.clone()),
            // Dated and brought to its Age by its annual flushes.
            Mature::Grown(grown) => (growth::skeleton_by_years(p, grown), grown.markers.clone()),
        },
    };
    crate::life::live(&mut skeleton, p);
    Ok((skeleton, markers))
}

/// `p` without its Age: the parameters of the stems as built at the Mature Age.
fn ageless(p: &SkeletonParams) -> SkeletonParams {
    SkeletonParams { age: 0.0, ..p.clone() }
}

impl EditCache {
    /// A cache for a session that makes one tree and ends (a cold generation): the stems and
    /// the tree after the edits are moved on, not copied into the cache, and the next update
    /// builds everything again.
    pub(super) fn one_shot() -> EditCache {
        EditCache { one_shot: true, ..EditCache::default() }
    }

    /// Forgets everything.
    pub(super) fn clear(&mut self) {
        let (resume, one_shot) = (self.resume, self.one_shot);
        *self = EditCache { resume, one_shot, ..EditCache::default() };
    }

    /// Forgets everything but the stems at the Mature Age.
    fn clear_edits(&mut self) {
        let mature = self.mature.take();
        self.clear();
        self.mature = mature;
    }

    /// The skeleton stage for `p` (see the module doc). On an error the cache forgets the last
    /// list (keeping the stems as built) and the session keeps its previous tree.
    pub(super) fn build(
        &mut self,
        p: &SkeletonParams,
        progress: Option<&mut dyn FnMut(f32)>,
    ) -> Result<SkeletonOut, SylvaError> {
        let base = base_params(p);
        let rebuilt = self.base.as_ref() != Some(&base);
        if rebuilt {
            self.clear_edits();
            let key = ageless(&base);
            let mut mature = match self.mature.take() {
                Some((k, m)) if k == key => Some(m),
                _ => None,
            };
            let built = build_stems(p, &mut mature, self.one_shot, progress);
            self.mature = mature.map(|m| (key, m));
            let (skeleton, markers) = built?;
            self.base = Some(base);
            self.prefixes = vec![Prefix { edits: 0, skeleton, markers, reports: Vec::new() }];
        }
        let result = self.apply(&p.edits);
        self.resume.rebuilt = rebuilt;
        if result.is_err() {
            self.prefixes.truncate(1);
            self.edits.clear();
            self.stroke = None;
        }
        let Prefix { skeleton, markers, reports, .. } = result?;
        let crown = edits::drawn_crown(&p.edits);
        let envelope = skeleton::preview_profile_with_crown(&skeleton, p, crown, ENVELOPE_SAMPLES);
        Ok(SkeletonOut { skeleton, markers, envelope, edits: reports })
    }

    /// The tree after every edit of `list`, from the longest kept prefix it shares with the last
    /// list (or the stroke being drawn, extended).
    fn apply(&mut self, list: &[Edit]) -> Result<Prefix, SylvaError> {
        let shared = self.edits.iter().zip(list).take_while(|(a, b)| a == b).count();
        if let Some(out) = self.extend_stroke(list, shared)? {
            return Ok(out);
        }
        // A new edit after the stroke drawn last: the tree after the stroke is its start.
        if let Some(stroke) = self.stroke.take() {
            if shared == self.edits.len() && stroke.from + 1 == shared {
                self.keep_stroke(&stroke)?;
            }
        }
        self.prefixes.retain(|q| q.edits <= shared);
        let mut tree = if self.one_shot {
            // Nothing is resumed after this update: the tree itself, and the stems built again
            // by the next one.
            self.base = None;
            self.prefixes.pop().expect("the empty prefix is always kept")
        } else {
            self.prefixes.last().expect("the empty prefix is always kept").clone()
        };
        self.resume = Resume { rebuilt: false, reused_edits: tree.edits, extended_stroke: false };
        let n = list.len();
        for (i, edit) in list.iter().enumerate().skip(tree.edits) {
            if let (true, Edit::Paint(paint)) = (i + 1 == n, edit) {
                // The last edit is a stroke: keep its growth, which the next update may extend.
                let (seed, budget) = (tree.skeleton.seed, tree.skeleton.max_vertices);
                let mut growth = PaintGrowth::new(&tree.skeleton, paint, seed, i, budget)?;
                growth.extend(&paint.points)?;
                let after = tree.grown(&growth)?;
                self.keep(tree);
                self.stroke = Some(Stroke { from: i, growth, paint: paint.clone() });
                tree = after;
                break;
            }
            let report = edits::apply_one(&mut tree.skeleton, edit, i, &mut tree.markers)?;
            tree.reports.push(report);
            tree.edits = i + 1;
            // Keep the trees near the end of the list: the next update most likely continues it.
            if i + 1 + KEEP > n && !self.one_shot {
                self.keep(tree.clone());
            }
        }
        self.edits = list.to_vec();
        Ok(tree)
    }

    /// The list's last edit continues the stroke being drawn: grow its new points from the
    /// tree before it. `None` when it does not.
    fn extend_stroke(&mut self, list: &[Edit], shared: usize) -> Result<Option<Prefix>, SylvaError> {
        let Some(stroke) = self.stroke.as_mut() else { return Ok(None) };
        let n = list.len();
        let Some(Edit::Paint(paint)) = list.last() else { return Ok(None) };
        if n != self.edits.len() || stroke.from + 1 != n || shared + 1 < n || !continues(&stroke.paint, paint) {
            return Ok(None);
        }
        let Some(before) = self.prefixes.iter().find(|q| q.edits == stroke.from) else { return Ok(None) };
        stroke.growth.extend(&paint.points)?;
        stroke.paint.points.clone_from(&paint.points);
        let after = before.grown(&stroke.growth)?;
        self.edits = list.to_vec();
        self.resume = Resume { rebuilt: false, reused_edits: n - 1, extended_stroke: true };
        Ok(Some(after))
    }

    /// Keeps the tree after `stroke`, the last edit of the last list.
    fn keep_stroke(&mut self, stroke: &Stroke) -> Result<(), SylvaError> {
        let Some(before) = self.prefixes.iter().find(|q| q.edits == stroke.from) else { return Ok(()) };
        let after = before.grown(&stroke.growth)?;
        self.keep(after);
        Ok(())
    }

    /// Keeps `tree`, the tree after the first `tree.edits` edits (replacing one kept for as
    /// many), and at most [`KEEP`] besides the empty one.
    fn keep(&mut self, tree: Prefix) {
        if tree.edits == 0 {
            return;
        }
        self.prefixes.retain(|q| q.edits != tree.edits);
        let at = self.prefixes.partition_point(|q| q.edits < tree.edits);
        self.prefixes.insert(at, tree);
        while self.prefixes.len() > KEEP + 1 {
            self.prefixes.remove(1);
        }
    }
}
