//! Hand edits on the default tree: a cut removes exactly its subtree and leaves a closed, capped
//! end; a bend moves the dragged point to its target and keeps the length, children riding along;
//! an edit that finds no stem is reported and changes nothing; the same edits give the same
//! bytes, cold or through a session.

mod common;

use common::{assert_mesh_invariants, edge_uses};
use glam::Vec3;
use sylva_core::clock::NoClock;
use sylva_core::edits::cut::FOOTPRINT;
use sylva_core::edits::resolve;
use sylva_core::mesh::cut_face::BEVEL;
use sylva_core::params::{Bend, Cut, Edit, SkeletonParams};
use sylva_core::session::{Quality, Session};
use sylva_core::skeleton::Skeleton;
use sylva_core::{generate, Generated, Material, TreeParams};

fn with_edits(edits: Vec<Edit>) -> TreeParams {
    TreeParams { skeleton: SkeletonParams { edits, ..Default::default() }, ..TreeParams::default() }
}

/// A level-1 branch of the default tree with children, longer than 2 m.
fn a_branch(sk: &Skeleton) -> usize {
    (0..sk.stems.len())
        .find(|&i| {
            let s = &sk.stems[i];
            s.level == 1 && s.length > 2.0 && sk.stems.iter().filter(|c| c.parent == Some(i as u32)).count() > 3
        })
        .expect("the default tree has long branches")
}

/// Stems a cut of stem `i` at `along` must remove: the children whose footprint reaches past
/// it, with all their descendants.
fn beyond(sk: &Skeleton, i: usize, along: f32) -> usize {
    let mut gone = vec![false; sk.stems.len()];
    for (c, s) in sk.stems.iter().enumerate().skip(i + 1) {
        gone[c] = match s.parent {
            Some(p) if p as usize == i => s.offset + FOOTPRINT * s.radius > along,
            Some(p) => gone[p as usize],
            None => false,
        };
    }
    gone.iter().filter(|&&g| g).count()
}

fn assert_closed(g: &Generated, name: &str) {
    assert_mesh_invariants(g, name);
    let open = edge_uses(&g.mesh).values().filter(|&&u| u != 2).count();
    assert_eq!(open, 0, "{name}: {open} edges open or non-manifold");
}

fn assert_children_attached(sk: &Skeleton, name: &str) {
    for (c, s) in sk.stems.iter().enumerate() {
        if let Some(p) = s.parent {
            let (on, _) = sk.stems[p as usize].point_at(s.offset);
            assert!(on.distance(s.base()) < 1e-3, "{name}: stem {c} left its parent by {}", on.distance(s.base()));
        }
    }
}

#[test]
fn a_cut_removes_the_subtree_and_leaves_a_closed_capped_end() {
    let g0 = generate(&TreeParams::default()).unwrap();
    let sk = &g0.skeleton;
    let i = a_branch(sk);
    let along = 0.5 * sk.stems[i].length;
    let (at, _) = sk.stems[i].point_at(along);
    let removed = beyond(sk, i, along);
    assert!(removed > 3, "the cut takes children with it");
    let g = generate(&with_edits(vec![Edit::Cut(Cut { at, year: None })])).unwrap();
    assert_eq!(g.skeleton.stems.len(), sk.stems.len() - removed);
    assert_eq!(g.edits.len(), 1);
    assert!(g.edits[0].resolved, "{:?}", g.edits);
    assert!(g.mesh.vertex_count() < g0.mesh.vertex_count());
    assert!(g.foliage.count() < g0.foliage.count(), "the cut branch's leaves go with it");
    assert_closed(&g, "cut");
    // The stump: cut at its length, ending with the radius it had there.
    let stump = &g.skeleton.stems[i];
    assert!(stump.cut_end);
    assert!((stump.length - along).abs() < 1e-3);
    assert!((stump.radius_at(1.0) - sk.stems[i].radius_at(0.5)).abs() < 1e-4);
    assert!(stump.tip().distance(at) < 1e-3);
    // Its face: one cut-face group whose vertices lie in the cut plane, within the bevel.
    let faces: Vec<_> = g.mesh.groups.iter().filter(|gr| gr.material == Material::CutFace).collect();
    assert_eq!(faces.len(), 1);
    let (tip, n) = stump.sample(1.0);
    let bevel = BEVEL * stump.radius_at(1.0);
    let face = &g.mesh.indices[faces[0].start as usize..(faces[0].start + faces[0].count) as usize];
    for &v in face {
        let p = Vec3::from_slice(&g.mesh.positions[v as usize * 3..v as usize * 3 + 3]);
        assert!((p - tip).dot(n).abs() <= bevel, "a face vertex lies {} m off the cut plane", (p - tip).dot(n));
        assert!(p.distance(tip) <= stump.radius_at(1.0) * 1.5, "a face vertex outside the stump");
    }
    assert!(g.meta_json().contains(r#""edits":[{"op":"cut","resolved":true}]"#), "{}", g.meta_json());
}

#[test]
fn cutting_the_trunk_keeps_the_roots_and_stays_closed() {
    let p = TreeParams::from_values([("root_count", 3.0)]).unwrap();
    let g0 = generate(&p).unwrap();
    let mut q = p.clone();
    q.skeleton.edits = vec![Edit::Cut(Cut { at: g0.skeleton.stems[0].point_at(2.0).0, year: None })];
    let g = generate(&q).unwrap();
    assert!(g.edits[0].resolved);
    assert_eq!(g.skeleton.stems.iter().filter(|s| s.kind == sylva_core::skeleton::StemKind::Root).count(), 3);
    assert!(g.bounds.max[1] < 2.5, "the crown is gone: {:?}", g.bounds);
    assert_closed(&g, "trunk cut");
}

#[test]
fn a_bend_moves_the_point_keeps_the_length_and_carries_the_children() {
    let g0 = generate(&TreeParams::default()).unwrap();
    let sk = &g0.skeleton;
    let i = a_branch(sk);
    let s = &sk.stems[i];
    let a = 0.7 * s.length;
    let (at, _) = s.point_at(a);
    let base = s.base();
    // A reachable target: the point turned 15° about the base, across the branch.
    let chord = at - base;
    let axis = chord.cross(Vec3::Y).normalize();
    let to = base + sylva_core::math::quat_axis_angle(axis, 15f32.to_radians()) * chord;
    let g = generate(&with_edits(vec![Edit::Bend(Bend { at, to })])).unwrap();
    assert!(g.edits[0].resolved);
    assert_eq!(g.skeleton.stems.len(), sk.stems.len());
    let bent = &g.skeleton.stems[i];
    let moved = bent.point_at(a).0;
    assert!(moved.distance(to) < 0.01, "the point is {} m from its target", moved.distance(to));
    let polyline = |st: &sylva_core::skeleton::Stem| st.points.windows(2).map(|w| w[0].distance(w[1])).sum::<f32>();
    let before = (0..=64).map(|k| s.point(k as f32 / 64.0)).collect::<Vec<_>>();
    let after = (0..=64).map(|k| bent.point(k as f32 / 64.0)).collect::<Vec<_>>();
    let curve = |p: &[Vec3]| p.windows(2).map(|w| w[0].distance(w[1])).sum::<f32>();
    assert!((curve(&after) / curve(&before) - 1.0).abs() < 0.01, "length {} -> {}", curve(&before), curve(&after));
    assert!(polyline(bent) > 0.0);
    assert!(bent.base().distance(base) < 1e-6, "the base stays");
    assert_children_attached(&g.skeleton, "bend");
    // The children moved with the branch.
    let child = (0..sk.stems.len()).rev().find(|&c| sk.stems[c].parent == Some(i as u32)).unwrap();
    assert!(g.skeleton.stems[child].tip().distance(sk.stems[child].tip()) > 0.05);
    assert_closed(&g, "bend");
}

#[test]
fn an_edit_that_no_longer_resolves_is_reported_and_changes_nothing() {
    let plain = generate(&TreeParams::default()).unwrap();
    let mid_air = Vec3::new(40.0, 5.0, 40.0);
    let g = generate(&with_edits(vec![
        Edit::Cut(Cut { at: mid_air, year: None }),
        Edit::Bend(Bend { at: mid_air, to: mid_air + Vec3::X }),
    ]))
    .unwrap();
    assert!(g.edits.iter().all(|e| !e.resolved && e.why.as_deref().is_some_and(|w| w.contains("no stem within"))));
    assert_eq!(g.hash, plain.hash, "unresolved edits leave the tree as it was");
    // A cut on a twig's tip of seed 0 that finds nothing in seed 5.
    let mut other = TreeParams::default();
    other.skeleton.seed = 5;
    let sk5 = generate(&other).unwrap().skeleton;
    let at = plain
        .skeleton
        .stems
        .iter()
        .filter(|s| s.level == 2)
        .map(|s| s.point_at(0.9 * s.length).0)
        .find(|&p| resolve::nearest(&sk5, p).is_err())
        .expect("some twig tip of seed 0 is far from every stem of seed 5");
    assert!(resolve::nearest(&plain.skeleton, at).is_ok());
    other.skeleton.edits = vec![Edit::Cut(Cut { at, year: None })];
    let g = generate(&other).unwrap();
    assert!(!g.edits[0].resolved);
    assert!(g.meta_json().contains(r#""resolved":false"#));
    other.skeleton.edits.clear();
    assert_eq!(g.hash, generate(&other).unwrap().hash);
}

#[test]
fn same_edits_same_bytes_cold_or_through_a_session() {
    let g0 = generate(&TreeParams::default()).unwrap();
    let i = a_branch(&g0.skeleton);
    let s = &g0.skeleton.stems[i];
    let edits = vec![
        Edit::Bend(Bend {
            at: s.point_at(0.6 * s.length).0,
            to: s.point_at(0.6 * s.length).0 + Vec3::new(0.0, 0.4, 0.0),
        }),
        Edit::Cut(Cut { at: s.point_at(0.8 * s.length).0, year: None }),
    ];
    let p = with_edits(edits);
    let a = generate(&p).unwrap();
    let b = generate(&p).unwrap();
    assert_eq!(a.hash, b.hash);
    assert_ne!(a.hash, g0.hash);
    let mut session = Session::new();
    session.update(&TreeParams::default(), Quality::Full, &NoClock, None).unwrap();
    let c = session.update(&p, Quality::Full, &NoClock, None).unwrap();
    assert_eq!(c.from, sylva_core::params::Stage::Skeleton, "an edit is a skeleton-stage change");
    assert_eq!(session.hash(), Some(a.hash));
    assert_eq!(session.update(&TreeParams::default(), Quality::Full, &NoClock, None).unwrap().skeleton.edits, vec![]);
    assert_eq!(session.hash(), Some(g0.hash));
}

#[test]
fn a_bend_across_the_tree_is_an_error_naming_the_edit() {
    let g0 = generate(&TreeParams::default()).unwrap();
    let i = a_branch(&g0.skeleton);
    let s = &g0.skeleton.stems[i];
    let at = s.point_at(0.5 * s.length).0;
    let e = generate(&with_edits(vec![
        Edit::Cut(Cut { at: Vec3::new(90.0, 1.0, 0.0), year: None }),
        Edit::Bend(Bend { at, to: s.base() + (s.base() - at).normalize() * (s.length + 1.0) }),
    ]))
    .unwrap_err();
    assert!(e.message().starts_with("edits[1].to is"), "{e}");
    assert!(e.message().ends_with("a bend across the tree"), "{e}");
}
