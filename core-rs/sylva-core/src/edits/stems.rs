//! Whole-subtree operations on a skeleton's stems that the cut and the bend share: finding a
//! stem's subtree, moving stems rigidly, removing stems and renumbering the parents.

use crate::skeleton::Skeleton;
use glam::{Quat, Vec3};

/// Stem `root` and all its descendants (parents come before children in the skeleton).
pub(crate) fn subtree(skeleton: &Skeleton, root: usize) -> Vec<bool> {
    let mut mark = vec![false; skeleton.stems.len()];
    mark[root] = true;
    for i in root + 1..skeleton.stems.len() {
        if let Some(p) = skeleton.stems[i].parent {
            mark[i] = mark[p as usize];
        }
    }
    mark
}

/// Moves the children of stem `i` (with their subtrees) after `i` was turned along its length
/// `length` as built: each child's subtree turns rigidly by `turn(fraction of the length where it
/// sits)` and moves with its attachment point onto `i`'s new curve (the bend and the droop).
/// `children` is the skeleton's [`Children`] index.
pub(crate) fn carry_children(
    skeleton: &mut Skeleton,
    children: &Children,
    i: usize,
    length: f32,
    turn: &dyn Fn(f32) -> Quat,
) {
    let mut moved = Vec::new();
    for &c in children.of(i) {
        let c = c as usize;
        let offset = skeleton.stems[c].offset;
        let from = skeleton.stems[c].base();
        let (on, _) = skeleton.stems[i].point_at(offset);
        children.subtree(c, &mut moved);
        transform(skeleton, &moved, turn(offset / length), from, on);
    }
}

/// Each stem's children, in index order: an index built once so that walking a subtree costs
/// its size, not the whole skeleton's (a replay or a droop reattaches every stem's children).
pub(crate) struct Children {
    /// `list[start[i]..start[i + 1]]` are stem `i`'s children.
    start: Vec<u32>,
    list: Vec<u32>,
}

impl Children {
    /// The index of `skeleton`'s stems as they are (valid until stems are added or removed).
    pub(crate) fn of_skeleton(skeleton: &Skeleton) -> Self {
        let n = skeleton.stems.len();
        let mut count = vec![0u32; n + 1];
        for s in &skeleton.stems {
            if let Some(p) = s.parent {
                count[p as usize + 1] += 1;
            }
        }
        for i in 0..n {
            count[i + 1] += count[i];
        }
        let start = count.clone();
        let mut list = vec![0u32; start[n] as usize];
        for (c, s) in skeleton.stems.iter().enumerate() {
            if let Some(p) = s.parent {
                list[count[p as usize] as usize] = c as u32;
                count[p as usize] += 1;
            }
        }
        Children { start, list }
    }

    /// Stem `i`'s children, in index order.
    pub(crate) fn of(&self, i: usize) -> &[u32] {
        &self.list[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// Stem `root` and all its descendants into `out` (cleared first).
    pub(crate) fn subtree(&self, root: usize, out: &mut Vec<u32>) {
        out.clear();
        out.push(root as u32);
        let mut k = 0;
        while k < out.len() {
            let s = out[k] as usize;
            out.extend_from_slice(self.of(s));
            k += 1;
        }
    }
}

/// Moves the stems `stems` rigidly: `x -> pivot_to + rotation (x - pivot_from)`.
pub(crate) fn transform(skeleton: &mut Skeleton, stems: &[u32], rotation: Quat, pivot_from: Vec3, pivot_to: Vec3) {
    for &i in stems {
        let s = &mut skeleton.stems[i as usize];
        for q in s.points.iter_mut() {
            *q = pivot_to + rotation * (*q - pivot_from);
        }
        s.base_normal = (rotation * s.base_normal).normalize_or(s.base_normal);
    }
}

/// Removes the marked stems and renumbers the parents of the others (a kept stem's parent is
/// never removed: removal takes whole subtrees).
pub(crate) fn remove(skeleton: &mut Skeleton, gone: &[bool]) {
    let mut new_index = Vec::with_capacity(gone.len());
    let mut n = 0u32;
    for &g in gone {
        new_index.push(n);
        n += u32::from(!g);
    }
    let stems = std::mem::take(&mut skeleton.stems);
    skeleton.stems = stems
        .into_iter()
        .zip(gone)
        .filter(|(_, &g)| !g)
        .map(|(mut s, _)| {
            s.parent = s.parent.map(|p| new_index[p as usize]);
            s
        })
        .collect();
}
