//! The hole-eligible stems' parts of the bark mesh (the tree-generator thesis posted on
//! 3dideas.wordpress.com (2008), §4.3): each eligible stem's block of vertices, the faces inside
//! it, and which of its vertices may be cut — inside the stem's block, used by no triangle reaching
//! outside the block (junction bridges), on no open edge, and sharing their position with no other
//! vertex (UV seam, cap ring, welded copies).

use crate::mesh::layout::Layout;
use crate::mesh::TreeMesh;
use crate::skeleton::{Skeleton, Stem};
use glam::Vec3;
use std::ops::Range;

/// One eligible stem's part of the mesh: its block of vertices and the faces inside it.
pub(super) struct Patch {
    pub(super) stem: usize,
    pub(super) block: Range<u32>,
    /// Triangle indices (into `indices / 3`) whose three vertices are in the block.
    pub(super) faces: Vec<u32>,
    /// Per block vertex: range into `vf` of its faces (CSR).
    vf_start: Vec<u32>,
    /// Positions into `faces`.
    vf: Vec<u32>,
    /// Per block vertex: may be cut (see the module docs).
    pub(super) free: Vec<bool>,
    /// Centre curve samples `(t, point)` for local radii.
    samples: Vec<(f32, Vec3)>,
}

impl Patch {
    pub(super) fn local(&self, v: u32) -> usize {
        (v - self.block.start) as usize
    }

    pub(super) fn faces_of(&self, v: u32) -> &[u32] {
        let l = self.local(v);
        &self.vf[self.vf_start[l] as usize..self.vf_start[l + 1] as usize]
    }

    pub(super) fn is_free(&self, v: u32) -> bool {
        self.block.contains(&v) && self.free[self.local(v)]
    }

    /// Neighbour vertices of `v` (sorted, unique).
    pub(super) fn neighbours(&self, mesh: &TreeMesh, v: u32, out: &mut Vec<u32>) {
        out.clear();
        for &f in self.faces_of(v) {
            let t = self.faces[f as usize] as usize * 3;
            out.extend(mesh.indices[t..t + 3].iter().copied().filter(|&w| w != v));
        }
        out.sort_unstable();
        out.dedup();
    }

    /// Fraction along the stem and local radius nearest to `x`.
    pub(super) fn radius_near(&self, stem: &Stem, x: Vec3) -> (f32, f32) {
        let mut best = (f32::INFINITY, 0.0f32);
        for &(t, c) in &self.samples {
            let d = (x - c).length_squared();
            if d < best.0 {
                best = (d, t);
            }
        }
        (best.1, stem.radius_at(best.1))
    }
}

pub(super) fn pos(mesh: &TreeMesh, v: u32) -> Vec3 {
    let k = v as usize * 3;
    Vec3::new(mesh.positions[k], mesh.positions[k + 1], mesh.positions[k + 2])
}

pub(super) fn nrm(mesh: &TreeMesh, v: u32) -> Vec3 {
    let k = v as usize * 3;
    Vec3::new(mesh.normals[k], mesh.normals[k + 1], mesh.normals[k + 2])
}

pub(super) fn bits(mesh: &TreeMesh, v: u32) -> [u32; 3] {
    let k = v as usize * 3;
    [mesh.positions[k].to_bits(), mesh.positions[k + 1].to_bits(), mesh.positions[k + 2].to_bits()]
}

/// The triangles that may use an eligible stem's vertices, in order: with a [`Layout`], the
/// eligible stems' own triangles, the junctions of the eligible stems and of their children,
/// and the faces after every junction's; without one, every triangle.
fn near_eligible(mesh: &TreeMesh, skeleton: &Skeleton, eligible: &[bool], layout: Option<&Layout>) -> Vec<Range<u32>> {
    let all = (mesh.indices.len() / 3) as u32;
    let Some(l) = layout else { return std::iter::once(0..all).collect() };
    let is = |i: usize| eligible.get(i).copied().unwrap_or(false);
    let mut ranges: Vec<Range<u32>> = Vec::new();
    for (i, s) in skeleton.stems.iter().enumerate() {
        if is(i) {
            ranges.extend(l.tubes.get(i).cloned());
        }
        if is(i) || s.parent.is_some_and(|p| is(p as usize)) {
            ranges.extend(l.junctions.get(i).cloned());
        }
    }
    ranges.push(l.rest.min(all)..all);
    ranges.retain(|r| !r.is_empty());
    ranges.sort_by_key(|r| r.start);
    ranges
}

/// Build the patches of the eligible stems: one pass over the triangles that may use their
/// vertices ([`near_eligible`]: with the sweep's [`Layout`] a few per cent of a large tree's,
/// else all of them; the same patches either way).
pub(super) fn patches(
    mesh: &TreeMesh,
    blocks: &[Range<u32>],
    skeleton: &Skeleton,
    eligible: &[bool],
    layout: Option<&Layout>,
) -> Vec<Patch> {
    let nv = mesh.vertex_count();
    let mut list: Vec<Patch> = eligible
        .iter()
        .enumerate()
        .filter(|&(i, &e)| e && i < blocks.len() && !blocks[i].is_empty() && blocks[i].end as usize <= nv)
        .map(|(i, _)| {
            let stem = &skeleton.stems[i];
            Patch {
                stem: i,
                block: blocks[i].clone(),
                faces: Vec::new(),
                vf_start: Vec::new(),
                vf: Vec::new(),
                free: vec![true; blocks[i].len()],
                samples: (0..=64).map(|k| (k as f32 / 64.0, stem.point(k as f32 / 64.0))).collect(),
            }
        })
        .collect();
    if list.is_empty() {
        return list;
    }
    list.sort_by_key(|p| p.block.start);
    let mut inside = vec![0u64; nv.div_ceil(64)];
    for p in &list {
        for v in p.block.clone() {
            inside[v as usize >> 6] |= 1 << (v & 63);
        }
    }
    let hit = |v: u32| inside[v as usize >> 6] >> (v & 63) & 1 == 1;
    let owner = |v: u32| list.partition_point(|p| p.block.end <= v);
    let mut foreign: Vec<(usize, u32)> = Vec::new();
    let mut local: Vec<(usize, u32)> = Vec::new();
    let triangles = near_eligible(mesh, skeleton, eligible, layout)
        .into_iter()
        .flat_map(|r| mesh.indices[3 * r.start as usize..3 * r.end as usize].chunks_exact(3).zip(r));
    for (t, k) in triangles {
        let (a, b, c) = (t[0], t[1], t[2]);
        if !(hit(a) || hit(b) || hit(c)) {
            continue;
        }
        let o = [a, b, c].map(|v| if hit(v) { owner(v) } else { usize::MAX });
        if o[0] != usize::MAX && o[0] == o[1] && o[1] == o[2] {
            local.push((o[0], k));
        } else {
            for (v, ov) in [a, b, c].into_iter().zip(o) {
                if ov != usize::MAX {
                    foreign.push((ov, v));
                }
            }
        }
    }
    for (o, k) in local {
        list[o].faces.push(k);
    }
    for (o, v) in foreign {
        let l = list[o].local(v);
        list[o].free[l] = false;
    }
    for p in &mut list {
        let n = p.block.len();
        let mut count = vec![0u32; n + 1];
        for &f in &p.faces {
            for &v in &mesh.indices[f as usize * 3..f as usize * 3 + 3] {
                count[p.local(v) + 1] += 1;
            }
        }
        for i in 0..n {
            count[i + 1] += count[i];
        }
        let mut fill = count.clone();
        let mut vf = vec![0u32; count[n] as usize];
        for (fi, &f) in p.faces.iter().enumerate() {
            for &v in &mesh.indices[f as usize * 3..f as usize * 3 + 3] {
                let l = p.local(v);
                vf[fill[l] as usize] = fi as u32;
                fill[l] += 1;
            }
        }
        p.vf_start = count;
        p.vf = vf;
        // Not free: unused vertices, vertices on edges not shared by exactly two local faces,
        // and vertices sharing their position with another vertex of the block.
        mark_odd_edges(mesh, &p.faces, &p.block, &mut p.free);
        for l in 0..n {
            if p.vf_start[l] == p.vf_start[l + 1] {
                p.free[l] = false;
            }
        }
        let mut by_pos: Vec<([u32; 3], u32)> = p.block.clone().map(|v| (bits(mesh, v), v)).collect();
        by_pos.sort_unstable();
        for w in by_pos.windows(2) {
            if w[0].0 == w[1].0 {
                let (la, lb) = (p.local(w[0].1), p.local(w[1].1));
                p.free[la] = false;
                p.free[lb] = false;
            }
        }
    }
    list
}

/// Marks in `free` (by vertex, from `block.start`) both ends of every edge of `faces` (all in
/// `block`) used by other than two of them. The edges (smaller end, larger end) are bucketed by
/// their smaller end (a counting sort), then each bucket's larger ends sorted: an edge used by
/// other than two faces is a run of other than two equal ends.
fn mark_odd_edges(mesh: &TreeMesh, faces: &[u32], block: &Range<u32>, free: &mut [bool]) {
    let n = block.len();
    let local = |v: u32| (v - block.start) as usize;
    let edge = |f: u32, j: usize| {
        let t = &mesh.indices[f as usize * 3..f as usize * 3 + 3];
        let (a, b) = (t[j], t[(j + 1) % 3]);
        (a.min(b), a.max(b))
    };
    let mut start = vec![0u32; n + 1];
    for &f in faces {
        for j in 0..3 {
            start[local(edge(f, j).0) + 1] += 1;
        }
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut at = start.clone();
    let mut ends = vec![0u32; start[n] as usize];
    for &f in faces {
        for j in 0..3 {
            let (a, b) = edge(f, j);
            let l = local(a);
            ends[at[l] as usize] = b;
            at[l] += 1;
        }
    }
    for la in 0..n {
        let bucket = &mut ends[start[la] as usize..start[la + 1] as usize];
        bucket.sort_unstable();
        for run in bucket.chunk_by(|x, y| x == y) {
            if run.len() != 2 {
                free[la] = false;
                free[local(run[0])] = false;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{MeshParams, SkeletonParams};
    use crate::TreeParams;

    /// [`mark_odd_edges`] as first written: every edge sorted, then the runs counted.
    fn mark_by_sorting_every_edge(mesh: &TreeMesh, faces: &[u32], block: &Range<u32>, free: &mut [bool]) {
        let mut edges: Vec<(u32, u32)> = Vec::new();
        for &f in faces {
            let t = &mesh.indices[f as usize * 3..f as usize * 3 + 3];
            for j in 0..3 {
                let (a, b) = (t[j], t[(j + 1) % 3]);
                edges.push((a.min(b), a.max(b)));
            }
        }
        edges.sort_unstable();
        for run in edges.chunk_by(|x, y| x == y) {
            if run.len() != 2 {
                free[(run[0].0 - block.start) as usize] = false;
                free[(run[0].1 - block.start) as usize] = false;
            }
        }
    }

    #[test]
    fn odd_edges_are_those_of_sorting_every_edge() {
        // A strip of quads with a fold (a triangle repeated), a dangling face and a degenerate one.
        let mut mesh = TreeMesh { positions: vec![0.0; 3 * 12], ..Default::default() };
        mesh.indices = vec![0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 1, 2, 6, 8, 9, 10, 11, 11, 3];
        let faces: Vec<u32> = (0..9).collect();
        let (mut a, mut b) = (vec![true; 12], vec![true; 12]);
        mark_odd_edges(&mesh, &faces, &(0..12), &mut a);
        mark_by_sorting_every_edge(&mesh, &faces, &(0..12), &mut b);
        assert_eq!(a, b);
        assert!(!a[0] && !a[11] && !a[3]);
        let oak = crate::presets::find("ca_black_oak").unwrap().params().unwrap();
        let sk = crate::skeleton::build(&oak.skeleton).unwrap();
        let built = crate::mesh::tube::build_with_stats(&sk, &oak.mesh).unwrap();
        for p in patches(&built.mesh, &built.layout.blocks, &sk, &built.layout.eligible, Some(&built.layout)) {
            let (mut a, mut b) = (vec![true; p.block.len()], vec![true; p.block.len()]);
            mark_odd_edges(&built.mesh, &p.faces, &p.block, &mut a);
            mark_by_sorting_every_edge(&built.mesh, &p.faces, &p.block, &mut b);
            assert_eq!(a, b, "stem {}", p.stem);
            assert!(a.iter().filter(|&&f| !f).count() > 10 && a.iter().any(|&f| f), "stem {}", p.stem);
        }
    }

    #[test]
    fn the_layout_gives_the_patches_of_every_triangle() {
        let thick = TreeParams {
            skeleton: SkeletonParams { ratio: 0.035, ..Default::default() },
            mesh: MeshParams { hole_count: 3, hole_min_radius: 0.1, ..Default::default() },
            ..TreeParams::default()
        };
        let oak = crate::presets::find("ca_black_oak").unwrap().params().unwrap();
        for p in [thick, oak] {
            let sk = crate::skeleton::build(&p.skeleton).unwrap();
            let built = crate::mesh::tube::build_with_stats(&sk, &p.mesh).unwrap();
            let (mesh, l) = (&built.mesh, &built.layout);
            assert!(l.eligible.iter().any(|&e| e));
            let near = near_eligible(mesh, &sk, &l.eligible, Some(l));
            let scanned: u32 = near.iter().map(|r| r.len() as u32).sum();
            assert!(scanned * 4 < (mesh.indices.len() / 3) as u32, "{scanned} triangles read");
            let (a, b) =
                (patches(mesh, &l.blocks, &sk, &l.eligible, None), patches(mesh, &l.blocks, &sk, &l.eligible, Some(l)));
            assert_eq!(a.len(), b.len());
            for (a, b) in a.iter().zip(&b) {
                assert_eq!(
                    (a.stem, &a.block, &a.faces, &a.vf_start, &a.vf, &a.free),
                    (b.stem, &b.block, &b.faces, &b.vf_start, &b.vf, &b.free)
                );
                assert!(!a.faces.is_empty() && a.free.iter().any(|&f| f) && a.free.iter().any(|&f| !f));
            }
        }
    }
}
