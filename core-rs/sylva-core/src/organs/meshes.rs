//! The parts' meshes, in metres, each attached at the origin and pointing along `+y`.
//!
//! * **Petals** come from the leaf pipeline ([`crate::leaf::generate`]): a spline outline
//!   (obovate, entire margin, no veins) triangulated and cupped like a leaf blade, five of them
//!   turned by 72° about the flower's axis and tilted up into a shallow cup. A samara's wings
//!   are two leaf blades too, long and narrow, spread in a V.
//! * **Round parts** (fruit, cones, catkins, buds, the flower's centre, stalks) are surfaces of
//!   revolution about `+y` ([`lathe`]): a profile of `(y, r)` from one pole to the other,
//!   closed at both, counter-clockwise seen from outside; a cone's and a catkin's profile
//!   ripples ring by ring for their scales.
//!
//! Every mesh is built once per process and kept (a pure function of its kind).

use super::calendar::Part;
use super::set::OrganKind;
use crate::leaf;
use crate::math;
use crate::mesh::{Material, MeshGroup, TreeMesh};
use crate::params::{Fruit, LeafMargin, LeafOutline, LeafPrimaries, LeafVenation, TreeParams};
use glam::Vec3;
use std::sync::{Arc, Mutex};

/// Sides around every surface of revolution.
const SIDES: usize = 8;

/// A closed surface of revolution about `+y`: `profile` runs `(y, r)` from the bottom pole
/// (its `r` ignored) through rings (`r > 0`) to the top pole.
pub fn lathe(profile: &[(f32, f32)], sides: usize) -> TreeMesh {
    let n = profile.len();
    assert!(n >= 3, "a lathe needs two poles and a ring");
    let mut m = TreeMesh::default();
    let mut vertex = |p: Vec3, nrm: Vec3, uv: [f32; 2]| {
        m.positions.extend_from_slice(&p.to_array());
        m.normals.extend_from_slice(&nrm.to_array());
        m.uvs.extend_from_slice(&uv);
    };
    vertex(Vec3::new(0.0, profile[0].0, 0.0), Vec3::NEG_Y, [0.5, 0.0]);
    let turns: Vec<(f32, f32)> = (0..=sides)
        .map(|j| {
            let a = std::f32::consts::TAU * (j % sides) as f32 / sides as f32;
            (math::sin(a), math::cos(a))
        })
        .collect();
    for i in 1..n - 1 {
        let (y, r) = profile[i];
        let (dy, dr) = (profile[i + 1].0 - profile[i - 1].0, profile[i + 1].1 - profile[i - 1].1);
        let len = (dy * dy + dr * dr).sqrt().max(1e-12);
        let (nr, ny) = (dy / len, -dr / len);
        for (j, &(s, c)) in turns.iter().enumerate() {
            let uv = [j as f32 / sides as f32, i as f32 / (n - 1) as f32];
            vertex(Vec3::new(r * s, y, r * c), Vec3::new(nr * s, ny, nr * c), uv);
        }
    }
    vertex(Vec3::new(0.0, profile[n - 1].0, 0.0), Vec3::Y, [0.5, 1.0]);
    let ring = |i: usize, j: usize| (1 + (i - 1) * (sides + 1) + j) as u32;
    let top = (m.positions.len() / 3 - 1) as u32;
    for j in 0..sides {
        m.indices.extend_from_slice(&[0, ring(1, j + 1), ring(1, j)]);
        for i in 1..n - 2 {
            let (a0, a1, b0, b1) = (ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1));
            m.indices.extend_from_slice(&[a0, a1, b1, a0, b1, b0]);
        }
        m.indices.extend_from_slice(&[top, ring(n - 2, j), ring(n - 2, j + 1)]);
    }
    close(m)
}

/// One group over the whole mesh.
fn close(mut m: TreeMesh) -> TreeMesh {
    m.groups = vec![MeshGroup { material: Material::Organ, start: 0, count: m.indices.len() as u32 }];
    m
}

/// A profile of `rings` rings from `y = 0` to `length`, radius `radius · shape(t)` (`t` 0..1
/// along it), every other ring `1 + ripple` times wider.
fn profile(length: f32, radius: f32, rings: usize, ripple: f32, shape: impl Fn(f32) -> f32) -> Vec<(f32, f32)> {
    let mut p = vec![(0.0, 0.0)];
    for i in 1..=rings {
        let t = i as f32 / (rings + 1) as f32;
        let bump = if i % 2 == 0 { 1.0 + ripple } else { 1.0 };
        p.push((length * t, radius * shape(t).max(0.02) * bump));
    }
    p.push((length, 0.0));
    p
}

/// `sin(π t)`.
fn arch(t: f32) -> f32 {
    math::sin(std::f32::consts::PI * t.clamp(0.0, 1.0))
}

/// Appends `src` to `dst`, its points mapped by the rotation `basis` (columns: where `x`, `y`
/// and `z` go, orthonormal and right-handed) and then moved by `offset`, scaled by `scale`.
fn append(dst: &mut TreeMesh, src: &TreeMesh, basis: [Vec3; 3], scale: Vec3, offset: Vec3) {
    let base = (dst.positions.len() / 3) as u32;
    for (p, n) in src.positions.chunks_exact(3).zip(src.normals.chunks_exact(3)) {
        let q = basis[0] * (p[0] * scale.x) + basis[1] * (p[1] * scale.y) + basis[2] * (p[2] * scale.z) + offset;
        // Normals of a non-uniformly scaled blade: the inverse scale, renormalised.
        let m = basis[0] * (n[0] / scale.x) + basis[1] * (n[1] / scale.y) + basis[2] * (n[2] / scale.z);
        dst.positions.extend_from_slice(&q.to_array());
        dst.normals.extend_from_slice(&m.normalize_or(Vec3::Y).to_array());
    }
    dst.uvs.extend_from_slice(&src.uvs);
    dst.indices.extend(src.indices.iter().map(|i| i + base));
}

/// A blade from the leaf pipeline: a spline outline with base angle `a1` and tip angle `a2`
/// (degrees), entire, veinless, cupped across by `cup`.
fn blade(a1: f32, a2: f32, cup: f32) -> TreeMesh {
    let mut p = TreeParams::default();
    let l = &mut p.leaf;
    l.leaf_outline = LeafOutline::Spline;
    (l.leaf_angle1, l.leaf_l1, l.leaf_angle2, l.leaf_l2) = (a1, 0.7, a2, 0.9);
    l.leaf_margin = LeafMargin::Entire;
    l.leaf_teeth = 0;
    l.leaf_primary_veins = LeafPrimaries::None;
    l.leaf_venation = LeafVenation::Open;
    l.leaf_vein_density = 0.0;
    l.leaf_cross_curvature = cup;
    l.leaf_midrib_curvature = -0.1;
    l.leaf_vein_displacement = 0.0;
    l.leaf_petiole_flat = false;
    l.leaf_texture_level = 4;
    l.leaf_impostor_grid = 2;
    l.leaf_rings = 1;
    l.leaf_detail = 0.25;
    leaf::generate(&p.leaf, 0.0).map(|g| g.mesh).unwrap_or_default()
}

/// Five petals `length` long around `+y`, each tilted `tilt` degrees up from the flower's
/// plane, their bases `inner` from the axis.
fn flower(length: f32, width: f32, tilt: f32, inner: f32, petal: &TreeMesh) -> TreeMesh {
    let mut m = TreeMesh::default();
    let (st, ct) = (math::sin(math::rad(tilt)), math::cos(math::rad(tilt)));
    for k in 0..5 {
        let a = math::rad(72.0 * k as f32 + 18.0);
        let radial = Vec3::new(math::cos(a), 0.0, math::sin(a));
        let tangent = Vec3::new(-math::sin(a), 0.0, math::cos(a));
        let up = radial * ct + Vec3::Y * st;
        let front = -radial * st + Vec3::Y * ct;
        append(&mut m, petal, [tangent, up, front], Vec3::new(length * width, length, length), radial * inner);
    }
    close(m)
}

/// The mesh of one set of `part`.
fn build(part: Part, kind: OrganKind) -> TreeMesh {
    let stalk = |r: f32| lathe(&[(0.0, 0.0), (0.0, r), (1.0, r), (1.0, 0.0)], 4);
    match (part, kind) {
        (_, OrganKind::Stalk) => stalk(if matches!(part, Part::Fruit(Fruit::Apples)) { 0.0014 } else { 0.0007 }),
        (Part::CherryBlossom, OrganKind::Petals) => flower(0.013, 1.7, 25.0, 0.002, &blade(35.0, 80.0, 0.25)),
        (_, OrganKind::Petals) => flower(0.018, 1.8, 30.0, 0.002, &blade(40.0, 85.0, 0.3)),
        (_, OrganKind::FlowerCentre) => {
            lathe(&[(0.0, 0.0), (0.0, 0.004), (0.004, 0.0035), (0.007, 0.002), (0.008, 0.0)], SIDES)
        }
        (Part::BirchCatkin | Part::AspenCatkin, _) => lathe(&profile(0.06, 0.0045, 13, 0.15, |t| arch(t).sqrt()), 6),
        (Part::WillowCatkin, _) => lathe(&profile(0.04, 0.003, 11, 0.15, |t| arch(t).sqrt()), 6),
        (Part::Bud, _) => {
            lathe(&profile(0.009, 0.0022, 5, 0.0, |t| math::pow(t, 0.3) * math::pow(1.0 - t, 0.7) * 1.6), SIDES)
        }
        (Part::Fruit(f), kind) => fruit(f, kind),
        _ => TreeMesh::default(),
    }
}

/// The meshes of the fruit (`kind` [`OrganKind::Fruit`] or its second part).
fn fruit(f: Fruit, kind: OrganKind) -> TreeMesh {
    let ball = |r: f32, squash: f32, dimple: f32| {
        lathe(&profile(2.0 * r * squash, r, 9, 0.0, arch), SIDES + 2).with_offset(Vec3::new(0.0, -dimple, 0.0))
    };
    match (f, kind) {
        (Fruit::Cherries, _) => ball(0.011, 0.95, 0.0015),
        (Fruit::Apples, _) => ball(0.034, 0.88, 0.006),
        (Fruit::Acorns, OrganKind::Fruit) => {
            // Widest at the cup's rim, rounded into the cup, tapering to a blunt point.
            let nut = |t: f32| if t < 0.3 { (t / 0.3).sqrt() } else { math::pow((1.0 - t) / 0.7, 0.6) };
            lathe(&profile(0.026, 0.0085, 9, 0.0, nut), SIDES).with_offset(Vec3::new(0.0, 0.002, 0.0))
        }
        (Fruit::Acorns, _) => lathe(
            &[(0.0, 0.0), (0.002, 0.006), (0.006, 0.0092), (0.0105, 0.0098), (0.0110, 0.0075), (0.0095, 0.0)],
            SIDES,
        ),
        (Fruit::Samaras, OrganKind::Fruit) => {
            let seed = lathe(&profile(0.009, 0.0035, 5, 0.0, arch), SIDES);
            let mut m = TreeMesh::default();
            for s in [-1.0f32, 1.0] {
                let dir = Vec3::new(0.5 * s, 0.87, 0.0);
                let x = Vec3::new(0.87, -0.5 * s, 0.0);
                append(&mut m, &seed, [x, dir, x.cross(dir)], Vec3::ONE, Vec3::ZERO);
            }
            close(m)
        }
        (Fruit::Samaras, _) => {
            let wing = blade(25.0, 40.0, 0.05);
            let mut m = TreeMesh::default();
            for s in [-1.0f32, 1.0] {
                // The wings spread 35° each side of the hanging axis, starting past the seeds.
                let dir = Vec3::new(0.57 * s, 0.82, 0.0);
                let x = Vec3::new(0.82, -0.57 * s, 0.0);
                append(&mut m, &wing, [x, dir, x.cross(dir)], Vec3::new(0.012, 0.035, 0.035), dir * 0.006);
            }
            close(m)
        }
        (Fruit::HangingCones, _) => {
            lathe(&profile(0.065, 0.021, 11, 0.14, |t| math::pow(arch(0.2 + 0.8 * t), 0.7)), SIDES)
        }
        (Fruit::UprightCones, _) => lathe(
            &profile(0.13, 0.03, 11, 0.1, |t| math::pow(arch(0.5 * t + 0.1), 0.5) * (1.0 - 0.4 * t * t * t)),
            SIDES,
        ),
        (Fruit::None, _) => TreeMesh::default(),
    }
}

trait Offset {
    fn with_offset(self, d: Vec3) -> Self;
}

impl Offset for TreeMesh {
    /// The mesh moved by `d`.
    fn with_offset(mut self, d: Vec3) -> TreeMesh {
        for p in self.positions.chunks_exact_mut(3) {
            p[0] += d.x;
            p[1] += d.y;
            p[2] += d.z;
        }
        self
    }
}

type Cache = Mutex<Vec<((Part, OrganKind), Arc<TreeMesh>)>>;
static CACHE: Cache = Mutex::new(Vec::new());

/// The mesh of the `kind` set of `part`, built once per process.
pub fn mesh(part: Part, kind: OrganKind) -> Arc<TreeMesh> {
    let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, m)) = cache.iter().find(|(k, _)| *k == (part, kind)) {
        return Arc::clone(m);
    }
    let m = Arc::new(build(part, kind));
    cache.push(((part, kind), Arc::clone(&m)));
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::LeafPhenology;

    fn every_mesh() -> Vec<(Part, OrganKind, Arc<TreeMesh>)> {
        let mut parts = vec![
            Part::CherryBlossom,
            Part::AppleBlossom,
            Part::BirchCatkin,
            Part::AspenCatkin,
            Part::WillowCatkin,
            Part::Bud,
        ];
        parts.extend(Fruit::ALL.iter().skip(1).map(|&f| Part::Fruit(f)));
        let _ = LeafPhenology::ALL;
        parts.into_iter().flat_map(|p| p.kinds().iter().map(move |&k| (p, k, mesh(p, k)))).collect()
    }

    #[test]
    fn every_part_is_a_finite_mesh_with_unit_normals() {
        for (part, kind, m) in every_mesh() {
            assert!(m.triangle_count() > 0, "{part:?} {kind:?}");
            assert!(m.positions.iter().all(|v| v.is_finite()));
            for n in m.normals.chunks_exact(3) {
                assert!((Vec3::from_slice(n).length() - 1.0).abs() < 1e-3, "{part:?} {kind:?}: {n:?}");
            }
            assert!(m.indices.iter().all(|&i| (i as usize) < m.vertex_count()));
            assert_eq!(m.groups[0].count as usize, m.indices.len());
        }
    }

    #[test]
    fn a_lathe_winds_outward() {
        // Every triangle's normal points away from the axis or the poles' ends.
        let m = lathe(&profile(1.0, 0.3, 6, 0.0, arch), 8);
        let p = |i: u32| Vec3::from_slice(&m.positions[3 * i as usize..3 * i as usize + 3]);
        for t in m.indices.chunks_exact(3) {
            let (a, b, c) = (p(t[0]), p(t[1]), p(t[2]));
            let n = (b - a).cross(c - a);
            let centre = (a + b + c) / 3.0 - Vec3::new(0.0, 0.5, 0.0);
            assert!(n.dot(centre) > 0.0, "inward triangle {t:?}");
        }
    }

    #[test]
    fn parts_are_light_enough_to_draw_by_the_thousand() {
        for (part, kind, m) in every_mesh() {
            println!("{part:?} {kind:?}: {} triangles", m.triangle_count());
            assert!(m.triangle_count() <= 200, "{part:?} {kind:?}: {} triangles", m.triangle_count());
        }
    }

    #[test]
    fn a_flower_has_five_petals_from_the_leaf_pipeline() {
        let petal = blade(35.0, 80.0, 0.25);
        let f = mesh(Part::CherryBlossom, OrganKind::Petals);
        assert_eq!(f.vertex_count(), 5 * petal.vertex_count());
        // Its petals spread about 1.3 cm from the axis.
        let reach = f.positions.chunks_exact(3).map(|p| (p[0] * p[0] + p[2] * p[2]).sqrt()).fold(0.0, f32::max);
        assert!((0.011..0.017).contains(&reach), "reach {reach}");
    }
}
