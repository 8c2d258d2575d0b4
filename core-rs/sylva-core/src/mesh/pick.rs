//! Boxes for picking the bark with a ray: the bark's triangles in index order, in runs of
//! [`PICK_RUN`] (the bark is written stem by stem, so a run is a compact piece of bark), each
//! with its axis-aligned box. The studio's viewer tests a ray against the boxes and then only
//! the triangles of the boxes it passes through (the brush, cut and bend tools pick on every
//! pointer move); the worker sends the boxes with every new bark.
//!
//! Layout: 6 floats per run, `min x, min y, min z, max x, max y, max z` (tree space, m); run `k`
//! holds triangles `k * PICK_RUN` to `min((k + 1) * PICK_RUN, triangles) - 1`. Plain
//! comparisons (NaN never wins, a tie keeps the value held), the same boxes as the package's
//! `pickBoxes` in TypeScript, which the worker used before (tested against it); in wasm a
//! vertex's three coordinates in the lanes of one `simd128` vector.

/// Triangles per box.
pub const PICK_RUN: usize = 64;

/// The boxes of the runs of `indices` (a triangle list) over `positions` (3 floats per vertex);
/// an index past the positions reads 0 there (see the module docs for the layout).
pub fn pick_boxes(positions: &[f32], indices: &[u32]) -> Vec<f32> {
    #[cfg(target_arch = "wasm32")]
    return lanes::pick_boxes(positions, indices);
    #[cfg(not(target_arch = "wasm32"))]
    pick_boxes_one_by_one(positions, indices)
}

/// [`pick_boxes`] one coordinate at a time (natively; in wasm the lanes, compared with the
/// TypeScript function on real trees by the package's `viewer/pick.test.ts`).
#[cfg(not(target_arch = "wasm32"))]
fn pick_boxes_one_by_one(positions: &[f32], indices: &[u32]) -> Vec<f32> {
    let triangles = indices.len() / 3;
    let mut out = Vec::with_capacity(triangles.div_ceil(PICK_RUN) * 6);
    let at = |k: usize| positions.get(k).copied().unwrap_or(0.0);
    for run in indices[..triangles * 3].chunks(PICK_RUN * 3) {
        let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for &i in run {
            let v = i as usize * 3;
            for a in 0..3 {
                let x = at(v + a);
                if x < lo[a] {
                    lo[a] = x;
                }
                if x > hi[a] {
                    hi[a] = x;
                }
            }
        }
        out.extend_from_slice(&lo);
        out.extend_from_slice(&hi);
    }
    out
}

#[cfg(target_arch = "wasm32")]
mod lanes {
    use core::arch::wasm32::*;

    /// [`super::pick_boxes`] with each vertex's `x, y, z` in the first three lanes of a vector
    /// (the fourth, the next float, is never read out): `f32x4_pmin(lo, p)` is `p < lo ? p : lo`
    /// and `f32x4_pmax(hi, p)` is `hi < p ? p : hi`, the plain comparisons lane by lane. The
    /// last vertex (no fourth float after it) and an index past the positions go one by one.
    #[target_feature(enable = "simd128")]
    pub(super) fn pick_boxes(positions: &[f32], indices: &[u32]) -> Vec<f32> {
        let triangles = indices.len() / 3;
        let mut out = Vec::with_capacity(triangles.div_ceil(super::PICK_RUN) * 6);
        let at = |k: usize| positions.get(k).copied().unwrap_or(0.0);
        for run in indices[..triangles * 3].chunks(super::PICK_RUN * 3) {
            let (mut lo, mut hi) = (f32x4_splat(f32::INFINITY), f32x4_splat(f32::NEG_INFINITY));
            for &i in run {
                let v = i as usize * 3;
                let p = match positions.get(v..v + 4) {
                    Some(p) => f32x4(p[0], p[1], p[2], p[3]),
                    None => f32x4(at(v), at(v + 1), at(v + 2), 0.0),
                };
                lo = f32x4_pmin(lo, p);
                hi = f32x4_pmax(hi, p);
            }
            out.extend_from_slice(&[
                f32x4_extract_lane::<0>(lo),
                f32x4_extract_lane::<1>(lo),
                f32x4_extract_lane::<2>(lo),
                f32x4_extract_lane::<0>(hi),
                f32x4_extract_lane::<1>(hi),
                f32x4_extract_lane::<2>(hi),
            ]);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_run_gets_the_tight_box_of_its_triangles() {
        // 130 triangles over 50 points: runs of 64, 64 and 2.
        let positions: Vec<f32> = (0..150).map(|k| ((k * 37 % 101) as f32 - 50.0) * 0.1).collect();
        let indices: Vec<u32> = (0..390).map(|k| (k * 7 % 50) as u32).collect();
        let boxes = pick_boxes(&positions, &indices);
        assert_eq!(boxes.len(), 3 * 6);
        for (r, b) in boxes.chunks_exact(6).enumerate() {
            let run = &indices[r * 192..((r + 1) * 192).min(390)];
            for a in 0..3 {
                let xs = run.iter().map(|&i| positions[i as usize * 3 + a]);
                assert_eq!(b[a], xs.clone().fold(f32::INFINITY, f32::min), "run {r} axis {a}");
                assert_eq!(b[3 + a], xs.fold(f32::NEG_INFINITY, f32::max), "run {r} axis {a}");
            }
        }
        // A trailing partial triangle is no triangle; no triangles, no boxes.
        assert_eq!(pick_boxes(&positions, &indices[..391.min(indices.len())]).len(), 18);
        assert!(pick_boxes(&positions, &[0, 1]).is_empty());
        // An index past the positions reads 0; NaN never wins.
        assert_eq!(pick_boxes(&[1.0, f32::NAN, 2.0], &[0, 0, 9]), [0.0, 0.0, 0.0, 1.0, 0.0, 2.0]);
    }
}
