//! # Age: a tree's growth replayed to a younger age
//!
//! (A Weber & Penn tree's; a grown tree is brought to its Age by its annual flushes of growth
//! iterations instead, [`crate::growth::skeleton_by_years`].)
//!
//! The skeleton stage builds the tree as it is at its **Mature Age** (the form its other
//! parameters describe); with **Age** below it, this replays the growth that led there: every
//! stem gets a birth year and grows from it along a growth curve, so a young tree is the mature
//! tree's own earlier self and grows smoothly into it. At Age = Mature Age nothing changes (every
//! preset's default Age is its Mature Age, so every tree is today's, byte for byte); past it the
//! tree keeps its mature form, changed only by the life over decades of [`crate::life`]
//! (shedding, thickening, drooping).
//!
//! **Birth years.** The trunk is born in year 0. A branch is born the year after the stem it
//! grows on has reached the branch's attachment point ([`BUD_DELAY`]: its bud opens the next
//! spring), but no later than [`MIN_GROWING`] years before the Mature Age, so every stem has time
//! to grow. A clone of a split is part of its stem's chain: it appears when the chain has grown to
//! the split. So a stem's birth year follows from its level and its offset along its parent.
//!
//! **Growth curve.** A stem's chain (the Weber & Penn stem with its split clones) born in year
//! `b` reaches fraction `g(τ)` of its final length at `τ = (age - b) / (mature - b)` of its growing
//! time, with `g` the Chapman-Richards height curve used in forest growth and yield (Richards
//! 1959, *A flexible growth function for empirical use*; Pienaar & Turnbull 1973), normalised
//! to reach 1 at maturity: `g(τ) = ((1 - e^(-kτ)) / (1 - e^(-k)))^c` with `k` = [`GROWTH_RATE`]
//! and `c` = [`GROWTH_SHAPE`]: fast at first, slowing toward the mature length. Its radius grows
//! by a constant ring width, `τ` of the final radius (secondary growth adds about one ring a
//! year; Kozlowski & Pallardy 1997, *Growth Control in Woody Plants*, ch. 3). Growth happens at
//! the tip: the part of a stem already grown keeps its place and shape, the young stem is the
//! base part of the mature one's centre curve, and its taper is the mature taper over its young
//! length (its tip closes as a mature tip does). Stems not yet born, or shorter than
//! [`MIN_SHOOT`] (still a bud), are absent, with everything on them.
//!
//! Lengths and radii only grow with age and grown parts never move, so the tree's bounds grow
//! monotonically with Age.

use crate::edits::cut::reattach_children;
use crate::edits::stems::{remove, Children};
use crate::math::{exp, ln, pow};
use crate::skeleton::{Points, Skeleton, StemKind};

/// `k` of the growth curve: how early growth slows (larger: faster early growth).
pub const GROWTH_RATE: f32 = 4.0;
/// `c` of the growth curve: 1 starts at full speed; above 1 makes an S-shaped start.
pub const GROWTH_SHAPE: f32 = 1.0;
/// Years from a stem reaching a bud's place to the bud opening.
pub const BUD_DELAY: f32 = 1.0;
/// Fewest years a stem grows before the Mature Age.
pub const MIN_GROWING: f32 = 1.0;
/// Shortest chain length divided by (m).
pub const MIN_LENGTH: f32 = 1e-3;
/// A young stem shorter than this is still a bud: not drawn (m; four of the thinnest radius, so
/// a just-born stem is never a stub as wide as it is long).
pub const MIN_SHOOT: f32 = 4.0 * MIN_RADIUS;
/// Thinnest stem (m), the skeleton's smallest radius.
const MIN_RADIUS: f32 = 1e-3;
/// Fewest segments a young stem's centre polyline gets.
const MIN_SEGMENTS: usize = 2;

/// Fraction of its final length a stem has at fraction `tau` of its growing time (0 before its
/// birth, 1 from its maturity on).
pub fn length_fraction(tau: f32) -> f32 {
    if tau <= 0.0 {
        return 0.0;
    }
    if tau >= 1.0 {
        return 1.0;
    }
    let k = GROWTH_RATE;
    pow((1.0 - exp(-k * tau)) / (1.0 - exp(-k)), GROWTH_SHAPE)
}

/// The fraction of its growing time at which a stem reaches fraction `f` of its final length
/// (the inverse of [`length_fraction`]).
pub fn time_to_length(f: f32) -> f32 {
    if f <= 0.0 {
        return 0.0;
    }
    if f >= 1.0 {
        return 1.0;
    }
    let k = GROWTH_RATE;
    -ln(1.0 - pow(f, 1.0 / GROWTH_SHAPE) * (1.0 - exp(-k))) / k
}

/// Each stem's chain birth year: the year its Weber & Penn stem (a clone: the stem it split
/// from) was born.
pub fn birth_years(skeleton: &Skeleton, mature: f32) -> Vec<f32> {
    let mut birth: Vec<f32> = Vec::with_capacity(skeleton.stems.len());
    for s in &skeleton.stems {
        let b = match (s.kind, s.parent) {
            (_, None) => 0.0,
            (StemKind::SplitClone, Some(p)) => birth[p as usize],
            (_, Some(p)) => {
                let parent = &skeleton.stems[p as usize];
                // The attachment point as a fraction of the parent's whole chain.
                let along = parent.chain_start + s.offset / parent.chain_length.max(MIN_LENGTH);
                bud_birth(birth[p as usize], along, mature)
            }
        };
        birth.push(b);
    }
    birth
}

/// The birth year of a branch whose bud sits at fraction `along` of its parent's whole chain, the
/// parent's chain born in year `parent_birth`: the year after the parent reached it, at the
/// latest [`MIN_GROWING`] years before `mature`.
pub fn bud_birth(parent_birth: f32, along: f32, mature: f32) -> f32 {
    let reached = parent_birth + (mature - parent_birth) * time_to_length(along);
    (reached + BUD_DELAY).min((mature - MIN_GROWING).max(reached))
}

/// Dates the wood of `skeleton`, built as it is at age `mature`: each record's
/// [`born`](crate::skeleton::Stem::born) (the year its base wood grew: its chain's birth year, or
/// for a split clone the year its chain reached the split) and
/// [`tip_year`](crate::skeleton::Stem::tip_year) (`mature`: a mature chain reaches its tip then).
pub fn date(skeleton: &mut Skeleton, mature: f32) {
    let birth = birth_years(skeleton, mature);
    for (s, b) in skeleton.stems.iter_mut().zip(birth) {
        s.born = b + (mature - b) * time_to_length(s.chain_start);
        s.tip_year = mature;
    }
}

/// Brings `skeleton`, built as it is at age `mature` and [`date`]d, to age `age` (years);
/// nothing changes at or past `mature`. See the module doc.
pub fn replay(skeleton: &mut Skeleton, age: f32, mature: f32) {
    if age >= mature {
        return;
    }
    let birth = birth_years(skeleton, mature);
    let n = skeleton.stems.len();
    let mut gone = vec![false; n];
    for i in 0..n {
        if let Some(p) = skeleton.stems[i].parent {
            if gone[p as usize] {
                gone[i] = true;
                continue;
            }
        }
        let s = &skeleton.stems[i];
        // A branch is born after its parent reached it; one attached past its young parent's tip
        // by rounding goes too (the parent, earlier in the list, is already young).
        if let Some(p) = s.parent.filter(|_| s.kind != StemKind::Root) {
            if s.offset > skeleton.stems[p as usize].length {
                gone[i] = true;
                continue;
            }
        }
        let tau = (age - birth[i]) / (mature - birth[i]).max(1e-3);
        let reached = length_fraction(tau);
        // The record spans the chain from its start to the chain's end.
        let kept = (reached - s.chain_start) / (1.0 - s.chain_start).max(1e-6);
        // A shoot shows once it is longer than a few of the thinnest radius (a bud before that;
        // a constant, so a stem once shown stays).
        if kept <= 0.0 || kept * s.length < MIN_SHOOT {
            gone[i] = true;
            continue;
        }
        young(skeleton, i, kept.min(1.0), reached, tau.clamp(0.0, 1.0));
        // A young tip is this year's wood.
        skeleton.stems[i].tip_year = age;
    }
    // The kept children sit on their young parent's resampled curve exactly.
    let children = Children::of_skeleton(skeleton);
    for i in 0..n {
        if !gone[i] {
            reattach_children(skeleton, &children, i, &gone);
        }
    }
    remove(skeleton, &gone);
}

/// Stem `i` as it is young: the first `kept` of its centre curve, the mature taper over the
/// chain's young length `reached` (a fraction of its final length), radii `tau` of the final.
fn young(skeleton: &mut Skeleton, i: usize, kept: f32, reached: f32, tau: f32) {
    let s = &skeleton.stems[i];
    let segs = (s.points.len() - 1).max(MIN_SEGMENTS);
    let mut cursor = s.points();
    let points: Points = (0..=segs).map(|k| cursor.at(kept * k as f32 / segs as f32)).collect();
    let radii = s
        .radii
        .as_ref()
        .map(|_| (0..=segs).map(|k| (s.radius_at(kept * k as f32 / segs as f32) * tau).max(MIN_RADIUS)).collect());
    let s = &mut skeleton.stems[i];
    s.points = points;
    s.radii = radii;
    s.length *= kept;
    s.radius = (s.radius * tau).max(MIN_RADIUS);
    s.chain_radius = (s.chain_radius * tau).max(MIN_RADIUS);
    s.chain_length *= reached;
    s.chain_start /= reached;
}
