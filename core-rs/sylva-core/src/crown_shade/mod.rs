//! Crown-depth shading: how much sky a point inside the crown still sees, an ambient-occlusion term
//! computed from the leaves the skeleton carries. The WebGL pages of *Modeling the Mighty Maple for
//! Web* (ibiblio.org/e-notes) (the "sunny" tree) shade leaves from a height map of the crown above
//! them; here the leaves are binned into a coarse voxel grid of leaf area, and for every cell the
//! transmittance `exp(-k · leaf area per unit cross-section)` is averaged over [`SKY_DIRECTIONS`]
//! rays to the upper hemisphere (swept layer by layer from the top, one pass per direction)
//! (Beer–Lambert through the foliage, `k` = 0.5 for randomly oriented leaves). A leaf's brightness
//! is `MIN_LIGHT + (1 - MIN_LIGHT) · sky`, read trilinearly at its base, so inner and lower leaves
//! are darker than the outer shell; the bark uses the same field ([`crate::mesh::shade`]).
//! Deterministic: plain arithmetic and the portable `math::exp`, in a fixed order. In wasm the
//! bark's vertices and the leaves read the field four at a time in `simd128` lanes
//! (`lanes.rs`), each lane the same operations as one lookup.

use glam::Vec3;

#[cfg(target_arch = "wasm32")]
mod lanes;

/// Brightness of a leaf (or bark) that sees no sky at all.
pub const MIN_LIGHT: f32 = 0.3;
/// Extinction per unit leaf area index (randomly oriented leaves: 0.5).
const EXTINCTION: f32 = 0.5;
/// Largest number of cells along an axis.
const MAX_CELLS: usize = 20;
/// Rays per cell: the zenith, then rings at 60° and 30° elevation (unit vectors, up is +y).
pub const SKY_DIRECTIONS: usize = 13;

fn sky_directions() -> [Vec3; SKY_DIRECTIONS] {
    let mut d = [Vec3::Y; SKY_DIRECTIONS];
    // cos/sin of 60° and 30° elevation, six azimuths 60° apart (offset between the rings).
    let rings = [(0.5f32, 0.866_025_4f32, 0.0f32), (0.866_025_4, 0.5, 0.5)];
    let az: [(f32, f32); 12] = [
        (1.0, 0.0),
        (0.5, 0.866_025_4),
        (-0.5, 0.866_025_4),
        (-1.0, 0.0),
        (-0.5, -0.866_025_4),
        (0.5, -0.866_025_4),
        (0.866_025_4, 0.5),
        (0.0, 1.0),
        (-0.866_025_4, 0.5),
        (-0.866_025_4, -0.5),
        (0.0, -1.0),
        (0.866_025_4, -0.5),
    ];
    for (r, &(horizontal, up, off)) in rings.iter().enumerate() {
        for k in 0..6 {
            let (c, s) = az[k + if off > 0.0 { 6 } else { 0 }];
            d[1 + r * 6 + k] = Vec3::new(c * horizontal, up, s * horizontal);
        }
    }
    d
}

/// The crown's light field: sky visibility (0..1) at the centre of every cell.
#[derive(Clone, Debug)]
pub struct CrownLight {
    min: Vec3,
    cell: f32,
    n: [usize; 3],
    /// For every cell (x fastest, then y, then z), the sky at the eight cell centres a point
    /// past its own centre is interpolated between: its own, then the next along x, y, and z
    /// (the last cell's own again at the grid's far side), x fastest; one read per lookup.
    corners: Vec<[f32; 8]>,
}

impl CrownLight {
    /// The field of leaves given as 4×4 instance matrices (column-major, 16 floats each, leaf
    /// `x` = width, `y` = length); `None` without leaves.
    pub fn from_leaves(matrices: &[f32]) -> Option<CrownLight> {
        let leaves: Vec<(Vec3, f32)> = matrices
            .chunks_exact(16)
            .map(|m| {
                let (x, y) = (Vec3::new(m[0], m[1], m[2]), Vec3::new(m[4], m[5], m[6]));
                (Vec3::new(m[12], m[13], m[14]) + 0.5 * y, 0.5 * x.cross(y).length())
            })
            .collect();
        CrownLight::from_area(&leaves)
    }

    /// The field of leaf area given as `(centre, area m²)` pairs; `None` without any.
    pub fn from_area(leaves: &[(Vec3, f32)]) -> Option<CrownLight> {
        let first = leaves.first()?.0;
        let (lo, hi) = leaves.iter().fold((first, first), |(lo, hi), &(p, _)| (lo.min(p), hi.max(p)));
        let extent = (hi - lo).max_element().max(1e-3);
        let cell = extent / (MAX_CELLS - 2) as f32;
        // One empty cell of margin on every side, so rays leave through empty cells.
        let min = lo - Vec3::splat(cell);
        let n = [0, 1, 2].map(|a| (((hi[a] - lo[a]) / cell) as usize + 3).min(MAX_CELLS + 1));
        let mut depth = vec![0.0f32; n[0] * n[1] * n[2]];
        let index = |p: Vec3| -> usize {
            let c = [0, 1, 2].map(|a| (((p[a] - min[a]) / cell) as usize).min(n[a] - 1));
            (c[2] * n[1] + c[1]) * n[0] + c[0]
        };
        // Optical depth of one cell crossed along a ray of one cell length: k · area / cell².
        let per_area = EXTINCTION / (cell * cell);
        for &(p, area) in leaves {
            depth[index(p)] += area * per_area;
        }
        let mut sky = vec![0.0f32; depth.len()];
        for d in sky_directions() {
            accumulate_sky(&depth, n, d, &mut sky);
        }
        sky.iter_mut().for_each(|s| *s /= SKY_DIRECTIONS as f32);
        let [nx, ny, nz] = n;
        let mut corners = Vec::with_capacity(sky.len());
        for z in 0..nz {
            for y in 0..ny {
                for x in 0..nx {
                    let (x1, y1, z1) = ((x + 1).min(nx - 1), (y + 1).min(ny - 1), (z + 1).min(nz - 1));
                    let at = |x: usize, y: usize, z: usize| sky[(z * ny + y) * nx + x];
                    corners.push([
                        at(x, y, z),
                        at(x1, y, z),
                        at(x, y1, z),
                        at(x1, y1, z),
                        at(x, y, z1),
                        at(x1, y, z1),
                        at(x, y1, z1),
                        at(x1, y1, z1),
                    ]);
                }
            }
        }
        Some(CrownLight { min, cell, n, corners })
    }

    /// Sky visibility at `p` (trilinear between cell centres; 1 outside the grid above, the
    /// nearest cell's value beside and below it). The bark's occlusion reads it at every vertex:
    /// the eight values come from one record of `corners`, and the clamped coordinates (0 to 20)
    /// are truncated through `i32` (what `as usize` gives for them, without its saturation
    /// checks); the arithmetic is the same operations in the same order.
    #[inline]
    pub fn sky_at(&self, p: Vec3) -> f32 {
        self.sky_at_inline(p)
    }

    /// [`CrownLight::sky_at`], inlined into its caller (the bark's occlusion reads it at every
    /// vertex in one loop, where the field's constants then stay in registers).
    #[inline(always)]
    pub fn sky_at_inline(&self, p: Vec3) -> f32 {
        let f = (p - self.min) / self.cell - Vec3::splat(0.5);
        let [nx, ny, nz] = self.n;
        if f.y > (ny - 1) as f32 {
            return 1.0;
        }
        // The lower cell centre and the fraction past it, along one axis of `n` cells.
        let axis = |v: f32, n: usize| {
            let v = v.clamp(0.0, (n - 1) as f32);
            let i = v as i32 as usize;
            (i, v - i as f32)
        };
        let ((x0, tx), (y0, ty), (z0, tz)) = (axis(f.x, nx), axis(f.y, ny), axis(f.z, nz));
        let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
        let c = &self.corners[(z0 * ny + y0) * nx + x0];
        let (x00, x10) = (lerp(c[0], c[1], tx), lerp(c[2], c[3], tx));
        let (x01, x11) = (lerp(c[4], c[5], tx), lerp(c[6], c[7], tx));
        lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz)
    }

    /// Brightness for sky visibility `sky`: [`MIN_LIGHT`] in full shade, 1 in the open.
    pub fn light(sky: f32) -> f32 {
        MIN_LIGHT + (1.0 - MIN_LIGHT) * sky
    }
}

/// Adds `exp(-optical depth)` toward the sky along `d` (unit, `d.y > 0`) to every cell of
/// `sky`. Layer by layer from the top: a ray leaving a cell climbs one layer per step of
/// `d / d.y`, so the depth above a cell is its own half plus the depth above the point it
/// reaches in the next layer up (bilinear between that layer's cells; empty outside the grid).
/// The layers are kept with a margin of empty cells wide enough for any step, so the cells a
/// ray reaches outside the grid read 0 without a test.
fn accumulate_sky(depth: &[f32], n: [usize; 3], d: Vec3, sky: &mut [f32]) {
    let step = d / d.y;
    let len = step.length();
    let (nx, ny, nz) = (n[0], n[1], n[2]);
    let at = |y: usize, x: usize, z: usize| (z * ny + y) * nx + x;
    // The margin: a ray reaches at most `|step| + 1` cells beyond its own column.
    let pad = step.x.abs().max(step.z.abs()).ceil() as usize + 2;
    let (wx, wz) = (nx + 2 * pad, nz + 2 * pad);
    // Optical depth from the centre of each cell of the layer above out of the grid (the
    // margins stay 0).
    let mut above = vec![0.0f32; wx * wz];
    let mut here = vec![0.0f32; wx * wz];
    // Where the ray from a cell reaches the layer above depends on its x (or z) alone, the
    // same for every layer: the lower of the two cells (in the margined layer) and the fraction
    // past it.
    let xs: Vec<(usize, f32)> = (0..nx).map(|x| reach(x as f32 + step.x, pad)).collect();
    let zs: Vec<(usize, f32)> = (0..nz).map(|z| reach(z as f32 + step.z, pad)).collect();
    for y in (0..ny).rev() {
        for (z, &(z0, tz)) in zs.iter().enumerate() {
            let (lo, hi) = (&above[z0 * wx..(z0 + 1) * wx], &above[(z0 + 1) * wx..(z0 + 2) * wx]);
            let row = (z + pad) * wx + pad;
            for (x, &(x0, tx)) in xs.iter().enumerate() {
                let up = if y + 1 < ny {
                    let a = lo[x0] + (lo[x0 + 1] - lo[x0]) * tx;
                    let b = hi[x0] + (hi[x0 + 1] - hi[x0]) * tx;
                    a + (b - a) * tz
                } else {
                    0.0
                };
                let own = depth[at(y, x, z)] * len;
                // exp(-0) is 1 exactly: most cells (the margin, the air above and around the
                // crown) see the open sky, and the software exp is the sweep's cost.
                let optical = 0.5 * own + up;
                sky[at(y, x, z)] += if optical == 0.0 { 1.0 } else { crate::math::exp(-optical) };
                here[row + x] = own + up;
            }
        }
        std::mem::swap(&mut above, &mut here);
    }
}

/// Where a ray reaches a layer along one axis, at fractional cell `f`: the lower of the two
/// cells it falls between, counted in a layer with `pad` empty cells before the grid's first,
/// and the fraction past it.
fn reach(f: f32, pad: usize) -> (usize, f32) {
    let f0 = f.floor();
    ((f0 as i64 + pad as i64) as usize, f - f0)
}

/// Multiplies each leaf's RGB tint (3 floats per leaf, matching `matrices`) by its crown light.
pub fn darken(matrices: &[f32], colors: &mut [f32]) {
    darken_with(CrownLight::from_leaves(matrices).as_ref(), matrices, colors);
}

/// [`darken`] with the field of these leaves already built (`None`: no leaves, nothing to do).
pub fn darken_with(field: Option<&CrownLight>, matrices: &[f32], colors: &mut [f32]) {
    let Some(field) = field else { return };
    // In wasm four leaves at a time (`crown_shade/lanes.rs`), the same bits.
    #[cfg(target_arch = "wasm32")]
    lanes::darken(field, matrices, colors);
    #[cfg(not(target_arch = "wasm32"))]
    darken_one_by_one(field, matrices, colors);
}

/// [`darken_with`] of the leaves of `matrices`, one at a time.
fn darken_one_by_one(field: &CrownLight, matrices: &[f32], colors: &mut [f32]) {
    for (m, c) in matrices.chunks_exact(16).zip(colors.chunks_exact_mut(3)) {
        let l = CrownLight::light(field.sky_at(Vec3::new(m[12], m[13], m[14]) + 0.5 * Vec3::new(m[4], m[5], m[6])));
        c.iter_mut().for_each(|v| *v *= l);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf_at(p: Vec3) -> [f32; 16] {
        [0.1, 0.0, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.1, 0.0, p.x, p.y, p.z, 1.0]
    }

    #[test]
    fn inner_leaves_are_darker_than_outer_ones() {
        // A ball of leaves, 1 m radius, on a lattice every 0.1 m.
        let mut m = Vec::new();
        for x in -10..=10 {
            for y in -10..=10 {
                for z in -10..=10 {
                    let p = Vec3::new(x as f32, y as f32, z as f32) * 0.1;
                    if p.length() <= 1.0 {
                        m.extend_from_slice(&leaf_at(p + Vec3::Y * 3.0));
                    }
                }
            }
        }
        let f = CrownLight::from_leaves(&m).unwrap();
        let (centre, top, bottom, side) = (
            f.sky_at(Vec3::new(0.0, 3.0, 0.0)),
            f.sky_at(Vec3::new(0.0, 3.95, 0.0)),
            f.sky_at(Vec3::new(0.0, 2.05, 0.0)),
            f.sky_at(Vec3::new(0.95, 3.0, 0.0)),
        );
        assert!(centre < 0.5 * top && centre < side && bottom < top, "{centre} {top} {bottom} {side}");
        assert!(f.sky_at(Vec3::new(0.0, 6.0, 0.0)) == 1.0 && (0.0..=1.0).contains(&centre));
        let mut c = vec![1.0; m.len() / 16 * 3];
        darken(&m, &mut c);
        assert!(c.iter().all(|&v| (MIN_LIGHT..=1.0).contains(&v)));
        assert!(c.iter().cloned().fold(1.0f32, f32::min) < 0.6, "the core of the ball is shaded");
    }

    #[test]
    fn lookup_matches_trilinear_between_cell_centres() {
        // A lopsided cloud of leaves, so the grid's axes differ and the edges are crossed.
        let mut m = Vec::new();
        let mut r = crate::rng::Rng::new(7, "crown_shade_test");
        for _ in 0..400 {
            let p = Vec3::new(2.0 * r.next_f32(), 3.0 + r.next_f32(), 0.7 * r.next_f32());
            m.extend_from_slice(&leaf_at(p));
        }
        let f = CrownLight::from_leaves(&m).unwrap();
        let [nx, ny, nz] = f.n;
        let own = |x: usize, y: usize, z: usize| f.corners[(z * ny + y) * nx + x][0];
        for _ in 0..2000 {
            let p = Vec3::new(3.0 * r.next_f32() - 0.5, 2.5 + 2.0 * r.next_f32(), 1.5 * r.next_f32() - 0.4);
            // The lookup spelled out: each axis clamped to the centres, its corners' own values.
            let g = (p - f.min) / f.cell - Vec3::splat(0.5);
            if g.y > (ny - 1) as f32 {
                assert_eq!(f.sky_at(p), 1.0);
                continue;
            }
            let axis = |v: f32, n: usize| {
                let v = v.clamp(0.0, (n - 1) as f32);
                let i = v.floor() as usize;
                (i, (i + 1).min(n - 1), v - i as f32)
            };
            let ((x0, x1, tx), (y0, y1, ty), (z0, z1, tz)) = (axis(g.x, nx), axis(g.y, ny), axis(g.z, nz));
            let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
            let at_y_z = |y, z| lerp(own(x0, y, z), own(x1, y, z), tx);
            let want = lerp(lerp(at_y_z(y0, z0), at_y_z(y1, z0), ty), lerp(at_y_z(y0, z1), at_y_z(y1, z1), ty), tz);
            assert_eq!(f.sky_at(p).to_bits(), want.to_bits(), "{p}");
        }
    }

    #[test]
    fn the_sky_sweep_matches_its_plain_formula() {
        // The sweep spelled out without its per-column reach: each cell's point in the layer
        // above found and read (0 outside) at every cell.
        fn plain(depth: &[f32], [nx, ny, nz]: [usize; 3], d: Vec3) -> Vec<f32> {
            let step = d / d.y;
            let len = step.length();
            let at = |y: usize, x: usize, z: usize| (z * ny + y) * nx + x;
            let (mut sky, mut above, mut here) = (vec![0.0; depth.len()], vec![0.0f32; nx * nz], vec![0.0f32; nx * nz]);
            for y in (0..ny).rev() {
                for z in 0..nz {
                    for x in 0..nx {
                        let (fx, fz) = (x as f32 + step.x, z as f32 + step.z);
                        let get = |x: f32, z: f32| {
                            if x < 0.0 || z < 0.0 || x >= nx as f32 || z >= nz as f32 {
                                0.0
                            } else {
                                above[z as usize * nx + x as usize]
                            }
                        };
                        let (x0, z0) = (fx.floor(), fz.floor());
                        let (tx, tz) = (fx - x0, fz - z0);
                        let a = get(x0, z0) + (get(x0 + 1.0, z0) - get(x0, z0)) * tx;
                        let b = get(x0, z0 + 1.0) + (get(x0 + 1.0, z0 + 1.0) - get(x0, z0 + 1.0)) * tx;
                        let up = if y + 1 < ny { a + (b - a) * tz } else { 0.0 };
                        let own = depth[at(y, x, z)] * len;
                        let optical = 0.5 * own + up;
                        sky[at(y, x, z)] += if optical == 0.0 { 1.0 } else { crate::math::exp(-optical) };
                        here[z * nx + x] = own + up;
                    }
                }
                std::mem::swap(&mut above, &mut here);
            }
            sky
        }
        let n = [7, 5, 6];
        let mut r = crate::rng::Rng::new(11, "sky_sweep_test");
        let depth: Vec<f32> =
            (0..7 * 5 * 6).map(|_| if r.next_f32() < 0.5 { 0.0 } else { 2.0 * r.next_f32() }).collect();
        for d in sky_directions() {
            let mut sky = vec![0.0; depth.len()];
            accumulate_sky(&depth, n, d, &mut sky);
            let want = plain(&depth, n, d);
            assert!(sky.iter().zip(&want).all(|(a, b)| a.to_bits() == b.to_bits()), "{d}");
        }
    }
}
