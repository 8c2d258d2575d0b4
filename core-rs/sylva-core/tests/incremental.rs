//! Incremental regeneration (`session`): an edit applied to a session gives the same bytes as a
//! cold generation of the same parameters, for every parameter of the registry; only the stages
//! from the edited parameter's declared stage on rerun; previews never leak into a full result.

use sylva_core::clock::NoClock;
use sylva_core::params::{registry, ParamKind, ParamSpec, Stage};
use sylva_core::session::{Quality, Session};
use sylva_core::{generate, TreeParams};

/// A valid value of `spec` different from `v` (a small step up, or down at the top).
fn edited(spec: &ParamSpec, v: f64) -> f64 {
    match spec.kind {
        ParamKind::Bool => 1.0 - v,
        ParamKind::Enum => (v + 1.0) % (spec.max + 1.0),
        ParamKind::Int => {
            if v + 1.0 <= spec.max {
                v + 1.0
            } else {
                v - 1.0
            }
        }
        ParamKind::Float => {
            let d = ((spec.max - spec.min) * 0.05).max(spec.step);
            let up = v + d;
            let w = if up <= spec.max { up } else { v - d };
            f64::from(w.clamp(spec.min, spec.max) as f32)
        }
    }
}

/// Bases whose every parameter matters somewhere: Weber & Penn with holes and roots, and a
/// small grown tree.
fn bases() -> Vec<(&'static str, TreeParams)> {
    let wp = TreeParams::from_values([("hole_count", 2.0), ("root_count", 3.0), ("l2_branches", 12.0)]).unwrap();
    let grown = TreeParams::from_values([("growth_mode", 1.0), ("markers", 400.0), ("iterations", 120.0)]).unwrap();
    vec![("weber_penn", wp), ("grown", grown)]
}

fn cold_hash(p: &TreeParams) -> Result<u64, String> {
    generate(p).map(|g| g.hash).map_err(|e| e.to_string())
}

#[test]
fn every_parameter_edited_incrementally_gives_the_cold_bytes() {
    for (name, base) in bases() {
        let mut session = Session::new();
        session.update(&base, Quality::Full, &NoClock, None).unwrap();
        assert_eq!(session.hash(), Some(cold_hash(&base).unwrap()), "{name}: base");
        for spec in registry() {
            let old = base.get(&spec.id).unwrap();
            let new = edited(spec, old);
            let mut p = base.clone();
            p.set(&spec.id, new).unwrap();
            let cold = cold_hash(&p);
            let warm = session.update(&p, Quality::Full, &NoClock, None).map(|c| c.from);
            match (&cold, warm) {
                (Ok(h), Ok(from)) => {
                    assert_eq!(from, spec.stage, "{name}: {} reran from the wrong stage", spec.id);
                    assert_eq!(session.hash(), Some(*h), "{name}: {} {old} -> {new}", spec.id);
                }
                (Err(c), Err(w)) => assert_eq!(*c, w.to_string(), "{name}: {}", spec.id),
                (c, w) => panic!("{name}: {} {old} -> {new}: cold {c:?}, incremental {w:?}", spec.id),
            }
            // Back to the base: the session must be able to return as well.
            session.update(&base, Quality::Full, &NoClock, None).unwrap();
            assert_eq!(session.hash(), Some(cold_hash(&base).unwrap()), "{name}: back from {}", spec.id);
        }
    }
}

#[test]
fn a_chain_of_edits_across_stages_stays_equal_to_cold() {
    let mut session = Session::new();
    let mut p = TreeParams::default();
    let edits: &[(&str, f64)] = &[
        ("foliage_angle", 30.0),
        ("leaf_teeth", 20.0),
        ("l1_length", 0.35),
        ("mesh_quality", 0.8),
        ("leaves", 12.0),
        ("leaf_margin", 2.0),
        ("show_preview", 1.0),
        ("seed", 9.0),
        ("foliage_lod", 3.0),
    ];
    for &(id, v) in edits {
        p.set(id, v).unwrap();
        session.update(&p, Quality::Full, &NoClock, None).unwrap();
        assert_eq!(session.hash(), Some(generate(&p).unwrap().hash), "after {id} = {v}");
    }
}

#[test]
fn later_stage_edits_keep_the_earlier_results() {
    let mut session = Session::new();
    let mut p = TreeParams::default();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();

    p.set("foliage_angle", 20.0).unwrap();
    let c = session.update(&p, Quality::Full, &NoClock, None).unwrap().changes;
    assert!(!c.skeleton && !c.bark && c.placements && !c.leaf_mesh && !c.leaf, "foliage edit: {c:?}");

    p.set("leaf_teeth", 30.0).unwrap();
    p.set("leaf_margin", 1.0).unwrap();
    let c = session.update(&p, Quality::Full, &NoClock, None).unwrap().changes;
    assert!(!c.skeleton && !c.bark && !c.placements && c.leaf_mesh && c.leaf, "leaf edit: {c:?}");

    p.set("show_preview", 1.0).unwrap();
    let cur = session.update(&p, Quality::Full, &NoClock, None).unwrap();
    assert_eq!(cur.from, Stage::Viewer);
    assert!(!cur.changes.any(), "viewer edit: {:?}", cur.changes);

    p.set("mesh_quality", 1.5).unwrap();
    let c = session.update(&p, Quality::Full, &NoClock, None).unwrap().changes;
    assert!(!c.skeleton && c.bark && !c.placements && !c.leaf, "mesh edit: {c:?}");

    p.set("l1_branches", 20.0).unwrap();
    let c = session.update(&p, Quality::Full, &NoClock, None).unwrap().changes;
    assert!(c.skeleton && c.bark && c.placements, "skeleton edit: {c:?}");
}

#[test]
fn season_edits_rerun_only_the_foliage_and_the_leaf() {
    // A maple through the year in one session: each month reruns from the foliage stage, keeps
    // the skeleton and the bark, and gives the cold bytes; back in July, today's tree.
    let base = sylva_core::presets::find("umbrella").unwrap().params().unwrap();
    let mut session = Session::new();
    session.update(&base, Quality::Full, &NoClock, None).unwrap();
    let summer = session.hash();
    let mut p = base.clone();
    for month in [10.5, 1.5, 4.8, 10.0, 7.0] {
        p.set("season", month).unwrap();
        let cur = session.update(&p, Quality::Full, &NoClock, None).unwrap();
        let (from, c) = (cur.from, cur.changes);
        assert_eq!(from, Stage::Foliage, "month {month}");
        assert!(!c.skeleton && !c.bark && c.placements, "month {month}: {c:?}");
        assert_eq!(session.hash(), Some(cold_hash(&p).unwrap()), "month {month}");
    }
    assert_eq!(session.hash(), summer);
    // A drag of the Season (preview quality allowed), then the release: the cold tree.
    p.set("season", 10.4).unwrap();
    session.update(&p, Quality::Preview { budget_ms: 0.0 }, &NoClock, None).unwrap();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();
    assert_eq!(session.hash(), Some(cold_hash(&p).unwrap()));
}

#[test]
fn first_difference_is_the_earliest_changed_stage_struct() {
    let a = TreeParams::default();
    let mut b = a.clone();
    assert_eq!(a.first_difference(&b), Stage::Viewer);
    b.set("leaf_teeth", 3.0).unwrap();
    assert_eq!(a.first_difference(&b), Stage::Leaf);
    b.set("foliage_angle", 3.0).unwrap();
    assert_eq!(a.first_difference(&b), Stage::Foliage);
    b.set("lobes", 3.0).unwrap();
    assert_eq!(a.first_difference(&b), Stage::Mesh);
    b.set("l2_length", 0.3).unwrap();
    assert_eq!(a.first_difference(&b), Stage::Skeleton);
    let mut c = a.clone();
    c.set("show_markers", 1.0).unwrap();
    assert_eq!(a.first_difference(&c), Stage::Viewer);
    assert_ne!(a.viewer, c.viewer);
    // The growth volumes are skeleton data.
    let mut d = a.clone();
    d.skeleton.volumes =
        sylva_core::params::volumes::from_json(r#"[{"kind":"sphere","group":"crown","centre":[0,6,0],"radius":3}]"#)
            .unwrap();
    assert_eq!(a.first_difference(&d), Stage::Skeleton);
}

/// Every parameter lives in the struct of the stage the registry declares for it: setting it
/// changes that struct and no other, so the session compares each parameter exactly once.
#[test]
fn every_parameter_lives_in_its_declared_stage_struct() {
    let a = TreeParams::default();
    for spec in registry() {
        let mut b = a.clone();
        b.set(&spec.id, edited(spec, a.get(&spec.id).unwrap())).unwrap();
        let changed = [
            (Stage::Skeleton, a.skeleton != b.skeleton),
            (Stage::Mesh, a.mesh != b.mesh),
            (Stage::Foliage, a.foliage != b.foliage),
            (Stage::Leaf, a.leaf != b.leaf),
            (Stage::Viewer, a.viewer != b.viewer),
        ];
        let stages: Vec<Stage> = changed.iter().filter(|c| c.1).map(|c| c.0).collect();
        assert_eq!(stages, [spec.stage], "{}", spec.id);
    }
}

#[test]
fn a_preview_is_never_the_full_tree_and_the_full_one_follows() {
    let mut session = Session::new();
    let mut p = TreeParams::default();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();
    // A budget of -1 ms: any bark is over it, so a bark edit is answered with a preview.
    let drag = Quality::Preview { budget_ms: -1.0 };
    p.set("l1_length", 0.34).unwrap();
    let cur = session.update(&p, drag, &NoClock, None).unwrap();
    assert!(cur.is_preview() && cur.changes.bark && cur.changes.placements);
    let preview_vertices = cur.bark.mesh.vertex_count();
    assert_eq!(session.hash(), None, "a preview has no content hash");
    // A foliage edit during the drag keeps the preview bark and does not sweep again.
    p.set("foliage_angle", 50.0).unwrap();
    let cur = session.update(&p, drag, &NoClock, None).unwrap();
    assert!(cur.is_preview() && !cur.changes.bark);
    // The drag ends: the same parameters at full quality sweep the full bark and light the
    // leaves by their own field (the preview lit them by the previous leaves'), nothing else.
    let cur = session.update(&p, Quality::Full, &NoClock, None).unwrap();
    assert!(!cur.is_preview() && cur.changes.bark && !cur.changes.skeleton && !cur.leaves_preview);
    assert!(cur.bark.mesh.vertex_count() > preview_vertices, "the preview is coarser");
    assert_eq!(session.hash(), Some(generate(&p).unwrap().hash));
    // With a generous budget the answer is full even when a preview is allowed.
    p.set("l1_length", 0.36).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: 1e9 }, &NoClock, None).unwrap();
    assert!(!cur.is_preview());
    assert_eq!(session.hash(), Some(generate(&p).unwrap().hash));
}

#[test]
fn an_error_keeps_the_previous_tree() {
    let mut session = Session::new();
    let p = TreeParams::default();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();
    let hash = session.hash();
    let mut bad = p.clone();
    bad.foliage.max_leaves = 10; // the budget error comes from the foliage stage, after a new bark
    bad.mesh.mesh_quality = 2.0;
    let e = session.update(&bad, Quality::Full, &NoClock, None).unwrap_err();
    assert!(e.to_string().contains("max_leaves"), "{e}");
    assert_eq!(session.hash(), hash);
    assert_eq!(session.current().unwrap().params, p);
    // And the next edit is still incremental against the kept tree.
    let mut q = p.clone();
    q.foliage.foliage_angle = 10.0;
    let cur = session.update(&q, Quality::Full, &NoClock, None).unwrap();
    assert!(!cur.changes.bark);
    assert_eq!(session.hash(), Some(generate(&q).unwrap().hash));
}

#[test]
fn a_leaf_drag_defers_the_bark_shade_and_the_full_tree_catches_up() {
    let mut session = Session::new();
    let mut p = TreeParams::default();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();
    let shade = session.current().unwrap().bark.mesh.shade.clone();
    // A drag of the leaves (budget -1 ms: over it) keeps the bark's old occlusion meanwhile.
    p.set("foliage_angle", 30.0).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap();
    assert!(cur.is_preview() && cur.changes.placements && !cur.changes.shade && !cur.changes.bark);
    assert_eq!(cur.bark.mesh.shade, shade, "the old shade stays while dragging");
    assert_eq!(session.hash(), None, "a preview has no content hash");
    // Another step of the drag: still deferred.
    p.set("foliage_angle", 31.0).unwrap();
    assert!(session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap().is_preview());
    // Released: the same parameters at full quality light the leaves by their own field and
    // shade the bark for them; the bark is not swept again.
    let cur = session.update(&p, Quality::Full, &NoClock, None).unwrap();
    assert!(!cur.is_preview() && cur.changes.shade && !cur.changes.bark && !cur.leaves_preview);
    assert_eq!(session.hash(), Some(generate(&p).unwrap().hash));
}

#[test]
fn a_drag_places_every_other_leaf_lit_by_the_previous_field_and_the_release_places_them_all() {
    let mut session = Session::new();
    let mut p = TreeParams::default();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();
    // Over the budget (-1 ms): the leaves move, their tints come from the old crown's field.
    p.set("l1_length", 0.36).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap();
    assert!(cur.is_preview() && cur.leaves_preview && cur.changes.placements);
    let preview = cur.foliage.clone();
    assert_eq!(session.hash(), None, "a preview has no content hash");
    // A leaf-shape step of the same drag keeps the previewed placements.
    p.set("leaf_teeth", 9.0).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap();
    assert!(cur.leaves_preview && !cur.changes.placements);
    // Within the budget the same parameters are placed and lit in full, the cold tree's bytes.
    let cur = session.update(&p, Quality::Preview { budget_ms: 1e9 }, &NoClock, None).unwrap();
    assert!(!cur.is_preview() && cur.changes.placements && !cur.changes.skeleton);
    let cold = generate(&p).unwrap();
    assert_eq!(cur.foliage.matrices, cold.foliage.matrices);
    // The preview placed every other leaf site, where the full tree has its leaf, √2 larger.
    let full = &cold.foliage.matrices;
    let thin = sylva_core::foliage::preview_thin(cold.foliage.count() as u64);
    assert_eq!(thin, sylva_core::foliage::PREVIEW_THIN, "the default tree's preview places every other site");
    assert_eq!(preview.count(), cold.foliage.count().div_ceil(thin), "one leaf site in {thin}");
    for (i, m) in preview.matrices.chunks_exact(16).enumerate().step_by(97) {
        let f = &full[i * thin * 16..(i * thin + 1) * 16];
        // Where the petiole meets the stem (the translation minus the petiole along the leaf's y).
        let attach = |c: &[f32]| [0, 1, 2].map(|a| c[12 + a] - c[4 + a] * p.foliage.leaf_petiole);
        let (a, b) = (attach(m), attach(f));
        assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-5), "preview leaf {i} sits where full leaf {} does", i * thin);
        let len = |c: &[f32]| (c[4] * c[4] + c[5] * c[5] + c[6] * c[6]).sqrt();
        assert!((len(m) / len(f) - (thin as f32).sqrt()).abs() < 1e-4, "preview leaf {i} is √{thin} larger");
    }
    assert_eq!(cur.foliage.colors, cold.foliage.colors);
    assert_ne!(preview.colors, cold.foliage.colors, "the preview's tints came from the old crown");
    assert_eq!(session.hash(), Some(cold.hash));
}

#[test]
fn a_dense_crowns_drag_places_a_bounded_number_of_leaves_and_keeps_the_leaf_area() {
    use sylva_core::foliage::{preview_thin, PREVIEW_LEAVES};
    let mut session = Session::new();
    let mut p = TreeParams::default();
    session.update(&p, Quality::Full, &NoClock, None).unwrap();
    // A drag of Leaves to 65 a twig: about 2.6 times the default tree's leaves.
    p.set("leaves", 65.0).unwrap();
    let preview = session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap().foliage.clone();
    let full = generate(&p).unwrap().foliage;
    let thin = preview_thin(full.count() as u64);
    assert!(thin > 2, "a crown of {} leaves is thinned past every other site", full.count());
    assert_eq!(preview.count(), full.count().div_ceil(thin));
    assert!(preview.count() as u64 <= PREVIEW_LEAVES + 1, "{} leaves in the preview", preview.count());
    // Leaf area (the sum of length × width over the leaves) within a few percent of the full tree's.
    let area = |m: &[f32]| -> f64 {
        m.chunks_exact(16)
            .map(|c| {
                let x = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
                let y = (c[4] * c[4] + c[5] * c[5] + c[6] * c[6]).sqrt();
                f64::from(x * y)
            })
            .sum()
    };
    let (a, b) = (area(&preview.matrices), area(&full.matrices));
    assert!((a / b - 1.0).abs() < 0.05, "preview leaf area {a:.1} against {b:.1} m²");
    // A bigger crown is thinned further, never below one site in two.
    assert_eq!(preview_thin(1), 2);
    assert!(preview_thin(10 * PREVIEW_LEAVES) == 10 && preview_thin(10 * PREVIEW_LEAVES + 1) == 11);
}

#[test]
fn a_drag_of_the_leaf_shape_shows_a_smaller_texture_and_the_release_the_full_leaf() {
    let mut session = Session::new();
    let mut p = TreeParams::default();
    let full_height =
        session.update(&p, Quality::Full, &NoClock, None).unwrap().foliage.leaf.as_ref().unwrap().texture.height;
    // Over the budget (-1 ms): the new leaf's texture is one Texture Size level down.
    p.set("leaf_teeth", 21.0).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap();
    assert!(cur.is_preview() && cur.leaf_preview && cur.changes.leaf && !cur.changes.placements);
    assert_eq!(cur.foliage.leaf.as_ref().unwrap().texture.height * 2, full_height);
    assert_eq!(session.hash(), None, "a preview has no content hash");
    // A leaf-placement step of the same drag keeps the preview leaf.
    p.set("foliage_angle", 33.0).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: -1.0 }, &NoClock, None).unwrap();
    assert!(cur.leaf_preview);
    // Released: the full leaf, the cold tree's bytes.
    let cur = session.update(&p, Quality::Full, &NoClock, None).unwrap();
    assert!(!cur.is_preview() && !cur.leaf_preview && cur.changes.leaf);
    assert_eq!(cur.foliage.leaf.as_ref().unwrap().texture.height, full_height);
    assert_eq!(session.hash(), Some(generate(&p).unwrap().hash));
    // Within the budget a leaf edit is answered in full at once.
    p.set("leaf_teeth", 22.0).unwrap();
    let cur = session.update(&p, Quality::Preview { budget_ms: 1e9 }, &NoClock, None).unwrap();
    assert!(!cur.leaf_preview && !cur.is_preview());
}

/// An Age drag reuses the stems as built at the Mature Age (replaying them only): every step,
/// younger, older than the Mature Age and back, with and without a cut made at 30, gives the
/// cold bytes.
#[test]
fn an_age_drag_gives_the_cold_bytes_at_every_step() {
    use glam::Vec3;
    use sylva_core::params::{Cut, Edit};
    for (name, mut base) in bases() {
        for cut in [false, true] {
            if cut {
                base.skeleton.edits = vec![Edit::Cut(Cut { at: Vec3::new(0.4, 3.0, 0.2), year: Some(30.0) })];
            }
            let mut session = Session::new();
            for age in [40.0, 36.5, 31.0, 12.0, 31.0, 55.0, 70.0, 40.0] {
                let mut p = base.clone();
                p.set("age", age).unwrap();
                let warm = session.update(&p, Quality::Full, &NoClock, None).map(|_| ()).map(|()| session.hash());
                match (cold_hash(&p), warm) {
                    (Ok(h), Ok(w)) => assert_eq!(w, Some(h), "{name} (cut {cut}) at Age {age}"),
                    (Err(c), Err(w)) => assert_eq!(c, w.to_string(), "{name} (cut {cut}) at Age {age}"),
                    (c, w) => panic!("{name} (cut {cut}) at Age {age}: cold {c:?}, incremental {w:?}"),
                }
            }
        }
    }
}
