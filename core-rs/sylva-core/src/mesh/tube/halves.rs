//! The deepest level's stems in two halves, swept and welded side by side on two threads.
//!
//! The deepest level (twigs and the smallest welded branches) is most of a tree's bark: 54 to
//! 66% of the presets' skeleton + mesh natively, four fifths of it in the welds. A stem's sweep
//! and weld read its parent's bark (vertices, ring frames, claimed quads) and write only its
//! own vertices, its junction's triangles and claims on its parent's quads. So the level splits
//! where no parent has children on both sides ([`split`]): the first half goes on as before,
//! the second half is swept by a second [`super::Sweep`] on another thread, which reads the
//! bark before the level through [`MeshBuilder::beside`] and numbers its vertices as if it came
//! first. Its results are then taken in after the first half's ([`super::Sweep::absorb`]): the
//! vertices copied, every number of its own moved by the first half's count (vertices,
//! triangles, claims, fallback rings), its claims on its parents merged. Each stem is swept and
//! welded by the same code in the same order relative to its siblings, and the vertices'
//! values do not depend on their numbers: the bytes are the same as one thread's.
//!
//! [`MeshBuilder::beside`]: crate::mesh::MeshBuilder::beside

use super::plan::Plan;
use crate::skeleton::Skeleton;

/// Threads the halves may use: in the threaded wasm module, this thread and the helpers
/// ([`crate::par::threads`]), where [`crate::par::join`] queues the second half for a helper,
/// which takes it only once free (after the leaf placements that run beside the bark); 1 in the
/// single-threaded module; natively 1 (never split), where
/// `join` starts a thread at once: on this two-core machine it competes with the placements and
/// the thread faulting in the bark's pages, and the second half's buffers come from another
/// allocator arena, which glibc gives back between trees (measured slower: docs/performance.md).
pub(super) fn threads() -> usize {
    if cfg!(all(target_arch = "wasm32", target_feature = "atomics")) {
        crate::par::threads()
    } else {
        1
    }
}

/// Planned vertices of the deepest level below which it stays on one thread (starting a thread
/// and copying the second half's vertices would cost more than they save).
pub(super) const MIN_VERTICES: usize = 16_384;

/// Share of the deepest level's planned vertices the second half aims at: half, not tuned (the
/// first half's thread also copies the second half's vertices in afterwards, and the helper
/// may start late).
const SHARE: f32 = 0.5;

/// Where to split `order` (stems level by level): the position of the deepest level's first
/// stem, and the position of the second half's first stem, as near the level's planned
/// vertices' share [`SHARE`] as a split can be where no parent (the stem a junction welds into)
/// has children on both sides. None when the level plans fewer than `min_vertices` vertices
/// or no split is possible.
pub(super) fn split(skeleton: &Skeleton, plan: &Plan, order: &[usize], min_vertices: usize) -> Option<(usize, usize)> {
    let stems = &skeleton.stems;
    let deepest = stems[*order.last()?].level;
    let level = order.partition_point(|&i| stems[i].level < deepest);
    let deep = &order[level..];
    let weight = |i: usize| plan.stems[i].rings.len() * (plan.stems[i].sides as usize + 1);
    let total: usize = deep.iter().map(|&i| weight(i)).sum();
    if total < min_vertices.max(1) || deep.len() < 2 {
        return None;
    }
    // `bad[k]`: how many parents have children (or themselves) both before position k and at
    // or after it; a split at k needs none.
    let mut span: Vec<Option<(usize, usize)>> = vec![None; stems.len()];
    let mut touch = |p: usize, k: usize| {
        let s = span[p].get_or_insert((k, k));
        s.1 = k;
    };
    for (k, &i) in deep.iter().enumerate() {
        touch(i, k);
        if let Some(j) = plan.junctions[i] {
            touch(j.parent as usize, k);
        }
    }
    let mut bad = vec![0i32; deep.len() + 1];
    for &(lo, hi) in span.iter().flatten() {
        if hi > lo {
            bad[lo + 1] += 1;
            bad[hi + 1] -= 1;
        }
    }
    for k in 1..bad.len() {
        bad[k] += bad[k - 1];
    }
    // The position where the second half's share of the weight reaches `SHARE`.
    let (mut aim, mut acc) = (deep.len(), 0usize);
    while aim > 1 && (acc as f32) < SHARE * total as f32 {
        aim -= 1;
        acc += weight(deep[aim]);
    }
    let ok = |k: usize| (1..deep.len()).contains(&k) && bad[k] == 0;
    let k = (0..deep.len()).flat_map(|d| [aim + d, aim.wrapping_sub(d)]).find(|&k| ok(k))?;
    Some((level, level + k))
}
