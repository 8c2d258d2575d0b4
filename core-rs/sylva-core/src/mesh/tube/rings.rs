//! Ring placement along each stem (the bark surface stage, [`super`]): rings follow the
//! Catmull-Rom centre curve and are added where the stem bends (about one per 12° of turn on thick
//! stems), through the trunk flare and rounded tips, and around the footprints of welded children
//! ([`weld`]: the parent gets extra rings across each footprint, the child starts at its junction
//! ring).

use crate::math::rad;
use crate::mesh::stem::drop_close;
use crate::mesh::weld;
use crate::skeleton::Stem;
use glam::Vec3;

/// Insert `t` into the sorted `out[first..]`.
fn insert_sorted(out: &mut Vec<f32>, first: usize, t: f32) {
    let k = out[first..].partition_point(|&x| x < t);
    out.insert(first + k, t);
}

/// Ring positions (fractions 0..1 of the stem) for one stem, appended to `out`. `feet` are the
/// junctions of its welded children, sorted by `t_lo`: each footprint needs a ring at most
/// [`weld::REACH`] footprint lengths below and above it, and gets one at its end where none is
/// that close; two footprints side by side around the stem (`pad`: one column) that no ring
/// separates get one between them, so that their holes never share a quad. A welded stem starts
/// at `start` (its junction ring) instead of 0. The last ring sits just short of the tip; the
/// apex closes the stem at t = 1.
pub(super) fn plan_rings(stem: &Stem, quality: f32, feet: &[weld::Junction], pad: f32, start: f32, out: &mut Vec<f32>) {
    let first = out.len();
    bent_rings(stem, quality, feet, pad, out);
    start_and_tip(stem, start, out, first);
}

/// The rings of [`plan_rings`] before its start and tip are placed: where the stem bends,
/// through the flare and rounded tips, and around the feet, appended to `out` (sorted). They do
/// not depend on the start, so a welded stem's tube and its fallback share them.
pub(super) fn bent_rings(stem: &Stem, quality: f32, feet: &[weld::Junction], pad: f32, out: &mut Vec<f32>) {
    let first = out.len();
    let pts = &stem.points;
    let segs = pts.len() - 1;
    let dir = |i: usize| (pts[i + 1] - pts[i]).normalize_or(Vec3::Y);
    let per_ring = rad(12.0) / (stem.radius / 0.02).sqrt().clamp(0.25, 1.0);
    let mut turn_in = 0.0f32;
    let mut d = dir(0);
    for i in 0..segs {
        // Subdivide a segment by the bend at its ends: about one ring per 12° of turn on thick
        // stems; thin stems tolerate more, since the chord error is what shows against the radius.
        let next = if i + 1 < segs { Some(dir(i + 1)) } else { None };
        // Turn angle from the chord between unit directions, c = 2 sin(θ/2): θ ≈ c (1 + c²/24),
        // within 0.5% up to 90°, which is all a ring count needs (and no acos per joint).
        let turn_out = next.map_or(0.0, |n| {
            let c = (n - d).length();
            c * (1.0 + c * c / 24.0)
        });
        let k = ((quality * turn_in.max(turn_out) / per_ring).ceil() as usize).clamp(1, 8);
        for j in 0..k {
            out.push((i as f32 + j as f32 / k as f32) / segs as f32);
        }
        turn_in = turn_out;
        if let Some(n) = next {
            d = n;
        }
    }
    let extra = stem.flare > 0.0 || stem.taper > 1.0;
    if stem.flare > 0.0 {
        // The flare lives in the lowest eighth and rises steeply: rings packed toward the ground.
        let m = ((6.0 * quality).ceil() as usize).max(2);
        for j in 1..m {
            let f = j as f32 / m as f32;
            out.push(0.125 * f * f);
        }
    }
    if stem.taper > 1.0 {
        // Rounded tips and periodic bulges change radius within one radius of length.
        let spacing = (0.5 * stem.radius / stem.length).max(1.0 / 128.0);
        let from = if stem.taper < 2.0 { (1.0 - 1.5 * stem.radius / stem.length).max(0.0) } else { 0.0 };
        let mut t = from;
        while t < 1.0 {
            out.push(t);
            t += spacing;
        }
    }
    if extra {
        out[first..].sort_by(f32::total_cmp);
    }
    drop_close(out, first);
    ring_feet(out, first, feet, pad);
}

/// The rings `out[first..]` (sorted) completed around `feet` (sorted by `t_lo`): a ring within
/// [`weld::REACH`] footprint lengths below and above each footprint, and one between two
/// footprints side by side around the stem that no ring separates ([`bent_rings`]).
fn ring_feet(out: &mut Vec<f32>, first: usize, feet: &[weld::Junction], pad: f32) {
    for (i, f) in feet.iter().enumerate() {
        ring_ends(out, first, f);
        // A ring lies between e and f exactly when the last ring at or below f's start is at or
        // above e's end: found once for f, then kept as the midpoints go in (each above it and
        // at most f's start), rather than searched for every earlier foot.
        let below = |out: &[f32]| {
            let k = out.partition_point(|&x| x <= f.t_lo);
            k.checked_sub(1).map(|k| out[k])
        };
        let mut last = below(&out[first..]);
        for e in &feet[..i] {
            if e.t_hi <= f.t_lo && last.is_none_or(|g| e.t_hi > g) && f.side_by_side(e, pad) {
                let mid = 0.5 * (e.t_hi + f.t_lo);
                insert_sorted(out, first, mid);
                last = Some(mid);
            }
        }
    }
}

/// Whether `out` holds a ring from `lo` to `hi` (sorted, both ends included).
fn has_ring(out: &[f32], lo: f32, hi: f32) -> bool {
    let k = out.partition_point(|&x| x < lo);
    k < out.len() && out[k] <= hi
}

/// The rings `out[first..]` (sorted) with one at each end of footprint `f` where none lies
/// within [`weld::REACH`] footprint lengths of it.
fn ring_ends(out: &mut Vec<f32>, first: usize, f: &weld::Junction) {
    let reach = weld::REACH * (f.t_hi - f.t_lo);
    if !has_ring(&out[first..], f.t_lo - reach, f.t_lo) {
        insert_sorted(out, first, f.t_lo);
    }
    if !has_ring(&out[first..], f.t_hi, f.t_hi + reach) {
        insert_sorted(out, first, f.t_hi);
    }
}

/// Completes the rings `out[first..]` of [`bent_rings`] into those of [`plan_rings`]: the tube starts
/// at `start` (0, or its junction ring) and ends a little short of the tip, or of a cut.
pub(super) fn start_and_tip(stem: &Stem, start: f32, out: &mut Vec<f32>, first: usize) {
    if start > 0.0 {
        // Drop the rings the junction replaces; the junction ring is the first.
        let keep = out[first..].partition_point(|&t| t <= start + 1e-4) + first;
        out.drain(first..keep);
        out.insert(first, start);
    }
    if stem.cut_end {
        // A cut end: the last ring a bevel short of the cut plane (see `crate::mesh::cut_face`).
        let end = 1.0 - crate::mesh::cut_face::bevel(stem) / stem.length.max(1e-6);
        let keep = out[first..].partition_point(|&t| t < end - 1e-4).max(1) + first;
        out.truncate(keep);
        let last = out[out.len() - 1];
        out.push(if end > last + 1e-4 { end } else { last + 0.75 * (1.0 - last) });
        return;
    }
    // Close to the tip (a quarter of the last spacing before it), leaving room for the apex.
    let last = *out.last().expect("at least one ring");
    out.push(last + 0.75 * (1.0 - last));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`ring_feet`] spelled out: every earlier foot searched for a ring between it and the next.
    fn plain(out: &mut Vec<f32>, first: usize, feet: &[weld::Junction], pad: f32) {
        for (i, f) in feet.iter().enumerate() {
            ring_ends(out, first, f);
            for e in &feet[..i] {
                if e.t_hi <= f.t_lo && f.side_by_side(e, pad) && !has_ring(&out[first..], e.t_hi, f.t_lo) {
                    insert_sorted(out, first, 0.5 * (e.t_hi + f.t_lo));
                }
            }
        }
    }

    #[test]
    fn feet_get_the_rings_of_the_plain_search() {
        let mut r = crate::rng::Rng::new(5, "ring_feet_test");
        for case in 0..300 {
            // Crowded stems (many short footprints around it) and sparse ones.
            let count = 1 + (r.next_f32() * if case % 3 == 0 { 120.0 } else { 12.0 }) as usize;
            let mut feet: Vec<weld::Junction> = (0..count)
                .map(|_| {
                    let t_lo = r.next_f32();
                    weld::Junction {
                        parent: 0,
                        t_start: 0.0,
                        t_lo,
                        t_hi: t_lo + 0.002 + 0.05 * r.next_f32(),
                        foot: 0.01,
                        phi: crate::math::TAU * r.next_f32(),
                        beta: 0.6 * r.next_f32(),
                        fork: false,
                    }
                })
                .collect();
            feet.sort_by(|a, b| a.t_lo.total_cmp(&b.t_lo));
            let mut rings = vec![9.0];
            let mut t = 0.0;
            while t < 1.0 {
                rings.push(t);
                t += 0.02 + 0.2 * r.next_f32();
            }
            let (mut fast, mut slow) = (rings.clone(), rings);
            ring_feet(&mut fast, 1, &feet, 0.1);
            plain(&mut slow, 1, &feet, 0.1);
            assert_eq!(fast, slow, "case {case}");
        }
    }
}
