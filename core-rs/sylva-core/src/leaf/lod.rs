//! Levels of detail (Leaf Generation guide §6; Décoret et al. 2003, *Billboard Clouds for Extreme
//! Model Simplification*; hemi-octahedral impostors):
//!
//! * **LOD0**: the full deformed blade ([`super::Leaf::mesh`]).
//! * **Card**: one quad over the UV box in the leaf plane (`z = 0`), UVs 0..1, showing the baked
//!   texture (its alpha cuts the outline).
//! * **Billboard cloud**: four quads, one per quadrant of the box (left / right of the midrib,
//!   lower / upper half), each on the least-squares plane `z = α + βx + γy` of the LOD0 vertices
//!   in it, so the cloud follows the midrib bend and the cupping; neighbouring quads meet and
//!   cross along the midrib and the middle.
//! * **Impostor views**: the centres of an `N × N` hemi-octahedral grid, unit directions over
//!   the front hemisphere (`z ≥ 0`) from which to bake the leaf.

use crate::leaf::uv::UvFrame;
use crate::mesh::{Material, MeshBuilder, TreeMesh};
use glam::{Vec2, Vec3};

/// The reduced representations of one leaf.
#[derive(Clone, Debug, PartialEq)]
pub struct LeafLod {
    /// One textured quad.
    pub card: TreeMesh,
    /// Four textured quads fitted to the surface.
    pub billboards: TreeMesh,
    /// Unit view directions over the front hemisphere, row by row of the grid.
    pub impostor_views: Vec<[f32; 3]>,
}

fn quad(b: &mut MeshBuilder, frame: &UvFrame, corners: [Vec2; 4], plane: [f32; 3]) {
    let [a, bx, cy] = plane;
    let n = Vec3::new(-bx, -cy, 1.0).normalize();
    let first = b.next_index();
    for c in corners {
        let uv = frame.uv(c);
        b.vertex([c.x, c.y, a + bx * c.x + cy * c.y], n.to_array(), uv.to_array());
    }
    b.triangle(first, first + 1, first + 2);
    b.triangle(first, first + 2, first + 3);
}

/// Least-squares plane `z = α + βx + γy` through `points` (`[0, 0, 0]` when underdetermined).
pub fn fit_plane(points: &[Vec3]) -> [f32; 3] {
    if points.len() < 3 {
        return [0.0; 3];
    }
    let (mut s, mut sx, mut sy, mut sxx, mut sxy, mut syy, mut sz, mut sxz, mut syz) =
        (0.0f64, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for p in points {
        let (x, y, z) = (f64::from(p.x), f64::from(p.y), f64::from(p.z));
        s += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
        sz += z;
        sxz += x * z;
        syz += y * z;
    }
    let det3 = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let m = [[s, sx, sy], [sx, sxx, sxy], [sy, sxy, syy]];
    let d = det3(m);
    if d.abs() < 1e-12 * s * s * s {
        return [(sz / s) as f32, 0.0, 0.0];
    }
    let r = [sz, sxz, syz];
    let solve = |col: usize| {
        let mut mm = m;
        for (row, v) in mm.iter_mut().zip(r) {
            row[col] = v;
        }
        (det3(mm) / d) as f32
    };
    [solve(0), solve(1), solve(2)]
}

/// Unit direction of hemi-octahedral grid cell `(i, j)` of `n × n` (`z ≥ 0`).
pub fn hemi_oct(i: usize, j: usize, n: usize) -> [f32; 3] {
    let ex = (i as f32 + 0.5) / n as f32 * 2.0 - 1.0;
    let ey = (j as f32 + 0.5) / n as f32 * 2.0 - 1.0;
    let (x, y) = (0.5 * (ex + ey), 0.5 * (ex - ey));
    Vec3::new(x, y, 1.0 - x.abs() - y.abs()).normalize().to_array()
}

/// Builds the card, the billboard cloud (from the LOD0 positions) and the impostor views.
pub fn build(frame: &UvFrame, lod0: &[Vec3], impostor_grid: u32) -> LeafLod {
    let (lo, hi) = (frame.lo, frame.lo + frame.size);
    let mut card = MeshBuilder::with_capacity(4, 6);
    card.begin_group(Material::Leaves);
    quad(&mut card, frame, [lo, Vec2::new(hi.x, lo.y), hi, Vec2::new(lo.x, hi.y)], [0.0; 3]);
    let mut cloud = MeshBuilder::with_capacity(16, 24);
    cloud.begin_group(Material::Leaves);
    let (xm, ym) = (0.0f32.clamp(lo.x, hi.x), 0.5 * (lo.y + hi.y));
    for (x0, x1) in [(lo.x, xm), (xm, hi.x)] {
        for (y0, y1) in [(lo.y, ym), (ym, hi.y)] {
            if x1 - x0 <= 0.0 || y1 - y0 <= 0.0 {
                continue;
            }
            let pts: Vec<Vec3> =
                lod0.iter().copied().filter(|p| p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1).collect();
            let plane = fit_plane(&pts);
            quad(
                &mut cloud,
                frame,
                [Vec2::new(x0, y0), Vec2::new(x1, y0), Vec2::new(x1, y1), Vec2::new(x0, y1)],
                plane,
            );
        }
    }
    let n = impostor_grid.max(1) as usize;
    let impostor_views = (0..n).flat_map(|j| (0..n).map(move |i| hemi_oct(i, j, n))).collect();
    LeafLod { card: card.finish(), billboards: cloud.finish(), impostor_views }
}
