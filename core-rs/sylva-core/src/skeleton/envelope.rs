//! The crown envelope of a built skeleton, for the viewer's Show Preview: the outline of the
//! space its level-1 branches can reach, from the same ShapeRatio the generator uses
//! ([`crate::crown`]).

use super::Skeleton;
use crate::params::{Crown, SkeletonParams};

/// The crown envelope of a generated tree for the viewer's Show Preview: pairs
/// `[height, radius]` (m, bottom to top) of a solid of revolution around the vertical axis that
/// holds every level-1 branch. At each attachment height on the trunk (and its split clones)
/// the longest possible level-1 branch is `L_trunk * (l1_length + l1_length_v) *
/// ShapeRatio(shape, r)`, the very function the generator uses; the branch reaches at most a
/// sphere of that radius around its attachment point, and the profile is the outline of the
/// union of those spheres.
pub fn preview_profile(skeleton: &Skeleton, p: &SkeletonParams, samples: usize) -> Vec<[f32; 2]> {
    preview_profile_with_crown(skeleton, p, None, samples)
}

/// [`preview_profile`] of a tree built with a crown drawn by hand
/// ([`super::build_with_crown`]): with Crown Shape Drawn, the reach at each attachment point
/// comes from the outline's ratio at that point's height, as the generator's does.
pub fn preview_profile_with_crown(
    skeleton: &Skeleton,
    p: &SkeletonParams,
    crown: Option<&Crown>,
    samples: usize,
) -> Vec<[f32; 2]> {
    let drawn = super::drawn_crown(p, crown);
    let l1 = &p.level[1];
    let max_len = l1.length + l1.length_v;
    // (centre, reach) of the attachment spheres.
    let mut spheres: Vec<(glam::Vec3, f32)> = Vec::new();
    for stem in skeleton.stems.iter().filter(|s| s.level == 0) {
        let chain = stem.chain_length;
        let span = chain - skeleton.crown_base;
        for i in 0..=48 {
            let z = i as f32 / 48.0;
            let along = stem.chain_start * chain + z * stem.length;
            if along < skeleton.crown_base || span <= 0.0 {
                continue;
            }
            let r = (chain - along) / span;
            let (c, _) = stem.sample(z);
            // Inflated by the sampling step, so attachment points between samples are covered.
            let ratio = drawn.as_ref().map_or_else(|| p.shape.ratio(r), |d| d.ratio_at_height(c.y));
            spheres.push((c, chain * max_len * ratio + stem.length / 48.0));
        }
    }
    if spheres.is_empty() || p.levels < 2 {
        return Vec::new();
    }
    let lo = spheres.iter().map(|(c, l)| c.y - l).fold(f32::INFINITY, f32::min).max(0.0);
    let hi = spheres.iter().map(|(c, l)| c.y + l).fold(f32::NEG_INFINITY, f32::max);
    let n = samples.max(3);
    (0..n)
        .map(|i| {
            let y = lo + (hi - lo) * i as f32 / (n - 1) as f32;
            let r = spheres
                .iter()
                .filter_map(|(c, l)| {
                    let dy = y - c.y;
                    (dy.abs() <= *l).then(|| (c.x * c.x + c.z * c.z).sqrt() + (l * l - dy * dy).sqrt())
                })
                .fold(0.0f32, f32::max);
            [y, r]
        })
        .collect()
}
