//! The structured entries of a share link: growth primitives (`vol=1;s:c:0,5.5,0,2;...`: per
//! primitive its kind, group, centre and sizes in metres) and hand edits (`e=1~p60.400...~c80.410.-20`:
//! per edit an op letter and whole numbers, lengths in centimetres, stroke and outline points as
//! differences). The forms of docs/formats.md ("Growth volume primitives", "Hand edits").

use super::{format_f32, plain_number, shown, Notices, MAX_EDITS_LINK_LENGTH, MAX_VOLUMES_LENGTH};
use crate::params::edits::{self, Bend, Crown, Cut, Edit, Paint, MAX_EDITS};
use crate::params::volumes::{self, MAX_VOLUMES};
use crate::params::{Primitive, VolumeGroup, VolumePrimitive};
use glam::{Vec2, Vec3};

/// The version prefix of `vol=` and of `e=`.
const ITEMS_VERSION: &str = "1";

/// Kind letters, group letters.
const KINDS: [(char, &str); 3] = [('s', "sphere"), ('b', "box"), ('c', "cylinder")];
const GROUPS: [(char, VolumeGroup); 3] =
    [('c', VolumeGroup::Crown), ('s', VolumeGroup::Shadow), ('x', VolumeGroup::Exclusion)];

/// The `vol=` value of `volumes` (before %-encoding); empty for none.
pub fn encode_volumes(volumes: &[VolumePrimitive]) -> String {
    if volumes.is_empty() {
        return String::new();
    }
    let items = volumes.iter().map(|v| {
        let group = GROUPS.iter().find(|(_, g)| *g == v.group).map_or('c', |(c, _)| *c);
        let (kind, centre, sizes) = match v.shape {
            Primitive::Sphere { centre, radius } => ('s', centre, vec![radius]),
            Primitive::Box { centre, size } => ('b', centre, size.to_array().to_vec()),
            Primitive::Cylinder { centre, radius, height } => ('c', centre, vec![radius, height]),
        };
        let numbers: Vec<String> = centre.to_array().into_iter().chain(sizes).map(format_f32).collect();
        format!("{kind}:{group}:{}", numbers.join(","))
    });
    std::iter::once(ITEMS_VERSION.to_string()).chain(items).collect::<Vec<_>>().join(";")
}

/// One primitive of a `vol=` value, or why it is refused.
fn decode_volume(item: &str) -> Result<VolumePrimitive, String> {
    let parts: Vec<&str> = item.split(':').collect();
    let [k, g, numbers] = parts[..] else { return Err(format!("\"{}\" is not kind:group:numbers", shown(item))) };
    let kind = KINDS.iter().find(|(c, _)| k.len() == 1 && k.starts_with(*c)).map(|(_, n)| *n);
    let kind = kind.ok_or_else(|| format!("unknown kind \"{}\" (s = sphere, b = box, c = cylinder)", shown(k)))?;
    let group = GROUPS.iter().find(|(c, _)| g.len() == 1 && g.starts_with(*c)).map(|(_, g)| *g);
    let group =
        group.ok_or_else(|| format!("unknown group \"{}\" (c = crown, s = shadow, x = exclusion)", shown(g)))?;
    let raw: Vec<&str> = numbers.split(',').collect();
    let want = 3 + match kind {
        "sphere" => 1,
        "box" => 3,
        _ => 2,
    };
    if raw.len() != want {
        return Err(format!("a {kind} takes {want} numbers, got {}", raw.len()));
    }
    let mut v = Vec::with_capacity(want);
    for text in raw {
        v.push(plain_number(text).ok_or_else(|| format!("\"{}\" is not a number", shown(text)))? as f32);
    }
    let centre = Vec3::new(v[0], v[1], v[2]);
    let shape = match kind {
        "sphere" => Primitive::Sphere { centre, radius: v[3] },
        "box" => Primitive::Box { centre, size: Vec3::new(v[3], v[4], v[5]) },
        _ => Primitive::Cylinder { centre, radius: v[3], height: v[4] },
    };
    let primitive = VolumePrimitive { group, shape };
    volumes::validate(&[primitive]).map_err(|e| e.to_string().replace("volumes[0].", ""))?;
    Ok(primitive)
}

/// The primitives of a `vol=` value: a bad one is skipped with a message naming it (`vol[2]`),
/// another version or an over-long value gives none.
pub(crate) fn decode_volumes(value: Option<&str>, notices: &mut Notices) -> Vec<VolumePrimitive> {
    let mut out = Vec::new();
    let Some(value) = value.filter(|v| !v.is_empty()) else { return out };
    if value.chars().count() > MAX_VOLUMES_LENGTH {
        notices.add(format!(
            "Ignored the volumes in the link: too long ({} characters, limit {MAX_VOLUMES_LENGTH}).",
            value.chars().count()
        ));
        return out;
    }
    let mut items = value.split(';');
    let version = items.next().unwrap_or_default();
    if version != ITEMS_VERSION {
        notices.add(format!(
            "Ignored the volumes in the link: unsupported version \"{}\" (this app reads {ITEMS_VERSION}).",
            shown(version)
        ));
        return out;
    }
    for (i, item) in items.enumerate() {
        match decode_volume(item) {
            Err(why) => notices.add(format!("Ignored vol[{i}] from the link: {why}.")),
            Ok(_) if out.len() >= MAX_VOLUMES => {
                notices.add(format!("Ignored vol[{i}] from the link: at most {MAX_VOLUMES} primitives."));
            }
            Ok(v) => out.push(v),
        }
    }
    out
}

/// Metres as whole centimetres, rounded as JavaScript's `Math.round` (halves up).
fn cm(metres: f32) -> i64 {
    (f64::from(metres) * 100.0 + 0.5).floor() as i64
}

/// The first point's numbers as they are, every next one's as differences to the one before.
fn deltas<const N: usize>(points: impl Iterator<Item = [f32; N]>) -> Vec<i64> {
    let mut out = Vec::new();
    let mut prev = [0i64; N];
    for p in points {
        for (k, &x) in p.iter().enumerate() {
            out.push(cm(x) - prev[k]);
            prev[k] = cm(x);
        }
    }
    out
}

/// One edit as a link item: its op letter and numbers.
fn encode_edit(e: &Edit) -> String {
    let (op, numbers) = match e {
        Edit::Paint(p) => {
            let head = [cm(p.radius), (f64::from(p.density) + 0.5).floor() as i64, cm(p.segment), cm(p.kill)];
            ('p', head.into_iter().chain(deltas(p.points.iter().map(|q| q.to_array()))).collect())
        }
        Edit::Crown(c) => ('o', deltas(c.outline.iter().map(|q| q.to_array()))),
        Edit::Cut(c) => {
            // A dated cut's year follows its point, in whole years.
            let year = c.year.map(|y| (f64::from(y) + 0.5).floor() as i64);
            ('c', c.at.to_array().map(cm).into_iter().chain(year).collect())
        }
        Edit::Bend(b) => ('b', b.at.to_array().into_iter().chain(b.to.to_array()).map(cm).collect::<Vec<_>>()),
    };
    let numbers: Vec<String> = numbers.iter().map(i64::to_string).collect();
    format!("{op}{}", numbers.join("."))
}

/// The `e=` value of `edits` (lengths rounded to centimetres, densities to whole markers per
/// m³); empty for none.
pub fn encode_edits(edits: &[Edit]) -> String {
    if edits.is_empty() {
        return String::new();
    }
    std::iter::once(ITEMS_VERSION.to_string()).chain(edits.iter().map(encode_edit)).collect::<Vec<_>>().join("~")
}

/// Centimetres as metres.
fn metres(centimetres: i64) -> f32 {
    (centimetres as f64 / 100.0) as f32
}

/// Running sums of `values` in tuples of `N`, as metres.
fn undeltas<const N: usize>(values: &[i64]) -> Vec<[f32; N]> {
    let mut running = [0i64; N];
    values
        .chunks_exact(N)
        .map(|c| {
            for k in 0..N {
                running[k] += c[k];
            }
            running.map(metres)
        })
        .collect()
}

/// One link item as an edit, or why it is refused.
fn decode_edit(item: &str) -> Result<Edit, String> {
    let mut chars = item.chars();
    let op = chars.next().unwrap_or(' ');
    let mut v = Vec::new();
    for text in chars.as_str().split('.') {
        let digits = text.strip_prefix('-').unwrap_or(text);
        let whole = (1..=7).contains(&digits.len()) && digits.bytes().all(|b| b.is_ascii_digit());
        if !whole {
            let text: String = text.chars().take(24).collect();
            return Err(format!("\"{text}\" is not a whole number of centimetres"));
        }
        v.push(text.parse::<i64>().map_err(|e| e.to_string())?);
    }
    let n = v.len();
    match op {
        'p' if n >= 7 && (n - 4) % 3 == 0 => Ok(Edit::Paint(Paint {
            points: undeltas::<3>(&v[4..]).into_iter().map(Vec3::from_array).collect(),
            radius: metres(v[0]),
            density: v[1] as f32,
            segment: metres(v[2]),
            kill: metres(v[3]),
        })),
        'p' => Err(format!("a paint stroke takes 4 numbers and x,y,z per point, got {n} numbers")),
        'o' if n >= 6 && n % 2 == 0 => {
            Ok(Edit::Crown(Crown { outline: undeltas::<2>(&v).into_iter().map(Vec2::from_array).collect() }))
        }
        'o' => Err(format!("a crown outline takes radius,height per point (at least 3), got {n} numbers")),
        'c' if n == 3 || n == 4 => Ok(Edit::Cut(Cut {
            at: Vec3::new(metres(v[0]), metres(v[1]), metres(v[2])),
            year: v.get(3).map(|&y| y as f32),
        })),
        'c' => Err(format!("a cut takes 3 numbers (and a year), got {n}")),
        'b' if n == 6 => Ok(Edit::Bend(Bend {
            at: Vec3::new(metres(v[0]), metres(v[1]), metres(v[2])),
            to: Vec3::new(metres(v[3]), metres(v[4]), metres(v[5])),
        })),
        'b' => Err(format!("a bend takes 6 numbers, got {n}")),
        _ => Err(format!("unknown op \"{op}\" (p = paint, o = crown outline, c = cut, b = bend)")),
    }
}

/// The edits of an `e=` value, all or nothing: anything wrong drops every edit with one message.
pub(crate) fn decode_edits(value: Option<&str>, notices: &mut Notices) -> Vec<Edit> {
    let Some(value) = value.filter(|v| !v.is_empty()) else { return Vec::new() };
    match edits_of(value) {
        Ok(list) => list,
        Err(why) => {
            notices.add(format!("Ignored the edits in the link: {why}. Import the edit list (Import edits…) instead."));
            Vec::new()
        }
    }
}

fn edits_of(value: &str) -> Result<Vec<Edit>, String> {
    let length = value.chars().count();
    if length > MAX_EDITS_LINK_LENGTH {
        return Err(format!("too long ({length} characters, limit {MAX_EDITS_LINK_LENGTH})"));
    }
    let mut items = value.split('~');
    let version = items.next().unwrap_or_default();
    if version != ITEMS_VERSION {
        return Err(format!("unsupported version \"{}\" (this app reads {ITEMS_VERSION})", shown(version)));
    }
    let items: Vec<&str> = items.collect();
    if items.len() > MAX_EDITS {
        return Err(format!("{} edits, at most {MAX_EDITS}", items.len()));
    }
    let list = items
        .iter()
        .enumerate()
        .map(|(i, item)| decode_edit(item).map_err(|why| format!("e[{i}]: {why}")))
        .collect::<Result<Vec<_>, _>>()?;
    edits::validate(&list).map_err(|e| e.to_string())?;
    Ok(list)
}
