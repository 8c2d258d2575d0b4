//! Skeleton stage: parameters -> stems (centre polylines with a radius profile), after Weber &
//! Penn, "Creation and Rendering of Realistic Trees" (SIGGRAPH 1995) with the paper's formulas:
//! stem lengths (level 1 scaled by the crown ShapeRatio), radii with RatioPower and
//! child <= parent at the attachment point, taper modes, trunk flare, curvature (Curve,
//! CurveBack, CurveV), DownAngle/Rotate with their negative variants, branch counts with error
//! diffusion, AttractionUp and Angle Spread.
//!
//! Every stem draws from its own generator split off its parent's, so editing a deeper level
//! never changes the stems above it.
//!
//! Here: the [`Skeleton`] and the vertex budget. The growth, stem by stem, is in `grow`, one
//! record's polyline (bends, splits, pruning) in `trace`, a stem's curve and radii in `stem`,
//! the trunk's guide curve and roots in `trunk`.

mod envelope;
mod grow;
mod life_record;
mod stem;
mod trace;
mod trunk;

pub use envelope::{preview_profile, preview_profile_with_crown};
pub use grow::build_with_crown;
pub use stem::{flare_factor, taper_radius, Points, Segment, Stem, StemKind, StemPoints};

use crate::edits::crown::DrawnCrown;
use crate::error::SylvaError;
use crate::params::{Crown, CrownShape, GrowthMode, SkeletonParams};
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

/// Build the skeleton. Fails only on the vertex budget (parameters are validated before).
pub fn build(p: &SkeletonParams) -> Result<Skeleton, SylvaError> {
    build_with_crown(p, None)
}

/// The drawn crown that shapes `p`'s tree: `crown`'s, when Crown Shape is Drawn.
pub(crate) fn drawn_crown(p: &SkeletonParams, crown: Option<&Crown>) -> Option<DrawnCrown> {
    crown.filter(|_| p.shape == CrownShape::Drawn).and_then(DrawnCrown::new)
}

impl Skeleton {
    /// The skeleton of `stems` made by `mode`, with `p`'s seed, levels, budget and ages and
    /// no life record.
    pub(crate) fn of(p: &SkeletonParams, mode: GrowthMode, stems: Vec<Stem>, scale: f32, crown_base: f32) -> Skeleton {
        Skeleton {
            mode,
            stems,
            scale,
            crown_base,
            seed: p.seed,
            levels: p.levels,
            max_vertices: p.max_vertices,
            age: p.age,
            maturity: p.maturity,
            life: None,
        }
    }

    /// Index of the first root ([`StemKind::Root`]): roots come after every other stem, so
    /// `0..first_root()` are the tree's own stems (`stems.len()` when there is no root).
    pub fn first_root(&self) -> usize {
        self.stems.iter().position(|s| s.kind == StemKind::Root).unwrap_or(self.stems.len())
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
