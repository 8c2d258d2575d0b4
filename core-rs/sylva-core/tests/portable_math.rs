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
