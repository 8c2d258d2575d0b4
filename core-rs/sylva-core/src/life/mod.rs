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
use crate::skeleton::Skeleton;

/// The years past `p`'s Mature Age acted on `skeleton` (see the module doc).
pub fn live(skeleton: &mut Skeleton, p: &SkeletonParams) {
    let years = p.age - p.maturity;
    if years <= 0.0 {
        return;
    }
    thicken::thicken(skeleton, p.ring_width * 1e-3 * years);
    shed::shed(skeleton, p.shed_light, p.shed_years, (p.maturity, p.age));
    droop::droop(skeleton, p.droop * years / 10.0);
}
