//! Where holes can go (the tree-generator thesis posted on 3dideas.wordpress.com (2008), §4.4):
//! candidates of both methods on each eligible stem's patch.
//! * *surface* (§4.4.1): every vertex gets its outside edge angle, `180° - 2·mean asin(e·n)` over
//!   its edges `e` (unit) and its normal `n`: 180° on a flat surface, more on a convex one, less
//!   in a concave valley (flutes, lobes, buttresses). Vertices more than [`CONCAVE_DEG`] below
//!   180° are grouped into connected clusters around the lowest one (within two hole radii);
//!   clusters of fewer than [`MIN_CLUSTER`] vertices are isolated and ignored; each cluster's
//!   lowest vertex is a candidate.
//! * *structural* (§4.4.2): below the junction of every big child (level-1 branches on the
//!   trunk, split forks; children at least half the minimum radius and a fifth of the local
//!   radius thick), outside the child's footprint, and on the trunk between neighbouring root
//!   starts (the valleys between buttress roots).

use super::patch::{nrm, pos, Patch};
use super::{Candidate, Source, CONCAVE_DEG, ELONGATION, MIN_CLUSTER};
use crate::math::{acos, atan2, cos, sin, unit_or, PI, TAU};
use crate::mesh::TreeMesh;
use crate::params::MeshParams;
use crate::skeleton::{Skeleton, Stem};
use glam::Vec3;

/// Outside edge angle at `v` in degrees (180 flat, less when concave), or None for a vertex with
/// fewer than three neighbours. A vertex certainly not concave gets 180 without the arc sines
/// (a software `acosf` in wasm): for `|y| <= 1`, `asin y = y + y³/6 + 3y⁵/40 + ...` lies within
/// `(π/2 - 1) |y|³` of `y`, so the mean of the `asin`s is at most the mean of `y + (π/2 - 1) |y|³`;
/// where that is a ten-thousandth of a radian below the concave mean, the angle is above
/// `180 - CONCAVE_DEG` whatever the rounding (only that comparison reads such an angle).
fn edge_angle(mesh: &TreeMesh, patch: &Patch, v: u32, scratch: &mut Vec<u32>) -> Option<f32> {
    patch.neighbours(mesh, v, scratch);
    if scratch.len() < 3 {
        return None;
    }
    let (x, n) = (pos(mesh, v), nrm(mesh, v));
    let count = scratch.len() as f32;
    let mut bound = 0.0f32;
    for &w in scratch.iter() {
        let y = unit_or(pos(mesh, w) - x, || Vec3::ZERO).dot(n).clamp(-1.0, 1.0);
        bound += y + (0.5 * PI - 1.0) * (y * y * y).abs();
    }
    if bound / count < 0.5 * CONCAVE_DEG.to_radians() - 1e-4 {
        return Some(180.0);
    }
    let mut sum = 0.0f32;
    for &w in scratch.iter() {
        let e = unit_or(pos(mesh, w) - x, || Vec3::ZERO);
        // asin(y) = π/2 - acos(y)
        sum += 0.5 * PI - acos(e.dot(n));
    }
    Some(180.0 - 2.0 * (sum / count).to_degrees())
}

fn surface_candidates(mesh: &TreeMesh, patch: &Patch, stem: &Stem, p: &MeshParams, out: &mut Vec<Candidate>) {
    let mut scratch = Vec::new();
    let mut low: Vec<(f32, u32)> = Vec::new();
    let mut angle = vec![f32::INFINITY; patch.block.len()];
    for v in patch.block.clone() {
        if !patch.free[patch.local(v)] {
            continue;
        }
        if let Some(a) = edge_angle(mesh, patch, v, &mut scratch) {
            angle[patch.local(v)] = a;
            if a < 180.0 - CONCAVE_DEG {
                low.push((a, v));
            }
        }
    }
    low.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let mut taken = vec![false; patch.block.len()];
    let mut queue = Vec::new();
    for &(_, seed) in &low {
        if taken[patch.local(seed)] {
            continue;
        }
        let x0 = pos(mesh, seed);
        let (_, r) = patch.radius_near(stem, x0);
        let reach = 2.0 * p.hole_size * r;
        let mut size = 0;
        queue.clear();
        queue.push(seed);
        taken[patch.local(seed)] = true;
        while let Some(v) = queue.pop() {
            size += 1;
            patch.neighbours(mesh, v, &mut scratch);
            for &w in scratch.iter() {
                let l = patch.local(w);
                if !taken[l] && angle[l] < 180.0 - CONCAVE_DEG && (pos(mesh, w) - x0).length() <= reach {
                    taken[l] = true;
                    queue.push(w);
                }
            }
        }
        if size >= MIN_CLUSTER {
            out.push(Candidate { stem: patch.stem as u32, vertex: seed, source: Source::Surface, local_radius: r });
        }
    }
}

/// The free vertex of `patch` nearest to `target`, if within `reach`.
fn snap(mesh: &TreeMesh, patch: &Patch, target: Vec3, reach: f32) -> Option<u32> {
    let mut best: Option<(f32, u32)> = None;
    for v in patch.block.clone() {
        if !patch.free[patch.local(v)] {
            continue;
        }
        let d = (pos(mesh, v) - target).length_squared();
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, v));
        }
    }
    best.filter(|&(d, _)| d <= reach * reach).map(|(_, v)| v)
}

fn structural_candidates(
    mesh: &TreeMesh,
    patch: &Patch,
    skeleton: &Skeleton,
    p: &MeshParams,
    children: &[u32],
    roots: usize,
    out: &mut Vec<Candidate>,
) {
    let stem = &skeleton.stems[patch.stem];
    let mut root_dirs: Vec<f32> = Vec::new();
    for &c in children {
        let child = &skeleton.stems[c as usize];
        if c as usize >= roots {
            let d = child.tip() - child.base();
            root_dirs.push(atan2(d.z, d.x));
            continue;
        }
        let t = (child.offset / stem.length).clamp(0.0, 1.0);
        let (base, tan) = stem.sample(t);
        let r = stem.radius_at(t);
        if child.radius < (0.5 * p.hole_min_radius).max(0.2 * r) {
            continue;
        }
        let (_, dir) = child.sample(0.0);
        let radial = dir - tan * dir.dot(tan);
        if radial.length_squared() < 1e-6 {
            continue;
        }
        let r_open = p.hole_size * r;
        let below = 1.2 * child.radius + 1.3 * ELONGATION * r_open;
        let target = base - tan * below + radial.normalize() * r;
        if let Some(v) = snap(mesh, patch, target, (0.5 * r).max(2.0 * r_open)) {
            let (_, lr) = patch.radius_near(stem, pos(mesh, v));
            out.push(Candidate { stem: patch.stem as u32, vertex: v, source: Source::Junction, local_radius: lr });
        }
    }
    if root_dirs.len() >= 2 && stem.parent.is_none() {
        root_dirs.sort_by(f32::total_cmp);
        let root_r = skeleton.stems[roots].radius;
        for k in 0..root_dirs.len() {
            let (a, mut b) = (root_dirs[k], root_dirs[(k + 1) % root_dirs.len()]);
            if b <= a {
                b += TAU;
            }
            let mid = 0.5 * (a + b);
            let h0 = 1.5 * root_r;
            let r0 = stem.radius_at(h0 / stem.length);
            let h = 1.2 * root_r + 1.3 * ELONGATION * p.hole_size * r0;
            let t = (h / stem.length).clamp(0.0, 1.0);
            let (c, tan) = stem.sample(t);
            let out_dir = Vec3::new(cos(mid), 0.0, sin(mid));
            let radial = unit_or(out_dir - tan * out_dir.dot(tan), || out_dir);
            let r = stem.radius_at(t);
            let target = c + radial * r;
            if let Some(v) = snap(mesh, patch, target, (0.5 * r).max(2.0 * p.hole_size * r)) {
                let (_, lr) = patch.radius_near(stem, pos(mesh, v));
                out.push(Candidate { stem: patch.stem as u32, vertex: v, source: Source::Root, local_radius: lr });
            }
        }
    }
}

/// Per patch: the stems starting on its stem (branches, split clones, roots), in stem order.
pub(super) fn children(skeleton: &Skeleton, patches: &[Patch]) -> Vec<Vec<u32>> {
    let mut children: Vec<Vec<u32>> = vec![Vec::new(); patches.len()];
    let slot: std::collections::BTreeMap<usize, usize> = patches.iter().enumerate().map(|(k, q)| (q.stem, k)).collect();
    for (i, s) in skeleton.stems.iter().enumerate() {
        if let Some(k) = s.parent.and_then(|par| slot.get(&(par as usize))) {
            children[*k].push(i as u32);
        }
    }
    children
}

pub(super) fn all_candidates(
    mesh: &TreeMesh,
    patches: &[Patch],
    skeleton: &Skeleton,
    p: &MeshParams,
    children: &[Vec<u32>],
) -> Vec<Candidate> {
    let roots = skeleton.first_root();
    let mut out = Vec::new();
    for (patch, kids) in patches.iter().zip(children) {
        let stem = &skeleton.stems[patch.stem];
        structural_candidates(mesh, patch, skeleton, p, kids, roots, &mut out);
        surface_candidates(mesh, patch, stem, p, &mut out);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::holes::patch::patches;
    use crate::params::SkeletonParams;
    use crate::TreeParams;

    /// [`edge_angle`] without its shortcut.
    fn by_the_formula(mesh: &TreeMesh, patch: &Patch, v: u32, scratch: &mut Vec<u32>) -> Option<f32> {
        patch.neighbours(mesh, v, scratch);
        if scratch.len() < 3 {
            return None;
        }
        let (x, n) = (pos(mesh, v), nrm(mesh, v));
        let sum: f32 = scratch.iter().map(|&w| 0.5 * PI - acos(unit_or(pos(mesh, w) - x, || Vec3::ZERO).dot(n))).sum();
        Some(180.0 - 2.0 * (sum / scratch.len() as f32).to_degrees())
    }

    #[test]
    fn the_edge_angles_shortcut_keeps_every_concave_vertex_and_its_angle() {
        let thick = TreeParams {
            skeleton: SkeletonParams { ratio: 0.035, ..Default::default() },
            mesh: MeshParams { hole_count: 3, hole_min_radius: 0.1, lobes: 5, lobe_depth: 0.1, ..Default::default() },
            ..TreeParams::default()
        };
        let oak = crate::presets::find("ca_black_oak").unwrap().params().unwrap();
        let (mut concave, mut skipped, mut scratch) = (0, 0, Vec::new());
        for p in [thick, oak] {
            let sk = crate::skeleton::build(&p.skeleton).unwrap();
            let built = crate::mesh::tube::build_with_stats(&sk, &p.mesh).unwrap();
            let (mesh, l) = (&built.mesh, &built.layout);
            for patch in patches(mesh, &l.blocks, &sk, &l.eligible, Some(l)) {
                for v in patch.block.clone() {
                    let (a, b) =
                        (edge_angle(mesh, &patch, v, &mut scratch), by_the_formula(mesh, &patch, v, &mut scratch));
                    let limit = 180.0 - CONCAVE_DEG;
                    assert_eq!(a.map(|a| a < limit), b.map(|b| b < limit), "vertex {v}: {a:?} {b:?}");
                    if b.is_some_and(|b| b < limit) {
                        assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits));
                        concave += 1;
                    }
                    skipped += usize::from(a == Some(180.0) && b != Some(180.0));
                }
            }
        }
        assert!(concave > 100 && skipped > 5 * concave, "{concave} concave, {skipped} without the arc sines");
    }
}
