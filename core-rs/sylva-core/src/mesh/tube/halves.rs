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
use super::{fork, weld, Sweep, WeldStats};
use crate::mesh::stem::StemMesh;
use crate::skeleton::Skeleton;
use std::sync::atomic::{AtomicBool, Ordering};

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

/// Sweeps the deepest level's stems `here`, then `there`, in two halves ([`split`]): `there` in
/// a sweep beside `sweep` on a helper of `threads` if one starts it before `here` is done (then
/// taken in), else on this thread after `here`.
pub(super) fn sweep(sweep: &mut Sweep, here: &[usize], there: &[usize], threads: usize) {
    let (mut other, at) = sweep.beside(there);
    // The second half is swept beside only if it starts before the first half ends; a
    // half taken back by this thread (every helper busy) is swept here, as on one thread.
    let first_done = AtomicBool::new(false);
    let (_, beside) = crate::par::join(
        threads,
        || {
            here.iter().for_each(|&i| sweep.stem(i));
            first_done.store(true, Ordering::Release);
        },
        || {
            let late = first_done.load(Ordering::Acquire);
            if !late {
                there.iter().for_each(|&i| other.stem(i));
            }
            !late
        },
    );
    if beside {
        sweep.absorb(other, there, at);
    } else {
        sweep.out.forgo(other.out);
        there.iter().for_each(|&i| sweep.stem(i));
    }
}

/// A copy of `v` with room for `more` elements after them.
fn grown<T: Copy>(v: &[T], more: usize) -> Vec<T> {
    let mut c = Vec::with_capacity(v.len() + more);
    c.extend_from_slice(v);
    c
}

impl<'a> Sweep<'a> {
    /// A sweep that goes on beside this one, on another thread, with the stems `there` (the
    /// second half of the deepest level, [`split`]): it reads the bark swept so far and numbers
    /// its vertices from this one's next on. Returns it with where this sweep stood (rings
    /// planned, quads reserved), for [`Sweep::absorb`].
    fn beside(&mut self, there: &[usize]) -> (Sweep<'a>, (usize, usize)) {
        let n = self.skeleton.stems.len();
        // Room for everything the other sweep writes, made here so that nothing grows on the
        // other thread: its own vertices (a collar's and a fallback's rings more per stem),
        // rings planned again for fallbacks (as many again), its quads and its junctions'
        // triangles (this sweep's room left).
        let (mut room, mut rings, mut quads) = (0, 0, 0);
        for &i in there {
            let s = &self.plan.stems[i];
            room += (s.rings.len() + 3) * (s.sides as usize + 1) + 2;
            rings += 2 * s.rings.len();
            quads += 2 * s.rings.len() * s.sides as usize;
        }
        let mut plan = self.plan.clone();
        plan.ts = grown(&self.plan.ts, rings);
        let other = Sweep {
            skeleton: self.skeleton,
            p: self.p,
            plan,
            out: self.out.beside(room),
            tables: self.tables,
            winds: self.winds,
            frames: grown(&self.frames, rings),
            meshes: self.meshes.clone(),
            claimed: grown(&self.claimed, quads),
            bridges: Vec::with_capacity(self.bridges.capacity() - self.bridges.len()),
            scratch: weld::Scratch::default(),
            fork_scratch: fork::Scratch::default(),
            stats: WeldStats::default(),
            blocks: vec![0..0; n],
            junctions: vec![0..0; n],
        };
        (other, (self.plan.ts.len(), self.claimed.len()))
    }

    /// Takes in `other`'s stems `there` ([`Sweep::beside`], made when this sweep had planned
    /// `at.0` rings and reserved `at.1` quads) after this sweep's: its vertices copied after
    /// this sweep's and its numbers moved by as many (vertices, junction triangles, quads,
    /// rings planned again for fallbacks), its claims on its parents' quads merged.
    fn absorb(&mut self, other: Sweep, there: &[usize], at: (usize, usize)) {
        let (r0, c0) = at;
        let Sweep { plan, out, frames, meshes, claimed, bridges, stats, blocks, junctions, .. } = other;
        let base = out.base();
        let first = self.out.absorb(out);
        let v = |x: u32| if x >= base { x - base + first } else { x };
        // Claims only ever set a quad, and each half claims only its own parents' quads.
        for (a, &b) in self.claimed[..c0].iter_mut().zip(&claimed[..c0]) {
            *a |= b;
        }
        let dc = self.claimed.len() - c0;
        self.claimed.extend_from_slice(&claimed[c0..]);
        let dr = self.plan.ts.len() - r0;
        self.plan.ts.extend_from_slice(&plan.ts[r0..]);
        self.frames.extend_from_slice(&frames[r0..]);
        let ring = |k: usize| if k >= r0 { k + dr } else { k };
        let tri0 = (self.bridges.len() / 3) as u32;
        self.bridges.extend(bridges.iter().map(|&x| v(x)));
        for &i in there {
            let planned = self.plan.stems[i].rings.clone();
            self.frames[planned.clone()].copy_from_slice(&frames[planned]);
            let rings = plan.stems[i].rings.clone();
            self.plan.stems[i].rings = ring(rings.start)..ring(rings.end);
            self.meshes[i] =
                meshes[i].map(|m| StemMesh { claim: m.claim + dc, ring0: ring(m.ring0), ..m.moved(v(m.first)) });
            self.blocks[i] = v(blocks[i].start)..v(blocks[i].end);
            self.junctions[i] = junctions[i].start + tri0..junctions[i].end + tri0;
        }
        self.stats.add(stats);
    }
}

#[cfg(test)]
mod tests {
    use super::Plan;

    #[test]
    fn the_deepest_level_in_two_halves_is_the_same_bark() {
        let mut split = 0;
        for preset in crate::presets::PRESETS {
            let params = preset.params().expect("preset");
            let Ok(sk) = crate::skeleton::build(&params.skeleton) else { continue };
            let one = super::super::build_on(&sk, &params.mesh, 1, None).expect("bark");
            // Side by side (the second half's thread starts before the first half ends, as a
            // thread of its own does at once), and in order (the second half taken back).
            for threads in [2, 1] {
                let two = super::super::build_on(&sk, &params.mesh, threads, Some(0)).expect("bark");
                assert_eq!(one.mesh, two.mesh, "{} on {threads}", preset.name);
                assert_eq!(one.welds, two.welds, "{} on {threads}", preset.name);
                assert_eq!(one.layout, two.layout, "{} on {threads}", preset.name);
            }
            let plan = Plan::new(&sk, &params.mesh).expect("plan");
            split += usize::from(super::split(&sk, &plan, &super::super::by_level(&sk.stems), 0).is_some());
        }
        assert!(split >= 10, "the presets' deepest levels split in two ({split})");
    }
}
