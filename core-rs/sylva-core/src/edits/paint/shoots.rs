//! The new nodes of a paint stroke as stems: each shoot is a chain of nodes that starts on an
//! existing stem, following the most-tipped child at every fork (the chains of
//! `crate::growth::skeleton`); other children start stems of their own on it. Radii follow the
//! pipe model from the tip radius (`crate::growth::pipe_radii`), never thicker than the stem they
//! sprout from at the attachment point.

use super::colonize::{Node, EXISTING};
use crate::growth::pipe_radii;
use crate::growth::sca::{Node as GrowthNode, ROOT};
use crate::skeleton::{Points, Stem, StemKind};
use glam::Vec3;

/// Where an existing node lies: the stem and the fraction along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Anchor {
    /// Index of the stem in the skeleton.
    pub stem: u32,
    /// Fraction along the stem (0 = base, 1 = tip).
    pub t: f32,
}

/// How the shoots are dressed.
#[derive(Clone, Copy, Debug)]
pub struct Dress {
    /// Radius of a shoot's tip (m).
    pub tip: f32,
    /// Pipe model exponent Δ (`r_parent^Δ = Σ r_child^Δ`).
    pub delta: f32,
    /// Deepest level a new stem may have.
    pub deepest: u8,
    /// Index the first new stem will have in the skeleton.
    pub first: u32,
    /// The year the shoots grow (the tree's Age): their wood's date.
    pub year: f32,
}

/// One stem still to make: its first new node, the node it branches from, the parent stem (its
/// skeleton index), where on it, and the level.
#[derive(Clone, Copy)]
struct Start {
    first: u32,
    from: u32,
    parent: u32,
    offset: f32,
    level: u8,
}

/// The new stems of `nodes` (the first `existing` are the tree's, at `anchors`), parents
/// before children; `stems` are the skeleton's stems before the new ones.
pub fn shoots(stems: &[Stem], nodes: &[Node], existing: usize, anchors: &[Anchor], d: Dress) -> Vec<Stem> {
    let new = &nodes[existing..];
    let local = |n: u32| n as usize - existing;
    let pipe: Vec<GrowthNode> = new
        .iter()
        .map(|n| GrowthNode {
            pos: n.pos,
            parent: if n.parent == EXISTING || (n.parent as usize) < existing {
                ROOT
            } else {
                n.parent - existing as u32
            },
            born: 0,
        })
        .collect();
    let radii = pipe_radii(&pipe, d.tip, d.delta);
    let mut tips = vec![0u32; new.len()];
    let mut children: Vec<Vec<u32>> = vec![Vec::new(); new.len()];
    for i in (0..new.len()).rev() {
        tips[i] = tips[i].max(1);
        if pipe[i].parent != ROOT {
            tips[pipe[i].parent as usize] += tips[i];
        }
    }
    let mut queue: Vec<Start> = Vec::new();
    for (i, n) in new.iter().enumerate() {
        if (n.parent as usize) < existing {
            let a = anchors[n.parent as usize];
            let parent = &stems[a.stem as usize];
            let level = parent.level.saturating_add(1).min(d.deepest.max(parent.level));
            let first = (existing + i) as u32;
            queue.push(Start { first, from: n.parent, parent: a.stem, offset: a.t * parent.length, level });
        } else {
            children[local(n.parent)].push((existing + i) as u32);
        }
    }
    let mut out: Vec<Stem> = Vec::new();
    let mut qi = 0;
    while qi < queue.len() {
        let s = queue[qi];
        qi += 1;
        let mut chain = vec![s.from, s.first];
        loop {
            let cur = local(*chain.last().expect("a chain has nodes"));
            let main = children[cur].iter().max_by_key(|&&k| (tips[local(k)], std::cmp::Reverse(k)));
            let Some(&main) = main else { break };
            chain.push(main);
        }
        let index = d.first + out.len() as u32;
        let parent = if s.parent >= d.first { &out[(s.parent - d.first) as usize] } else { &stems[s.parent as usize] };
        let (_, parent_dir) = parent.point_at(s.offset);
        let cap = parent.radius_at(s.offset / parent.length);
        let points: Points = chain.iter().map(|&n| nodes[n as usize].pos).collect();
        let mut r: Vec<f32> = chain[1..].iter().map(|&n| radii[local(n)]).collect();
        r.insert(0, r[0]);
        for x in &mut r {
            *x = x.min(cap).max(d.tip.min(cap));
        }
        let mut offsets = vec![0.0f32];
        for w in points.windows(2) {
            offsets.push(offsets.last().copied().unwrap_or(0.0) + w[0].distance(w[1]));
        }
        for (k, &n) in chain.iter().enumerate().skip(1) {
            let main_next = chain.get(k + 1).copied();
            for &kid in children[local(n)].iter().filter(|&&kid| Some(kid) != main_next) {
                let level = s.level.saturating_add(1).min(d.deepest.max(s.level));
                queue.push(Start { first: kid, from: n, parent: index, offset: offsets[k], level });
            }
        }
        let along = offsets.last().copied().unwrap_or(0.0).max(1e-4);
        let dir = (points[1] - points[0]).normalize_or(Vec3::Y);
        out.push(Stem {
            kind: StemKind::Branch,
            level: s.level,
            parent: Some(s.parent),
            offset: s.offset,
            base_normal: dir.any_orthonormal_vector(),
            length: along,
            radius: r[0],
            taper: 0.0,
            flare: 0.0,
            down_angle: parent_dir.angle_between(dir).to_degrees(),
            chain_length: along,
            chain_radius: r[0],
            chain_start: 0.0,
            lobed: false,
            radii: Some(r),
            cut_end: false,
            callus: 0.0,
            born: d.year,
            tip_year: d.year,
            points,
        });
    }
    out
}
