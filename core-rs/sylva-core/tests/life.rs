//! Life past the Mature Age: shaded branches are shed over the decades and leave closing stubs
//! (scars), the pipe model thickens the stems year by year, main branches sink under their load
//! with their tips turned up, leaves stay only on recent wood with Leafy Years; at the Mature Age
//! none of it runs.

mod common;

use common::{assert_mesh_invariants, edge_uses};
use sylva_core::life::shed::shoot_light;
use sylva_core::skeleton::{Skeleton, StemKind};
use sylva_core::{generate, Generated, TreeParams};

fn at(age: f32, values: &[(&str, f32)]) -> Generated {
    let mut v: Vec<(&str, f64)> = values.iter().map(|&(k, x)| (k, f64::from(x))).collect();
    v.push(("age", f64::from(age)));
    generate(&TreeParams::from_values(v).unwrap()).unwrap()
}

/// Living stems: not roots, not the stubs of shed branches.
fn branches(sk: &Skeleton) -> usize {
    sk.stems.iter().filter(|s| s.kind != StemKind::Root && !s.cut_end).count()
}

fn main_branch_tips(sk: &Skeleton) -> Vec<(glam::Vec3, f32)> {
    sk.stems.iter().filter(|s| s.level == 1 && s.kind == StemKind::Branch).map(|s| (s.tip(), s.length)).collect()
}

#[test]
fn at_the_mature_age_nothing_changes_whatever_the_life_parameters() {
    let plain = at(40.0, &[]);
    let tuned = at(40.0, &[("ring_width", 9.0), ("shed_light", 0.9), ("shed_years", 1.0), ("droop", 20.0)]);
    assert_eq!(plain.hash, tuned.hash);
    let leafy = at(40.0, &[("leaf_years", 0.0)]);
    assert_eq!(plain.hash, leafy.hash);
}

#[test]
fn shading_sheds_branches_over_decades_and_leaves_closing_scars() {
    // Shedding Light 0.3: a crown with its shaded third dropping over the decades.
    let shady = [("shed_light", 0.3)];
    let young = at(20.0, &shady);
    let mature = at(40.0, &shady);
    let old = at(60.0, &shady);
    let older = at(100.0, &shady);
    let (m, o, oo) = (branches(&mature.skeleton), branches(&old.skeleton), branches(&older.skeleton));
    assert!(o < m && oo < o, "stems: mature {m}, 60 years {o}, 100 years {oo}");
    assert!(branches(&young.skeleton) < m, "a 20-year tree is still growing");
    // Stubs: cut ends with woundwood closing over them, some already closed.
    let stubs: Vec<f32> = older.skeleton.stems.iter().filter(|s| s.cut_end).map(|s| s.callus).collect();
    assert!(stubs.len() > 3, "{} stubs", stubs.len());
    assert!(stubs.iter().all(|c| (0.0..=1.0).contains(c)));
    assert!(stubs.iter().any(|&c| c > 0.5), "old stubs are closing: {stubs:?}");
    // The shed are the shaded: in the mature crown's light, the stems that became stubs saw less
    // sky than those still alive.
    let light = shoot_light(&mature.skeleton).unwrap();
    let sky = |g: &Generated, stub: bool| {
        let v: Vec<f32> = g
            .skeleton
            .stems
            .iter()
            .filter(|s| s.level >= 1 && s.kind == StemKind::Branch && s.cut_end == stub)
            .map(|s| light.sky_at(s.tip()))
            .collect();
        v.iter().sum::<f32>() / v.len() as f32
    };
    assert!(sky(&older, true) < sky(&older, false), "{} vs {}", sky(&older, true), sky(&older, false));
    // No shedding without a threshold.
    assert_eq!(branches(&at(100.0, &[("shed_light", 0.0)]).skeleton), m);
    for g in [&old, &older] {
        assert_mesh_invariants(g, "old tree");
        let open = edge_uses(&g.mesh).values().filter(|&&u| u != 2).count();
        assert_eq!(open, 0, "{open} edges open");
    }
}

#[test]
fn the_pipe_model_thickens_every_stem_by_its_tips() {
    let mature = at(40.0, &[("shed_light", 0.0), ("droop", 0.0)]);
    let old = at(60.0, &[("shed_light", 0.0), ("droop", 0.0)]);
    let trunk = (mature.skeleton.stems[0].radius, old.skeleton.stems[0].radius);
    assert!((trunk.1 - trunk.0 - 0.06).abs() < 1e-4, "20 years of 3 mm rings: {trunk:?}");
    for (a, b) in mature.skeleton.stems.iter().zip(&old.skeleton.stems) {
        assert!(b.radius >= a.radius, "no stem thins");
    }
    // Relative growth is largest where the stem is thin for the tips it feeds: the trunk grows
    // more in absolute terms than a twig.
    let twig = mature.skeleton.stems.iter().rposition(|s| s.level == 2).unwrap();
    let d = old.skeleton.stems[twig].radius - mature.skeleton.stems[twig].radius;
    assert!(d > 0.0 && d < trunk.1 - trunk.0);
}

#[test]
fn main_branches_sink_under_their_load_and_turn_their_tips_up() {
    let flat = at(60.0, &[("shed_light", 0.0), ("droop", 0.0)]);
    let sunk = at(60.0, &[("shed_light", 0.0), ("droop", 10.0)]);
    let (a, b) = (main_branch_tips(&flat.skeleton), main_branch_tips(&sunk.skeleton));
    assert_eq!(a.len(), b.len());
    let lower = a.iter().zip(&b).filter(|(p, q)| q.0.y < p.0.y - 1e-3).count();
    assert!(lower * 10 >= a.len() * 9, "{lower} of {} tips lower", a.len());
    for ((_, la), (_, lb)) in a.iter().zip(&b) {
        assert!((la - lb).abs() < 1e-4, "length kept");
    }
    // More years, more sag (a long branch's load keeps growing).
    let sunk_more = at(100.0, &[("shed_light", 0.0), ("droop", 10.0)]);
    let mean_y = |t: &[(glam::Vec3, f32)]| t.iter().map(|p| p.0.y).sum::<f32>() / t.len() as f32;
    assert!(mean_y(&main_branch_tips(&sunk_more.skeleton)) < mean_y(&b));
    // The outer part turns up: the tip's slope sags less than the branch's chord.
    let s = sunk.skeleton.stems.iter().find(|s| s.level == 1 && s.kind == StemKind::Branch && s.length > 3.0).unwrap();
    let (_, tip_dir) = s.sample(1.0);
    let (_, mid_dir) = s.sample(0.6);
    assert!(tip_dir.y > mid_dir.y, "tip turned up: {tip_dir} vs {mid_dir}");
    assert_mesh_invariants(&sunk_more, "sunk");
}

#[test]
fn leaves_sit_only_on_recent_wood() {
    let all = at(40.0, &[]);
    let recent = at(40.0, &[("leaf_years", 8.0)]);
    assert!(recent.foliage.count() < all.foliage.count());
    assert!(recent.foliage.count() > 0);
    // The leaves kept are the outer ones: on average further from the trunk axis.
    let mean_r = |g: &Generated| {
        let m = &g.foliage.matrices;
        let n = m.len() / 16;
        (0..n).map(|i| glam::Vec2::new(m[i * 16 + 12], m[i * 16 + 14]).length()).sum::<f32>() / n as f32
    };
    assert!(mean_r(&recent) > mean_r(&all), "{} vs {}", mean_r(&recent), mean_r(&all));
    // More years of leafy wood, more leaves.
    assert!(at(40.0, &[("leaf_years", 20.0)]).foliage.count() > recent.foliage.count());
    // With the season too (leaves kept and leaves fallen both thin the crown): October.
    let autumn = at(40.0, &[("leaf_years", 8.0), ("season", 10.5)]);
    assert!(autumn.foliage.count() <= recent.foliage.count());
    assert_eq!(autumn.foliage.matrices.len(), autumn.foliage.count() * 16);
}
