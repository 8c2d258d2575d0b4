//! The sources' side of leaf vein colonization ([`super`]): associating sources with vein nodes
//! (Open: the closest node; Closed: the relative neighbourhood), killing them when veins arrive,
//! and closing loops between arrivals from different veins. Only a new node can change a
//! source's association, so each new node visits the sources in the grid cells within the
//! attraction distance, never all pairs.

use super::State;
use crate::leaf::veins::graph::{VeinLink, NONE};
use crate::leaf::veins::grid::StaticGrid;
use glam::Vec2;

/// Most nodes kept in a source's relative neighbourhood.
const RN_MAX: usize = 6;
/// Where dead sources move in the scan copy (squared distances stay finite).
const FAR: f32 = 1e18;
/// Arrivals at one source from veins more than this many nodes apart are joined by a link.
const LOOP_MIN_HOPS: u32 = 6;

/// The vein nodes in a source's relative neighbourhood, with their squared distances to the
/// source and positions (kept here so updates touch one small block of memory).
#[derive(Clone, Copy)]
pub(super) struct Neighbourhood {
    pub(super) len: u8,
    pub(super) id: [u32; RN_MAX],
    pub(super) d: [f32; RN_MAX],
    pub(super) pos: [Vec2; RN_MAX],
}

/// An empty neighbourhood.
pub(super) const EMPTY: Neighbourhood =
    Neighbourhood { len: 0, id: [NONE; RN_MAX], d: [0.0; RN_MAX], pos: [Vec2::ZERO; RN_MAX] };

impl State {
    /// Puts source `s` on the list of sources that pull this iteration.
    pub(super) fn activate(&mut self, s: u32) {
        if !self.in_active[s as usize] {
            self.in_active[s as usize] = true;
            self.active.push(s);
        }
    }

    /// Source `s` dies (`reached`: a vein arrived, recorded as the iteration it was reached in).
    pub(super) fn kill(&mut self, s: u32, reached: bool) {
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

    /// A new node `u` updates the sources it can reach: those associated from afar (sparse
    /// sources), then those within the attraction distance (through `grid`).
    pub(super) fn new_node(&mut self, grid: &StaticGrid, u: u32) {
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
    pub(super) fn try_close(&mut self, s: u32, force: bool) {
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
