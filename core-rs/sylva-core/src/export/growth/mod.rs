//! # The growth animation
//!
//! A generated tree played from year 0 to its Age as **morph targets between key years** on the
//! tree's own meshes (written by [`crate::export::glb::write_growth`], layout in
//! docs/formats.md, "Growth animation"). The growth replay ([`crate::age`]) only ever adds
//! wood at the stem tips and thickens stems ring by ring, so every vertex of the tree as built
//! has a place in every earlier year ([`morph`]); [`life`] recovers each stem's birth year and
//! mature form from the stems as built.
//!
//! Key years ([`key_years`]) are denser early, where the Chapman-Richards curve grows fastest;
//! each key but the last (the tree as built, the meshes' own positions) is one morph target,
//! and the animation moves the weight from one target to the next between their years, so
//! the tree between two keys is the straight blend of its shapes in those years.
//!
//! [`years::years_zip`] is the other form, for tools without glTF animation: one plain GLB per whole
//! year, each tree generated at that Age (the replay at Age `y` is the tree at Age `y`).

pub mod aged;
pub mod life;
pub mod morph;
pub mod years;

use crate::mesh::WIND_STRIDE;
use crate::Generated;
use life::Lives;
use morph::{bark_places, bark_target, leaf_target, StemIndex, YearShape};

/// Morph targets (key years but the last) at most.
pub const KEYS: usize = 10;
/// The key years' spacing: fraction `(k / (KEYS - 1))^KEY_POWER` of the growing years.
pub const KEY_POWER: f32 = 1.5;

/// Key years past the Mature Age of a tree that plays its life ([`aged`]): the Mature Age,
/// this many evenly spaced years between, and the Age.
pub const AGED_KEYS: usize = 3;

/// The key years of a tree of Age `age` and Mature Age `mature` (seconds of the animation: one
/// second a year): 0, then whole years `min(age, mature) · (k / 9)^1.5` (duplicates dropped),
/// then `min(age, mature)` itself and, for a tree past its Mature Age, `age`, with
/// [`AGED_KEYS`] years between when its life is played (`aged`; otherwise the tree keeps
/// its form as built past the Mature Age). Strictly increasing, first 0, last `age`.
pub fn key_years(age: f32, mature: f32, aged: bool) -> Vec<f32> {
    let grown = age.min(mature);
    let mut years = vec![0.0];
    for k in 1..KEYS - 1 {
        let y = (grown * crate::math::pow(k as f32 / (KEYS - 1) as f32, KEY_POWER)).round();
        if y > years[years.len() - 1] && y < grown {
            years.push(y);
        }
    }
    if grown > 0.0 {
        years.push(grown);
    }
    if aged && age > grown {
        for k in 1..=AGED_KEYS {
            let y = (grown + (age - grown) * k as f32 / (AGED_KEYS + 1) as f32).round();
            if y > years[years.len() - 1] && y < age {
                years.push(y);
            }
        }
    }
    if age > grown {
        years.push(age);
    }
    years
}

/// The growth morphs of a tree: key years and, per key year that differs from the tree as built,
/// the bark's and the leaves' position deltas (3 floats per vertex).
#[derive(Clone, Debug, Default)]
pub struct GrowthMorphs {
    /// [`key_years`].
    pub years: Vec<f32>,
    /// Bark targets, one per year before `min(age, mature)` (the first `targets` years).
    pub bark: Vec<Vec<f32>>,
    /// Baked-leaf targets, the same years (empty without leaves).
    pub leaves: Vec<Vec<f32>>,
    /// The animation's weights: per key year, one per target (1 for the key's own target, 0
    /// for the others; all 0 from `min(age, mature)` on).
    pub weights: Vec<f32>,
}

impl GrowthMorphs {
    /// Number of morph targets.
    pub fn targets(&self) -> usize {
        self.bark.len()
    }
}

/// The baked leaves the growth morphs move: positions, vertices per leaf, and each leaf's wind
/// record (the one of the twig it hangs on, with the point it meets it).
pub struct LeafInput<'a> {
    /// Positions of the baked leaf mesh (leaf after leaf).
    pub positions: &'a [f32],
    /// Vertices per leaf.
    pub per_leaf: usize,
    /// Per leaf: where it meets its twig and the twig's wind record there.
    pub anchors: Vec<(glam::Vec3, [f32; WIND_STRIDE])>,
}

/// The growth morphs of `g`, built at Age `age` with Mature Age `mature`: the bark's (which
/// must carry wind data, as every generated mesh does) and, with `leaves`, the baked leaves'.
pub fn morphs(g: &Generated, age: f32, mature: f32, leaves: Option<&LeafInput<'_>>, threads: usize) -> GrowthMorphs {
    let sk = &g.skeleton;
    let aged = if age > mature { aged::Aged::new(sk) } else { None };
    let years = key_years(age, mature, aged.is_some());
    let index = StemIndex::new(sk);
    let bark = if g.mesh.wind.len() == g.mesh.vertex_count() * WIND_STRIDE {
        bark_places(&g.mesh, &index)
    } else {
        Vec::new()
    };
    let leaf_places: Vec<morph::Place> =
        leaves.map(|l| l.anchors.iter().map(|(p, w)| index.place(*p, w)).collect()).unwrap_or_default();
    let (bark, leaves) = match &aged {
        Some(a) => aged_targets(a, g, &years, (&bark, &leaf_places), leaves, threads),
        None => {
            let grown = age.min(mature);
            let lives = Lives::new(sk, age, mature);
            let target_years: Vec<f32> = years.iter().copied().filter(|&y| y < grown).collect();
            let made = crate::par::map(target_years, threads, |y| {
                let shape = YearShape::new(sk, &lives, y);
                let b = if bark.is_empty() {
                    vec![0.0; g.mesh.positions.len()]
                } else {
                    bark_target(&g.mesh, &bark, &shape)
                };
                let l = leaves.map(|l| leaf_target(l.positions, l.per_leaf, &leaf_places, &shape)).unwrap_or_default();
                (b, l)
            });
            made.into_iter().unzip()
        }
    };
    let leaves = if leaves.iter().all(Vec::is_empty) { Vec::new() } else { leaves };
    let n = bark.len();
    let weights = (0..years.len()).flat_map(|k| (0..n).map(move |j| if j == k { 1.0 } else { 0.0 })).collect();
    GrowthMorphs { years, bark, leaves, weights }
}

/// The bark and leaf targets of an aged tree ([`aged`]): one per key year but the last (the
/// tree as built).
fn aged_targets(
    a: &aged::Aged<'_>,
    g: &Generated,
    years: &[f32],
    (bark, leaf_places): (&[morph::Place], &[morph::Place]),
    leaves: Option<&LeafInput<'_>>,
    threads: usize,
) -> (Vec<Vec<f32>>, Vec<Vec<f32>>) {
    let mature = g.skeleton.maturity.min(g.skeleton.age);
    let lives = aged::mature_lives(a);
    let bark_m: Vec<morph::Place> = bark.iter().map(|p| a.carry(&a.mature, p).0).collect();
    let leaf_m: Vec<(morph::Place, glam::Quat)> = leaf_places.iter().map(|p| a.carry(&a.mature, p)).collect();
    let target_years = years[..years.len() - 1].to_vec();
    let made = crate::par::map(target_years, threads, |y| {
        let (shape, stems);
        let year = if y < mature {
            shape = YearShape::new(&a.mature, &lives, y);
            aged::Year::Young(&shape)
        } else {
            stems = a.stems_in(y);
            aged::Year::Old(&stems)
        };
        let mut b = Vec::with_capacity(g.mesh.positions.len());
        if bark.is_empty() {
            b.resize(g.mesh.positions.len(), 0.0);
        }
        for ((p, place), at_m) in g.mesh.positions.chunks_exact(3).zip(bark).zip(&bark_m) {
            let d = aged::bark_at(a, year, place, at_m) - glam::Vec3::from_slice(p);
            b.extend_from_slice(&d.to_array());
        }
        let l =
            leaves.map(|l| aged::leaves_at(a, year, l.positions, l.per_leaf, leaf_places, &leaf_m)).unwrap_or_default();
        (b, l)
    });
    made.into_iter().unzip()
}
