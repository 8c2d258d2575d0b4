//! Standing rule 5 as a test: outside test modules, the core never calls the platform's float
//! functions (`x.sin()`, `x.powf(y)`, ...), which differ between glibc and wasm in the last bit.
//! Everything transcendental goes through `sylva_core::math` (libm), glam's rotations included,
//! so buffers stay byte-identical on every target.

use std::path::Path;

const FORBIDDEN: [&str; 27] = [
    ".powf(",
    ".powi(",
    ".sin(",
    ".cos(",
    ".tan(",
    ".exp(",
    ".exp2(",
    ".ln(",
    ".log(",
    ".log2(",
    ".log10(",
    ".atan2(",
    ".acos(",
    ".asin(",
    ".atan(",
    ".sinh(",
    ".cosh(",
    ".hypot(",
    ".cbrt(",
    ".sin_cos(",
    // glam's rotations take their sines from the platform (glam is built without libm).
    "from_rotation_x(",
    "from_rotation_y(",
    "from_rotation_z(",
    "from_axis_angle(",
    "from_scaled_axis(",
    ".slerp(",
    "from_euler(",
];

fn visit(dir: &Path, hits: &mut Vec<String>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            visit(&path, hits);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).unwrap();
            // Test modules sit at the end of a file: check only what comes before them.
            let code = text.split("#[cfg(test)]").next().unwrap_or("");
            for (n, line) in code.lines().enumerate() {
                let line = line.split("//").next().unwrap_or("");
                for f in FORBIDDEN {
                    if line.contains(f) {
                        hits.push(format!("{}:{}: {}", path.display(), n + 1, line.trim()));
                    }
                }
            }
        }
    }
}

#[test]
fn no_platform_float_functions_in_the_core() {
    let mut hits = Vec::new();
    visit(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut hits);
    assert!(hits.is_empty(), "use sylva_core::math (libm) instead:\n{}", hits.join("\n"));
}

#[test]
fn plain_max_min_and_round_give_the_std_values() {
    // `math::max`, `min` and `round` are the forms wasm runs as instructions (std's are calls to
    // fmaxf, fminf and roundf there): the same values as std's, max and min for every pair
    // without NaN, round for every float (bit for bit, signed zeros included).
    use sylva_core::math;
    let mut vals = vec![
        0.0,
        -0.0,
        0.5,
        -0.5,
        1.5,
        -2.5,
        0.499_999_97,
        -0.499_999_97,
        8_388_607.5,
        -8_388_609.0,
        f32::MAX,
        f32::MIN,
        f32::MIN_POSITIVE,
        1e-45,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
    ];
    let mut x = 0x1234_5678u32;
    for _ in 0..200_000 {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        vals.push(f32::from_bits(x));
        vals.push(f32::from_bits(x) * 1e-30); // more values near the halfway points
    }
    for &a in &vals {
        let (ours, std) = (math::round(a), a.round());
        assert!(ours.to_bits() == std.to_bits() || (ours.is_nan() && std.is_nan()), "round({a:e})");
    }
    for w in vals.windows(2) {
        let (a, b) = (w[0], w[1]);
        if !a.is_nan() && !b.is_nan() {
            assert_eq!(math::max(a, b), a.max(b), "max({a:e}, {b:e})");
            assert_eq!(math::min(a, b), a.min(b), "min({a:e}, {b:e})");
        }
    }
}

/// Rotations of `sylva_core::math` at 20,000 pseudo-random angles, axes and blends: a hash of
/// their bits.
fn rotations_hash() -> u64 {
    use glam::{Quat, Vec3};
    use sylva_core::math;
    let mut x = 0x9e37_79b9u32;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        (x as f32 / u32::MAX as f32 - 0.5) * 10f32.powi((x % 5) as i32 - 2)
    };
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    let mut eat = |q: Quat| {
        for v in q.to_array() {
            h = (h ^ u64::from(v.to_bits())).wrapping_mul(0x0100_0000_01b3);
        }
    };
    for _ in 0..20_000 {
        let a = next();
        let axis = Vec3::new(next(), next(), next()).normalize_or(Vec3::X);
        let (rx, ry, ra) = (math::quat_rotation_x(a), math::quat_rotation_y(a), math::quat_axis_angle(axis, a));
        let t = next().abs().fract();
        let (from, to) = (Quat::IDENTITY, (ra * rx).normalize());
        let (s1, s2) = (math::slerp(from, to, t), math::slerp(rx, -ry, t));
        for q in [rx, ry, ra, s1, s2] {
            eat(q);
        }
    }
    h
}

#[test]
fn rotations_keep_the_values_glam_gave_with_libm() {
    // glam is built without its `libm` feature (its square roots and roundings are then the
    // instructions, in wasm too), so its rotations would take their sines from the platform.
    // `math`'s rotations are glam's formulas with libm's sines: this hash pins them to the
    // values glam gave when it was built with libm (measured then, when each of them was also
    // compared with glam's own bit for bit).
    assert_eq!(rotations_hash(), 0xf521_3c3b_5564_1de0);
}
