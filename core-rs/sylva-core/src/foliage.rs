//! # Foliage
//!
//! Leaves on the tree: one leaf mesh (the generated leaf's LOD0 from [`crate::leaf`], its
//! billboard cloud or its flat card, see **Leaf Mesh**) drawn once per leaf through a per-instance matrix and colour.
//!
//! * **Where**: on every stem of the last branch level present (Weber & Penn: the leaves hang
//!   on the deepest level), `Leaves` per whole stem shared among its split records, spread
//!   over the part of the stem above **Leaf Start**, crowded toward the tip or the base by
//!   **Leaf Distribution**, pulled into clumps by **Clumping**. Grown trees (space
//!   colonization) carry them on the outermost internodes (the last three) of every shoot.
//! * **Orientation** ("Top oriented leaves", *Modeling the Mighty Maple for Web*
//!   (ibiblio.org/e-notes)): a leaf first leaves its stem at **Leaf Angle**, turned about the stem
//!   by the golden angle from one leaf to the next. Its direction `t` (the midrib, leaf `+y`) is
//!   then lowered, `t_y ← t_y (1 − t_y²)`, and renormalised, so no leaf points straight up; finally
//!   the leaf turns about that direction so its front (leaf `+z`) faces the sky as much as it can:
//!   the front is the component of world up perpendicular to `t`.
//! * **Size**: `Leaf Scale` (m, base to tip) times `1 ± Size Variation`; the width is further
//!   times **Leaf Scale X**.
//! * **Colour**: a per-leaf RGB tint (multiplies the leaf texture): brightness and a shift
//!   toward yellow, by **Colour Variation**.
//! * **Season**: away from July, [`crate::season`] flushes, colours, drops or removes each leaf
//!   (stream `"season"`), reading the summer crown's light field; at July nothing changes.
//! * **Leaf Mesh**: the blade (LOD0), its billboard cloud or its card; Auto picks the finest
//!   that keeps the whole foliage under [`AUTO_TRIANGLES`] triangles.
//! * **Budget**: more than `max_leaves` leaves stops the generation with an error before any
//!   instance is written.
//!
//! Matrices are column-major 4×4 (`f32 × 16` per leaf, the WebGL / three.js layout) mapping
//! leaf units to metres. Randomness: the named stream `"foliage"`. Deterministic: the same
//! skeleton and parameters give byte-identical buffers.

use crate::crown_shade::CrownLight;
use crate::error::SylvaError;
use crate::leaf::{self, texture::LeafTexture, Leaf};
use crate::math;
use crate::mesh::TreeMesh;
use crate::organs::OrganSet;
use crate::params::{FoliageParams, GrowthMode, LeafLod, LeafParams};
use crate::rng::Rng;
use crate::skeleton::Skeleton;
pub use frames::{face_up, lower};
use frames::{Site, LANES};
use glam::Vec3;
use std::sync::{Arc, Mutex};

mod frames;

/// Internodes at the end of each grown shoot that carry leaves.
const GROWN_LEAF_INTERNODES: usize = 3;
/// Golden angle (degrees): the turn about the stem from one leaf to the next.
const GOLDEN_ANGLE: f32 = 137.507_77;
/// Leaves per clump (Clumping).
const CLUMP: usize = 5;
/// Leaf Mesh = Auto: the most triangles the foliage may have before a lighter leaf is used.
pub const AUTO_TRIANGLES: u64 = 200_000;

/// The leaves of one tree.
#[derive(Clone, Debug)]
pub struct Foliage {
    /// The leaf geometry in leaf units (LOD0 blade or card), one `leaves` group.
    pub mesh: TreeMesh,
    /// Per-leaf 4×4 matrices, column-major, 16 floats per leaf.
    pub matrices: Vec<f32>,
    /// Per-leaf RGB tint, 3 floats per leaf.
    pub colors: Vec<f32>,
    /// The leaf (texture and hash), shared with the cache.
    pub leaf: Option<Arc<Leaf>>,
    /// How many of the instances, at the end, are leaves lying on the ground (**Fallen
    /// Leaves**, [`crate::season::Ground`]); the ones before them are on the tree.
    pub fallen: usize,
    /// Flowers, fruit, catkins and buds ([`crate::organs`]), one set per kind of part.
    pub organs: Vec<OrganSet>,
}

impl Foliage {
    /// Number of leaf instances (on the tree and fallen).
    pub fn count(&self) -> usize {
        self.colors.len() / 3
    }

    /// Number of leaves on the tree (the instances before the fallen ones).
    pub fn on_tree(&self) -> usize {
        self.count() - self.fallen
    }

    /// A tree without leaves or parts.
    pub fn bare() -> Foliage {
        Foliage {
            mesh: TreeMesh::default(),
            matrices: Vec::new(),
            colors: Vec::new(),
            leaf: None,
            fallen: 0,
            organs: Vec::new(),
        }
    }

    /// The baked leaf colour texture, if there are leaves.
    pub fn texture(&self) -> Option<&LeafTexture> {
        self.leaf.as_deref().map(|l| &l.texture)
    }

    /// Hash of the leaf shape (changes exactly when the leaf parameters change), 0 when bare.
    pub fn leaf_hash(&self) -> u64 {
        self.leaf.as_deref().map_or(0, |l| l.hash)
    }

    /// Feeds the foliage buffers into a content hash (FNV-1a over 32-bit words).
    pub fn hash_into(&self, mut h: u64) -> u64 {
        let mut word = |w: u32| h = (h ^ u64::from(w)).wrapping_mul(0x0000_0100_0000_01b3);
        let m = self.mesh.content_hash();
        word(m as u32);
        word((m >> 32) as u32);
        self.matrices.iter().for_each(|v| word(v.to_bits()));
        self.colors.iter().for_each(|v| word(v.to_bits()));
        // Trees without parts (every preset's summer) keep the hash they had before them.
        self.organs.iter().fold(h, |h, o| o.hash_into(h))
    }
}

/// What the leaf itself is made of: the leaf parameters but Leaf Mesh (which picks one of the
/// leaf's meshes to draw, not the leaf), and the petiole's length (a foliage parameter).
/// Equal keys give the same [`Leaf`].
#[derive(Clone, Debug, PartialEq)]
pub struct LeafKey(LeafParams, u32);

impl LeafKey {
    /// The key of the leaf of `p` with a petiole `petiole` leaf lengths long.
    pub fn of(p: &LeafParams, petiole: f32) -> LeafKey {
        LeafKey(LeafParams { foliage_lod: LeafLod::Auto, ..p.clone() }, petiole.to_bits())
    }
}

type LeafCache = Mutex<Option<(LeafKey, Arc<Leaf>)>>;
static LEAF_CACHE: LeafCache = Mutex::new(None);

/// The leaf for these parameters, generated once per leaf-parameter change (the leaf is a pure
/// function of its parameters, so the cache never changes a result).
pub fn cached_leaf(p: &LeafParams, petiole: f32) -> Result<Arc<Leaf>, SylvaError> {
    let key = LeafKey::of(p, petiole);
    if let Ok(slot) = LEAF_CACHE.lock() {
        if let Some((k, l)) = slot.as_ref() {
            if *k == key {
                return Ok(Arc::clone(l));
            }
        }
    }
    let l = Arc::new(leaf::generate(p, petiole)?);
    if let Ok(mut slot) = LEAF_CACHE.lock() {
        *slot = Some((key, Arc::clone(&l)));
    }
    Ok(l)
}

/// The budget error for leaves.
pub fn budget_error(need: u64, max: u32) -> SylvaError {
    SylvaError::Budget {
        param: "max_leaves".into(),
        message: format!(
            "this tree would need {need} leaves, more than the max_leaves budget of {max}: \
             lower Leaves or Branches, or raise Max Leaves"
        ),
    }
}

/// Sine and cosine of the golden-angle turn of leaf `k` (`GOLDEN_ANGLE · k` degrees), for every
/// `k < n`. The same for every tree, so computed once and kept (grown when a tree has more
/// leaves): two software trigonometric calls per leaf were a fifth of the foliage stage.
fn golden_turns(n: usize) -> Arc<Vec<[f32; 2]>> {
    static TURNS: Mutex<Option<Arc<Vec<[f32; 2]>>>> = Mutex::new(None);
    let mut slot = TURNS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(t) = slot.as_ref().filter(|t| t.len() >= n) {
        return Arc::clone(t);
    }
    let have = slot.as_ref().map_or(0, |t| t.len());
    let mut turns: Vec<[f32; 2]> = slot.as_ref().map_or_else(Vec::new, |t| t.to_vec());
    turns.reserve(n.max(2 * have) - have);
    for k in have..n.max(2 * have) {
        let a = math::rad(GOLDEN_ANGLE * k as f32);
        turns.push([math::sin(a), math::cos(a)]);
    }
    let turns = Arc::new(turns);
    *slot = Some(Arc::clone(&turns));
    turns
}

/// A drag's preview ([`place_lit_by`]) places at most one leaf site in this many.
pub const PREVIEW_THIN: usize = 2;
/// The most leaves a drag's preview places (about half the default tree's): a denser crown is
/// thinned further, so a preview's cost stays bounded whatever the leaf count.
pub const PREVIEW_LEAVES: u64 = 20_000;

/// One leaf site in this many is placed by a drag's preview of a tree of `leaves` leaves: every
/// [`PREVIEW_THIN`]-th, or sparser so that at most about [`PREVIEW_LEAVES`] are placed.
pub fn preview_thin(leaves: u64) -> usize {
    PREVIEW_THIN.max(leaves.div_ceil(PREVIEW_LEAVES) as usize)
}

/// Where leaves sit along one stem: `(stem index, first t, last t, count)`.
fn spans(skeleton: &Skeleton, p: &FoliageParams) -> Vec<(usize, f32, f32, usize)> {
    let stems = &skeleton.stems;
    let n = p.leaves as f32;
    if p.leaves == 0 || stems.is_empty() {
        return Vec::new();
    }
    if skeleton.mode == GrowthMode::SpaceColonization {
        return stems
            .iter()
            .enumerate()
            .filter(|(_, s)| s.level > 0 && s.points.len() >= 2)
            .map(|(i, s)| {
                let segs = s.points.len() - 1;
                let first = segs.saturating_sub(GROWN_LEAF_INTERNODES) as f32 / segs as f32;
                (i, first.max(p.foliage_start), 1.0, p.leaves as usize)
            })
            .collect();
    }
    let last = stems.iter().map(|s| s.level).max().unwrap_or(0);
    let mut carry = 0.0f32;
    stems
        .iter()
        .enumerate()
        .filter(|(_, s)| s.level == last && s.length > 0.0)
        .filter_map(|(i, s)| {
            // A split record carries its share of the whole stem's leaves (error diffusion).
            let share = n * (s.length / s.chain_length.max(s.length)) + carry;
            let count = share.round().max(0.0);
            carry = share - count;
            (count > 0.0).then_some((i, p.foliage_start, 1.0, count as usize))
        })
        .collect()
}

/// Places the leaves on `skeleton` and dresses them with the leaf ([`place`] then [`dress`]).
pub fn build(skeleton: &Skeleton, p: &FoliageParams, leaf: &LeafParams) -> Result<Foliage, SylvaError> {
    let mut foliage = place(skeleton, p)?;
    dress(&mut foliage, leaf, p.leaf_petiole)?;
    Ok(foliage)
}

/// The foliage stage: where the leaves sit (per-leaf matrices and tints), without the leaf
/// itself (`mesh` empty, `leaf` none until [`dress`]). Reads the skeleton and the Foliage
/// parameters; the leaf-shape parameters never change a placement.
pub fn place(skeleton: &Skeleton, p: &FoliageParams) -> Result<Foliage, SylvaError> {
    place_lit(skeleton, p).map(|(f, _)| f)
}

/// [`place`], also returning the leaves' light field ([`crate::crown_shade`], `None` for a bare
/// tree), which has darkened their tints and shades the bark ([`crate::mesh::shade`]).
pub fn place_lit(skeleton: &Skeleton, p: &FoliageParams) -> Result<(Foliage, Option<CrownLight>), SylvaError> {
    place_lit_by(skeleton, p, None, false)
}

/// [`place_lit`], darkening the tints by `field` (a field of other leaves, for a preview while
/// dragging) instead of one built from these leaves when it is given; returns the field used.
///
/// A `preview` (while dragging) places only every `thin`-th leaf site ([`preview_thin`]: every
/// other one, sparser for crowns of over [`PREVIEW_LEAVES`] leaves), each leaf `√thin` times
/// larger so the crown keeps its leaf area. The leaves kept sit exactly where the full
/// placement puts them (every site still draws its random numbers).
pub fn place_lit_by(
    skeleton: &Skeleton,
    p: &FoliageParams,
    field: Option<&CrownLight>,
    preview: bool,
) -> Result<(Foliage, Option<CrownLight>), SylvaError> {
    let spans = spans(skeleton, p);
    let per_site: u64 = if p.foliage_twigs3 { 3 } else { 1 };
    let need: u64 = spans.iter().map(|s| s.3 as u64).sum::<u64>() * per_site;
    if need > u64::from(p.max_leaves) {
        return Err(budget_error(need, p.max_leaves));
    }
    let bare = Foliage::bare();
    if need == 0 {
        return Ok((bare, None));
    }
    let thin = if preview { preview_thin(need) } else { 1 };
    let mut rng = Rng::new(u64::from(skeleton.seed), "foliage");
    let need_n = need as usize / thin + 1;
    let mut matrices = Vec::with_capacity(need_n * 16);
    let mut colors = Vec::with_capacity(need_n * 3);
    let enlarge = if thin == 1 { 1.0 } else { (thin as f32).sqrt() };
    let bias = math::pow(2.0, -2.0 * p.foliage_distribution);
    let a = math::rad(p.foliage_angle);
    let angle = (math::cos(a), math::sin(a));
    let turns = golden_turns(spans.iter().map(|s| s.3).sum());
    let mut season = crate::season::Sites::new(skeleton.seed, p);
    let mut batch = Batch::new(Shape { per_site: per_site as usize, angle, enlarge, p });
    // Leafy Years: whether each leaf's wood is recent enough to carry it (empty: all are).
    let mut recent: Vec<bool> = Vec::new();
    let mut k = 0usize;
    for &(si, t0, t1, count) in &spans {
        let stem = &skeleton.stems[si];
        let mut curve = stem.points();
        let mut clump_t = 0.0f32;
        for j in 0..count {
            let mut u = (j as f32 + 0.5 + 0.5 * rng.var(0.5)) / count as f32;
            if p.foliage_clumping > 0.0 {
                // Every CLUMP leaves share a clump centre; Clumping pulls them onto it.
                if j % CLUMP == 0 {
                    let mid = ((j + CLUMP / 2).min(count - 1) as f32 + 0.5) / count as f32;
                    clump_t = mid;
                }
                u += (clump_t - u) * p.foliage_clumping;
            }
            // pow(u, 1) is u exactly: skip the call for an even distribution.
            let u = if bias == 1.0 { u.clamp(0.0, 1.0) } else { math::pow(u.clamp(0.0, 1.0), bias) };
            let t = t0 + (t1 - t0) * u;
            if k % thin != 0 {
                // A site a preview leaves out: its random numbers are drawn all the same (the
                // season's after the leaves before it).
                k += 1;
                batch.flush(&mut matrices, &mut colors, season.as_mut());
                for _ in 0..per_site {
                    rng.var(p.foliage_size_v);
                    rng.var(0.5 * p.foliage_color_v);
                    rng.next_f32();
                    if let Some(s) = season.as_mut() {
                        s.skip();
                    }
                }
                continue;
            }
            let (pos, tangent) = curve.sample(t);
            let site = Site { pos, tangent, base_normal: stem.base_normal, turn: turns[k] };
            k += 1;
            let v = p.foliage_color_v;
            // Size, brightness and yellowing of each of the site's leaves, in the stream's order.
            let mut draws = [[0.0; 3]; 3];
            for d in &mut draws[..per_site as usize] {
                let s = math::max(1.0 + rng.var(p.foliage_size_v), 0.05);
                let b = 1.0 + rng.var(0.5 * v);
                *d = [s, b, 0.5 * v * rng.next_f32()];
            }
            batch.push(site, draws, per_site as usize);
            if p.leaf_years > 0.0 {
                let wood = stem.born + (stem.tip_year - stem.born) * t;
                let keep = skeleton.age - wood <= p.leaf_years;
                recent.extend(std::iter::repeat_n(keep, per_site as usize));
            }
            if batch.full() {
                batch.flush(&mut matrices, &mut colors, season.as_mut());
            }
        }
    }
    batch.flush(&mut matrices, &mut colors, season.as_mut());
    if recent.contains(&false) {
        keep_recent(&recent, &mut matrices, &mut colors);
        if let Some(s) = season.as_mut() {
            s.keep(&recent);
        }
    }
    // Inner leaves see less sky: the crown-depth term multiplies into the tints.
    let mut light = field.cloned().or_else(|| CrownLight::from_leaves(&matrices));
    // The season reads the summer crown's light; leaves resized or fallen make a new field.
    let mut ground = p.fallen_leaves.then(crate::season::Ground::default);
    if season.is_some_and(|s| s.apply(light.as_ref(), &mut matrices, &mut colors, ground.as_mut())) && field.is_none() {
        light = CrownLight::from_leaves(&matrices);
    }
    crate::crown_shade::darken_with(light.as_ref(), &matrices, &mut colors);
    // The fallen leaves follow the tree's, outside its light field.
    let fallen = ground.as_ref().map_or(0, |g| g.colors.len() / 3);
    if let Some(g) = ground {
        matrices.extend_from_slice(&g.matrices);
        colors.extend_from_slice(&g.colors);
    }
    let organs = crate::organs::place(skeleton, p);
    Ok((Foliage { matrices, colors, fallen, organs, ..bare }, light))
}

/// Keeps the leaves marked in `recent` (Leafy Years: leaves only on wood grown in the last years;
/// older, inner wood goes bare), their matrices and tints.
fn keep_recent(recent: &[bool], matrices: &mut Vec<f32>, colors: &mut Vec<f32>) {
    let mut n = 0;
    for (i, _) in recent.iter().enumerate().filter(|(_, &r)| r) {
        matrices.copy_within(i * 16..i * 16 + 16, n * 16);
        colors.copy_within(i * 3..i * 3 + 3, n * 3);
        n += 1;
    }
    matrices.truncate(n * 16);
    colors.truncate(n * 3);
}

/// What every leaf's shape reads: leaves per site, the Foliage Angle's cosine and sine, the
/// preview's enlargement and the parameters.
struct Shape<'a> {
    per_site: usize,
    angle: (f32, f32),
    enlarge: f32,
    p: &'a FoliageParams,
}

/// Up to [`LANES`] sites waiting for their geometry ([`frames`]), with their leaves' random
/// numbers (size, brightness, yellowing; `per_site` a site), already drawn in the stream's order.
struct Batch<'a> {
    shape: Shape<'a>,
    sites: [Site; LANES],
    draws: [[f32; 3]; 3 * LANES],
    n: usize,
}

impl<'a> Batch<'a> {
    fn new(shape: Shape<'a>) -> Batch<'a> {
        Batch { shape, sites: [Site::default(); LANES], draws: [[0.0; 3]; 3 * LANES], n: 0 }
    }

    fn push(&mut self, site: Site, draws: [[f32; 3]; 3], per_site: usize) {
        self.sites[self.n] = site;
        self.draws[self.n * per_site..(self.n + 1) * per_site].copy_from_slice(&draws[..per_site]);
        self.n += 1;
    }

    fn full(&self) -> bool {
        self.n == LANES
    }

    /// Writes the waiting sites' leaves (matrices, tints, the season's record), in order.
    fn flush(&mut self, matrices: &mut Vec<f32>, colors: &mut Vec<f32>, mut season: Option<&mut crate::season::Sites>) {
        let Shape { per_site, angle, enlarge, p } = self.shape;
        let sites = &self.sites[..self.n];
        let frames = frames::leaf_frames(sites, angle);
        let mut dirs = [Vec3::ZERO; 3 * LANES];
        frames::twig_dirs(&frames[..self.n], per_site, &mut dirs);
        let m = self.n * per_site;
        let mut fronts = [Vec3::ZERO; 3 * LANES];
        frames::lower_and_face_up(&mut dirs[..m], &mut fronts[..m]);
        for (k, ((&d, &front), &[s, b, yellow])) in dirs.iter().zip(&fronts).zip(&self.draws).take(m).enumerate() {
            let pos = frames[k / per_site].0;
            let len = p.foliage_scale * s * enlarge;
            // The petiole (leaf y from -Petiole Length to 0) starts on the stem.
            let base = pos + d * (len * p.leaf_petiole);
            frames::push_matrix(matrices, base, d, front, len, len * p.foliage_scale_x);
            if let Some(s) = season.as_deref_mut() {
                s.leaf(pos);
            }
            colors.extend_from_slice(&[b * (1.0 + yellow), b * (1.0 + 0.4 * yellow), b * (1.0 - yellow)]);
        }
        self.n = 0;
    }
}

/// The leaf stage: the leaf of the Leaf parameters (generated once per leaf shape, see
/// [`cached_leaf`]) and the mesh drawn for every placed leaf, by **Leaf Mesh** (Auto: the
/// finest whose triangles times the leaf count stay within [`AUTO_TRIANGLES`]). A bare tree
/// stays bare. `petiole`: the Petiole Length the leaves were placed with.
pub fn dress(foliage: &mut Foliage, p: &LeafParams, petiole: f32) -> Result<(), SylvaError> {
    (foliage.mesh, foliage.leaf) = leaf_mesh(foliage.count(), p, petiole)?;
    Ok(())
}

/// The mesh drawn per leaf for `count` leaves and the leaf it comes from (empty and none for
/// no leaves); see [`dress`].
pub fn leaf_mesh(count: usize, p: &LeafParams, petiole: f32) -> Result<(TreeMesh, Option<Arc<Leaf>>), SylvaError> {
    let need = count as u64;
    if need == 0 {
        return Ok((TreeMesh::default(), None));
    }
    let leaf = cached_leaf(p, petiole)?;
    let mesh = match p.foliage_lod {
        LeafLod::Blade => leaf.mesh.clone(),
        LeafLod::Billboards => leaf.lod.billboards.clone(),
        LeafLod::Card => leaf.lod.card.clone(),
        LeafLod::Auto => {
            let fits = |m: &TreeMesh| (m.triangle_count() as u64) * need <= AUTO_TRIANGLES;
            [&leaf.mesh, &leaf.lod.billboards].into_iter().find(|m| fits(m)).unwrap_or(&leaf.lod.card).clone()
        }
    };
    Ok((mesh, Some(leaf)))
}
