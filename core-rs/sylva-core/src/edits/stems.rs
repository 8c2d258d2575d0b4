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

/// Moves every stem marked in `mark` rigidly: `x -> pivot_to + rotation (x - pivot_from)`.
pub(crate) fn transform(skeleton: &mut Skeleton, mark: &[bool], rotation: Quat, pivot_from: Vec3, pivot_to: Vec3) {
    for (s, _) in skeleton.stems.iter_mut().zip(mark).filter(|(_, &m)| m) {
        for q in s.points.iter_mut() {
            *q = pivot_to + rotation * (*q - pivot_from);
        }
        s.base_normal = (rotation * s.base_normal).normalize_or(s.base_normal);
    }
}

/// Moves the children of stem `i` (with their subtrees) after `i` was turned along its length
/// `length` as built: each child's subtree turns rigidly by `turn(fraction of the length where it
/// sits)` and moves with its attachment point onto `i`'s new curve (the bend and the droop).
pub(crate) fn carry_children(skeleton: &mut Skeleton, i: usize, length: f32, turn: &dyn Fn(f32) -> Quat) {
    for c in i + 1..skeleton.stems.len() {
        if skeleton.stems[c].parent != Some(i as u32) {
            continue;
        }
        let offset = skeleton.stems[c].offset;
        let from = skeleton.stems[c].base();
        let (on, _) = skeleton.stems[i].point_at(offset);
        transform(skeleton, &subtree(skeleton, c), turn(offset / length), from, on);
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
