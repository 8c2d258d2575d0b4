//! Stage 5, the vein network (Mtree's *Leaf Generation Guide* §4; Runions et al. 2005; Michel Anders
//! 2013, "OSL leaf veins shader for Cycles", blog.michelanders.nl).
//!
//! * [`colonize`]: space colonization from a root at the petiole, Open (a tree) or Closed (a
//!   source associates with every node in its relative neighbourhood and dies when all have
//!   reached it, which joins veins into real loops), accelerated by uniform grids.
//! * [`primary`]: the species' primary veins (pinnate, palmate, dichotomous) that colonization
//!   starts from instead of the petiole alone.
//! * [`spline`]: arcuate / pinnate veins as quadratic splines from the midrib to the edge.
//!
//! Both give a [`VeinGraph`]: nodes with a parent (a tree rooted at the petiole) plus loop
//! links, every node and link stamped with the iteration it was born in, so a step slider can
//! replay the growth. Widths follow the pipe model (Shinozaki 1964; da Vinci's rule with
//! exponent 2): `width = vein_width × sqrt(tips downstream / all tips)`, so the midrib is the
//! thickest and no vein gets wider toward its tips.

pub mod auxins;
pub mod colonize;
mod graph;
pub mod grid;
pub mod primary;
pub mod spline;

pub use graph::{Auxin, VeinGraph, VeinLink, VeinNode, Veins, NONE};

use crate::leaf::margin::Outline;
use crate::leaf::raster::Mask;
use crate::params::LeafParams;
use crate::params::LeafVenation;
use crate::rng::Rng;

/// Most auxin sources a leaf gets.
pub const MAX_AUXINS: usize = 5_000;

/// Stage 5: the network chosen by `leaf_venation`.
pub fn build(p: &LeafParams, outline: &Outline, mask: &Mask) -> Veins {
    let mut veins = match p.leaf_venation {
        LeafVenation::None => Veins::default(),
        LeafVenation::Open | LeafVenation::Closed => {
            let mut rng = Rng::new(u64::from(p.leaf_vein_seed), "leaf-veins");
            let area = crate::leaf::geom::polygon_area(&outline.points).abs();
            let count = ((f64::from(p.leaf_vein_density) * area).round() as usize).min(MAX_AUXINS);
            let settings = colonize::Settings {
                attraction: p.leaf_attraction,
                kill: p.leaf_kill,
                step: p.leaf_growth_step,
                closed: p.leaf_venation == LeafVenation::Closed,
            };
            let sources = auxins::place(&outline.points, area, mask, count, settings.kill, &mut rng);
            let seed = primary::build(p, outline, mask);
            colonize::grow_from(&settings, mask, &sources, &seed, &mut rng)
        }
        LeafVenation::Spline => Veins { graph: spline::build(p, outline, mask), auxins: Vec::new() },
    };
    veins.graph.assign_widths(p.leaf_vein_width);
    veins
}
