//! Flowers, fruit, catkins, buds and fallen leaves through the Season (`organs/`, `season.rs`):
//! the cherry blossoms in April, an oak has acorns in September, parts hang from their twigs and
//! keep their places from flower to fruit, bare trees carry buds and lie on their own leaves.

#![allow(clippy::disallowed_methods, reason = "the tests' own geometry measures, not output bytes")]

use glam::Vec3;
use sylva_core::organs::{OrganKind, OrganSet};
use sylva_core::params::Fruit;
use sylva_core::presets::PRESETS;
use sylva_core::skeleton::Skeleton;
use sylva_core::{generate, Generated, TreeParams};

fn params(preset: &str, month: f32) -> TreeParams {
    let mut p = sylva_core::presets::find(preset).unwrap().params().unwrap();
    p.foliage.season = month;
    p
}

fn at(preset: &str, month: f32) -> Generated {
    generate(&params(preset, month)).unwrap()
}

fn set<'a>(g: &'a Generated, name: &str) -> Option<&'a OrganSet> {
    g.foliage.organs.iter().find(|s| s.name == name)
}

fn origins(s: &OrganSet) -> Vec<Vec3> {
    s.matrices.chunks_exact(16).map(|m| Vec3::new(m[12], m[13], m[14])).collect()
}

/// The bark as points: each stem's smooth centre curve (the one the mesh follows) every 4 mm,
/// with its radius there.
fn bark_samples(skeleton: &Skeleton) -> Vec<(Vec3, f32)> {
    let mut out = Vec::new();
    for s in &skeleton.stems {
        let mut curve = s.points();
        let n = ((s.length / 0.004) as usize).max(8);
        out.extend((0..=n).map(|k| {
            let z = k as f32 / n as f32;
            (curve.at(z), s.radius_at(z))
        }));
    }
    out
}

/// Distance from `p` to the bark (to within 2 mm).
fn to_bark(bark: &[(Vec3, f32)], p: Vec3) -> f32 {
    bark.iter().map(|(c, r)| (*c - p).length() - r).fold(f32::MAX, f32::min)
}

#[test]
fn in_april_the_cherry_has_flowers() {
    let g = at("cherry", 4.2);
    let petals = set(&g, "cherry blossom petals").expect("blossom in April");
    let centres = set(&g, "cherry blossom centres").unwrap();
    println!("cherry in April: {} flowers, {} leaves", petals.count(), g.foliage.on_tree());
    assert!(petals.count() > 300, "{} flowers", petals.count());
    assert_eq!(centres.count(), petals.count(), "every flower has its centre");
    // White: the petals' colour is near white, and nothing else of the tree is a fruit.
    assert!(petals.color.iter().all(|&c| c > 0.85), "{:?}", petals.color);
    assert!(g.foliage.organs.iter().all(|s| s.kind != OrganKind::Fruit));
    // The blossom comes with the first small leaves, and has gone by June.
    assert!(set(&at("cherry", 6.0), "cherry blossom petals").is_none());
    // The apple blossoms later, in May.
    assert!(set(&at("apple", 4.2), "apple blossom petals").is_none_or(|s| s.count() < petals.count() / 4));
    assert!(set(&at("apple", 4.9), "apple blossom petals").is_some_and(|s| s.count() > 300));
}

#[test]
fn an_oak_in_september_has_acorns() {
    for preset in ["oak", "ca_black_oak"] {
        let g = at(preset, 9.2);
        let acorns = set(&g, "acorns").expect("acorns in September");
        let cups = set(&g, "acorn cups").unwrap();
        println!("{preset} in September: {} acorns", acorns.count());
        assert!(acorns.count() > 100, "{preset}: {} acorns", acorns.count());
        assert_eq!(cups.matrices, acorns.matrices, "each acorn sits in its cup");
        // None in July, some dropped by late October, none by December.
        assert!(set(&at(preset, 7.0), "acorns").is_none());
        let late = at(preset, 10.6);
        assert!(set(&late, "acorns").is_some_and(|s| s.count() < acorns.count()));
        assert!(set(&at(preset, 11.5), "acorns").is_none());
    }
}

#[test]
fn fruit_hangs_from_its_twigs() {
    // Every stalk starts on the bark of a stem, and the fruit hangs at the stalk's end, below it.
    for (preset, month, stalks, fruit) in [
        ("oak", 9.2, "acorn stalks", "acorns"),
        ("cherry", 6.0, "cherry stalks", "cherries"),
        ("apple", 9.0, "apple stalks", "apples"),
    ] {
        let g = at(preset, month);
        let (s, f) = (set(&g, stalks).unwrap(), set(&g, fruit).unwrap());
        assert_eq!(s.count(), f.count());
        let bark = bark_samples(&g.skeleton);
        for (base, m) in origins(s).into_iter().zip(s.matrices.chunks_exact(16)) {
            let d = to_bark(&bark, base);
            assert!(d < 0.005, "{preset}: a stalk starts {d} m off the bark");
            // The stalk's axis (its matrix's y column) points down.
            assert!(m[5] < 0.0, "{preset}: a stalk points up");
        }
        for (tip, fruit_at) in origins(s).iter().zip(origins(f)) {
            assert!(fruit_at.y < tip.y, "{preset}: a fruit above its stalk's base");
        }
    }
}

#[test]
fn parts_keep_their_places_from_flower_to_fruit() {
    // The cherries of June hang where the blossom of April was: each cherry stalk starts where a
    // blossom stalk did.
    let (april, june) = (at("cherry", 4.2), at("cherry", 6.0));
    let flowers = origins(set(&april, "cherry blossom stalks").unwrap());
    let cherries = origins(set(&june, "cherry stalks").unwrap());
    assert!(cherries.len() > 100);
    for c in &cherries {
        assert!(flowers.iter().any(|f| (*f - *c).length() < 1e-5), "a cherry where no flower was: {c}");
    }
}

#[test]
fn the_season_is_deterministic_and_switchable() {
    let g = at("cherry", 6.0);
    assert_eq!(g.hash, at("cherry", 6.0).hash);
    let mut off = params("cherry", 6.0);
    off.foliage.organs = false;
    let bare = generate(&off).unwrap();
    assert!(bare.foliage.organs.is_empty());
    assert_ne!(bare.hash, g.hash);
    // The leaves are the same with or without the fruit.
    assert_eq!(bare.foliage.matrices, g.foliage.matrices);
    // No fruit on a tree that has none.
    let mut none = params("oak", 9.2);
    none.foliage.fruit = Fruit::None;
    assert!(generate(&none).unwrap().foliage.organs.is_empty());
}

#[test]
fn july_carries_parts_only_on_the_fruit_trees() {
    for p in PRESETS {
        let g = generate(&p.params().unwrap()).unwrap();
        let names: Vec<&str> = g.foliage.organs.iter().map(|s| s.name).collect();
        match p.name {
            "apple" => assert_eq!(names, ["apple stalks", "apples"], "young green apples in July"),
            _ => assert!(names.is_empty(), "{}: {names:?}", p.name),
        }
        assert_eq!(g.foliage.fallen, 0, "{}", p.name);
    }
}

#[test]
fn winter_buds_at_every_shoot_tip_and_catkins_where_the_species_has_them() {
    let g = at("oak", 1.5);
    let buds = set(&g, "buds").expect("buds in January");
    // A bud sits on each tip: every bud is within a centimetre of a stem's end point.
    let tips: Vec<Vec3> = g.skeleton.stems.iter().filter_map(|s| s.points.last().copied()).collect();
    for b in origins(buds) {
        assert!(tips.iter().any(|t| (*t - b).length() < 0.01), "a bud off any tip: {b}");
    }
    assert!(buds.count() > 500, "{} buds", buds.count());
    // Conifers have none; birch carries its catkins all winter, aspen in March.
    assert!(at("fir", 1.5).foliage.organs.iter().all(|s| s.name != "buds"));
    assert!(set(&at("weeping", 1.5), "birch catkins").is_some(), "a birch's winter catkins");
    assert!(set(&at("quaking_aspen", 3.3), "aspen catkins").is_some_and(|s| s.count() > 100));
    assert!(set(&at("weeping_willow", 4.0), "willow catkins").is_some());
    assert!(set(&at("quaking_aspen", 6.0), "aspen catkins").is_none());
}

#[test]
fn cones_and_samaras_in_their_months() {
    let fir = at("fir", 9.0);
    let cones = set(&fir, "fir cones").expect("fir cones in September");
    // A fir's cones stand upright on its upper branches.
    let top = fir.bounds.max[1];
    for (o, m) in origins(cones).iter().zip(cones.matrices.chunks_exact(16)) {
        assert!(m[5] > 0.0, "a fir cone hangs");
        assert!(o.y > 0.6 * top, "a cone low in the crown at {}", o.y);
    }
    let maple = at("umbrella", 9.5);
    let seeds = set(&maple, "samara seeds").unwrap();
    assert_eq!(set(&maple, "samara wings").unwrap().count(), seeds.count());
}

#[test]
fn fallen_leaves_lie_under_the_crown() {
    let (oct, nov) = (at("umbrella", 10.6), at("umbrella", 11.2));
    println!("maple: {} / {} fallen in late October / November", oct.foliage.fallen, nov.foliage.fallen);
    assert!(oct.foliage.fallen > 0 && nov.foliage.fallen > oct.foliage.fallen);
    // They lie flat on the ground (front up), under and around the crown.
    let reach = nov.bounds.max[0].max(nov.bounds.max[2]).max(-nov.bounds.min[0]).max(-nov.bounds.min[2]);
    for m in nov.foliage.matrices.chunks_exact(16).skip(nov.foliage.on_tree()) {
        let front = Vec3::new(m[8], m[9], m[10]).normalize();
        assert!(front.y > 0.99, "a fallen leaf on edge: {front}");
        assert!(m[13] < 0.02 && m[13] > 0.0, "a fallen leaf at height {}", m[13]);
        assert!(Vec3::new(m[12], 0.0, m[14]).length() < 1.5 * reach + 1.0);
    }
    // Every leaf on the tree or on the ground: as many as in July until they rot away.
    assert_eq!(nov.foliage.count(), at("umbrella", 7.0).foliage.count());
    let mut tidy = params("umbrella", 11.2);
    tidy.foliage.fallen_leaves = false;
    let g = generate(&tidy).unwrap();
    assert_eq!((g.foliage.fallen, g.foliage.count()), (0, nov.foliage.on_tree()));
}
