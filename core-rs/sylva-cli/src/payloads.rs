//! `sylva params --payloads`: the JSON objects the core returns beside the buffers (a tree's meta,
//! a session update's, the levels of detail's, errors, bark styles, the leaf inspector's counts)
//! as TypeScript interfaces (`packages/sylva-trees/src/core/generated/payloads.ts`).
//!
//! The core knows nothing of TypeScript: this module describes its payload structs
//! (`sylva_core::meta`, `SylvaError`, `BarkStyle`) in [`INTERFACES`], a table of each object's
//! fields and their TypeScript types. The string unions (stages, materials, error kinds) are not
//! typed out: they are the serialised values of the Rust enums ([`UNIONS`]), listed through an
//! exhaustive `match`, so a new variant does not compile until it is listed. The tests
//! (`payloads/tests.rs`) serialise real values of every payload and check each key and value
//! kind against the table, both ways: a field renamed, added or dropped in Rust, or a field the
//! table declares that the core never sends, fails them. The output is formatted as Prettier
//! formats it; `npm run docs` writes it and `tests/docs.rs` fails when it is stale.

use crate::typescript::{const_list, WIDTH};
use serde_json::Value;
use sylva_core::params::Stage;
use sylva_core::{Material, SylvaError};

/// The TypeScript type of a JSON value.
#[derive(Clone, Copy, Debug)]
pub enum Ty {
    /// `number`.
    Number,
    /// `string`.
    String,
    /// `boolean`.
    Bool,
    /// An interface of [`INTERFACES`] or a union of [`UNIONS`], by name.
    Named(&'static str),
    /// `T[]`.
    Array(&'static Ty),
    /// `[A, B, ...]`.
    Tuple(&'static [Ty]),
    /// `T | null`.
    Nullable(&'static Ty),
    /// `Record<string, number>`.
    NumberRecord,
}

/// One field of an interface.
#[derive(Debug)]
pub struct Field {
    /// The JSON key (the Rust field's name).
    pub name: &'static str,
    /// Its TypeScript type.
    pub ty: Ty,
    /// Absent from some objects (`name?:`; the Rust field is skipped when `None`).
    pub optional: bool,
    /// Its doc comment.
    pub doc: &'static str,
}

/// A JSON object the core returns, as a TypeScript interface.
#[derive(Debug)]
pub struct Interface {
    /// The interface's name.
    pub name: &'static str,
    /// Its doc comment (names the Rust type).
    pub doc: &'static str,
    /// Its fields, in the order the interface lists them.
    pub fields: &'static [Field],
}

/// A string union: the JSON values of a Rust enum, as a `const` list and its type.
#[derive(Debug)]
pub struct Union {
    /// The type's name.
    pub name: &'static str,
    /// The name of the `const` list of its values.
    pub list: &'static str,
    /// Its doc comment (names the Rust type).
    pub doc: &'static str,
    /// Every value of the Rust enum, serialised.
    pub values: fn() -> Vec<String>,
}

const fn f(name: &'static str, ty: Ty, doc: &'static str) -> Field {
    Field { name, ty, optional: false, doc }
}

const fn opt(name: &'static str, ty: Ty, doc: &'static str) -> Field {
    Field { name, ty, optional: true, doc }
}

const VEC3: Ty = Ty::Tuple(&[Ty::Number, Ty::Number, Ty::Number]);
const PAIR: Ty = Ty::Tuple(&[Ty::Number, Ty::Number]);

/// The string unions, by the Rust enums they come from.
pub const UNIONS: &[Union] = &[
    Union {
        name: "Stage",
        list: "STAGES",
        doc: "A pipeline stage (`sylva_core::params::Stage`), in pipeline order: a parameter's \
              first stage, and the first stage a session update reran.",
        values: stages,
    },
    Union {
        name: "MaterialName",
        list: "MATERIALS",
        doc: "The material of an index range of the bark mesh (`sylva_core::Material`).",
        values: materials,
    },
    Union {
        name: "CoreErrorKind",
        list: "CORE_ERROR_KINDS",
        doc: "The kinds of error the core reports (`sylva_core::SylvaError`).",
        values: error_kinds,
    },
];

/// The payload objects, in the order the module declares them.
pub const INTERFACES: &[Interface] = &[
    Interface {
        name: "Bounds",
        doc: "Axis-aligned bounds in metres, Y up (`sylva_core::Bounds`).",
        fields: &[f("min", VEC3, "Smallest x, y, z."), f("max", VEC3, "Largest x, y, z.")],
    },
    Interface {
        name: "MeshGroup",
        doc: "An index range of the mesh drawn with one material (`sylva_core::MeshGroup`).",
        fields: &[
            f("material", Ty::Named("MaterialName"), "Material of the range."),
            f("start", Ty::Number, "First index (a multiple of 3)."),
            f("count", Ty::Number, "Number of indices (a multiple of 3)."),
        ],
    },
    Interface {
        name: "TreeChanges",
        doc: "Which buffers of a session update differ from the previous update's \
              (`sylva_core::meta::Changes`).",
        fields: &[
            f("skeleton", Ty::Bool, "The stems (and envelope, markers) were rebuilt."),
            f("bark", Ty::Bool, "The bark buffers differ."),
            f("placements", Ty::Bool, "The leaf matrices or tints differ."),
            f("leaf_mesh", Ty::Bool, "The leaf mesh drawn per leaf differs."),
            f("leaf", Ty::Bool, "The leaf shape (texture) differs."),
            f("shade", Ty::Bool, "The bark's occlusion was computed again."),
        ],
    },
    Interface {
        name: "TreeMeta",
        doc: "A tree's meta (`sylva_core::meta::TreeMeta`): `meta_json()` of a generated tree (with \
              `hash`) or a session's `update()` (with `preview`, `from` and `changes`).",
        fields: &[
            f("vertices", Ty::Number, "Bark vertices."),
            f("triangles", Ty::Number, "Bark triangles."),
            f("stems", Ty::Number, "Stems in the skeleton."),
            f("holes", Ty::Number, "Tree holes cut into the bark."),
            f("bounds", Ty::Named("Bounds"), "Bounds of the bark."),
            f("groups", Ty::Array(&Ty::Named("MeshGroup")), "The bark mesh's index ranges by material."),
            f("envelope", Ty::Array(&PAIR), "Crown envelope preview: `[height, radius]` pairs."),
            f("leaves", Ty::Number, "Leaves (instances); 0 for a bare tree."),
            f("leaf_hash", Ty::String, "Hash of the leaf shape: changes exactly when the leaf parameters change."),
            f("leaf_texture", Ty::Nullable(&PAIR), "Size of the baked leaf texture `[width, height]`, null when bare."),
            f("bark_type", Ty::Number, "The `bark_type` parameter's index: which bark maps the tree wears."),
            f("stage_ms", Ty::NumberRecord, "Milliseconds per stage, by stage name."),
            f("total_ms", Ty::Number, "Milliseconds of the whole generation or update."),
            opt("hash", Ty::String, "Content hash (16 hex digits) of a generated tree; a session's comes later."),
            opt("preview", Ty::Bool, "A session update: the tree is a drag's quick preview, not the full tree."),
            opt("from", Ty::Named("Stage"), "A session update: the first stage it reran."),
            opt("changes", Ty::Named("TreeChanges"), "A session update: what changed since the previous update."),
            opt(
                "edits",
                Ty::Array(&Ty::Named("EditReport")),
                "What became of each hand edit, in list order (absent without edits).",
            ),
        ],
    },
    Interface {
        name: "EditReport",
        doc: "What became of one hand edit (`sylva_core::edits::EditReport`).",
        fields: &[
            f("op", Ty::String, "The edit's op: `paint`, `crown`, `cut` or `bend`."),
            f("resolved", Ty::Bool, "Whether the edit found its stem and was applied."),
            opt("why", Ty::String, "Why not, when unresolved."),
            opt(
                "pending_year",
                Ty::Number,
                "A dated cut the tree is too young for: the year it happens (the branch is whole until then).",
            ),
        ],
    },
    Interface {
        name: "LodLevelMeta",
        doc: "One level's counts in `GeneratedLods.meta_json()` (`sylva_core::meta::LodLevelMeta`).",
        fields: &[
            f("triangles", Ty::Number, "Triangles drawn: bark + leaf mesh × leaves + 2 per cloud quad."),
            f("vertices", Ty::Number, "Bark vertices."),
            f("bark_triangles", Ty::Number, "Bark triangles."),
            f("leaves", Ty::Number, "Leaves (instances)."),
            f("leaf_triangles", Ty::Number, "Triangles of the leaf mesh drawn per leaf."),
            f("quads", Ty::Number, "Billboard-cloud quads."),
            f("stems", Ty::Number, "Stems swept into the bark."),
            f("groups", Ty::Array(&Ty::Named("MeshGroup")), "The bark mesh's index ranges by material."),
        ],
    },
    Interface {
        name: "LodMeta",
        doc: "`GeneratedLods.meta_json()` (`sylva_core::meta::LodMeta`).",
        fields: &[
            f("hash", Ty::String, "Hash of LOD0 (equals the `generate` hash of the same params)."),
            f("bounds", Ty::Named("Bounds"), "Bounds of LOD0's bark."),
            f("levels", Ty::Array(&Ty::Named("LodLevelMeta")), "LOD0, LOD1, LOD2."),
            f("leaf_hash", Ty::String, "Hash of the leaf shape."),
            f("leaf_texture", Ty::Nullable(&PAIR), "Size of the baked leaf texture `[width, height]`, null when bare."),
        ],
    },
    Interface {
        name: "CoreError",
        doc: "An error the core throws as JSON text (`sylva_core::SylvaError`).",
        fields: &[
            f("kind", Ty::Named("CoreErrorKind"), "What went wrong."),
            opt("param", Ty::String, "The parameter at fault, if one is."),
            f("message", Ty::String, "The message shown to users: names the parameter and what is allowed."),
        ],
    },
    Interface {
        name: "BarkStyle",
        doc: "How a bark type lies on a stem: `bark_style_json()` (`sylva_core::mesh::bark::BarkStyle`).",
        fields: &[
            f("tile_at_1m", Ty::Number, "Tile width (m) on a stem of 1 m girth; `tile_at_1m * sqrt(girth)` on others."),
            f("young_radius", Ty::Number, "Below this stem radius (m) the bark is young: smooth, of `young_rgb`."),
            f("young_rgb", VEC3, "Linear RGB of young bark."),
            f("relief", Ty::Number, "Strength of the normal map on old bark."),
        ],
    },
    Interface {
        name: "LeafInspection",
        doc: "The leaf inspector's drawing and counts: `leaf_inspect()` \
              (`sylva_core::meta::LeafInspection`).",
        fields: &[
            f("svg", Ty::String, "The SVG drawing."),
            f("iterations", Ty::Number, "Vein growth iterations."),
            f("nodes", Ty::Number, "Vein graph nodes."),
            f("links", Ty::Number, "Vein loop links."),
            f("segments", Ty::Number, "Vein segments drawn at the requested step."),
            f("auxins", Ty::Number, "Auxin sources."),
            f("triangles", Ty::Number, "Triangles of the leaf blade."),
            f("hash", Ty::String, "Hash of the leaf (16 hex digits)."),
        ],
    },
];

/// The JSON string of a serialised unit variant.
fn json_str(value: serde_json::Result<Value>) -> String {
    match value {
        Ok(Value::String(s)) => s,
        other => panic!("not a string: {other:?}"),
    }
}

fn stages() -> Vec<String> {
    use Stage::*;
    // Exhaustive: a new stage does not compile until it is listed here.
    let all = [Skeleton, Mesh, Foliage, Leaf, Viewer];
    all.iter().for_each(|s| match s {
        Skeleton | Mesh | Foliage | Leaf | Viewer => {}
    });
    all.iter().map(|v| json_str(serde_json::to_value(v))).collect()
}

fn materials() -> Vec<String> {
    let all = [Material::Bark, Material::Leaves, Material::CutFace, Material::Organ];
    all.iter().for_each(|m| match m {
        Material::Bark | Material::Leaves | Material::CutFace | Material::Organ => {}
    });
    all.iter().map(|v| json_str(serde_json::to_value(v))).collect()
}

/// One error of every kind (`kinds` tests build them too).
pub fn sample_errors() -> Vec<SylvaError> {
    let (param, message) = (String::from("p"), String::from("m"));
    let all = vec![
        SylvaError::InvalidParam { param: param.clone(), message: message.clone() },
        SylvaError::UnknownParam { param: param.clone(), message: message.clone() },
        SylvaError::Budget { param, message: message.clone() },
        SylvaError::Input { message },
    ];
    all.iter().for_each(|e| match e {
        SylvaError::InvalidParam { .. }
        | SylvaError::UnknownParam { .. }
        | SylvaError::Budget { .. }
        | SylvaError::Input { .. } => {}
    });
    all
}

fn error_kinds() -> Vec<String> {
    sample_errors()
        .iter()
        .map(|e| match serde_json::to_value(e) {
            Ok(v) => v["kind"].as_str().expect("an error has a kind").to_string(),
            Err(err) => panic!("an error serialises: {err}"),
        })
        .collect()
}

const HEADER: &str = "\
// @generated by `sylva params --payloads` (`npm run docs`) from the core's payload structs: do
// not edit. core-rs/sylva-cli/tests/docs.rs fails when this file is stale.
/**
 * The JSON objects the core returns beside the buffers (a tree's meta, a session update's, the
 * levels of detail's, errors, bark styles, the leaf inspector's counts), as TypeScript.
 */
";

/// The module's text.
pub fn payloads_module() -> String {
    let mut out = String::from(HEADER);
    for u in UNIONS {
        let values = (u.values)();
        let items: Vec<&str> = values.iter().map(String::as_str).collect();
        out.push('\n');
        out.push_str(&doc(0, &format!("Every value of `{}`, in the core's order.", u.name)));
        out.push_str(&const_list(u.list, &items));
        out.push('\n');
        out.push_str(&doc(0, u.doc));
        out.push_str(&format!("export type {} = (typeof {})[number];\n", u.name, u.list));
    }
    for i in INTERFACES {
        out.push('\n');
        out.push_str(&doc(0, i.doc));
        out.push_str(&format!("export interface {} {{\n", i.name));
        for fl in i.fields {
            out.push_str(&doc(2, fl.doc));
            out.push_str(&format!("  {}{}: {};\n", fl.name, if fl.optional { "?" } else { "" }, ts(fl.ty)));
        }
        out.push_str("}\n");
    }
    out.truncate(out.trim_end().len());
    out
}

/// The TypeScript text of `ty`.
pub fn ts(ty: Ty) -> String {
    match ty {
        Ty::Number => "number".into(),
        Ty::String => "string".into(),
        Ty::Bool => "boolean".into(),
        Ty::Named(n) => n.into(),
        Ty::Array(t) => format!("{}[]", ts(*t)),
        Ty::Tuple(ts_) => format!("[{}]", ts_.iter().map(|t| ts(*t)).collect::<Vec<_>>().join(", ")),
        Ty::Nullable(t) => format!("{} | null", ts(*t)),
        Ty::NumberRecord => "Record<string, number>".into(),
    }
}

/// A doc comment at `indent` spaces: one line when it fits, else wrapped at the line width.
fn doc(indent: usize, text: &str) -> String {
    let pad = " ".repeat(indent);
    let one = format!("{pad}/** {text} */");
    if one.len() <= WIDTH {
        return format!("{one}\n");
    }
    let mut out = format!("{pad}/**\n");
    let mut line = format!("{pad} *");
    for word in text.split_whitespace() {
        if line.len() + 1 + word.len() > WIDTH {
            out.push_str(&line);
            out.push('\n');
            line = format!("{pad} *");
        }
        line.push(' ');
        line.push_str(word);
    }
    out.push_str(&format!("{line}\n{pad} */\n"));
    out
}

#[cfg(test)]
mod tests;
