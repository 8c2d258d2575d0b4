//! Per-vertex bark occlusion ([`TreeMesh::shade`]): how much sky and light reach each bark
//! vertex, 0 (none) to 255 (open sky). Two terms multiply:
//!
//! * **Crown depth**: the sky the vertex still sees through the foliage, from the same leaf-area
//!   field that shades the leaves ([`crate::crown_shade`]), so the inner trunk and branches inside
//!   the crown are darker than the outer twigs.
//! * **Tree holes** (the tree-generator thesis posted on 3dideas.wordpress.com (2008), §4.3 "Hole
//!   Generation"): inside a cavity the light falls off with the depth below the opening, so a hole
//!   reads as a dark opening; the depth is measured from the stem's own curved surface (a cylinder
//!   of the local radius through the hole's rim), so the bark around the opening stays lit.
//!
//! Viewers multiply the bark colour by it (the viewer as an attribute, the GLB through `COLOR_0`).
//! Natively a large bark is shared between the cores; in wasm four vertices read the light field
//! at once, in `simd128` lanes (`lanes.rs`), with the same bytes.

use super::holes::Hole;
use super::TreeMesh;
use crate::crown_shade::CrownLight;
use glam::Vec3;

#[cfg(target_arch = "wasm32")]
mod lanes;

/// Light left at the bottom of a cavity.
pub const CAVITY_FLOOR: f32 = 0.06;

/// How much light the inside of `hole` lets reach `p` (1 outside the cavity). `stem_radius` is
/// the local radius of the stem it is cut into.
#[inline]
pub fn cavity_light(hole: &Hole, stem_radius: f32, p: Vec3) -> f32 {
    let rel = p - hole.centre;
    let below = -rel.dot(hole.normal);
    // Above the opening's plane (half the bark): no need for the lateral distance.
    if below <= 0.0 {
        return 1.0;
    }
    let lateral = (rel + hole.normal * below).length();
    if lateral > 1.6 * hole.radius {
        return 1.0;
    }
    // The stem's surface curves away from the opening's plane: depth below it, not the plane.
    let x = lateral.min(stem_radius);
    let surface = stem_radius - (stem_radius * stem_radius - x * x).sqrt();
    let d = below - surface;
    if d <= 0.0 {
        return 1.0;
    }
    let t = (d / (0.4 * hole.depth.max(1e-6))).min(1.0);
    1.0 - (1.0 - CAVITY_FLOOR) * t * t * (3.0 - 2.0 * t)
}

/// The occlusion of every vertex of `mesh` (see the module docs); `leaf_matrices` are the
/// foliage's instance matrices, `hole_size` the parameter the holes were cut with.
pub fn occlusion(mesh: &TreeMesh, holes: &[Hole], leaf_matrices: &[f32], hole_size: f32) -> Vec<u8> {
    occlusion_with(mesh, holes, CrownLight::from_leaves(leaf_matrices).as_ref(), hole_size)
}

/// [`occlusion`] with the leaves' light field already built (`None`: no leaves). Natively a
/// large bark is shared between the machine's cores ([`crate::par`]): every vertex's value
/// depends on that vertex alone, so the bytes are the same on any number of threads.
pub fn occlusion_with(mesh: &TreeMesh, holes: &[Hole], crown: Option<&CrownLight>, hole_size: f32) -> Vec<u8> {
    let n = mesh.positions.len() / 3;
    let threads = if n >= PARALLEL_VERTICES { crate::par::threads() } else { 1 };
    let mut out = vec![0u8; n];
    let mut jobs = Vec::new();
    let mut rest = out.as_mut_slice();
    for r in crate::par::ranges(n, threads * 4) {
        let (part, tail) = rest.split_at_mut(r.len());
        jobs.push((r, part));
        rest = tail;
    }
    // Each hole's stem radius divided out once, not at every vertex.
    let cavities: Vec<(&Hole, f32)> = holes.iter().map(|h| (h, h.radius / hole_size.max(1e-3))).collect();
    crate::par::run(jobs, threads, |(r, part)| {
        let positions = &mesh.positions[r.start * 3..r.end * 3];
        match crown {
            Some(c) => light_bytes(c, &cavities, positions, part),
            // No leaves: the open sky, darkened in the cavities.
            None => {
                for (p, o) in positions.chunks_exact(3).zip(part) {
                    *o = shade(&cavities, p, 1.0);
                }
            }
        }
    });
    out
}

/// A vertex's byte from its `light`, darkened further by each of `cavities` (a hole and the
/// radius of the stem it is cut into).
#[inline]
fn shade(cavities: &[(&Hole, f32)], p: &[f32], light: f32) -> u8 {
    let p = Vec3::new(p[0], p[1], p[2]);
    to_byte(cavities.iter().fold(light, |l, &(h, stem_radius)| l * cavity_light(h, stem_radius, p)))
}

/// Each vertex's byte (`positions`: `x, y, z` each) into `out`: the light field's light there,
/// darkened in `cavities`. In wasm four vertices at a time (`shade/lanes.rs`).
fn light_bytes(c: &CrownLight, cavities: &[(&Hole, f32)], positions: &[f32], out: &mut [u8]) {
    #[cfg(target_arch = "wasm32")]
    lanes::light_bytes(c, cavities, positions, out);
    #[cfg(not(target_arch = "wasm32"))]
    light_bytes_one_by_one(c, cavities, positions, out);
}

/// [`light_bytes`], one vertex at a time; most trees have no holes: the light alone, in its own
/// tight loop.
fn light_bytes_one_by_one(c: &CrownLight, cavities: &[(&Hole, f32)], positions: &[f32], out: &mut [u8]) {
    if cavities.is_empty() {
        for (p, o) in positions.chunks_exact(3).zip(out) {
            *o = to_byte(CrownLight::light(c.sky_at_inline(Vec3::new(p[0], p[1], p[2]))));
        }
    } else {
        for (p, o) in positions.chunks_exact(3).zip(out) {
            *o = shade(cavities, p, CrownLight::light(c.sky_at_inline(Vec3::new(p[0], p[1], p[2]))));
        }
    }
}

/// Barks of at least this many vertices are shaded on every core (natively).
const PARALLEL_VERTICES: usize = 1 << 16;

/// A light of 0..1 as the occlusion byte.
#[inline(always)]
fn to_byte(light: f32) -> u8 {
    // 0.5 to 255.5 (or NaN): through `i32` the same byte as `as u8`, without its saturation.
    (light.clamp(0.0, 1.0) * 255.0 + 0.5) as i32 as u8
}

#[cfg(test)]
mod tests {
    use super::to_byte;

    #[test]
    fn byte_through_i32_is_the_saturating_cast() {
        let mut lights = vec![f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -0.0, 0.0, 1.0, 2.0, -1.0];
        lights.extend((0..=100_000).map(|i| i as f32 / 100_000.0));
        lights.extend((0..=255).flat_map(|k| {
            let edge = (k as f32 + 0.5) / 255.0;
            [edge, f32::from_bits(edge.to_bits() - 1), f32::from_bits(edge.to_bits() + 1)]
        }));
        for l in lights {
            assert_eq!(to_byte(l), (l.clamp(0.0, 1.0) * 255.0 + 0.5) as u8, "{l}");
        }
    }
}
