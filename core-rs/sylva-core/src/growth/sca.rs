//! Space colonization (Runions, Lane & Prusinkiewicz 2007, *Modeling Trees with a Space
//! Colonization Algorithm*). Markers (attraction points) fill the crown; each iteration every
//! marker attracts its closest node within the influence radius, every attracted node grows one
//! internode toward the normalised sum of unit vectors to its markers (plus tropism and jitter),
//! and markers within the kill distance of a node die. Growth stops when no marker is left, nothing
//! grows, or the iteration cap is hit.
//!
//! Speed: each marker remembers its closest node and is updated only when a node appears within
//! its influence radius (a uniform grid finds those markers), so an iteration costs one pass over
//! the live markers plus a grid query per new node; nothing is all-pairs. A query leaves out the
//! grid cells beyond its reach, and a new marker's search for its closest node reaches no
//! further than the nearest node in its own cell ([`Grid::for_each_near_within`]): the same
//! nodes decide, in the same order, so the tree is the same.
//!
//! Botany on top: apical control (interior nodes sprout less often than tips), light competition
//! (a shoot is rejected if the canopy above or beside it is higher by more than the shade
//! depth, as in the "sunny tree"), exclusion volumes that stop branches, and new markers added
//! during growth for bushier interiors.

use super::grid::Grid;
use super::volume::Environment;
use crate::error::SylvaError;
use crate::rng::Rng;
use glam::Vec3;

/// The budget error for growth.
pub fn node_budget_error(max: usize) -> SylvaError {
    SylvaError::Budget {
        param: "max_vertices".into(),
        message: format!(
            "growth stopped at {max} nodes (a quarter of the max_vertices budget): \
             lower Markers, Iterations or Extra Markers, raise Internode, or raise Max Vertices"
        ),
    }
}

/// Smallest mean resultant length of a node's marker directions that still makes it grow.
const MIN_PULL: f32 = 0.2;

/// `parent` of a root node.
pub const ROOT: u32 = u32::MAX;

/// One internode end: a point of the branching skeleton.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// Position (m).
    pub pos: Vec3,
    /// Index of the parent node, or [`ROOT`].
    pub parent: u32,
    /// Iteration in which the node grew (0 for the start points).
    pub born: u32,
}

/// Growth settings (defaults and ranges live in the parameter registry).
#[derive(Clone, Debug)]
pub struct GrowthConfig {
    /// Number of markers sampled in the crown at the start.
    pub markers: usize,
    /// -1 toward the crown axis, 1 toward its surface.
    pub surface_bias: f32,
    /// -1 toward the crown bottom, 1 toward its top.
    pub top_bias: f32,
    /// A marker attracts nodes closer than this (m).
    pub influence: f32,
    /// A marker dies when a node comes this close (m).
    pub kill: f32,
    /// Length of one growth step (m).
    pub internode: f32,
    /// Iteration cap.
    pub iterations: u32,
    /// Upward (positive) or downward (negative) pull added to every growth direction.
    pub tropism: f32,
    /// Random deviation of growth directions (0 = none).
    pub jitter: f32,
    /// Probability that a node which already has a child does not sprout again this iteration.
    pub apical_control: f32,
    /// Where trunks start (y = 0).
    pub starts: Vec<Vec3>,
    /// Markers added per 1,000 iterations while growing.
    pub extra_markers_per_1000: f32,
    /// Light competition: reject shoots shaded by more than this many internodes (None = off).
    pub shade_depth: Option<f32>,
    /// Most nodes allowed before growth stops with a budget error.
    pub max_nodes: usize,
}

/// The result of growth.
#[derive(Clone, Debug, Default)]
pub struct Growth {
    /// All nodes, parents before children.
    pub nodes: Vec<Node>,
    /// The markers sampled at the start (for display).
    pub markers: Vec<Vec3>,
    /// Iterations actually run.
    pub iterations: u32,
}

struct Light {
    min: Vec3,
    inv: f32,
    dims: [usize; 2],
    top: Vec<f32>,
    depth: f32,
}

impl Light {
    fn cell(&self, p: Vec3) -> (usize, usize) {
        let x = (((p.x - self.min.x) * self.inv).max(0.0) as usize).min(self.dims[0] - 1);
        let z = (((p.z - self.min.z) * self.inv).max(0.0) as usize).min(self.dims[1] - 1);
        (x, z)
    }
    fn add(&mut self, p: Vec3) {
        let (x, z) = self.cell(p);
        let t = &mut self.top[z * self.dims[0] + x];
        *t = t.max(p.y);
    }
    /// Shaded: the canopy in this cell or a neighbour (left, right, front, behind) is higher than
    /// `p` by more than the shade depth.
    fn shaded(&self, p: Vec3) -> bool {
        let (x, z) = self.cell(p);
        let cells = [(x, z), (x.wrapping_sub(1), z), (x + 1, z), (x, z.wrapping_sub(1)), (x, z + 1)];
        cells.iter().any(|&(cx, cz)| {
            cx < self.dims[0] && cz < self.dims[1] && self.top[cz * self.dims[0] + cx] > p.y + self.depth
        })
    }
}

/// Everything that changes while the tree grows.
struct State {
    nodes: Vec<Node>,
    children: Vec<u16>,
    /// The markers sampled at the start, kept for display.
    initial: Vec<Vec3>,
    markers: Vec<Vec3>,
    alive: Vec<bool>,
    alive_count: usize,
    /// Closest node within the influence radius of each marker, and its squared distance.
    closest: Vec<u32>,
    closest_d2: Vec<f32>,
    node_grid: Grid,
    marker_grid: Grid,
    /// Markers in `marker_grid` (live or dead); rebuilt from the live ones when mostly dead.
    in_grid: Vec<u32>,
    grid_box: (Vec3, Vec3, f32),
    light: Option<Light>,
    influence: f32,
    influence2: f32,
    kill2: f32,
    /// The larger of the influence and kill distances: the queries' reach.
    within: f32,
}

impl State {
    /// Add a node: it becomes the closest node of the markers it is nearer to, and kills the
    /// markers within the kill distance.
    fn add_node(&mut self, node: Node) -> u32 {
        let id = self.nodes.len() as u32;
        if node.parent != ROOT {
            let c = &mut self.children[node.parent as usize];
            *c = c.saturating_add(1);
        }
        self.nodes.push(node);
        self.children.push(0);
        self.node_grid.insert(id, node.pos);
        if let Some(l) = self.light.as_mut() {
            l.add(node.pos);
        }
        let (markers, alive, closest, closest_d2) =
            (&self.markers, &mut self.alive, &mut self.closest, &mut self.closest_d2);
        let mut killed = 0;
        let in_grid = &self.in_grid;
        // Every marker within the influence or kill distance, as the plain visit finds them.
        self.marker_grid.for_each_near_within(node.pos, self.influence, self.within, |g| {
            let m = in_grid[g as usize] as usize;
            if !alive[m] {
                return;
            }
            let d2 = markers[m].distance_squared(node.pos);
            if d2 <= self.kill2 {
                alive[m] = false;
                killed += 1;
            } else if d2 < self.influence2 && d2 < closest_d2[m] {
                closest[m] = id;
                closest_d2[m] = d2;
            }
        });
        self.alive_count -= killed;
        id
    }

    /// Rebuild the marker grid from the live markers once most of its entries are dead, so
    /// queries stop wading through them.
    fn compact_markers(&mut self) {
        if self.alive_count * 2 >= self.in_grid.len() {
            return;
        }
        let (lo, hi, cell) = self.grid_box;
        let mut grid = Grid::new(lo, hi, cell, 160);
        self.in_grid.retain(|&m| self.alive[m as usize]);
        for (g, &m) in self.in_grid.iter().enumerate() {
            grid.insert(g as u32, self.markers[m as usize]);
        }
        self.marker_grid = grid;
    }

    /// Add a marker during growth, associated with its closest node (or dead at once if a node
    /// is already within the kill distance).
    fn add_marker(&mut self, p: Vec3) {
        let id = self.markers.len();
        self.markers.push(p);
        self.marker_grid.insert(self.in_grid.len() as u32, p);
        self.in_grid.push(id as u32);
        let (mut best, mut best_d2, mut dead) = (ROOT, f32::INFINITY, false);
        let nodes = &self.nodes;
        // Only the nearest nodes decide (the first nearest in the grid's order, and whether it
        // is within the kill distance): the search reaches no further than the nearest node in
        // the marker's own cell.
        let within = nearest_bound(&self.node_grid, nodes, p).min(self.within);
        self.node_grid.for_each_near_within(p, self.influence, within, |n| {
            let d2 = nodes[n as usize].pos.distance_squared(p);
            dead |= d2 <= self.kill2;
            if d2 < self.influence2 && d2 < best_d2 {
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

/// The distance from `p` to the nearest of `nodes` in `p`'s own cell of `grid` (infinite when
/// the cell is empty): no node nearer than that lies beyond it.
fn nearest_bound(grid: &Grid, nodes: &[Node], p: Vec3) -> f32 {
    let mut d2 = f32::INFINITY;
    grid.for_each_in_cell(p, |n| d2 = d2.min(nodes[n as usize].pos.distance_squared(p)));
    d2.sqrt()
}

/// Iterations between two progress reports of [`grow_with_progress`].
pub const PROGRESS_EVERY: u32 = 16;

/// Grow a tree. Fails only when the node budget is exceeded.
pub fn grow(env: &Environment, cfg: &GrowthConfig, rng: &mut Rng) -> Result<Growth, SylvaError> {
    grow_with_progress(env, cfg, rng, None)
}

/// [`grow`], calling `progress` with the fraction of the iteration cap run so far every
/// [`PROGRESS_EVERY`] iterations (it only observes: the tree is the same with or without it).
pub fn grow_with_progress(
    env: &Environment,
    cfg: &GrowthConfig,
    rng: &mut Rng,
    mut progress: Option<&mut dyn FnMut(f32)>,
) -> Result<Growth, SylvaError> {
    let markers = env.sample_markers(cfg.markers, cfg.surface_bias, cfg.top_bias, rng);
    let mut st = State::new(env, cfg, markers);
    let mut leaders: Vec<u32> =
        cfg.starts.iter().map(|s| st.add_node(Node { pos: *s, parent: ROOT, born: 0 })).collect();
    let mut pulls = Pulls::default();
    let mut extra_carry = 0.0f32;
    let mut iterations = 0;
    let mut attracted_once = false;
    for iter in 1..=cfg.iterations {
        iterations = iter;
        if iter % PROGRESS_EVERY == 0 {
            if let Some(report) = progress.as_mut() {
                report(iter as f32 / cfg.iterations as f32);
            }
        }
        // With markers added during growth, a pause (no live marker, nothing grew) is not the end.
        let replenishing = cfg.extra_markers_per_1000 > 0.0;
        if st.alive_count == 0 && !replenishing {
            break;
        }
        // 1. Each live marker pulls its closest node.
        st.pull(&mut pulls);
        let mut grown = 0usize;
        if pulls.touched.is_empty() {
            if attracted_once && !replenishing {
                break; // the markers left are out of every node's reach
            }
            // 2a. No marker in reach yet: the trunks rise straight toward the crown.
            for leader in leaders.iter_mut().filter(|_| !attracted_once) {
                let from = st.nodes[*leader as usize].pos;
                let to = from + Vec3::Y * cfg.internode;
                if env.segment_allowed(from, to) {
                    *leader = st.add_node(Node { pos: to, parent: *leader, born: iter });
                    grown += 1;
                }
            }
        } else {
            attracted_once = true;
            grown = st.grow_attracted(&mut pulls, env, cfg, rng, iter)?;
        }
        st.compact_markers();
        // 3. New markers during growth make bushier interiors.
        extra_carry += cfg.extra_markers_per_1000 / 1000.0;
        while extra_carry >= 1.0 {
            extra_carry -= 1.0;
            if let Some(p) = env.sample_markers(1, cfg.surface_bias, cfg.top_bias, rng).pop() {
                st.add_marker(p);
            }
        }
        if grown == 0 && attracted_once && !replenishing {
            break;
        }
    }
    Ok(Growth { nodes: st.nodes, markers: st.initial, iterations })
}

/// The markers' pulls of one iteration, per node: the summed unit vectors toward its markers,
/// how many pull it, and the pulled nodes in marker order.
#[derive(Default)]
struct Pulls {
    acc: Vec<Vec3>,
    count: Vec<u32>,
    touched: Vec<u32>,
}

impl State {
    /// The state before growth: both grids over the crown and the start points (with a margin
    /// of an influence radius and an internode), the `markers` sampled in the crown, and the
    /// light field when light competition is on.
    fn new(env: &Environment, cfg: &GrowthConfig, markers: Vec<Vec3>) -> State {
        let crown = env.bounds();
        let mut lo = crown.min.min(Vec3::ZERO);
        let mut hi = crown.max.max(Vec3::ZERO);
        for s in &cfg.starts {
            lo = lo.min(*s);
            hi = hi.max(*s);
        }
        let margin = Vec3::splat(cfg.influence + cfg.internode);
        let (lo, hi) = (lo - margin, hi + margin);
        // Half the query radius per cell: a query visits about 4x the sphere's volume, not 6x.
        let cell = 0.5 * cfg.influence.max(cfg.kill);
        let mut marker_grid = Grid::new(lo, hi, cell, 160);
        for (i, m) in markers.iter().enumerate() {
            marker_grid.insert(i as u32, *m);
        }
        let light = cfg.shade_depth.map(|depth| {
            let cell = 2.0 * cfg.internode;
            let dims = [(((hi.x - lo.x) / cell) as usize + 1).min(512), (((hi.z - lo.z) / cell) as usize + 1).min(512)];
            let inv = (dims[0] as f32 / (hi.x - lo.x)).min(dims[1] as f32 / (hi.z - lo.z));
            Light { min: lo, inv, dims, top: vec![f32::NEG_INFINITY; dims[0] * dims[1]], depth: depth * cfg.internode }
        });
        let count = markers.len();
        State {
            nodes: Vec::new(),
            children: Vec::new(),
            initial: markers.clone(),
            markers,
            alive: vec![true; count],
            alive_count: count,
            closest: vec![ROOT; count],
            closest_d2: vec![f32::INFINITY; count],
            node_grid: Grid::new(lo, hi, cell, 160),
            marker_grid,
            in_grid: (0..count as u32).collect(),
            grid_box: (lo, hi, cell),
            light,
            influence: cfg.influence,
            influence2: cfg.influence * cfg.influence,
            kill2: cfg.kill * cfg.kill,
            within: cfg.influence.max(cfg.kill),
        }
    }

    /// Step 1: each live marker pulls its closest node.
    fn pull(&self, pulls: &mut Pulls) {
        pulls.acc.resize(self.nodes.len(), Vec3::ZERO);
        pulls.count.resize(self.nodes.len(), 0);
        pulls.touched.clear();
        for (m, &n) in self.closest.iter().enumerate() {
            if n == ROOT || !self.alive[m] {
                continue;
            }
            if pulls.count[n as usize] == 0 {
                pulls.touched.push(n);
            }
            pulls.count[n as usize] += 1;
            pulls.acc[n as usize] += (self.markers[m] - self.nodes[n as usize].pos).normalize_or_zero();
        }
    }

    /// Step 2b: the attracted nodes grow one internode toward their markers (in marker order:
    /// deterministic), bent by jitter and tropism, unless their pull is too weak, apical control
    /// holds them back, or the shoot would leave the volumes or stand in the shade. Returns how
    /// many grew; fails when the node budget is exceeded.
    fn grow_attracted(
        &mut self,
        pulls: &mut Pulls,
        env: &Environment,
        cfg: &GrowthConfig,
        rng: &mut Rng,
        iter: u32,
    ) -> Result<usize, SylvaError> {
        let mut grown = 0;
        for &n in &pulls.touched {
            let sum = std::mem::take(&mut pulls.acc[n as usize]);
            let count = std::mem::take(&mut pulls.count[n as usize]) as f32;
            // Markers on opposite sides cancel out: a weak mean pull would only make the tip
            // orbit between them, so it does not grow (MIN_PULL of the mean resultant).
            if sum.length() < MIN_PULL * count {
                continue;
            }
            let mut dir = sum.normalize_or_zero();
            if cfg.apical_control > 0.0 && self.children[n as usize] > 0 && rng.next_f32() < cfg.apical_control {
                continue;
            }
            if cfg.jitter > 0.0 {
                let j = Vec3::new(rng.var(1.0), rng.var(1.0), rng.var(1.0));
                dir = (dir + j * cfg.jitter).normalize_or(dir);
            }
            dir = (dir + Vec3::Y * cfg.tropism).normalize_or(dir);
            if self.nodes[n as usize].parent == ROOT {
                dir = Vec3::Y; // a trunk leaves the ground vertically (its base ring stays level)
            }
            let from = self.nodes[n as usize].pos;
            let to = from + dir * cfg.internode;
            if !env.segment_allowed(from, to) || self.light.as_ref().is_some_and(|l| l.shaded(to)) {
                continue;
            }
            if self.nodes.len() >= cfg.max_nodes {
                return Err(node_budget_error(cfg.max_nodes));
            }
            self.add_node(Node { pos: to, parent: n, born: iter });
            grown += 1;
        }
        Ok(grown)
    }
}
