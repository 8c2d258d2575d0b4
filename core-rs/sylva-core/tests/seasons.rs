//! Seasons (`season.rs`): July is today's tree on every preset; a maple's leaves turn red in
//! October, sun leaves before shaded ones; deciduous trees are bare in January and conifers keep
//! their needles; spring leaves are small. The exported GLB's colours are in `tests/export/season.rs`,
//! season edits in `tests/incremental.rs`.

#![allow(clippy::disallowed_methods, reason = "the test's own colour measure, not output bytes")]

use glam::Vec3;
use sylva_core::crown_shade::CrownLight;
use sylva_core::params::LeafPhenology;
use sylva_core::presets::PRESETS;
use sylva_core::{generate, Generated, TreeParams};

fn at(preset: &str, month: f32) -> Generated {
    let mut p = sylva_core::presets::find(preset).unwrap().params().unwrap();
    p.foliage.season = month;
    generate(&p).unwrap()
}

/// Mean of the leaves' colour as shown: tint times the blade green decoded to linear light
/// (what the tint multiplies), and the mean tint itself.
fn means(g: &Generated) -> (Vec3, Vec3) {
    let lin = |c: f32| if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) };
    let blade = Vec3::from(sylva_core::leaf::texture::BLADE.map(lin));
    let n = g.foliage.on_tree() as f32;
    let tint =
        g.foliage.colors.chunks_exact(3).take(g.foliage.on_tree()).fold(Vec3::ZERO, |s, c| s + Vec3::from_slice(c)) / n;
    (tint * blade, tint)
}

#[test]
fn mid_july_is_the_summer_tree_on_every_preset() {
    // The default (1 July) skips the season; mid-July runs it, and every leaf stays as it is.
    for p in PRESETS {
        let params = p.params().unwrap();
        let mut july = params.clone();
        july.foliage.season = 7.5;
        let (mid, first) = (generate(&july).unwrap(), generate(&params).unwrap());
        if first.foliage.organs.is_empty() {
            assert_eq!(mid.hash, first.hash, "{}", p.name);
        } else {
            // The apple's young fruit swells through July; its leaves stay as they are.
            assert_eq!(
                (mid.foliage.matrices, mid.foliage.colors),
                (first.foliage.matrices, first.foliage.colors),
                "{}",
                p.name
            );
        }
    }
}

#[test]
fn a_maple_is_red_in_october_and_green_in_july() {
    // `umbrella` wears the maple leaf.
    let july = at("umbrella", 7.0);
    let october = at("umbrella", 10.5);
    let ((shown_j, tint_j), (shown_o, tint_o)) = (means(&july), means(&october));
    println!("maple July: shown {shown_j} tint {tint_j}; October: shown {shown_o} tint {tint_o}");
    assert!(shown_j.y > 2.0 * shown_j.x, "July is green: {shown_j}");
    assert!(shown_o.x > 2.0 * shown_o.y, "October is red: {shown_o}");
    assert!(tint_o.x > tint_o.y, "October's tint is redder than green: {tint_o}");
    // Some leaves have fallen by mid-October, none in July.
    assert!(
        october.foliage.on_tree() < july.foliage.on_tree() && october.foliage.on_tree() > july.foliage.on_tree() / 4
    );
}

#[test]
fn sun_leaves_are_further_into_autumn_than_shaded_ones() {
    // Early October: the maple's leaves are turning and none has fallen yet, so leaf k is the
    // same leaf in July and in October, lit by the same field.
    let (july, october) = (at("umbrella", 7.0), at("umbrella", 10.0));
    assert_eq!(july.foliage.on_tree(), october.foliage.on_tree());
    assert_eq!(july.foliage.matrices, october.foliage.matrices);
    let field = CrownLight::from_leaves(&july.foliage.matrices).unwrap();
    let mut leaves: Vec<(f32, f32)> = july
        .foliage
        .matrices
        .chunks_exact(16)
        .zip(july.foliage.colors.chunks_exact(3).zip(october.foliage.colors.chunks_exact(3)))
        .map(|(m, (j, o))| {
            let centre = Vec3::new(m[12], m[13], m[14]) + 0.5 * Vec3::new(m[4], m[5], m[6]);
            // How much redder than in July, relative to green (the crown shade cancels).
            (field.sky_at(centre), (o[0] / o[1]) / (j[0] / j[1]))
        })
        .collect();
    leaves.sort_by(|a, b| a.0.total_cmp(&b.0));
    let quarter = leaves.len() / 4;
    let mean = |s: &[(f32, f32)]| s.iter().map(|l| l.1).sum::<f32>() / s.len() as f32;
    let (shaded, sunlit) = (mean(&leaves[..quarter]), mean(&leaves[leaves.len() - quarter..]));
    println!("redness gain: sunlit quarter {sunlit:.2}, shaded quarter {shaded:.2}");
    assert!(sunlit > 1.5 * shaded && shaded >= 1.0, "sunlit {sunlit}, shaded {shaded}");
}

#[test]
fn january_is_bare_but_for_the_conifers() {
    for p in PRESETS {
        let params = p.params().unwrap();
        let mut january = params.clone();
        january.foliage.season = 1.5;
        let (summer, winter) = (generate(&params).unwrap(), generate(&january).unwrap());
        println!("{}: {} leaves in July, {} in January", p.name, summer.foliage.on_tree(), winter.foliage.on_tree());
        if params.foliage.leaf_phenology == LeafPhenology::Conifer {
            assert_eq!(winter.foliage.on_tree(), summer.foliage.on_tree(), "{}", p.name);
            assert_ne!(winter.foliage.colors, summer.foliage.colors, "{}: the needles bronze", p.name);
        } else {
            assert_eq!(winter.foliage.on_tree(), 0, "{}", p.name);
            // Last autumn's leaves lie on the ground (the leaf mesh draws them), and only there.
            assert!(
                winter.foliage.fallen > summer.foliage.on_tree() / 2,
                "{}: {} fallen",
                p.name,
                winter.foliage.fallen
            );
            let ground = winter.foliage.matrices.chunks_exact(16).map(|m| m[13]).fold(0.0f32, f32::max);
            assert!(ground < 0.05, "{}: a fallen leaf at height {ground}", p.name);
            let mut no_litter = january.clone();
            no_litter.foliage.fallen_leaves = false;
            let bare = generate(&no_litter).unwrap();
            assert!(bare.foliage.count() == 0 && bare.foliage.mesh.indices.is_empty(), "{}", p.name);
        }
        // The skeleton and the bark's geometry are the summer tree's.
        assert_eq!(winter.mesh.positions, summer.mesh.positions, "{}", p.name);
    }
}

#[test]
fn spring_leaves_are_small() {
    let (july, april) = (at("oak", 7.0), at("oak", 5.0));
    let area = |g: &Generated| -> f32 {
        g.foliage
            .matrices
            .chunks_exact(16)
            .take(g.foliage.on_tree())
            .map(|m| Vec3::new(m[0], m[1], m[2]).cross(Vec3::new(m[4], m[5], m[6])).length())
            .sum()
    };
    let (a, b) = (area(&april), area(&july));
    println!(
        "oak leaf area: 1 May {a:.1}, July {b:.1}; leaves {} / {}",
        april.foliage.on_tree(),
        july.foliage.on_tree()
    );
    assert!(april.foliage.on_tree() > 0 && a < 0.6 * b, "{a} {b}");
    let before = at("oak", 3.5);
    assert_eq!(before.foliage.on_tree(), 0, "no oak leaf is out in mid-March");
}

#[test]
fn the_season_never_changes_the_default_with_other_species() {
    // At the default Season the phenology only names a calendar: the tree is the same.
    let base = generate(&TreeParams::default()).unwrap();
    let mut p = TreeParams::default();
    p.foliage.leaf_phenology = LeafPhenology::Maple;
    assert_eq!(generate(&p).unwrap().hash, base.hash);
}
