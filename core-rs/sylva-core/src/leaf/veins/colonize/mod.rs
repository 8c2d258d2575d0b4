//! # Vein growth by space colonization
//!
//! Space colonization of the blade (Runions et al. 2005, *Modeling and Visualization of Leaf Venation Patterns*).
//!
//! Each iteration: (1) every live auxin source pulls the vein nodes it is associated with;
//! (2) every pulled node grows one step `D` toward the normalised sum of the unit vectors to its
//! sources (plus a little seeded jitter, so a node between two sources does not stall), unless
//! the step leaves the blade or lands on an existing node; (3) the new nodes update the
//! associations and kill sources. Association:
//!
//! * **Open**: a source associates with its closest node within the attraction distance and
//!   dies when any node comes within the kill distance. The network is a tree.
//! * **Closed**: a source associates with every node in its *relative neighbourhood* (node `v`
//!   within the attraction distance such that no node `u` is closer both to the source and to
//!   `v`), nodes stop growing toward it once within the kill distance, and it dies only when all
//!   of them have arrived; arrivals from different veins (more than six nodes apart along the
//!   tree) are joined by a link, closing a loop.
//!
//! Associations are updated incrementally: only a new node can change a source's closest node
//! or neighbourhood, so each new node visits the sources in the grid cells within the
//! attraction distance ([`super::grid`]), never all pairs.
//!
//! Growth never stalls: an **apex source** at the tip `(0, 1)` always pulls its closest node
//! (whatever the distance, with three times a source's weight, which keeps the midrib straight)
//! until a vein reaches it, so the midrib ends within the kill distance
//! (at most 0.05) of the tip; when nothing can grow but sources remain out of reach (sparse
//! sources), each is associated with its nearest node whatever the distance; after an iteration
//! without growth each node follows only its nearest source (so one caught between sources picks
//! one); a step that would leave the blade turns along the margin (up to about 60°); sources
//! whose nodes still cannot grow toward them after four tries are dropped.

mod association;

use super::graph::{Auxin, VeinGraph, VeinLink, VeinNode, Veins, NONE};
use super::grid::{DynGrid, GridSpec, StaticGrid};
use crate::leaf::raster::Mask;
use crate::rng::Rng;
use association::{Neighbourhood, EMPTY};
use glam::Vec2;
use std::collections::BTreeSet;

/// Space colonization distances, in leaf lengths (the registry checks the ranges).
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Attraction distance `d_a` (`leaf_attraction`): default 0.08, 0.005 to 0.5, above `kill`.
    pub attraction: f32,
    /// Kill distance `d_k` (`leaf_kill`): default 0.02, 0.002 to 0.05.
    pub kill: f32,
    /// Growth step `D` (`leaf_growth_step`): default 0.01, 0.002 to 0.05.
    pub step: f32,
    /// Closed venation (relative neighbourhoods and loops) instead of open: default `false`
    /// (`leaf_venation` Open).
    pub closed: bool,
}

/// Random deviation of each growth step's direction.
const JITTER: f32 = 0.08;
/// Weight of the apex source's pull (the others pull with 1): keeps the midrib straight.
const APEX_PULL: f32 = 3.0;
/// Most vein nodes grown.
const MAX_NODES: usize = 200_000;
/// Iterations without growth before the pulling sources are given up.
const STALL_RETRIES: u32 = 4;
/// `(cos, sin)` of the step's turns tried in order when a step would leave the blade:
/// 0, ±0.5 and ±1 radian.
const TURNS: [(f32, f32); 5] = [
    (1.0, 0.0),
    (0.877_582_6, 0.479_425_55),
    (0.877_582_6, -0.479_425_55),
    (0.540_302_3, 0.841_470_96),
    (0.540_302_3, -0.841_470_96),
];

/// The pulls gathered in one iteration, per vein node: the summed pull of its sources (after a
/// stall, the nearest source's alone) and the squared distance of the nearest.
#[derive(Default)]
struct Pulls {
    acc: Vec<Vec2>,
    best: Vec<f32>,
    marked: Vec<bool>,
    /// The nodes pulled this iteration, in the order they were first pulled.
    touched: Vec<u32>,
}

impl Pulls {
    /// Room for one more node.
    fn push(&mut self) {
        self.acc.push(Vec2::ZERO);
        self.best.push(0.0);
        self.marked.push(false);
    }

    /// Adds source pull `d` (squared distance `d2`) to node `v`; in `direct` mode (after a
    /// stall) keeps only the nearest source's pull, so a node caught between sources picks one.
    #[inline]
    fn add(&mut self, v: u32, d: Vec2, d2: f32, direct: bool) {
        let i = v as usize;
        if !self.marked[i] {
            self.marked[i] = true;
            self.touched.push(v);
            self.acc[i] = d;
            self.best[i] = d2;
        } else if !direct {
            self.acc[i] += d;
        } else if d2 < self.best[i] {
            self.acc[i] = d;
            self.best[i] = d2;
        }
    }

    /// Node `v`'s pull, reset for the next iteration.
    fn take(&mut self, v: u32) -> Vec2 {
        self.marked[v as usize] = false;
        std::mem::take(&mut self.acc[v as usize])
    }
}

/// Everything that changes while the veins grow: the sources (index 0 is the apex source), the
/// vein nodes, the associations between them and the loops closed so far.
struct State {
    s: Settings,
    /// Squared attraction and kill distances.
    a2: f32,
    k2: f32,
    /// Source positions.
    src: Vec<Vec2>,
    /// `src` with dead sources moved far away, so the grid scan needs no liveness test.
    scan: Vec<Vec2>,
    alive: Vec<bool>,
    alive_count: usize,
    /// Iteration each source was reached in (`NONE`: never).
    killed_at: Vec<u32>,
    /// Open venation: each source's closest node within reach, and its squared distance.
    assoc: Vec<u32>,
    assoc_d2: Vec<f32>,
    /// Sources associated with their nearest node whatever the distance (the apex, sparse
    /// sources after a stall), and the list of them.
    far: Vec<bool>,
    far_list: Vec<u32>,
    /// Closed venation: each source's relative neighbourhood.
    rn: Vec<Neighbourhood>,
    /// The sources that pull this iteration.
    active: Vec<u32>,
    in_active: Vec<bool>,
    /// Closed venation: sources with a node within the kill distance, to try closing.
    check: Vec<u32>,
    /// Scratch of the grid scan: (source, squared distance), one slot per source.
    hits: Vec<(u32, f32)>,
    /// The vein nodes: position, parent, iteration born and depth along the tree.
    pos: Vec<Vec2>,
    parent: Vec<u32>,
    born: Vec<u32>,
    depth: Vec<u32>,
    pulls: Pulls,
    links: Vec<VeinLink>,
    link_set: BTreeSet<(u32, u32)>,
    iter: u32,
}

/// What an iteration without growth leads to.
enum Stall {
    /// Try again: the jitter changes each step's direction.
    Retry,
    /// The sources whose nodes cannot grow were given up.
    Dropped,
    /// With none pulling, the sources out of reach are associated with their nearest nodes.
    Reaching,
    /// No source is left.
    Done,
}

/// Grows the veins from the petiole `(0, 0)` toward `sources` inside `mask`; the returned
/// auxins list the apex source first, then `sources` (in grid-cell order), with the iteration each was reached in.
pub fn grow(s: &Settings, mask: &Mask, sources: &[Vec2], rng: &mut Rng) -> Veins {
    grow_from(s, mask, sources, &super::primary::root(), rng)
}

/// [`grow`] from given primary veins (`seed`: a tree rooted at the petiole, parents before
/// children, see [`super::primary`]) instead of the petiole alone. Growth iterations continue
/// after the seed's last `born`; with more than the root, the apex source is not used (the
/// primaries are the main veins) and sources near the primaries die at once.
pub fn grow_from(s: &Settings, mask: &Mask, sources: &[Vec2], seed: &VeinGraph, rng: &mut Rng) -> Veins {
    let (mut st, grid, mut nodes_grid) = State::new(s, sources, seed);
    let max_iter = st.iter + (8.0 / s.step) as u32 + 200;
    let mut last_growth = st.iter;
    let mut fallback = false;
    let mut stalls = 0;
    let mut new_nodes: Vec<u32> = Vec::new();
    while st.alive_count > 0 && st.iter < max_iter && st.pos.len() < MAX_NODES {
        st.iter += 1;
        // (1) Pull (after a stall, each node follows only its nearest source).
        st.pull(stalls > 0);
        // (2) Grow.
        st.grow_nodes(mask, &mut nodes_grid, rng, &mut new_nodes);
        // (3) Associate and kill.
        for &u in &new_nodes {
            st.new_node(&grid, u);
        }
        let links_before = st.links.len();
        for c in std::mem::take(&mut st.check) {
            st.try_close(c, false);
        }
        if !new_nodes.is_empty() || st.links.len() > links_before {
            last_growth = st.iter;
            stalls = 0;
            continue;
        }
        stalls += 1;
        match st.stall(stalls, &nodes_grid) {
            Stall::Retry => {}
            Stall::Dropped if st.links.len() > links_before => last_growth = st.iter,
            Stall::Dropped => {}
            Stall::Reaching => fallback = true,
            Stall::Done => break,
        }
    }
    st.into_veins(last_growth, fallback)
}

impl State {
    /// The state before growth, with the grids of the sources (in grid-cell order) and of the
    /// nodes: the apex source first, then the sources; the petiole's node, then the seed's.
    fn new(s: &Settings, sources: &[Vec2], seed: &VeinGraph) -> (State, StaticGrid, DynGrid) {
        let root = Vec2::ZERO;
        let apex = Vec2::new(0.0, 1.0);
        let (mut lo, mut hi) = (root.min(apex), root.max(apex));
        for p in sources.iter().chain(seed.nodes.iter().map(|n| &n.pos)) {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        let (lo, hi) = (lo - Vec2::splat(s.step * 2.0), hi + Vec2::splat(s.step * 2.0));
        // Sources in grid-cell order: a query reads consecutive memory.
        let mut sorted = sources.to_vec();
        let (grid, _) = StaticGrid::sorted(GridSpec::new(lo, hi, 0.25 * s.attraction), &mut sorted);
        let mut src = Vec::with_capacity(sources.len() + 1);
        src.push(apex);
        src.extend_from_slice(&sorted);
        let mut nodes_grid = DynGrid::new(GridSpec::new(lo, hi, s.step));
        let n = src.len();
        let mut st = State {
            s: *s,
            a2: s.attraction * s.attraction,
            k2: s.kill * s.kill,
            alive: vec![true; n],
            alive_count: n,
            killed_at: vec![NONE; n],
            assoc: vec![NONE; n],
            assoc_d2: vec![s.attraction * s.attraction; n],
            far: vec![false; n],
            far_list: vec![0],
            rn: if s.closed { vec![EMPTY; n] } else { Vec::new() },
            active: Vec::new(),
            in_active: vec![false; n],
            check: Vec::new(),
            hits: vec![(0, 0.0); src.len() + 1],
            scan: src.clone(),
            src,
            pos: vec![root],
            parent: vec![NONE],
            born: vec![0],
            depth: vec![0],
            pulls: Pulls::default(),
            links: Vec::new(),
            link_set: BTreeSet::new(),
            iter: 0,
        };
        st.pulls.push();
        // The apex source: always associated with its closest node, whatever the distance.
        st.far[0] = true;
        st.assoc[0] = 0;
        st.assoc_d2[0] = apex.length_squared();
        st.activate(0);
        nodes_grid.push(0, root);
        st.new_node(&grid, 0);
        if seed.nodes.len() > 1 {
            st.kill(0, false);
        }
        for n in seed.nodes.iter().skip(1) {
            let u = st.push_node(&mut nodes_grid, n.pos, n.parent, n.born);
            st.new_node(&grid, u);
            st.iter = st.iter.max(n.born);
        }
        (st, grid, nodes_grid)
    }

    /// Adds a vein node at `p` (a child of `parent`, born in iteration `born`); returns its id.
    fn push_node(&mut self, nodes_grid: &mut DynGrid, p: Vec2, parent: u32, born: u32) -> u32 {
        let u = self.pos.len() as u32;
        self.pos.push(p);
        self.parent.push(parent);
        self.born.push(born);
        self.depth.push(self.depth[parent as usize] + 1);
        self.pulls.push();
        nodes_grid.push(u, p);
        u
    }

    /// Step 1: every live active source pulls the nodes it is associated with (`direct`: after
    /// a stall, each node keeps its nearest source's pull only).
    fn pull(&mut self, direct: bool) {
        let active = std::mem::take(&mut self.active);
        let mut kept = Vec::with_capacity(active.len());
        for &a in &active {
            let si = a as usize;
            if !self.alive[si] {
                self.in_active[si] = false;
                continue;
            }
            kept.push(a);
            let sp = self.src[si];
            if self.s.closed && !self.far[si] {
                let nb = &self.rn[si];
                for k in 0..nb.len as usize {
                    let (v, l2) = (nb.id[k], nb.d[k]);
                    if l2 >= self.k2 {
                        let d = sp - nb.pos[k];
                        self.pulls.add(v, d / l2.sqrt(), l2, direct);
                    }
                }
            } else if self.assoc[si] != NONE {
                let v = self.assoc[si];
                let d = sp - self.pos[v as usize];
                let l = d.length_squared().sqrt();
                if l > 0.0 {
                    let w = if a == 0 { APEX_PULL } else { 1.0 };
                    self.pulls.add(v, d * (w / l), l * l, direct);
                }
            }
        }
        self.active = kept;
    }

    /// Step 2: every pulled node grows one step toward its pull (with a little jitter) into
    /// `new_nodes`, unless the step leaves the blade (it slides along the margin instead, turned
    /// by up to about 60° either way) or lands on an existing node.
    fn grow_nodes(&mut self, mask: &Mask, nodes_grid: &mut DynGrid, rng: &mut Rng, new_nodes: &mut Vec<u32>) {
        let step = self.s.step;
        let dup = 0.25 * step;
        new_nodes.clear();
        let touched = std::mem::take(&mut self.pulls.touched);
        for &v in &touched {
            let a = self.pulls.take(v);
            let len = a.length_squared().sqrt();
            let base = if len > 1e-6 { a / len } else { Vec2::new(rng.var(1.0), rng.var(1.0)) };
            let dir = base + Vec2::new(rng.var(JITTER), rng.var(JITTER));
            let dl = dir.length_squared().sqrt();
            if dl <= 1e-6 {
                continue;
            }
            let dir = dir / dl;
            let from = self.pos[v as usize];
            let Some(p) = TURNS
                .iter()
                .map(|&(c, sn)| from + Vec2::new(c * dir.x - sn * dir.y, sn * dir.x + c * dir.y) * step)
                .find(|&q| mask.contains(q))
            else {
                continue;
            };
            if nodes_grid.any_near(p, dup, |id| (self.pos[id as usize] - p).length_squared() < dup * dup) {
                continue;
            }
            new_nodes.push(self.push_node(nodes_grid, p, v, self.iter));
        }
        self.pulls.touched = touched;
        self.pulls.touched.clear();
    }

    /// An iteration without growth (the `stalls`-th in a row): after a few tries, drop the
    /// sources whose nodes cannot grow toward them; with none pulling, reach for the sources
    /// out of reach (sparse sources) from their nearest nodes.
    fn stall(&mut self, stalls: u32, nodes_grid: &DynGrid) -> Stall {
        let stuck: Vec<u32> = self.active.iter().copied().filter(|&a| self.alive[a as usize]).collect();
        if !stuck.is_empty() && stalls < STALL_RETRIES {
            return Stall::Retry;
        }
        if !stuck.is_empty() {
            for a in stuck {
                if self.s.closed && !self.far[a as usize] {
                    self.try_close(a, true);
                } else {
                    self.kill(a, false);
                }
            }
            return Stall::Dropped;
        }
        let mut reached = false;
        for si in 1..self.src.len() {
            if !self.alive[si] {
                continue;
            }
            let (best, bd) = nodes_grid.nearest(self.src[si], &self.pos);
            self.far[si] = true;
            if self.s.closed {
                self.rn[si].len = 0;
            }
            self.assoc[si] = best;
            self.assoc_d2[si] = bd;
            self.far_list.push(si as u32);
            self.activate(si as u32);
            reached = true;
        }
        if reached {
            Stall::Reaching
        } else {
            Stall::Done
        }
    }

    /// The grown veins and the sources with the iteration each was reached in.
    fn into_veins(self, iterations: u32, fallback: bool) -> Veins {
        let nodes = (0..self.pos.len())
            .map(|i| VeinNode { pos: self.pos[i], parent: self.parent[i], born: self.born[i], width: 0.0, tips: 0 })
            .collect();
        let auxins = self.src.iter().zip(&self.killed_at).map(|(&pos, &killed_at)| Auxin { pos, killed_at }).collect();
        Veins { graph: VeinGraph { nodes, links: self.links, iterations, fallback }, auxins }
    }
}
