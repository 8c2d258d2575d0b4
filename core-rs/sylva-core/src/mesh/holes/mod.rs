//! # Tree holes
//!
//! A post-process on the bark mesh that cuts cavities into the trunk and into level-1 stems thick
//! enough for them ([`eligible`]), after the tree-hole chapter of the tree-generator thesis posted
//! on 3dideas.wordpress.com (2008): §4.3 "Hole Generation" and §4.4 "Recommended Methods for Hole
//! Generation".
//!
//! ## Where (§4.4)
//!
//! * *Surface*: vertices more than [`CONCAVE_DEG`] below a flat surface's 180° outside edge angle
//!   (flutes, lobes, buttress valleys), grouped in clusters of at least [`MIN_CLUSTER`]; each
//!   cluster's lowest vertex is a candidate.
//! * *Structural*: below the junction of every big child and between neighbouring root starts.
//!
//! Candidates on stems thinner than `hole_min_radius` are dropped; the rest are taken in a random
//! order (stream `"holes"`) until `hole_count` are cut, away from earlier holes and buried bases.
//!
//! ## How (§4.3: chamfer, connect, delete, extrude, subdivide)
//!
//! The faces inside the hole's ellipse (`hole_size` × local radius, 1.5 times taller along the
//! stem) must form a topological disk (else it shrinks and retries); they are removed, the rim
//! gets a rolled callus lip and a chamfer, and is extruded inward into [`CAVITY_RINGS`] rings
//! narrowing to a closed bottom `hole_depth` × local radius deep, smoothed by Laplacian passes.
//!
//! ## Invariants
//!
//! Only *free* faces are cut (inside the stem's block, on no junction bridge, open edge or shared
//! position), so the bark stays closed and edge-manifold. New normals face into the cavity, `v`
//! continues the bark's, wind entries come from the nearest rim vertex; the rings holding a reused
//! slot leave `TreeMesh::rings`.

mod candidates;
mod cavity;
mod cut;
mod patch;

use super::layout::Layout;
use super::TreeMesh;
use crate::math::TAU;
use crate::params::MeshParams;
use crate::rng::Rng;
use crate::skeleton::{Skeleton, Stem};
use candidates::{all_candidates, children};
use cavity::{plan_cavity, Cavity};
pub use cut::near_x;
use cut::{commit, drop_coincident, drop_rings, select, write_triangles};
use glam::Vec3;
use patch::{nrm, patches, pos};
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
/// Height of the rolled callus lip around an opening, as a fraction of its half-size (the wound
/// wood a tree grows over the edge of a cavity).
const LIP: f32 = 0.22;
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

/// A selected disk of faces around a candidate.
pub(super) struct Region {
    pub(super) patch: usize,
    pub(super) centre: u32,
    /// Triangle indices of the faces to remove.
    pub(super) faces: Vec<u32>,
    /// Boundary loop, directed as in the removed faces (counter-clockwise from outside).
    pub(super) lp: Vec<u32>,
    /// Vertices used only by removed faces (their slots are reused).
    pub(super) interior: Vec<u32>,
    /// Opening half-width (m) and cavity depth (m).
    pub(super) radius: f32,
    pub(super) depth: f32,
    pub(super) local_radius: f32,
    pub(super) source: Source,
}

/// Whether stem `i` can carry holes: the trunk records whose base is at least `hole_min_radius`
/// thick, and level-1 stems (not roots, not Bezier twigs) at least twice that (a thinner branch
/// would be densified along its whole length for a hole near its base only). The tube densifies these (rings about
/// as far apart as the sides, see [`densify`]) when holes are asked for.
pub fn eligible(skeleton: &Skeleton, p: &MeshParams, twigs: &[bool]) -> Vec<bool> {
    let n = skeleton.stems.len();
    if p.hole_count == 0 {
        return Vec::new();
    }
    let roots = skeleton.first_root();
    skeleton
        .stems
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let min = if s.level == 0 { p.hole_min_radius } else { 2.0 * p.hole_min_radius };
            s.level <= 1
                && i < roots
                && !s.cut_end
                && !twigs.get(i).copied().unwrap_or(false)
                && s.radius_at(0.0) >= min
        })
        .chain(std::iter::repeat(false))
        .take(n)
        .collect()
}

/// Make an eligible stem's mesh dense enough for holes, as that chapter (§4.3) cuts them into a dense
/// mesh: at least enough sides for an opening to span five columns (at most 96), and rings added
/// to its plan (`ts[start..]`, sorted, the last one next to the tip) about one side apart wherever
/// the stem is thick enough for a hole. Returns the number of sides to use.
pub(crate) fn densify(stem: &Stem, sides: u32, p: &MeshParams, ts: &mut Vec<f32>, start: usize) -> u32 {
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
    ts[start..].sort_by(f32::total_cmp);
    super::stem::drop_close(ts, start);
    sides
}

/// Sides of an eligible stem that would get `sides` as a plain tube: enough for a hole's opening
/// to span five columns, at most 96.
pub fn dense_sides(sides: u32, p: &MeshParams) -> u32 {
    sides.max(((TAU * 2.5 / p.hole_size).ceil() as u32).min(96))
}

/// Every candidate of both methods, in a fixed order (stems in order; junctions, roots, then
/// surface clusters), before the radius filter. For tests and tools; [`cut`](fn@cut) uses the same list.
pub fn candidates(mesh: &TreeMesh, blocks: &[Range<u32>], skeleton: &Skeleton, p: &MeshParams) -> Vec<Candidate> {
    let twigs = super::twig::mask(skeleton);
    let eligible = eligible(skeleton, p, &twigs);
    let patches = patches(mesh, blocks, skeleton, &eligible, None);
    all_candidates(mesh, &patches, skeleton, p, &children(skeleton, &patches))
}

/// Cut `p.hole_count` holes into `mesh`, the bark as the sweep laid it out (`layout`: each
/// stem's vertices and triangles, and the stems swept for holes), both from the same `p`: a
/// bark swept without holes has no stems dense enough for them, and gets none. Returns the
/// holes actually cut (fewer when there are not enough valid places).
pub fn cut(mesh: &mut TreeMesh, layout: &Layout, skeleton: &Skeleton, p: &MeshParams) -> Vec<Hole> {
    if p.hole_count == 0 || mesh.indices.is_empty() {
        return Vec::new();
    }
    let mut patches = patches(mesh, &layout.blocks, skeleton, &layout.eligible, Some(layout));
    if patches.is_empty() {
        return Vec::new();
    }
    let kids = children(skeleton, &patches);
    let mut cands: Vec<Candidate> = all_candidates(mesh, &patches, skeleton, p, &kids)
        .into_iter()
        .filter(|c| c.local_radius >= p.hole_min_radius && c.local_radius > 0.0)
        .collect();
    let mut rng = Rng::new(u64::from(skeleton.seed) ^ (u64::from(p.hole_seed) << 32), "holes");
    for i in (1..cands.len()).rev() {
        let j = (rng.next_u32() as usize) % (i + 1);
        cands.swap(i, j);
    }
    let mut regions: Vec<(Region, Cavity)> = Vec::new();
    // Cavities add vertices: a hole that would take the mesh past the vertex budget is skipped,
    // so the budget holds with holes too (fewer holes, never a bigger mesh).
    let mut room = (skeleton.max_vertices as usize).saturating_sub(mesh.vertex_count());
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
        // The hole recipe (§4.3) shrinks a selection that is not a clean disk; on a coarse mesh a larger one
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
