use super::*;

fn heights(m: &BarkMaps) -> Vec<i32> {
    m.normal.rgba.chunks_exact(4).map(|p| i32::from(p[3])).collect()
}

#[test]
fn every_type_tiles_without_a_seam() {
    // The pattern is periodic over the tile: the texel past the last one is the first again.
    for &kind in BarkType::ALL {
        for k in 0..200 {
            let t = k as f32 / 200.0;
            for (a, b) in [((0.0, t), (1.0, t)), ((t, 0.0), (t, 1.0))] {
                let (p, q) = (patterns::sample(kind, a.0, a.1, 5), patterns::sample(kind, b.0, b.1, 5));
                assert!((p.height - q.height).abs() < 2e-3, "{kind:?} at {a:?}: {} vs {}", p.height, q.height);
                assert!((p.rgb[1] - q.rgb[1]).abs() < 2e-3 && (p.rough - q.rough).abs() < 2e-3, "{kind:?} at {a:?}");
            }
        }
    }
}

#[test]
fn normals_are_unit_and_maps_deterministic() {
    for &kind in BarkType::ALL {
        let m = bake(kind, 32);
        for px in m.normal.rgba.chunks_exact(4) {
            let v: Vec<f32> = px[..3].iter().map(|&b| b as f32 / 255.0 * 2.0 - 1.0).collect();
            let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            assert!((len - 1.0).abs() < 0.02, "{kind:?} {len}");
        }
        assert_eq!(bake(kind, 32), m);
        assert!(m.orm.rgba.chunks_exact(4).all(|p| p[2] == 0 && p[3] == 255), "no metal");
    }
}

/// Mean and standard deviation of the height, and the fraction of texels rougher than 0.8.
fn stats(m: &BarkMaps) -> (f32, f32, f32) {
    let h: Vec<f32> = heights(m).iter().map(|&v| v as f32 / 255.0).collect();
    let mean = h.iter().sum::<f32>() / h.len() as f32;
    let sd = (h.iter().map(|v| (v - mean) * (v - mean)).sum::<f32>() / h.len() as f32).sqrt();
    let rough = m.orm.rgba.chunks_exact(4).filter(|p| p[1] > 204).count() as f32 / (m.orm.rgba.len() / 4) as f32;
    (mean, sd, rough)
}

#[test]
fn types_differ_as_the_species_do() {
    let [f, p, s, b] =
        [BarkType::Furrowed, BarkType::Plated, BarkType::SmoothBanded, BarkType::Fibrous].map(|k| bake(k, 128));
    for (a, b) in [(&f, &p), (&f, &s), (&f, &b), (&p, &s), (&p, &b), (&s, &b)] {
        assert_ne!(a.color, b.color);
        assert_ne!(a.normal, b.normal);
    }
    let (sf, ss, sp, sb) = (stats(&f), stats(&s), stats(&p), stats(&b));
    // Smooth-banded is smooth and shiny; the rough types have deep relief.
    assert!(ss.1 < 0.5 * sf.1.min(sp.1).min(sb.1), "relief sd: smooth {} vs {} {} {}", ss.1, sf.1, sp.1, sb.1);
    assert!(ss.2 < 0.3 && sf.2 > 0.7 && sp.2 > 0.5, "roughness: smooth {} furrowed {} plated {}", ss.2, sf.2, sp.2);
    // Smooth-banded is pale, the others dark brown-grey.
    let lum = |m: &BarkMaps| {
        m.color.rgba.chunks_exact(4).map(|p| f32::from(p[1])).sum::<f32>() / (m.color.rgba.len() / 4) as f32
    };
    let (ls, lo) = (lum(&s), lum(&f).max(lum(&p)).max(lum(&b)));
    assert!(ls > 1.35 * lo, "pale birch: {ls} vs {lo}");
}

#[test]
fn furrows_run_along_the_stem_and_plates_are_cells() {
    // Furrowed: the height changes much faster around the stem (u) than along it (v).
    let h = heights(&bake(BarkType::Furrowed, 128));
    let grad = |dx: usize, dy: usize| {
        (0..127 * 127)
            .map(|i| (h[(i / 127 + dy) * 128 + i % 127 + dx] - h[(i / 127) * 128 + i % 127]).abs())
            .sum::<i32>()
    };
    assert!(2 * grad(1, 0) > 3 * grad(0, 1), "furrows are vertical: du {} dv {}", grad(1, 0), grad(0, 1));
}

#[test]
fn pattern_grows_with_girth_and_twigs_are_young() {
    for &kind in BarkType::ALL {
        let s = kind.style();
        let tile = |r: f32| crate::math::TAU * r / s.repeats(r);
        // Tiles widen with the girth, but slower than the girth (more repeats on a thick trunk).
        assert!(tile(0.5) > 1.5 * tile(0.1) && s.repeats(0.5) > s.repeats(0.1), "{kind:?}");
        assert!(s.young_radius < 0.05 && s.young_radius > 0.005);
    }
    // Oak at 1 m girth: six ridges per tile, about 4 cm apart.
    let s = BarkType::Furrowed.style();
    let spacing = 1.0 / s.repeats(1.0 / crate::math::TAU) / 6.0;
    assert!((0.03..0.05).contains(&spacing), "{spacing}");
}

#[test]
fn bark_type_enters_the_hash() {
    let hashes: Vec<u64> = BarkType::ALL.iter().map(|&k| hash_into(k, 7)).collect();
    for i in 0..hashes.len() {
        for j in 0..i {
            assert_ne!(hashes[i], hashes[j]);
        }
    }
}

#[test]
fn plate_cracks_never_ring_the_stem() {
    // A crack running across the whole tile becomes a ring around the trunk (the tile repeats
    // around it): every row of the plated map must be mostly plate. The rows between two rows
    // of cells once were a zigzag across the full width; staggered columns break them up.
    let size = 256;
    let h = heights(&bake(BarkType::Plated, size));
    let crack_share = |y: usize| (0..size).filter(|&x| h[y * size + x] < 40).count() as f32 / size as f32;
    let worst = (0..size).map(crack_share).fold(0.0f32, f32::max);
    let mean = (0..size).map(crack_share).sum::<f32>() / size as f32;
    // Aligned rows of cells: one row 0.78 crack (mean 0.16); staggered: 0.40 (mean 0.15).
    assert!(worst < 0.5 && worst < 3.0 * mean, "a row of the plated map is {worst:.2} crack (mean {mean:.2})");
}

/// The sRGB bytes through the steps are the bytes through the power: around every step (4,096
/// floats either side), over the whole range 0..=1 (every 61st float here; every float of it
/// was compared once, in 34 s), outside it and for NaN.
#[test]
fn srgb_bytes_by_steps_are_the_bytes_by_the_power() {
    let same = |c: f32| assert_eq!(srgb8(c), srgb8_by_power(c), "{c:e} ({:#x})", c.to_bits());
    for &step in srgb_steps() {
        let bits = step.to_bits();
        for b in bits.saturating_sub(4096)..=bits + 4096 {
            same(f32::from_bits(b));
        }
    }
    for b in (0..=1.0f32.to_bits()).step_by(61) {
        same(f32::from_bits(b));
    }
    for c in [
        f32::NAN,
        -f32::NAN,
        -0.0,
        -1e-30,
        -1.0,
        1.0,
        1.000_000_1,
        2.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MIN_POSITIVE,
    ] {
        same(c);
    }
    // Every byte is some input's.
    assert!(srgb_steps().windows(2).all(|w| w[0] < w[1]));
}

/// The maps the viewer shows (256 texels square), pinned byte for byte: a faster bake must not
/// change a texel; a change of the look updates these on purpose.
#[test]
fn the_maps_keep_their_bytes() {
    let pinned = [
        (BarkType::Furrowed, 0x763b_9dae_3c89_90ab),
        (BarkType::Plated, 0x375f_5f05_e283_7ad0),
        (BarkType::SmoothBanded, 0x3db9_757f_69d9_f2de),
        (BarkType::Fibrous, 0xca58_84b5_f0c8_96bc),
    ];
    for (kind, hash) in pinned {
        let m = bake(kind, 256);
        let bytes = [&m.color.rgba[..], &m.normal.rgba[..], &m.orm.rgba[..]].concat();
        assert_eq!(fnv64(&bytes), hash, "{kind:?}");
    }
}
