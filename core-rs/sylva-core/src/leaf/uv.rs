//! Stage 4, UVs (Leaf Generation guide pipeline): planar over the blade's bounding box in the
//! leaf plane, `u = (x - x_min) / width`, `v = (y - y_min) / height`, both 0..1. The baked
//! texture and the card LOD cover exactly this box, so every LOD samples the same texels.

use crate::leaf::geom::bounds;
use glam::Vec2;

/// The bounding box the UVs (and the baked texture) span.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvFrame {
    /// Lower-left corner (`u = v = 0`).
    pub lo: Vec2,
    /// Width and height (never zero).
    pub size: Vec2,
}

impl UvFrame {
    /// The box of an outline.
    pub fn of(outline: &[Vec2]) -> UvFrame {
        let (lo, hi) = bounds(outline);
        UvFrame { lo, size: (hi - lo).max(Vec2::splat(1e-6)) }
    }

    /// The UV of a point in the leaf plane.
    #[inline]
    pub fn uv(&self, p: Vec2) -> Vec2 {
        ((p - self.lo) / self.size).clamp(Vec2::ZERO, Vec2::ONE)
    }

    /// The leaf-plane point of a UV.
    #[inline]
    pub fn point(&self, uv: Vec2) -> Vec2 {
        self.lo + uv * self.size
    }
}

/// Stage 4: the UV of every vertex.
pub fn build(frame: &UvFrame, vertices: &[Vec2]) -> Vec<Vec2> {
    vertices.iter().map(|&p| frame.uv(p)).collect()
}
