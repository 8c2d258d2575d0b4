//! The vein influence field (Leaf Generation guide §5, "vein displacement"): a raster over the
//! UV box where every vein segment of width `w` raises a ridge of height `w / w_max` and radius
//! `2 w + 1 texel`, profile `(1 - (d/R)²)²`, so thicker veins raise higher and wider
//! ridges; the field keeps the highest ridge per texel (the midrib's crest is 1). A second
//! channel holds the veins' anti-aliased coverage for the colour texture. Deformation samples
//! the height; the texture bake turns both into colour and normals.

use crate::leaf::uv::UvFrame;
use crate::leaf::veins::VeinGraph;
use glam::Vec2;

/// Ridge height and vein coverage on a `w × h` grid over the UV box (row 0 at `v = 0`).
#[derive(Clone, Debug, PartialEq)]
pub struct VeinField {
    /// Texels per row.
    pub w: usize,
    /// Rows.
    pub h: usize,
    /// The UV box.
    pub frame: UvFrame,
    /// Ridge height 0..1 per texel.
    pub height: Vec<f32>,
    /// Vein coverage 0..1 per texel.
    pub cover: Vec<f32>,
}

impl VeinField {
    /// Size of a texel in leaf units.
    pub fn texel(&self) -> Vec2 {
        self.frame.size / Vec2::new(self.w as f32, self.h as f32)
    }

    /// Bilinear ridge height at a leaf-plane point.
    pub fn sample(&self, p: Vec2) -> f32 {
        let t = (p - self.frame.lo) / self.texel() - Vec2::splat(0.5);
        let x0 = (t.x.floor().max(0.0) as usize).min(self.w - 1);
        let y0 = (t.y.floor().max(0.0) as usize).min(self.h - 1);
        let (x1, y1) = ((x0 + 1).min(self.w - 1), (y0 + 1).min(self.h - 1));
        let (fx, fy) = ((t.x - x0 as f32).clamp(0.0, 1.0), (t.y - y0 as f32).clamp(0.0, 1.0));
        let at = |x: usize, y: usize| self.height[y * self.w + x];
        let top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
        let bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
        top + (bottom - top) * fy
    }
}

/// Rasterises every edge of the graph.
#[inline(never)]
pub fn build(graph: &VeinGraph, frame: &UvFrame, w: usize, h: usize) -> VeinField {
    let mut f = VeinField { w, h, frame: *frame, height: vec![0.0; w * h], cover: vec![0.0; w * h] };
    let wmax = graph.nodes.first().map_or(0.0, |n| n.width).max(1e-9);
    let texel = f.texel();
    let tmin = texel.min_element();
    for (a, b, _, width) in graph.edges() {
        let (pa, pb) = (graph.nodes[a as usize].pos, graph.nodes[b as usize].pos);
        let amp = width / wmax;
        let r = 2.0 * width + tmin;
        let half = 0.5 * width.max(0.75 * tmin);
        let strength = (width / (0.75 * tmin)).min(1.0).sqrt();
        let lo = (pa.min(pb) - Vec2::splat(r) - frame.lo) / texel - Vec2::splat(0.5);
        let hi = (pa.max(pb) + Vec2::splat(r) - frame.lo) / texel - Vec2::splat(0.5);
        let (lo, hi) = (Vec2::new(lo.x.ceil(), lo.y.ceil()).max(Vec2::ZERO), Vec2::new(hi.x.floor(), hi.y.floor()));
        if hi.x < 0.0 || hi.y < 0.0 {
            continue;
        }
        let (x0, y0) = (lo.x as usize, lo.y as usize);
        let (x1, y1) = ((hi.x as usize).min(w - 1), (hi.y as usize).min(h - 1));
        let ab = pb - pa;
        let len2 = ab.length_squared();
        let inv_len2 = if len2 > 0.0 { 1.0 / len2 } else { 0.0 };
        let (r2, inv_r2, inv_t) = (r * r, 1.0 / (r * r), 1.0 / tmin);
        let cover_r2 = (half + 0.5 * tmin) * (half + 0.5 * tmin);
        let x_start = frame.lo.x + (x0 as f32 + 0.5) * texel.x - pa.x;
        for y in y0..=y1 {
            let qy = frame.lo.y + (y as f32 + 0.5) * texel.y - pa.y;
            let range = y * w + x0..y * w + x1 + 1;
            for (i, (hc, cc)) in f.height[range.clone()].iter_mut().zip(&mut f.cover[range]).enumerate() {
                let qx = x_start + i as f32 * texel.x;
                let t = (qx * ab.x + qy * ab.y) * inv_len2;
                let t = t.clamp(0.0, 1.0);
                let (dx, dy) = (qx - ab.x * t, qy - ab.y * t);
                let d2 = dx * dx + dy * dy;
                if d2 >= r2 {
                    continue;
                }
                let k = 1.0 - d2 * inv_r2;
                let hgt = amp * k * k;
                if hgt > *hc {
                    *hc = hgt;
                }
                if d2 < cover_r2 {
                    let c = (half - d2.sqrt()) * inv_t + 0.5;
                    let c = if c > 1.0 { strength } else { c * strength };
                    if c > *cc {
                        *cc = c;
                    }
                }
            }
        }
    }
    f
}
