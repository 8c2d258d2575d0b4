//! Mesh buffers: the one geometry type that leaves the core. The wasm payload, the OBJ (and
//! later GLB) exporters and the tests all read [`TreeMesh`]; the stages write into it through
//! [`MeshBuilder`] (lyon's `GeometryBuilder` idea), so there is one layout to document and check.

pub mod bark;
mod bounds;
mod builder;
pub mod cut_face;
pub mod fork;
pub mod fork_rows;
pub mod holes;
mod junction;
mod layout;
pub mod pick;
pub mod shade;
mod stem;
pub mod topology;
pub mod trunk;
pub mod tube;
pub mod twig;
pub mod weld;

pub use bounds::Bounds;
pub(crate) use bounds::{merge_ranges, ranges};

use serde::Serialize;

pub use builder::{seam_shifts, MeshBuilder, Tail, VertexBlock, VertexSink};

/// Which material a range of indices uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Material {
    /// Stems: trunk, branches, twigs.
    Bark,
    /// Leaf blades.
    Leaves,
    /// The end grain of a cut stem's face ([`cut_face`]), inside its bark rim.
    #[serde(rename = "cut_face")]
    CutFace,
    /// A flower, fruit, catkin or bud ([`crate::organs`]): each set has its own colour.
    Organ,
}

impl Material {
    /// The material's name in exports (OBJ groups and materials, glTF materials).
    pub fn name(self) -> &'static str {
        match self {
            Material::Bark => "bark",
            Material::Leaves => "leaves",
            Material::CutFace => "cut_face",
            Material::Organ => "organ",
        }
    }
}

/// A contiguous range of `indices` drawn with one material.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MeshGroup {
    /// Material of the range.
    pub material: Material,
    /// First index (an offset into `indices`, a multiple of 3).
    pub start: u32,
    /// Number of indices (a multiple of 3).
    pub count: u32,
}

/// A generated tree as flat, typed buffers. Coordinates: metres, **Y up**, the tree's base at
/// the origin. Vertex `i` is made of:
///
/// | buffer      | type | per vertex | layout                                                    |
/// |-------------|------|-----------:|-----------------------------------------------------------|
/// | `positions` | f32  | 3          | `x, y, z` (finite)                                         |
/// | `normals`   | f32  | 3          | `nx, ny, nz`, unit length, pointing out of the surface     |
/// | `uvs`       | f32  | 2          | bark: `u` = around the stem 0..1 (seam duplicated at u = 1), `v` = along the stem, continuous, 1 unit per circumference |
///
/// | `wind`      | f32  | 8 (or none)| `pivot_x, pivot_y, pivot_z, level, phase, stiffness, distance, radius` (see below) |
///
/// `wind` is either empty or holds 8 floats per vertex for wind animation and exporters:
/// `pivot` = base point of the stem the vertex belongs to (m), `level` = branch level (0 trunk,
/// 1, 2, 3 as a float), `phase` = 0..1, one random value per stem (stream `"wind"`), `stiffness` =
/// 0..1 (1 = rigid trunk base, toward 0 on thin twigs; from the local radius relative to the trunk
/// base radius), `distance` = path length from the root to the vertex's ring along the stems (m),
/// `radius` = local stem radius at the ring (m).
///
/// `indices` (u32) hold triangles, three per triangle, counter-clockwise seen from outside;
/// `groups` split them by material. 32-bit indices: trees pass 65,535 vertices easily.
///
/// `rings` lists the tube rings among the vertices (see [`TreeMesh::rings`]): structure the
/// exporters use, derived from the same construction; it is not part of [`TreeMesh::content_hash`]
/// nor of the buffers handed to JavaScript.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TreeMesh {
    /// `x, y, z` per vertex.
    pub positions: Vec<f32>,
    /// Unit normal per vertex.
    pub normals: Vec<f32>,
    /// `u, v` per vertex.
    pub uvs: Vec<f32>,
    /// Triangle list.
    pub indices: Vec<u32>,
    /// Index ranges per material.
    pub groups: Vec<MeshGroup>,
    /// Wind data, 8 floats per vertex (layout above), or empty.
    pub wind: Vec<f32>,
    /// Tube rings, `[first vertex, vertex count]` each, sorted and disjoint: a ring is a run of
    /// `sides + 1` consecutive vertices around a swept stem (tube or twig), `u` = `j / sides`
    /// increasing along the run (counter-clockwise about the stem's direction, so
    /// `cross(normal, direction of increasing u)` points along the stem) and `v` the same for
    /// the whole ring, increasing from ring to ring; the last vertex is the seam twin of the
    /// first (the same position, `u = 1`). Every listed vertex still sits where the sweep put
    /// it (rings a later stage rewrites, as holes do, are dropped). Meshes built otherwise may
    /// leave it empty, and code that edits the positions or uvs of a generated mesh should
    /// clear it: it only lets the GLB writer take a ring vertex's tangent from its ring
    /// neighbours instead of accumulating it over triangles.
    pub rings: Vec<[u32; 2]>,
    /// Bark occlusion, one byte per vertex (0 = no light, 255 = open sky; [`shade`]), or empty.
    /// Viewers multiply the bark colour by it; part of [`TreeMesh::content_hash`].
    pub shade: Vec<u8>,
}

/// Floats per vertex in [`TreeMesh::wind`].
pub const WIND_STRIDE: usize = 8;
/// Index of `stiffness` in a wind record ([`TreeMesh::wind`]): the pivot, level and phase come
/// before it, the values that vary along a stem from it on.
pub const WIND_STIFFNESS: usize = 5;
/// Index of `distance` (path length from the root) in a wind record ([`TreeMesh::wind`]).
pub const WIND_DISTANCE: usize = 6;
/// Index of `radius` (the local stem radius) in a wind record ([`TreeMesh::wind`]).
pub const WIND_RADIUS: usize = 7;

impl TreeMesh {
    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len() / 3
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Bounds of all positions (zero box for an empty mesh).
    pub fn bounds(&self) -> Bounds {
        Bounds::of(&self.positions)
    }

    /// Content hash of every buffer (positions, normals, uvs, indices, wind, groups): equal hashes
    /// mean byte-identical meshes. Four interleaved 64-bit FNV-1a-style lanes over pairs of
    /// 32-bit words, then mixed; the value is part of the golden tests, so change it only on purpose.
    pub fn content_hash(&self) -> u64 {
        let mut h = Hasher::new();
        h.words(&self.positions, f32::to_bits);
        h.words(&self.normals, f32::to_bits);
        h.words(&self.uvs, f32::to_bits);
        h.words(&self.indices, |i| i);
        if !self.wind.is_empty() {
            h.words(&self.wind, f32::to_bits);
        }
        if !self.shade.is_empty() {
            h.words(&self.shade, u32::from);
        }
        for g in &self.groups {
            h.words(&[g.material as u32, g.start, g.count], |w| w);
        }
        h.finish()
    }

    /// The mesh as Wavefront OBJ text (positions, uvs, normals, one `g` per group).
    pub fn to_obj(&self) -> String {
        use std::fmt::Write;
        let mut s = String::with_capacity(self.positions.len() * 40);
        s.push_str("# Sylva tree\n");
        for p in self.positions.chunks_exact(3) {
            let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
        }
        for t in self.uvs.chunks_exact(2) {
            let _ = writeln!(s, "vt {} {}", t[0], t[1]);
        }
        for n in self.normals.chunks_exact(3) {
            let _ = writeln!(s, "vn {} {} {}", n[0], n[1], n[2]);
        }
        for g in &self.groups {
            let _ = writeln!(s, "g {}", g.material.name());
            let range = g.start as usize..(g.start + g.count) as usize;
            for t in self.indices[range].chunks_exact(3) {
                let (a, b, c) = (t[0] + 1, t[1] + 1, t[2] + 1);
                let _ = writeln!(s, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}");
            }
        }
        s
    }
}

struct Hasher {
    lanes: [u64; 4],
    n: u64,
}

const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

impl Hasher {
    fn new() -> Self {
        Hasher {
            lanes: [0xcbf2_9ce4_8422_2325, 0x8422_2325_cbf2_9ce4, 0x9e37_79b9_7f4a_7c15, 0x2545_f491_4f6c_dd1d],
            n: 0,
        }
    }

    /// Hash one buffer: each lane takes two 32-bit words per step as one 64-bit word (eight
    /// words per round over four independent multiply chains, so the CPU overlaps them); the
    /// tail goes one word per lane. Every step is a bijection of the lane state, so any change to
    /// any word changes the result.
    fn words<T: Copy>(&mut self, data: &[T], bits: impl Fn(T) -> u32) {
        let pair = |lo: T, hi: T| u64::from(bits(lo)) | u64::from(bits(hi)) << 32;
        let [mut a, mut b, mut c, mut d] = self.lanes;
        let mut chunks = data.chunks_exact(8);
        for q in &mut chunks {
            a = (a ^ pair(q[0], q[1])).wrapping_mul(FNV_PRIME);
            b = (b ^ pair(q[2], q[3])).wrapping_mul(FNV_PRIME);
            c = (c ^ pair(q[4], q[5])).wrapping_mul(FNV_PRIME);
            d = (d ^ pair(q[6], q[7])).wrapping_mul(FNV_PRIME);
        }
        self.lanes = [a, b, c, d];
        for (k, &w) in chunks.remainder().iter().enumerate() {
            let lane = &mut self.lanes[k & 3];
            *lane = (*lane ^ u64::from(bits(w))).wrapping_mul(FNV_PRIME);
        }
        self.n += data.len() as u64;
    }

    fn finish(&self) -> u64 {
        let mut h = self.n;
        for l in self.lanes {
            h = (h ^ l).wrapping_mul(0xff51_afd7_ed55_8ccd);
            h ^= h >> 33;
        }
        h
    }
}
