//! The fork search's shortcut: steps at which the two tubes certainly have not separated,
//! skipped without evaluating them (a weeping willow's thousands of clones each run along their
//! original for up to 100 radii). Exact: every step skipped is one the search would have
//! rejected, so the forks found are the same (the golden hashes, and a test comparing both
//! searches stem by stem).
//!
//! From a step with gap `g` between the two centres, the gap at a later step of the same pair
//! of curve segments is at most `g + |Δu_o h_o − Δu_c h_c|`, with `h` a point of each
//! segment's hodograph hull ([`Segment::hodograph`]): a chord of a cubic is its parameter step
//! times a mean derivative. While that bound, with room for rounding, stays below half the
//! clearance still needed at the window's end (radii that never grow from base to tip), no
//! step up to there separates.
//!
//! [`Segment::hodograph`]: crate::skeleton::Segment::hodograph

use crate::math::max;
use crate::skeleton::Stem;
use std::cell::Cell;

use super::{CLEARANCE, COARSE, STEPS};

/// The search's fixed quantities for one clone (see [`super::geometry_from`]).
pub(super) struct Search<'a> {
    pub o: &'a Stem,
    pub c: &'a Stem,
    /// Their lengths (at least a micrometre).
    pub lo: f32,
    pub lc: f32,
    pub t_split: f32,
    pub ahead: f32,
    pub step: f32,
    pub bound: f32,
    pub min_s: f32,
    pub max_start: f32,
    /// The last pair of segments' bound (see [`Search::rate`]): the search moves along both
    /// stems a radius at a time, so it mostly asks for the same pair again.
    pub memo: Cell<Option<Rate>>,
}

/// How fast the gap between two segments' points can grow per metre up the original, and the
/// rounding allowed for, for segments `i_o` of the original and `i_c` of the clone.
#[derive(Clone, Copy)]
pub(super) struct Rate {
    i_o: usize,
    i_c: usize,
    rate: f32,
    slack: f32,
}

impl Search<'_> {
    /// Step `k`: how far up the original from the split, and where both stems are then.
    pub fn at_step(&self, k: usize) -> (f32, f32, f32) {
        let s = k as f32 * self.step;
        (s, self.t_split + s / self.lo, (self.ahead + s) / self.lc)
    }

    /// Whether step `k` lies past the search's end (the clone too far along, or the original).
    pub fn past_end(&self, t_o: f32, t_c: f32) -> bool {
        t_c > self.max_start || t_o > 0.9
    }

    /// The clearance the centres need at fractions `t_o`, `t_c`.
    pub fn clearance(&self, t_o: f32, t_c: f32) -> f32 {
        CLEARANCE * (self.o.radius_at(t_o) * self.bound + self.c.radius_at(t_c))
    }

    /// The last coarse step (a multiple of [`COARSE`], at least `k`) such that every coarse
    /// step after `k` up to it certainly does not separate, given that step `k` (not past the
    /// end, not separated) has its centres `gap` apart.
    pub fn clear_until(&self, k: usize, gap: f32) -> usize {
        let (o, c) = (self.o, self.c);
        let (_, t_ok, t_ck) = self.at_step(k);
        let ((i_o, _), (i_c, _)) = (o.locate(t_ok), c.locate(t_ck));
        // The window: the coarse steps still on both segments and before the search's end.
        let (lo, lc) = (self.lo, self.lc);
        let (n_o, n_c) = (o.segments() as f32, c.segments() as f32);
        let s_end = ((((i_o + 1) as f32 / n_o).min(0.9) - self.t_split) * lo)
            .min(((i_c + 1) as f32 / n_c).min(self.max_start) * lc - self.ahead);
        let mut m = ((s_end / self.step).max(0.0) as usize).min(STEPS) / COARSE * COARSE;
        while m > k {
            let (_, t_o, t_c) = self.at_step(m);
            if !self.past_end(t_o, t_c) && o.locate(t_o).0 == i_o && c.locate(t_c).0 == i_c {
                break;
            }
            m -= COARSE;
        }
        if m <= k {
            return k;
        }
        // Steps closer than the least distance never separate, whatever the gap.
        let until = self.last_within(k, m, |s| s < self.min_s);
        if !(o.radius_never_grows() && c.radius_never_grows()) {
            return until;
        }
        let Rate { rate, slack, .. } = self.rate(i_o, i_c);
        let (_, t_om, t_cm) = self.at_step(m);
        let room = 0.5 * self.clearance(t_om, t_cm) - gap - slack;
        if room <= 0.0 {
            return until;
        }
        let s_k = self.at_step(k).0;
        let reach = if rate > 0.0 { 0.99 * room / rate } else { f32::INFINITY };
        self.last_within(k, m, |s| s - s_k <= reach).max(until)
    }

    /// The bound on the gap's growth between segment `i_o` of the original and `i_c` of the
    /// clone, from the last call when it asked for the same pair.
    fn rate(&self, i_o: usize, i_c: usize) -> Rate {
        if let Some(r) = self.memo.get().filter(|r| (r.i_o, r.i_c) == (i_o, i_c)) {
            return r;
        }
        let (o, c) = (self.o, self.c);
        let (n_o, n_c) = (o.segments() as f32, c.segments() as f32);
        let (seg_o, seg_c) = (o.segment(i_o), c.segment(i_c));
        // Per metre up the original, each segment's parameter moves n / l.
        let (ko, kc) = (n_o / self.lo, n_c / self.lc);
        let (ho, hc) = (seg_o.hodograph(), seg_c.hodograph());
        let mut rate = 0.0f32;
        for a in ho {
            for b in hc {
                rate = max(rate, (a * ko - b * kc).length());
            }
        }
        let big = |h: [glam::Vec3; 3]| h.iter().map(|v| v.length()).fold(0.0, max);
        let (bo, bc) = (big(ho), big(hc));
        // Rounding: the positions' sums (a few units in the last place of their terms), and the
        // parameters' (each `t` within a unit in the last place of 1).
        let slack =
            16.0 * f32::EPSILON * (seg_o.magnitude() + seg_c.magnitude()) + 4.0 * f32::EPSILON * (n_o * bo + n_c * bc);
        let r = Rate { i_o, i_c, rate: rate + 1e-3 * (ko * bo + kc * bc), slack };
        self.memo.set(Some(r));
        r
    }

    /// The last coarse step in `k..=m` up to which `ok` holds for every step's distance `s`
    /// after `k` (`ok` must hold up to some distance and not after).
    fn last_within(&self, k: usize, m: usize, ok: impl Fn(f32) -> bool) -> usize {
        let (mut lo, mut hi) = (k / COARSE, m / COARSE);
        while lo < hi {
            let mid = (lo + hi).div_ceil(2);
            if ok(self.at_step(mid * COARSE).0) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        lo * COARSE
    }
}
