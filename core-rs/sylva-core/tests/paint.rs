//! Paint growth (`sylva_core::edits::paint`): a stroke grows new shoots from the existing tree
//! toward it, with its own internode; the shoots start on their parents, the result is
//! deterministic and the same grown in steps as at once, and the painted tree meshes cleanly
//! and carries leaves.

mod common;

use glam::Vec3;
use sylva_core::edits::paint::{paint, PaintGrowth, PaintOutcome};
use sylva_core::params::Paint;
use sylva_core::skeleton::{self, Skeleton, Stem};
use sylva_core::{foliage, generate, growth, mesh, presets, SylvaError, TreeParams};

/// The default Weber & Penn tree and its skeleton.
fn default_tree() -> (TreeParams, Skeleton) {
    let p = TreeParams::default();
    let sk = skeleton::build(&p.skeleton).unwrap();
    (p, sk)
}

/// The largest x any stem point of `stems` reaches.
fn max_x<'a>(stems: impl Iterator<Item = &'a Stem>) -> f32 {
    stems.flat_map(|s| s.points.iter().map(|q| q.x)).fold(f32::NEG_INFINITY, f32::max)
}

/// A 40-point stroke from inside the crown's +x side out to `reach` m beyond it, at mid height.
fn side_stroke(sk: &Skeleton, reach: f32, segment: f32, kill: f32) -> Paint {
    let edge = max_x(sk.stems.iter());
    let (x0, x1) = (edge - 0.6, edge + reach);
    let points = (0..40).map(|i| Vec3::new(x0 + (x1 - x0) * i as f32 / 39.0, 9.0 + 0.02 * i as f32, 0.3)).collect();
    Paint { points, radius: 0.5, density: 400.0, segment, kill }
}

fn new_stems<'a>(sk: &'a Skeleton, out: &PaintOutcome) -> &'a [Stem] {
    &sk.stems[out.stems.clone()]
}

/// Mean internode length of `stems` (all their segments).
fn mean_internode(stems: &[Stem]) -> f32 {
    let lens: Vec<f32> = stems.iter().flat_map(|s| s.points.windows(2).map(|w| w[0].distance(w[1]))).collect();
    lens.iter().sum::<f32>() / lens.len() as f32
}

#[test]
fn a_stroke_beside_the_crown_extends_the_tree_toward_it() {
    let (p, mut sk) = default_tree();
    let before = max_x(sk.stems.iter());
    let stroke = side_stroke(&sk, 2.0, 0.25, 0.4);
    let out = paint(&mut sk, &stroke, p.skeleton.seed, 0, p.skeleton.max_vertices).unwrap();
    assert!(out.stems.len() > 3, "{out:?}");
    assert!(
        out.markers.len() > 500 && out.iterations > 5,
        "{} markers, {} iterations",
        out.markers.len(),
        out.iterations
    );
    let after = max_x(new_stems(&sk, &out).iter());
    assert!(after > before + 1.5, "the tree reached x = {after}, it was {before}");
    let far = *stroke.points.last().unwrap();
    let nearest = new_stems(&sk, &out)
        .iter()
        .flat_map(|s| s.points.iter().map(|q| q.distance(far)))
        .fold(f32::INFINITY, f32::min);
    assert!(nearest < 2.0 * stroke.kill, "the new stems come {nearest} m close to the stroke's far end");
    // Markers lie in the brush tube.
    for m in &out.markers {
        let d = stroke.points.windows(2).map(|w| seg_dist(*m, w[0], w[1])).fold(f32::INFINITY, f32::min);
        assert!(d <= stroke.radius * 1.0001, "marker {m} {d} m from the stroke");
    }
}

fn seg_dist(p: Vec3, a: Vec3, b: Vec3) -> f32 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared().max(1e-12)).clamp(0.0, 1.0);
    (a + d * t).distance(p)
}

#[test]
fn each_stroke_grows_with_its_own_internode() {
    let (p, mut sk) = default_tree();
    let fine = side_stroke(&sk, 2.0, 0.12, 0.2);
    // The same stroke mirrored to the -x side, with long internodes.
    let mut coarse = side_stroke(&sk, 2.0, 0.5, 0.7);
    for q in &mut coarse.points {
        q.x = -q.x;
    }
    let a = paint(&mut sk, &fine, p.skeleton.seed, 0, p.skeleton.max_vertices).unwrap();
    let fine_len = mean_internode(new_stems(&sk, &a));
    let b = paint(&mut sk, &coarse, p.skeleton.seed, 1, p.skeleton.max_vertices).unwrap();
    let coarse_len = mean_internode(new_stems(&sk, &b));
    assert!((fine_len - 0.12).abs() < 0.012, "fine stroke: mean internode {fine_len}");
    assert!((coarse_len - 0.5).abs() < 0.05, "coarse stroke: mean internode {coarse_len}");
    // Each stroke's shoots stay on its side of the tree.
    assert!(new_stems(&sk, &b).iter().all(|s| s.tip().x < 0.0));
}

#[test]
fn new_stems_start_on_their_parents_and_stay_thinner() {
    let (p, mut sk) = default_tree();
    let stroke = side_stroke(&sk, 2.0, 0.25, 0.4);
    let out = paint(&mut sk, &stroke, 3, 0, p.skeleton.max_vertices).unwrap();
    let deepest = sk.stems[..out.stems.start].iter().map(|s| s.level).max().unwrap();
    for (i, s) in sk.stems.iter().enumerate().skip(out.stems.start).take(out.stems.len()) {
        let parent = &sk.stems[s.parent.unwrap() as usize];
        assert!((s.parent.unwrap() as usize) < i, "stem {i}: parents come first");
        let (on, _) = parent.point_at(s.offset);
        assert!(s.base().distance(on) < 1e-4, "stem {i} starts {} m off its parent", s.base().distance(on));
        assert!(s.radius <= parent.radius_at(s.offset / parent.length) + 1e-6, "stem {i} thicker than its parent");
        assert!(s.level <= deepest && s.level >= parent.level.min(deepest), "stem {i} level {}", s.level);
        let r = s.radii.as_ref().unwrap();
        assert!(r.windows(2).all(|w| w[1] <= w[0] + 1e-7), "stem {i}: radii grow toward the tip");
    }
    // Roots still come last and still hang on the trunk.
    let roots = sk.first_root();
    assert!(roots >= out.stems.end && sk.stems[roots..].iter().all(|s| s.parent == Some(0)));
}

fn stems_bits(stems: &[Stem]) -> Vec<u32> {
    stems
        .iter()
        .flat_map(|s| {
            let pts = s.points.iter().flat_map(|q| q.to_array()).map(f32::to_bits);
            let radii = s.radii.iter().flatten().map(|r| r.to_bits());
            pts.chain(radii)
                .chain([s.offset.to_bits(), s.parent.unwrap_or(u32::MAX), u32::from(s.level)])
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn paint_is_deterministic_and_the_same_grown_in_steps() {
    let (p, base) = default_tree();
    let stroke = side_stroke(&base, 2.0, 0.25, 0.4);
    let whole = |sk: &Skeleton| {
        let mut sk = sk.clone();
        let out = paint(&mut sk, &stroke, 5, 2, p.skeleton.max_vertices).unwrap();
        (stems_bits(&sk.stems), out)
    };
    let (a, out_a) = whole(&base);
    let (b, out_b) = whole(&base);
    assert_eq!(a, b);
    assert_eq!(out_a, out_b);
    // Drawn point by point: 40 extensions give the same tree and markers as one call.
    let mut g = PaintGrowth::new(&base, &stroke, 5, 2, p.skeleton.max_vertices).unwrap();
    for n in 1..=stroke.points.len() {
        g.extend(&stroke.points[..n]).unwrap();
    }
    let mut sk = base.clone();
    let out = g.apply(&mut sk).unwrap();
    assert_eq!(stems_bits(&sk.stems), a);
    assert_eq!(out, out_a);
    // A stroke that does not continue the one grown so far is refused.
    let mut moved = stroke.points.clone();
    moved[0].x += 0.1;
    let e = g.extend(&moved).unwrap_err();
    assert!(matches!(&e, SylvaError::InvalidParam { param, .. } if param == "edits[2].points"), "{e:?}");
}

#[test]
fn paint_grows_on_a_grown_tree_too() {
    let p = presets::find("grown_broadleaf").unwrap().params().unwrap();
    let g = growth::grow(&p.skeleton).unwrap();
    let mut sk = growth::skeleton(&p.skeleton, &g);
    let before = sk.stems.len();
    let stroke = side_stroke(&sk, 1.5, 0.2, 0.35);
    let out = paint(&mut sk, &stroke, p.skeleton.seed, 0, p.skeleton.max_vertices).unwrap();
    assert!(out.stems.len() > 3 && sk.stems.len() == before + out.stems.len(), "{out:?}");
    let tip = p.skeleton.tip_radius;
    for s in new_stems(&sk, &out) {
        assert!(s.level >= 1 && s.radii.as_ref().unwrap().last().unwrap() >= &(tip - 1e-6));
    }
    let far = *stroke.points.last().unwrap();
    let nearest = new_stems(&sk, &out).iter().map(|s| s.tip().distance(far)).fold(f32::INFINITY, f32::min);
    assert!(nearest < 2.0 * stroke.kill, "{nearest}");
}

/// The painted tree meshed (bark swept and welded as the mesh stage does) in place of `g`'s.
fn remesh(mut g: sylva_core::Generated, sk: Skeleton, p: &TreeParams) -> sylva_core::Generated {
    let built = mesh::tube::build_with_stats(&sk, &p.mesh).unwrap();
    g.mesh = built.mesh;
    g.bounds = g.mesh.bounds();
    g.skeleton = sk;
    g
}

#[test]
fn a_painted_tree_meshes_cleanly_and_carries_leaves() {
    for name in ["default", "grown_broadleaf"] {
        let p = if name == "default" { TreeParams::default() } else { presets::find(name).unwrap().params().unwrap() };
        let g = generate(&p).unwrap();
        let mut sk = g.skeleton.clone();
        let stroke = side_stroke(&sk, 2.0, 0.25, 0.4);
        let out = paint(&mut sk, &stroke, p.skeleton.seed, 0, p.skeleton.max_vertices).unwrap();
        let leaves_near = |sk: &Skeleton| {
            let f = foliage::place(sk, &p.foliage).unwrap();
            f.matrices.chunks_exact(16).filter(|m| m[12] > max_x(g.skeleton.stems.iter()) + 0.5).count()
        };
        let (before, after) = (leaves_near(&g.skeleton), leaves_near(&sk));
        assert!(before == 0 && after > 20, "{name}: {before} leaves beyond the old crown, {after} after painting");
        let painted = remesh(g, sk, &p);
        common::assert_mesh_invariants(&painted, name);
        let open = common::edge_uses(&painted.mesh).values().filter(|&&u| u != 2).count();
        assert_eq!(open, 0, "{name}: {open} edges not shared by exactly two triangles");
        assert!(painted.bounds.max[0] > max_x(painted.skeleton.stems[..out.stems.start].iter()) + 1.0);
    }
}

#[test]
fn runaway_strokes_stop_with_a_message_naming_the_field() {
    let (p, mut sk) = default_tree();
    let mut stroke = side_stroke(&sk, 2.0, 0.25, 0.4);
    stroke.density = 1e6;
    let Err(e) = paint(&mut sk, &stroke, 1, 4, p.skeleton.max_vertices) else { panic!("a marker cap error expected") };
    assert!(matches!(&e, SylvaError::Budget { param, .. } if param == "edits[4].density"), "{e:?}");
    let stroke = side_stroke(&sk, 2.0, 0.25, 0.4);
    // A budget that holds the tree and ten new nodes.
    let tree: u64 = sk.stems.iter().map(|s| skeleton::min_vertices(s.points.len() as u32 - 1)).sum();
    let Err(e) = paint(&mut sk, &stroke, 1, 0, tree as u32 + 40) else { panic!("a budget error expected") };
    assert!(matches!(&e, SylvaError::Budget { param, .. } if param == "max_vertices"), "{e:?}");
    let Err(e) = paint(&mut sk, &Paint { segment: 0.0, ..stroke }, 1, 7, p.skeleton.max_vertices) else {
        panic!("an error expected")
    };
    assert!(matches!(&e, SylvaError::InvalidParam { param, .. } if param == "edits[7].segment"), "{e:?}");
}

/// Regression: the marker cap counted the candidates each brush point's capsule draws (its whole
/// capsule, most of it inside the capsule before), not the markers kept: with brush points a
/// fifth of a metre apart, as the studio lays them, an ordinary 8 m stroke of the default brush
/// (radius 0.6 m, 400 markers per m³) reported 20,147 "markers" and stopped growing.
#[test]
fn a_long_stroke_of_the_default_brush_grows_and_the_cap_counts_markers() {
    let (p, mut sk) = default_tree();
    let edge = max_x(sk.stems.iter());
    let points: Vec<Vec3> =
        (0..60).map(|i| Vec3::new(edge - 4.0 + 0.2 * i as f32, 9.0 + 0.03 * i as f32, 0.0)).collect();
    let stroke = Paint { points, radius: 0.6, density: 400.0, segment: 0.25, kill: 0.4 };
    let out =
        paint(&mut sk, &stroke, 1, 0, p.skeleton.max_vertices).expect("a 12 m stroke of the default brush paints");
    // The tube: a 0.6 m ball and 59 segments of about 0.2 m, times 400 per m³: about 5,700 markers.
    let tube = 400.0 * std::f32::consts::PI * 0.36 * (0.8 + 59.0 * 0.2022);
    let n = out.markers.len() as f32;
    assert!((n - tube).abs() < 0.1 * tube, "{n} markers, the tube holds {tube}");
    assert!(!new_stems(&sk, &out).is_empty());
    // Points a millimetre apart with a 10 m brush would draw billions of candidates for few
    // markers: the sampling budget stops it, naming the density.
    let (_, mut sk) = default_tree();
    let points: Vec<Vec3> = (0..4000).map(|i| Vec3::new(0.001 * i as f32, 9.0, 0.0)).collect();
    let stroke = Paint { points, radius: 10.0, density: 1.0, segment: 0.25, kill: 0.4 };
    let Err(e) = paint(&mut sk, &stroke, 1, 2, p.skeleton.max_vertices) else { panic!("the sampling budget expected") };
    assert!(
        matches!(&e, SylvaError::Budget { param, message } if param == "edits[2].density" && message.contains("candidate")),
        "{e:?}"
    );
}
