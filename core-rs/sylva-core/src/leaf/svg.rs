//! The leaf as an SVG drawing for the 2D inspector and the CLI (a conifer shoot: its twig and
//! needles): base outline (dashed), petiole,
//! blade with its margin, the triangulation (optional), auxin sources (orange while alive, grey once
//! reached) and the vein graph with pipe-model stroke widths (loop links in blue), all as they
//! were after a given growth step.

use crate::leaf::veins::NONE;
use crate::leaf::Leaf;
use crate::meta::LeafInspection;
use glam::Vec2;
use std::fmt::Write;

/// What to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SvgOptions {
    /// Draw the triangle edges. Default `false`.
    pub triangulation: bool,
    /// Draw the auxin sources. Default `true`.
    pub auxins: bool,
    /// Draw the growth as it was after this iteration (`None`: finished). Default `None`.
    pub step: Option<u32>,
    /// Size of the longer side of the picture in pixels (64 to 8192). Default 800.
    pub size_px: u32,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions { triangulation: false, auxins: true, step: None, size_px: 800 }
    }
}

struct View {
    lo: Vec2,
    hi: Vec2,
    scale: f32,
    pad: f32,
}

impl View {
    fn pt(&self, p: Vec2) -> (f32, f32) {
        ((p.x - self.lo.x) * self.scale + self.pad, (self.hi.y - p.y) * self.scale + self.pad)
    }
}

fn path(view: &View, pts: &[Vec2]) -> String {
    let mut d = String::with_capacity(pts.len() * 16);
    for (i, &p) in pts.iter().enumerate() {
        let (x, y) = view.pt(p);
        let _ = write!(d, "{}{x:.2} {y:.2}", if i == 0 { "M" } else { " L" });
    }
    d.push_str(" Z");
    d
}

/// Renders the leaf.
pub fn render(leaf: &Leaf, opts: &SvgOptions) -> String {
    let step = opts.step.unwrap_or(u32::MAX);
    let (mut lo, mut hi) = (leaf.uv_frame.lo, leaf.uv_frame.lo + leaf.uv_frame.size);
    for p in &leaf.outline.base_outline {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    lo.y = lo.y.min(-leaf.petiole);
    let px = opts.size_px.clamp(64, 8192) as f32;
    let pad = 0.04 * px;
    let scale = (px - 2.0 * pad) / (hi - lo).max_element().max(1e-6);
    let view = View { lo, hi, scale, pad };
    let (w, h) = ((hi.x - lo.x) * scale + 2.0 * pad, (hi.y - lo.y) * scale + 2.0 * pad + 18.0);
    let mut s = String::with_capacity(64 * 1024);
    let _ = writeln!(s, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.2} {h:.2}">"#
    );
    let _ = writeln!(s, r##"<rect x="0" y="0" width="{w:.2}" height="{h:.2}" fill="#ffffff"/>"##);
    if !leaf.shoot.is_empty() {
        shoot(&mut s, &view, leaf, h - 6.0);
        return s;
    }
    if leaf.outline.base_outline != leaf.outline.points {
        let _ = writeln!(
            s,
            r##"<path d="{}" fill="none" stroke="#9aa5a0" stroke-width="1" stroke-dasharray="4 3"/>"##,
            path(&view, &leaf.outline.base_outline)
        );
    }
    if leaf.petiole > 0.0 {
        let ((x0, y0), (x1, y1)) = (view.pt(Vec2::new(0.0, -leaf.petiole)), view.pt(Vec2::ZERO));
        let width = (crate::leaf::needles::PETIOLE_WIDTH * scale).max(1.5);
        let _ = writeln!(
            s,
            r##"<path d="M{x0:.2} {y0:.2} L{x1:.2} {y1:.2}" fill="none" stroke="#3d6b2a" stroke-width="{width:.2}" stroke-linecap="round"/>"##
        );
    }
    let _ = writeln!(
        s,
        r##"<path d="{}" fill="#d3e8bd" stroke="#3d6b2a" stroke-width="1.2" stroke-linejoin="round"/>"##,
        path(&view, &leaf.outline.points)
    );
    if opts.triangulation {
        let v = &leaf.triangulation.vertices;
        let mut d = String::with_capacity(leaf.triangulation.triangles.len() * 48);
        for t in &leaf.triangulation.triangles {
            let pts = [v[t[0] as usize], v[t[1] as usize], v[t[2] as usize]];
            d.push_str(&path(&view, &pts));
            d.push(' ');
        }
        let _ = writeln!(s, r##"<path d="{}" fill="none" stroke="#8fb07a" stroke-width="0.4"/>"##, d.trim_end());
    }
    if opts.auxins {
        let _ = writeln!(s, r#"<g stroke="none">"#);
        for (i, a) in leaf.veins.auxins.iter().enumerate() {
            let (x, y) = view.pt(a.pos);
            let alive = a.killed_at == NONE || a.killed_at > step;
            let (r, fill) = match (i, alive) {
                (0, _) => (3.0, "#c0392b"),
                (_, true) => (1.6, "#e07b39"),
                (_, false) => (1.0, "#b8b8b8"),
            };
            let _ = writeln!(s, r#"<circle cx="{x:.2}" cy="{y:.2}" r="{r}" fill="{fill}"/>"#);
        }
        let _ = writeln!(s, "</g>");
    }
    let g = &leaf.veins.graph;
    let _ = writeln!(s, r##"<g stroke="#2d4a1e" stroke-linecap="round" fill="none">"##);
    for (i, n) in g.nodes.iter().enumerate() {
        if n.parent == NONE || n.born > step {
            continue;
        }
        let ((x1, y1), (x2, y2)) = (view.pt(g.nodes[n.parent as usize].pos), view.pt(n.pos));
        let sw = (n.width * scale).max(0.4);
        let _ = writeln!(
            s,
            r#"<line x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}" stroke-width="{sw:.2}" data-node="{i}"/>"#
        );
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(s, r##"<g stroke="#1f6fb2" stroke-linecap="round" fill="none">"##);
    for l in g.links.iter().filter(|l| l.born <= step) {
        let ((x1, y1), (x2, y2)) = (view.pt(g.nodes[l.a as usize].pos), view.pt(g.nodes[l.b as usize].pos));
        let sw = (l.width * scale).max(0.4);
        let _ = writeln!(s, r#"<line x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}" stroke-width="{sw:.2}"/>"#);
    }
    let _ = writeln!(s, "</g>");
    let shown = step.min(g.iterations);
    let nodes = g.nodes.iter().filter(|n| n.born <= step).count();
    let loops = g.links.iter().filter(|l| l.born <= step).count();
    let _ = writeln!(
        s,
        r##"<text x="{:.2}" y="{:.2}" font-family="sans-serif" font-size="12" fill="#333333">step {shown} of {}: {nodes} vein nodes, {loops} loops, {} triangles ({:?})</text>"##,
        pad,
        h - 6.0,
        g.iterations,
        leaf.triangulation.triangles.len(),
        leaf.triangulation.method
    );
    s.push_str("</svg>\n");
    s
}

/// A conifer shoot: the twig, then every needle outline in drawing order, and a caption.
fn shoot(s: &mut String, view: &View, leaf: &Leaf, caption_y: f32) {
    let twig = crate::leaf::shoot::twig(leaf.petiole);
    let _ = writeln!(s, r##"<path d="{}" fill="#8a7350" stroke="#5c4a30" stroke-width="0.6"/>"##, path(view, &twig));
    let _ = writeln!(s, r##"<g fill="#bcd9a4" stroke="#2f5a22" stroke-width="0.7" stroke-linejoin="round">"##);
    for needle in &leaf.shoot {
        let _ = writeln!(s, r#"<path d="{}"/>"#, path(view, needle));
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(
        s,
        r##"<text x="{:.2}" y="{caption_y:.2}" font-family="sans-serif" font-size="12" fill="#333333">shoot: {} needles, {} triangles</text>"##,
        view.pad,
        leaf.shoot.len(),
        leaf.mesh.triangle_count()
    );
    s.push_str("</svg>\n");
}

/// Vein segments drawn at `step` (`None`: all): tree edges plus loop links born by then.
pub fn segments_at(leaf: &Leaf, step: Option<u32>) -> usize {
    let s = step.unwrap_or(u32::MAX);
    let g = &leaf.veins.graph;
    g.nodes.iter().filter(|n| n.parent != NONE && n.born <= s).count() + g.links.iter().filter(|l| l.born <= s).count()
}

/// The inspector's answer as JSON ([`inspection`]).
pub fn inspect_json(leaf: &Leaf, opts: &SvgOptions) -> String {
    crate::meta::to_json(&inspection(leaf, opts))
}

/// The inspector's answer: the drawing and the vein and blade counts, where `segments` is
/// [`segments_at`] the options' step.
pub fn inspection(leaf: &Leaf, opts: &SvgOptions) -> LeafInspection {
    let g = &leaf.veins.graph;
    LeafInspection {
        svg: render(leaf, opts),
        iterations: g.iterations,
        nodes: g.nodes.len(),
        links: g.links.len(),
        segments: segments_at(leaf, opts.step),
        auxins: leaf.veins.auxins.len(),
        triangles: leaf.triangulation.triangles.len(),
        hash: leaf.hash_hex(),
    }
}
