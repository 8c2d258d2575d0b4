//! Shedding: past the Mature Age a branch whose shoots stay in the shade dies, drops and
//! leaves a stub, which woundwood closes over in the years after (a scar, a knot in the bark).
//!
//! The light is the crown's light field ([`CrownLight`], Beer–Lambert through the foliage, the
//! field that shades the leaves and the bark), built here from the shoots: every terminal stem
//! carries leaf area in proportion to its length, [`LEAF_AREA_INDEX`] times the crown's ground
//! area in all. A branch's light is the mean sky its terminal shoots see. Below the Shedding
//! Light it dies after `delay · sky / (threshold - sky)` years (the Shedding Delay for one at
//! half the threshold; the darkest go at once, those near the threshold only after many
//! decades), so over the decades the shaded lower and inner branches drop one after another, as in Palubicki et al. 2009 (*Self-organizing tree
//! models for image synthesis*, §4), where a branch that gathers too little light is shed. The
//! field is the mature crown's: the light a drop lets through is not given back to the others.

use crate::crown_shade::CrownLight;
use crate::edits::cut::{cut_by, plan};
use crate::skeleton::{Skeleton, StemKind};
use glam::Vec3;

/// Leaf area per unit of the crown's ground area (m²/m²): a closed broadleaf crown holds 3 to 6.
pub const LEAF_AREA_INDEX: f32 = 4.0;
/// A stub reaches this many of the branch's base radii (plus [`STUB_EXTRA`]) out of its parent's
/// bark: dead branches break off a little way out from the collar.
pub const STUB_RADII: f32 = 2.5;
/// Extra stub length (m).
pub const STUB_EXTRA: f32 = 0.02;

/// Which stems have leaves at their ends: no children of their own and not roots.
fn terminal(skeleton: &Skeleton) -> Vec<bool> {
    let mut leafy: Vec<bool> = skeleton.stems.iter().map(|s| s.kind != StemKind::Root).collect();
    for s in &skeleton.stems {
        if let Some(p) = s.parent {
            leafy[p as usize] = false;
        }
    }
    leafy
}

/// The crown's light field from its shoots (see the module doc), or `None` without any.
pub fn shoot_light(skeleton: &Skeleton) -> Option<CrownLight> {
    let leafy = terminal(skeleton);
    let mut samples: Vec<(Vec3, f32)> = Vec::new();
    let (mut total, mut reach) = (0.0f32, 0.0f32);
    for (s, _) in skeleton.stems.iter().zip(&leafy).filter(|(_, &l)| l) {
        for t in [0.5, 1.0] {
            let p = s.point(t);
            reach = reach.max(Vec3::new(p.x, 0.0, p.z).length());
            samples.push((p, 0.5 * s.length));
        }
        total += s.length;
    }
    if total <= 0.0 {
        return None;
    }
    let area = LEAF_AREA_INDEX * std::f32::consts::PI * reach.max(0.5) * reach.max(0.5) / total;
    samples.iter_mut().for_each(|(_, a)| *a *= area);
    CrownLight::from_area(&samples)
}

/// Drops the branches that died of shade between the Mature Age and the Age (`years`:
/// `(mature, age)`), each cut to a stub dated to its death and seen in year `seen` (its callus
/// has grown for the years from its death to `seen`; see the module doc). `twin`, the same
/// stems in an earlier year (thinner), loses the same branches to the same stubs.
pub fn shed(
    skeleton: &mut Skeleton,
    threshold: f32,
    delay: f32,
    (mature, age): (f32, f32),
    seen: f32,
    mut twin: Option<&mut Skeleton>,
) {
    if threshold <= 0.0 {
        return;
    }
    let Some(light) = shoot_light(skeleton) else { return };
    let n = skeleton.stems.len();
    let leafy = terminal(skeleton);
    // Sum and count of the sky seen by each stem's terminal shoots (children come after parents).
    let mut sky = vec![(0.0f32, 0u32); n];
    for i in (0..n).rev() {
        if leafy[i] {
            let s = &skeleton.stems[i];
            sky[i] = (light.sky_at(s.point(0.5)) + light.sky_at(s.point(1.0)), 2);
        }
        if let Some(p) = skeleton.stems[i].parent {
            let (a, c) = sky[i];
            sky[p as usize].0 += a;
            sky[p as usize].1 += c;
        }
    }
    // Dead branches, parents first (a branch on a dead one goes with it).
    let mut dead: Vec<(usize, f32)> = Vec::new();
    let mut gone = vec![false; n];
    for i in 0..n {
        let s = &skeleton.stems[i];
        if let Some(p) = s.parent {
            if gone[p as usize] {
                gone[i] = true;
                continue;
            }
        }
        if s.parent.is_none() || matches!(s.kind, StemKind::Root | StemKind::SplitClone) || sky[i].1 == 0 {
            continue;
        }
        let seen = sky[i].0 / sky[i].1 as f32;
        let death = mature + delay * seen / (threshold - seen).max(1e-6);
        if seen < threshold && age >= death {
            gone[i] = true;
            dead.push((i, death));
        }
    }
    // Cut from the last, so the indices of the ones before stay valid.
    for &(i, death) in dead.iter().rev() {
        let s = &skeleton.stems[i];
        // From the parent's axis (where a branch starts) through its bark, then the stub.
        let parent = &skeleton.stems[s.parent.expect("a branch") as usize];
        let inside = parent.radius_at(s.offset / parent.length.max(1e-3));
        let stub = ((inside + STUB_RADII * s.radius + STUB_EXTRA) / s.length.max(1e-3)).min(0.5);
        let plan = plan(skeleton, i, stub);
        let years = (seen - death).max(0.0);
        cut_by(skeleton, i, stub, years, &plan);
        if let Some(t) = twin.as_deref_mut() {
            cut_by(t, i, stub, years, &plan);
        }
    }
}
