//! Species leaves (issue 19): lobes placed along the midrib (pinnate) or radiating from the
//! petiole (palmate), the primary veins they start from (pinnate, palmate, dichotomous),
//! needles in fascicles, the petiole, and tree presets wearing their own leaves.
#![allow(clippy::disallowed_methods, reason = "the test's own measures, not output bytes")]

use glam::Vec2;
use sylva_core::leaf::geom::point_in_polygon;
use sylva_core::leaf::presets::{find, LEAF_PRESETS};
use sylva_core::leaf::veins::{VeinGraph, NONE};
use sylva_core::leaf::{margin, outline, Leaf, Outline};
use sylva_core::params::{LeafOutline, LeafPrimaries};
use sylva_core::TreeParams;

/// The leaf of tree parameters `p`: its leaf parameters and Petiole Length.
fn generate(p: &TreeParams) -> Result<Leaf, sylva_core::SylvaError> {
    sylva_core::leaf::generate(&p.leaf, p.foliage.leaf_petiole)
}

fn preset(name: &str) -> TreeParams {
    find(name).unwrap_or_else(|| panic!("leaf preset {name}")).params().unwrap()
}

fn outline_of(p: &TreeParams) -> Outline {
    margin::build(&p.leaf, &outline::build(&p.leaf)).unwrap()
}

/// Local maxima of the half-width `|x|` along the left half (tip to base) that stand at least
/// `delta` above the minima on both sides: `(y, |x|)` of each.
fn lobes_along_the_midrib(o: &Outline, delta: f32) -> Vec<(f32, f32)> {
    let half = o.half(0);
    let w: Vec<f32> = half.iter().map(|q| q.x.abs()).collect();
    let mut out = Vec::new();
    let (mut lo, mut best, mut rising) = (0.0f32, 0usize, true);
    for i in 1..w.len() {
        if rising {
            if w[i] > w[best] {
                best = i;
            } else if w[best] - w[i] >= delta && w[best] - lo >= delta {
                out.push((half[best].y, w[best]));
                rising = false;
                lo = w[i];
            }
        } else if w[i] < lo {
            lo = w[i];
        } else if w[i] - lo >= delta {
            rising = true;
            best = i;
        }
    }
    out
}

/// Nodes reachable from the root through exactly one path of single-child nodes after it
/// forks: the children of `node` in `g`.
fn children(g: &VeinGraph, node: u32) -> Vec<u32> {
    (0..g.nodes.len() as u32).filter(|&i| g.nodes[i as usize].parent == node).collect()
}

#[test]
fn oak_lobes_sit_along_the_midrib_with_sinuses_halfway_in() {
    let p = preset("oak");
    assert_eq!(p.leaf.leaf_outline, LeafOutline::Pinnate);
    let o = outline_of(&p);
    let lobes = lobes_along_the_midrib(&o, 0.015);
    // Five lateral lobes per side plus the terminal lobe, at distinct heights along the midrib
    // (a radial superformula puts its points around one centre instead).
    assert_eq!(lobes.len(), p.leaf.leaf_lobes as usize + 1, "{lobes:?}");
    let ys: Vec<f32> = lobes.iter().map(|l| l.0).collect();
    assert!(ys.windows(2).all(|w| w[0] - w[1] > 0.08), "lobes spread from the tip to the base: {ys:?}");
    assert!(*ys.last().unwrap() < 0.35 && ys[1] > 0.6, "{ys:?}");
    // Each sinus between two lateral lobes reaches about halfway to the midrib.
    let half = o.half(0);
    for pair in lobes[1..].windows(2) {
        let (hi, lo) = (pair[0], pair[1]);
        let sinus = half.iter().filter(|q| q.y < hi.0 && q.y > lo.0).map(|q| q.x.abs()).fold(f32::MAX, f32::min);
        let ratio = sinus / hi.1.min(lo.1);
        assert!((0.3..0.75).contains(&ratio), "sinus at {ratio} of the lobes' half-width");
    }
    // Obovate: the widest lobe is in the upper half.
    let widest = lobes.iter().max_by(|a, b| a.1.total_cmp(&b.1)).unwrap();
    assert!(widest.0 > 0.5, "obovate: widest at y = {}", widest.0);
    // A new lobe count places that many lobes (the lowest, by the narrow base, are small).
    for n in [3, 7, 9] {
        let mut q = p.clone();
        q.leaf.leaf_lobes = n;
        assert_eq!(lobes_along_the_midrib(&outline_of(&q), 0.008).len(), n as usize + 1, "{n} lobes");
    }
}

#[test]
fn oak_has_one_secondary_vein_per_lobe_ending_in_it() {
    let p = preset("oak");
    let l = generate(&p).unwrap();
    let g = &l.veins.graph;
    let o = &l.outline;
    let lobes = lobes_along_the_midrib(o, 0.015);
    // The primaries are the nodes born before colonization started: the midrib (x = 0) and the
    // secondaries; each lateral lobe tip has a primary vein end within 0.05 of it.
    let midrib_end = g.midrib();
    let tip = g.nodes[*midrib_end.last().unwrap() as usize].pos;
    assert!((tip - Vec2::new(0.0, 1.0)).length() < 0.05, "the midrib reaches the tip: {tip}");
    for side in [-1.0f32, 1.0] {
        for &(y, w) in &lobes[1..] {
            let apex = Vec2::new(side * w, y);
            let near = g.nodes.iter().any(|n| (n.pos - apex).length() < 0.05);
            assert!(near, "a vein reaches the lobe at {apex}");
        }
    }
    // Among the primaries, exactly one secondary per lobe and side leaves the midrib (x = 0).
    let mask = sylva_core::leaf::raster::Mask::new(&o.points, 256);
    let primaries = sylva_core::leaf::veins::primary::build(&p.leaf, o, &mask);
    let off_midrib = primaries
        .nodes
        .iter()
        .filter(|n| n.parent != NONE && primaries.nodes[n.parent as usize].pos.x == 0.0 && n.pos.x != 0.0)
        .count();
    assert_eq!(off_midrib, 2 * p.leaf.leaf_lobes as usize, "one secondary per lobe");
}

#[test]
fn maple_has_five_primary_veins_from_the_petiole_junction() {
    let p = preset("maple");
    assert_eq!((p.leaf.leaf_outline, p.leaf.leaf_primary_veins), (LeafOutline::Palmate, LeafPrimaries::Palmate));
    let l = generate(&p).unwrap();
    let mask = sylva_core::leaf::raster::Mask::new(&l.outline.points, 256);
    let g = &sylva_core::leaf::veins::primary::build(&p.leaf, &l.outline, &mask);
    // The petiole's vein runs up to the junction, where the five primaries part.
    let junction = (0..g.nodes.len() as u32).find(|&i| children(g, i).len() > 1).unwrap();
    assert!((g.nodes[junction as usize].pos - l.outline.center).length() < 0.02, "the junction is the centre");
    let first = children(g, junction);
    assert_eq!(first.len(), 5, "five primaries leave the junction");
    // Each runs straight to a lobe apex: far from the junction, in five distinct directions
    // spread over more than 200°.
    let mut angles = Vec::new();
    for &c in &first {
        let mut v = c;
        while let Some(&next) =
            children(g, v).iter().find(|&&k| g.nodes[k as usize].born == g.nodes[v as usize].born + 1)
        {
            v = next;
        }
        let end = g.nodes[v as usize].pos;
        let d = end - g.nodes[junction as usize].pos;
        assert!(d.length() > 0.4, "primary {c} reaches a lobe: ends at {end}");
        angles.push(d.x.atan2(d.y).to_degrees());
    }
    angles.sort_by(f32::total_cmp);
    assert!(angles[4] - angles[0] > 200.0, "primaries fan out: {angles:?}");
    assert!(angles.windows(2).all(|w| w[1] - w[0] > 35.0), "{angles:?}");
    // The five lobes are visible in the outline: five radius peaks about the junction.
    let radii: Vec<f32> = l.outline.points.iter().map(|q| (*q - l.outline.center).length()).collect();
    let peaks = (0..radii.len())
        .filter(|&i| {
            let n = radii.len();
            let window = (1..=n / 20).all(|k| radii[i] >= radii[(i + k) % n] && radii[i] >= radii[(i + n - k) % n]);
            window && radii[i] > 0.4 * radii.iter().fold(0.0f32, |a, &b| a.max(b))
        })
        .count();
    assert_eq!(peaks, 5, "five lobes");
    // Closed venation fills between the primaries with loops.
    assert!(l.veins.graph.loops() > 50);
}

#[test]
fn ginkgo_veins_fork_in_two_again_and_again() {
    let p = preset("ginkgo");
    assert_eq!(p.leaf.leaf_primary_veins, LeafPrimaries::Dichotomous);
    let l = generate(&p).unwrap();
    let g = &l.veins.graph;
    assert_eq!(children(g, 0).len(), 2, "two veins enter the blade from the petiole");
    let mut forks = 0;
    for i in 0..g.nodes.len() as u32 {
        let c = children(g, i).len();
        assert!(c <= 2, "node {i}: a dichotomous vein forks in two, never more ({c})");
        forks += usize::from(c == 2);
    }
    assert!(forks >= 30, "{forks} forks");
    // Veins run outward from the junction: every node is farther from it than its parent.
    for n in g.nodes.iter().skip(1) {
        assert!(n.pos.length() > g.nodes[n.parent as usize].pos.length() - 1e-4);
    }
    // Tips reach the outer margin all across the fan, fairly evenly spaced: no midrib, no
    // colonization in between (no loops).
    assert_eq!(g.loops(), 0);
    let tips: Vec<Vec2> =
        (0..g.nodes.len() as u32).filter(|&i| children(g, i).is_empty()).map(|i| g.nodes[i as usize].pos).collect();
    assert!(tips.len() >= 30, "{} vein ends", tips.len());
    let mut angles: Vec<f32> = tips.iter().map(|q| q.x.atan2(q.y)).collect();
    angles.sort_by(f32::total_cmp);
    assert!(angles[0] < -0.8 && *angles.last().unwrap() > 0.8, "the fan is covered: {angles:?}");
    // The notch: the outline's top middle is lower than its two sides.
    let top = |x0: f32, x1: f32| {
        l.outline.points.iter().filter(|q| q.x >= x0 && q.x <= x1).map(|q| q.y).fold(f32::MIN, f32::max)
    };
    assert!(top(-0.05, 0.05) < top(0.2, 0.8) - 0.05, "notched in the middle");
}

#[test]
fn primaries_stay_inside_the_blade_and_colonization_starts_from_them() {
    for name in ["oak", "maple", "birch", "aspen", "willow", "tupelo", "ginkgo", "black_oak"] {
        let p = preset(name);
        let l = generate(&p).unwrap();
        let g = &l.veins.graph;
        for (i, n) in g.nodes.iter().enumerate() {
            assert!(n.pos.is_finite());
            assert!(n.parent == NONE || (n.parent as usize) < i, "{name}: parents come first");
            let inside = point_in_polygon(n.pos, &l.outline.points)
                || sylva_core::leaf::geom::dist_to_polygon(n.pos, &l.outline.points) < 0.02;
            assert!(inside, "{name}: node {i} at {} outside the blade", n.pos);
        }
        // Replay order: the primaries are born first; colonization's nodes after them.
        let primaries = sylva_core::leaf::veins::primary::build(
            &p.leaf,
            &l.outline,
            &sylva_core::leaf::raster::Mask::new(&l.outline.points, 256),
        );
        let last = primaries.nodes.iter().map(|n| n.born).max().unwrap();
        for (a, b) in g.nodes.iter().zip(&primaries.nodes) {
            assert_eq!((a.pos, a.parent, a.born), (b.pos, b.parent, b.born), "{name}: the primaries come first");
        }
        assert!(g.nodes[primaries.nodes.len()..].iter().all(|n| n.born > last), "{name}");
    }
}

fn check_mesh(name: &str, l: &Leaf) {
    let m = &l.mesh;
    assert!(m.positions.iter().all(|v| v.is_finite()), "{name}");
    for n in m.normals.chunks_exact(3) {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-4, "{name}: unit normals");
    }
    assert!(m.indices.iter().all(|&i| (i as usize) < m.positions.len() / 3), "{name}");
}

#[test]
fn pine_needles_come_in_fascicles_of_round_needles() {
    for n in 2..=5u32 {
        let mut p = preset("pine");
        p.leaf.leaf_fascicle = n;
        p.leaf.leaf_shoot = 0; // one fascicle (the shoot of them is tested below)
        let l = generate(&p).unwrap();
        check_mesh("pine", &l);
        let pos: Vec<glam::Vec3> =
            l.mesh.positions.chunks_exact(3).map(|c| glam::Vec3::new(c[0], c[1], c[2])).collect();
        // Needle tips: the vertices at the top (y near 1), one per needle, splayed apart.
        let tips: Vec<glam::Vec3> = pos.iter().copied().filter(|q| q.y > 0.99).collect();
        assert_eq!(tips.len(), n as usize, "{n} needles");
        for (i, a) in tips.iter().enumerate() {
            for b in &tips[i + 1..] {
                assert!((*a - *b).length() > 0.05, "the needles splay apart");
            }
        }
        // Round, not a flat blade: the needles have depth (z) as well as width (x).
        let zs = pos.iter().map(|q| q.z.abs()).fold(0.0f32, f32::max);
        assert!(zs > 0.3 * p.leaf.leaf_aspect, "fascicle depth {zs}");
        // Faces wind outward: each face's normal points away from the fascicle's axis.
        let outward = l
            .mesh
            .indices
            .chunks_exact(3)
            .filter(|t| {
                let [a, b, c] = [pos[t[0] as usize], pos[t[1] as usize], pos[t[2] as usize]];
                let centre = (a + b + c) / 3.0;
                (b - a).cross(c - a).dot(glam::Vec3::new(centre.x, 0.0, centre.z)) >= 0.0
            })
            .count();
        assert!(outward * 10 >= l.mesh.indices.len() / 3 * 7, "{n}: most faces face outward ({outward})");
    }
}

#[test]
fn the_petiole_is_drawn_and_flat_for_aspen() {
    for (name, flat) in [("aspen", true), ("maple", false)] {
        let p = preset(name);
        let l = generate(&p).unwrap();
        check_mesh(name, &l);
        let lowest = l.mesh.positions.chunks_exact(3).map(|c| c[1]).fold(f32::MAX, f32::min);
        assert!(
            (lowest + p.foliage.leaf_petiole).abs() < 1e-6,
            "{name}: the petiole reaches y = -{}",
            p.foliage.leaf_petiole
        );
        // The petiole is the mesh's last quad.
        let stalk: Vec<&[f32]> = l.mesh.positions.chunks_exact(3).rev().take(4).collect();
        let spread = |k: usize| {
            stalk.iter().map(|c| c[k]).fold(f32::MIN, f32::max) - stalk.iter().map(|c| c[k]).fold(f32::MAX, f32::min)
        };
        if flat {
            assert!(spread(2) > 0.02 && spread(0) < 1e-6, "{name}: flattened across the blade's plane");
        } else {
            assert!(spread(0) > 0.02 && spread(2) < 1e-6, "{name}: in the blade's plane");
        }
        assert!(
            l.petiole == p.foliage.leaf_petiole
                && sylva_core::leaf::svg::render(&l, &Default::default()).contains("stroke-linecap=\"round\"")
        );
    }
    let oak = preset("oak");
    assert!(oak.foliage.leaf_petiole < 0.1 && preset("maple").foliage.leaf_petiole > 0.5, "oak short, maple long");
}

#[test]
fn every_species_preset_is_a_valid_leaf_with_its_own_look() {
    let mut hashes = std::collections::BTreeSet::new();
    for preset in LEAF_PRESETS {
        let l = generate(&preset.params().unwrap()).unwrap();
        check_mesh(preset.name, &l);
        assert!(hashes.insert(l.hash), "{}: a leaf of its own", preset.name);
    }
    // Willow is lanceolate (about 7:1), aspen nearly round.
    let ratio = |name: &str| {
        let o = outline_of(&preset(name));
        let (lo, hi) = sylva_core::leaf::geom::bounds(&o.points);
        (hi.y - lo.y) / (hi.x - lo.x)
    };
    assert!((5.5..9.0).contains(&ratio("willow")), "willow {}", ratio("willow"));
    assert!((0.85..1.2).contains(&ratio("aspen")), "aspen {}", ratio("aspen"));
}

#[test]
fn tree_presets_wear_their_own_leaves() {
    use sylva_core::presets::{find as tree, PRESETS};
    for t in PRESETS {
        assert!(find(t.leaf).is_some(), "{}: leaf preset {} exists", t.name, t.leaf);
        let p = t.params().unwrap();
        let leaf = find(t.leaf).unwrap().params().unwrap();
        for s in sylva_core::params::registry().iter().filter(|s| s.group.starts_with("Leaf")) {
            assert_eq!(p.get(&s.id), leaf.get(&s.id), "{}: {} from the {} leaf", t.name, s.id, t.leaf);
        }
    }
    for (name, leaf) in [
        ("quaking_aspen", "aspen"),
        ("fir", "fir"),
        ("cypress", "cypress"),
        ("oak", "oak"),
        ("ca_black_oak", "black_oak"),
        ("weeping_willow", "willow"),
    ] {
        assert_eq!(tree(name).unwrap().leaf, leaf);
    }
    // The share link carries the leaf: the presets' JSON values include the leaf's.
    let json: serde_json::Value = serde_json::from_str(&sylva_core::presets::presets_json()).unwrap();
    let oak = json.as_array().unwrap().iter().find(|p| p["name"] == "oak").unwrap();
    assert_eq!(oak["leaf"], "oak");
    assert_eq!(oak["values"]["leaf_lobes"], 5.0);
}

/// Regression: a pinnate secondary vein whose bend point sits below y = 0.02 (Secondary Angle
/// or lobes near the base) made `clamp(0.02, 0.95 * y)` panic with min > max, a crash of the
/// worker. Found by the incremental test's sweep over every parameter; every leaf parameter at
/// its minimum and maximum, on every species, must give a leaf or a typed error, never a panic.
#[test]
fn regression_every_leaf_parameter_at_its_bounds_on_every_species() {
    // Few auxins and a small texture keep the ~1,300 leaves quick; the outline and primary
    // veins, where the panic was, do not depend on them.
    let quick = [("leaf_vein_density", 100.0), ("leaf_texture_level", 4.0), ("leaf_rings", 2.0)];
    for leaf in sylva_core::leaf::presets::LEAF_PRESETS {
        let mut base = leaf.params().unwrap();
        for (id, v) in quick {
            base.set(id, v).unwrap();
        }
        for s in sylva_core::params::registry().iter().filter(|s| s.group.starts_with("Leaf")) {
            if quick.iter().any(|(id, _)| *id == s.id) {
                continue;
            }
            for v in [s.min, s.max] {
                let mut p = base.clone();
                p.set(&s.id, v).unwrap();
                let r = std::panic::catch_unwind(|| generate(&p).map(|_| ()));
                assert!(r.is_ok(), "{}: {} = {v} panicked", leaf.name, s.id);
            }
        }
    }
}

fn positions(l: &Leaf) -> Vec<glam::Vec3> {
    l.mesh.positions.chunks_exact(3).map(|c| glam::Vec3::new(c[0], c[1], c[2])).collect()
}

fn centroid(poly: &[Vec2]) -> Vec2 {
    poly.iter().copied().sum::<Vec2>() / poly.len() as f32
}

#[test]
fn conifer_shoots_carry_their_needles_in_ranks_or_all_around() {
    // Fir: 56 single flat needles in two ranks, alternately left and right of the twig, in a
    // shallow V (close to the leaf plane).
    let p = preset("fir");
    let fir = generate(&p).unwrap();
    check_mesh("fir shoot", &fir);
    assert_eq!(fir.shoot.len(), 56);
    let mut single = p.clone();
    single.leaf.leaf_shoot = 0;
    single.foliage.leaf_petiole = 0.0;
    let needle = generate(&single).unwrap();
    // Every needle is the single needle's blade, plus the twig's and the stalk's quads.
    assert_eq!(fir.mesh.triangle_count(), 56 * needle.mesh.triangle_count() + 2 + 2);
    for (i, n) in fir.shoot.iter().enumerate() {
        let side = centroid(n).x;
        assert!(if i % 2 == 0 { side > 0.02 } else { side < -0.02 }, "needle {i} on its rank: {side}");
    }
    let fir_pos = positions(&fir);
    let depth = |pos: &[glam::Vec3]| pos.iter().map(|q| q.z.abs()).fold(0.0f32, f32::max);
    assert!(depth(&fir_pos) < 0.5 * p.leaf.leaf_shoot_needle, "flat: {}", depth(&fir_pos));
    // Needles reach from the base to past the tip, along the whole twig.
    let ys: Vec<f32> = fir.shoot.iter().map(|n| centroid(n).y).collect();
    assert!(ys.iter().copied().fold(f32::MAX, f32::min) < 0.15 && ys.iter().copied().fold(0.0, f32::max) > 0.9);

    // Pine: 30 fascicles of two round needles all around the twig: the needles stand out in
    // front of and behind the leaf plane as far as to its sides.
    let p = preset("pine");
    let pine = generate(&p).unwrap();
    check_mesh("pine shoot", &pine);
    assert_eq!(pine.shoot.len(), 30 * 2, "two outlines per fascicle");
    let pos = positions(&pine);
    let reach = p.leaf.leaf_shoot_needle * p.leaf.leaf_shoot_angle.to_radians().sin();
    let front = pos.iter().map(|q| q.z).fold(f32::MIN, f32::max);
    let back = pos.iter().map(|q| q.z).fold(f32::MAX, f32::min);
    assert!(front > 0.6 * reach && back < -0.6 * reach, "all around: z {back}..{front}, reach {reach}");

    // The baked texture: a brown twig along the middle, green needles either side, and the
    // needles cover a good share of the box (the mass a far conifer needs).
    for (name, l) in [("fir", &fir), ("pine", &pine)] {
        let t = &l.texture;
        let texel = |x: f32, y: f32| {
            let uv = l.uv_frame.uv(Vec2::new(x, y));
            let (i, j) = ((uv.x * t.width as f32) as usize, (uv.y * t.height as f32) as usize);
            let k = 4 * (j.min(t.height as usize - 1) * t.width as usize + i.min(t.width as usize - 1));
            [t.color[k], t.color[k + 1], t.color[k + 2], t.color[k + 3]]
        };
        let twig = texel(0.0, -0.5 * p.foliage.leaf_petiole.max(0.02));
        assert!(twig[3] == 255 && twig[0] > twig[1], "{name}: brown twig {twig:?}");
        let inside = t.color.chunks_exact(4).filter(|c| c[3] == 255).collect::<Vec<_>>();
        let green = inside.iter().filter(|c| c[1] > c[0] && c[1] > c[2]).count();
        assert!(green > inside.len() / 2, "{name}: green needles");
        let share = inside.len() as f64 / f64::from(t.width * t.height);
        assert!(share > 0.2, "{name}: needles cover {share} of the box");
    }
}

#[test]
fn a_fir_carries_the_needles_of_a_real_conifer() {
    // With one needle per leaf the fir had 131,600 needles (17 m² of needle area) and looked bare
    // from a distance; as shoots its 26,320 leaves carry 1,473,920 needles.
    let p = sylva_core::presets::find("fir").unwrap().params().unwrap();
    let skeleton = sylva_core::skeleton::build(&p.skeleton).unwrap();
    let foliage = sylva_core::foliage::build(&skeleton, &p.foliage, &p.leaf).unwrap();
    let per_shoot = foliage.leaf.as_ref().unwrap().shoot.len();
    assert_eq!(per_shoot, 56);
    let needles = foliage.count() * per_shoot;
    assert!(needles > 1_000_000, "{needles} needles");
    assert!(foliage.count() < 30_000, "{} shoots stay cheap to draw", foliage.count());
}

#[test]
fn oak_lobes_are_irregular_like_a_real_leaf() {
    // No two lobes of a real oak leaf match: with its Asymmetry Seed the lobes move along the
    // midrib, reach out more or less and their sinuses cut to different depths; seed 0 draws
    // the regular layout. The outline stays continuous (no jump at a period's end).
    let lobes = |seed: u32| {
        let mut p = preset("oak");
        p.leaf.leaf_asymmetry_seed = seed;
        let shape = sylva_core::leaf::lobes::Pinnate::from_params(&p.leaf);
        let step = (0..=20_000).map(|i| shape.lobe(f64::from(i) / 20_000.0));
        let jump = step.clone().zip(step.skip(1)).map(|(a, b)| (b - a).abs()).fold(0.0, f64::max);
        assert!(jump < 0.01, "seed {seed}: the lobe profile jumps by {jump}");
        lobes_along_the_midrib(&outline_of(&p), 0.01)
    };
    let oak = preset("oak").leaf.leaf_asymmetry_seed;
    assert!(oak != 0);
    let (regular, irregular) = (lobes(0), lobes(oak));
    assert_eq!(regular.len(), irregular.len(), "the same lobes, drawn differently");
    let moved = regular.iter().zip(&irregular).map(|(a, b)| (a.0 - b.0).abs()).fold(0.0f32, f32::max);
    let reach = regular.iter().zip(&irregular).map(|(a, b)| (b.1 / a.1 - 1.0).abs()).fold(0.0f32, f32::max);
    assert!(moved > 0.015, "a lobe moves along the midrib: {moved}");
    assert!(reach > 0.08, "a lobe reaches further or less far: {reach}");
}

#[test]
fn ginkgo_is_a_fan_with_straight_sides_and_a_clean_notch() {
    // A ginkgo blade is a fan: its sides run straight into the petiole. The palmate model drew
    // round shoulders, a small knob around the junction (its 0.06 floor) and a spike in the
    // notch (the smooth maximum of the two lobes where they meet stood 2^⅛ above either).
    let o = outline_of(&preset("ginkgo"));
    let half = o.half(0);
    // Straight sides: between the junction and the shoulders the half-width grows in
    // proportion to the height, as along a line through the junction (a knob would hold it
    // up low down, a round shoulder would bend it).
    let width_at = |y: f32| {
        half.windows(2)
            .find(|w| (w[0].y - y) * (w[1].y - y) <= 0.0 && (w[0].y - w[1].y).abs() > 1e-6)
            .map(|w| {
                let s = (y - w[0].y) / (w[1].y - w[0].y);
                (w[0].x + (w[1].x - w[0].x) * s).abs()
            })
            .unwrap()
    };
    let (lowest, _) = half.iter().fold((f32::MAX, 0.0f32), |(lo, x), q| if q.y < lo { (q.y, q.x) } else { (lo, x) });
    assert!(lowest > -0.02, "no knob below the junction: lowest point at y = {lowest}");
    let shoulder = half.iter().max_by(|a, b| a.x.abs().total_cmp(&b.x.abs())).unwrap().y;
    let slope = |y: f32| width_at(y) / y;
    let (s1, s2, s3) = (slope(0.15 * shoulder), slope(0.5 * shoulder), slope(0.85 * shoulder));
    assert!((s1 - s2).abs() < 0.15 * s2 && (s3 - s2).abs() < 0.15 * s2, "straight sides: {s1} {s2} {s3}");
    // A clean notch: the tip point (t = 0, on the midline) is its lowest point, no spike.
    let notch: Vec<Vec2> = o.points.iter().copied().filter(|q| q.x.abs() < 0.03 && q.y > 0.5).collect();
    let tip = o.points[0];
    assert!(notch.iter().all(|q| q.y >= tip.y - 1e-5), "the notch's bottom is at the midline: {tip} {notch:?}");
}
