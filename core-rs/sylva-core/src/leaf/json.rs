//! The leaf as one JSON object: what `sylva leaf` prints and `leaf_json()` returns in wasm.
//! Serialised straight from borrowed data (no intermediate JSON tree), so it stays cheap for
//! 5,000 sources and thousands of vein nodes.
//!
//! ```text
//! { hash, frame, outline: [[x, y]], base_index, base_outline: [[x, y]],
//!   triangulation: {method, vertices: [[x, y]], triangles: [[a, b, c]]},
//!   auxins: [[x, y, killed_at | null]]            (the first is the apex source at the tip)
//!   veins: {nodes: [{x, y, parent | null, born, width, tips}], links: [[a, b, born]],
//!           edges: [[a, b, born, width]]}        (tree edges child→parent, then links)
//!   loops, iterations, fallback,
//!   mesh: {vertices, triangles, hash}, texture: {width, height, layout},
//!   lod: {card_triangles, billboard_quads, impostor_views: [[x, y, z]]},
//!   ms: {stage: ms}, total_ms }
//! ```

use crate::leaf::triangulate::Method;
use crate::leaf::veins::NONE;
use crate::leaf::Leaf;
use serde::Serialize;
use std::collections::BTreeMap;

fn opt(v: u32) -> Option<u32> {
    (v != NONE).then_some(v)
}

fn xy(v: &[glam::Vec2]) -> Vec<[f32; 2]> {
    v.iter().map(|p| [p.x, p.y]).collect()
}

#[derive(Serialize)]
struct Frame {
    units: &'static str,
    base: [f32; 2],
    tip: [f32; 2],
    front: &'static str,
}

#[derive(Serialize)]
struct Tri<'a> {
    method: Method,
    vertices: Vec<[f32; 2]>,
    triangles: &'a [[u32; 3]],
}

#[derive(Serialize)]
struct Node {
    x: f32,
    y: f32,
    parent: Option<u32>,
    born: u32,
    width: f32,
    tips: u32,
}

#[derive(Serialize)]
struct VeinsOut {
    nodes: Vec<Node>,
    links: Vec<[u32; 3]>,
    edges: Vec<(u32, u32, u32, f32)>,
}

#[derive(Serialize)]
struct MeshOut {
    vertices: usize,
    triangles: usize,
    hash: String,
}

#[derive(Serialize)]
struct TextureOut {
    width: u32,
    height: u32,
    layout: &'static str,
}

#[derive(Serialize)]
struct LodOut<'a> {
    card_triangles: usize,
    billboard_quads: usize,
    impostor_views: &'a [[f32; 3]],
}

#[derive(Serialize)]
struct LeafOut<'a> {
    hash: String,
    frame: Frame,
    outline: Vec<[f32; 2]>,
    base_index: usize,
    base_outline: Vec<[f32; 2]>,
    triangulation: Tri<'a>,
    auxins: Vec<(f32, f32, Option<u32>)>,
    veins: VeinsOut,
    loops: usize,
    iterations: u32,
    fallback: bool,
    mesh: MeshOut,
    texture: TextureOut,
    lod: LodOut<'a>,
    ms: BTreeMap<&'static str, f64>,
    total_ms: f64,
}

/// The leaf as a JSON string.
pub fn to_json(l: &Leaf) -> String {
    let g = &l.veins.graph;
    let out = LeafOut {
        hash: l.hash_hex(),
        frame: Frame { units: "leaf length (base to tip = 1)", base: [0.0, 0.0], tip: [0.0, 1.0], front: "+z" },
        outline: xy(&l.outline.points),
        base_index: l.outline.base_index,
        base_outline: xy(&l.outline.base_outline),
        triangulation: Tri {
            method: l.triangulation.method,
            vertices: xy(&l.triangulation.vertices),
            triangles: &l.triangulation.triangles,
        },
        auxins: l.veins.auxins.iter().map(|a| (a.pos.x, a.pos.y, opt(a.killed_at))).collect(),
        veins: VeinsOut {
            nodes: g
                .nodes
                .iter()
                .map(|n| Node {
                    x: n.pos.x,
                    y: n.pos.y,
                    parent: opt(n.parent),
                    born: n.born,
                    width: n.width,
                    tips: n.tips,
                })
                .collect(),
            links: g.links.iter().map(|k| [k.a, k.b, k.born]).collect(),
            edges: g.edges().collect(),
        },
        loops: g.loops(),
        iterations: g.iterations,
        fallback: g.fallback,
        mesh: MeshOut {
            vertices: l.mesh.vertex_count(),
            triangles: l.mesh.triangle_count(),
            hash: format!("{:016x}", l.mesh.content_hash()),
        },
        texture: TextureOut {
            width: l.texture.width,
            height: l.texture.height,
            layout: "RGBA8 color + RGBA8 normal/height, row-major, row 0 = v 0",
        },
        lod: LodOut {
            card_triangles: l.lod.card.triangle_count(),
            billboard_quads: l.lod.billboards.triangle_count() / 2,
            impostor_views: &l.lod.impostor_views,
        },
        ms: l.stats.stage_ms.iter().copied().collect(),
        total_ms: l.stats.total_ms,
    };
    serde_json::to_string(&out).expect("a leaf serialises")
}
