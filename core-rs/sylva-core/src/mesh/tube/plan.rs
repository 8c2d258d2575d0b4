//! Planning the bark sweep ([`super`]) before any vertex exists: the sides of every stem, the
//! welded junctions ([`weld::plan`]) grouped by parent, the ring positions along every stem, and
//! a conservative vertex and index count checked against the budget (every junction counted as
//! if it fell back to a separate tube).

use super::rings::{bent_rings, plan_rings, start_and_tip};
use crate::error::SylvaError;
use crate::math::TAU;
use crate::mesh::stem::sides_for;
use crate::mesh::{fork, fork_rows, holes, twig, weld};
use crate::params::MeshParams;
use crate::skeleton::{budget_error, Skeleton, StemKind};
use std::ops::Range;

/// Bound on the rows of a junction's hole, for the index capacity estimate.
const MAX_ROWS_BOUND: u64 = 8;

/// How one stem will be meshed: its ring positions along the stem and its number of sides.
#[derive(Clone)]
pub(super) struct StemPlan {
    /// Range into the shared ring-parameter buffer ([`Plan::ts`]).
    pub rings: Range<usize>,
    /// Sides around the stem.
    pub sides: u32,
}

/// The plan of a whole tree's bark.
#[derive(Clone)]
pub(super) struct Plan {
    /// Sides per stem, as planned for tubes (a twig's own count is in its [`StemPlan`]).
    pub sides: Vec<u32>,
    /// The junction of every stem welded into its parent.
    pub junctions: Vec<Option<weld::Junction>>,
    /// Stems meshed as Bezier twigs ([`twig`]).
    pub twigs: Vec<bool>,
    /// Stems swept densely enough for tree holes ([`holes::eligible`]; may be empty).
    pub dense: Vec<bool>,
    /// The junctions of every parent's welded children, grouped by parent, sorted along it.
    feet: Vec<weld::Junction>,
    /// Each stem's range of `feet`.
    feet_of: Vec<Range<usize>>,
    /// Ring positions (fractions of each stem), every stem's block in turn.
    pub ts: Vec<f32>,
    /// Every stem's rings and sides.
    pub stems: Vec<StemPlan>,
    /// Upper bounds of the vertices, the stems' indices and the junctions' indices.
    pub vertices: u64,
    pub indices: u64,
    pub bridges: u64,
}

impl Plan {
    /// Plans every stem. Fails with a budget error when the vertex count could pass
    /// `max_vertices`.
    pub fn new(skeleton: &Skeleton, p: &MeshParams) -> Result<Plan, SylvaError> {
        let n = skeleton.stems.len();
        let twig_candidates = twig::mask(skeleton);
        let dense = holes::eligible(skeleton, p, &twig_candidates);
        let mut sides = stem_sides(skeleton, p, &dense);
        let junctions = if p.weld { weld::plan(skeleton, p, &sides) } else { vec![None; n] };
        // A fork's clone has its original's sides (column k of both points the same way).
        for i in 0..n {
            if let Some(j) = junctions[i].filter(|j| j.fork) {
                sides[i] = sides[j.parent as usize];
            }
        }
        // Welding wins: a twig candidate with a junction is swept as a tube and welded.
        let twigs = twig_candidates.iter().zip(&junctions).map(|(&t, j)| t && j.is_none()).collect();
        let (feet, feet_of) = group_by_parent(&junctions, n);
        let mut plan = Plan {
            sides,
            junctions,
            twigs,
            dense,
            feet,
            feet_of,
            ts: Vec::with_capacity(n * 8),
            stems: Vec::with_capacity(n),
            vertices: 0,
            indices: 0,
            bridges: 0,
        };
        plan.plan_stems(skeleton, p);
        if plan.vertices > u64::from(skeleton.max_vertices) {
            return Err(budget_error(skeleton.mode, skeleton.max_vertices, "", plan.vertices));
        }
        Ok(plan)
    }

    /// Whether stem `i` is swept densely enough for tree holes.
    fn is_dense(&self, i: usize) -> bool {
        self.dense.get(i) == Some(&true)
    }

    /// The junctions of stem `i`'s welded children, sorted along it.
    pub fn feet(&self, i: usize) -> &[weld::Junction] {
        &self.feet[self.feet_of[i].clone()]
    }

    /// Appends the ring positions of tube `i` to `out`, starting at `t0` (its junction ring if
    /// it is welded, else 0): rings where it bends and around its children's footprints,
    /// densified for holes, with its forks' rows kept open.
    pub fn tube_rings(&self, skeleton: &Skeleton, p: &MeshParams, i: usize, t0: f32, out: &mut Vec<f32>) {
        let (stem, sides, start) = (&skeleton.stems[i], self.sides[i], out.len());
        plan_rings(stem, p.mesh_quality, self.feet(i), TAU / sides as f32, t0, out);
        self.finish_rings(skeleton, p, i, out, start);
    }

    /// [`Plan::tube_rings`] of welded tube `i` from its junction ring `t0` into `out`, and the
    /// rings a fallback to a tube from its base would have (`fallback`, replaced): the rings
    /// where it bends are placed once for both.
    fn tube_rings_and_fallback(
        &self,
        skeleton: &Skeleton,
        p: &MeshParams,
        i: usize,
        t0: f32,
        out: &mut Vec<f32>,
        fallback: &mut Vec<f32>,
    ) {
        let (stem, sides, start) = (&skeleton.stems[i], self.sides[i], out.len());
        bent_rings(stem, p.mesh_quality, self.feet(i), TAU / sides as f32, out);
        fallback.clear();
        fallback.extend_from_slice(&out[start..]);
        for (rings, first, from) in [(&mut *out, start, t0), (&mut *fallback, 0, 0.0)] {
            start_and_tip(stem, from, rings, first);
            self.finish_rings(skeleton, p, i, rings, first);
        }
    }

    /// The last steps of [`Plan::tube_rings`] on `out[start..]`: densified for holes, the forks'
    /// rows kept open.
    fn finish_rings(&self, skeleton: &Skeleton, p: &MeshParams, i: usize, out: &mut Vec<f32>, start: usize) {
        if self.is_dense(i) {
            holes::densify(&skeleton.stems[i], self.sides[i], p, out, start);
        }
        fork::keep_gaps(self.feet(i), out, start);
    }

    /// Every stem's rings, and the vertex and index counts: tubes, apexes, caps, the collar
    /// loops of every junction, and for each junction the rings a fallback to a buried tube
    /// would add back.
    fn plan_stems(&mut self, skeleton: &Skeleton, p: &MeshParams) {
        let q = p.mesh_quality;
        let mut ts = std::mem::take(&mut self.ts);
        let mut fallback: Vec<f32> = Vec::new();
        for (i, s) in skeleton.stems.iter().enumerate() {
            let start = ts.len();
            if self.twigs[i] {
                let sides = twig::plan(s, p, &mut ts);
                let rings = (ts.len() - start) as u64;
                // Rings, the apex and the cap centre; quads and two fans.
                self.vertices += rings * (u64::from(sides) + 1) + 2;
                self.indices += (rings + 1) * u64::from(sides) * 6;
                self.stems.push(StemPlan { rings: start..ts.len(), sides });
                continue;
            }
            let t0 = self.junctions[i].map_or(0.0, |j| j.t_start);
            if self.junctions[i].is_some() {
                self.tube_rings_and_fallback(skeleton, p, i, t0, &mut ts, &mut fallback);
            } else {
                self.tube_rings(skeleton, p, i, t0, &mut ts);
            }
            let plan = StemPlan { rings: start..ts.len(), sides: self.sides[i] };
            let ring = u64::from(plan.sides) + 1;
            self.vertices += plan.rings.len() as u64 * ring + 2 + if s.parent.is_none() { ring + 1 } else { 0 };
            // Quads, tip fan and base fan; a junction's zip and collar quads.
            self.indices += (plan.rings.len() as u64 + 1) * u64::from(plan.sides) * 6;
            if s.cut_end {
                // A cut end's bevel and face rings, its rim quads and face fan.
                self.vertices += crate::mesh::cut_face::extra_vertices(s, plan.sides);
                self.indices += crate::mesh::cut_face::extra_indices(s, plan.sides);
            }
            if let Some(j) = self.junctions[i] {
                // Either the footprint loop and the collar loops, or a fallback swept from the
                // parent's axis: planned here as it would be (densified for holes too), so that
                // the budget holds either way.
                let more = fallback.len().saturating_sub(plan.rings.len());
                let fork = j.fork.then(|| fork_rows::rows(&j, &skeleton.stems[j.parent as usize], q));
                let joined = match fork {
                    Some(rows) => fork::vertices(self.sides[i], rows) as u64,
                    // The footprint loop twice, the collar loops, and up to a ring of copies
                    // across the parent's seam (`MeshBuilder::unwrap_u`).
                    None => (weld::collar_loops(q) as u64 + 3) * ring,
                };
                self.vertices += (more as u64 * ring).max(joined);
                self.bridges += fork.map_or(0, |rows| fork::indices(self.sides[i], rows) as u64);
                self.bridges += (2 * u64::from(plan.sides) * (weld::collar_loops(q) as u64 + 1)
                    + 4 * (MAX_ROWS_BOUND + u64::from(self.sides[s.parent.map_or(0, |q| q as usize)])))
                    * 3;
            }
            self.stems.push(plan);
        }
        self.ts = ts;
    }
}

/// Sides per stem: by radius and quality ([`sides_for`], lobes on the trunk), more on stems
/// densified for holes, and even on both branches of a split that may fork.
fn stem_sides(skeleton: &Skeleton, p: &MeshParams, dense: &[bool]) -> Vec<u32> {
    let stems = &skeleton.stems;
    let mut sides: Vec<u32> = stems
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let plain = sides_for(s.radius, p.mesh_quality, if s.lobed { p.lobes } else { 0 });
            if dense.get(i) == Some(&true) {
                holes::dense_sides(plain, p)
            } else {
                plain
            }
        })
        .collect();
    if p.weld {
        // Forks need an even number of sides on both branches of a split.
        for (i, s) in stems.iter().enumerate() {
            if weld::is_candidate(stems, i) && s.kind == StemKind::SplitClone {
                let o = s.parent.map_or(i, |q| q as usize);
                sides[o] += sides[o] % 2;
                sides[i] += sides[i] % 2;
            }
        }
    }
    sides
}

/// The junctions grouped by parent, sorted along it, and each stem's range of them.
fn group_by_parent(junctions: &[Option<weld::Junction>], n: usize) -> (Vec<weld::Junction>, Vec<Range<usize>>) {
    // Bucketed by parent in stem order (a counting sort), then each parent's sorted along it:
    // the order of one stable sort by parent, then `t_lo`.
    let mut start = vec![0usize; n + 1];
    for j in junctions.iter().flatten() {
        start[j.parent as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut at = start.clone();
    let mut slots: Vec<Option<weld::Junction>> = vec![None; start[n]];
    for j in junctions.iter().flatten() {
        slots[at[j.parent as usize]] = Some(*j);
        at[j.parent as usize] += 1;
    }
    let mut feet: Vec<weld::Junction> = slots.into_iter().flatten().collect();
    let of: Vec<Range<usize>> = (0..n).map(|i| start[i]..start[i + 1]).collect();
    for r in &of {
        feet[r.clone()].sort_by(|a, b| a.t_lo.total_cmp(&b.t_lo));
    }
    (feet, of)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The welded tubes' rings and their fallbacks' come out as two separate plans give them,
    /// for every welded stem of every preset (with holes and forks among them), so the budget
    /// counts do not change.
    #[test]
    fn rings_with_the_fallback_are_those_of_two_plans() {
        let mut welded = 0;
        for preset in crate::presets::PRESETS {
            let params = preset.params().expect("preset");
            let Ok(sk) = crate::skeleton::build(&params.skeleton) else { continue };
            let p = &params.mesh;
            let plan = Plan::new(&sk, p).expect("plan");
            let (mut out, mut fallback) = (vec![0.5f32], Vec::new());
            for i in 0..sk.stems.len() {
                let Some(j) = plan.junctions[i] else { continue };
                welded += 1;
                out.truncate(1);
                plan.tube_rings_and_fallback(&sk, p, i, j.t_start, &mut out, &mut fallback);
                let (mut tube, mut alone) = (vec![0.5f32], Vec::new());
                plan.tube_rings(&sk, p, i, j.t_start, &mut tube);
                plan.tube_rings(&sk, p, i, 0.0, &mut alone);
                assert_eq!(out, tube, "{} stem {i}", preset.name);
                assert_eq!(fallback, alone, "{} stem {i}", preset.name);
            }
        }
        assert!(welded > 50_000, "{welded} welded stems");
    }

    /// The junctions grouped as one stable sort by parent, then along it, groups them, on every
    /// preset (ties along a parent kept in stem order).
    #[test]
    fn the_junctions_are_grouped_as_a_stable_sort_groups_them() {
        for preset in crate::presets::PRESETS {
            let params = preset.params().expect("preset");
            let Ok(sk) = crate::skeleton::build(&params.skeleton) else { continue };
            let n = sk.stems.len();
            let mut junctions = weld::plan(&sk, &params.mesh, &stem_sides(&sk, &params.mesh, &[]));
            // A tie along a parent, where the stable sort keeps stem order.
            if let Some(k) = (1..n).find(|&k| junctions[k].is_some() && junctions[k - 1].is_some()) {
                junctions[k - 1] = junctions[k].map(|j| weld::Junction { fork: !j.fork, ..j });
            }
            let (feet, of) = group_by_parent(&junctions, n);
            let mut sorted: Vec<weld::Junction> = junctions.iter().flatten().copied().collect();
            sorted.sort_by(|a, b| a.parent.cmp(&b.parent).then(a.t_lo.total_cmp(&b.t_lo)));
            let key = |j: &weld::Junction| (j.parent, j.t_lo.to_bits(), j.t_start.to_bits(), j.fork);
            assert_eq!(
                feet.iter().map(key).collect::<Vec<_>>(),
                sorted.iter().map(key).collect::<Vec<_>>(),
                "{}",
                preset.name
            );
            assert_eq!(of.len(), n);
            for (i, r) in of.iter().enumerate() {
                assert!(feet[r.clone()].iter().all(|j| j.parent as usize == i), "{}", preset.name);
            }
        }
    }
}
