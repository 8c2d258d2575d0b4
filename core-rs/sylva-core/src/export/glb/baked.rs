//! The leaves baked into one mesh for the GLB ([`LeafMode::Baked`](crate::export::LeafMode)):
//! the file for content tools (Blender and other editors), which import
//! `EXT_mesh_gpu_instancing` as one object per leaf.
//!
//! Every leaf's copy of the leaf mesh ([`crate::export::bake_leaves`]: positions, normals, UVs,
//! tangents) carries two more things per vertex:
//!
//! * **Its leaf's tint** as `COLOR_0` (RGBA8): the instanced file's `_COLOR_0`, which already
//!   holds the crown's shade (inner leaves darker, [`crate::crown_shade`]), clamped to glTF's
//!   0..1 as the OBJ's vertex colours are. On the presets at most 0.7% of the leaves have a
//!   component past 1 (bright outer leaves, reaching 1.11): clamping keeps every other leaf
//!   exactly as the engines' file shows it, where scaling all of them to fit would darken the
//!   whole crown.
//! * **The wind record of its twig** (`_WIND_PIVOT`, `_WIND_PARAMS`, [`leaf_wind`]), so a
//!   shader that sways the bark with them sways each leaf with the twig it hangs on: the same
//!   pivot, level and phase, and the twig's stiffness, distance from the root and radius where
//!   the leaf meets it. All the vertices of one leaf share its record. (The instanced file
//!   has no per-leaf wind record: a shader there takes a leaf's anchor from its instance
//!   translation, which the baked file no longer has.)

use crate::export::bake::{bake_leaves_scaled, BakedLeaves};
use crate::mesh::{Bounds, WIND_STRIDE};
use crate::Generated;
use glam::Vec3;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// The baked leaves of `g` ([`bake_leaves_scaled`]: the tints divided by `scale` as colours) and, with `wind`,
/// each leaf's wind record repeated on its vertices (`mesh.wind`, when the bark carries wind
/// data; [`leaf_wind`]).
pub(super) fn bake(g: &Generated, with_tangents: bool, wind: bool, threads: usize, scale: [f32; 3]) -> BakedLeaves {
    let mut b = bake_leaves_scaled(&g.foliage, with_tangents, scale);
    let nv = g.foliage.mesh.vertex_count();
    if let Some(records) = wind.then(|| leaf_wind(g, threads)).flatten() {
        b.mesh.wind = Vec::with_capacity(records.len() * nv * WIND_STRIDE);
        for r in &records {
            (0..nv).for_each(|_| b.mesh.wind.extend_from_slice(r));
        }
    }
    b
}

/// Per leaf of `g`, a wind record (`TreeMesh::wind` layout: pivot, level, phase, stiffness,
/// distance, radius) of the stem it hangs on: the stem whose centre curve passes nearest to
/// where the leaf meets it ([`attachment`]; ties go to the lower stem index), and of that
/// stem's bark vertices (the ones whose record has the stem's base as pivot and its level) the
/// one nearest to that point (ties to the lower vertex index). A stem without bark vertices
/// hands its leaves to its parent. `None` when the bark has no wind data or there are no
/// leaves. The same records on any number of `threads`.
pub(super) fn leaf_wind(g: &Generated, threads: usize) -> Option<Vec<[f32; WIND_STRIDE]>> {
    let (bark, f, stems) = (&g.mesh, &g.foliage, &g.skeleton.stems);
    let n = bark.vertex_count();
    if n == 0 || bark.wind.len() != n * WIND_STRIDE || f.count() == 0 || stems.is_empty() {
        return None;
    }
    let petiole = f.leaf.as_deref().map_or(0.0, |l| l.petiole);
    let at: Vec<Vec3> = f.matrices.chunks_exact(16).map(|m| attachment(m, petiole)).collect();
    let grid = StemGrid::new(&g.skeleton.stems);
    let parts = crate::par::ranges(at.len(), threads.max(1) * 4);
    let mut stem: Vec<u32> =
        crate::par::map(parts, threads, |r| at[r].iter().map(|&p| grid.nearest(p)).collect::<Vec<u32>>()).concat();
    let key = |i: u32| {
        let s = &stems[i as usize];
        stem_key(&s.base().to_array(), f32::from(s.level))
    };
    let mut best: Vec<(f32, u32)> = vec![(f32::INFINITY, u32::MAX); at.len()];
    loop {
        let mut leaves: KeyMap<(u64, u64), Vec<u32>> = KeyMap::default();
        for (k, _) in best.iter().enumerate().filter(|(_, b)| b.1 == u32::MAX) {
            leaves.entry(key(stem[k])).or_default().push(k as u32);
        }
        if leaves.is_empty() {
            break;
        }
        let parts = crate::par::ranges(n, threads);
        for part in crate::par::map(parts, threads, |r| nearest_own_vertices(g, &at, &leaves, r)) {
            // Parts come in vertex order: a later part wins only when strictly nearer.
            for (b, (d, v)) in best.iter_mut().zip(part).filter(|(_, p)| p.1 != u32::MAX) {
                if b.1 == u32::MAX || d < b.0 {
                    *b = (d, v);
                }
            }
        }
        // Leaves on a stem with no bark vertex of its own go to its parent; past the root, to
        // vertex 0.
        for (k, b) in best.iter_mut().enumerate().filter(|(_, b)| b.1 == u32::MAX) {
            match stems[stem[k] as usize].parent {
                Some(parent) => stem[k] = parent,
                None => *b = (0.0, 0),
            }
        }
    }
    Some(
        best.iter()
            .map(|b| bark.wind[b.1 as usize * WIND_STRIDE..][..WIND_STRIDE].try_into().expect("a record"))
            .collect(),
    )
}

/// For the leaves listed under their stem's key in `leaves`, the nearest of the bark vertices
/// `vertices` with that key to the leaf's point in `at`: per leaf `(squared distance, vertex)`,
/// vertex `u32::MAX` when there is none (ties to the lower vertex).
fn nearest_own_vertices(
    g: &Generated,
    at: &[Vec3],
    leaves: &KeyMap<(u64, u64), Vec<u32>>,
    vertices: std::ops::Range<usize>,
) -> Vec<(f32, u32)> {
    let bark = &g.mesh;
    let mut best = vec![(f32::INFINITY, u32::MAX); at.len()];
    for v in vertices {
        let w = &bark.wind[WIND_STRIDE * v..WIND_STRIDE * v + 4];
        let Some(ks) = leaves.get(&stem_key(w, w[3])) else { continue };
        let p = Vec3::from_slice(&bark.positions[3 * v..3 * v + 3]);
        for &k in ks {
            let d = p.distance_squared(at[k as usize]);
            let b = &mut best[k as usize];
            if b.1 == u32::MAX || d < b.0 {
                *b = (d, v as u32);
            }
        }
    }
    best
}

/// A hash map with [`KeyHasher`]: its lookups (the only use; it is never iterated for output
/// order) are the same on every target.
type KeyMap<K, V> = HashMap<K, V, BuildHasherDefault<KeyHasher>>;

/// A small multiplicative hasher for integer keys (FxHash's step): much cheaper than the
/// default SipHash for the millions of look-ups per export.
#[derive(Default)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn write(&mut self, bytes: &[u8]) {
        bytes.iter().for_each(|&b| self.write_u64(u64::from(b)));
    }

    fn write_u32(&mut self, n: u32) {
        self.write_u64(u64::from(n));
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// The bits of a wind record's pivot and level: which stem's bark a vertex is.
fn stem_key(pivot: &[f32], level: f32) -> (u64, u64) {
    let bits = |a: f32, b: f32| u64::from(a.to_bits()) << 32 | u64::from(b.to_bits());
    (bits(pivot[0], pivot[1]), bits(pivot[2], level))
}

/// Where a leaf with instance matrix `m` (column-major 4×4, leaf units to metres) meets its
/// stem: the foot of its petiole, leaf point `(0, −petiole, 0)` (the blade's base when
/// `petiole` is 0), which the foliage places on the stem's centre curve.
pub(super) fn attachment(m: &[f32], petiole: f32) -> Vec3 {
    Vec3::new(m[12] - petiole * m[4], m[13] - petiole * m[5], m[14] - petiole * m[6])
}

/// Cells along the longest side of the skeleton's bounds in the [`StemGrid`].
const GRID_CELLS: f32 = 256.0;
/// How far (m) a segment of a stem's centre curve may bow away from its chord before the
/// [`StemGrid`] cuts it into more pieces.
const BOW: f32 = 0.0005;
/// Rings of cells a [`StemGrid`] query searches before it looks at every piece.
const SHELLS: i64 = 6;

/// The stems' centre curves as straight pieces (each segment of the Catmull-Rom curve cut into
/// up to 8, so the curve bows at most about [`BOW`] from them), each listed in every cell of a
/// uniform grid its box (grown by a twentieth of a cell) overlaps: nearest-stem queries.
struct StemGrid {
    /// Piece ends and stem index.
    pieces: Vec<(Vec3, Vec3, u32)>,
    min: Vec3,
    cell: f32,
    margin: f32,
    dims: [i64; 3],
    /// The pieces listed in each cell, cell after cell.
    list: Vec<u32>,
    /// Where each non-empty cell's run of `list` is.
    cells: KeyMap<u64, (u32, u32)>,
}

impl StemGrid {
    fn new(stems: &[crate::skeleton::Stem]) -> StemGrid {
        let mut pieces = Vec::new();
        for (i, s) in stems.iter().enumerate().filter(|(_, s)| s.points.len() >= 2) {
            for k in 0..s.points.len() - 1 {
                let seg = s.segment(k);
                let (mut a, end) = (seg.position(0.0), seg.position(1.0));
                // A chord cut into n pieces bows about n² times less.
                let bow = seg.position(0.5).distance(0.5 * (a + end));
                let n = (bow / BOW).sqrt().ceil().clamp(1.0, 8.0) as usize;
                for j in 1..=n {
                    let b = if j == n { end } else { seg.position(j as f32 / n as f32) };
                    pieces.push((a, b, i as u32));
                    a = b;
                }
            }
        }
        let ends: Vec<f32> = pieces.iter().flat_map(|p| [p.0, p.1]).flat_map(|v| v.to_array()).collect();
        let b = Bounds::of(&ends);
        let (lo, hi) = (Vec3::from(b.min), Vec3::from(b.max));
        let cell = ((hi - lo).max_element() / GRID_CELLS).max(1e-3);
        let margin = 0.05 * cell;
        let min = lo - Vec3::splat(margin);
        let dims = ((hi - lo + Vec3::splat(2.0 * margin)) / cell).to_array().map(|d| d as i64 + 1);
        let mut g = StemGrid { pieces, min, cell, margin, dims, list: Vec::new(), cells: KeyMap::default() };
        let mut entries = Vec::new();
        for (k, &(a, b, _)) in g.pieces.iter().enumerate() {
            let (c0, c1) = (g.cell_of(a.min(b) - Vec3::splat(margin)), g.cell_of(a.max(b) + Vec3::splat(margin)));
            for x in c0[0]..=c1[0] {
                for y in c0[1]..=c1[1] {
                    for z in c0[2]..=c1[2] {
                        entries.push((g.key([x, y, z]), k as u32));
                    }
                }
            }
        }
        entries.sort_unstable();
        for (i, &(key, piece)) in entries.iter().enumerate() {
            g.list.push(piece);
            g.cells.entry(key).or_insert((i as u32, i as u32)).1 = i as u32 + 1;
        }
        g
    }

    /// The cell holding `p`, clamped to the grid.
    fn cell_of(&self, p: Vec3) -> [i64; 3] {
        let c = ((p - self.min) / self.cell).to_array();
        [0, 1, 2].map(|k| (c[k].max(0.0) as i64).min(self.dims[k] - 1))
    }

    fn key(&self, c: [i64; 3]) -> u64 {
        ((c[0] * self.dims[1] + c[1]) * self.dims[2] + c[2]) as u64
    }

    /// The stem whose centre curve passes nearest to `p` (the lowest index among equally near
    /// ones; 0 when there are no pieces). The cells up to [`SHELLS`] away from `p`'s, then, for
    /// a point that far from every stem (never a leaf of a generated tree), every piece.
    fn nearest(&self, p: Vec3) -> u32 {
        let c = self.cell_of(p);
        let mut best = (f32::INFINITY, 0u32);
        let consider = |best: &mut (f32, u32), (a, b, stem): (Vec3, Vec3, u32)| {
            let ab = b - a;
            let t = ((p - a).dot(ab) / ab.length_squared().max(1e-20)).clamp(0.0, 1.0);
            let d = (a + ab * t).distance_squared(p);
            if (d, stem) < *best {
                *best = (d, stem);
            }
        };
        for r in 0..=SHELLS {
            self.shell(c, r, |k| consider(&mut best, self.pieces[k as usize]));
            // A piece not seen yet is listed in no cell within `r` of `p`'s cell, so it lies
            // more than `r` cells plus the margin from `p` (also when `p` was clamped).
            let covered = r as f32 * self.cell + self.margin;
            if best.0 <= covered * covered {
                return best.1;
            }
        }
        self.pieces.iter().for_each(|&piece| consider(&mut best, piece));
        best.1
    }

    /// Calls `visit` with every piece listed in the cells at Chebyshev distance `r` from `c`.
    fn shell(&self, c: [i64; 3], r: i64, mut visit: impl FnMut(u32)) {
        let range = |k: usize| (c[k] - r).max(0)..=(c[k] + r).min(self.dims[k] - 1);
        for x in range(0) {
            for y in range(1) {
                for z in range(2) {
                    if (x - c[0]).abs().max((y - c[1]).abs()).max((z - c[2]).abs()) != r {
                        continue;
                    }
                    if let Some(&(a, b)) = self.cells.get(&self.key([x, y, z])) {
                        self.list[a as usize..b as usize].iter().for_each(|&k| visit(k));
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_finds_the_nearest_stem_like_a_search_of_every_piece() {
        let p = crate::presets::find("grown_bushy").and_then(|p| p.params().ok()).expect("preset");
        let g = crate::generate(&p).expect("tree");
        let grid = StemGrid::new(&g.skeleton.stems);
        let brute = |q: Vec3| {
            let mut best = (f32::INFINITY, 0u32);
            for &(a, b, stem) in &grid.pieces {
                let ab = b - a;
                let t = ((q - a).dot(ab) / ab.length_squared().max(1e-20)).clamp(0.0, 1.0);
                let d = ((a + ab * t).distance_squared(q), stem);
                if d < best {
                    best = d;
                }
            }
            best.1
        };
        // Points on the stems, near them, in the open crown and far outside the grid.
        let b = g.mesh.bounds();
        let (lo, hi) = (Vec3::from(b.min) - 2.0, Vec3::from(b.max) + 2.0);
        let mut rng = crate::rng::Rng::new(3, "grid test");
        for k in 0..3000 {
            let q = if k % 2 == 0 {
                let s = &g.skeleton.stems[k % g.skeleton.stems.len()];
                s.point(rng.next_f32()) + 0.01 * (k % 7) as f32 * Vec3::new(rng.next_f32(), 0.5, -0.3)
            } else {
                lo + (hi - lo) * Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32())
            };
            assert_eq!(grid.nearest(q), brute(q), "{q}");
        }
        assert_eq!(grid.nearest(Vec3::splat(1e4)), brute(Vec3::splat(1e4)));
    }
}
