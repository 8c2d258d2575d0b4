//! # Leaves
//!
//! A single leaf from parameters, in the order of Mtree's *Leaf Generation Guide* (its sections
//! are cited below as "Leaf Generation guide §N"):
//!
//! ```text
//! outline → margin → triangulation → UVs → veins → deformation (+ vein field) → texture → LOD
//! ```
//!
//! | stage | module | reference |
//! |---|---|---|
//! | outline | [`outline`] | superformula (Gielis 2003) or mirrored cubic spline, adaptive sampling |
//! | margin | [`margin`] | `r (1 + depth · wave(f))` (Leaf Generation guide §2) |
//! | lobed outlines | [`lobes`] | pinnate lobes along the midrib, palmate lobes (Ellis et al. 2009, `docs/leaves.md`) |
//! | needles, petiole | [`needles`] | pine fascicles, the leaf stalk (`docs/leaves.md`) |
//! | conifer shoots | [`shoot`] | many needles on a twig, baked into one texture (`docs/leaves.md`) |
//! | triangulation | [`triangulate`] | concentric rings + fan; ear clipping + constrained Delaunay fallback |
//! | UVs | [`uv`] | planar over the blade's box |
//! | veins | [`veins`] | primary veins (pinnate, palmate, dichotomous), then space colonization (Runions 2005), open / closed; spline veins |
//! | deformation | [`deform`], [`field`] | midrib / cross curvature, edge curl, vein ridges |
//! | texture | [`texture`] | vein colour + normal maps, RGBA8, powers of two |
//! | LOD | [`lod`] | card, billboard cloud, hemi-octahedral impostor views |
//!
//! **The leaf frame** (every stage): leaf units, the base-to-tip distance is 1. The petiole
//! attaches at the origin, the midrib runs up `+y` to the tip at `(0, 1)`, `+x` is the right
//! half seen from the front, and the front face looks along `+z` (triangles are
//! counter-clockwise seen from `+z`). Basal lobes may reach below `y = 0`. Deformation moves
//! vertices along `z` only.
//!
//! Every parameter is in the registry (groups "Leaf", "Leaf Veins", "Leaf Surface"); the tree's
//! foliage instances this leaf (see [`crate::foliage`]). The species presets and their
//! references are described in `docs/leaves.md`. Randomness comes from the named streams `"leaf-margin"`,
//! `"leaf-veins"` and `"leaf-spline-veins"`; all transcendental math goes through `libm`, so
//! native and wasm leaves are byte-identical ([`Leaf::hash`]).

pub mod deform;
pub mod field;
pub mod geom;
pub mod json;
pub mod lobes;
pub mod lod;
pub mod margin;
pub mod needles;
pub mod outline;
pub mod presets;
pub mod raster;
pub mod shoot;
pub mod svg;
pub mod texture;
pub mod triangulate;
pub mod uv;
pub mod veins;

use crate::clock::{self, Clock};
use crate::error::SylvaError;
use crate::mesh::{Material, MeshBuilder, TreeMesh};
use crate::params::LeafParams;
pub use margin::Outline;
pub use triangulate::Triangulation;
pub use veins::{Auxin, VeinGraph, Veins};

/// Cells along the longer side of the blade mask the veins grow in.
const MASK_RESOLUTION: usize = 256;

/// Timings of one leaf.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LeafStats {
    /// Milliseconds per stage, in pipeline order (`outline`, `margin`, `triangulation`, `uvs`,
    /// `veins`, `deformation`, `texture`, `lod`, `hash`).
    pub stage_ms: Vec<(&'static str, f64)>,
    /// Milliseconds for the whole leaf.
    pub total_ms: f64,
}

/// A generated leaf.
#[derive(Clone, Debug)]
pub struct Leaf {
    /// The final outline (with its margin).
    pub outline: Outline,
    /// The blade's triangulation in the leaf plane.
    pub triangulation: Triangulation,
    /// The box the UVs and the textures span.
    pub uv_frame: uv::UvFrame,
    /// Veins and auxin sources.
    pub veins: Veins,
    /// LOD0: the deformed blade (one `leaves` group; UVs planar, see [`uv`]).
    pub mesh: TreeMesh,
    /// The baked vein textures.
    pub texture: texture::LeafTexture,
    /// Card, billboard cloud and impostor views.
    pub lod: lod::LeafLod,
    /// Petiole length below the blade's base (leaf units; 0 = none), drawn in the mesh.
    pub petiole: f32,
    /// A conifer shoot's needle outlines projected onto the leaf plane (empty for one blade;
    /// see [`shoot`]): then `mesh`, `texture` and `uv_frame` are the shoot's.
    pub shoot: Vec<Vec<glam::Vec2>>,
    /// Timings.
    pub stats: LeafStats,
    /// Content hash of everything above but the timings.
    pub hash: u64,
}

impl Leaf {
    /// The hash as 16 hex digits.
    pub fn hash_hex(&self) -> String {
        format!("{:016x}", self.hash)
    }
}

/// Checks the leaf parameters and the petiole's length (Petiole Length, `leaf_petiole`),
/// including the leaf rules the registry ranges cannot express.
pub fn validate(p: &LeafParams, petiole: f32) -> Result<(), SylvaError> {
    p.validate()?;
    crate::params::spec("leaf_petiole").expect("a registry parameter").check(f64::from(petiole))?;
    if p.leaf_kill >= p.leaf_attraction {
        return Err(SylvaError::InvalidParam {
            param: "leaf_attraction".into(),
            message: format!(
                "leaf_attraction (Attraction Distance) is {}: it must be larger than leaf_kill (Kill Distance, {})",
                p.leaf_attraction, p.leaf_kill
            ),
        });
    }
    Ok(())
}

/// Generates the leaf described by the leaf parameters, its petiole `petiole` leaf lengths long
/// (Petiole Length, a foliage parameter: the placements hang the blade that far from its stem).
pub fn generate(p: &LeafParams, petiole: f32) -> Result<Leaf, SylvaError> {
    generate_with_clock(p, petiole, clock::default_clock().as_ref())
}

/// [`generate`] with an explicit clock for the stage timings.
pub fn generate_with_clock(p: &LeafParams, petiole: f32, clock: &dyn Clock) -> Result<Leaf, SylvaError> {
    validate(p, petiole)?;
    let mut stage_ms = Vec::with_capacity(9);
    let t_start = clock.now_ms();
    let mut t = t_start;
    let mut lap = |name: &'static str, stage_ms: &mut Vec<(&'static str, f64)>| {
        let now = clock.now_ms();
        stage_ms.push((name, now - t));
        t = now;
    };
    let base = outline::build(p);
    lap("outline", &mut stage_ms);
    let outline = margin::build(p, &base)?;
    lap("margin", &mut stage_ms);
    let triangulation = triangulate::build(&outline, p.leaf_rings);
    lap("triangulation", &mut stage_ms);
    let uv_frame = uv::UvFrame::of(&outline.points);
    let uvs = uv::build(&uv_frame, &triangulation.vertices);
    lap("uvs", &mut stage_ms);
    let mask = raster::Mask::new(&outline.points, MASK_RESOLUTION);
    let veins = veins::build(p, &outline, &mask);
    lap("veins", &mut stage_ms);
    let (tw, th) = texture::size(p.leaf_texture_level, &uv_frame);
    let field = field::build(&veins.graph, &uv_frame, tw, th);
    let rings = (triangulation.method == triangulate::Method::Rings).then_some(p.leaf_rings);
    let edge = deform::edge_weights(&triangulation.vertices, &outline.points, rings);
    let positions = deform::displace(p, &triangulation.vertices, &outline.points, &edge, &field);
    let surface = if p.leaf_fascicle > 1 {
        needles::fascicle(p, &uv_frame)
    } else {
        let normals = deform::normals(&positions, &triangulation.triangles);
        needles::Surface { positions, normals, uvs, triangles: triangulation.triangles.clone() }
    };
    // A conifer shoot: the needle above, many times along a twig, in the shoot's own box.
    let shoot = (p.leaf_shoot > 0).then(|| {
        let placed = shoot::placements(p);
        let outlines = shoot::projected(&placed, &outline.points, p.leaf_fascicle);
        let frame = shoot::frame(&outlines, petiole);
        (placed, outlines, frame)
    });
    let (surface, uv_frame) = match &shoot {
        Some((placed, _, frame)) => (shoot::surface(placed, &surface, frame), *frame),
        None => (surface, uv_frame),
    };
    let mut b = MeshBuilder::with_capacity(surface.positions.len() + 4, surface.triangles.len() * 3 + 6);
    b.begin_group(Material::Leaves);
    for ((q, n), uv) in surface.positions.iter().zip(&surface.normals).zip(&surface.uvs) {
        b.vertex(q.to_array(), n.to_array(), uv.to_array());
    }
    for tri in &surface.triangles {
        b.triangle(tri[0], tri[1], tri[2]);
    }
    needles::petiole(p, petiole, &uv_frame, &mut b);
    let mesh = b.finish();
    let positions = surface.positions;
    lap("deformation", &mut stage_ms);
    let texture = match &shoot {
        Some((placed, outlines, frame)) => {
            shoot::bake(placed, outlines, p.leaf_fascicle, petiole, frame, p.leaf_texture_level)
        }
        None => texture::bake(&field, &outline.points, p.leaf_vein_displacement),
    };
    lap("texture", &mut stage_ms);
    let lod = lod::build(&uv_frame, &positions, p.leaf_impostor_grid);
    lap("lod", &mut stage_ms);
    let mut leaf = Leaf {
        outline,
        triangulation,
        uv_frame,
        veins,
        mesh,
        texture,
        lod,
        petiole,
        shoot: shoot.map(|(_, outlines, _)| outlines).unwrap_or_default(),
        stats: LeafStats::default(),
        hash: 0,
    };
    leaf.hash = content_hash(&leaf);
    lap("hash", &mut stage_ms);
    leaf.stats = LeafStats { total_ms: t - t_start, stage_ms };
    Ok(leaf)
}

/// FNV-1a (64-bit) over 32-bit words.
struct Fnv(u64);

impl Fnv {
    fn word(&mut self, w: u32) {
        self.0 = (self.0 ^ u64::from(w)).wrapping_mul(0x0000_0100_0000_01b3);
    }
    fn f(&mut self, v: f32) {
        self.word(v.to_bits());
    }
    fn bytes(&mut self, b: &[u8]) {
        let mut chunks = b.chunks_exact(4);
        for c in &mut chunks {
            self.word(u32::from_le_bytes([c[0], c[1], c[2], c[3]]));
        }
        for &r in chunks.remainder() {
            self.word(u32::from(r));
        }
    }
    fn u64(&mut self, v: u64) {
        self.word(v as u32);
        self.word((v >> 32) as u32);
    }
}

/// Hash of the outline, triangulation, veins, auxins, meshes and textures.
fn content_hash(l: &Leaf) -> u64 {
    let mut h = Fnv(0xcbf2_9ce4_8422_2325);
    for p in &l.outline.points {
        h.f(p.x);
        h.f(p.y);
    }
    for t in &l.triangulation.triangles {
        t.iter().for_each(|&i| h.word(i));
    }
    for n in &l.veins.graph.nodes {
        h.f(n.pos.x);
        h.f(n.pos.y);
        h.word(n.parent);
        h.word(n.born);
        h.f(n.width);
    }
    for k in &l.veins.graph.links {
        h.word(k.a);
        h.word(k.b);
        h.word(k.born);
    }
    for a in &l.veins.auxins {
        h.f(a.pos.x);
        h.f(a.pos.y);
        h.word(a.killed_at);
    }
    h.u64(l.mesh.content_hash());
    h.u64(l.lod.card.content_hash());
    h.u64(l.lod.billboards.content_hash());
    for v in &l.lod.impostor_views {
        v.iter().for_each(|&c| h.f(c));
    }
    h.word(l.texture.width);
    h.word(l.texture.height);
    h.bytes(&l.texture.color);
    h.bytes(&l.texture.normal);
    h.0
}
