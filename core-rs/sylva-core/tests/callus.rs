//! Dated cuts and the callus ring: a cut made in year Y has not happened while the tree is
//! younger (the branch is whole, the edit is pending); in year Y it is the fresh cut; later,
//! woundwood rolls in over the face from the bark rim a centimetre a year until the wound is
//! closed, and the bark stays a closed, manifold surface all along.

mod common;

use common::{assert_mesh_invariants, edge_uses};
use glam::Vec3;
use sylva_core::edits::cut::{callus, CALLUS_RATE};
use sylva_core::mesh::cut_face::{BEVEL, OPEN_MIN, ROLL_HEIGHT};
use sylva_core::params::edits::{from_json, to_json};
use sylva_core::params::{Cut, Edit, SkeletonParams};
use sylva_core::{generate, Generated, Material, TreeParams};

/// The default tree (Age = Mature Age = 40) at `age`, with `edits`.
fn at_age(age: f32, edits: Vec<Edit>) -> Generated {
    let mut p = TreeParams::default();
    p.skeleton = SkeletonParams { edits, age, ..p.skeleton };
    generate(&p).unwrap()
}

/// A point 15 % out along the first level-1 branch longer than 2 m (born well before year 30),
/// and that branch's index.
fn branch_point() -> (Vec3, usize) {
    let g = generate(&TreeParams::default()).unwrap();
    let i = g.skeleton.stems.iter().position(|s| s.level == 1 && s.length > 2.0).expect("a main branch");
    (g.skeleton.stems[i].point_at(0.15 * g.skeleton.stems[i].length).0, i)
}

fn cut(at: Vec3, year: Option<f32>) -> Edit {
    Edit::Cut(Cut { at, year })
}

/// The cut-face group's triangles' total area (m²).
fn face_area(g: &Generated) -> f32 {
    let p = |v: u32| Vec3::from_slice(&g.mesh.positions[v as usize * 3..v as usize * 3 + 3]);
    g.mesh
        .groups
        .iter()
        .filter(|gr| gr.material == Material::CutFace)
        .flat_map(|gr| g.mesh.indices[gr.start as usize..(gr.start + gr.count) as usize].chunks_exact(3))
        .map(|t| 0.5 * (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).length())
        .sum()
}

fn assert_closed(g: &Generated, name: &str) {
    assert_mesh_invariants(g, name);
    let open = edge_uses(&g.mesh).values().filter(|&&u| u != 2).count();
    assert_eq!(open, 0, "{name}: {open} edges open or non-manifold");
}

#[test]
fn a_cut_dated_later_than_the_tree_has_not_happened() {
    let (at, _) = branch_point();
    let whole = at_age(30.0, Vec::new());
    let g = at_age(30.0, vec![cut(at, Some(35.0))]);
    assert_eq!(g.hash, whole.hash, "the branch is whole until year 35");
    assert!(g.edits[0].resolved && g.edits[0].pending_year == Some(35.0), "{:?}", g.edits);
    assert!(g.meta_json().contains(r#""pending_year":35.0"#), "{}", g.meta_json());
}

#[test]
fn in_its_own_year_a_dated_cut_is_the_fresh_cut() {
    let (at, _) = branch_point();
    let fresh = at_age(40.0, vec![cut(at, None)]);
    let dated = at_age(40.0, vec![cut(at, Some(40.0))]);
    assert_eq!(dated.hash, fresh.hash);
    assert!(dated.skeleton.stems.iter().all(|s| s.callus == 0.0));
}

#[test]
fn woundwood_closes_over_the_face_year_by_year() {
    let (at, i) = branch_point();
    let fresh = at_age(30.0, vec![cut(at, Some(30.0))]);
    let r = fresh.skeleton.stems[i].radius_at(1.0);
    assert!(fresh.skeleton.stems[i].cut_end && r > 0.02, "a stump thick enough to close over years: r = {r}");
    let years_to_close = r / CALLUS_RATE;
    let mut last_area = face_area(&fresh);
    let mut last_closure = 0.0;
    for years in [0.15, 0.4, 0.7, 1.2].map(|f| f * years_to_close) {
        // The tree keeps growing around the stump: compare each age with the same cut made then
        // (fresh), so only the callus differs.
        let age = 30.0 + years;
        let g = at_age(age, vec![cut(at, Some(30.0))]);
        let same_age_fresh = at_age(age, vec![cut(at, Some(age))]);
        let stump = &g.skeleton.stems[i];
        assert!(stump.cut_end);
        let closure = callus(years, stump.radius_at(1.0));
        assert!((stump.callus - closure).abs() < 1e-5, "callus {} vs {closure}", stump.callus);
        assert!(closure > last_closure, "{years} years: closure {closure} after {last_closure}");
        assert_closed(&g, &format!("{years} years after the cut"));
        // One more ring (the roll's inner one) than the fresh cut of the same tree.
        let sides = (g.mesh.vertex_count() - same_age_fresh.mesh.vertex_count()) as u32;
        assert!((3..=64).contains(&(sides - 1)), "the callus adds one ring: {sides} vertices");
        // The open face shrinks to radius (1 - closure) r from the fresh face's (1 - BEVEL) r,
        // down to the seam.
        let area = face_area(&g);
        let want = face_area(&same_age_fresh) * ((1.0 - closure).max(OPEN_MIN) / (1.0 - BEVEL)).powi(2);
        assert!((area - want).abs() <= 0.05 * want + 1e-6, "{years} years: face {area} m², expected {want}");
        assert!(area < last_area || years > years_to_close, "{years} years: the face did not shrink");
        // The roll stands proud of the cut plane.
        let (tip, n) = stump.sample(1.0);
        let height = (0..g.mesh.vertex_count())
            .map(|v| Vec3::from_slice(&g.mesh.positions[v * 3..v * 3 + 3]))
            .filter(|q| q.distance(tip) < 1.2 * stump.radius_at(1.0))
            .map(|q| (q - tip).dot(n))
            .fold(f32::MIN, f32::max);
        let want = ROLL_HEIGHT * closure * stump.radius_at(1.0);
        assert!((height - want).abs() < 0.1 * want + 1e-4, "{years} years: roll {height} m high, expected {want}");
        last_area = area;
        last_closure = closure;
    }
    assert_eq!(last_closure, 1.0, "closed after radius / rate years");
}

#[test]
fn a_callus_on_the_trunk_and_roots_stays_closed() {
    let mut p = TreeParams::from_values([("root_count", 3.0)]).unwrap();
    let g0 = generate(&p).unwrap();
    let at = g0.skeleton.stems[0].point_at(2.0).0;
    p.skeleton.edits = vec![cut(at, Some(30.0))];
    p.skeleton.age = 45.0;
    let g = generate(&p).unwrap();
    assert!(g.skeleton.stems[0].callus > 0.3 && g.skeleton.stems[0].callus < 1.0, "{}", g.skeleton.stems[0].callus);
    assert_closed(&g, "trunk callus");
}

#[test]
fn dated_cuts_round_trip_through_json_and_are_checked() {
    let edits = vec![cut(Vec3::new(0.5, 4.0, 0.25), Some(32.0)), cut(Vec3::new(0.5, 3.0, 0.25), None)];
    let json = to_json(&edits);
    assert!(json.contains(r#""year":32.0"#) && json.matches("year").count() == 1, "{json}");
    assert_eq!(from_json(&json).unwrap(), edits);
    let bad = r#"{"version":1,"edits":[{"op":"cut","at":[0.5,4,0.2],"year":-3}]}"#;
    let e = from_json(bad).unwrap_err().to_string();
    assert!(e.contains("edits[0].year is -3") && e.contains("0 to 300 years"), "{e}");
    let bad = r#"{"version":1,"edits":[{"op":"cut","at":[0.5,4,0.2],"year":"spring"}]}"#;
    let e = from_json(bad).unwrap_err().to_string();
    assert!(e.contains("edits[0].year must be a number"), "{e}");
}
