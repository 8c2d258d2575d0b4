//! Primary veins, laid down before space colonization fills the rest (pinnate, palmate and
//! dichotomous venation, Ellis et al. 2009, *Manual of Leaf Architecture*; Runions et al. 2005 grow
//! their networks from such a given skeleton too). Every vein is a polyline of nodes spaced by the
//! growth step, cut where it would leave the blade; a node's `born` is its distance in steps from
//! the petiole, so the step slider draws the primaries first.
//!
//! * **Pinnate**: a straight midrib from the petiole `(0, 0)` to the tip, and secondary veins
//!   along it: one per lobe, ending at the lobe's apex (oak), or on an unlobed blade Secondary
//!   Veins per side spread from 10% to 85% of the half's length, each ending at the tooth apex
//!   nearest its end (craspedodromous, birch). Into a lobe the vein first reaches the lobe's
//!   axis inside the sinuses, then runs out along it to the apex. A secondary leaves the midrib at Secondary Angle
//!   (10° wider at the start, so it arcs toward the tip) from `y = E_y − |E_x| / tan(angle)`.
//! * **Palmate**: from the petiole up to the junction (the palmate blade's centre), then one
//!   straight primary from the junction to each lobe's apex (Palmate
//!   outline), or to the edge along rays spread evenly over ±Lobe Spread (other outlines).
//! * **Dichotomous** (ginkgo): two veins leave the petiole, each owning an angular sector of
//!   the blade seen from the junction; a vein steers toward the middle of its sector and forks
//!   in two (halving the sector) whenever the sector's width at its distance exceeds twice the
//!   vein spacing (2 × Kill Distance), so the veins stay evenly spaced as the fan widens.

use super::graph::{VeinGraph, VeinNode, NONE};
use crate::leaf::margin::Outline;
use crate::leaf::outline::Shape;
use crate::leaf::raster::Mask;
use crate::params::LeafParams;
use crate::params::{LeafOutline, LeafPrimaries};
use glam::Vec2;

/// The root alone: a node at the petiole.
pub fn root() -> VeinGraph {
    VeinGraph {
        nodes: vec![VeinNode { pos: Vec2::ZERO, parent: NONE, born: 0, width: 0.0, tips: 0 }],
        ..VeinGraph::default()
    }
}

/// The primary veins chosen by `leaf_primary_veins` (the root alone for None).
pub fn build(p: &LeafParams, outline: &Outline, mask: &Mask) -> VeinGraph {
    let mut g = root();
    let step = p.leaf_growth_step;
    match p.leaf_primary_veins {
        LeafPrimaries::None => {}
        LeafPrimaries::Pinnate => pinnate(p, outline, mask, step, &mut g),
        LeafPrimaries::Palmate => {
            // The junction: the palmate blade's centre, or just above the petiole.
            let centre = if p.leaf_outline == LeafOutline::Palmate { outline.center } else { Vec2::new(0.0, 0.03) };
            let junction = path(&mut g, 0, &[centre], mask, step);
            for target in palmate_targets(p, outline, mask) {
                path(&mut g, junction, &[target], mask, step);
            }
        }
        LeafPrimaries::Dichotomous => dichotomous(outline, mask, step, 2.0 * p.leaf_kill, &mut g),
    }
    g.iterations = g.nodes.iter().map(|n| n.born).max().unwrap_or(0);
    g
}

/// Appends a polyline from node `from` through `points` (each leg cut into growth steps),
/// stopping where it would leave the blade. Returns the last node.
fn path(g: &mut VeinGraph, from: u32, points: &[Vec2], mask: &Mask, step: f32) -> u32 {
    let mut prev = from;
    for &q in points {
        let a = g.nodes[prev as usize].pos;
        let n = (((q - a).length() / step).ceil() as usize).max(1);
        for j in 1..=n {
            let r = a + (q - a) * (j as f32 / n as f32);
            if !mask.contains(r) {
                return prev;
            }
            let born = g.nodes[prev as usize].born + 1;
            g.nodes.push(VeinNode { pos: r, parent: prev, born, width: 0.0, tips: 0 });
            prev = g.nodes.len() as u32 - 1;
        }
    }
    prev
}

/// Outline points of half `side` (0 left, 1 right) with their `t` (0 tip, 1 base).
fn half_points(o: &Outline, side: usize) -> impl Iterator<Item = (Vec2, f32)> + '_ {
    o.points.iter().zip(&o.params).enumerate().filter_map(move |(i, (&q, &t))| {
        let on = if side == 0 { i <= o.base_index } else { i == 0 || i >= o.base_index };
        on.then_some((q, t))
    })
}

/// The point of half `side` within `±window` of `t` that stands out most (largest `reach`).
fn apex_near(o: &Outline, side: usize, t: f32, window: f32, reach: impl Fn(Vec2) -> f32) -> Option<Vec2> {
    half_points(o, side)
        .filter(|&(_, u)| (u - t).abs() <= window)
        .max_by(|a, b| reach(a.0).total_cmp(&reach(b.0)))
        .map(|(q, _)| q)
}

/// Midrib and secondaries.
fn pinnate(p: &LeafParams, o: &Outline, mask: &Mask, step: f32, g: &mut VeinGraph) {
    let tip = Vec2::new(0.0, 0.985);
    path(g, 0, &[tip], mask, step);
    let midrib: Vec<u32> = (0..g.nodes.len() as u32).collect();
    let shape = Shape::from_params(p);
    let lobed = p.leaf_outline == LeafOutline::Pinnate && p.leaf_lobes > 0;
    let (ts, window): (Vec<f32>, f32) = if lobed {
        (shape.lobe_tips().iter().map(|&t| t as f32).collect(), 0.25 / (p.leaf_lobes as f32 + 0.5))
    } else {
        let n = p.leaf_secondaries;
        let ts = (0..n).map(|i| 0.15 + 0.75 * (i as f32 + 0.5) / n.max(1) as f32).collect();
        (ts, 0.35 / (n as f32 + 1.0))
    };
    let angle = crate::math::rad(p.leaf_secondary_angle);
    let cot = crate::math::cos(angle) / crate::math::sin(angle);
    for side in 0..2 {
        let sign = if side == 0 { -1.0 } else { 1.0 };
        for &t in &ts {
            let Some(end) = apex_near(o, side, t, window, |q| q.x.abs()) else { continue };
            let end = end - Vec2::new(sign * 0.012, 0.0);
            // Into a lobe: reach the lobe's axis inside the sinuses first, then run out along it,
            // rising toward the tip as the lobe leans.
            let bend = if lobed {
                let x = end.x * 0.55 * (1.0 - p.leaf_lobe_depth);
                Vec2::new(x, end.y - 0.02 - 0.25 * (end.x - x).abs())
            } else {
                end
            };
            let y0 = (bend.y - bend.x.abs() * cot).clamp(0.02, (0.95 * bend.y).max(0.02));
            let attach = midrib.iter().copied().min_by(|&a, &b| {
                let d = |i: u32| (g.nodes[i as usize].pos.y - y0).abs();
                d(a).total_cmp(&d(b))
            });
            let Some(attach) = attach else { continue };
            let start = g.nodes[attach as usize].pos;
            // Leave the midrib 10° wider than the chord, then arc toward the tip.
            let wide = angle + crate::math::rad(10.0);
            let reach = 0.45 * (bend - start).length();
            let ctrl = start + Vec2::new(sign * crate::math::sin(wide), crate::math::cos(wide)) * reach;
            let n = (((bend - start).length() / step).ceil() as usize).max(2);
            let mut pts: Vec<Vec2> = (1..=n)
                .map(|j| {
                    let u = j as f32 / n as f32;
                    start * ((1.0 - u) * (1.0 - u)) + ctrl * (2.0 * u * (1.0 - u)) + bend * (u * u)
                })
                .collect();
            if lobed {
                pts.push(end);
            }
            path(g, attach, &pts, mask, step);
        }
    }
}

/// Ends of the palmate primaries: the lobe apices (Palmate outline) or where rays from the
/// junction spread over ±Lobe Spread leave the blade.
fn palmate_targets(p: &LeafParams, o: &Outline, mask: &Mask) -> Vec<Vec2> {
    let n = p.leaf_lobes.max(1) as usize;
    if p.leaf_outline == LeafOutline::Palmate {
        let shape = Shape::from_params(p);
        let tips = shape.lobe_tips();
        let window = 0.5 * crate::math::rad(p.leaf_lobe_spread) / std::f32::consts::PI / n as f32;
        let c = o.center;
        let mut out = Vec::new();
        for (k, &t) in tips.iter().enumerate() {
            for side in 0..2 {
                if k == 0 && t == 0.0 && side == 1 {
                    continue;
                }
                out.extend(apex_near(o, side, t as f32, window, |q| (q - c).length()));
            }
        }
        return out;
    }
    let spread = crate::math::rad(p.leaf_lobe_spread);
    (0..n)
        .map(|k| {
            let a = if n == 1 { 0.0 } else { -spread + 2.0 * spread * k as f32 / (n - 1) as f32 };
            let dir = Vec2::new(crate::math::sin(a), crate::math::cos(a));
            let mut r = 0.0f32;
            while r < 3.0 && mask.contains(dir * (r + 0.01)) {
                r += 0.01;
            }
            dir * r
        })
        .filter(|q| q.length() > 0.05)
        .collect()
}

/// A growing dichotomous vein: its last node, direction, and the sector it owns (angles from
/// `+y`, about the junction).
struct Fork {
    node: u32,
    dir: Vec2,
    a: f32,
    b: f32,
}

/// Repeatedly forking veins from the petiole (see the module docs).
fn dichotomous(o: &Outline, mask: &Mask, step: f32, spacing: f32, g: &mut VeinGraph) {
    let reach =
        o.points.iter().filter(|q| q.y > 0.05).map(|q| crate::math::atan2(q.x.abs(), q.y)).fold(0.0f32, f32::max);
    let beta = 0.92 * reach;
    let mut live =
        vec![Fork { node: 0, dir: Vec2::Y, a: -beta, b: 0.0 }, Fork { node: 0, dir: Vec2::Y, a: 0.0, b: beta }];
    let max_steps = (4.0 / step) as usize;
    for _ in 0..max_steps {
        if live.is_empty() {
            break;
        }
        let mut next = Vec::with_capacity(live.len() + 2);
        for f in live {
            let mid = 0.5 * (f.a + f.b);
            let want = Vec2::new(crate::math::sin(mid), crate::math::cos(mid));
            let dir = (f.dir * 0.7 + want * 0.3).normalize_or(want);
            let from = g.nodes[f.node as usize].pos;
            let q = from + dir * step;
            if !mask.contains(q) {
                continue;
            }
            let born = g.nodes[f.node as usize].born + 1;
            g.nodes.push(VeinNode { pos: q, parent: f.node, born, width: 0.0, tips: 0 });
            let node = g.nodes.len() as u32 - 1;
            if q.length() * (f.b - f.a) > 2.0 * spacing && q.length() > 3.0 * step {
                next.push(Fork { node, dir, a: f.a, b: mid });
                next.push(Fork { node, dir, a: mid, b: f.b });
            } else {
                next.push(Fork { node, dir, a: f.a, b: f.b });
            }
        }
        live = next;
    }
}
