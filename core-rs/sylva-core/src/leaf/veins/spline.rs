//! Spline venation (Michel Anders 2013, "OSL leaf veins shader for Cycles",
//! blog.michelanders.nl; arcuate / pinnate): a straight midrib from
//! the petiole toward the tip and `Veins` lateral veins per side, each a quadratic spline
//! `P0 → P1 → P2`:
//!
//! * `P0` on the midrib at `y = δ/2 + (iδ + δ/2 · Var · noise) · Squish`, `δ = 1/(Veins + 1)`;
//! * `P2` on the edge at the fraction `(iδ + δ/2) · Squish + 1 - Squish` of the half's length
//!   from the base (pulled 3% inward);
//! * `P1` the edge point at the same fraction with its half-width scaled by `Up` (a copy of the
//!   edge squeezed toward the midrib: low `Up` gives straight pinnate veins, high `Up` arcs).
//!
//! Nodes are spaced by the growth step; a node's `born` is its distance in steps from the
//! petiole along the veins, so the step slider draws the midrib first and the laterals after.

use super::graph::{VeinGraph, VeinNode, NONE};
use crate::leaf::margin::Outline;
use crate::leaf::raster::Mask;
use crate::params::LeafParams;
use crate::rng::Rng;
use glam::Vec2;

/// The point at `frac` of a polyline's length.
fn along(poly: &[Vec2], frac: f32) -> Vec2 {
    let total: f32 = poly.windows(2).map(|w| (w[1] - w[0]).length()).sum();
    let mut left = frac.clamp(0.0, 1.0) * total;
    for w in poly.windows(2) {
        let l = (w[1] - w[0]).length();
        if left <= l && l > 0.0 {
            return w[0] + (w[1] - w[0]) * (left / l);
        }
        left -= l;
    }
    *poly.last().expect("a half has points")
}

/// The spline veins of `outline`, kept inside `mask`.
pub fn build(p: &LeafParams, outline: &Outline, mask: &Mask) -> VeinGraph {
    let step = p.leaf_growth_step;
    let mut nodes = vec![VeinNode { pos: Vec2::ZERO, parent: NONE, born: 0, width: 0.0, tips: 0 }];
    let steps = (0.99 / step) as u32;
    for k in 1..=steps {
        let q = Vec2::new(0.0, k as f32 * step);
        if !mask.contains(q) {
            break;
        }
        nodes.push(VeinNode { pos: q, parent: k - 1, born: k, width: 0.0, tips: 0 });
    }
    let midrib_len = nodes.len();
    let veins = p.leaf_vein_count as usize;
    let delta = 1.0 / (veins as f32 + 1.0);
    let squish = p.leaf_vein_squish;
    let mut rng = Rng::new(u64::from(p.leaf_vein_seed), "leaf-spline-veins");
    for side in 0..2 {
        // Each half from the base to the tip.
        let mut half = outline.half(side);
        half.reverse();
        for i in 0..veins {
            let jitter = 0.5 * delta * p.leaf_vein_var * rng.next_f32();
            let y0 = 0.5 * delta + (i as f32 * delta + jitter) * squish;
            let frac = (i as f32 * delta + 0.5 * delta) * squish + 1.0 - squish;
            let edge = along(&half, frac);
            let end = Vec2::new(edge.x * 0.97, edge.y);
            let ctrl = Vec2::new(edge.x * p.leaf_vein_up, edge.y);
            let attach = ((y0 / step).round() as usize).clamp(0, midrib_len - 1);
            let start = nodes[attach].pos;
            let len = (ctrl - start).length() + (end - ctrl).length();
            let n = ((len / step).ceil() as usize).max(1);
            let mut prev = attach as u32;
            for j in 1..=n {
                let u = j as f32 / n as f32;
                let q = start * ((1.0 - u) * (1.0 - u)) + ctrl * (2.0 * u * (1.0 - u)) + end * (u * u);
                if !mask.contains(q) {
                    break;
                }
                let born = nodes[prev as usize].born + 1;
                nodes.push(VeinNode { pos: q, parent: prev, born, width: 0.0, tips: 0 });
                prev = nodes.len() as u32 - 1;
            }
        }
    }
    let iterations = nodes.iter().map(|n| n.born).max().unwrap_or(0);
    VeinGraph { nodes, links: Vec::new(), iterations, fallback: false }
}
