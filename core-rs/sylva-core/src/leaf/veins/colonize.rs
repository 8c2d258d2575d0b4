//! Space colonization of the blade (Runions et al. 2005; ANCHORS §4).
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

use super::grid::{DynGrid, GridSpec, StaticGrid};
use super::{Auxin, VeinGraph, VeinLink, VeinNode, Veins, NONE};
use crate::leaf::raster::Mask;
use crate::rng::Rng;
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

const RN_MAX: usize = 6;
/// Where dead sources move in the scan copy (squared distances stay finite).
const FAR: f32 = 1e18;
const LOOP_MIN_HOPS: u32 = 6;
const JITTER: f32 = 0.08;
/// Weight of the apex source's pull (the others pull with 1): keeps the midrib straight.
const APEX_PULL: f32 = 3.0;
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

/// The vein nodes in a source's relative neighbourhood, with their squared distances to the
/// source and positions (kept here so updates touch one small block of memory).
#[derive(Clone, Copy)]
struct Neighbourhood {
    len: u8,
    id: [u32; RN_MAX],
    d: [f32; RN_MAX],
    pos: [Vec2; RN_MAX],
}

const EMPTY: Neighbourhood = Neighbourhood { len: 0, id: [NONE; RN_MAX], d: [0.0; RN_MAX], pos: [Vec2::ZERO; RN_MAX] };

struct State {
    s: Settings,
    a2: f32,
    k2: f32,
    src: Vec<Vec2>,
    /// `src` with dead sources moved far away, so the grid scan needs no liveness test.
    scan: Vec<Vec2>,
    alive: Vec<bool>,
    alive_count: usize,
    killed_at: Vec<u32>,
    assoc: Vec<u32>,
    assoc_d2: Vec<f32>,
    far: Vec<bool>,
    far_list: Vec<u32>,
    /// Closed venation: each source's relative neighbourhood.
    rn: Vec<Neighbourhood>,
    active: Vec<u32>,
    in_active: Vec<bool>,
    check: Vec<u32>,
    hits: Vec<(u32, f32)>,
    pos: Vec<Vec2>,
    parent: Vec<u32>,
    born: Vec<u32>,
    depth: Vec<u32>,
    acc: Vec<Vec2>,
    best: Vec<f32>,
    marked: Vec<bool>,
    touched: Vec<u32>,
    links: Vec<VeinLink>,
    link_set: BTreeSet<(u32, u32)>,
    iter: u32,
}

impl State {
    fn activate(&mut self, s: u32) {
        if !self.in_active[s as usize] {
            self.in_active[s as usize] = true;
            self.active.push(s);
        }
    }

    fn kill(&mut self, s: u32, reached: bool) {
        if self.alive[s as usize] {
            self.alive[s as usize] = false;
            self.scan[s as usize] = Vec2::splat(FAR);
            self.alive_count -= 1;
            if reached {
                self.killed_at[s as usize] = self.iter;
            }
        }
    }

    /// Relative-neighbourhood update of source `s` for the new node `u` at squared distance
    /// `du`: drops the members `u` shadows, adds `u` unless a member shadows it.
    fn rn_update(&mut self, s: u32, u: u32, du: f32) {
        let pu = self.pos[u as usize];
        let nb = &mut self.rn[s as usize];
        let len = nb.len as usize;
        let mut m = 0;
        let mut shadowed = false;
        let mut farthest = (f32::NEG_INFINITY, 0usize);
        for k in 0..len {
            let (v, dv, pv) = (nb.id[k], nb.d[k], nb.pos[k]);
            let duv = (pu - pv).length_squared();
            if du < dv && duv < dv {
                continue;
            }
            shadowed |= dv < du && duv < du;
            if dv > farthest.0 {
                farthest = (dv, m);
            }
            nb.id[m] = v;
            nb.d[m] = dv;
            nb.pos[m] = pv;
            m += 1;
        }
        if !shadowed {
            let slot = if m < RN_MAX {
                m += 1;
                Some(m - 1)
            } else {
                (du < farthest.0).then_some(farthest.1)
            };
            if let Some(k) = slot {
                nb.id[k] = u;
                nb.d[k] = du;
                nb.pos[k] = pu;
            }
        }
        nb.len = m as u8;
        if m > 0 {
            self.activate(s);
        }
    }

    /// Updates associations and kills of source `s` (within the attraction distance, squared
    /// distance `d2`) for the new node `u`.
    fn visit(&mut self, s: u32, u: u32, d2: f32) {
        if self.s.closed {
            if self.far[s as usize] {
                self.far[s as usize] = false;
                self.rn[s as usize].len = 0;
            }
            self.rn_update(s, u, d2);
            if d2 < self.k2 {
                self.check.push(s);
            }
        } else if d2 < self.k2 {
            self.kill(s, true);
        } else if d2 < self.assoc_d2[s as usize] {
            self.assoc[s as usize] = u;
            self.assoc_d2[s as usize] = d2;
            self.far[s as usize] = false;
            self.activate(s);
        }
    }

    fn new_node(&mut self, grid: &StaticGrid, u: u32) {
        let p = self.pos[u as usize];
        for i in 0..self.far_list.len() {
            let s = self.far_list[i];
            if !self.alive[s as usize] || !self.far[s as usize] {
                continue;
            }
            let d2 = (self.src[s as usize] - p).length_squared();
            if d2 < self.k2 {
                self.kill(s, true);
            } else if d2 < self.assoc_d2[s as usize] {
                self.assoc[s as usize] = u;
                self.assoc_d2[s as usize] = d2;
            }
        }
        self.far_list.retain(|&s| self.alive[s as usize] && self.far[s as usize]);
        // Grid ids are source indices minus one (the apex is not in the grid). First a tight
        // filter over consecutive memory, then the updates for the few sources in range.
        let (scan, a2) = (&self.scan[1..], self.a2);
        let hits = &mut self.hits;
        let mut n = 0;
        grid.for_near(p, self.s.attraction, |ids| {
            let first = ids.start as u32 + 1;
            // Branch-free: write every candidate, keep it by advancing only when in range
            // (`hits` holds one slot per source, so it never overflows).
            for (k, &q) in scan[ids].iter().enumerate() {
                let d2 = (q - p).length_squared();
                hits[n] = (first + k as u32, d2);
                n += usize::from(d2 < a2);
            }
        });
        let hits = std::mem::take(&mut self.hits);
        for &(s, d2) in &hits[..n] {
            self.visit(s, u, d2);
        }
        self.hits = hits;
    }

    /// Nodes between `a` and `b` along the tree, or anything above `LOOP_MIN_HOPS`.
    fn hops(&self, a: u32, b: u32) -> u32 {
        let (mut x, mut y, mut h) = (a, b, 0);
        while self.depth[x as usize] > self.depth[y as usize] && h <= LOOP_MIN_HOPS {
            x = self.parent[x as usize];
            h += 1;
        }
        while self.depth[y as usize] > self.depth[x as usize] && h <= LOOP_MIN_HOPS {
            y = self.parent[y as usize];
            h += 1;
        }
        while x != y && h <= LOOP_MIN_HOPS {
            x = self.parent[x as usize];
            y = self.parent[y as usize];
            h += 2;
        }
        h
    }

    /// Closed venation: kills `s` if every node of its neighbourhood has arrived (or `force`),
    /// linking arrivals from different veins.
    fn try_close(&mut self, s: u32, force: bool) {
        if !self.alive[s as usize] || self.far[s as usize] {
            return;
        }
        let mut arrived = [(0.0f32, 0u32); RN_MAX];
        let mut n = 0;
        let nb = self.rn[s as usize];
        for (&v, &d) in nb.id[..nb.len as usize].iter().zip(&nb.d[..nb.len as usize]) {
            if d < self.k2 {
                arrived[n] = (d, v);
                n += 1;
            } else if !force {
                return;
            }
        }
        let arrived = &mut arrived[..n];
        arrived.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        if let Some(&(_, first)) = arrived.first() {
            for &(_, v) in &arrived[1..] {
                let key = (first.min(v), first.max(v));
                if self.hops(first, v) > LOOP_MIN_HOPS && self.link_set.insert(key) {
                    self.links.push(VeinLink { a: key.0, b: key.1, born: self.iter, width: 0.0 });
                }
            }
        }
        self.kill(s, n > 0);
    }
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
        acc: vec![Vec2::ZERO],
        best: vec![0.0],
        marked: vec![false],
        touched: Vec::new(),
        links: Vec::new(),
        link_set: BTreeSet::new(),
        iter: 0,
    };
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
        let u = st.pos.len() as u32;
        st.pos.push(n.pos);
        st.parent.push(n.parent);
        st.born.push(n.born);
        st.depth.push(st.depth[n.parent as usize] + 1);
        st.acc.push(Vec2::ZERO);
        st.best.push(0.0);
        st.marked.push(false);
        nodes_grid.push(u, n.pos);
        st.new_node(&grid, u);
        st.iter = st.iter.max(n.born);
    }
    let first_iter = st.iter;
    let max_iter = first_iter + (8.0 / s.step) as u32 + 200;
    let dup = 0.25 * s.step;
    let mut last_growth = first_iter;
    let mut fallback = false;
    let mut stalls = 0;
    let mut new_nodes: Vec<u32> = Vec::new();
    while st.alive_count > 0 && st.iter < max_iter && st.pos.len() < MAX_NODES {
        st.iter += 1;
        // (1) Pull (after a stall, each node follows only its nearest source).
        let direct = stalls > 0;
        let active = std::mem::take(&mut st.active);
        let mut kept = Vec::with_capacity(active.len());
        for &a in &active {
            let si = a as usize;
            if !st.alive[si] {
                st.in_active[si] = false;
                continue;
            }
            kept.push(a);
            let sp = st.src[si];
            if s.closed && !st.far[si] {
                let nb = &st.rn[si];
                for k in 0..nb.len as usize {
                    let (v, l2) = (nb.id[k], nb.d[k]);
                    if l2 >= st.k2 {
                        let d = sp - nb.pos[k];
                        pull(&mut st.acc, &mut st.best, &mut st.marked, &mut st.touched, v, d / l2.sqrt(), l2, direct);
                    }
                }
            } else if st.assoc[si] != NONE {
                let v = st.assoc[si];
                let d = sp - st.pos[v as usize];
                let l = d.length_squared().sqrt();
                if l > 0.0 {
                    let w = if a == 0 { APEX_PULL } else { 1.0 };
                    pull(&mut st.acc, &mut st.best, &mut st.marked, &mut st.touched, v, d * (w / l), l * l, direct);
                }
            }
        }
        st.active = kept;
        // (2) Grow.
        new_nodes.clear();
        let touched = std::mem::take(&mut st.touched);
        for &v in &touched {
            let a = st.acc[v as usize];
            st.acc[v as usize] = Vec2::ZERO;
            st.marked[v as usize] = false;
            let len = a.length_squared().sqrt();
            let base = if len > 1e-6 { a / len } else { Vec2::new(rng.var(1.0), rng.var(1.0)) };
            let dir = base + Vec2::new(rng.var(JITTER), rng.var(JITTER));
            let dl = dir.length_squared().sqrt();
            if dl <= 1e-6 {
                continue;
            }
            let dir = dir / dl;
            // A step that would leave the blade slides along the margin instead (turned by up to
            // about 60° either way).
            let from = st.pos[v as usize];
            let Some(p) = TURNS
                .iter()
                .map(|&(c, sn)| from + Vec2::new(c * dir.x - sn * dir.y, sn * dir.x + c * dir.y) * s.step)
                .find(|&q| mask.contains(q))
            else {
                continue;
            };
            if nodes_grid.any_near(p, dup, |id| (st.pos[id as usize] - p).length_squared() < dup * dup) {
                continue;
            }
            let u = st.pos.len() as u32;
            st.pos.push(p);
            st.parent.push(v);
            st.born.push(st.iter);
            st.depth.push(st.depth[v as usize] + 1);
            st.acc.push(Vec2::ZERO);
            st.best.push(0.0);
            st.marked.push(false);
            nodes_grid.push(u, p);
            new_nodes.push(u);
        }
        st.touched = touched;
        st.touched.clear();
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
        // Stall: after a few tries (the jitter changes each step's direction), drop the sources
        // whose nodes cannot grow; with none pulling, reach for the sparse sources.
        stalls += 1;
        let stuck: Vec<u32> = st.active.iter().copied().filter(|&a| st.alive[a as usize]).collect();
        if !stuck.is_empty() && stalls < STALL_RETRIES {
            continue;
        }
        if !stuck.is_empty() {
            for a in stuck {
                if s.closed && !st.far[a as usize] {
                    st.try_close(a, true);
                } else {
                    st.kill(a, false);
                }
            }
            if st.links.len() > links_before {
                last_growth = st.iter;
            }
            continue;
        }
        let mut reached = false;
        for si in 1..n {
            if !st.alive[si] {
                continue;
            }
            let sp = st.src[si];
            let (best, bd) = nodes_grid.nearest(sp, &st.pos);
            st.far[si] = true;
            if s.closed {
                st.rn[si].len = 0;
            }
            st.assoc[si] = best;
            st.assoc_d2[si] = bd;
            st.far_list.push(si as u32);
            st.activate(si as u32);
            reached = true;
        }
        if !reached {
            break;
        }
        fallback = true;
    }
    let nodes = (0..st.pos.len())
        .map(|i| VeinNode { pos: st.pos[i], parent: st.parent[i], born: st.born[i], width: 0.0, tips: 0 })
        .collect();
    let auxins = st.src.iter().zip(&st.killed_at).map(|(&pos, &killed_at)| Auxin { pos, killed_at }).collect();
    Veins { graph: VeinGraph { nodes, links: st.links, iterations: last_growth, fallback }, auxins }
}

#[inline]
/// Adds source pull `d` (squared distance `d2`) to node `v`; in `direct` mode (after a stall)
/// keeps only the nearest source's pull, so a node caught between sources picks one.
fn pull(
    acc: &mut [Vec2],
    best: &mut [f32],
    marked: &mut [bool],
    touched: &mut Vec<u32>,
    v: u32,
    d: Vec2,
    d2: f32,
    direct: bool,
) {
    let i = v as usize;
    if !marked[i] {
        marked[i] = true;
        touched.push(v);
        acc[i] = d;
        best[i] = d2;
    } else if !direct {
        acc[i] += d;
    } else if d2 < best[i] {
        acc[i] = d;
        best[i] = d2;
    }
}
