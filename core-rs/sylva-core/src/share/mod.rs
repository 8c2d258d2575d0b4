//! Share links: a tree as the studio's address-bar query, `v=1&id=value&...&vol=...&e=...`
//! (docs/formats.md, "Share links"), for the tools that exchange trees with the studio outside
//! the browser (the Python package and the Blender add-on). The same form as the studio's codec
//! (`packages/sylva-trees/src/url/codec.ts` and `editsCodec.ts`); `tests/share_links.rs` and the
//! studio's `url/shareFixtures.test.ts` check both against the same links
//! (`tests/share_links.json`).
//!
//! [`encode`] writes the values that differ from the defaults in registry order (a float as the
//! shortest decimal of the `f32` the core stores, so the studio reads back the same value), the
//! growth primitives (`vol=`) and the hand edits (`e=`, left out past
//! [`MAX_EDITS_LINK_LENGTH`] characters, as the studio does). [`decode`] reads a link as the
//! studio does: strictly, never failing; a bad value keeps its default, with a message naming it.

mod items;

use crate::params::{registry, ParamKind, ParamSpec, TreeParams};
use items::{decode_edits, decode_volumes};
pub use items::{encode_edits, encode_volumes};

/// The format version written as `v=`.
pub const FORMAT_VERSION: &str = "1";
/// Longest query read (characters, without `?`), not counting the `e=` entry.
pub const MAX_QUERY_LENGTH: usize = 4096;
/// Longest `vol=` value read (characters).
pub const MAX_VOLUMES_LENGTH: usize = 1500;
/// Longest `e=` value written or read (characters).
pub const MAX_EDITS_LINK_LENGTH: usize = 2000;
/// Most messages one decode lists; the rest are counted in one more line.
pub const MAX_MESSAGES: usize = 6;

/// What [`decode`] read: the parameters (defaults where the link has nothing usable), the
/// growth primitives and hand edits, and the messages about what was ignored.
#[derive(Clone, Debug)]
pub struct Decoded {
    /// The tree the link names.
    pub params: TreeParams,
    /// What was ignored and why, at most [`MAX_MESSAGES`] lines and a count.
    pub messages: Vec<String>,
}

/// The query (without `?`) of `p`: `v=1`, then each value that differs from its default, then
/// `vol=` and `e=` when there are primitives or edits (edits longer than
/// [`MAX_EDITS_LINK_LENGTH`] characters are left out).
pub fn encode(p: &TreeParams) -> String {
    let mut parts = vec![format!("v={FORMAT_VERSION}")];
    for spec in registry() {
        let Some(v) = p.get(&spec.id) else { continue };
        if !same(spec, v, spec.default) {
            parts.push(format!("{}={}", spec.id, format_value(spec, v)));
        }
    }
    let vol = encode_volumes(&p.skeleton.volumes);
    if !vol.is_empty() {
        parts.push(format!("vol={}", uri_component(&vol)));
    }
    let e = encode_edits(&p.skeleton.edits);
    if !e.is_empty() && e.len() <= MAX_EDITS_LINK_LENGTH {
        parts.push(format!("e={e}"));
    }
    parts.join("&")
}

/// Whether two wire values are the same stored value (floats are stored as `f32`).
fn same(spec: &ParamSpec, a: f64, b: f64) -> bool {
    match spec.kind {
        ParamKind::Float => (a as f32) == (b as f32),
        _ => a == b,
    }
}

/// A wire value as the link writes it: the shortest decimal of the stored `f32` for a float,
/// the whole number otherwise; never `-0`.
fn format_value(spec: &ParamSpec, v: f64) -> String {
    match spec.kind {
        ParamKind::Float => format_f32(v as f32),
        _ => format!("{}", v as i64),
    }
}

/// The shortest decimal that reads back as `x` (Rust's `Display` of `f32`), `0` for `-0`.
pub(crate) fn format_f32(x: f32) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x}")
    }
}

/// `text` %-encoded as JavaScript's `encodeURIComponent` does.
fn uri_component(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || b"-_.!~*'()".contains(&b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// `text` with `+` as a space and `%XX` decoded (`None` for bad %-encoding or UTF-8).
fn uri_decode(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' => {
                let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
                out.push(u8::from_str_radix(hex, 16).ok()?);
                i += 2;
            }
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8(out).ok()
}

/// Collects messages, keeping the first [`MAX_MESSAGES`] and counting the rest.
#[derive(Default)]
pub(crate) struct Notices {
    lines: Vec<String>,
    dropped: usize,
}

impl Notices {
    pub(crate) fn add(&mut self, line: String) {
        if self.lines.len() < MAX_MESSAGES {
            self.lines.push(line);
        } else {
            self.dropped += 1;
        }
    }

    fn done(mut self) -> Vec<String> {
        if self.dropped > 0 {
            let s = if self.dropped == 1 { "" } else { "s" };
            self.lines.push(format!("…and {} more problem{s} in the share link (ignored).", self.dropped));
        }
        self.lines
    }
}

/// At most 24 characters of `text` for a message, control characters shown as `?`.
pub(crate) fn shown(text: &str) -> String {
    let clean: String = text.chars().take(24).map(|c| if c.is_control() { '?' } else { c }).collect();
    if text.chars().count() > 24 {
        format!("{clean}…")
    } else {
        clean
    }
}

/// A plain decimal number, as the studio accepts: `[+-]`, digits with an optional fraction (or a
/// fraction alone), an optional exponent; no spaces, hex, `NaN` or `Infinity`.
pub(crate) fn plain_number(text: &str) -> Option<f64> {
    let body = text.strip_prefix(['+', '-']).unwrap_or(text);
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    let mantissa_ok = digits(int) && digits(frac) && !(int.is_empty() && frac.is_empty());
    let exponent_ok = exponent.is_none_or(|e| {
        let e = e.strip_prefix(['+', '-']).unwrap_or(e);
        !e.is_empty() && digits(e)
    });
    (mantissa_ok && exponent_ok).then(|| text.parse::<f64>().ok()).flatten().filter(|v| v.is_finite())
}

/// A query value checked against its spec: the value, or why it is refused.
fn parse_value(spec: &ParamSpec, raw: &str) -> Result<f64, String> {
    let v = plain_number(raw).ok_or_else(|| format!("\"{}\" is not a number", shown(raw)))?;
    if spec.kind != ParamKind::Float && v.fract() != 0.0 {
        return Err(format!("\"{}\" is not an integer", shown(raw)));
    }
    if v < spec.min || v > spec.max {
        return Err(format!("\"{}\" is out of range", shown(raw)));
    }
    Ok(if v == 0.0 { 0.0 } else { v })
}

/// What a parameter accepts, for a message.
fn range_text(spec: &ParamSpec) -> String {
    match spec.kind {
        ParamKind::Bool => "0 or 1".into(),
        ParamKind::Enum => format!("an option index 0–{}", spec.max),
        ParamKind::Int => format!("an integer in {}–{}", spec.min, spec.max),
        ParamKind::Float => format!("a number in {}–{}", spec.min, spec.max),
    }
}

/// The query of a link: what follows the first `?` (all of it when there is none), without a
/// `#` fragment.
fn query_of(link: &str) -> &str {
    let link = link.trim();
    let query = link.split_once('?').map_or(link, |(_, q)| q);
    query.split_once('#').map_or(query, |(q, _)| q)
}

/// Reads a share link (a whole address or its query) as the studio does: unknown keys are
/// ignored, a bad value keeps that parameter's default with a message, a repeated key keeps its
/// first value, another version or an over-long query gives the defaults with a message; bad
/// primitives are skipped one by one, bad edits drop the whole list. Never fails.
pub fn decode(link: &str) -> Decoded {
    let query = query_of(link);
    let mut params = TreeParams::default();
    let mut notices = Notices::default();
    let pairs: Vec<(&str, &str)> =
        query.split('&').filter(|s| !s.is_empty()).map(|s| s.split_once('=').unwrap_or((s, ""))).collect();
    let measured = query.split('&').filter(|s| s.split('=').next() != Some("e")).collect::<Vec<_>>().join("&");
    let measured = measured.chars().count();
    if measured > MAX_QUERY_LENGTH {
        notices.add(format!(
            "The share link is too long ({measured} characters, limit {MAX_QUERY_LENGTH}); loaded the defaults."
        ));
        return Decoded { params, messages: notices.done() };
    }
    let decoded: Vec<(String, Option<String>)> =
        pairs.iter().map(|(k, v)| (uri_decode(k).unwrap_or_default(), uri_decode(v))).collect();
    let first = |key: &str| decoded.iter().find(|(k, _)| k == key).map(|(_, v)| v.clone().unwrap_or_default());
    if let Some(version) = first("v") {
        if version != FORMAT_VERSION {
            notices.add(format!(
                "Unsupported share-link version \"{}\" (this app reads v={FORMAT_VERSION}); loaded the defaults.",
                shown(&version)
            ));
            return Decoded { params, messages: notices.done() };
        }
    }
    let mut seen = std::collections::HashSet::new();
    for (key, raw) in &decoded {
        let Some(spec) = registry().iter().find(|s| s.id == *key) else { continue };
        if !seen.insert(key.as_str()) {
            notices.add(format!("Ignored a repeated \"{key}\" in the link; kept its first value."));
            continue;
        }
        let value = raw.as_deref().ok_or_else(|| "the value has bad %-encoding".to_string());
        match value.and_then(|raw| parse_value(spec, raw)) {
            Ok(v) => {
                // In range and whole where it must be: `set` cannot refuse it.
                let _ = params.set(key, v);
            }
            Err(why) => notices.add(format!(
                "Ignored \"{key}\" from the link: {why} (expected {}); using the default {}.",
                range_text(spec),
                format_value(spec, spec.default)
            )),
        }
    }
    params.skeleton.volumes = decode_volumes(first("vol").as_deref(), &mut notices);
    params.skeleton.edits = decode_edits(first("e").as_deref(), &mut notices);
    Decoded { params, messages: notices.done() }
}
