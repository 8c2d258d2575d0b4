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
