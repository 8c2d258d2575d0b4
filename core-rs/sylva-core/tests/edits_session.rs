//! The session's skeleton stage resumes on the hand edit list: a stroke drawn point by point
//! extends its growth instead of growing again, an edit added, undone or redone starts from the
//! tree before it, and every answer is the same tree (the same hash) as a cold generation of
//! the same list.

use glam::Vec3;
use sylva_core::clock::NoClock;
use sylva_core::params::{Bend, Cut, Edit, Paint, SkeletonParams};
use sylva_core::session::{Quality, Resume, Session};
use sylva_core::skeleton::Skeleton;
use sylva_core::{generate, TreeParams};

fn with_edits(edits: Vec<Edit>) -> TreeParams {
    TreeParams { skeleton: SkeletonParams { edits, ..Default::default() }, ..TreeParams::default() }
}

/// A stroke from inside the default tree's crown out beside it, as the studio lays one: brush
/// points a fifth of a metre apart.
fn stroke(points: usize) -> Paint {
    let points = (0..points).map(|i| Vec3::new(1.5 + 0.2 * i as f32, 9.0 + 0.04 * i as f32, 0.2)).collect();
    Paint { points, radius: 0.6, density: 400.0, segment: 0.25, kill: 0.4 }
}

/// A long first-level branch with several children, as `tests/edits.rs` picks one.
fn a_branch(sk: &Skeleton) -> usize {
    (0..sk.stems.len())
        .find(|&i| {
            let s = &sk.stems[i];
            s.level == 1 && s.length > 2.0 && sk.stems.iter().filter(|c| c.parent == Some(i as u32)).count() > 3
        })
        .expect("the default tree has long branches")
}

/// Brings `session` to `edits` at full quality: its hash, checked against a cold generation.
fn full(session: &mut Session, edits: &[Edit]) -> Resume {
    let p = with_edits(edits.to_vec());
    session.update(&p, Quality::Full, &NoClock, None).expect("the edited tree");
    let cold = generate(&p).expect("cold");
    assert_eq!(session.hash(), Some(cold.hash), "{} edits: the session's tree is the cold one", edits.len());
    session.skeleton_resume()
}

#[test]
fn a_stroke_drawn_point_by_point_extends_its_growth_and_ends_where_the_whole_stroke_does() {
    let whole = stroke(30);
    let mut session = Session::new();
    session.update(&TreeParams::default(), Quality::Full, &NoClock, None).expect("the default tree");
    let drag = Quality::Preview { budget_ms: 16.0 };
    for k in 2..=whole.points.len() {
        let part = Paint { points: whole.points[..k].to_vec(), ..whole.clone() };
        let p = with_edits(vec![Edit::Paint(part.clone())]);
        session.update(&p, drag, &NoClock, None).expect("a stroke being drawn");
        let resume = session.skeleton_resume();
        assert!(!resume.rebuilt, "point {k}: the stems are not built again");
        assert_eq!(resume.extended_stroke, k > 2, "point {k}: {resume:?}");
        if k == 10 || k == whole.points.len() {
            // The release: the full tree, the same as growing the whole stroke at once.
            let r = full(&mut session, &[Edit::Paint(part)]);
            assert!(r.extended_stroke, "the release extends the stroke too: {r:?}");
        }
    }
    let grown = session.current().expect("a tree").skeleton.skeleton.stems.len();
    assert!(grown > generate(&TreeParams::default()).unwrap().stats.stems, "the stroke grew shoots");
}

#[test]
fn edits_added_undone_and_redone_resume_from_the_tree_before_them() {
    let g0 = generate(&TreeParams::default()).unwrap();
    let s = &g0.skeleton.stems[a_branch(&g0.skeleton)];
    let at = s.point_at(0.6 * s.length).0;
    let paint = Edit::Paint(stroke(12));
    let bend = Edit::Bend(Bend { at, to: at + Vec3::new(0.0, -0.4, 0.0) });
    let cut = Edit::Cut(Cut { at: s.point_at(0.85 * s.length).0, year: None });
    let mut session = Session::new();
    let r = full(&mut session, &[]);
    assert!(r.rebuilt);
    let r = full(&mut session, std::slice::from_ref(&paint));
    assert_eq!(r, Resume { rebuilt: false, reused_edits: 0, extended_stroke: false });
    // A bend after the stroke starts from the painted tree: the stroke is not grown again.
    let list = [paint.clone(), bend.clone(), cut.clone()];
    assert_eq!(full(&mut session, &list[..2]).reused_edits, 1);
    assert_eq!(full(&mut session, &list).reused_edits, 2);
    // Undo the cut, then redo it: both start from the tree after the bend.
    assert_eq!(full(&mut session, &list[..2]).reused_edits, 2);
    assert_eq!(full(&mut session, &list).reused_edits, 2);
    // Undo back to the bare tree and redo the stroke: from the tree as built.
    assert_eq!(full(&mut session, &[]).reused_edits, 0);
    assert_eq!(full(&mut session, &list[..1]).reused_edits, 0);
    // Deleting the first edit replays the others on the tree as built.
    let r = full(&mut session, &list[1..]);
    assert_eq!((r.rebuilt, r.reused_edits), (false, 0));
    // A new seed builds the stems again; the edits apply to the new tree.
    let mut p = with_edits(list.to_vec());
    p.skeleton.seed = 7;
    session.update(&p, Quality::Full, &NoClock, None).expect("a new seed");
    assert!(session.skeleton_resume().rebuilt);
    assert_eq!(session.hash(), Some(generate(&p).unwrap().hash));
}

#[test]
fn a_failed_stroke_keeps_the_tree_and_the_next_update_is_right() {
    let mut session = Session::new();
    full(&mut session, &[Edit::Paint(stroke(6))]);
    let before = session.hash();
    // Far too dense: the stroke stops with a budget error and the tree stays.
    let dense = Paint { density: 5000.0, ..stroke(60) };
    let e = session
        .update(&with_edits(vec![Edit::Paint(dense)]), Quality::Full, &NoClock, None)
        .expect_err("past the marker cap");
    assert!(e.to_string().contains("edits[0].density"), "{e}");
    assert_eq!(session.hash(), before);
    // The cache forgot the failed stroke: a longer stroke of the first brush is still right.
    full(&mut session, &[Edit::Paint(stroke(9))]);
}

#[test]
fn a_one_shot_session_updated_again_builds_its_tree_again() {
    // `generate`'s session hands its stems on instead of keeping copies: a second update (which
    // `generate` never makes) finds nothing kept and must build everything again.
    let mut session = Session::one_shot();
    let g0 = generate(&TreeParams::default()).expect("the default tree");
    let s = &g0.skeleton.stems[a_branch(&g0.skeleton)];
    let at = s.point_at(0.6 * s.length).0;
    let bend = Edit::Bend(Bend { at, to: at + Vec3::new(0.0, -0.4, 0.0) });
    let lists =
        [vec![], vec![Edit::Paint(stroke(12))], vec![bend.clone()], vec![bend.clone(), Edit::Paint(stroke(8))], vec![]];
    for edits in &lists {
        let r = full(&mut session, edits);
        assert!(r.rebuilt && r.reused_edits == 0, "nothing was kept: {r:?}");
    }
    let mut aged = with_edits(vec![bend]);
    aged.set("age", 20.0).expect("an age");
    session.update(&aged, Quality::Full, &NoClock, None).expect("a younger tree");
    assert_eq!(session.hash(), Some(generate(&aged).expect("cold").hash));
}
