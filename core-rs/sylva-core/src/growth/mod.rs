//! Growth mode: trees grown by space colonization instead of drawn by Weber & Penn's rules.
//! Parameters -> [`volume::Environment`] + [`sca::GrowthConfig`] -> [`sca::grow`] -> nodes ->
//! pipe-model radii -> stems (a [`Skeleton`]) that the ordinary bark mesher sweeps.
//!
//! Thickness follows the pipe model (da Vinci's rule; Shinozaki et al. 1964, *A quantitative
//! analysis of plant form: the pipe model theory*): `r_parent^Δ = Σ r_child^Δ` at every fork, from
//! `Tip Radius` at the tips, so a node's radius is `tip_radius * (tips above it)^(1/Δ)`.

pub mod grid;
pub mod sca;
pub mod volume;

use crate::edits::crown::DrawnCrown;
use crate::error::SylvaError;
use crate::params::{Crown, CrownVolumeKind, GrowthMode, SkeletonParams, VolumeGroup};
use crate::rng::Rng;
use crate::skeleton::{Points, Skeleton, Stem, StemKind};
use glam::Vec3;
pub use sca::node_budget_error;
pub(crate) use sca::Growth;
use sca::{GrowthConfig, Node, ROOT};
use volume::{Aabb, CrownVolume, Environment};

/// The environment described by the parameters: crown (one copy per start point), the wall.
pub fn environment(p: &SkeletonParams) -> Environment {
    environment_with_crown(p, None)
}

/// [`environment`] with a crown drawn by hand: when `crown` is given (and usable), its solid of
/// revolution is the crown volume in place of the ellipsoid or envelope ([`crate::edits::crown`]);
/// the user's crown-group primitives still win where Crown Volume is Primitives.
pub fn environment_with_crown(p: &SkeletonParams, crown: Option<&Crown>) -> Environment {
    let parametric = match p.crown_volume {
        CrownVolumeKind::Ellipsoid | CrownVolumeKind::Primitives => {
            CrownVolume::Ellipsoid { base: p.crown_base, height: p.crown_height, radius: p.crown_radius }
        }
        CrownVolumeKind::Envelope => {
            CrownVolume::Envelope { base: p.crown_base, height: p.crown_height, radius: p.crown_radius, shape: p.shape }
        }
    };
    let crown = crown.and_then(DrawnCrown::new).map_or(parametric, CrownVolume::Drawn);
    let mut env = Environment {
        crown,
        crown_offsets: starts(p),
        shadow: Vec::new(),
        exclusion: Vec::new(),
        occluders: Vec::new(),
        crown_union: Vec::new(),
        shadow_prims: Vec::new(),
        exclusion_prims: Vec::new(),
    };
    for v in &p.volumes {
        match v.group {
            VolumeGroup::Crown if p.crown_volume == CrownVolumeKind::Primitives => env.crown_union.push(v.shape),
            VolumeGroup::Crown => {}
            VolumeGroup::Shadow => env.shadow_prims.push(v.shape),
            VolumeGroup::Exclusion => env.exclusion_prims.push(v.shape),
        }
    }
    if p.wall {
        // A wall on the -x side, running along z: branches stop at it and it shades the markers near it.
        let x = -p.wall_distance;
        let wall = Aabb {
            min: Vec3::new(x - 0.2, 0.0, -0.5 * p.wall_width),
            max: Vec3::new(x, p.wall_height, 0.5 * p.wall_width),
        };
        env.exclusion.push(wall);
        env.occluders.push(wall);
    }
    env
}

/// Start points: `Start Points` trunks in a row along x (a hedgerow), centred on the origin.
pub fn starts(p: &SkeletonParams) -> Vec<Vec3> {
    let n = p.start_points.max(1);
    (0..n).map(|i| Vec3::new((i as f32 - 0.5 * (n - 1) as f32) * p.start_spacing, 0.0, 0.0)).collect()
}

/// The growth settings described by the parameters.
pub fn config(p: &SkeletonParams) -> GrowthConfig {
    GrowthConfig {
        markers: p.markers as usize,
        surface_bias: p.marker_surface_bias,
        top_bias: p.marker_top_bias,
        influence: p.influence_radius,
        kill: p.kill_distance,
        internode: p.internode,
        iterations: p.iterations,
        tropism: p.tropism,
        jitter: p.growth_jitter,
        apical_control: p.apical_control,
        starts: starts(p),
        extra_markers_per_1000: p.extra_markers as f32,
        shade_depth: p.light_competition.then_some(p.shade_depth),
        max_nodes: (p.max_vertices / 4) as usize,
    }
}

/// Grow the tree of `p` (its nodes and markers, before thickness and meshing).
pub fn grow(p: &SkeletonParams) -> Result<Growth, SylvaError> {
    grow_with_progress(p, None)
}

/// [`grow`] reporting progress (the fraction of the iteration cap run so far, 0..1) to
/// `progress` every [`sca::PROGRESS_EVERY`] iterations; the result is the same.
pub fn grow_with_progress(p: &SkeletonParams, progress: Option<&mut dyn FnMut(f32)>) -> Result<Growth, SylvaError> {
    grow_with_crown(p, None, progress)
}

/// [`grow_with_progress`] in the crown drawn by hand, when one is given
/// ([`environment_with_crown`]).
pub fn grow_with_crown(
    p: &SkeletonParams,
    crown: Option<&Crown>,
    progress: Option<&mut dyn FnMut(f32)>,
) -> Result<Growth, SylvaError> {
    let mut rng = Rng::new(u64::from(p.seed), "growth");
    sca::grow_with_progress(&environment_with_crown(p, crown), &config(p), &mut rng, progress)
}

/// Pipe-model radius of every node of `nodes` (parents before children): tips get `tip`,
/// every other node `(Σ r_child^Δ)^(1/Δ)`.
pub fn pipe_radii(nodes: &[Node], tip: f32, delta: f32) -> Vec<f32> {
    let mut sum = vec![0.0f32; nodes.len()];
    let mut r = vec![0.0f32; nodes.len()];
    for i in (0..nodes.len()).rev() {
        r[i] = if sum[i] == 0.0 { tip } else { crate::math::pow(sum[i], 1.0 / delta) };
        if nodes[i].parent != ROOT {
            sum[nodes[i].parent as usize] += crate::math::pow(r[i], delta);
        }
    }
    r
}

/// Build the skeleton of a grown tree as seen at its Growth Age (fraction 0..1 of its growth:
/// nodes born later are left out, and thickness is recomputed for the younger tree).
pub fn skeleton(p: &SkeletonParams, growth: &Growth) -> Skeleton {
    skeleton_at(p, growth, p.growth_age)
}

/// The grown tree at `p`'s Age, in annual flushes: the iterations that make the tree at its
/// Mature Age (its Growth Age of them) are spread evenly over its years, so a year's flush is
/// the iterations of that year (about `iterations × Growth Age / Mature Age`), and the tree at
/// Age `a` is the growth up to iteration `a / Mature Age` of the mature tree's. Every stem is
/// dated by its nodes' iterations ([`Stem::born`], [`Stem::tip_year`]). Past the Mature Age it
/// is the mature tree.
pub fn skeleton_by_years(p: &SkeletonParams, growth: &Growth) -> Skeleton {
    let years = (p.age / p.maturity.max(1e-3)).min(1.0);
    skeleton_at(p, growth, p.growth_age * years)
}

/// [`skeleton`] with the nodes of the first `fraction` of the iterations.
fn skeleton_at(p: &SkeletonParams, growth: &Growth, fraction: f32) -> Skeleton {
    let last = (fraction * growth.iterations as f32).round() as u32;
    // The year an iteration's flush grew in: the mature tree's iterations over its years.
    let per_year = (p.growth_age * growth.iterations as f32 / p.maturity.max(1e-3)).max(1e-6);
    // Keep nodes born by `last` (parents are always older than their children).
    let mut remap = vec![ROOT; growth.nodes.len()];
    let mut nodes: Vec<Node> = Vec::new();
    for (i, n) in growth.nodes.iter().enumerate() {
        if n.born <= last && (n.parent == ROOT || remap[n.parent as usize] != ROOT) {
            remap[i] = nodes.len() as u32;
            nodes.push(Node { parent: if n.parent == ROOT { ROOT } else { remap[n.parent as usize] }, ..*n });
        }
    }
    let radii = pipe_radii(&nodes, p.tip_radius, p.pipe_power);
    // Tips above each node, to follow the main (most-tipped) child along a stem.
    let mut tips = vec![0u32; nodes.len()];
    let mut children: Vec<Vec<u32>> = vec![Vec::new(); nodes.len()];
    for i in (0..nodes.len()).rev() {
        if tips[i] == 0 {
            tips[i] = 1;
        }
        if nodes[i].parent != ROOT {
            tips[nodes[i].parent as usize] += tips[i];
        }
    }
    for (i, n) in nodes.iter().enumerate() {
        if n.parent != ROOT {
            children[n.parent as usize].push(i as u32);
        }
    }
    let mut stems: Vec<Stem> = Vec::new();
    // (first node of the stem, the node it branches from, parent stem, offset on it, level)
    let mut queue: Vec<(u32, u32, Option<u32>, f32, u8)> = Vec::new();
    for (i, n) in nodes.iter().enumerate() {
        if n.parent == ROOT {
            queue.push((i as u32, ROOT, None, 0.0, 0));
        }
    }
    let mut qi = 0;
    while qi < queue.len() {
        let (first, from, parent_stem, offset, level) = queue[qi];
        qi += 1;
        let mut chain: Vec<u32> = Vec::new();
        if from != ROOT {
            chain.push(from);
        }
        let mut cur = first;
        loop {
            chain.push(cur);
            let kids = &children[cur as usize];
            let Some(&main) = kids.iter().max_by_key(|&&k| (tips[k as usize], std::cmp::Reverse(k))) else {
                break;
            };
            cur = main;
        }
        if chain.len() < 2 {
            continue; // a lone start point that never grew
        }
        let stem_index = stems.len() as u32;
        let points: Points = chain.iter().map(|&n| nodes[n as usize].pos).collect();
        // The year its wood grew: its first own node's flush at the base, its last's at the tip.
        let own = chain[usize::from(from != ROOT)];
        let year = |n: u32| nodes[n as usize].born as f32 / per_year;
        let (born, tip_year) = (year(own), year(*chain.last().expect("two nodes or more")));
        let mut r: Vec<f32> = chain.iter().map(|&n| radii[n as usize]).collect();
        if from != ROOT {
            r[0] = r[1]; // a side branch starts at its own thickness, not its parent's
        }
        let mut along = 0.0f32;
        let mut offsets = Vec::with_capacity(chain.len());
        for w in points.windows(2) {
            offsets.push(along);
            along += w[0].distance(w[1]);
        }
        offsets.push(along);
        // Side branches of this stem, in node order.
        for (k, &n) in chain.iter().enumerate() {
            if k == 0 && from != ROOT {
                continue;
            }
            let main_next = chain.get(k + 1).copied();
            for &kid in &children[n as usize] {
                if Some(kid) != main_next {
                    queue.push((kid, n, Some(stem_index), offsets[k], level.saturating_add(1)));
                }
            }
        }
        let dir = (points[1] - points[0]).normalize_or(Vec3::Y);
        let parent_dir = parent_stem.map(|s| {
            let st = &stems[s as usize];
            st.point_at(offset).1
        });
        stems.push(Stem {
            kind: if parent_stem.is_some() { StemKind::Branch } else { StemKind::Trunk },
            level: level.min(3),
            parent: parent_stem,
            offset,
            base_normal: dir.any_orthonormal_vector(),
            length: along.max(1e-4),
            radius: r[0],
            taper: 0.0,
            flare: 0.0,
            down_angle: parent_dir.map_or(0.0, |d| d.angle_between(dir).to_degrees()),
            chain_length: along.max(1e-4),
            chain_radius: r[0],
            chain_start: 0.0,
            lobed: false,
            radii: Some(r),
            cut_end: false,
            callus: 0.0,
            born,
            tip_year,
            points,
        });
    }
    Skeleton::of(p, GrowthMode::SpaceColonization, stems, p.crown_base + p.crown_height, p.crown_base)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pipe_model_holds_at_every_fork() {
        // A Y: root -> a -> (b, c), c -> d.
        let n = |parent: u32| Node { pos: Vec3::ZERO, parent, born: 0 };
        let nodes = [n(ROOT), n(0), n(1), n(1), n(3)];
        let r = pipe_radii(&nodes, 0.01, 2.0);
        assert!((r[1] * r[1] - (r[2] * r[2] + r[3] * r[3])).abs() < 1e-9);
        assert_eq!(r[2], 0.01);
        assert_eq!(r[3], r[4]);
    }
}
