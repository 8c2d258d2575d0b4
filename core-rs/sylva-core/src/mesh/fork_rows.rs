//! How many rows of quads a fork's side patches get ([`super::fork`]): the side patches bend
//! twice (leaving along the original, arriving along the branch), so they need rows enough for
//! each bend not to show as one polygon corner (issue #17's knee on a shifted fork).

use super::weld::Junction;
use crate::skeleton::Stem;

/// Number of quad rows of each branch's collar: about one per half radius of the fork's length
/// at quality 1, [`MIN_ROWS`] to [`MAX_ROWS`]. The side patches bend twice (leaving along the
/// original, arriving along the branch); with two or three rows each bend was one polygon
/// corner, a visible knee where a shifted fork's branch has drawn far away.
pub(crate) fn rows(j: &Junction, original: &Stem, quality: f32) -> usize {
    let len = (j.t_hi - j.t_lo) * original.length;
    let r = original.radius_at(j.t_lo).max(1e-6);
    ((quality * len / (0.5 * r)).ceil() as usize).clamp(MIN_ROWS, MAX_ROWS)
}

/// The row counts a fork is tried with, in order: [`rows`], then one fewer at a time down to
/// the coarse count of before (one row per 1.5 radii, 2 to 6), for a fork whose fine rows would
/// fold a triangle (a second clone forking one step up, whose branch has drawn far away).
pub(crate) fn row_choices(j: &Junction, original: &Stem, quality: f32) -> impl Iterator<Item = usize> {
    let len = (j.t_hi - j.t_lo) * original.length;
    let r = original.radius_at(j.t_lo).max(1e-6);
    let coarse = ((quality * len / (1.5 * r)).ceil() as usize).clamp(2, 6);
    let fine = rows(j, original, quality);
    (coarse.min(fine)..=fine).rev()
}

/// Fewest and most quad rows of a fork's side patches ([`rows`]).
pub(crate) const MIN_ROWS: usize = 5;
/// See [`MIN_ROWS`].
pub(crate) const MAX_ROWS: usize = 10;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::fork::tests::fork;
    use crate::skeleton::StemKind;
    use glam::Vec3;

    #[test]
    fn short_forks_get_enough_rows_to_bend_smoothly() {
        // A fork 2.5 radii long (the shifted second fork of CA Black Oak's base) once had two
        // rows, each bend a single polygon corner (issue #17's knee).
        let stem = Stem {
            level: 0,
            kind: StemKind::Trunk,
            parent: None,
            offset: 0.0,
            base_normal: Vec3::X,
            length: 10.0,
            radius: 0.1,
            taper: 0.0,
            flare: 0.0,
            down_angle: 0.0,
            chain_length: 10.0,
            chain_radius: 0.1,
            chain_start: 0.0,
            lobed: false,
            radii: Some(vec![0.1, 0.1]),
            cut_end: false,
            callus: 0.0,
            born: 0.0,
            tip_year: 0.0,
            points: [Vec3::ZERO, Vec3::Y * 10.0].into_iter().collect(),
        };
        let short = fork(0.1, 0.1 + 2.5 * 0.1 / 10.0);
        assert!(rows(&short, &stem, 1.0) >= MIN_ROWS);
        assert_eq!(rows(&fork(0.1, 0.8), &stem, 1.0), MAX_ROWS);
        assert!(rows(&short, &stem, 4.0) > rows(&short, &stem, 1.0));
    }
}
