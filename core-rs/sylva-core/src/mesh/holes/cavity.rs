//! The cavity of one hole (the tree-generator thesis posted on 3dideas.wordpress.com (2008), §4.3
//! "Hole Generation": the extrude and subdivide steps of the 3ds Max recipe): the boundary loop
//! gets a rolled callus lip (three rings rising to [`LIP`] × the opening's half-size above the
//! surface and curling over the edge, along a round copy of the loop, which on a coarse mesh
//! zigzags around the ellipse), then a chamfered ring (inset toward the loop's centre and bevelled
//! inward), and that rim is extruded inward along minus the surface normal into [`CAVITY_RINGS`]
//! rings that narrow toward a closed bottom `hole_depth` × local radius below the surface; the
//! cavity rings are then smoothed by a few Laplacian passes (that recipe's final subdivision, which
//! softens the edges). New normals are area-weighted face normals, so they face into the cavity
//! (out of the wood); `u` follows the rim, `v` continues the bark's at one unit per circumference.

use super::patch::{nrm, pos};
use super::{Hole, Region, CAVITY_RINGS, CHAMFER, LIP, SMOOTH_PASSES};
use crate::math::{unit_or, TAU};
use crate::mesh::TreeMesh;
use glam::Vec3;

/// A vertex of a cavity triangle: an existing rim vertex or the `k`-th new vertex.
#[derive(Clone, Copy, Debug)]
pub(super) enum Id {
    Rim(u32),
    New(usize),
}

/// The geometry of one cavity before it is written into the mesh.
pub(super) struct Cavity {
    /// New vertices: position, normal, uv, and the rim vertex whose wind entry they copy.
    pub(super) verts: Vec<(Vec3, Vec3, [f32; 2], u32)>,
    pub(super) tris: Vec<[Id; 3]>,
    pub(super) hole: Hole,
}

/// The loop's offsets from its centre with their lengths low-pass filtered around the loop
/// (three passes of a 1-2-1 kernel): same directions, a round outline.
fn round_loop(q: &[Vec3]) -> Vec<Vec3> {
    let m = q.len();
    let mut len: Vec<f32> = q.iter().map(|v| v.length()).collect();
    for _ in 0..3 {
        let old = len.clone();
        for i in 0..m {
            len[i] = 0.25 * old[(i + m - 1) % m] + 0.5 * old[i] + 0.25 * old[(i + 1) % m];
        }
    }
    q.iter().zip(&len).map(|(v, &l)| unit_or(*v, || Vec3::ZERO) * l).collect()
}

/// Laplacian smoothing of the cavity rings from ring `first` on (the roll, the chamfer ring and
/// the bottom stay).
fn smooth_rings(ring_pos: &mut [Vec<Vec3>], first: usize, bottom: Vec3) {
    let rings = ring_pos.len();
    let m = ring_pos.first().map_or(0, Vec::len);
    for _ in 0..SMOOTH_PASSES {
        let old = ring_pos.to_vec();
        for k in first..rings {
            for i in 0..m {
                let below = if k + 1 < rings { old[k + 1][i] } else { bottom };
                let avg = (old[k][(i + m - 1) % m] + old[k][(i + 1) % m] + old[k - 1][i] + below) * 0.25;
                ring_pos[k][i] = old[k][i] + (avg - old[k][i]) * 0.5;
            }
        }
    }
}

/// Build the cavity of one region (chamfered rim, extruded rings, bottom fan, smoothing,
/// normals); None if any new triangle would be degenerate or wound against its normals.
pub(super) fn plan_cavity(mesh: &TreeMesh, r: &Region, stem: u32) -> Option<Cavity> {
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
    // The wall drops right inside the lip, so the opening reads as a dark ellipse in its rim.
    let bevel = (0.35 * mean_q).min(0.5 * r.depth);
    let lip = LIP * mean_q;
    // The loop runs along mesh edges and zigzags in and out around the ellipse (a star on a
    // coarse mesh); the rings inside it follow a round copy of it.
    let round = round_loop(&q);
    // The callus roll: three rings rise above the rim, crest and curl over into the opening,
    // then the chamfer ring tucks under it; the cavity rings follow. No roll ring may reach
    // past the (zigzag) rim it starts from.
    let roll = [(0.97, -0.55 * lip), (0.9, -lip), (0.84, -0.6 * lip)];
    let rings = CAVITY_RINGS + 1 + roll.len();
    let at_scale = |i: usize, s: f32| {
        let inside = 0.96 * q[i].length();
        let len = round[i].length();
        if len * s > inside && len > 0.0 {
            round[i] * (inside / len)
        } else {
            round[i] * s
        }
    };
    let mut ring_pos: Vec<Vec<Vec3>> = (0..rings)
        .map(|k| {
            if let Some(&(s, d)) = roll.get(k) {
                return (0..m).map(|i| g + at_scale(i, s) + n * (h[i] - d)).collect();
            }
            let a = (k - roll.len()) as f32 / CAVITY_RINGS as f32;
            let s = (1.0 - CHAMFER) * (1.0 - 0.35 * a * a);
            let d = bevel + (r.depth - bevel) * a;
            (0..m).map(|i| g + at_scale(i, s) + n * (h[i] * (1.0 - a) + h_c * a - d)).collect()
        })
        .collect();
    let bottom = g + n * (h_c - r.depth);
    smooth_rings(&mut ring_pos, roll.len() + 1, bottom);
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
