//! The deepest level's stems in two parts, swept and welded side by side on two threads.
//!
//! The deepest level (twigs and the smallest welded branches) is most of a tree's bark: 54 to
//! 66% of the presets' skeleton + mesh natively, four fifths of it in the welds. A stem's sweep
//! and weld read its parent's bark (vertices, ring frames, claimed quads) and write only its
//! own vertices, its junction's triangles and claims on its parent's quads. So the level may be
//! cut where no parent has children on both sides ([`cuts`]). This thread sweeps the level's
//! stems in order; a helper that becomes free while it does (once the leaf placements beside
//! the bark are done) cuts what is left near its middle, at the cut nearest it ([`Cuts::at`]),
//! and sweeps the stems after the cut in a second [`super::Sweep`], which reads the bark
//! before the level through [`MeshBuilder::beside`] and numbers its vertices as if it came
//! first. This thread stops at the cut; the other's results are then taken in after its own
//! ([`super::Sweep::absorb`]): the vertices copied, every number of its own moved by this
//! part's count (vertices, triangles, claims, fallback rings), its claims on its parents
//! merged. Each stem is swept and welded by the same code in the same order relative to its
//! siblings, and the vertices' values do not depend on their numbers: the bytes are the same
//! as one thread's, wherever the cut falls.
//!
//! [`MeshBuilder::beside`]: crate::mesh::MeshBuilder::beside

use super::plan::Plan;
use super::{fork, weld, Sweep, WeldStats};
use crate::mesh::stem::StemMesh;
use crate::skeleton::Skeleton;
use std::sync::atomic::{AtomicU64, Ordering};

/// Threads the two parts may use: in the threaded wasm module, this thread and the helpers
/// ([`crate::par::threads`]), where [`crate::par::join`] queues the helper's part, which a
/// helper takes only once free (after the leaf placements that run beside the bark); 1 in the
/// single-threaded module; natively 1 (never cut), where `join` starts a thread at once: on
/// this two-core machine it competes with the placements and the thread faulting in the bark's
/// pages, and the second part's buffers come from another allocator arena, which glibc gives
/// back between trees (measured slower, and again with a kept helper thread:
/// docs/performance.md).
pub(super) fn threads() -> usize {
    if cfg!(all(target_arch = "wasm32", target_feature = "atomics")) {
        crate::par::threads()
    } else {
        1
    }
}

/// Planned vertices of the deepest level below which it stays on one thread (starting a thread
/// and copying the second part's vertices would cost more than they save).
pub(super) const MIN_VERTICES: usize = 16_384;

/// Planned vertices below which a helper takes nothing: sweeping them on this thread costs
/// less than waiting for the helper's and copying them in.
const MIN_TAKEN: usize = 8_192;

/// Share of the deepest level's planned vertices left when the helper comes that it takes:
/// half, not tuned (this thread also copies the helper's vertices in afterwards).
const SHARE: f32 = 0.5;

/// Where the deepest level may be cut in two ([`cuts`]): its first position in the stems'
/// order, and for each position `k` of the level the planned vertices before it and whether no
/// parent (the stem a junction welds into) has children both before `k` and at or after it.
pub(super) struct Cuts {
    /// Position of the level's first stem in the order.
    pub level: usize,
    /// `before[k]`: planned vertices of the level's first `k` stems (one more entry than stems).
    before: Vec<usize>,
    /// `ok[k]`: the level may be cut before its stem `k` (never before the first).
    ok: Vec<bool>,
}

impl Cuts {
    /// The cut for a helper that comes when this thread has taken the level's first `next`
    /// stems: of the cuts after them, the one that leaves the helper nearest [`SHARE`] of the
    /// planned vertices left (the later of two as near). None when there is none.
    pub(super) fn at(&self, next: usize) -> Option<usize> {
        let total = *self.before.last()?;
        let left = total.checked_sub(*self.before.get(next)?)?;
        let aim = total - (SHARE * left as f32) as usize;
        (next + 1..self.ok.len())
            .filter(|&k| self.ok[k] && total - self.before[k] >= MIN_TAKEN)
            .min_by_key(|&k| (self.before[k].abs_diff(aim), usize::MAX - k))
    }
}

/// Where `order` (stems level by level) may cut the deepest level ([`Cuts`]). None when the
/// level plans fewer than `min_vertices` vertices or cannot be cut.
pub(super) fn cuts(skeleton: &Skeleton, plan: &Plan, order: &[usize], min_vertices: usize) -> Option<Cuts> {
    let stems = &skeleton.stems;
    let deepest = stems[*order.last()?].level;
    let level = order.partition_point(|&i| stems[i].level < deepest);
    let deep = &order[level..];
    let weight = |i: usize| plan.stems[i].rings.len() * (plan.stems[i].sides as usize + 1);
    let mut before = Vec::with_capacity(deep.len() + 1);
    before.push(0);
    for &i in deep {
        before.push(before.last().copied().unwrap_or(0) + weight(i));
    }
    if before[deep.len()] < min_vertices.max(1) || deep.len() < 2 {
        return None;
    }
    // `bad[k]`: how many parents have children (or themselves) both before position k and at
    // or after it; a cut at k needs none.
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
    let ok: Vec<bool> = (0..deep.len()).map(|k| k > 0 && bad[k] == 0).collect();
    ok.contains(&true).then_some(Cuts { level, before, ok })
}

/// Sweeps the deepest level's stems `deep` ([`Cuts`]): in order on this thread, unless a helper
/// of `threads` comes while it does (once this thread has taken at least `wait` of them: 0, but
/// for the tests of a helper coming late). The helper then takes the stems after the cut
/// [`Cuts::at`] gives, sweeps them beside `sweep`, and they are taken in after this thread's.
pub(super) fn sweep(sweep: &mut Sweep, deep: &[usize], cuts: &Cuts, threads: usize, wait: usize) {
    // Room for what the helper could take: every stem after the first cut.
    let first = cuts.ok.iter().position(|&o| o).unwrap_or(deep.len());
    let (mut other, at) = sweep.beside(&deep[first..]);
    // The stems this thread takes next and where it stops, packed: it takes one at a time,
    // the helper moves the stop once.
    let state = AtomicU64::new(pack(0, deep.len()));
    let (_, cut) = crate::par::join(
        threads,
        || loop {
            let s = state.load(Ordering::Acquire);
            let (next, stop) = unpack(s);
            if next >= stop {
                break;
            }
            if state.compare_exchange(s, pack(next + 1, stop), Ordering::AcqRel, Ordering::Acquire).is_ok() {
                sweep.stem(deep[next]);
            }
        },
        || {
            while wait > 0 && unpack(state.load(Ordering::Acquire)).0 < wait.min(deep.len()) {
                std::hint::spin_loop();
            }
            let mut s = state.load(Ordering::Acquire);
            loop {
                let (next, stop) = unpack(s);
                let k = cuts.at(next).filter(|&k| k < stop)?;
                // This thread goes on meanwhile (finding the cut can take longer than a stem):
                // the cut stays good while it is ahead of it.
                while unpack(s).0 < k {
                    match state.compare_exchange_weak(s, pack(unpack(s).0, k), Ordering::AcqRel, Ordering::Acquire) {
                        Ok(_) => {
                            deep[k..].iter().for_each(|&i| other.stem(i));
                            return Some(k);
                        }
                        Err(now) => s = now,
                    }
                }
            }
        },
    );
    match cut {
        Some(k) => sweep.absorb(other, &deep[k..], at),
        // No helper came in time (every one busy, or this thread was done): all swept here.
        None => sweep.out.forgo(other.out),
    }
}

/// The state of [`sweep`]: the next stem this thread takes and where it stops.
fn pack(next: usize, stop: usize) -> u64 {
    (next as u64) << 32 | stop as u64
}

/// [`pack`] undone.
fn unpack(s: u64) -> (usize, usize) {
    ((s >> 32) as usize, (s & 0xffff_ffff) as usize)
}

/// A copy of `v` with room for `more` elements after them.
fn grown<T: Copy>(v: &[T], more: usize) -> Vec<T> {
    let mut c = Vec::with_capacity(v.len() + more);
    c.extend_from_slice(v);
    c
}

impl<'a> Sweep<'a> {
    /// A sweep that goes on beside this one, on another thread, with stems of `there` (the
    /// deepest level after its first cut, [`cuts`]): it reads the bark swept so far and numbers
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
            let order = super::super::by_level(&sk.stems);
            let plan = Plan::new(&sk, &params.mesh).expect("plan");
            let Some(cuts) = super::cuts(&sk, &plan, &order, 0) else {
                continue;
            };
            split += 1;
            // Side by side, the helper coming at once (a thread of its own starts at once) and
            // late (this thread a third of the way through the level: a cut further on), and in
            // order (the helper's part taken back: no cut).
            let third = (order.len() - cuts.level) / 3;
            for (threads, wait) in [(2, 0), (2, third), (1, 0)] {
                let two = super::super::build_on(&sk, &params.mesh, threads, Some((0, wait))).expect("bark");
                let case = format!("{} on {threads}, the helper after {wait}", preset.name);
                assert_eq!(one.mesh, two.mesh, "{case}");
                assert_eq!(one.welds, two.welds, "{case}");
                assert_eq!(one.layout, two.layout, "{case}");
            }
        }
        assert!(split >= 10, "the presets' deepest levels are cut in two ({split})");
    }

    #[test]
    fn a_late_helper_cuts_what_is_left_near_its_middle() {
        // Six stems of `u` planned vertices each (`u` the least a helper takes), cuts allowed
        // before stems 2 and 5 only.
        let u = super::MIN_TAKEN;
        let cuts = super::Cuts {
            level: 0,
            before: (0..=6).map(|k| u * k).collect(),
            ok: vec![false, false, true, false, false, true],
        };
        assert_eq!(cuts.at(0), Some(2), "6u left, half at 3u: the cut at 2u is nearer than the one at 5u");
        assert_eq!(cuts.at(1), Some(5), "5u left, half at 3.5u: the cuts at 2u and 5u as near, the later one");
        assert_eq!(cuts.at(2), Some(5), "4u left: only the cut at 5u is after the stems taken");
        assert_eq!(cuts.at(5), None, "no cut after the fifth stem");
        assert_eq!(cuts.at(6), None, "all taken");
        // Stems of half that: the last cut leaves the helper less than `u`.
        let small = super::Cuts { level: 0, before: (0..=6).map(|k| u / 2 * k).collect(), ..cuts };
        assert_eq!(small.at(0), Some(2), "3u left");
        assert_eq!(small.at(2), None, "2u left, and after the only cut half a u");
    }
}
