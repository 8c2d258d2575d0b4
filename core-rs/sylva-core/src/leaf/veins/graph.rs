//! What stage 5 ([`super`]) builds: the vein graph ([`VeinGraph`]: nodes, loop links, widths by
//! the pipe model) and the auxin sources it grew toward ([`Veins`]). A module of its own so that
//! the vein builders ([`super::colonize`], [`super::primary`], [`super::spline`]) write it
//! without importing back from the stage that chooses between them.

use glam::Vec2;

/// "No node": the root's parent, an auxin source never reached.
pub const NONE: u32 = u32::MAX;

/// One vein node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VeinNode {
    /// Position in the leaf frame.
    pub pos: Vec2,
    /// The node it grew from ([`NONE`] for the root at the petiole).
    pub parent: u32,
    /// Growth iteration that made it (the root: 0).
    pub born: u32,
    /// Width of the vein from this node to its parent (the root: the midrib's base width).
    pub width: f32,
    /// Vein tips downstream (pipe model).
    pub tips: u32,
}

/// An extra edge that closes a loop (Closed venation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VeinLink {
    /// One end (the smaller node index).
    pub a: u32,
    /// The other end.
    pub b: u32,
    /// Iteration that made it.
    pub born: u32,
    /// Width: the finest vein's (one tip's share of the pipe model).
    pub width: f32,
}

/// An auxin source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Auxin {
    /// Position in the leaf frame.
    pub pos: Vec2,
    /// Iteration in which a vein reached it ([`NONE`]: never; unreachable sources are dropped
    /// with this value when growth cannot get to them).
    pub killed_at: u32,
}

/// The vein network.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VeinGraph {
    /// Nodes; a parent always comes before its children; node 0 is the root.
    pub nodes: Vec<VeinNode>,
    /// Loop links.
    pub links: Vec<VeinLink>,
    /// Growth iterations run (the last iteration any node or link was born in).
    pub iterations: u32,
    /// Whether the sparse-source fallback (association beyond the attraction distance) ran.
    pub fallback: bool,
}

impl VeinGraph {
    /// Independent loops: links join nodes of one tree, so each adds one cycle.
    pub fn loops(&self) -> usize {
        self.links.len()
    }

    /// Every edge as `(a, b, born, width)`: tree edges (child, parent) then links.
    pub fn edges(&self) -> impl Iterator<Item = (u32, u32, u32, f32)> + '_ {
        let tree = self
            .nodes
            .iter()
            .enumerate()
            .filter(|(_, n)| n.parent != NONE)
            .map(|(i, n)| (i as u32, n.parent, n.born, n.width));
        tree.chain(self.links.iter().map(|l| (l.a, l.b, l.born, l.width)))
    }

    /// Whether the edges contain a cycle (union-find over all edges).
    pub fn has_cycle(&self) -> bool {
        let mut up: Vec<u32> = (0..self.nodes.len() as u32).collect();
        fn find(up: &mut [u32], mut x: u32) -> u32 {
            while up[x as usize] != x {
                up[x as usize] = up[up[x as usize] as usize];
                x = up[x as usize];
            }
            x
        }
        for (a, b, _, _) in self.edges() {
            let (ra, rb) = (find(&mut up, a), find(&mut up, b));
            if ra == rb {
                return true;
            }
            up[ra as usize] = rb;
        }
        false
    }

    /// The midrib: the path from the root to the node nearest the tip `(0, 1)`, root first.
    pub fn midrib(&self) -> Vec<u32> {
        let Some(end) = self.nearest(Vec2::new(0.0, 1.0)) else {
            return Vec::new();
        };
        let mut path = vec![end];
        let mut v = end;
        while self.nodes[v as usize].parent != NONE {
            v = self.nodes[v as usize].parent;
            path.push(v);
        }
        path.reverse();
        path
    }

    /// The node nearest `p`.
    pub fn nearest(&self, p: Vec2) -> Option<u32> {
        let mut best: Option<(f32, u32)> = None;
        for (i, n) in self.nodes.iter().enumerate() {
            let d = (n.pos - p).length_squared();
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, i as u32));
            }
        }
        best.map(|(_, i)| i)
    }

    /// Pipe-model widths: tips downstream of every node, `width = max_width × sqrt(tips / all
    /// tips)`; loop links get the finest width (one tip's).
    pub fn assign_widths(&mut self, max_width: f32) {
        let n = self.nodes.len();
        if n == 0 {
            return;
        }
        let mut children = vec![0u32; n];
        for node in &self.nodes {
            if node.parent != NONE {
                children[node.parent as usize] += 1;
            }
        }
        for (node, &c) in self.nodes.iter_mut().zip(&children) {
            node.tips = u32::from(c == 0);
        }
        for i in (1..n).rev() {
            let (t, p) = (self.nodes[i].tips, self.nodes[i].parent);
            if p != NONE {
                self.nodes[p as usize].tips += t;
            }
        }
        let all = self.nodes[0].tips.max(1) as f32;
        for node in &mut self.nodes {
            node.width = max_width * (node.tips as f32 / all).sqrt();
        }
        // Loop links are the finest veins: one tip's width.
        let finest = max_width * (1.0 / all).sqrt();
        for l in &mut self.links {
            l.width = finest.min(self.nodes[l.a as usize].width).min(self.nodes[l.b as usize].width);
        }
    }
}

/// The veins and the auxin sources they grew toward.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Veins {
    /// The network.
    pub graph: VeinGraph,
    /// Auxin sources (space colonization only; the first is the apex source at the tip).
    pub auxins: Vec<Auxin>,
}
