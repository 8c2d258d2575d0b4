//! Checking an edit list against the documented limits of [`super`]: counts, finite coordinates
//! within ±[`MAX_COORD`], the paint ranges, outlines that close without crossing themselves, cuts
//! and bends above the ground. Every message names the edit and the field, e.g.
//! `edits[3].radius is 0: allowed range is 0.02 to 10 m`.

use super::{
    bad, Edit, DENSITY_RANGE, GROUND, KILL_RANGE, MAX_COORD, MAX_EDITS, MAX_OUTLINE_POINTS, MAX_POINTS,
    MAX_STROKE_POINTS, RADIUS_RANGE, SEGMENT_RANGE, YEAR_RANGE,
};
use crate::error::SylvaError;
use glam::{Vec2, Vec3};

/// Check an edit list: at most [`MAX_EDITS`] edits and [`MAX_POINTS`] points in all, every field
/// in its documented range. Errors name the edit and field (`edits[i].field`).
pub fn validate(edits: &[Edit]) -> Result<(), SylvaError> {
    check_count(edits.len())?;
    let mut points = 0usize;
    for (i, e) in edits.iter().enumerate() {
        let f = |name: &str| format!("edits[{i}].{name}");
        match e {
            Edit::Paint(p) => {
                points += p.points.len();
                check_points(&f("points"), p.points.len(), MAX_STROKE_POINTS, 1)?;
                for (k, &q) in p.points.iter().enumerate() {
                    check_vec3(&format!("{}[{k}]", f("points")), q)?;
                }
                check_range(&f("radius"), p.radius, RADIUS_RANGE, " m")?;
                check_range(&f("density"), p.density, DENSITY_RANGE, " markers per m³")?;
                check_range(&f("segment"), p.segment, SEGMENT_RANGE, " m")?;
                check_range(&f("kill"), p.kill, KILL_RANGE, " m")?;
                if p.kill < p.segment {
                    return Err(bad(
                        f("kill"),
                        format!(
                            "{} is {}: it must be at least the segment length {} m (else new shoots step past their markers)",
                            f("kill"),
                            p.kill,
                            p.segment
                        ),
                    ));
                }
            }
            Edit::Crown(c) => {
                points += c.outline.len();
                check_points(&f("outline"), c.outline.len(), MAX_OUTLINE_POINTS, 3)?;
                for (k, &q) in c.outline.iter().enumerate() {
                    let field = format!("{}[{k}]", f("outline"));
                    check_coord(&format!("{field}[0]"), q.x, 0.0)?;
                    check_coord(&format!("{field}[1]"), q.y, -MAX_COORD)?;
                }
                if let Some((a, b)) = first_crossing(&c.outline) {
                    return Err(bad(
                        f("outline"),
                        format!(
                            "{} crosses itself (its edges {a} and {b} intersect): draw a simple closed outline",
                            f("outline")
                        ),
                    ));
                }
            }
            Edit::Cut(c) => {
                check_above_ground(&f("at"), c.at)?;
                if let Some(year) = c.year {
                    check_range(&f("year"), year, YEAR_RANGE, " years")?;
                }
            }
            Edit::Bend(b) => {
                check_above_ground(&f("at"), b.at)?;
                check_vec3(&f("to"), b.to)?;
            }
        }
        if points > MAX_POINTS {
            return Err(bad(
                "edits",
                format!("the edits hold more than {MAX_POINTS} points in all (at edits[{i}]): split the work into fewer, shorter strokes"),
            ));
        }
    }
    Ok(())
}

/// At most [`MAX_EDITS`] edits.
pub(super) fn check_count(n: usize) -> Result<(), SylvaError> {
    if n > MAX_EDITS {
        return Err(bad("edits", format!("edits has {n} edits: at most {MAX_EDITS} are allowed")));
    }
    Ok(())
}

/// Between `min` and `max` points.
pub(super) fn check_points(field: &str, n: usize, max: usize, min: usize) -> Result<(), SylvaError> {
    if n > max {
        return Err(bad(field, format!("{field} has {n} points: at most {max} are allowed")));
    }
    if n < min {
        return Err(bad(field, format!("{field} has {n} points: at least {min} are needed")));
    }
    Ok(())
}

fn check_range(field: &str, v: f32, (lo, hi): (f32, f32), unit: &str) -> Result<(), SylvaError> {
    if !v.is_finite() || !(lo..=hi).contains(&v) {
        return Err(bad(field, format!("{field} is {v}: allowed range is {lo} to {hi}{unit}")));
    }
    Ok(())
}

fn check_coord(field: &str, v: f32, lo: f32) -> Result<(), SylvaError> {
    if !v.is_finite() || v < lo || v > MAX_COORD {
        return Err(bad(field, format!("{field} is {v}: allowed range is {lo} to {MAX_COORD} m")));
    }
    Ok(())
}

fn check_vec3(field: &str, q: Vec3) -> Result<(), SylvaError> {
    for (k, c) in q.to_array().into_iter().enumerate() {
        check_coord(&format!("{field}[{k}]"), c, -MAX_COORD)?;
    }
    Ok(())
}

fn check_above_ground(field: &str, q: Vec3) -> Result<(), SylvaError> {
    check_vec3(field, q)?;
    if q.y <= GROUND {
        return Err(bad(
            field,
            format!("{field} is on the ground (y = {} m): a cut or bend names a branch above {GROUND} m", q.y),
        ));
    }
    Ok(())
}

/// The first pair of non-adjacent edges of the closed polygon `p` that intersect (edge `k` runs
/// from `p[k]` to `p[k + 1]`, the last back to `p[0]`), if any.
pub(crate) fn first_crossing(p: &[Vec2]) -> Option<(usize, usize)> {
    let n = p.len();
    let edge = |k: usize| (p[k], p[(k + 1) % n]);
    for a in 0..n {
        for b in a + 1..n {
            let adjacent = b == a + 1 || (a == 0 && b == n - 1);
            let (p0, p1) = edge(a);
            let (q0, q1) = edge(b);
            if adjacent {
                // Neighbours share a point; they cross only by folding back onto each other.
                let (shared, x, y) = if b == a + 1 { (p1, p0, q1) } else { (p0, p1, q0) };
                let (u, v) = (x - shared, y - shared);
                if u.perp_dot(v) == 0.0 && u.dot(v) > 0.0 {
                    return Some((a, b));
                }
                continue;
            }
            if segments_meet(p0, p1, q0, q1) {
                return Some((a, b));
            }
        }
    }
    None
}

/// Whether the closed segments `a0 a1` and `b0 b1` share a point.
fn segments_meet(a0: Vec2, a1: Vec2, b0: Vec2, b1: Vec2) -> bool {
    let side = |p: Vec2, q: Vec2, r: Vec2| (q - p).perp_dot(r - p);
    let on = |p: Vec2, q: Vec2, r: Vec2| r.cmpge(p.min(q)).all() && r.cmple(p.max(q)).all();
    let (d1, d2) = (side(b0, b1, a0), side(b0, b1, a1));
    let (d3, d4) = (side(a0, a1, b0), side(a0, a1, b1));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return true;
    }
    (d1 == 0.0 && on(b0, b1, a0))
        || (d2 == 0.0 && on(b0, b1, a1))
        || (d3 == 0.0 && on(a0, a1, b0))
        || (d4 == 0.0 && on(a0, a1, b1))
}
