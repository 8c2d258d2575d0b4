//! Standing rule 5 as a test: outside test modules, the core never calls the platform's float
//! functions (`x.sin()`, `x.powf(y)`, ...), which differ between glibc and wasm in the last bit.
//! Everything transcendental goes through `sylva_core::math` (libm), so buffers stay
//! byte-identical on every target.

use std::path::Path;

const FORBIDDEN: [&str; 20] = [
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

#[test]
fn hardware_square_roots_give_glams_values() {
    // `HwSqrt` and `normalize_or_hw` redo glam's length and normalisation with the square-root
    // instruction: bit for bit glam's results (which go through libm's software square root).
    use glam::{Quat, Vec3};
    use sylva_core::math::{normalize_or_hw, HwSqrt};
    let mut x = 0x9e37_79b9u32;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        (x as f32 / u32::MAX as f32 - 0.5) * 10f32.powi((x % 9) as i32 - 4)
    };
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    for _ in 0..50_000 {
        let v = Vec3::new(next(), next(), next());
        assert_eq!(v.length_hw().to_bits(), v.length().to_bits(), "{v}");
        assert_eq!(bits(v.normalize_hw()), bits(v.normalize()), "{v}");
        assert_eq!(bits(normalize_or_hw(v, Vec3::Y)), bits(v.normalize_or(Vec3::Y)), "{v}");
        let q = Quat::from_xyzw(next(), next(), next(), next());
        assert_eq!(q.normalize_hw().to_array().map(f32::to_bits), q.normalize().to_array().map(f32::to_bits));
    }
    assert_eq!(normalize_or_hw(Vec3::ZERO, Vec3::Y), Vec3::Y);
}
