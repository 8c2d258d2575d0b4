//! Secondary thickening past the Mature Age, by the pipe model (Shinozaki et al. 1964, *A
//! quantitative analysis of plant form: the pipe model theory*): the trunk's base radius grows
//! by the Ring Width a year, and the cross-section area that adds is shared among the stems in
//! proportion to the shoot tips each carries (every tip is fed by its own pipe down to the
//! roots). A stem's radii all grow by one factor, `sqrt(r² + a / π) / r` at its base, so its
//! taper keeps its shape; a split clone grows with the stem it split from, and the roots with
//! the trunk.

use crate::skeleton::{Skeleton, StemKind};

/// Thickens `skeleton` by `ring` metres of trunk base radius (see the module doc).
pub fn thicken(skeleton: &mut Skeleton, ring: f32) {
    if ring <= 0.0 || skeleton.stems.is_empty() {
        return;
    }
    let n = skeleton.stems.len();
    // Shoot tips per stem (children come after parents).
    let mut tips = vec![0u32; n];
    let mut has_child = vec![false; n];
    for s in &skeleton.stems {
        if let Some(p) = s.parent.filter(|_| s.kind != StemKind::Root) {
            has_child[p as usize] = true;
        }
    }
    for i in (0..n).rev() {
        let s = &skeleton.stems[i];
        if s.kind == StemKind::Root {
            continue;
        }
        if !has_child[i] {
            tips[i] += 1;
        }
        if let Some(p) = s.parent {
            tips[p as usize] += tips[i];
        }
    }
    let r0 = skeleton.stems[0].radius.max(1e-3);
    let added = std::f32::consts::PI * ((r0 + ring) * (r0 + ring) - r0 * r0);
    let all = tips[0].max(1) as f32;
    let mut factor = vec![1.0f32; n];
    for i in 0..n {
        let s = &skeleton.stems[i];
        factor[i] = match (s.kind, s.parent) {
            (StemKind::SplitClone, Some(p)) => factor[p as usize],
            (StemKind::Root, _) => factor[0],
            _ => {
                let r = s.radius.max(1e-4);
                let a = added * tips[i] as f32 / all;
                (r * r + a / std::f32::consts::PI).sqrt() / r
            }
        };
    }
    for (s, &f) in skeleton.stems.iter_mut().zip(&factor) {
        s.radius *= f;
        s.chain_radius *= f;
        if let Some(r) = s.radii.as_mut() {
            r.iter_mut().for_each(|x| *x *= f);
        }
    }
}
