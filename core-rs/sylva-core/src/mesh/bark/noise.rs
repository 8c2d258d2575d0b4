//! Tileable noise for the bark textures: lattice hashes, value noise and cellular (Worley)
//! distances, all periodic over the unit tile so the baked maps repeat without a seam. Integer
//! hashes and `+ * floor sqrt` only: the same bits natively and in wasm.

/// Integer hash of a lattice point (periodic with periods `px`, `py`) to [0, 1).
pub fn lattice(x: i32, y: i32, px: i32, py: i32, seed: u32) -> f32 {
    hash(x.rem_euclid(px) as u32, y.rem_euclid(py) as u32, seed)
}

/// [`lattice`] of a point already within its periods.
#[inline]
fn hash(x: u32, y: u32, seed: u32) -> f32 {
    let mut h = x.wrapping_mul(0x8da6_b343) ^ y.wrapping_mul(0xd816_3841) ^ seed.wrapping_mul(0xcb1a_b31f);
    h ^= h >> 13;
    h = h.wrapping_mul(0x5bd1_e995);
    h ^= h >> 15;
    (h >> 8) as f32 / 16_777_216.0
}

/// Smooth value noise in [0, 1) at tile coordinates (u, v) with `px` × `py` lattice cells per tile.
pub fn value(u: f32, v: f32, px: i32, py: i32, seed: u32) -> f32 {
    let (x, y) = (u * px as f32, v * py as f32);
    let (xi, yi) = (x.floor() as i32, y.floor() as i32);
    let (fx, fy) = (x - xi as f32, y - yi as f32);
    let s = |t: f32| t * t * (3.0 - 2.0 * t);
    let (sx, sy) = (s(fx), s(fy));
    // The cell's corners within the periods: one remainder per axis (a division), the next
    // corner by a step.
    let (x0, y0) = (xi.rem_euclid(px), yi.rem_euclid(py));
    let step = |c: i32, p: i32| if c + 1 == p { 0 } else { c + 1 };
    let (x1, y1) = (step(x0, px), step(y0, py));
    let l = |x: i32, y: i32| hash(x as u32, y as u32, seed);
    let a = l(x0, y0) + (l(x1, y0) - l(x0, y0)) * sx;
    let b = l(x0, y1) + (l(x1, y1) - l(x0, y1)) * sx;
    a + (b - a) * sy
}

/// Three octaves of [`value`] noise (periods `p`, `2p`, `4p`), in [0, 1).
pub fn fbm(u: f32, v: f32, px: i32, py: i32, seed: u32) -> f32 {
    (value(u, v, px, py, seed) * 4.0
        + value(u, v, 2 * px, 2 * py, seed + 1) * 2.0
        + value(u, v, 4 * px, 4 * py, seed + 2))
        / 7.0
}

/// Cellular noise: one feature point per cell of a `px` × `py` grid over the tile. Returns the
/// distances to the nearest and second-nearest points (in cell widths along u; v distances are
/// scaled by `px / py` so elongated cells stay elongated) and the nearest cell's id hash in [0, 1).
/// Each column of cells is shifted along v by its own fraction of a cell (periodic over the
/// tile): on an aligned grid the borders between two rows of cells run across the whole tile,
/// which the tiling around a stem turns into rings.
pub fn cells(u: f32, v: f32, px: i32, py: i32, seed: u32) -> (f32, f32, f32) {
    let (x, y) = (u * px as f32, v * py as f32);
    let xi = x.floor() as i32;
    let aspect = py as f32 / px as f32;
    let (mut f1, mut f2, mut id) = (f32::MAX, f32::MAX, 0.0);
    for dx in -1..=1 {
        let cx = xi + dx;
        // The cell within the periods once (a remainder is a division), for its three hashes.
        let xw = cx.rem_euclid(px) as u32;
        let shift = hash(xw, 0, seed + 53);
        let yi = (y - shift).floor() as i32;
        for dy in -1..=1 {
            let cy = yi + dy;
            let yw = cy.rem_euclid(py) as u32;
            let fx = cx as f32 + 0.1 + 0.8 * hash(xw, yw, seed);
            let fy = cy as f32 + shift + 0.1 + 0.8 * hash(xw, yw, seed + 17);
            let (ex, ey) = (fx - x, (fy - y) / aspect);
            let d = (ex * ex + ey * ey).sqrt();
            if d < f1 {
                f2 = f1;
                f1 = d;
                id = hash(xw, yw, seed + 31);
            } else if d < f2 {
                f2 = d;
            }
        }
    }
    (f1, f2, id)
}

/// Hermite step from 0 at `a` to 1 at `b`.
pub fn smoothstep(a: f32, b: f32, x: f32) -> f32 {
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_is_periodic_over_the_tile() {
        for k in 0..50 {
            let v = k as f32 / 50.0;
            assert!((value(0.0, v, 5, 3, 9) - value(1.0, v, 5, 3, 9)).abs() < 1e-5);
            assert!((fbm(v, 0.0, 4, 4, 2) - fbm(v, 1.0, 4, 4, 2)).abs() < 1e-5);
            let (a, b) = (cells(0.0, v, 6, 4, 1), cells(1.0, v, 6, 4, 1));
            assert!((a.0 - b.0).abs() < 1e-4 && (a.1 - b.1).abs() < 1e-4, "{a:?} {b:?}");
        }
    }
}
