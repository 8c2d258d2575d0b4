//! # Levels of detail
//!
//! Every level is built from the **one** skeleton [`crate::generate`] built, so the levels of a
//! tree never disagree about where its branches are:
//!
//! * **LOD0**: the generated tree itself (bark tubes at Mesh Quality, every leaf).
//! * **LOD1**: the same sweep ([`crate::mesh::tube::build`]) at [`LOD1_QUALITY`] × Mesh Quality
//!   (fewer rings and sides); every [`LOD1_LEAF_STRIDE`]-th leaf, each scaled by
//!   `√(leaves / kept)` so the leaves cover the same area, drawn with the next lighter leaf mesh
//!   (blade → billboard cloud → card).
//! * **LOD2**: only the trunk and the level-1 stems, swept at [`LOD2_QUALITY`] × Mesh Quality; the
//!   leaves become a **billboard cloud** (Décoret et al. 2003, simplified): the leaf positions are
//!   clustered (deterministic k-means, at most [`CLOUD_CLUSTERS_MAX`] clusters) and each cluster
//!   becomes three crossed quads on its principal planes, sized to the cluster and tinted with its
//!   mean leaf colour, for the browser to texture.
//! * The **impostor** (a hemi-octahedral atlas of views) is baked in the browser from LOD0.
//! * **Flowers, fruit, catkins and buds** ([`crate::organs`]): LOD1 keeps every organ set as it
//!   is (they are few and small next to the leaves); LOD2 carries none (at its distance they
//!   are a pixel or less, and its leaves are the cloud).
//!
//! The LOD1 and LOD2 barks carry the same crown-depth occlusion as LOD0's
//! ([`TreeMesh::shade`], from LOD0's leaves), so a level switch does not change the bark's tone.
//!
//! Cloud quads are [`QUAD_FLOATS`] floats each: `centre xyz, u xyz, v xyz, rgb, density`, where
//! `u` and `v` are the quad's half-axes (m): its corners are `centre ± u ± v`, and `density`
//! (0.05..1) is the share of the quad the cluster's leaves cover (their summed leaf-box area over
//! the quad area of its main plane), so the browser can draw sparse clusters sparse. Only IEEE-exact
//! operations are used, so the buffers are byte-identical on every target.

use crate::crown_shade::CrownLight;
use crate::error::SylvaError;
use crate::foliage::Foliage;
use crate::mesh::shade::occlusion_with;
use crate::mesh::{tube, TreeMesh};
use crate::meta::{LodLevelMeta, LodMeta};
use crate::params::{MeshParams, TreeParams};
use crate::skeleton::Skeleton;
use crate::Generated;
use glam::Vec3;

/// LOD1 Mesh Quality as a fraction of the tree's.
pub const LOD1_QUALITY: f32 = 0.5;
/// LOD2 Mesh Quality as a fraction of the tree's.
pub const LOD2_QUALITY: f32 = 0.25;
/// LOD1 keeps one leaf in this many.
pub const LOD1_LEAF_STRIDE: usize = 3;
/// Most clusters of the LOD2 billboard cloud.
pub const CLOUD_CLUSTERS_MAX: usize = 32;
/// Quads per cloud cluster.
pub const QUADS_PER_CLUSTER: usize = 3;
/// Floats per cloud quad: `centre xyz, u xyz, v xyz, rgb, density`.
pub const QUAD_FLOATS: usize = 13;
/// Lloyd iterations of the leaf clustering.
const KMEANS_ITERATIONS: usize = 10;

/// One reduced level: bark mesh, leaves (instanced) and billboard-cloud quads.
#[derive(Clone, Debug)]
pub struct LodLevel {
    /// Bark tubes.
    pub mesh: TreeMesh,
    /// Leaves (empty for LOD2, whose leaves are the cloud).
    pub foliage: Foliage,
    /// Billboard-cloud quads, [`QUAD_FLOATS`] floats each (empty for LOD1).
    pub cloud: Vec<f32>,
    /// Number of stems swept.
    pub stems: usize,
}

/// Triangles of a bark mesh plus its instanced leaves plus its cloud quads.
fn count_triangles(mesh: &TreeMesh, foliage: &Foliage, cloud: &[f32]) -> usize {
    mesh.triangle_count() + foliage.mesh.triangle_count() * foliage.count() + 2 * (cloud.len() / QUAD_FLOATS)
}

impl LodLevel {
    /// Triangles drawn for this level (bark + every leaf instance + 2 per cloud quad).
    pub fn triangles(&self) -> usize {
        count_triangles(&self.mesh, &self.foliage, &self.cloud)
    }

    /// Number of cloud quads.
    pub fn quads(&self) -> usize {
        self.cloud.len() / QUAD_FLOATS
    }
}

/// A generated tree with its reduced levels.
#[derive(Clone, Debug)]
pub struct TreeLods {
    /// LOD0: the generated tree (also the source of the other levels' skeleton).
    pub lod0: Generated,
    /// Fewer rings, sides and leaves.
    pub lod1: LodLevel,
    /// Trunk and main branches with a billboard cloud.
    pub lod2: LodLevel,
}

/// A borrowed view of one level's buffers.
#[derive(Clone, Copy, Debug)]
pub struct LevelRef<'a> {
    /// Bark tubes.
    pub mesh: &'a TreeMesh,
    /// Leaves.
    pub foliage: &'a Foliage,
    /// Cloud quads.
    pub cloud: &'a [f32],
    /// Stems swept.
    pub stems: usize,
}

impl LevelRef<'_> {
    /// Triangles drawn for this level.
    pub fn triangles(&self) -> usize {
        count_triangles(self.mesh, self.foliage, self.cloud)
    }
}

impl TreeLods {
    /// Level `i` (0, 1 or 2; larger values give LOD2).
    pub fn level(&self, i: usize) -> LevelRef<'_> {
        match i {
            0 => LevelRef {
                mesh: &self.lod0.mesh,
                foliage: &self.lod0.foliage,
                cloud: &[],
                stems: self.lod0.skeleton.stems.len(),
            },
            1 => LevelRef {
                mesh: &self.lod1.mesh,
                foliage: &self.lod1.foliage,
                cloud: &self.lod1.cloud,
                stems: self.lod1.stems,
            },
            _ => LevelRef {
                mesh: &self.lod2.mesh,
                foliage: &self.lod2.foliage,
                cloud: &self.lod2.cloud,
                stems: self.lod2.stems,
            },
        }
    }

    /// Triangles per level, LOD0 to LOD2.
    pub fn triangles(&self) -> [usize; 3] {
        [self.level(0).triangles(), self.level(1).triangles(), self.level(2).triangles()]
    }

    /// Counts per level as JSON (what `GeneratedLods.meta_json()` returns in wasm).
    pub fn meta_json(&self) -> String {
        crate::meta::to_json(&self.meta())
    }

    /// The hash, bounds and leaf facts of LOD0 and the counts of every level.
    pub fn meta(&self) -> LodMeta {
        let levels = (0..3)
            .map(|i| {
                let l = self.level(i);
                LodLevelMeta {
                    triangles: l.triangles(),
                    vertices: l.mesh.vertex_count(),
                    bark_triangles: l.mesh.triangle_count(),
                    leaves: l.foliage.count(),
                    leaf_triangles: l.foliage.mesh.triangle_count(),
                    quads: l.cloud.len() / QUAD_FLOATS,
                    stems: l.stems,
                    groups: l.mesh.groups.clone(),
                }
            })
            .collect();
        let g = &self.lod0;
        LodMeta {
            hash: g.hash_hex(),
            bounds: g.bounds,
            levels,
            leaf_hash: format!("{:016x}", g.foliage.leaf_hash()),
            leaf_texture: g.foliage.texture().map(|t| [t.width, t.height]),
        }
    }
}

/// Generates a tree and its reduced levels (see the module docs).
pub fn generate_lods(params: &TreeParams) -> Result<TreeLods, SylvaError> {
    let lod0 = crate::generate(params)?;
    lods_of(lod0, &params.mesh)
}

/// The reduced levels of an already generated tree (`lod0` must come from parameters whose
/// mesh parameters are `params`).
pub fn lods_of(lod0: Generated, params: &MeshParams) -> Result<TreeLods, SylvaError> {
    let mut lod1 = build_lod1(&lod0.skeleton, &lod0.foliage, params)?;
    let mut lod2 = build_lod2(&lod0.skeleton, &lod0.foliage, params)?;
    // The reduced barks sit in LOD0's crown: the same leaves shade them (no holes are cut).
    let light = CrownLight::from_leaves(&lod0.foliage.matrices);
    for level in [&mut lod1, &mut lod2] {
        level.mesh.shade = occlusion_with(&level.mesh, &[], light.as_ref(), params.hole_size);
    }
    Ok(TreeLods { lod0, lod1, lod2 })
}

/// `params` with Mesh Quality scaled by `factor` (not re-validated: the sweep only needs q > 0).
fn with_quality(params: &MeshParams, factor: f32) -> MeshParams {
    let mut p = params.clone();
    p.mesh_quality = params.mesh_quality * factor;
    p
}

/// LOD1: the whole skeleton at a lower quality, fewer but larger leaves.
pub fn build_lod1(skeleton: &Skeleton, foliage: &Foliage, params: &MeshParams) -> Result<LodLevel, SylvaError> {
    let mesh = tube::build(skeleton, &with_quality(params, LOD1_QUALITY))?;
    Ok(LodLevel {
        mesh,
        foliage: thin_leaves(foliage, LOD1_LEAF_STRIDE),
        cloud: Vec::new(),
        stems: skeleton.stems.len(),
    })
}

/// LOD2: trunk and level-1 stems at a low quality; leaves as a billboard cloud.
pub fn build_lod2(skeleton: &Skeleton, foliage: &Foliage, params: &MeshParams) -> Result<LodLevel, SylvaError> {
    let main = main_stems(skeleton);
    let mesh = tube::build(&main, &with_quality(params, LOD2_QUALITY))?;
    Ok(LodLevel { mesh, foliage: Foliage::bare(), cloud: billboard_cloud(foliage), stems: main.stems.len() })
}

/// The trunk and the level-1 stems (parents remapped to the kept stems).
pub fn main_stems(skeleton: &Skeleton) -> Skeleton {
    let mut map = vec![u32::MAX; skeleton.stems.len()];
    let mut stems = Vec::new();
    for (i, s) in skeleton.stems.iter().enumerate() {
        if s.level > 1 {
            continue;
        }
        let parent = s.parent.map(|p| map[p as usize]);
        if parent == Some(u32::MAX) {
            continue; // a level-1 stem whose parent was dropped (not produced by the generators)
        }
        map[i] = stems.len() as u32;
        let mut kept = s.clone();
        kept.parent = parent;
        stems.push(kept);
    }
    let Skeleton { mode, scale, crown_base, seed, levels, max_vertices, age, maturity, .. } = *skeleton;
    Skeleton { mode, stems, scale, crown_base, seed, levels, max_vertices, age, maturity, life: None }
}

/// The leaf mesh one step lighter than `mesh`: blade → billboard cloud → card.
fn lighter_leaf_mesh(foliage: &Foliage) -> TreeMesh {
    let Some(leaf) = foliage.leaf.as_deref() else { return foliage.mesh.clone() };
    let n = foliage.mesh.triangle_count();
    if n > leaf.lod.billboards.triangle_count() {
        leaf.lod.billboards.clone()
    } else if n > leaf.lod.card.triangle_count() {
        leaf.lod.card.clone()
    } else {
        foliage.mesh.clone()
    }
}

/// Keeps every `stride`-th leaf (the first always), scaled by `√(leaves / kept)` about its base so
/// the covered area stays the same, with the next lighter leaf mesh.
pub fn thin_leaves(foliage: &Foliage, stride: usize) -> Foliage {
    let n = foliage.count();
    let stride = stride.max(1);
    let kept = n.div_ceil(stride);
    if n == 0 {
        return foliage.clone();
    }
    let s = (n as f32 / kept as f32).sqrt();
    let mut matrices = Vec::with_capacity(kept * 16);
    let mut colors = Vec::with_capacity(kept * 3);
    let mut fallen = 0;
    for i in (0..n).step_by(stride) {
        let m = &foliage.matrices[i * 16..i * 16 + 16];
        matrices.extend(m[..12].iter().map(|v| v * s));
        matrices.extend_from_slice(&m[12..16]);
        colors.extend_from_slice(&foliage.colors[i * 3..i * 3 + 3]);
        fallen += usize::from(i >= foliage.on_tree());
    }
    let organs = foliage.organs.clone();
    Foliage { mesh: lighter_leaf_mesh(foliage), matrices, colors, leaf: foliage.leaf.clone(), fallen, organs }
}

/// Area of the leaf box (leaf units `x` × `y` mapped to metres) summed over the leaves: the
/// covered area up to the leaf shape's fill factor, which every level shares.
pub fn leaf_box_area(foliage: &Foliage) -> f32 {
    foliage
        .matrices
        .chunks_exact(16)
        .map(|m| Vec3::new(m[0], m[1], m[2]).cross(Vec3::new(m[4], m[5], m[6])).length())
        .sum()
}

/// Number of cloud clusters for `n` leaves.
pub fn cluster_count(n: usize) -> usize {
    if n == 0 {
        return 0;
    }
    ((n as f32 / 4.0).sqrt().round() as usize).clamp(1, CLOUD_CLUSTERS_MAX).min(n)
}

/// The leaves' billboard cloud: [`QUADS_PER_CLUSTER`] quads per leaf cluster.
pub fn billboard_cloud(foliage: &Foliage) -> Vec<f32> {
    let n = foliage.count();
    let k = cluster_count(n);
    if k == 0 {
        return Vec::new();
    }
    let pos: Vec<Vec3> = foliage.matrices.chunks_exact(16).map(|m| Vec3::new(m[12], m[13], m[14])).collect();
    let len: Vec<f32> = foliage.matrices.chunks_exact(16).map(|m| Vec3::new(m[4], m[5], m[6]).length()).collect();
    let area: Vec<f32> = foliage
        .matrices
        .chunks_exact(16)
        .map(|m| Vec3::new(m[0], m[1], m[2]).cross(Vec3::new(m[4], m[5], m[6])).length())
        .collect();
    // Deterministic k-means: centres start on leaves spread evenly through the (stem-ordered) list.
    let mut centres: Vec<Vec3> = (0..k).map(|j| pos[(j * n + n / 2) / k]).collect();
    let mut owner = vec![0usize; n];
    for _ in 0..KMEANS_ITERATIONS {
        for (i, p) in pos.iter().enumerate() {
            let mut best = (f32::INFINITY, 0usize);
            for (j, c) in centres.iter().enumerate() {
                let d = (*p - *c).length_squared();
                if d < best.0 {
                    best = (d, j);
                }
            }
            owner[i] = best.1;
        }
        let mut sum = vec![Vec3::ZERO; k];
        let mut count = vec![0usize; k];
        for (i, p) in pos.iter().enumerate() {
            sum[owner[i]] += *p;
            count[owner[i]] += 1;
        }
        for j in 0..k {
            if count[j] > 0 {
                centres[j] = sum[j] / count[j] as f32;
            }
        }
    }
    let mut out = Vec::with_capacity(k * QUADS_PER_CLUSTER * QUAD_FLOATS);
    for (j, centre) in centres.iter().enumerate() {
        let members: Vec<usize> = (0..n).filter(|&i| owner[i] == j).collect();
        if members.is_empty() {
            continue;
        }
        let m = members.len() as f32;
        let leaf = members.iter().map(|&i| len[i]).sum::<f32>() / m;
        let mut cov = [[0.0f32; 3]; 3];
        let mut tint = Vec3::ZERO;
        for &i in &members {
            let d = (pos[i] - *centre).to_array();
            for (r, row) in cov.iter_mut().enumerate() {
                for (c, v) in row.iter_mut().enumerate() {
                    *v += d[r] * d[c] / m;
                }
            }
            tint += Vec3::from_slice(&foliage.colors[i * 3..i * 3 + 3]);
        }
        tint /= m;
        let (axes, _) = eigen_symmetric(cov);
        // Half-extent along each principal axis: the farthest member (capped at 2.2 σ against
        // stray leaves) plus half a leaf.
        let half: Vec<f32> = axes
            .iter()
            .map(|a| {
                let (mut far, mut var) = (0.0f32, 0.0f32);
                for &i in &members {
                    let p = (pos[i] - *centre).dot(*a);
                    far = far.max(p.abs());
                    var += p * p / m;
                }
                far.min(2.2 * var.sqrt()) + 0.5 * leaf
            })
            .collect();
        let covered: f32 = members.iter().map(|&i| area[i]).sum();
        let density = (covered / (4.0 * half[0] * half[1])).clamp(0.05, 1.0);
        for (a, b) in [(0usize, 1usize), (0, 2), (1, 2)] {
            let u = axes[a] * half[a];
            let v = axes[b] * half[b];
            out.extend_from_slice(&[
                centre.x, centre.y, centre.z, u.x, u.y, u.z, v.x, v.y, v.z, tint.x, tint.y, tint.z, density,
            ]);
        }
    }
    out
}

/// Eigenvectors (unit, by decreasing eigenvalue) and eigenvalues of a symmetric 3×3 matrix:
/// cyclic Jacobi rotations (only `+ - * / sqrt`, so portable bit for bit).
pub fn eigen_symmetric(m: [[f32; 3]; 3]) -> ([Vec3; 3], [f32; 3]) {
    let mut a = m;
    let mut v = [[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..12 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if off <= 1e-20 {
            break;
        }
        for (p, q) in [(0usize, 1usize), (0, 2), (1, 2)] {
            if a[p][q].abs() <= 1e-30 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            // A ← Jᵀ A J with the rotation J in the (p, q) plane.
            for row in &mut a {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (rp, rq) = (a[p], a[q]);
            a[p] = std::array::from_fn(|k| c * rp[k] - s * rq[k]);
            a[q] = std::array::from_fn(|k| s * rp[k] + c * rq[k]);
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let mut order = [0usize, 1, 2];
    order.sort_by(|&x, &y| a[y][y].total_cmp(&a[x][x]));
    let col = |j: usize| crate::math::unit_or(Vec3::new(v[0][j], v[1][j], v[2][j]), || Vec3::X);
    let vals = [a[order[0]][order[0]], a[order[1]][order[1]], a[order[2]][order[2]]];
    // A right-handed frame: the third axis is the cross product of the first two.
    let e0 = col(order[0]);
    let e1 = crate::math::unit_or(col(order[1]) - e0 * e0.dot(col(order[1])), || e0.any_orthonormal_vector());
    ([e0, e1, e0.cross(e1)], vals)
}
