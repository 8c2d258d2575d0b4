//! # Life over decades: the tree past its Mature Age
//!
//! The skeleton stage builds a tree as it is at its Mature Age ([`crate::age`] replays the
//! years before); with Age past it, these processes act over the years since, in this order:
//!
//! 1. **Secondary thickening** ([`thicken`]): a ring of new wood a year, shared by the pipe
//!    model (Shinozaki et al. 1964, *A quantitative analysis of plant form: the pipe model
//!    theory*): each stem's new wood is in proportion to the shoot tips it carries.
//! 2. **Shedding** ([`shed`]): a branch whose shoots stay in the shade dies and drops, leaving
//!    a stub out of the (thickened) bark that woundwood closes over, a knot (Palubicki et al.
//!    2009, *Self-organizing tree models for image synthesis*, §4: shaded branches receive too
//!    little light to live).
//! 3. **Gravity bending** ([`droop`]): main branches sink under their growing load, the outer
//!    part turning up again (the tip's gravitropism), as a uniformly loaded cantilever bends
//!    (Alméras & Fournier 2009, *Biomechanical design and long-term stability of trees*).
//!
//! The fourth, **leaves only on recent wood** (Leafy Years), is the foliage stage's: it reads
//! the dates [`crate::age::date`] gives every stem. At Age = Mature Age (every preset's default)
//! nothing here runs, so every tree is today's, byte for byte.

pub mod droop;
pub mod shed;
pub mod thicken;

use crate::params::SkeletonParams;
use crate::skeleton::{LifeRecord, Skeleton};
use std::sync::Arc;

impl LifeRecord {
    /// The tree in `year` (from the Mature Age to the Age): thickened and sunk by the years to
    /// it; the branches dead by the Age are shed, their stubs as old as they are in `year` (a
    /// fresh cut before the branch's death: the animation has no wood for a branch the tree
    /// as built has lost). At the Age, the tree as built.
    pub fn at(&self, year: f32) -> Skeleton {
        let (mature, age) = self.years;
        let seen = year.clamp(mature, age);
        let years = seen - mature;
        // The branches are shed (and their stubs cut) as the tree at its Age has them, so
        // every year has the same stems; an earlier year's thinner stems follow those cuts.
        let mut s = self.mature.clone();
        thicken::thicken(&mut s, self.ring * (age - mature));
        let mut then = (seen < age).then(|| {
            let mut t = self.mature.clone();
            thicken::thicken(&mut t, self.ring * years);
            t
        });
        shed::shed(&mut s, self.shed.0, self.shed.1, (mature, age), seen, then.as_mut());
        let mut s = then.unwrap_or(s);
        droop::droop(&mut s, self.droop * years / 10.0);
        s
    }
}

/// The years past `p`'s Mature Age acted on `skeleton` (see the module doc); the skeleton
/// keeps the record of them ([`LifeRecord`]).
pub fn live(skeleton: &mut Skeleton, p: &SkeletonParams) {
    let years = p.age - p.maturity;
    if years <= 0.0 {
        return;
    }
    let record = LifeRecord {
        mature: skeleton.clone(),
        ring: p.ring_width * 1e-3,
        shed: (p.shed_light, p.shed_years),
        droop: p.droop,
        years: (p.maturity, p.age),
    };
    *skeleton = record.at(p.age);
    skeleton.life = Some(Arc::new(record));
}
