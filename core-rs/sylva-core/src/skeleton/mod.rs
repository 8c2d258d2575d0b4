//! Skeleton stage: parameters -> stems (centre polylines with a radius profile), after Weber &
//! Penn, "Creation and Rendering of Realistic Trees" (SIGGRAPH 1995) with the paper's formulas:
//! stem lengths (level 1 scaled by the crown ShapeRatio), radii with RatioPower and
//! child <= parent at the attachment point, taper modes, trunk flare, curvature (Curve,
//! CurveBack, CurveV), DownAngle/Rotate with their negative variants, branch counts with error
//! diffusion, AttractionUp and Angle Spread.
//!
//! Every stem draws from its own generator split off its parent's, so editing a deeper level
//! never changes the stems above it.

mod envelope;
mod life_record;
mod stem;
mod trace;
mod trunk;

pub use envelope::{preview_profile, preview_profile_with_crown};
pub use stem::{flare_factor, taper_radius, Points, Segment, Stem, StemKind, StemPoints};
use trace::{inside_prune_envelope, trace};
use trunk::{add_roots, guide_curve};

use crate::edits::crown::DrawnCrown;
use crate::error::SylvaError;
use crate::math::{self, pow, rad, unit_or};
use crate::params::{Crown, CrownShape, GrowthMode, SkeletonParams};
use crate::rng::Rng;
use glam::{Quat, Vec3};
pub use life_record::LifeRecord;

/// The stems of one tree, parents before children.
#[derive(Clone, Debug)]
pub struct Skeleton {
    /// How the stems were made: Weber & Penn's rules or space colonization.
    pub mode: GrowthMode,
    /// All stems; `stems[0]` is the trunk. Roots ([`StemKind::Root`]) come last.
    pub stems: Vec<Stem>,
    /// `Scale + var(ScaleV)` drawn for this tree (m).
    pub scale: f32,
    /// Height above the ground where the crown starts (m).
    pub crown_base: f32,
    /// The tree's Seed: the later stages' random streams start from it.
    pub seed: u32,
    /// Levels (stem levels including the trunk) the stems were built with.
    pub levels: u32,
    /// Max Vertices: the vertex budget the mesh stage checks too.
    pub max_vertices: u32,
    /// The tree's Age (years): dated hand edits happen only from their year on.
    pub age: f32,
    /// The tree's Mature Age (years): the form the stems were built in ([`crate::age`]).
    pub maturity: f32,
    /// For a tree past its Mature Age: the stems at it and the life that followed
    /// ([`LifeRecord`]), so the growth animation can show any year between.
    pub life: Option<std::sync::Arc<LifeRecord>>,
}

/// Smallest stem length that is still built (m); shorter children are dropped.
const MIN_LENGTH: f32 = 1e-3;
/// Smallest radius a stem gets (m): 1 mm keeps every ring wider than f32 rounding at tree
/// heights, so no triangle collapses.
const MIN_RADIUS: f32 = 1e-3;

/// Lower bound of the vertices a stem will need in the mesh stage; used to stop runaway trees
/// before they allocate (the mesh stage checks the exact count against the same budget).
pub fn min_vertices(curve_res: u32) -> u64 {
    (u64::from(curve_res) + 1) * 4 + 1
}

/// The vertex budget error, shared by the skeleton and mesh stages: the advice names the
/// parameters that make the tree (Weber & Penn's, or growth's).
pub fn budget_error(mode: GrowthMode, max: u32, what: &str, need: u64) -> SylvaError {
    let lower = match mode {
        crate::params::GrowthMode::Parametric => "lower Levels or Branches",
        crate::params::GrowthMode::SpaceColonization => {
            "lower Markers or Extra Markers, raise Internode or Kill Distance"
        }
    };
    SylvaError::Budget {
        param: "max_vertices".into(),
        message: format!(
            "this tree would need {what}{need} vertices, more than the max_vertices budget of {max}: \
             {lower}, or raise Max Vertices"
        ),
    }
}

struct Builder<'a> {
    p: &'a SkeletonParams,
    stems: Vec<Stem>,
    /// Error-diffusion remainders of fractional branch counts, per level.
    carry: [f32; 4],
    /// Error-diffusion remainders of fractional segment splits, per level.
    split_carry: [f32; 4],
    vertex_floor: u64,
    scale: f32,
    crown_base: f32,
    /// The drawn crown when Crown Shape is Drawn and a crown edit gives the outline.
    drawn: Option<DrawnCrown>,
    /// Emptied lists for [`trace()`]'s clones, for the next stems ([`Builder::grow`]).
    clone_lists: Vec<Vec<StemStart>>,
    /// [`Builder::pruned_length`]'s trace, kept for the next stem.
    unit: Vec<Vec3>,
}

/// Where and how a stem (or a clone made by a split) starts.
struct StemStart {
    level: usize,
    parent: Option<u32>,
    /// Distance along the parent record where this record starts.
    offset: f32,
    base: Vec3,
    /// Local +Y along the stem, local +X the axis positive Curve bends around.
    frame: Quat,
    /// Full Weber & Penn length of the stem (for a clone: of the stem it split from).
    length: f32,
    /// Base radius of the whole stem.
    radius: f32,
    down_angle: f32,
    /// First segment this record covers (0, or the split boundary for a clone).
    first_seg: usize,
    /// Per-segment turn back toward the original direction after splits (degrees).
    correction: f32,
    rng: Rng,
}

/// Build the skeleton. Fails only on the vertex budget (parameters are validated before).
pub fn build(p: &SkeletonParams) -> Result<Skeleton, SylvaError> {
    build_with_crown(p, None)
}

/// [`build`] with a crown drawn by hand: with Crown Shape *Drawn*, the level-1 branch lengths
/// follow `crown`'s outline ([`DrawnCrown::ratio_at_height`] at each attachment point's height);
/// without a crown (or with another shape) the tree is [`build`]'s.
pub fn build_with_crown(p: &SkeletonParams, crown: Option<&Crown>) -> Result<Skeleton, SylvaError> {
    let mut rng = Rng::new(u64::from(p.seed), "skeleton");
    let scale = (p.scale + rng.var(p.scale_v)).max(0.1);
    let l0 = &p.level[0];
    let length = ((l0.length + rng.var(l0.length_v)) * scale).max(MIN_LENGTH);
    let radius = (length * p.ratio * (p.scale0 + rng.var(p.scale0_v))).max(MIN_RADIUS);
    let mut b = Builder {
        p,
        stems: Vec::new(),
        carry: [0.0; 4],
        split_carry: [0.0; 4],
        vertex_floor: 0,
        scale,
        crown_base: p.base_size * length,
        drawn: drawn_crown(p, crown),
        clone_lists: Vec::new(),
        unit: Vec::new(),
    };
    b.grow(StemStart {
        level: 0,
        parent: None,
        offset: 0.0,
        base: Vec3::ZERO,
        frame: Quat::IDENTITY,
        length,
        radius,
        down_angle: 0.0,
        first_seg: 0,
        correction: 0.0,
        rng,
    })?;
    add_roots(p, &mut b.stems);
    Ok(Skeleton {
        mode: GrowthMode::Parametric,
        stems: b.stems,
        scale,
        crown_base: b.crown_base,
        seed: p.seed,
        levels: p.levels,
        max_vertices: p.max_vertices,
        age: p.age,
        maturity: p.maturity,
        life: None,
    })
}

/// The drawn crown that shapes `p`'s tree: `crown`'s, when Crown Shape is Drawn.
pub(crate) fn drawn_crown(p: &SkeletonParams, crown: Option<&Crown>) -> Option<DrawnCrown> {
    crown.filter(|_| p.shape == CrownShape::Drawn).and_then(DrawnCrown::new)
}

impl Skeleton {
    /// Index of the first root ([`StemKind::Root`]): roots come after every other stem, so
    /// `0..first_root()` are the tree's own stems (`stems.len()` when there is no root).
    pub fn first_root(&self) -> usize {
        self.stems.iter().position(|s| s.kind == StemKind::Root).unwrap_or(self.stems.len())
    }
}

impl Builder<'_> {
    /// Grow one stem record (tracing its segments, splitting off clones), then its children and
    /// its clones. Records are pushed parents first.
    fn grow(&mut self, s: StemStart) -> Result<(), SylvaError> {
        let p = self.p;
        let lp = &p.level[s.level];
        self.vertex_floor += min_vertices(lp.curve_res);
        if self.vertex_floor > u64::from(p.max_vertices) {
            return Err(budget_error(p.growth_mode, p.max_vertices, "at least ", self.vertex_floor));
        }
        let mut rng = s.rng.clone();
        let mut length = s.length;
        if p.prune_ratio > 0.0 && s.level >= 1 && s.first_seg == 0 {
            length = self.pruned_length(&s);
            if length < (2.0 * s.radius).max(MIN_LENGTH) {
                return Ok(()); // pruned to a stub that would sit inside its parent
            }
        }
        let mut carry = self.split_carry[s.level];
        let trunk = s.level == 0 && s.parent.is_none();
        let mut points = Points::with_capacity(p.level[s.level].curve_res as usize + 1);
        // The clones' list from a pool, one per level of recursion: no allocation per stem.
        let mut clones = self.clone_lists.pop().unwrap_or_default();
        trace(p, &s, length, &mut rng, Some(&mut carry), &mut clones, &mut |q| {
            points.push(q);
            true
        });
        self.split_carry[s.level] = carry;
        if trunk && p.guide_xy > 0.0 {
            guide_curve(p, &mut points);
        }
        let segs = lp.curve_res as usize;
        let z0 = s.first_seg as f32 / segs as f32;
        let index = self.stems.len() as u32;
        let record_len = length * (1.0 - z0);
        let kind = if s.first_seg > 0 {
            StemKind::SplitClone
        } else if trunk {
            StemKind::Trunk
        } else {
            StemKind::Branch
        };
        self.stems.push(Stem {
            kind,
            level: s.level as u8,
            parent: s.parent,
            offset: s.offset,
            base_normal: s.frame * Vec3::X,
            points,
            length: record_len.max(MIN_LENGTH),
            radius: taper_radius(s.radius, lp.taper, length, z0).max(MIN_RADIUS),
            taper: lp.taper,
            flare: if s.level == 0 { p.flare } else { 0.0 },
            down_angle: s.down_angle,
            chain_length: length,
            chain_radius: s.radius,
            chain_start: z0,
            lobed: trunk,
            radii: None,
            cut_end: false,
            callus: 0.0,
            born: 0.0,
            tip_year: 0.0,
        });
        if s.level + 1 < p.levels as usize {
            self.grow_children(s.level, index, &mut rng)?;
        }
        for mut c in clones.drain(..) {
            c.parent = Some(index);
            c.offset = (c.first_seg - s.first_seg) as f32 * length / segs as f32;
            c.length = length;
            self.grow(c)?;
        }
        self.clone_lists.push(clones);
        Ok(())
    }

    /// Weber & Penn pruning: the longest length at which the stem stays inside the pruning
    /// envelope (bisection), then `L - (L - L_fit) * PruneRatio`. A stem's shape does not depend
    /// on its length (bends are per segment), so one unit-length trace, scaled, answers every
    /// trial length.
    fn pruned_length(&mut self, s: &StemStart) -> f32 {
        let mut unit = std::mem::take(&mut self.unit);
        unit.clear();
        let length = self.fit_length(s, &mut unit);
        self.unit = unit;
        length
    }

    /// [`Builder::pruned_length`] with its buffer for the unit-length trace (empty on entry).
    fn fit_length(&self, s: &StemStart, unit: &mut Vec<Vec3>) -> f32 {
        let p = self.p;
        trace(p, s, 1.0, &mut s.rng.clone(), None, &mut Vec::new(), &mut |q| {
            unit.push(q - s.base);
            true
        });
        // From the tip down: a stem too long leaves the envelope at its tip first, most often.
        let fits = |len: f32| unit.iter().rev().all(|&d| inside_prune_envelope(p, self.scale, s.base + d * len));
        if fits(s.length) {
            return s.length;
        }
        let (mut lo, mut hi) = (0.0f32, s.length);
        for _ in 0..10 {
            let mid = 0.5 * (lo + hi);
            if fits(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        s.length - (s.length - lo) * p.prune_ratio
    }

    fn grow_children(&mut self, level: usize, index: u32, rng: &mut Rng) -> Result<(), SylvaError> {
        let p = self.p;
        let child = level + 1;
        let cp = &p.level[child];
        let stem = self.stems[index as usize].clone();
        // Weber & Penn reason about whole stems: a clone's children use its stem's length.
        let stem_len = stem.chain_length;
        let chain_offset = stem.chain_start * stem_len;
        let (parent_len, parent_offset) = match stem.parent {
            Some(i) => {
                let parent = &self.stems[i as usize];
                (parent.chain_length, parent.chain_start * parent.chain_length + stem.offset)
            }
            None => (stem_len, 0.0),
        };
        // How many children (Weber & Penn 1995, §4.3), fractional counts carried over by error diffusion.
        let wanted = match child {
            1 => cp.branches as f32,
            2 => {
                let max_child = (p.level[1].length + p.level[1].length_v).max(1e-6);
                cp.branches as f32 * (0.2 + 0.8 * (stem_len / parent_len) / max_child)
            }
            _ => cp.branches as f32 * (1.0 - 0.5 * parent_offset / parent_len),
        }
        .max(0.0)
            * (stem.length / stem_len);
        let exact = wanted + self.carry[child];
        let count = exact.floor().max(0.0);
        self.carry[child] = exact - count;
        let count = count as usize;
        if count == 0 {
            return Ok(());
        }
        let start = if level == 0 { (self.crown_base - chain_offset).clamp(0.0, stem.length) } else { 0.0 };
        let mut rot = 0.0f32;
        for i in 0..count {
            let mut crng = rng.split();
            let offset = start + (stem.length - start) * (i as f32 + 0.5) / count as f32;
            let along = chain_offset + offset;
            // Crown position r: 1 at the crown base, 0 at the top (as in `crate::crown`).
            let crown_span = stem_len - self.crown_base;
            let crown_r = if crown_span > 0.0 { (stem_len - along) / crown_span } else { 0.0 };
            let length = if child == 1 {
                let ratio = match &self.drawn {
                    Some(d) => d.ratio_at_height(stem.point(offset / stem.length).y),
                    None => p.shape.ratio(crown_r),
                };
                stem_len * (cp.length + crng.var(cp.length_v)) * ratio
            } else {
                (cp.length + crng.var(cp.length_v)) * (stem_len - 0.6 * along)
            };
            let mut down = if cp.down_angle_v >= 0.0 {
                cp.down_angle + crng.var(cp.down_angle_v)
            } else {
                let r = (stem_len - along) / stem_len;
                cp.down_angle + cp.down_angle_v * (1.0 - 2.0 * CrownShape::Conical.ratio(r))
            };
            if child == 1 {
                down += p.angle_spread * (2.0 * CrownShape::Conical.ratio(crown_r) - 1.0);
            }
            rot = if cp.rotate >= 0.0 {
                rot + cp.rotate + crng.var(cp.rotate_v)
            } else {
                let side = if i % 2 == 0 { 1.0 } else { -1.0 };
                side * (180.0 + cp.rotate) + crng.var(cp.rotate_v)
            };
            let radius = (stem.chain_radius * pow(length / stem_len, p.ratio_power))
                .min(stem.radius_at(offset / stem.length))
                .max(MIN_RADIUS);
            if length < (2.0 * radius).max(MIN_LENGTH) {
                continue; // shorter than its own thickness: it would sit inside the parent
            }
            let (pos, dir) = stem.point_at(offset);
            // Parent frame at the attachment point: its +Y along `dir`, +X transported from the base.
            let x = unit_or(stem.base_normal - dir * stem.base_normal.dot(dir), || dir.any_orthonormal_vector());
            let parent_frame = Quat::from_mat3(&glam::Mat3::from_cols(x, dir, x.cross(dir)));
            let frame = (parent_frame * math::quat_rotation_y(rad(rot)) * math::quat_rotation_x(rad(down))).normalize();
            self.grow(StemStart {
                level: child,
                parent: Some(index),
                offset,
                base: pos,
                frame,
                length,
                radius,
                down_angle: down,
                first_seg: 0,
                correction: 0.0,
                rng: crng,
            })?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn taper_modes() {
        // Cone to a point, cylinder, half taper.
        assert!((taper_radius(1.0, 1.0, 10.0, 0.5) - 0.5).abs() < 1e-6);
        assert_eq!(taper_radius(1.0, 0.0, 10.0, 0.9), 1.0);
        assert!((taper_radius(1.0, 0.5, 10.0, 1.0) - 0.5).abs() < 1e-6);
        // 1 < taper <= 2: full radius until one radius from the tip, then a hemisphere closing to 0.
        assert!((taper_radius(1.0, 2.0, 10.0, 0.5) - 1.0).abs() < 1e-6);
        assert!(taper_radius(1.0, 2.0, 10.0, 1.0).abs() < 1e-3);
    }

    #[test]
    fn points_are_the_samples_positions_exactly() {
        // `Stem::point`, `StemPoints::at` and `StemPoints::sample` (the fork search's and the
        // foliage's cheap readers) must give the very bits of `Stem::sample`, forward, backward
        // and jumping between segments: the forks and leaves, so the golden hashes, depend on them.
        let p = crate::presets::find("weeping_willow").unwrap().params().unwrap();
        let sk = build(&p.skeleton).unwrap();
        for stem in sk.stems.iter().step_by(97) {
            let mut cursor = stem.points();
            for k in (0..=300).chain((0..=300).rev()).chain([0, 300, 7, 290, 150]) {
                let t = k as f32 / 300.0;
                let want = stem.sample(t);
                assert_eq!(stem.point(t), want.0);
                assert_eq!(cursor.at(t), want.0);
                assert_eq!(cursor.sample(t), want);
            }
        }
    }

    #[test]
    fn flare_only_near_ground() {
        assert!((flare_factor(1.0, 0.0) - 1.99).abs() < 1e-5);
        assert_eq!(flare_factor(1.0, 0.2), 1.0);
        assert_eq!(flare_factor(0.0, 0.0), 1.0);
    }

    #[test]
    fn trunk_first_children_inside_crown() {
        let p = SkeletonParams::default();
        let s = build(&p).unwrap();
        assert_eq!(s.stems[0].level, 0);
        assert_eq!(s.stems.iter().filter(|st| st.level == 1).count(), 50);
        for st in s.stems.iter().filter(|st| st.level == 1) {
            assert!(st.offset >= s.crown_base - 1e-4, "branch below crown base");
            assert!(st.radius <= s.stems[0].radius_at(st.offset / s.stems[0].length) + 1e-6);
        }
        // Every child starts on its parent's axis.
        for st in &s.stems[1..] {
            let parent = &s.stems[st.parent.unwrap() as usize];
            let (pt, _) = parent.point_at(st.offset);
            assert!(pt.distance(st.base()) < 1e-4);
        }
    }

    #[test]
    fn every_stem_records_its_kind() {
        let mut p = crate::presets::find("ca_black_oak").unwrap().params().unwrap();
        p.skeleton.root_count = 5;
        let sk = build(&p.skeleton).unwrap();
        let kinds = |k: StemKind| sk.stems.iter().filter(|s| s.kind == k).count();
        assert_eq!(sk.mode, GrowthMode::Parametric);
        assert_eq!(sk.stems[0].kind, StemKind::Trunk);
        assert_eq!(kinds(StemKind::Trunk), 1);
        assert!(kinds(StemKind::SplitClone) > 10, "the oak splits");
        assert_eq!(kinds(StemKind::Root), 5);
        assert_eq!(sk.first_root(), sk.stems.len() - 5);
        for (i, s) in sk.stems.iter().enumerate() {
            let parent = s.parent.map(|q| &sk.stems[q as usize]);
            match s.kind {
                StemKind::Trunk => assert!(parent.is_none() && s.lobed),
                StemKind::SplitClone => assert!(parent.unwrap().level == s.level && s.chain_start > 0.0),
                StemKind::Branch => assert!(parent.unwrap().level + 1 == s.level && i < sk.first_root()),
                StemKind::Root => assert!(s.parent == Some(0) && i >= sk.first_root()),
            }
        }
    }

    #[test]
    fn editing_a_deeper_level_keeps_the_upper_levels() {
        let a = build(&SkeletonParams::default()).unwrap();
        let mut p = SkeletonParams::default();
        p.level[2].curve_v = 10.0;
        let b = build(&p).unwrap();
        let level1 = |s: &Skeleton| s.stems.iter().filter(|st| st.level <= 1).map(|st| st.tip()).collect::<Vec<_>>();
        assert_eq!(level1(&a), level1(&b));
    }

    #[test]
    fn runaway_tree_hits_the_budget_early() {
        let mut p = SkeletonParams::default();
        p.levels = 4;
        p.level[1].branches = 500;
        p.level[2].branches = 500;
        p.level[3].branches = 500;
        p.max_vertices = 100_000;
        let e = build(&p).unwrap_err();
        assert!(matches!(e, SylvaError::Budget { .. }), "{e}");
        assert!(e.message().contains("max_vertices budget of 100000"), "{e}");
    }
}
