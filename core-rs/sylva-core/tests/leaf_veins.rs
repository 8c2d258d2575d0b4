//! Leaf veins (issue 4): open venation is a tree, closed venation has real loops, pipe-model
//! widths never grow toward the tips, the midrib reaches the tip even with sparse sources, the
//! growth can be replayed step by step, and the veins stay inside the blade.

use glam::Vec2;
use sylva_core::leaf::geom::dist_to_polygon;
use sylva_core::leaf::geom::point_in_polygon;
use sylva_core::leaf::presets::{find, LEAF_PRESETS};
use sylva_core::leaf::veins::{MAX_AUXINS, NONE};
use sylva_core::leaf::Leaf;
use sylva_core::params::{LeafPrimaries, LeafVenation};
use sylva_core::TreeParams;

/// The leaf of tree parameters `p`: its leaf parameters and Petiole Length.
fn generate(p: &TreeParams) -> Result<Leaf, sylva_core::SylvaError> {
    sylva_core::leaf::generate(&p.leaf, p.foliage.leaf_petiole)
}

fn preset(name: &str) -> TreeParams {
    find(name).unwrap().params().unwrap()
}

fn leaf(p: &TreeParams) -> Leaf {
    generate(p).unwrap()
}

#[test]
fn open_venation_is_a_tree_closed_venation_has_loops() {
    for name in ["superformula_oak", "superformula_birch", "superformula_willow"] {
        let l = leaf(&preset(name));
        let g = &l.veins.graph;
        assert!(g.nodes.len() > 100, "{name}: {} nodes", g.nodes.len());
        assert!(g.links.is_empty() && !g.has_cycle(), "{name}: open venation has no cycles");
        assert_eq!(g.loops(), 0);
    }
    let maple = preset("superformula_maple");
    let l = leaf(&maple);
    let g = &l.veins.graph;
    assert!(g.has_cycle(), "closed venation has cycles");
    assert!(g.loops() >= 100, "maple: {} loops", g.loops());
    // Each link closes a loop between different veins: its ends are far apart along the tree.
    for k in &g.links {
        let (a, b) = (g.nodes[k.a as usize].pos, g.nodes[k.b as usize].pos);
        assert!((a - b).length() <= 2.0 * maple.leaf.leaf_kill + 1e-4, "a link joins veins that met at one source");
        assert_ne!(g.nodes[k.a as usize].parent, k.b);
        assert_ne!(g.nodes[k.b as usize].parent, k.a);
    }
}

#[test]
fn widths_follow_the_pipe_model_and_never_grow_toward_the_tips() {
    for preset_def in LEAF_PRESETS {
        let p = preset_def.params().unwrap();
        let l = leaf(&p);
        let g = &l.veins.graph;
        if g.nodes.is_empty() {
            assert_eq!(p.leaf.leaf_venation, LeafVenation::None, "{}", preset_def.name);
            continue;
        }
        let root = g.nodes[0];
        assert_eq!(root.width, p.leaf.leaf_vein_width, "{}: the midrib base has the full width", preset_def.name);
        for (i, n) in g.nodes.iter().enumerate().skip(1) {
            let parent = g.nodes[n.parent as usize];
            assert!(n.width <= parent.width, "{}: node {i} is wider than its parent", preset_def.name);
            let want = p.leaf.leaf_vein_width * (n.tips as f32 / root.tips as f32).sqrt();
            assert!((n.width - want).abs() <= 1e-6 * p.leaf.leaf_vein_width, "{}: node {i} width", preset_def.name);
        }
        // The midrib is the thickest vein at every height: its first segment carries the most tips
        // (palmate and dichotomous leaves share the flow between several primaries instead).
        if matches!(p.leaf.leaf_primary_veins, LeafPrimaries::Palmate | LeafPrimaries::Dichotomous) {
            continue;
        }
        let midrib = g.midrib();
        let first = g.nodes[midrib[1] as usize];
        assert!(g.nodes.iter().filter(|n| n.parent == 0).all(|n| n.tips <= first.tips), "{}", preset_def.name);
        for k in &g.links {
            assert!(k.width <= g.nodes[k.a as usize].width && k.width <= g.nodes[k.b as usize].width);
        }
    }
}

fn assert_midrib_reaches_tip(l: &Leaf, what: &str) {
    let g = &l.veins.graph;
    let midrib = g.midrib();
    assert_eq!(midrib[0], 0, "{what}: the midrib starts at the petiole");
    let end = g.nodes[*midrib.last().unwrap() as usize].pos;
    let gap = (end - Vec2::new(0.0, 1.0)).length();
    assert!(gap <= 0.05, "{what}: the midrib ends {gap} from the tip");
}

#[test]
fn the_midrib_reaches_the_tip_even_with_sparse_sources() {
    for name in ["superformula_oak", "superformula_maple", "superformula_birch", "superformula_willow"] {
        let p = preset(name);
        assert_midrib_reaches_tip(&leaf(&p), name);
        for density in [0.0, 10.0, 40.0, 150.0] {
            for seed in [1, 2, 3] {
                let mut q = p.clone();
                q.leaf.leaf_vein_density = density;
                q.leaf.leaf_vein_seed = seed;
                let l = leaf(&q);
                assert_midrib_reaches_tip(&l, &format!("{name} density {density} seed {seed}"));
                // Every source is reached: sparse sources are fetched from any distance.
                let unreached = l.veins.auxins.iter().filter(|a| a.killed_at == NONE).count();
                assert!(
                    unreached <= l.veins.auxins.len() / 10,
                    "{name} density {density}: {unreached} sources never reached"
                );
            }
        }
    }
    let mut p = preset("superformula_oak");
    p.leaf.leaf_venation = LeafVenation::Spline;
    assert_midrib_reaches_tip(&leaf(&p), "spline veins");
}

#[test]
fn sparse_sources_use_the_fallback_and_still_branch() {
    let mut p = preset("superformula_willow");
    (p.leaf.leaf_vein_density, p.leaf.leaf_attraction, p.leaf.leaf_kill) = (40.0, 0.03, 0.01);
    let l = leaf(&p);
    let g = &l.veins.graph;
    assert!(g.fallback, "sources beyond the attraction distance are fetched by the fallback");
    let branch_points =
        (0..g.nodes.len()).filter(|&i| g.nodes.iter().filter(|n| n.parent == i as u32).count() > 1).count();
    assert!(branch_points >= 3, "{branch_points} branch points");
}

#[test]
fn auxin_count_is_density_times_area_up_to_5000() {
    let mut p = preset("superformula_oak");
    let area = sylva_core::leaf::geom::polygon_area(&leaf(&p).outline.points);
    for density in [200.0f32, 1000.0] {
        p.leaf.leaf_vein_density = density;
        let l = leaf(&p);
        let want = (f64::from(density) * area).round() as usize;
        assert_eq!(l.veins.auxins.len(), want + 1, "density {density} (plus the apex source)");
    }
    p.leaf.leaf_vein_density = 20_000.0;
    assert_eq!(leaf(&p).veins.auxins.len(), MAX_AUXINS + 1);
}

#[test]
fn growth_is_recorded_per_iteration_for_replay() {
    for name in ["superformula_oak", "superformula_maple"] {
        let l = leaf(&preset(name));
        let g = &l.veins.graph;
        let max_born = g.nodes.iter().map(|n| n.born).chain(g.links.iter().map(|k| k.born)).max().unwrap();
        assert_eq!(g.iterations, max_born, "{name}");
        for n in g.nodes.iter().skip(1) {
            assert!(n.born > g.nodes[n.parent as usize].born, "{name}: a node is born after its parent");
        }
        for k in &g.links {
            assert!(k.born >= g.nodes[k.a as usize].born && k.born >= g.nodes[k.b as usize].born);
        }
        // Auxins are consumed as the veins grow: more are gone after later steps.
        let gone = |step: u32| l.veins.auxins.iter().filter(|a| a.killed_at <= step).count();
        assert!(gone(g.iterations / 4) < gone(g.iterations / 2) && gone(g.iterations / 2) < gone(g.iterations));
    }
}

#[test]
fn veins_stay_inside_the_blade() {
    for name in ["superformula_oak", "superformula_maple", "superformula_birch", "superformula_willow"] {
        for venation in [LeafVenation::Open, LeafVenation::Closed, LeafVenation::Spline] {
            let mut p = preset(name);
            p.leaf.leaf_venation = venation;
            let l = leaf(&p);
            let poly = &l.outline.points;
            for (i, n) in l.veins.graph.nodes.iter().enumerate().skip(1) {
                assert!(
                    point_in_polygon(n.pos, poly) || dist_to_polygon(n.pos, poly) < 1e-4,
                    "{name} {venation:?}: node {i} at {} is outside the blade",
                    n.pos
                );
            }
        }
    }
}

#[test]
fn spline_venation_has_the_requested_lateral_veins() {
    let mut p = preset("superformula_birch");
    p.leaf.leaf_venation = LeafVenation::Spline;
    for count in [3, 7, 12] {
        p.leaf.leaf_vein_count = count;
        let l = leaf(&p);
        let g = &l.veins.graph;
        assert!(!g.has_cycle());
        let midrib: std::collections::BTreeSet<u32> = g.midrib().into_iter().collect();
        let laterals = g
            .nodes
            .iter()
            .filter(|n| {
                n.parent != NONE
                    && midrib.contains(&n.parent)
                    && !midrib.contains(&(g.nodes.iter().position(|m| m == *n).unwrap() as u32))
            })
            .count();
        assert_eq!(laterals, 2 * count as usize, "{count} veins per side");
    }
}
