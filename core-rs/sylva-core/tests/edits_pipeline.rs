//! Paint and crown edits through the whole pipeline (`generate`, the session): a stroke beside
//! the crown grows the tree toward it and its markers are shown; the last crown edit shapes a
//! Weber & Penn tree whose Crown Shape is Drawn; edits give the same bytes cold and through a
//! session.

mod common;

use common::{assert_mesh_invariants, edge_uses};
use glam::{Vec2, Vec3};
use sylva_core::clock::NoClock;
use sylva_core::params::{Crown, CrownShape, Edit, Paint, SkeletonParams};
use sylva_core::session::{Quality, Session};
use sylva_core::{generate, TreeParams};

fn with_edits(edits: Vec<Edit>) -> TreeParams {
    TreeParams { skeleton: SkeletonParams { edits, ..Default::default() }, ..TreeParams::default() }
}

/// A stroke beside the default tree's crown, pointing away from the trunk along +x.
fn stroke() -> Edit {
    let points = (0..12).map(|i| Vec3::new(3.0 + 0.25 * i as f32, 9.0 + 0.05 * i as f32, 0.0)).collect();
    Edit::Paint(Paint { points, radius: 0.6, density: 400.0, segment: 0.25, kill: 0.4 })
}

#[test]
fn a_painted_stroke_grows_the_generated_tree_toward_it() {
    let plain = generate(&TreeParams::default()).expect("the default tree");
    let painted = generate(&with_edits(vec![stroke()])).expect("a painted tree");
    assert!(painted.stats.stems > plain.stats.stems, "{} stems, {} before", painted.stats.stems, plain.stats.stems);
    assert!(painted.foliage.count() > plain.foliage.count(), "the new shoots carry leaves");
    assert!(painted.bounds.max[0] > plain.bounds.max[0] + 1.0, "{} vs {}", painted.bounds.max[0], plain.bounds.max[0]);
    assert!(painted.markers.iter().all(|m| m.x > 2.0), "the stroke's markers are shown");
    assert!(!painted.markers.is_empty());
    assert!(painted.edits.iter().all(|r| r.resolved));
    assert_mesh_invariants(&painted, "painted");
    let open = edge_uses(&painted.mesh).values().filter(|&&u| u != 2).count();
    assert_eq!(open, 0, "the painted bark stays closed");
}

#[test]
fn the_last_crown_edit_shapes_a_drawn_weber_and_penn_crown() {
    // The outline gives the ratio of the widest radius at each height to its widest radius
    // (Weber & Penn's ShapeRatio), so what differs is its profile: wide low against wide high.
    let low =
        Crown { outline: vec![Vec2::new(0.0, 5.0), Vec2::new(5.0, 6.0), Vec2::new(0.5, 15.0), Vec2::new(0.0, 16.0)] };
    let high =
        Crown { outline: vec![Vec2::new(0.0, 5.0), Vec2::new(0.5, 6.0), Vec2::new(5.0, 15.0), Vec2::new(0.0, 16.0)] };
    let drawn = |edits: Vec<Edit>| {
        let mut p = with_edits(edits);
        p.skeleton.shape = CrownShape::Drawn;
        generate(&p).expect("a drawn crown")
    };
    // The last crown edit counts, wherever it stands in the list.
    let last_high = drawn(vec![Edit::Crown(low.clone()), Edit::Crown(high.clone())]);
    let only_high = drawn(vec![Edit::Crown(high)]);
    let only_low = drawn(vec![Edit::Crown(low)]);
    assert_eq!(last_high.hash_hex(), only_high.hash_hex());
    assert_ne!(only_high.hash_hex(), only_low.hash_hex());
    // The envelope preview (`[height, radius]`) is widest where the outline is.
    let widest_at = |g: &sylva_core::Generated| {
        g.envelope.iter().copied().fold([0.0, 0.0], |a, p| if p[1] > a[1] { p } else { a })[0]
    };
    assert!(widest_at(&only_low) < widest_at(&only_high), "{} vs {}", widest_at(&only_low), widest_at(&only_high));
}

#[test]
fn painted_trees_give_the_same_bytes_cold_and_through_a_session() {
    let p = with_edits(vec![stroke()]);
    let cold = generate(&p).expect("cold");
    let mut session = Session::new();
    session.update(&TreeParams::default(), Quality::Full, &NoClock, None).expect("the default tree");
    session.update(&p, Quality::Full, &NoClock, None).expect("the painted tree");
    let warm = session.into_generated(&NoClock).expect("a full tree");
    assert_eq!(cold.hash_hex(), warm.hash_hex());
}
