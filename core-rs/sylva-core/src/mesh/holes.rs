//! Tree holes (the thesis, §4.3–4.4): a post-process on the bark mesh that cuts cavities into
//! the trunk and into level-1 stems thick enough for them (see [`eligible`]).
//!
//! **Where** — both of the thesis' methods give candidates, each on a stem's own swept block of
//! vertices:
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
//!
//! Candidates whose local stem radius is below `hole_min_radius` are dropped; the rest are taken
//! in a random order (stream `"holes"`, seeded by `seed` and `hole_seed`) until `hole_count`
//! holes are cut, skipping those too close to an earlier hole or to a child stem's buried base.
//!
//! **How** (§4.3, the 3ds Max recipe of chamfer, connect, delete, extrude, subdivide): the faces
//! around the candidate within the hole's ellipse (half-width `hole_size` × local radius, 1.5 times
//! taller along the stem) are selected; the selection must be a topological disk (one boundary
//! loop, Euler characteristic 1), else it shrinks and is tried again. Its faces are removed, the
//! boundary loop gets a chamfered ring (inset toward the loop's centre and bevelled inward), and
//! that rim is extruded inward along minus the surface normal into [`CAVITY_RINGS`] rings that
//! narrow toward a closed bottom `hole_depth` × local radius below the surface; the cavity rings
//! are then smoothed by a few Laplacian passes (the thesis' final subdivision, which softens the
//! edges). New vertices reuse the slots of the removed interior vertices, then append.
//!
//! The surface stays closed and edge-manifold: only faces whose vertices are all *free* are cut —
//! inside the stem's block, used by no triangle reaching outside the block (junction bridges),
//! on no open edge, and sharing their position with no other vertex (UV seam, cap ring, welded
//! copies). New normals are area-weighted face normals, so they face into the cavity (out of the
//! wood); `u` follows the rim, `v` continues the bark's at one unit per circumference; wind
//! entries, when the mesh has them, are copied from the nearest rim vertex. The tube rings
//! holding a reused or parked slot leave `TreeMesh::rings`.

use super::TreeMesh;
use super::WIND_STRIDE;
use crate::growth::GrowthMode;
use crate::math::{acos, atan2, cos, sin, unit_or, PI, TAU};
use crate::params::TreeParams;
use crate::rng::Rng;
use crate::skeleton::{Skeleton, Stem};
use glam::Vec3;
use std::ops::Range;

/// A vertex is concave when its outside edge angle is at least this far below 180° (degrees).
pub const CONCAVE_DEG: f32 = 3.0;
/// Smallest cluster of concave vertices that makes a surface candidate.
pub const MIN_CLUSTER: usize = 3;
/// Rings of the cavity wall below the chamfered rim.
pub const CAVITY_RINGS: usize = 3;
/// A hole's opening is this much taller (along the stem) than wide.
const ELONGATION: f32 = 1.5;
/// Fraction of the way from the rim toward the loop's centre the chamfer ring is inset.
const CHAMFER: f32 = 0.2;
/// Laplacian smoothing passes over the cavity rings.
const SMOOTH_PASSES: usize = 4;

/// Which method found a candidate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Source {
    /// A cluster of concave vertices (§4.4.1).
    Surface,
    /// Below a big branch or fork junction (§4.4.2).
    Junction,
    /// Between two root starts (§4.4.2).
    Root,
}

/// A place a hole could go.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Stem whose surface it is on.
    pub stem: u32,
    /// The vertex at its centre.
    pub vertex: u32,
    /// How it was found.
    pub source: Source,
    /// Stem radius there (m, from the stem's profile).
    pub local_radius: f32,
}

/// A hole that was cut.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hole {
    /// Stem it was cut into.
    pub stem: u32,
    /// How its place was found.
    pub source: Source,
    /// Surface point at its centre (m).
    pub centre: Vec3,
    /// Outward surface normal there.
    pub normal: Vec3,
    /// Half-width of the opening (m).
    pub radius: f32,
    /// Depth of the cavity below `centre` (m).
    pub depth: f32,
}

/// Whether stem `i` can carry holes: the trunk records whose base is at least `hole_min_radius`
/// thick, and level-1 stems (not roots, not Bezier twigs) at least twice that (a thinner branch
/// would be densified along its whole length for a hole near its base only). The tube densifies these (rings about
/// as far apart as the sides, see [`densify`]) when holes are asked for.
pub fn eligible(skeleton: &Skeleton, p: &TreeParams, twigs: &[bool]) -> Vec<bool> {
    let n = skeleton.stems.len();
    if p.hole_count == 0 {
        return Vec::new();
    }
    let roots = first_root(skeleton, p);
    skeleton
        .stems
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let min = if s.level == 0 { p.hole_min_radius } else { 2.0 * p.hole_min_radius };
            s.level <= 1 && i < roots && !twigs.get(i).copied().unwrap_or(false) && s.radius_at(0.0) >= min
        })
        .chain(std::iter::repeat(false))
        .take(n)
        .collect()
}

/// Index of the first root stem (roots are appended last by the skeleton).
fn first_root(skeleton: &Skeleton, p: &TreeParams) -> usize {
    let n = skeleton.stems.len();
    if p.growth_mode == GrowthMode::Parametric {
        n - (p.root_count as usize).min(n.saturating_sub(1))
    } else {
        n
    }
}

/// Make an eligible stem's mesh dense enough for holes, as the thesis cuts them into a dense
/// mesh: at least enough sides for an opening to span five columns (at most 96), and rings added
/// to its plan (`ts[start..]`, sorted, the last one next to the tip) about one side apart wherever
/// the stem is thick enough for a hole. Returns the number of sides to use.
pub(crate) fn densify(stem: &Stem, sides: u32, p: &TreeParams, ts: &mut Vec<f32>, start: usize) -> u32 {
    let sides = dense_sides(sides, p);
    let Some(&last) = ts.last() else { return sides };
    let len = stem.length.max(1e-6);
    // From the plan's first ring on (a welded branch starts at its junction ring, outside its
    // parent: no ring may go below it).
    let mut t = ts.get(start).copied().unwrap_or(0.0);
    let before = ts.len();
    while t < last {
        let r = stem.radius_at(t);
        if r < 0.8 * p.hole_min_radius {
            break;
        }
        ts.push(t);
        t += (TAU * r / sides as f32 / len).max(1.0 / 512.0);
    }
    if ts.len() == before {
        return sides;
    }
    let rings = &mut ts[start..];
    rings.sort_by(f32::total_cmp);
    let mut n = 0;
    for i in 0..rings.len() {
        if n == 0 || rings[i] - rings[n - 1] > 1e-4 {
            rings[n] = rings[i];
            n += 1;
        }
    }
    ts.truncate(start + n);
    sides
}

/// Sides of an eligible stem that would get `sides` as a plain tube: enough for a hole's opening
/// to span five columns, at most 96.
pub fn dense_sides(sides: u32, p: &TreeParams) -> u32 {
    sides.max(((TAU * 2.5 / p.hole_size).ceil() as u32).min(96))
}

/// One eligible stem's part of the mesh: its block of vertices and the faces inside it.
struct Patch {
    stem: usize,
    block: Range<u32>,
    /// Triangle indices (into `indices / 3`) whose three vertices are in the block.
    faces: Vec<u32>,
    /// Per block vertex: range into `vf` of its faces (CSR).
    vf_start: Vec<u32>,
    /// Positions into `faces`.
    vf: Vec<u32>,
    /// Per block vertex: may be cut (see the module docs).
    free: Vec<bool>,
    /// Centre curve samples `(t, point)` for local radii.
    samples: Vec<(f32, Vec3)>,
}

impl Patch {
    fn local(&self, v: u32) -> usize {
        (v - self.block.start) as usize
    }

    fn faces_of(&self, v: u32) -> &[u32] {
        let l = self.local(v);
        &self.vf[self.vf_start[l] as usize..self.vf_start[l + 1] as usize]
    }

    fn is_free(&self, v: u32) -> bool {
        self.block.contains(&v) && self.free[self.local(v)]
    }

    /// Neighbour vertices of `v` (sorted, unique).
    fn neighbours(&self, mesh: &TreeMesh, v: u32, out: &mut Vec<u32>) {
        out.clear();
        for &f in self.faces_of(v) {
            let t = self.faces[f as usize] as usize * 3;
            out.extend(mesh.indices[t..t + 3].iter().copied().filter(|&w| w != v));
        }
        out.sort_unstable();
        out.dedup();
    }

    /// Fraction along the stem and local radius nearest to `x`.
    fn radius_near(&self, stem: &Stem, x: Vec3) -> (f32, f32) {
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

fn pos(mesh: &TreeMesh, v: u32) -> Vec3 {
    let k = v as usize * 3;
    Vec3::new(mesh.positions[k], mesh.positions[k + 1], mesh.positions[k + 2])
}

fn nrm(mesh: &TreeMesh, v: u32) -> Vec3 {
    let k = v as usize * 3;
    Vec3::new(mesh.normals[k], mesh.normals[k + 1], mesh.normals[k + 2])
}

fn bits(mesh: &TreeMesh, v: u32) -> [u32; 3] {
    let k = v as usize * 3;
    [mesh.positions[k].to_bits(), mesh.positions[k + 1].to_bits(), mesh.positions[k + 2].to_bits()]
}

/// Build the patches of the eligible stems: one pass over all triangles.
fn patches(mesh: &TreeMesh, blocks: &[Range<u32>], skeleton: &Skeleton, eligible: &[bool]) -> Vec<Patch> {
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
                samples: (0..=64).map(|k| (k as f32 / 64.0, stem.sample(k as f32 / 64.0).0)).collect(),
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
    for (k, t) in mesh.indices.chunks_exact(3).enumerate() {
        let (a, b, c) = (t[0], t[1], t[2]);
        if !(hit(a) || hit(b) || hit(c)) {
            continue;
        }
        let o = [a, b, c].map(|v| if hit(v) { owner(v) } else { usize::MAX });
        if o[0] != usize::MAX && o[0] == o[1] && o[1] == o[2] {
            local.push((o[0], k as u32));
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
        let mut edges: Vec<(u32, u32)> = Vec::with_capacity(p.faces.len() * 3);
        for &f in &p.faces {
            let t = &mesh.indices[f as usize * 3..f as usize * 3 + 3];
            for j in 0..3 {
                let (a, b) = (t[j], t[(j + 1) % 3]);
                edges.push((a.min(b), a.max(b)));
            }
        }
        edges.sort_unstable();
        let mut i = 0;
        while i < edges.len() {
            let mut j = i + 1;
            while j < edges.len() && edges[j] == edges[i] {
                j += 1;
            }
            if j - i != 2 {
                let (a, b) = edges[i];
                let (la, lb) = (p.local(a), p.local(b));
                p.free[la] = false;
                p.free[lb] = false;
            }
            i = j;
        }
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

/// Outside edge angle at `v` in degrees (180 flat, less when concave), or None for a vertex with
/// fewer than three neighbours.
fn edge_angle(mesh: &TreeMesh, patch: &Patch, v: u32, scratch: &mut Vec<u32>) -> Option<f32> {
    patch.neighbours(mesh, v, scratch);
    if scratch.len() < 3 {
        return None;
    }
    let (x, n) = (pos(mesh, v), nrm(mesh, v));
    let mut sum = 0.0f32;
    for &w in scratch.iter() {
        let e = unit_or(pos(mesh, w) - x, || Vec3::ZERO);
        // asin(y) = π/2 - acos(y)
        sum += 0.5 * PI - acos(e.dot(n));
    }
    Some(180.0 - 2.0 * (sum / scratch.len() as f32).to_degrees())
}

fn surface_candidates(mesh: &TreeMesh, patch: &Patch, stem: &Stem, p: &TreeParams, out: &mut Vec<Candidate>) {
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
    p: &TreeParams,
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

/// Every candidate of both methods, in a fixed order (stems in order; junctions, roots, then
/// surface clusters), before the radius filter. For tests and tools; [`cut`] uses the same list.
pub fn candidates(mesh: &TreeMesh, blocks: &[Range<u32>], skeleton: &Skeleton, p: &TreeParams) -> Vec<Candidate> {
    let twigs = super::twig::mask(skeleton, p);
    let eligible = eligible(skeleton, p, &twigs);
    let patches = patches(mesh, blocks, skeleton, &eligible);
    all_candidates(mesh, &patches, skeleton, p, &children(skeleton, &patches))
}

/// Per patch: the stems starting on its stem (branches, split clones, roots), in stem order.
fn children(skeleton: &Skeleton, patches: &[Patch]) -> Vec<Vec<u32>> {
    let mut children: Vec<Vec<u32>> = vec![Vec::new(); patches.len()];
    let slot: std::collections::BTreeMap<usize, usize> = patches.iter().enumerate().map(|(k, q)| (q.stem, k)).collect();
    for (i, s) in skeleton.stems.iter().enumerate() {
        if let Some(k) = s.parent.and_then(|par| slot.get(&(par as usize))) {
            children[*k].push(i as u32);
        }
    }
    children
}

fn all_candidates(
    mesh: &TreeMesh,
    patches: &[Patch],
    skeleton: &Skeleton,
    p: &TreeParams,
    children: &[Vec<u32>],
) -> Vec<Candidate> {
    let roots = first_root(skeleton, p);
    let mut out = Vec::new();
    for (patch, kids) in patches.iter().zip(children) {
        let stem = &skeleton.stems[patch.stem];
        structural_candidates(mesh, patch, skeleton, p, kids, roots, &mut out);
        surface_candidates(mesh, patch, stem, p, &mut out);
    }
    out
}

/// A selected disk of faces around a candidate.
struct Region {
    patch: usize,
    centre: u32,
    /// Triangle indices of the faces to remove.
    faces: Vec<u32>,
    /// Boundary loop, directed as in the removed faces (counter-clockwise from outside).
    lp: Vec<u32>,
    /// Vertices used only by removed faces (their slots are reused).
    interior: Vec<u32>,
    /// Opening half-width (m) and cavity depth (m).
    radius: f32,
    depth: f32,
    local_radius: f32,
    source: Source,
}

/// Select the faces within the hole's ellipse around `centre`; None unless they form a disk.
fn select(
    mesh: &TreeMesh,
    patch: &Patch,
    centre: u32,
    r_open: f32,
    axis: Vec3,
) -> Option<(Vec<u32>, Vec<u32>, Vec<u32>)> {
    let x0 = pos(mesh, centre);
    let inside = |x: Vec3| {
        let d = x - x0;
        let a = d.dot(axis);
        let q = d - axis * a;
        (a / ELONGATION) * (a / ELONGATION) + q.length_squared() <= r_open * r_open
    };
    let mut picked: Vec<u32> = vec![centre];
    let mut queue = vec![centre];
    let mut scratch = Vec::new();
    while let Some(v) = queue.pop() {
        patch.neighbours(mesh, v, &mut scratch);
        for &w in scratch.iter() {
            if patch.is_free(w) && !picked.contains(&w) && inside(pos(mesh, w)) {
                picked.push(w);
                queue.push(w);
            }
        }
        if picked.len() > 4096 {
            return None;
        }
    }
    picked.sort_unstable();
    let mut faces: Vec<u32> = Vec::new();
    for &v in &picked {
        for &f in patch.faces_of(v) {
            let k = patch.faces[f as usize];
            let t = &mesh.indices[k as usize * 3..k as usize * 3 + 3];
            if t.iter().all(|w| picked.binary_search(w).is_ok()) {
                faces.push(k);
            }
        }
    }
    faces.sort_unstable();
    faces.dedup();
    if faces.len() < 2 {
        return None;
    }
    // Directed edges; boundary edges are those whose reverse is not among them.
    let mut directed: Vec<(u32, u32)> = Vec::with_capacity(faces.len() * 3);
    for &k in &faces {
        let t = &mesh.indices[k as usize * 3..k as usize * 3 + 3];
        for j in 0..3 {
            directed.push((t[j], t[(j + 1) % 3]));
        }
    }
    directed.sort_unstable();
    let mut boundary: Vec<(u32, u32)> =
        directed.iter().copied().filter(|&(a, b)| directed.binary_search(&(b, a)).is_err()).collect();
    let interior_edges = (directed.len() - boundary.len()) / 2;
    let edges = interior_edges + boundary.len();
    let mut verts: Vec<u32> = directed.iter().map(|e| e.0).collect();
    verts.sort_unstable();
    verts.dedup();
    // Euler characteristic of a disk: V - E + F = 1.
    if verts.len() as i64 - edges as i64 + faces.len() as i64 != 1 || boundary.len() < 3 {
        return None;
    }
    boundary.sort_unstable();
    // One simple loop: every boundary vertex starts exactly one boundary edge and all are visited.
    if boundary.windows(2).any(|w| w[0].0 == w[1].0) {
        return None;
    }
    let mut lp = Vec::with_capacity(boundary.len());
    let start = boundary[0].0;
    let mut v = start;
    loop {
        lp.push(v);
        let i = boundary.binary_search_by(|e| e.0.cmp(&v)).ok()?;
        v = boundary[i].1;
        if v == start || lp.len() > boundary.len() {
            break;
        }
    }
    if v != start || lp.len() != boundary.len() {
        return None;
    }
    let mut on_loop = lp.clone();
    on_loop.sort_unstable();
    if on_loop.binary_search(&centre).is_ok() {
        return None; // the hole must surround its centre
    }
    let interior: Vec<u32> = verts.into_iter().filter(|w| on_loop.binary_search(w).is_err()).collect();
    Some((faces, lp, interior))
}

/// Closest distance between segments `[a0, a1]` and `[b0, b1]`.
fn segment_distance(a0: Vec3, a1: Vec3, b0: Vec3, b1: Vec3) -> f32 {
    let (d1, d2, r) = (a1 - a0, b1 - b0, a0 - b0);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let (s, t) = if a <= 1e-12 && e <= 1e-12 {
        (0.0, 0.0)
    } else if a <= 1e-12 {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(r);
        if e <= 1e-12 {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(d2);
            let den = a * e - b * b;
            let mut s = if den > 1e-12 { ((b * f - c * e) / den).clamp(0.0, 1.0) } else { 0.0 };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    ((a0 + d1 * s) - (b0 + d2 * t)).length()
}

/// Cut `p.hole_count` holes into `mesh` (the bark, `blocks[i]` the vertices swept for stem `i`).
/// Returns the holes actually cut (fewer when there are not enough valid places).
pub fn cut(mesh: &mut TreeMesh, blocks: &[Range<u32>], skeleton: &Skeleton, p: &TreeParams) -> Vec<Hole> {
    if p.hole_count == 0 || mesh.indices.is_empty() {
        return Vec::new();
    }
    let twigs = super::twig::mask(skeleton, p);
    let eligible = eligible(skeleton, p, &twigs);
    let mut patches = patches(mesh, blocks, skeleton, &eligible);
    if patches.is_empty() {
        return Vec::new();
    }
    let mut cands: Vec<Candidate> = all_candidates(mesh, &patches, skeleton, p, &children(skeleton, &patches))
        .into_iter()
        .filter(|c| c.local_radius >= p.hole_min_radius && c.local_radius > 0.0)
        .collect();
    let mut rng = Rng::new(u64::from(p.seed) ^ (u64::from(p.hole_seed) << 32), "holes");
    for i in (1..cands.len()).rev() {
        let j = (rng.next_u32() as usize) % (i + 1);
        cands.swap(i, j);
    }
    let kids = children(skeleton, &patches);
    let mut regions: Vec<(Region, Cavity)> = Vec::new();
    // Cavities add vertices: a hole that would take the mesh past the vertex budget is skipped,
    // so the budget holds with holes too (fewer holes, never a bigger mesh).
    let mut room = (p.max_vertices as usize).saturating_sub(mesh.vertex_count());
    for c in cands {
        if regions.len() >= p.hole_count as usize {
            break;
        }
        let Some(pi) = patches.iter().position(|q| q.stem == c.stem as usize) else { continue };
        let patch = &patches[pi];
        if !patch.is_free(c.vertex) {
            continue;
        }
        let stem = &skeleton.stems[c.stem as usize];
        let x0 = pos(mesh, c.vertex);
        let (t, _) = patch.radius_near(stem, x0);
        let axis = stem.sample(t).1;
        let n0 = nrm(mesh, c.vertex);
        let r_open = p.hole_size * c.local_radius;
        let depth = p.hole_depth * c.local_radius;
        // Keep clear of earlier holes (their rims plus a margin).
        if regions.iter().any(|(h, _)| (pos(mesh, h.centre) - x0).length() < 1.6 * ELONGATION * (h.radius + r_open)) {
            continue;
        }
        // Keep clear of the buried part of every child stem starting on this stem.
        let bottom = x0 - n0 * depth;
        let clear = kids[pi].iter().all(|&k| {
            let s = &skeleton.stems[k as usize];
            let reach = (2.5 * c.local_radius).min(s.length);
            let (tip, _) = s.point_at(reach);
            let need = s.radius_at(0.0) + ELONGATION * r_open * 1.1;
            segment_distance(x0, bottom, s.base(), tip) >= need
        });
        if !clear {
            continue;
        }
        // The thesis shrinks a selection that is not a clean disk; on a coarse mesh a larger one
        // may be needed, so a few sizes around the asked one are tried.
        let mut found = None;
        for f in [1.0, 0.8, 1.25, 1.6, 2.0] {
            let r_try = r_open * f;
            let Some((faces, lp, interior)) = select(mesh, patch, c.vertex, r_try, axis) else { continue };
            let region = Region {
                patch: pi,
                centre: c.vertex,
                faces,
                lp,
                interior,
                radius: r_try,
                depth,
                local_radius: c.local_radius,
                source: c.source,
            };
            if let Some(cav) = plan_cavity(mesh, &region, c.stem) {
                found = Some((region, cav));
                break;
            }
        }
        let Some((region, cav)) = found else { continue };
        if cav.verts.len() > room {
            continue;
        }
        room -= cav.verts.len();
        let patch = &mut patches[pi];
        for &k in &region.faces {
            for &v in &mesh.indices[k as usize * 3..k as usize * 3 + 3] {
                let l = patch.local(v);
                patch.free[l] = false;
            }
        }
        regions.push((region, cav));
    }
    drop_coincident(mesh, &patches, &mut regions);
    let mut new_tris: Vec<[u32; 3]> = Vec::new();
    let mut freed_tris: Vec<u32> = Vec::new();
    for (r, cav) in &regions {
        commit(mesh, r, cav, &mut new_tris);
        freed_tris.extend_from_slice(&r.faces);
        drop_rings(mesh, &r.interior);
    }
    write_triangles(mesh, &mut freed_tris, &new_tris);
    regions.into_iter().map(|(_, cav)| cav.hole).collect()
}

/// Drop regions with a vertex whose position another vertex outside its block shares (a welded
/// copy made by a later stage): cutting there could open the welded surface.
fn drop_coincident<T>(mesh: &TreeMesh, patches: &[Patch], regions: &mut Vec<(Region, T)>) {
    if regions.is_empty() {
        return;
    }
    let boxes: Vec<(Vec3, Vec3, Vec<[u32; 3]>)> = regions
        .iter()
        .map(|(r, _)| {
            let mut lo = Vec3::splat(f32::INFINITY);
            let mut hi = Vec3::splat(f32::NEG_INFINITY);
            let mut keys = Vec::new();
            for &k in &r.faces {
                for &v in &mesh.indices[k as usize * 3..k as usize * 3 + 3] {
                    let x = pos(mesh, v);
                    lo = lo.min(x);
                    hi = hi.max(x);
                    keys.push(bits(mesh, v));
                }
            }
            keys.sort_unstable();
            keys.dedup();
            (lo, hi, keys)
        })
        .collect();
    let (ulo, uhi) = boxes
        .iter()
        .fold((Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)), |(a, b), x| (a.min(x.0), b.max(x.1)));
    let mut bad = vec![false; regions.len()];
    for (v, q) in mesh.positions.chunks_exact(3).enumerate() {
        let x = Vec3::new(q[0], q[1], q[2]);
        if x.cmplt(ulo).any() || x.cmpgt(uhi).any() {
            continue;
        }
        for (ri, (lo, hi, keys)) in boxes.iter().enumerate() {
            if x.cmplt(*lo).any() || x.cmpgt(*hi).any() || patches[regions[ri].0.patch].block.contains(&(v as u32)) {
                continue;
            }
            if keys.binary_search(&[q[0].to_bits(), q[1].to_bits(), q[2].to_bits()]).is_ok() {
                bad[ri] = true;
            }
        }
    }
    let mut i = 0;
    regions.retain(|_| {
        i += 1;
        !bad[i - 1]
    });
}

/// A vertex of a cavity triangle: an existing rim vertex or the `k`-th new vertex.
#[derive(Clone, Copy, Debug)]
enum Id {
    Rim(u32),
    New(usize),
}

/// The geometry of one cavity before it is written into the mesh.
struct Cavity {
    /// New vertices: position, normal, uv, and the rim vertex whose wind entry they copy.
    verts: Vec<(Vec3, Vec3, [f32; 2], u32)>,
    tris: Vec<[Id; 3]>,
    hole: Hole,
}

/// Build the cavity of one region (chamfered rim, extruded rings, bottom fan, smoothing,
/// normals); None if any new triangle would be degenerate or wound against its normals.
fn plan_cavity(mesh: &TreeMesh, r: &Region, stem: u32) -> Option<Cavity> {
    let lp = &r.lp;
    let m = lp.len();
    let rim: Vec<Vec3> = lp.iter().map(|&v| pos(mesh, v)).collect();
    let c0 = pos(mesh, r.centre);
    let n = unit_or(lp.iter().map(|&v| nrm(mesh, v)).sum::<Vec3>(), || nrm(mesh, r.centre));
    let g = rim.iter().copied().sum::<Vec3>() / m as f32;
    let h_c = (c0 - g).dot(n);
    let q: Vec<Vec3> = rim.iter().map(|&x| (x - g) - n * (x - g).dot(n)).collect();
    let h: Vec<f32> = rim.iter().map(|&x| (x - g).dot(n)).collect();
    // The loop must be star-shaped around its centre seen along the normal, so that the inset
    // rings (scaled copies) never fold.
    for i in 0..m {
        let (a, b) = (q[i], q[(i + 1) % m]);
        if a.cross(b).dot(n) <= 0.05 * a.length() * b.length() {
            return None;
        }
    }
    let mean_q = q.iter().map(|v| v.length()).sum::<f32>() / m as f32;
    let bevel = (0.3 * CHAMFER * mean_q).min(0.5 * r.depth);
    let rings = CAVITY_RINGS + 1; // the chamfer ring, then the cavity rings
    let mut ring_pos: Vec<Vec<Vec3>> = (0..rings)
        .map(|k| {
            let a = k as f32 / CAVITY_RINGS as f32;
            let s = (1.0 - CHAMFER) * (1.0 - 0.35 * a * a);
            let d = bevel + (r.depth - bevel) * a;
            (0..m).map(|i| g + q[i] * s + n * (h[i] * (1.0 - a) + h_c * a - d)).collect()
        })
        .collect();
    let bottom = g + n * (h_c - r.depth);
    // Laplacian smoothing of the cavity rings (the chamfer ring and the bottom stay).
    for _ in 0..SMOOTH_PASSES {
        let old = ring_pos.clone();
        for k in 1..rings {
            for i in 0..m {
                let below = if k + 1 < rings { old[k + 1][i] } else { bottom };
                let avg = (old[k][(i + m - 1) % m] + old[k][(i + 1) % m] + old[k - 1][i] + below) * 0.25;
                ring_pos[k][i] = old[k][i] + (avg - old[k][i]) * 0.5;
            }
        }
    }
    let circumference = TAU * r.local_radius.max(1e-6);
    let rim_uv: Vec<[f32; 2]> = lp.iter().map(|&v| [mesh.uvs[v as usize * 2], mesh.uvs[v as usize * 2 + 1]]).collect();
    let id = |k: usize, i: usize| Id::New(k * m + i);
    let mut verts = vec![(Vec3::ZERO, Vec3::ZERO, [0.0f32; 2], 0u32); rings * m + 1];
    for i in 0..m {
        let mut along = 0.0f32;
        let mut prev = rim[i];
        for (k, ring) in ring_pos.iter().enumerate() {
            along += (ring[i] - prev).length();
            prev = ring[i];
            verts[k * m + i] = (ring[i], Vec3::ZERO, [rim_uv[i][0], rim_uv[i][1] + along / circumference], lp[i]);
        }
    }
    let nearest = (0..m).min_by(|&a, &b| (rim[a] - g).length().total_cmp(&(rim[b] - g).length())).unwrap_or(0);
    let mean_uv = rim_uv.iter().fold([0.0f32; 2], |s, u| [s[0] + u[0] / m as f32, s[1] + u[1] / m as f32]);
    verts[rings * m] = (bottom, Vec3::ZERO, [mean_uv[0], mean_uv[1] + (r.depth + bevel) / circumference], lp[nearest]);
    let bottom_id = Id::New(rings * m);
    // Triangles: rim -> chamfer ring -> cavity rings -> bottom fan, each strip wound like the
    // removed faces (the region lies left of every loop edge).
    let mut tris = Vec::with_capacity(m * (2 * rings + 1));
    for i in 0..m {
        let j = (i + 1) % m;
        tris.push([Id::Rim(lp[i]), Id::Rim(lp[j]), id(0, j)]);
        tris.push([Id::Rim(lp[i]), id(0, j), id(0, i)]);
        for k in 1..rings {
            tris.push([id(k - 1, i), id(k - 1, j), id(k, j)]);
            tris.push([id(k - 1, i), id(k, j), id(k, i)]);
        }
        tris.push([id(rings - 1, i), id(rings - 1, j), bottom_id]);
    }
    let at = |v: Id, verts: &[(Vec3, Vec3, [f32; 2], u32)]| match v {
        Id::Rim(w) => (pos(mesh, w), nrm(mesh, w)),
        Id::New(k) => (verts[k].0, verts[k].1),
    };
    // Normals of the new vertices: area-weighted normals of their faces.
    for t in &tris {
        let (a, b, c) = (at(t[0], &verts).0, at(t[1], &verts).0, at(t[2], &verts).0);
        let f = (b - a).cross(c - a);
        for v in t {
            if let Id::New(k) = *v {
                verts[k].1 += f;
            }
        }
    }
    for v in &mut verts {
        v.1 = unit_or(v.1, || n);
    }
    // Every new triangle must be a real triangle wound with its vertex normals.
    let min_area = 1e-6 * r.radius * r.radius;
    for t in &tris {
        let ([a, b, c], [na, nb, nc]) = (t.map(|v| at(v, &verts).0), t.map(|v| at(v, &verts).1));
        let f = (b - a).cross(c - a);
        let area = f.length();
        if area.is_nan() || area <= min_area || f.dot(na + nb + nc) <= 0.0 {
            return None;
        }
    }
    let hole = Hole { stem, source: r.source, centre: c0, normal: n, radius: r.radius, depth: (c0 - bottom).dot(n) };
    Some(Cavity { verts, tris, hole })
}

/// Drop the tube rings ([`TreeMesh::rings`]) holding any of `slots` (vertices a cavity rewrote
/// or parked): they no longer sit on their ring.
fn drop_rings(mesh: &mut TreeMesh, slots: &[u32]) {
    let rings = &mesh.rings;
    let mut gone: Vec<usize> = slots
        .iter()
        .filter_map(|&v| {
            let i = rings.partition_point(|r| r[0] <= v).checked_sub(1)?;
            (v < rings[i][0] + rings[i][1]).then_some(i)
        })
        .collect();
    gone.sort_unstable();
    gone.dedup();
    let mut k = 0;
    let mut i = 0;
    mesh.rings.retain(|_| {
        let drop = gone.get(k) == Some(&i);
        k += usize::from(drop);
        i += 1;
        !drop
    });
}

/// Write a planned cavity: new vertices reuse the removed interior slots, then append; the
/// triangles (in mesh indices) go to `tris`.
fn commit(mesh: &mut TreeMesh, r: &Region, cav: &Cavity, tris: &mut Vec<[u32; 3]>) {
    let needed = cav.verts.len();
    let mut slots: Vec<u32> = r.interior.iter().copied().take(needed).collect();
    let extra = needed - slots.len();
    let first_new = mesh.vertex_count() as u32;
    slots.extend(first_new..first_new + extra as u32);
    let has_wind = !mesh.wind.is_empty() && mesh.wind.len() == first_new as usize * WIND_STRIDE;
    mesh.positions.resize(mesh.positions.len() + 3 * extra, 0.0);
    mesh.normals.resize(mesh.normals.len() + 3 * extra, 0.0);
    mesh.uvs.resize(mesh.uvs.len() + 2 * extra, 0.0);
    if has_wind {
        mesh.wind.resize(mesh.wind.len() + WIND_STRIDE * extra, 0.0);
    }
    let set = |mesh: &mut TreeMesh, v: u32, (x, nv, uv, src): (Vec3, Vec3, [f32; 2], u32)| {
        let k = v as usize;
        mesh.positions[k * 3..k * 3 + 3].copy_from_slice(&x.to_array());
        mesh.normals[k * 3..k * 3 + 3].copy_from_slice(&nv.to_array());
        mesh.uvs[k * 2..k * 2 + 2].copy_from_slice(&uv);
        if has_wind {
            let s = src as usize * WIND_STRIDE;
            mesh.wind.copy_within(s..s + WIND_STRIDE, k * WIND_STRIDE);
        }
    };
    for (&v, &data) in slots.iter().zip(&cav.verts) {
        set(mesh, v, data);
    }
    // Interior slots the cavity does not need stay unreferenced; park them on the bottom point.
    let bottom = *cav.verts.last().expect("a cavity has a bottom");
    for &v in r.interior.iter().skip(needed) {
        set(mesh, v, bottom);
    }
    tris.extend(cav.tris.iter().map(|t| {
        t.map(|v| match v {
            Id::Rim(w) => w,
            Id::New(k) => slots[k],
        })
    }));
}

/// Replace the removed triangles by the new ones: new triangles fill the removed slots first;
/// the rest go at the end of the group holding the first removed triangle, or, when fewer new
/// triangles than removed ones, the leftover slots are dropped.
fn write_triangles(mesh: &mut TreeMesh, freed: &mut [u32], new: &[[u32; 3]]) {
    freed.sort_unstable();
    let fill = freed.len().min(new.len());
    for (k, t) in freed.iter().zip(new) {
        mesh.indices[*k as usize * 3..*k as usize * 3 + 3].copy_from_slice(t);
    }
    if freed.len() > fill {
        let drop = &freed[fill..];
        let mut groups = mesh.groups.clone();
        for g in &mut groups {
            let (lo, hi) = (g.start / 3, (g.start + g.count) / 3);
            let gone = drop.iter().filter(|&&k| k >= lo && k < hi).count() as u32;
            g.count -= 3 * gone;
        }
        // Groups tile the index buffer in order (MeshBuilder), so starts follow the counts.
        let mut start = 0;
        for g in &mut groups {
            g.start = start;
            start += g.count;
        }
        let mut k = 0usize;
        let mut t = 0u32;
        mesh.indices.retain(|_| {
            let tri = t / 3;
            t += 1;
            while k < drop.len() && drop[k] < tri {
                k += 1;
            }
            !(k < drop.len() && drop[k] == tri)
        });
        mesh.groups = groups;
        return;
    }
    let rest: Vec<u32> = new[fill..].iter().flatten().copied().collect();
    if rest.is_empty() {
        return;
    }
    let first = freed.first().map_or(0, |&k| k * 3);
    let gi = mesh.groups.iter().position(|g| first >= g.start && first < g.start + g.count);
    let at = match gi {
        Some(i) => (mesh.groups[i].start + mesh.groups[i].count) as usize,
        None => mesh.indices.len(),
    };
    let added = rest.len() as u32;
    mesh.indices.splice(at..at, rest);
    if let Some(i) = gi {
        mesh.groups[i].count += added;
        for g in &mut mesh.groups[i + 1..] {
            g.start += added;
        }
    }
}
