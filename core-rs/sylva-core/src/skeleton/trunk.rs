//! Trunk extras of the skeleton: the surface roots, and the guide curve of the tree-generator
//! thesis posted on 3dideas.wordpress.com (2008), §4.2.1 "Creating a Guiding Curve".

use super::{Points, Stem, StemKind};
use crate::math::TAU;
use crate::params::SkeletonParams;
use crate::rng::Rng;
use glam::Vec3;

/// The guide curve (the tree-generator thesis posted on 3dideas.wordpress.com (2008), §4.2.1): the
/// trunk's points keep their heights but move by random x/z offsets within `Guide Limit` (the first
/// point stays at the origin, the second moves at most half as far), from their own random stream.
pub(super) fn guide_curve(p: &SkeletonParams, points: &mut Points) {
    let mut rng = Rng::new(u64::from(p.seed), "trunk-guide");
    for (i, q) in points.iter_mut().enumerate().skip(1) {
        let limit = if i == 1 { 0.5 * p.guide_xy } else { p.guide_xy };
        q.x += rng.var(limit);
        q.z += rng.var(limit);
    }
}

/// Surface roots: `Roots` stems leaving the trunk base, spread evenly around it (with `Root
/// Spread` of random variation), running outward just under the ground and diving to `Root
/// Depth` (in root radii) below it, tapering to a point. They start inside the flared base, so
/// they emerge from it; their own random stream keeps every other stem unchanged.
pub(super) fn add_roots(p: &SkeletonParams, stems: &mut Vec<Stem>) {
    if p.root_count == 0 || stems.is_empty() {
        return;
    }
    let mut rng = Rng::new(u64::from(p.seed), "roots");
    let trunk = stems[0].clone();
    let r0 = trunk.radius * p.root_radius;
    let length = trunk.length * p.root_length;
    let segs = 8usize;
    for k in 0..p.root_count {
        let angle = TAU * (k as f32 + rng.var(0.5 * p.root_spread)) / p.root_count as f32;
        let (dx, dz) = (crate::math::cos(angle), crate::math::sin(angle));
        let len = length * (1.0 + rng.var(0.3 * p.root_spread));
        let start_y = 0.35 * r0;
        let end_y = -p.root_depth * r0;
        let mut points = Points::new();
        for i in 0..=segs {
            let t = i as f32 / segs as f32;
            // Out along the ground, sinking smoothly (smoothstep) from just above it to the depth.
            let s = t * t * (3.0 - 2.0 * t);
            let wobble = rng.var(0.05) * len * t;
            let horizontal = 0.25 * trunk.radius + len * t;
            points.push(Vec3::new(
                dx * horizontal - dz * wobble,
                start_y + (end_y - start_y) * s,
                dz * horizontal + dx * wobble,
            ));
        }
        points[0] = Vec3::new(0.0, start_y, 0.0);
        stems.push(Stem {
            kind: StemKind::Root,
            level: 1,
            parent: Some(0),
            offset: 0.0,
            base_normal: Vec3::Y,
            points,
            length: len,
            radius: r0,
            taper: 1.0,
            flare: 0.0,
            down_angle: 90.0,
            chain_length: len,
            chain_radius: r0,
            chain_start: 0.0,
            lobed: false,
            radii: None,
            cut_end: false,
            callus: 0.0,
            born: 0.0,
            tip_year: 0.0,
        });
    }
}
