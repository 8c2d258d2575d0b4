//! Wavefront OBJ + MTL writer (the OBJ and MTL formats as documented in Wavefront's Advanced
//! Visualizer manual, appendices B1 and B2, with the common `v x y z r g b` vertex-colour and
//! `norm` normal-map extensions).
//!
//! * `NAME.obj`: `mtllib NAME.mtl`, then object `bark` and object `leaves` (leaves always baked:
//!   OBJ has no instancing; [`LeafMode::Instanced`] writes them baked too, [`LeafMode::None`]
//!   leaves them out). Each object lists `v` (with the vertex colour as three more numbers when
//!   [`ExportOptions::vertex_colors`]), `vt`, `vn`, then `usemtl` and `f a/a/a b/b/b c/c/c`
//!   faces (1-based, global across objects, counter-clockwise seen from outside). Numbers are
//!   Rust's shortest round-trip form of the `f32` values (colours: 4 decimals), so the text is
//!   deterministic and reads back to the same floats.
//! * Flowers, fruit, catkins and buds ([`crate::organs`]): after the leaves, one object per organ
//!   set, baked as the leaves are (tints as vertex colours), named after the set with `_` for
//!   spaces (`acorn_cups`), each with a plain material of that name (`Kd` its colour); none with
//!   [`LeafMode::None`].
//! * `NAME.mtl`: materials `bark` and `leaves`, `Kd` (white when textured, the plain colour
//!   otherwise), `Ks 0 0 0`, `map_Kd NAME_bark_color.png`, `norm NAME_bark_normal.png`, and the
//!   same for the leaves (the leaf colour PNG has the alpha that cuts the blade outline). A tree
//!   with a cut stem also gets `cut_face` (the end grain of [`crate::mesh::bark::end_grain`],
//!   `NAME_cut_face_color.png` and `NAME_cut_face_normal.png`), used by the faces of its cuts.
//! * The PNG files ([`textures`]): OBJ puts `vt` 0 at the **bottom** of an image (OpenGL), so the
//!   baked textures (row 0 = `v` 0) are written with their rows reversed and the UVs stay as
//!   they are; the normal maps then follow the OpenGL (+Y up) convention.

use super::organs::BakedSet;
use super::{ExportOptions, LeafMode};
use crate::mesh::{Material, TreeMesh};
use crate::Generated;
use std::fmt::Write;

/// An OBJ export: the two text files and the PNG files they reference.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjFiles {
    /// The `.obj` text.
    pub obj: String,
    /// The `.mtl` text.
    pub mtl: String,
    /// `(file name, PNG bytes)` of every texture the MTL names, empty without textures.
    pub textures: Vec<(String, Vec<u8>)>,
}

/// OBJ, MTL and textures for a tree; `name` is the file stem the OBJ and MTL refer to
/// (`name.mtl`, `name_bark_color.png`, ...).
pub fn write(g: &Generated, opts: &ExportOptions, name: &str) -> ObjFiles {
    ObjFiles { obj: obj(g, opts, name), mtl: mtl(g, opts, name), textures: textures(g, opts, name) }
}

/// Whether the bark has cut faces (a cut stem): then the `cut_face` material and its textures.
fn has_cut(g: &Generated) -> bool {
    g.mesh.groups.iter().any(|gr| gr.material == Material::CutFace && gr.count > 0)
}

fn has_leaves(g: &Generated, opts: &ExportOptions) -> bool {
    opts.leaves != LeafMode::None && g.foliage.count() > 0 && !g.foliage.mesh.indices.is_empty()
}

/// The texture file names the MTL uses: `(bark color, bark normal, leaf color, leaf normal,
/// cut face color, cut face normal)`.
fn texture_names_all(name: &str) -> [String; 6] {
    ["bark_color", "bark_normal", "leaf_color", "leaf_normal", "cut_face_color", "cut_face_normal"]
        .map(|k| format!("{name}_{k}.png"))
}

/// The `.obj` text.
pub fn obj(g: &Generated, opts: &ExportOptions, name: &str) -> String {
    let bark = &g.mesh;
    let scale = super::tint_scale(&g.foliage);
    let baked = has_leaves(g, opts).then(|| super::bake_leaves_scaled(&g.foliage, false, scale));
    let leaves = baked.as_ref().map(|b| &b.mesh);
    let organs: Vec<BakedSet> = super::organs::exported(g, opts).into_iter().map(super::organs::bake_set).collect();
    let verts = bark.vertex_count()
        + leaves.map_or(0, TreeMesh::vertex_count)
        + organs.iter().map(|b| b.baked.mesh.vertex_count()).sum::<usize>();
    let tris = bark.triangle_count()
        + leaves.map_or(0, TreeMesh::triangle_count)
        + organs.iter().map(|b| b.baked.mesh.triangle_count()).sum::<usize>();
    let mut s = String::with_capacity(verts * 100 + tris * 40);
    let _ = writeln!(s, "# Sylva {} tree, hash {}", crate::VERSION, g.hash_hex());
    let _ = writeln!(s, "# {verts} vertices, {tris} triangles");
    let _ = writeln!(s, "mtllib {name}.mtl");
    let bark_colors = opts.vertex_colors.then(|| super::bark_colors(bark));
    let mut first = 1u64;
    if bark.vertex_count() > 0 {
        first += object(&mut s, "bark", bark, bark_colors.as_deref(), first, None);
    }
    if let Some(b) = &baked {
        first += object(&mut s, "leaves", &b.mesh, opts.vertex_colors.then_some(&b.colors[..]), first, None);
    }
    for b in &organs {
        let name = super::organs::file_name(b.set);
        first +=
            object(&mut s, &name, &b.baked.mesh, opts.vertex_colors.then_some(&b.baked.colors[..]), first, Some(&name));
    }
    s
}

/// Writes one object (its groups' materials, or `material` for all); returns its vertex count.
fn object(s: &mut String, name: &str, m: &TreeMesh, colors: Option<&[u8]>, first: u64, material: Option<&str>) -> u64 {
    let _ = writeln!(s, "o {name}");
    for (i, p) in m.positions.chunks_exact(3).enumerate() {
        let _ = write!(s, "v {} {} {}", p[0], p[1], p[2]);
        if let Some(c) = colors {
            let c = &c[4 * i..4 * i + 3];
            let f = |b: u8| f32::from(b) / 255.0;
            let _ = write!(s, " {:.4} {:.4} {:.4}", f(c[0]), f(c[1]), f(c[2]));
        }
        s.push('\n');
    }
    for t in m.uvs.chunks_exact(2) {
        let _ = writeln!(s, "vt {} {}", t[0], t[1]);
    }
    for n in m.normals.chunks_exact(3) {
        let _ = writeln!(s, "vn {} {} {}", n[0], n[1], n[2]);
    }
    for g in m.groups.iter().filter(|g| g.count > 0) {
        let mat = material.unwrap_or(g.material.name());
        let _ = writeln!(s, "usemtl {mat}");
        for t in m.indices[g.start as usize..(g.start + g.count) as usize].chunks_exact(3) {
            let (a, b, c) = (u64::from(t[0]) + first, u64::from(t[1]) + first, u64::from(t[2]) + first);
            let _ = writeln!(s, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}");
        }
    }
    m.vertex_count() as u64
}

/// The `.mtl` text (materials `bark` and `leaves`).
pub fn mtl(g: &Generated, opts: &ExportOptions, name: &str) -> String {
    let [bc, bn, lc, ln, cc, cn] = texture_names_all(name);
    let mut s = format!("# Sylva {} materials\n", crate::VERSION);
    let normals = opts.textures && opts.normal_maps;
    // Plain colours (sRGB) when untextured: the viewer's bark #5b3d26 and the leaf blade green.
    s.push_str("\nnewmtl bark\n");
    s.push_str(if opts.textures { "Kd 1 1 1\n" } else { "Kd 0.357 0.239 0.149\n" });
    s.push_str("Ks 0 0 0\nNs 10\nd 1\nillum 2\n");
    if opts.textures {
        let _ = writeln!(s, "map_Kd {bc}");
        if normals {
            let _ = writeln!(s, "norm {bn}");
        }
    }
    if has_leaves(g, opts) {
        s.push_str("\nnewmtl leaves\n");
        s.push_str(if opts.textures { "Kd 1 1 1\n" } else { "Kd 0.30 0.52 0.18\n" });
        s.push_str("Ks 0 0 0\nNs 20\nd 1\nillum 2\n");
        if opts.textures && g.foliage.texture().is_some() {
            let _ = writeln!(s, "map_Kd {lc}");
            if normals {
                let _ = writeln!(s, "norm {ln}");
            }
        }
    }
    organ_materials(g, opts, &mut s);
    if has_cut(g) {
        // Plain: the viewer's cut-face wood #c8a57a.
        s.push_str("\nnewmtl cut_face\n");
        s.push_str(if opts.textures { "Kd 1 1 1\n" } else { "Kd 0.784 0.647 0.478\n" });
        s.push_str("Ks 0 0 0\nNs 8\nd 1\nillum 2\n");
        if opts.textures {
            let _ = writeln!(s, "map_Kd {cc}");
            if normals {
                let _ = writeln!(s, "norm {cn}");
            }
        }
    }
    s
}

/// One plain material per organ set, named as its object: `Kd` the set's colour (sRGB; with
/// vertex colours, times the tint scale the baked colours were divided by, as in the GLB).
fn organ_materials(g: &Generated, opts: &ExportOptions, s: &mut String) {
    for set in super::organs::exported(g, opts) {
        let lin = if opts.vertex_colors { super::organs::bake_set(set).base } else { super::organs::linear_color(set) };
        let kd = lin.map(super::organs::linear_to_srgb);
        let _ = writeln!(s, "\nnewmtl {}", super::organs::file_name(set));
        let _ = writeln!(s, "Kd {:.4} {:.4} {:.4}", kd[0], kd[1], kd[2]);
        s.push_str("Ks 0 0 0\nNs 10\nd 1\nillum 2\n");
    }
}

/// The textures an OBJ export references, in file order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tex {
    BarkColor,
    BarkNormal,
    LeafColor,
    LeafNormal,
    CutFaceColor,
    CutFaceNormal,
}

fn texture_plan(g: &Generated, opts: &ExportOptions) -> Vec<Tex> {
    let mut plan = Vec::new();
    if !opts.textures {
        return plan;
    }
    plan.push(Tex::BarkColor);
    if opts.normal_maps {
        plan.push(Tex::BarkNormal);
    }
    if has_leaves(g, opts) && g.foliage.texture().is_some() {
        plan.push(Tex::LeafColor);
        if opts.normal_maps {
            plan.push(Tex::LeafNormal);
        }
    }
    if has_cut(g) {
        plan.push(Tex::CutFaceColor);
        if opts.normal_maps {
            plan.push(Tex::CutFaceNormal);
        }
    }
    plan
}

/// The names of the PNG files the MTL refers to, in the order of [`texture_png`]'s indices.
pub fn texture_names(g: &Generated, opts: &ExportOptions, name: &str) -> Vec<String> {
    let [bc, bn, lc, ln, cc, cn] = texture_names_all(name);
    texture_plan(g, opts)
        .into_iter()
        .map(|t| match t {
            Tex::BarkColor => bc.clone(),
            Tex::BarkNormal => bn.clone(),
            Tex::LeafColor => lc.clone(),
            Tex::LeafNormal => ln.clone(),
            Tex::CutFaceColor => cc.clone(),
            Tex::CutFaceNormal => cn.clone(),
        })
        .collect()
}

/// PNG file `index` of [`texture_names`], rows flipped for OBJ's bottom-up `vt` (module docs);
/// `None` when out of range.
pub fn texture_png(g: &Generated, opts: &ExportOptions, index: usize) -> Option<Vec<u8>> {
    let tex = *texture_plan(g, opts).get(index)?;
    let png = |w: u32, h: u32, rgba: &[u8]| super::png::encode_rgba(w, h, &flip_rows(rgba, w as usize));
    match tex {
        Tex::BarkColor | Tex::BarkNormal => {
            let m = crate::mesh::bark::bake(g.bark, opts.bark_texture_size as usize);
            let s = m.color.size as u32;
            Some(png(s, s, if tex == Tex::BarkColor { &m.color.rgba } else { &m.normal.rgba }))
        }
        Tex::LeafColor | Tex::LeafNormal => {
            let t = g.foliage.texture()?;
            if tex == Tex::LeafNormal {
                return Some(png(t.width, t.height, &t.normal));
            }
            // The colours are the tints divided by this scale (`tint_scale`): the texture takes it.
            Some(png(t.width, t.height, &super::scale_texels(&t.color, super::tint_scale(&g.foliage))))
        }
        Tex::CutFaceColor | Tex::CutFaceNormal => {
            let m = crate::mesh::bark::end_grain::bake(g.bark, opts.bark_texture_size as usize);
            let s = m.color.size as u32;
            Some(png(s, s, if tex == Tex::CutFaceColor { &m.color.rgba } else { &m.normal.rgba }))
        }
    }
}

/// Rows reversed (the bottom row first).
fn flip_rows(rgba: &[u8], width: usize) -> Vec<u8> {
    rgba.chunks_exact(width * 4).rev().flatten().copied().collect()
}

/// Every PNG file the MTL names: `(file name, PNG bytes)`.
pub fn textures(g: &Generated, opts: &ExportOptions, name: &str) -> Vec<(String, Vec<u8>)> {
    texture_names(g, opts, name)
        .into_iter()
        .enumerate()
        .filter_map(|(i, n)| texture_png(g, opts, i).map(|p| (n, p)))
        .collect()
}
