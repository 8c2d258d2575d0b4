//! Space colonization from an existing tree (Runions, Lane & Prusinkiewicz 2007, *Modeling Trees
//! with a Space Colonization Algorithm*, §3): every live marker attracts its closest node within
//! the influence distance, every attracted node grows one internode toward the normalised sum of
//! the unit vectors to its markers, and markers within the kill distance of a node die. The
//! nodes start as points sampled along the tree's stems (they grow like any other); markers
//! arrive in batches ([`Colony::add_markers`]) and each batch is grown to convergence
//! ([`Colony::grow`]).
//!
//! Results never depend on the grids (they only find candidates): a marker's closest node is the
//! nearest one, ties going to the older node; nodes grow in the order their first marker comes.
//! A new marker's search reaches no further than the nearest node in its own grid cell: inside
//! a crown, whose nodes lie every internode along every stem, that is a few cells instead of
//! the whole block around the influence distance.

use crate::error::SylvaError;
use crate::growth::grid::Grid;
use crate::growth::volume::GROUND_CLEARANCE;
use glam::Vec3;

/// `parent` of a node of the existing tree.
pub const EXISTING: u32 = u32::MAX;

/// Smallest mean resultant length of a node's marker directions that still makes it grow (as in
/// `crate::growth::sca`): markers on opposite sides cancel out instead of making the tip orbit.
const MIN_PULL: f32 = 0.2;

/// A new internode grows only if no node lies closer to its end than this fraction of the
/// internode (a tip pulled back and forth does not pile up nodes).
const CROWDED: f32 = 0.1;

/// One node: a point on the existing tree ([`EXISTING`] parent) or a new internode's end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// Position (m).
    pub pos: Vec3,
    /// The node it grew from, or [`EXISTING`].
    pub parent: u32,
}

/// The growth settings of one stroke.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// A marker attracts nodes closer than this (m).
    pub influence: f32,
    /// A marker dies when a node comes this close (m).
    pub kill: f32,
    /// Length of one new internode (m).
    pub segment: f32,
    /// Most new nodes before growth stops with a budget error.
    pub max_new: usize,
}

/// The nodes and markers of one stroke's growth.
pub struct Colony {
    /// All nodes: the existing tree's first, then the new ones (parents before children).
    pub nodes: Vec<Node>,
    /// How many of `nodes` are the existing tree's.
    pub existing: usize,
    /// Every marker added, live or dead (for display).
    pub markers: Vec<Vec3>,
    alive: Vec<bool>,
    alive_count: usize,
    closest: Vec<u32>,
    closest_d2: Vec<f32>,
    node_grid: Grid,
    marker_grid: Grid,
    lo: Vec3,
    hi: Vec3,
    s: Settings,
    /// Growth iterations run so far.
    pub iterations: u32,
}

impl Colony {
    /// A colony of the existing tree's nodes `existing` (no markers yet).
    pub fn new(existing: &[Vec3], s: Settings) -> Colony {
        let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        for p in existing {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        if existing.is_empty() {
            (lo, hi) = (Vec3::ZERO, Vec3::ONE);
        }
        let cell = 0.5 * s.influence;
        let mut c = Colony {
            nodes: existing.iter().map(|&pos| Node { pos, parent: EXISTING }).collect(),
            existing: existing.len(),
            markers: Vec::new(),
            alive: Vec::new(),
            alive_count: 0,
            closest: Vec::new(),
            closest_d2: Vec::new(),
            node_grid: Grid::new(lo, hi, cell, 160),
            marker_grid: Grid::new(lo, hi, cell, 160),
            lo,
            hi,
            s,
            iterations: 0,
        };
        c.rebuild_grids();
        c
    }

    /// Both grids again over `lo..hi` (after the box grew).
    fn rebuild_grids(&mut self) {
        let cell = 0.5 * self.s.influence;
        self.node_grid = Grid::new(self.lo, self.hi, cell, 160);
        for (i, n) in self.nodes.iter().enumerate() {
            self.node_grid.insert(i as u32, n.pos);
        }
        self.marker_grid = Grid::new(self.lo, self.hi, cell, 160);
        for (i, m) in self.markers.iter().enumerate() {
            self.marker_grid.insert(i as u32, *m);
        }
    }

    /// Add markers: each finds its closest node within the influence distance, or dies at once
    /// when a node is within the kill distance.
    pub fn add_markers(&mut self, markers: &[Vec3]) {
        let reach = Vec3::splat(self.s.influence + self.s.segment);
        let outside = markers.iter().any(|m| m.cmplt(self.lo).any() || m.cmpgt(self.hi).any());
        if outside {
            for m in markers {
                self.lo = self.lo.min(*m - reach);
                self.hi = self.hi.max(*m + reach);
            }
            self.rebuild_grids();
        }
        let (influence2, kill2) = (self.s.influence * self.s.influence, self.s.kill * self.s.kill);
        // Every node within the influence or kill distance, as the plain visit finds them.
        let within = self.s.influence.max(self.s.kill);
        for &p in markers {
            let id = self.markers.len() as u32;
            self.markers.push(p);
            self.marker_grid.insert(id, p);
            let (mut best, mut best_d2, mut dead) = (EXISTING, f32::INFINITY, false);
            let nodes = &self.nodes;
            // Only the nearest nodes decide: the search reaches no further than the nearest
            // node in the marker's own cell.
            let mut bound = f32::INFINITY;
            self.node_grid.for_each_in_cell(p, |n| bound = bound.min(nodes[n as usize].pos.distance_squared(p)));
            let within = within.min(bound.sqrt());
            self.node_grid.for_each_near_within(p, self.s.influence, within, |n| {
                let d2 = nodes[n as usize].pos.distance_squared(p);
                dead |= d2 <= kill2;
                if d2 < influence2 && (d2 < best_d2 || (d2 == best_d2 && n < best)) {
                    best = n;
                    best_d2 = d2;
                }
            });
            self.alive.push(!dead);
            self.alive_count += usize::from(!dead);
            self.closest.push(best);
            self.closest_d2.push(best_d2);
        }
    }

    /// Add a node: it becomes the closest node of the live markers it is nearer to, and kills
    /// those within the kill distance.
    fn add_node(&mut self, node: Node) {
        let id = self.nodes.len() as u32;
        self.nodes.push(node);
        self.node_grid.insert(id, node.pos);
        let (influence2, kill2) = (self.s.influence * self.s.influence, self.s.kill * self.s.kill);
        let (markers, alive, closest, closest_d2) =
            (&self.markers, &mut self.alive, &mut self.closest, &mut self.closest_d2);
        let mut killed = 0;
        self.marker_grid.for_each_near_within(node.pos, self.s.influence, self.s.influence.max(self.s.kill), |m| {
            let m = m as usize;
            if !alive[m] {
                return;
            }
            let d2 = markers[m].distance_squared(node.pos);
            if d2 <= kill2 {
                alive[m] = false;
                killed += 1;
            } else if d2 < influence2 && d2 < closest_d2[m] {
                closest[m] = id;
                closest_d2[m] = d2;
            }
        });
        self.alive_count -= killed;
    }

    /// Whether a node lies within [`CROWDED`] internodes of `p`.
    fn crowded(&self, p: Vec3) -> bool {
        let r = CROWDED * self.s.segment;
        let mut hit = false;
        self.node_grid.for_each_near(p, r, |n| hit |= self.nodes[n as usize].pos.distance_squared(p) < r * r);
        hit
    }

    /// Grow until no marker is left, nothing grows, or `max_iterations` iterations ran. Fails
    /// when more than `max_new` nodes would be new.
    pub fn grow(&mut self, max_iterations: u32) -> Result<(), SylvaError> {
        let mut acc: Vec<Vec3> = Vec::new();
        let mut count: Vec<u32> = Vec::new();
        let mut touched: Vec<u32> = Vec::new();
        for _ in 0..max_iterations {
            if self.alive_count == 0 {
                break;
            }
            acc.resize(self.nodes.len(), Vec3::ZERO);
            count.resize(self.nodes.len(), 0);
            touched.clear();
            for (m, &n) in self.closest.iter().enumerate() {
                if n == EXISTING || !self.alive[m] {
                    continue;
                }
                if count[n as usize] == 0 {
                    touched.push(n);
                }
                count[n as usize] += 1;
                acc[n as usize] += (self.markers[m] - self.nodes[n as usize].pos).normalize_or_zero();
            }
            if touched.is_empty() {
                break;
            }
            self.iterations += 1;
            let mut grown = 0;
            for &n in &touched {
                let sum = std::mem::take(&mut acc[n as usize]);
                let c = std::mem::take(&mut count[n as usize]) as f32;
                if sum.length() < MIN_PULL * c {
                    continue;
                }
                let from = self.nodes[n as usize].pos;
                let to = from + sum.normalize() * self.s.segment;
                if (to.y < GROUND_CLEARANCE && to.y <= from.y) || self.crowded(to) {
                    continue;
                }
                if self.nodes.len() - self.existing >= self.s.max_new {
                    return Err(budget_error(self.s.max_new));
                }
                self.add_node(Node { pos: to, parent: n });
                grown += 1;
            }
            if grown == 0 {
                break;
            }
        }
        Ok(())
    }
}

/// The budget error of paint growth.
pub fn budget_error(max_new: usize) -> SylvaError {
    SylvaError::Budget {
        param: "max_vertices".into(),
        message: format!(
            "paint growth stopped at {max_new} new nodes, all the max_vertices budget leaves for them: \
             paint a smaller or sparser stroke (lower its density, raise its segment), or raise Max Vertices"
        ),
    }
}
