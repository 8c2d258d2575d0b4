//! Each stem's life, read back from the tree as built: the growth replay of [`crate::age`] run
//! again on the stems of a generated tree, so the growth animation can say how long and how
//! thick every stem of it was in any earlier year.
//!
//! The tree was built at its Age `A` (at most its Mature Age `M`): a stem there is the mature
//! stem's young self, its length `kept` of the mature length, its chain `reached` of the mature
//! chain and its radii `tau` of the mature radii ([`crate::age`]). Walking the stems in order
//! (parents first), each stem's birth year follows from its parent's mature chain as in
//! [`crate::age::birth_years`], and its mature chain from its birth year and the young record.
//! A year `Y ≤ A` then gives each stem its young length (or none: not born, still a bud, or
//! on a parent too short to carry it, the same rules as [`crate::age::replay`]) and its radius
//! along it. Lengths are metres along the stem as built: a young stem is the base part of it
//! (grown wood never moves).

use crate::age::{bud_birth, length_fraction, MIN_LENGTH, MIN_SHOOT};
use crate::skeleton::{flare_factor, taper_radius, Skeleton, Stem, StemKind};

/// A stem's mature chain and birth, reconstructed from its record as built.
#[derive(Clone, Copy, Debug)]
struct Life {
    birth: f32,
    /// Fraction of the whole mature chain where this record starts.
    chain_start: f32,
    /// Length of the whole mature chain (m).
    chain_length: f32,
    /// Length of the mature record (m).
    length: f32,
    /// Base radius of the whole mature chain (m).
    chain_radius: f32,
    /// The radius fraction `tau` the stem had as built.
    tau: f32,
}

/// Every stem's life ([`Lives::year`] gives the stems in one year).
#[derive(Clone, Debug)]
pub struct Lives {
    stems: Vec<Life>,
    mature: f32,
    /// The age the tree was built at, at most `mature` (older trees keep the mature form).
    built: f32,
    /// A grown tree: its stems are dated by their annual flushes ([`Stem::born`] at the base,
    /// [`Stem::tip_year`] at the tip, the wood between grown evenly), which give their lengths.
    dated: bool,
}

/// One stem in one year: how long (m, from its base along the stem as built) and how thick.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Young {
    /// Length (m), at most the length as built.
    pub length: f32,
    /// Radius fraction of the mature stem (the ring width times the years grown).
    pub tau: f32,
    /// Fraction of the mature chain's length the chain has.
    pub reached: f32,
}

impl Lives {
    /// The lives of the stems of `skeleton`, built at age `age` with Mature Age `mature`.
    pub fn new(skeleton: &Skeleton, age: f32, mature: f32) -> Lives {
        let built = age.min(mature);
        let mut stems: Vec<Life> = Vec::with_capacity(skeleton.stems.len());
        for s in &skeleton.stems {
            let birth = match (s.kind, s.parent) {
                (_, None) => 0.0,
                (StemKind::SplitClone, Some(p)) => stems[p as usize].birth,
                (_, Some(p)) => {
                    let parent = &stems[p as usize];
                    bud_birth(parent.birth, parent.chain_start + s.offset / parent.chain_length.max(MIN_LENGTH), mature)
                }
            };
            let (tau, reached) = if age >= mature {
                (1.0, 1.0)
            } else {
                let tau = (built - birth) / (mature - birth).max(1e-3);
                (tau.clamp(1e-6, 1.0), length_fraction(tau).max(1e-6))
            };
            let chain_start = s.chain_start * reached;
            let kept = ((reached - chain_start) / (1.0 - chain_start).max(1e-6)).clamp(1e-6, 1.0);
            stems.push(Life {
                birth,
                chain_start,
                chain_length: s.chain_length / reached,
                length: s.length / kept,
                chain_radius: s.chain_radius / tau,
                tau,
            });
        }
        let dated = skeleton.mode == crate::params::GrowthMode::SpaceColonization;
        Lives { stems, mature, built, dated }
    }

    /// A grown tree's stem `s` in `year` (see [`Lives::dated`]): its wood grew evenly from its
    /// base's year to its tip's, and its radius by the years since its birth.
    fn dated_year(&self, s: &Stem, year: f32) -> Option<Young> {
        if year < s.born {
            return None;
        }
        let grown = ((year - s.born) / (s.tip_year - s.born).max(1e-3)).clamp(0.0, 1.0);
        let length = s.length * grown;
        if length < MIN_SHOOT {
            return None;
        }
        let tau = ((year - s.born) / (self.built - s.born).max(1e-3)).clamp(1e-6, 1.0);
        Some(Young { length, tau, reached: grown.max(1e-6) })
    }

    /// Each stem in year `year` (clamped to the age the tree was built at), `None` where it is
    /// absent: not born yet, still a bud, or its parent absent or shorter than its offset.
    pub fn year(&self, skeleton: &Skeleton, year: f32) -> Vec<Option<Young>> {
        let year = year.min(self.built);
        let mut out: Vec<Option<Young>> = Vec::with_capacity(self.stems.len());
        for (s, l) in skeleton.stems.iter().zip(&self.stems) {
            let parent = s.parent.map(|p| out[p as usize]);
            if parent == Some(None) {
                out.push(None);
                continue;
            }
            if let Some(Some(p)) = parent.filter(|_| s.kind != StemKind::Root) {
                if s.offset > p.length {
                    out.push(None);
                    continue;
                }
            }
            if self.dated {
                out.push(self.dated_year(s, year));
                continue;
            }
            let tau = (year - l.birth) / (self.mature - l.birth).max(1e-3);
            let reached = length_fraction(tau);
            let kept = (reached - l.chain_start) / (1.0 - l.chain_start).max(1e-6);
            if kept <= 0.0 || kept * l.length < MIN_SHOOT {
                out.push(None);
                continue;
            }
            let length = (l.length * kept.min(1.0)).min(s.length);
            out.push(Some(Young { length, tau: tau.clamp(0.0, 1.0), reached }));
        }
        out
    }

    /// The radius (m) of stem `i` (`stem` as built) in its young state `y`, at `d` metres from
    /// its base (within `y.length`): its radii as built scaled by the ring width for a stem with
    /// radii of its own, else the mature taper over the young chain ([`crate::age`]).
    pub fn radius(&self, i: usize, stem: &Stem, y: &Young, d: f32) -> f32 {
        let l = &self.stems[i];
        if self.dated {
            return stem.radius_at(d / stem.length.max(1e-6)) * y.tau;
        }
        if stem.radii.is_some() {
            return stem.radius_at(d / stem.length.max(1e-6)) * y.tau / l.tau;
        }
        let start = l.chain_start / y.reached.max(1e-6);
        let zc = start + d / y.length.max(1e-6) * (1.0 - start);
        taper_radius(l.chain_radius * y.tau, stem.taper, l.chain_length * y.reached, zc) * flare_factor(stem.flare, zc)
    }
}
