use super::*;

const SIZE: usize = 512;

/// The texel of `t` at polar disc coordinates `(ρ, θ)` (stem radii, radians), row-major RGBA.
fn texel(t: &Texture, rho: f32, theta: f32) -> [u8; 4] {
    let s = t.size as f32;
    let to = |c: f32| ((0.5 + c * UV_RADIUS) * s).floor().clamp(0.0, s - 1.0) as usize;
    let (x, y) = (to(rho * crate::math::cos(theta)), to(rho * sin(theta)));
    let i = (y * t.size + x) * 4;
    [t.rgba[i], t.rgba[i + 1], t.rgba[i + 2], t.rgba[i + 3]]
}

fn lum(p: [u8; 4]) -> f32 {
    0.3 * f32::from(p[0]) + 0.59 * f32::from(p[1]) + 0.11 * f32::from(p[2])
}

/// Mean luminance of the wood between radii `a` and `b` (stem radii).
fn mean_lum(t: &Texture, a: f32, b: f32) -> f32 {
    let mut sum = (0.0, 0);
    for i in 0..64 {
        for k in 0..32 {
            let rho = a + (b - a) * k as f32 / 31.0;
            sum.0 += lum(texel(t, rho, TAU * i as f32 / 64.0));
            sum.1 += 1;
        }
    }
    sum.0 / sum.1 as f32
}

#[test]
fn maps_are_deterministic_and_normals_unit() {
    for &kind in BarkType::ALL {
        let m = bake(kind, 64);
        assert_eq!(bake(kind, 64), m, "{kind:?}");
        assert_eq!((m.color.size, m.color.rgba.len(), m.normal.rgba.len()), (64, 64 * 64 * 4, 64 * 64 * 4));
        for px in m.normal.rgba.chunks_exact(4) {
            let v: Vec<f32> = px[..3].iter().map(|&b| b as f32 / 255.0 * 2.0 - 1.0).collect();
            let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            assert!((len - 1.0).abs() < 0.02 && v[2] > 0.2, "{kind:?} {len} {v:?}");
        }
    }
    // Power of two, at least 16.
    assert_eq!(bake(BarkType::Plated, 20).color.size, 32);
    assert_eq!(bake(BarkType::Plated, 1).normal.size, 16);
}

#[test]
fn alpha_is_the_disc() {
    let m = bake(BarkType::Furrowed, SIZE);
    let t = &m.color;
    for i in 0..256 {
        let theta = TAU * i as f32 / 256.0;
        for rho in [0.0, 0.3, 0.8, 0.92, 0.99] {
            assert_eq!(texel(t, rho, theta)[3], 255, "inside at {rho} {theta}");
        }
        assert_eq!(texel(t, 1.01, theta)[3], 0, "outside at {theta}");
    }
    // The corners are outside, their colour the outer bark's (no black bleeding into the rim).
    for (x, y) in [(0, 0), (SIZE - 1, 0), (0, SIZE - 1), (SIZE - 1, SIZE - 1)] {
        let p = &t.rgba[(y * SIZE + x) * 4..][..4];
        assert_eq!(p[3], 0);
        let edge = texel(t, 0.99, atan2(y as f32 - 255.5, x as f32 - 255.5));
        assert!(p[..3].iter().zip(&edge[..3]).all(|(a, b)| a.abs_diff(*b) < 40), "{p:?} vs {edge:?}");
    }
}

#[test]
fn pith_heartwood_sapwood_and_bark_differ() {
    for &kind in BarkType::ALL {
        let m = bake(kind, SIZE);
        let pith = lum(texel(&m.color, 0.0, 0.0));
        let (heart, sap) = (mean_lum(&m.color, 0.08, 0.3), mean_lum(&m.color, 0.62, 0.76));
        let bark = mean_lum(&m.color, 0.885, 0.92);
        assert!(pith < 0.8 * heart, "{kind:?}: the pith is dark ({pith} vs rings {heart})");
        assert!(sap > heart + 4.0, "{kind:?}: sapwood lighter than heartwood ({sap} vs {heart})");
        assert!(bark < 0.8 * sap, "{kind:?}: the outer bark band is dark ({bark} vs {sap})");
        // The relief: the pith sunken below the wood.
        let h = |rho, theta| f32::from(texel(&m.normal, rho, theta)[3]);
        assert!(h(0.0, 0.0) + 20.0 < h(0.5, 1.0).max(h(0.5, 2.0)), "{kind:?}");
    }
}

/// Sharp rises of luminance along a radius from `a` to `b`: each ring's latewood ends abruptly
/// in the next ring's pale earlywood.
fn ring_transitions(t: &Texture, theta: f32, a: f32, b: f32, step: u8) -> usize {
    let n = ((b - a) * UV_RADIUS * t.size as f32) as usize;
    let profile: Vec<f32> = (0..=n).map(|k| lum(texel(t, a + (b - a) * k as f32 / n as f32, theta))).collect();
    let mut count = 0;
    let mut k = 0;
    while k + 3 < profile.len() {
        if profile[k + 3] - profile[k] > f32::from(step) {
            count += 1;
            k += 4;
        } else {
            k += 1;
        }
    }
    count
}

#[test]
fn rings_alternate_along_every_radius() {
    for &kind in BarkType::ALL {
        let m = bake(kind, SIZE);
        let rings = kind.wood().rings as usize;
        let step = if kind == BarkType::SmoothBanded { 6 } else { 12 };
        for i in 0..12 {
            // Between the checks: sample on directions off the cracks, away from the pith.
            let theta = TAU * (i as f32 + 0.5) / 12.0;
            let n = ring_transitions(&m.color, theta, 0.06, CAMBIUM - 0.01, step);
            assert!(n >= rings * 2 / 3 && n <= rings + 4, "{kind:?} at {theta}: {n} ring edges ({rings} rings)");
        }
    }
}

#[test]
fn rings_are_irregular_and_not_circles() {
    let bounds = ring_bounds(&BarkType::Plated.wood(), 3);
    let widths: Vec<f32> = bounds.windows(2).map(|w| w[1] - w[0]).collect();
    let (lo, hi) = widths.iter().fold((f32::MAX, 0.0f32), |(a, b), &w| (a.min(w), b.max(w)));
    assert!(hi > 2.0 * lo, "ring widths vary: {lo}..{hi}");
    assert!((bounds[widths.len()] - CAMBIUM).abs() < 1e-6 && bounds[0] == 0.0);
    // The same ring edge lies at different radii in different directions.
    let m = bake(BarkType::Plated, SIZE);
    let first_edge = |theta: f32| {
        let n = 200;
        (1..n)
            .map(|k| 0.2 + 0.4 * k as f32 / n as f32)
            .find(|&r| lum(texel(&m.color, r + 0.006, theta)) - lum(texel(&m.color, r - 0.006, theta)) > 15.0)
            .unwrap_or(0.0)
    };
    let edges: Vec<f32> = (0..16).map(|i| first_edge(TAU * (i as f32 + 0.5) / 16.0)).collect();
    let spread = edges.iter().fold(0.0f32, |a, &b| a.max(b)) - edges.iter().fold(1.0f32, |a, &b| a.min(b));
    assert!(spread > 0.01, "wobbly rings: {edges:?}");
}

#[test]
fn radial_checks_run_from_the_pith() {
    for &kind in BarkType::ALL {
        let m = bake(kind, SIZE);
        // Around a circle at 0.12 radii: runs of deep texels, one per check crossing it.
        let deep: Vec<bool> = (0..720).map(|i| texel(&m.normal, 0.12, TAU * i as f32 / 720.0)[3] < 60).collect();
        let runs = (0..720).filter(|&i| deep[i] && !deep[(i + 719) % 720]).count();
        assert!((3..=5).contains(&runs), "{kind:?}: {runs} checks");
        // None reaches the cambium.
        let outer = (0..720).filter(|&i| texel(&m.normal, 0.75, TAU * i as f32 / 720.0)[3] < 60).count();
        assert_eq!(outer, 0, "{kind:?}");
    }
}

#[test]
fn bark_types_have_their_own_wood() {
    let maps: Vec<EndGrainMaps> = BarkType::ALL.iter().map(|&k| bake(k, 128)).collect();
    for i in 0..maps.len() {
        for j in 0..i {
            assert_ne!(maps[i].color, maps[j].color);
            assert_ne!(maps[i].normal, maps[j].normal);
        }
    }
    let mean = |k: BarkType, c: usize| {
        let t = &maps[k as usize].color;
        let inner: Vec<f32> = (0..64).map(|i| f32::from(texel(t, 0.4, TAU * i as f32 / 64.0)[c])).collect();
        inner.iter().sum::<f32>() / 64.0
    };
    let l = |k| 0.3 * mean(k, 0) + 0.59 * mean(k, 1) + 0.11 * mean(k, 2);
    // Birch is the palest wood; pine's heartwood is redder than birch's.
    for k in [BarkType::Furrowed, BarkType::Plated, BarkType::Fibrous] {
        assert!(l(BarkType::SmoothBanded) > l(k) + 10.0, "{k:?}");
    }
    let red = |k| mean(k, 0) / mean(k, 2);
    assert!(red(BarkType::Plated) > 1.2 * red(BarkType::SmoothBanded));
}

#[test]
fn bytes_are_colour_then_normal() {
    let m = bake(BarkType::Fibrous, 32);
    let b = m.to_bytes();
    assert_eq!(b.len(), 8 * 32 * 32);
    assert_eq!((&b[..4 * 32 * 32], &b[4 * 32 * 32..]), (&m.color.rgba[..], &m.normal.rgba[..]));
}

/// The maps the viewer and the exports show, pinned byte for byte at the viewer's size (a change
/// of the bake's speed must not change a texel; a change of its look updates these on purpose).
#[test]
fn the_maps_keep_their_bytes() {
    let pinned = [
        (BarkType::Furrowed, 0x0df8_8e20_cdd6_baeb),
        (BarkType::Plated, 0x6e1f_4f41_98bf_7b15),
        (BarkType::SmoothBanded, 0xd6d3_5b16_7e1c_ace6),
        (BarkType::Fibrous, 0x5f0c_fb95_7cc7_58e5),
    ];
    for (kind, hash) in pinned {
        assert_eq!(super::super::fnv64(&bake(kind, SIZE).to_bytes()), hash, "{kind:?}");
    }
}

/// [`CHECK_FAR`]: no check is wider than its bound, and a point that far from a check (or
/// farther) gets no crack from it, exactly, so the bake may leave its term out.
#[test]
fn a_check_is_never_wider_than_its_far_bound() {
    let mut widest = 0.0f32;
    for k in 0..=1_000_000 {
        let r = k as f32 / 1e6;
        widest = widest.max(0.02 * pow(r, 0.4) * pow(1.0 - r, 1.2));
    }
    assert!(widest > 0.0081 && widest < 0.00814, "{widest}");
    assert_eq!(1.0 - smoothstep(0.6, 1.0, CHECK_FAR / (widest * 1.001)), 0.0);
}
