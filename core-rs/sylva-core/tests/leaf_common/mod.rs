//! Helpers shared by the leaf tests.
#![allow(dead_code)]

use sylva_core::leaf::{margin, outline, triangulate, Outline, Triangulation};
use sylva_core::params::{registry, ParamKind};
use sylva_core::rng::Rng;
use sylva_core::TreeParams;

/// Outline, margin and triangulation only (no veins: fast).
pub fn stages(p: &TreeParams) -> (Outline, Triangulation) {
    try_stages(p).unwrap_or_else(|e| panic!("{e}"))
}

/// [`stages`], or the error of parameters whose blade has no area.
pub fn try_stages(p: &TreeParams) -> Result<(Outline, Triangulation), sylva_core::SylvaError> {
    let base = outline::build(&p.leaf);
    let o = margin::build(&p.leaf, &base)?;
    let t = triangulate::build(&o, p.leaf.leaf_rings);
    Ok((o, t))
}

/// A random value of a registry parameter on its slider grid.
fn random_value(id: &str, rng: &mut Rng) -> f64 {
    let s = registry().iter().find(|s| s.id == id).unwrap();
    let steps = ((s.max - s.min) / s.step).floor();
    let k = (f64::from(rng.next_f32()) * (steps + 1.0)).floor().min(steps);
    let v = (s.min + k * s.step).min(s.max);
    if s.kind == ParamKind::Float {
        v
    } else {
        v.round()
    }
}

/// Random values for every leaf parameter over its whole registry range (slower vein settings
/// kept moderate), with attraction above kill.
pub fn random_leaf_params(rng: &mut Rng) -> TreeParams {
    let mut p = TreeParams::default();
    for s in registry().iter().filter(|s| s.id.starts_with("leaf_")) {
        let v = random_value(&s.id, rng);
        p.set(&s.id, v).unwrap();
    }
    p.leaf.leaf_vein_density = p.leaf.leaf_vein_density.min(3000.0);
    p.leaf.leaf_growth_step = p.leaf.leaf_growth_step.max(0.008);
    p.leaf.leaf_texture_level = p.leaf.leaf_texture_level.min(7);
    if p.leaf.leaf_attraction <= p.leaf.leaf_kill {
        p.leaf.leaf_attraction = (p.leaf.leaf_kill * 3.0).min(0.5);
    }
    p
}
