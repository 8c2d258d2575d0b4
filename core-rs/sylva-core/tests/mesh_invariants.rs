//! Geometry invariants (standing rule 6) on every preset and on a spread of seeds.

mod common;

use common::{assert_mesh_invariants, edge_uses};
use sylva_core::mesh::tube::sides_for;
use sylva_core::mesh::twig;
use sylva_core::params::{MeshParams, SkeletonParams};
use sylva_core::{generate, presets::PRESETS, TreeParams};

#[test]
fn every_preset_satisfies_the_invariants() {
    for preset in PRESETS {
        let g = generate(&preset.params().unwrap()).unwrap();
        assert_mesh_invariants(&g, preset.name);
    }
}

#[test]
fn many_seeds_satisfy_the_invariants() {
    for seed in 0..12 {
        let p = TreeParams { skeleton: SkeletonParams { seed, ..Default::default() }, ..TreeParams::default() };
        assert_mesh_invariants(&generate(&p).unwrap(), &format!("seed {seed}"));
    }
}

#[test]
fn uv_v_is_continuous_and_increasing_along_stems() {
    let g = generate(&TreeParams::default()).unwrap();
    // Along each ring column (same u), v never decreases from one ring to the next.
    let uv = &g.mesh.uvs;
    let mut checked = 0;
    for t in g.mesh.indices.chunks_exact(6).take(20_000) {
        // Quads are (a, b, c), (a, c, d) with d one ring above a.
        let (a, d) = (t[0] as usize, t[5] as usize);
        if uv[a * 2] == uv[d * 2] {
            assert!(uv[d * 2 + 1] >= uv[a * 2 + 1], "v decreases along a stem");
            checked += 1;
        }
    }
    assert!(checked > 1000);
}

#[test]
fn quality_changes_resolution_and_budget_stops_runaways() {
    let lo =
        generate(&TreeParams { mesh: MeshParams { mesh_quality: 0.5, ..Default::default() }, ..TreeParams::default() })
            .unwrap();
    let hi =
        generate(&TreeParams { mesh: MeshParams { mesh_quality: 2.0, ..Default::default() }, ..TreeParams::default() })
            .unwrap();
    assert!(hi.stats.vertices > lo.stats.vertices * 2);
    let e = generate(&TreeParams {
        skeleton: SkeletonParams { max_vertices: 10_000, ..Default::default() },
        ..TreeParams::default()
    })
    .unwrap_err();
    assert_eq!(e.to_json().split('"').nth(3), Some("budget"), "{e:?}");
    assert!(e.message().contains("max_vertices budget of 10000"), "{e}");
}

// Regressions: each found while bringing up the Weeping Willow preset.

#[test]
fn regression_trunk_cap_faces_down_under_strong_flare() {
    // The base fan once reused the flared ring's up-tilted side normals: wound against them.
    let g = generate(&TreeParams {
        skeleton: SkeletonParams { flare: 5.0, ..Default::default() },
        ..TreeParams::default()
    })
    .unwrap();
    assert_mesh_invariants(&g, "flare 5");
}

#[test]
fn regression_split_clones_never_coincide_with_their_original() {
    // With the split angle clamped to 0 and strong downward attraction, clones once landed
    // exactly on top of their originals (edges shared by four triangles).
    let mut p =
        TreeParams { skeleton: SkeletonParams { attraction_up: -10.0, ..Default::default() }, ..TreeParams::default() };
    p.skeleton.level[1].seg_splits = 0.5;
    p.skeleton.level[2].seg_splits = 0.5;
    p.skeleton.level[2].curve_v = 0.0;
    let g = generate(&p).unwrap();
    assert!(edge_uses(&g.mesh).values().all(|&u| u <= 2));
    assert_mesh_invariants(&g, "clones");
}

#[test]
fn regression_stems_pruned_to_nothing_are_dropped() {
    // Pruning with a tiny envelope once left zero-length stems whose rings collapsed.
    let g = generate(&TreeParams {
        skeleton: SkeletonParams { prune_ratio: 1.0, prune_width: 0.02, ..Default::default() },
        ..TreeParams::default()
    })
    .unwrap();
    assert_mesh_invariants(&g, "pruned");
    assert!(g.skeleton.stems.iter().all(|s| s.length > 0.0));
}

#[test]
fn complex_trunk_is_fluted_and_still_a_valid_surface() {
    let p = TreeParams {
        skeleton: SkeletonParams { flare: 0.0, ..Default::default() },
        mesh: MeshParams { refine_curves: 6, lobes: 0, base_ripple: 0.0, ..Default::default() },
        ..TreeParams::default()
    };
    let g = generate(&p).unwrap();
    assert_mesh_invariants(&g, "refined trunk");
    // Ring 0 of the trunk (the first stem's first vertices) lies on the union of the main circle
    // and the refinement circles: never inside the main circle, never beyond the largest reach.
    let trunk = &g.skeleton.stems[0];
    let sides = sides_for(trunk.radius, p.mesh.mesh_quality, 0) as usize;
    let r0 = trunk.radius_at(0.0);
    let reach = r0
        * (p.mesh.refine_offset * (1.0 + p.mesh.refine_variation)
            + p.mesh.refine_radius * (1.0 + p.mesh.refine_variation));
    let dist: Vec<f32> = (0..sides)
        .map(|j| {
            let v = &g.mesh.positions[j * 3..j * 3 + 3];
            (v[0] * v[0] + v[2] * v[2]).sqrt()
        })
        .collect();
    let (lo, hi) = dist.iter().fold((f32::MAX, 0.0f32), |(a, b), &d| (a.min(d), b.max(d)));
    assert!(lo >= r0 * 0.999 && hi <= reach * 1.001, "ring 0 radii {lo}..{hi}, main {r0}, reach {reach}");
    assert!(hi / lo > 1.15, "the outline is not fluted: {lo}..{hi}");
    // The base ripple alone makes a 7-fold ribbed base.
    let rippled = generate(&TreeParams {
        mesh: MeshParams { base_ripple: 0.2, lobes: 0, ..Default::default() },
        ..TreeParams::default()
    })
    .unwrap();
    assert_mesh_invariants(&rippled, "base ripple");
    assert_ne!(
        rippled.hash,
        generate(&TreeParams { mesh: MeshParams { lobes: 0, ..Default::default() }, ..TreeParams::default() })
            .unwrap()
            .hash
    );
}

#[test]
fn surface_roots_spread_from_the_trunk_base_into_the_ground() {
    let none = generate(&TreeParams::default()).unwrap();
    let p = TreeParams {
        skeleton: SkeletonParams { root_count: 6, root_depth: 1.0, ..Default::default() },
        ..TreeParams::default()
    };
    let g = generate(&p).unwrap();
    assert_mesh_invariants(&g, "roots");
    let roots: Vec<_> = g.skeleton.stems.iter().filter(|s| s.parent == Some(0) && s.down_angle == 90.0).collect();
    assert_eq!(roots.len(), 6);
    let trunk_r = g.skeleton.stems[0].radius;
    for r in &roots {
        assert!(r.tip().y < 0.0, "root tip above the ground");
        assert!(r.radius <= trunk_r, "root thicker than the trunk");
        let out = (r.tip().x * r.tip().x + r.tip().z * r.tip().z).sqrt();
        assert!(out > 2.0 * trunk_r, "root does not spread outward");
    }
    // Roots add geometry below the ground and leave every other stem as it was.
    assert!(g.bounds.min[1] < -0.01);
    assert_eq!(g.skeleton.stems.len(), none.skeleton.stems.len() + 6);
    assert!(none.skeleton.stems.iter().zip(&g.skeleton.stems).all(|(a, b)| a.points == b.points));
}

#[test]
fn the_guide_curve_moves_trunk_points_sideways_within_the_limit() {
    let straight = generate(&TreeParams::default()).unwrap();
    let g = generate(&TreeParams {
        skeleton: SkeletonParams { guide_xy: 0.3, ..Default::default() },
        ..TreeParams::default()
    })
    .unwrap();
    assert_mesh_invariants(&g, "guide curve");
    let (a, b) = (&straight.skeleton.stems[0].points, &g.skeleton.stems[0].points);
    assert_eq!(b[0], a[0], "the guide curve starts at the origin");
    for (i, (p, q)) in a.iter().zip(b.iter()).enumerate().skip(1) {
        let limit = if i == 1 { 0.15 } else { 0.3 };
        assert_eq!(p.y, q.y, "heights are kept");
        assert!((p.x - q.x).abs() <= limit + 1e-6 && (p.z - q.z).abs() <= limit + 1e-6);
    }
    assert!(a.iter().zip(b.iter()).skip(1).any(|(p, q)| (p.x - q.x).abs() > 0.01));
}

#[test]
fn wind_attributes_follow_the_stems() {
    use sylva_core::mesh::WIND_STRIDE;
    for name in ["default", "ca_black_oak", "grown_broadleaf"] {
        // Without holes: a cavity's vertices copy their rim's records (tests/holes.rs checks
        // that), so `v` and distance need not agree inside one.
        let p = TreeParams {
            mesh: MeshParams { hole_count: 0, ..sylva_core::presets::find(name).unwrap().params().unwrap().mesh },
            ..sylva_core::presets::find(name).unwrap().params().unwrap()
        };
        let g = generate(&p).unwrap();
        let (m, stems) = (&g.mesh, &g.skeleton.stems);
        assert_eq!(m.wind.len(), WIND_STRIDE * m.vertex_count(), "{name}: wind length");
        assert!(m.wind.iter().all(|w| w.is_finite()), "{name}: non-finite wind");
        let w = |i: usize| &m.wind[i * WIND_STRIDE..(i + 1) * WIND_STRIDE];
        // Each stem: its pivot is its base point, its level its level, one phase for all its
        // vertices, so there are exactly as many (pivot, level, phase) keys as stems.
        let key = |i: usize| {
            let r = w(i);
            (r[0].to_bits(), r[1].to_bits(), r[2].to_bits(), r[3].to_bits(), r[4].to_bits())
        };
        let mut keys = std::collections::BTreeSet::new();
        for i in 0..m.vertex_count() {
            let phase = w(i)[4];
            assert!((0.0..1.0).contains(&phase), "{name}: phase {phase}");
            assert!((0.0..=1.0).contains(&w(i)[5]), "{name}: stiffness {}", w(i)[5]);
            assert!(w(i)[7] >= 0.0, "{name}: radius {}", w(i)[7]);
            keys.insert(key(i));
        }
        assert_eq!(keys.len(), stems.len(), "{name}: one (pivot, level, phase) per stem");
        let pivots: std::collections::BTreeSet<_> = keys.iter().map(|k| (k.0, k.1, k.2, k.3)).collect();
        let mut base = vec![0.0f32; stems.len()];
        for (k, s) in stems.iter().enumerate() {
            base[k] = s.parent.map_or(0.0, |p| base[p as usize] + s.offset);
            let b = s.base();
            let bits = (b.x.to_bits(), b.y.to_bits(), b.z.to_bits(), f32::from(s.level).to_bits());
            assert!(pivots.contains(&bits), "{name}: no vertex carries stem {k}'s pivot and level");
        }
        assert_eq!(w(0)[3], 0.0, "{name}: the first vertices are the trunk's");
        assert!(w(0)[5] > 0.99, "{name}: the trunk base is stiff");
        // Distance grows along each stem: on every edge inside one stem, distance and v agree.
        let mut checked = 0;
        for t in m.indices.chunks_exact(3) {
            for e in 0..3 {
                let (a, b) = (t[e] as usize, t[(e + 1) % 3] as usize);
                if key(a) != key(b) {
                    continue;
                }
                let dd = w(b)[6] - w(a)[6];
                if dd.abs() > 1e-5 {
                    let dv = m.uvs[b * 2 + 1] - m.uvs[a * 2 + 1];
                    assert!(dd * dv > 0.0, "{name}: distance and v disagree on edge {a}-{b}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 1000, "{name}: only {checked} edges checked");
        // Distances start at the root: the largest is about the longest root-to-tip path.
        let max = m.wind.chunks_exact(WIND_STRIDE).map(|r| r[6]).fold(0.0f32, f32::max);
        let longest = stems.iter().enumerate().map(|(k, s)| base[k] + s.length).fold(0.0f32, f32::max);
        assert!((max - longest).abs() < 1e-3 * longest.max(1.0), "{name}: max distance {max} vs {longest}");
    }
}

#[test]
fn bezier_twigs_are_closed_and_their_detail_sets_the_sides() {
    use sylva_core::params::TwigDetail;
    let mut sides_seen = Vec::new();
    for i in 0..4 {
        // Unwelded, every simple deepest-level stem is a twig (welded ones are swept as tubes).
        let p = TreeParams {
            mesh: MeshParams { twig_detail: TwigDetail::from_index(i), weld: false, ..Default::default() },
            ..TreeParams::default()
        };
        let g = generate(&p).unwrap();
        assert_mesh_invariants(&g, &format!("twig detail {i}"));
        let twigs = twig::mask(&g.skeleton);
        let count = twigs.iter().filter(|&&t| t).count();
        assert!(count > 20, "the default tree has Bezier twigs: {count}");
        // Twigs are closed at their tips and capped at their bases: no open edge anywhere.
        let open = edge_uses(&g.mesh).values().filter(|&&u| u == 1).count();
        assert_eq!(open, 0, "detail {i}: open edges");
        let first = g.skeleton.stems.iter().zip(&twigs).find(|(_, &t)| t).unwrap().0;
        sides_seen.push(twig::sides(first.radius, p.mesh.mesh_quality, p.mesh.twig_detail));
        if i == 2 {
            assert_eq!(sides_seen[2], sides_for(first.radius, p.mesh.mesh_quality, 0), "step 4 = the tube's sides");
        }
    }
    assert!(sides_seen.windows(2).all(|w| w[0] > w[1]), "finer steps, more sides: {sides_seen:?}");
    // One level deeper, the deepest stems are straight (one segment): all of them are twigs.
    let p = TreeParams { skeleton: SkeletonParams { levels: 4, ..Default::default() }, ..TreeParams::default() };
    let g = generate(&p).unwrap();
    assert_mesh_invariants(&g, "levels 4");
    let twigs = twig::mask(&g.skeleton);
    let deepest = g.skeleton.stems.iter().filter(|s| s.level == 3).count();
    assert!(deepest > 1000);
    assert_eq!(twigs.iter().filter(|&&t| t).count(), deepest);
}

#[test]
fn twig_rings_follow_the_bezier_span_and_its_radii() {
    use sylva_core::mesh::twig::{middle_radius, Span};
    let p = TreeParams { mesh: MeshParams { weld: false, ..Default::default() }, ..TreeParams::default() };
    let g = generate(&p).unwrap();
    let twigs = twig::mask(&g.skeleton);
    let (i, stem) = g.skeleton.stems.iter().enumerate().find(|(i, _)| twigs[*i]).unwrap();
    let span = Span::fit(stem);
    let l0 = (span.p[1] - span.p[0]).length();
    let l1 = (span.p[2] - span.p[1]).length();
    assert_eq!(span.r[1], middle_radius(l0, l1, span.r[0], span.r[2]));
    // The span passes through the stem's base, the centre curve's midpoint and its tip.
    assert!((span.point(0.5) - stem.sample(0.5).0).length() < 1e-5);
    assert_eq!(span.point(0.0), stem.base());
    assert!((span.point(1.0) - stem.tip()).length() < 1e-5);
    // The twig's first ring is the control circle R0 around the base, across the first leg.
    let (mesh, layout) = sylva_core::mesh::tube::build_laid_out(&g.skeleton, &p.mesh).unwrap();
    let blocks = layout.blocks;
    let sides = twig::sides(stem.radius, p.mesh.mesh_quality, p.mesh.twig_detail) as usize;
    let d0 = (span.p[1] - span.p[0]).normalize();
    for v in blocks[i].start as usize..blocks[i].start as usize + sides + 1 {
        let x = glam::Vec3::from_slice(&mesh.positions[v * 3..v * 3 + 3]);
        assert!(((x - span.p[0]).length() - span.r[0]).abs() < 1e-4 * (1.0 + span.r[0]));
        assert!((x - span.p[0]).dot(d0).abs() < 1e-4);
    }
    // Its block: rings of sides + 1 vertices, the apex and the base cap's centre.
    assert_eq!((blocks[i].len() - 2) % (sides + 1), 0);
}
