//! The growth animation (`export::glb::write_growth`, docs/formats.md "Growth animation"): one
//! animation from year 0 to the Age over morph targets at the key years, the morphed tree
//! matching the trees generated at those Ages (stem counts, heights), collapsed to the trunk
//! base at year 0, the tree as built at the Age, bounds growing key by key; and the zip of one
//! GLB per year.

use super::*;
use glam::Vec3;
use sylva_core::export::glb::write_growth;
use sylva_core::export::growth::key_years;
use sylva_core::export::growth::life::Lives;
use sylva_core::export::growth::morph::{bark_places, bark_target, StemIndex, YearShape};
use sylva_core::export::growth::years::{growth_years, years_zip};
use sylva_core::params::GrowthMode;

fn params(name: &str, age: Option<f32>) -> TreeParams {
    let mut p = presets::find(name).expect("preset").params().expect("params");
    if let Some(a) = age {
        p.skeleton.age = a;
    }
    p
}

/// Positions (3 floats each) of a POSITION accessor, flattened.
fn flat(glb: &Glb, acc: u64) -> Vec<f32> {
    glb.floats(acc).concat()
}

/// The bounds of `base + delta`.
fn morphed(base: &[f32], delta: &[f32]) -> (Vec3, Vec3) {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for (p, d) in base.chunks_exact(3).zip(delta.chunks_exact(3)) {
        let q = Vec3::from_slice(p) + Vec3::from_slice(d);
        (lo, hi) = (lo.min(q), hi.max(q));
    }
    (lo, hi)
}

#[test]
fn the_growth_glb_plays_year_0_to_the_age_over_one_target_per_key_year() {
    for (name, age) in [("default", None), ("grown_broadleaf", None), ("default", Some(25.0))] {
        let p = params(name, age);
        let (age, mature) = (p.skeleton.age, p.skeleton.maturity);
        let g = generate(&p).unwrap();
        let bytes = write_growth(&g, &ExportOptions::default(), age, mature);
        assert!(bytes == write_growth(&g, &ExportOptions::default(), age, mature), "deterministic");
        let glb = parse(&bytes);
        glb.check_layout();
        let label = format!("{name} at {age}");
        assert!(glb.node("leaves").unwrap().get("extensions").is_none(), "{label}: baked leaves");
        let years = key_years(age, mature, false);
        assert_eq!((years[0], *years.last().unwrap()), (0.0, age), "{label}");
        let targets = years.len() - 1;
        assert!((7..=9).contains(&targets), "{label}: {years:?}");
        // One animation: the key years in seconds, one weight per target per key.
        let anims = glb.json["animations"].as_array().unwrap();
        assert_eq!(anims.len(), 1);
        let s = &anims[0]["samplers"][0];
        assert_eq!(s["interpolation"], "LINEAR");
        let input = flat(&glb, s["input"].as_u64().unwrap());
        assert_eq!(input, years, "{label}: times are the key years");
        assert_eq!(glb.accessor(s["input"].as_u64().unwrap())["max"][0].as_f64(), Some(f64::from(age)));
        let w = flat(&glb, s["output"].as_u64().unwrap());
        assert_eq!(w.len(), years.len() * targets);
        for (k, row) in w.chunks_exact(targets).enumerate() {
            let expect: Vec<f32> = (0..targets).map(|j| if j == k { 1.0 } else { 0.0 }).collect();
            assert_eq!(row, expect, "{label}: weights at key {k}");
        }
        let channels = anims[0]["channels"].as_array().unwrap();
        let animated: Vec<&str> = channels
            .iter()
            .map(|c| {
                assert_eq!(c["target"]["path"], "weights");
                glb.json["nodes"][c["target"]["node"].as_u64().unwrap() as usize]["name"].as_str().unwrap()
            })
            .collect();
        assert_eq!(animated, ["bark", "leaves"], "{label}");
        for node in ["bark", "leaves"] {
            let mesh = glb.mesh_of(node);
            assert_eq!(mesh["weights"].as_array().unwrap().len(), targets, "{label} {node}");
            assert_eq!(mesh["extras"]["targetNames"][0], "year 0");
            let prims = mesh["primitives"].as_array().unwrap();
            let base = flat(&glb, prims[0]["attributes"]["POSITION"].as_u64().unwrap());
            let mut last: Option<(Vec3, Vec3)> = None;
            let mut shown = 0;
            for (k, t) in prims[0]["targets"].as_array().unwrap().iter().enumerate() {
                assert!(prims.iter().all(|q| q["targets"][k] == *t), "{label} {node}: primitives share targets");
                let delta = flat(&glb, t["POSITION"].as_u64().unwrap());
                assert_eq!(delta.len(), base.len(), "{label} {node}: a delta per vertex");
                let b = morphed(&base, &delta);
                if k == 0 {
                    // Year 0: nothing but the seed, at the trunk's base.
                    let trunk = g.skeleton.stems[0].base();
                    assert!((b.1 - b.0).max_element() < 1e-3, "{label} {node}: year 0 spans {:?}", b);
                    assert!(b.0.distance(trunk) < 1e-3, "{label} {node}");
                }
                // Leaves only appear: as many or more in place (no delta) every key.
                let now = delta.chunks_exact(3).filter(|d| d.iter().all(|&x| x == 0.0)).count();
                assert!(now >= shown, "{label} {node}: {now} vertices in place in year {}, {shown} before", years[k]);
                shown = now;
                if let Some(prev) = last.filter(|_| node == "bark") {
                    let grew = (b.0.cmple(prev.0 + 0.01)).all() && (b.1.cmpge(prev.1 - 0.01)).all();
                    assert!(grew, "{label} {node}: year {} {b:?} within year {} {prev:?}", years[k], years[k - 1]);
                }
                last = Some(b);
            }
            let all = morphed(&base, &vec![0.0; base.len()]);
            let prev = last.unwrap();
            assert!((all.0.cmple(prev.0 + 0.01)).all() && (all.1.cmpge(prev.1 - 0.01)).all(), "{label} {node}");
            assert!(shown < base.len() / 3, "{label} {node}: young leaves are hidden");
        }
    }
}

#[test]
fn the_morphed_tree_is_the_tree_generated_at_each_key_year() {
    for (name, age) in [("default", None), ("grown_broadleaf", None), ("default", Some(25.0))] {
        let p = params(name, age);
        let (age, mature) = (p.skeleton.age, p.skeleton.maturity);
        let g = generate(&p).unwrap();
        let sk = &g.skeleton;
        let lives = Lives::new(sk, age, mature);
        let index = StemIndex::new(sk);
        let places = bark_places(&g.mesh, &index);
        // At its Age the tree is itself: every stem there at its length, every vertex in place.
        let now = YearShape::new(sk, &lives, age);
        assert_eq!(now.stems(), sk.stems.len(), "{name} at {age}");
        let still = bark_target(&g.mesh, &places, &now);
        let moved = still.iter().fold(0.0f32, |m, d| m.max(d.abs()));
        assert!(moved < 1e-4, "{name} at {age}: a vertex moves {moved} m at the Age");
        for &y in key_years(age, mature, false).iter().filter(|&&y| y >= 1.0 && y < age) {
            let shape = YearShape::new(sk, &lives, y);
            let mut q = p.clone();
            q.skeleton.age = y;
            let cold = generate(&q).unwrap();
            // The same stems as the replay at Age y (a tree built young is reconstructed to a
            // few float roundings: a stem or two may sit on the edge of being born).
            let (n, m) = (shape.stems() as i64, cold.skeleton.stems.len() as i64);
            // A grown tree's stems are the chains of its nodes by their tips: a younger tree's
            // nodes chain a little differently, so its count of stems differs a little.
            let slack = if sk.mode == GrowthMode::SpaceColonization {
                2 + m / 8
            } else if age < mature {
                2 + m / 200
            } else {
                0
            };
            assert!((n - m).abs() <= slack, "{name} at {age}, year {y}: {n} stems vs {m}");
            let (lo, hi) = morphed(&g.mesh.positions, &bark_target(&g.mesh, &places, &shape));
            let (clo, chi) = (Vec3::from(cold.bounds.min), Vec3::from(cold.bounds.max));
            let size = (chi - clo).max_element();
            let off = (lo - clo).abs().max((hi - chi).abs()).max_element();
            // A grown tree grows by whole internodes a flush, its morph evenly along each stem.
            let step = if sk.mode == GrowthMode::SpaceColonization { p.skeleton.internode } else { 0.02 };
            assert!(off < 0.03 * size + step, "{name} at {age}, year {y}: bounds {lo}..{hi} vs {clo}..{chi}");
        }
    }
}

/// The mean of the bark's `base + delta` heights, and the largest distance from the trunk's
/// axis of the bark within 0.3 m of the ground (the trunk's base radius, with its flare).
fn height_and_foot(base: &[f32], delta: &[f32]) -> (f32, f32) {
    let (mut sum, mut foot) = (0.0f64, 0.0f32);
    for (p, d) in base.chunks_exact(3).zip(delta.chunks_exact(3)) {
        let q = Vec3::from_slice(p) + Vec3::from_slice(d);
        sum += f64::from(q.y);
        if Vec3::from_slice(p).y < 0.3 {
            foot = foot.max(Vec3::new(q.x, 0.0, q.z).length());
        }
    }
    ((sum / (base.len() / 3) as f64) as f32, foot)
}

#[test]
fn an_old_tree_plays_its_life_past_the_mature_age() {
    // The oak (Mature Age 100) at 160: sixty years of rings, shedding and drooping, played
    // between key years 100, 115, 130 and 145 and the tree as built at 160.
    let p = params("oak", Some(160.0));
    let g = generate(&p).unwrap();
    let glb = parse(&write_growth(&g, &ExportOptions::default(), 160.0, 100.0));
    glb.check_layout();
    let years = key_years(160.0, 100.0, true);
    assert_eq!(years[years.len() - 5..], [100.0, 115.0, 130.0, 145.0, 160.0]);
    let s = &glb.json["animations"][0]["samplers"][0];
    assert_eq!(flat(&glb, s["input"].as_u64().unwrap()), years);
    let mesh = glb.mesh_of("bark");
    let prim = &mesh["primitives"][0];
    let base = flat(&glb, prim["attributes"]["POSITION"].as_u64().unwrap());
    let targets: Vec<Vec<f32>> =
        prim["targets"].as_array().unwrap().iter().map(|t| flat(&glb, t["POSITION"].as_u64().unwrap())).collect();
    assert_eq!(targets.len(), years.len() - 1);
    let at = |y: f32| years.iter().position(|&k| k == y).unwrap();
    let mut shapes: Vec<(f32, f32)> =
        [100.0, 115.0, 130.0, 145.0].iter().map(|&y| height_and_foot(&base, &targets[at(y)])).collect();
    shapes.push(height_and_foot(&base, &vec![0.0; base.len()]));
    println!("oak 100 → 160: (mean bark height, trunk foot radius) {shapes:?}");
    for w in shapes.windows(2) {
        // The limbs sink year by year and the trunk thickens.
        assert!(w[1].0 < w[0].0, "the bark rises from one key to the next: {shapes:?}");
        assert!(w[1].1 > w[0].1, "the trunk thins: {shapes:?}");
    }
    // Sixty rings of 3 mm: the trunk's base radius is 18 cm more at 160 than at 100, and its
    // flared foot grows in the same proportion.
    let r = g.skeleton.stems[0].radius;
    let (grew, expect) = (shapes[4].1 / shapes[0].1, r / (r - 0.18));
    assert!((grew / expect - 1.0).abs() < 0.05, "the trunk's foot grew {grew}x, its base radius {expect}x");
    // At the Mature Age the morphed tree is the tree generated at that Age, but for the branches
    // it sheds later (stubs already): its bounds within a few per cent.
    let cold = generate(&params("oak", Some(100.0))).unwrap();
    let (lo, hi) = morphed(&base, &targets[at(100.0)]);
    let (clo, chi) = (Vec3::from(cold.bounds.min), Vec3::from(cold.bounds.max));
    let off = (lo - clo).abs().max((hi - chi).abs()).max_element();
    assert!(off < 0.05 * (chi - clo).max_element(), "year 100: {lo}..{hi} vs {clo}..{chi}");
}

#[test]
fn the_year_zip_holds_the_tree_of_every_year() {
    let mut p = params("default", Some(3.0));
    p.set("levels", 2.0).unwrap();
    let opts = ExportOptions { textures: false, ..ExportOptions::default() };
    let zip = years_zip(&p, &opts).unwrap();
    assert_eq!(growth_years(3.0), [1.0, 2.0, 3.0]);
    // The central directory: one entry per year, in order, each the GLB of that year's tree.
    let end = zip.len() - 22;
    assert_eq!(u32_at(&zip, end), 0x0605_4b50);
    let count = u16::from_le_bytes([zip[end + 10], zip[end + 11]]) as usize;
    assert_eq!(count, 3);
    let mut at = u32_at(&zip, end + 16) as usize;
    for year in 1..=3u32 {
        assert_eq!(u32_at(&zip, at), 0x0201_4b50);
        let method = u16::from_le_bytes([zip[at + 10], zip[at + 11]]);
        let (packed, size) = (u32_at(&zip, at + 20) as usize, u32_at(&zip, at + 24) as usize);
        let name_len = u16::from_le_bytes([zip[at + 28], zip[at + 29]]) as usize;
        let name = std::str::from_utf8(&zip[at + 46..at + 46 + name_len]).unwrap();
        assert_eq!(name, format!("year_{year:03}.glb"));
        let local = u32_at(&zip, at + 42) as usize;
        let local_name = u16::from_le_bytes([zip[local + 26], zip[local + 27]]) as usize;
        let body = &zip[local + 30 + local_name..][..packed];
        let data = if method == 8 { miniz_oxide::inflate::decompress_to_vec(body).unwrap() } else { body.to_vec() };
        assert_eq!(data.len(), size);
        let mut q = p.clone();
        q.skeleton.age = year as f32;
        assert!(data == export::to_glb(&generate(&q).unwrap(), &opts), "year {year}");
        at += 46 + name_len;
    }
}
