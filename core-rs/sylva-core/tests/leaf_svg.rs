//! The leaf's SVG drawing (issue 4): well-formed XML for every preset and step, the
//! triangulation toggle, auxin sources, and the vein graph replayed step by step.

use sylva_core::leaf::presets::{find, LEAF_PRESETS};
use sylva_core::leaf::svg::{render, SvgOptions};
use sylva_core::leaf::Leaf;
use sylva_core::TreeParams;

/// The leaf of tree parameters `p`: its leaf parameters and Petiole Length.
fn generate(p: &TreeParams) -> Result<Leaf, sylva_core::SylvaError> {
    sylva_core::leaf::generate(&p.leaf, p.foliage.leaf_petiole)
}

/// A strict little XML check: balanced tags, quoted attributes, escaped text, finite numbers.
/// Returns the element names in document order.
fn well_formed(svg: &str) -> Result<Vec<String>, String> {
    let body = svg.strip_prefix(r#"<?xml version="1.0" encoding="UTF-8"?>"#).ok_or("no XML declaration")?;
    let mut stack: Vec<String> = Vec::new();
    let mut names = Vec::new();
    let mut rest = body;
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        if text.contains('>') || text.contains('&') && !text.contains("&amp;") {
            return Err(format!("unescaped text {text:?}"));
        }
        let close = rest[open..].find('>').ok_or("unclosed tag")? + open;
        let tag = &rest[open + 1..close];
        rest = &rest[close + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            let top = stack.pop().ok_or(format!("</{name}> without an opening tag"))?;
            if top != name {
                return Err(format!("</{name}> closes <{top}>"));
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let tag = tag.trim_end_matches('/');
        let (name, mut attrs) = tag.split_once(' ').unwrap_or((tag, ""));
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric()) {
            return Err(format!("bad element name {name:?}"));
        }
        while !attrs.trim().is_empty() {
            let a = attrs.trim_start();
            let eq = a.find("=\"").ok_or(format!("attribute without a quoted value in <{name}>"))?;
            let key = &a[..eq];
            if key.is_empty() || !key.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == ':') {
                return Err(format!("bad attribute name {key:?}"));
            }
            let end = a[eq + 2..].find('"').ok_or("unterminated attribute")? + eq + 2;
            let value = &a[eq + 2..end];
            if value.contains('<') || value.contains("NaN") || value.contains("inf") {
                return Err(format!("bad value {key}={value:?}"));
            }
            attrs = &a[end + 1..];
        }
        names.push(name.to_string());
        if !self_closing {
            stack.push(name.to_string());
        }
    }
    if !stack.is_empty() || !rest.trim().is_empty() {
        return Err(format!("unclosed elements {stack:?}"));
    }
    if names.first().map(String::as_str) != Some("svg") {
        return Err("the root is not <svg>".into());
    }
    Ok(names)
}

fn leaf(name: &str) -> Leaf {
    generate(&find(name).unwrap().params().unwrap()).unwrap()
}

#[test]
fn svg_is_well_formed_for_every_preset_and_step() {
    for preset in LEAF_PRESETS {
        let l = generate(&preset.params().unwrap()).unwrap();
        for triangulation in [false, true] {
            for step in [Some(0), Some(l.veins.graph.iterations / 2), None] {
                let svg = render(&l, &SvgOptions { triangulation, step, ..SvgOptions::default() });
                well_formed(&svg).unwrap_or_else(|e| panic!("{} step {step:?}: {e}", preset.name));
            }
        }
    }
}

#[test]
fn svg_draws_outline_triangulation_auxins_and_veins() {
    let l = leaf("superformula_maple");
    let plain = render(&l, &SvgOptions::default());
    let names = well_formed(&plain).unwrap();
    let count = |n: &str, names: &[String]| names.iter().filter(|x| x.as_str() == n).count();
    assert_eq!(count("circle", &names), l.veins.auxins.len(), "one dot per auxin source");
    let g = &l.veins.graph;
    assert_eq!(count("line", &names), g.nodes.len() - 1 + g.links.len(), "every vein segment and loop link");
    let with_tri = render(&l, &SvgOptions { triangulation: true, ..SvgOptions::default() });
    let zs = with_tri.matches(" Z").count() - plain.matches(" Z").count();
    assert_eq!(zs, l.triangulation.triangles.len(), "the toggle draws every triangle");
    assert!(plain.contains("stroke-dasharray"), "the margin-free outline is drawn dashed under the lobes");
}

#[test]
fn svg_replays_the_growth_step_by_step() {
    let l = leaf("superformula_oak");
    let lines = |step: u32| {
        let svg = render(&l, &SvgOptions { step: Some(step), ..SvgOptions::default() });
        well_formed(&svg).unwrap().iter().filter(|n| n.as_str() == "line").count()
    };
    let it = l.veins.graph.iterations;
    let counts: Vec<usize> = (0..=it).step_by((it as usize / 8).max(1)).map(lines).collect();
    assert_eq!(counts[0], 0, "step 0 draws no vein");
    assert!(counts.windows(2).all(|w| w[0] < w[1]), "more veins after every later step: {counts:?}");
    assert_eq!(lines(it), l.veins.graph.nodes.len() - 1);
    let alive_dots =
        |step: u32| render(&l, &SvgOptions { step: Some(step), ..SvgOptions::default() }).matches("#e07b39").count();
    assert!(alive_dots(0) > alive_dots(it / 2) && alive_dots(it / 2) > alive_dots(it), "sources are consumed");
}
