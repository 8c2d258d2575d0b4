//! The `sylva` command line, declared once with clap's derive: parsing, `sylva help`, every
//! command's `--help`, docs/cli.md and the docs page's Command line section
//! (`web/src/docs/cli.json`) all come from these declarations (see [`crate::reference`]).
//!
//! Values with a message of their own (`--set`, `--leaves`, `--report`, whole numbers, crown
//! shapes) are parsed by the functions below; `main` prints such a message as it is.

use clap::{Args, CommandFactory, Parser, Subcommand};
use sylva_core::export::LeafMode;
use sylva_core::CrownShape;

/// Sylva's command line: the same trees as the browser, natively (the same content hash).
///
/// `--set` takes numbers, `true`/`false`, or an enum option by name (`--set shape=inverse-conical`);
/// `sylva params` lists every id (docs/parameters.md). Invalid parameters, unknown options and
/// budget overruns print `error: ...` to stderr and exit with status 2. From the repository, run it
/// as `cargo run --release -p sylva-cli -- COMMAND ...`.
#[derive(Parser, Debug)]
#[command(name = "sylva", disable_version_flag = true, arg_required_else_help = true)]
pub struct Cli {
    /// Print the core's version
    #[arg(long)]
    pub version: bool,
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The commands, in the order `sylva help` lists them.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Generate one tree and print one JSON object
    ///
    /// The object holds `vertices`, `triangles`, `stems`, the content `hash` (the same as the app
    /// shows), `ms` per stage and `total_ms`. `--report skeleton` adds `skeleton`: every stem
    /// (level, parent, base height, length, radius, down angle, split clone). `--report mesh` adds
    /// `non_manifold_edges`, `boundary_edges` (with vertices welded by position), `holes`,
    /// `hole_list`, `welds`, `weld_fallbacks`, `split_welds`, `split_fallbacks` and `forks` (split
    /// welds that are smooth Y forks). `--out` writes the tree as glTF 2.0 binary (`.glb`: bark and
    /// leaf meshes, PBR materials, embedded PNG textures, tangents, vertex colours, the wind
    /// attributes `_WIND_PIVOT` and `_WIND_PARAMS`) or as Wavefront OBJ (`.obj`, plus `NAME.mtl` and
    /// `NAME_*.png` textures next to it, leaves baked), and adds `written`: `[file, bytes]` per
    /// file (docs/formats.md). With edits (`--edits`), `edits` lists each edit's `op` and whether
    /// it `resolved` (with `why` not); each unresolved edit is also printed on stderr.
    #[command(args_override_self = true)]
    Generate(GenerateArgs),
    /// Print the parameter registry as JSON
    ///
    /// One object per parameter: `id`, `group`, `label`, `kind`, `default`, `min`, `max`, `step`,
    /// `unit`, `description` and, for enums, `options`. With `--markdown`: the parameter reference
    /// docs/parameters.md. With `--typescript`: the registry and the presets as the TypeScript
    /// module packages/sylva-trees/src/core/generated/params.ts (`ParamId`, `PresetId`, ...).
    /// With `--payloads`: the JSON objects the core returns beside the buffers (a tree's meta,
    /// a session update's, the levels of detail's, errors, ...) as the TypeScript interfaces of
    /// packages/sylva-trees/src/core/generated/payloads.ts. With `--python-stub`: the type stub of
    /// the Python package, core-rs/sylva-py/python/sylva_trees/__init__.pyi (`Params` with one
    /// documented key per parameter, `PresetName`, `ParamId`, ...).
    #[command(args_override_self = true)]
    Params {
        /// Print the parameter reference as Markdown instead
        #[arg(long, conflicts_with_all = ["typescript", "payloads", "python_stub"])]
        markdown: bool,
        /// Print the registry and the presets as a TypeScript module instead
        #[arg(long, conflicts_with_all = ["payloads", "python_stub"])]
        typescript: bool,
        /// Print the TypeScript interfaces of the core's JSON payloads instead
        #[arg(long, conflicts_with = "python_stub")]
        payloads: bool,
        /// Print the Python package's type stub (__init__.pyi) instead
        #[arg(long)]
        python_stub: bool,
    },
    /// Print the tree presets as JSON
    ///
    /// One object per preset: `name`, `label`, `description`, `leaf` (the leaf preset it
    /// wears) and `values`, the values that differ from the defaults.
    Presets,
    /// Print the leaf presets as JSON
    ///
    /// One object per leaf preset: `name`, `label`, `description` and `values` (the leaf
    /// parameters that differ from the defaults); the names `sylva leaf --preset` takes.
    LeafPresets,
    /// Print `[[r, ShapeRatio(r)], ...]` for one crown shape
    ///
    /// `r` runs from 0 (the top of the crown) to 1 (the crown base) in evenly spaced samples; a
    /// level-1 branch's length is multiplied by ShapeRatio(r).
    #[command(args_override_self = true)]
    Envelope {
        /// The crown shape, by name (case and separators ignored)
        #[arg(long, value_name = "NAME", value_parser = crown_shape)]
        shape: CrownShape,
        /// Number of samples, from 2 to 100000
        #[arg(long, value_name = "N", value_parser = samples, default_value_t = 101)]
        samples: usize,
    },
    /// Time the native generation: the median over N runs after a warm-up
    ///
    /// Prints `native: V vertices, median T ms over N runs (X M vertices/s)`, or with `--json` one
    /// object: `target`, `runs`, `vertices`, `triangles`, `median_ms`, `stage_median_ms`,
    /// `vertices_per_second`, `hash`. `--glb` also times the GLB export (with the export flags):
    /// the median into a fresh buffer (as `--out` writes), into one reused buffer on every core and
    /// on one, and the first export, which encodes the PNG textures; the JSON then has `glb`:
    /// `median_ms`, `reused_buffer_median_ms`, `reused_buffer_one_thread_median_ms`, `threads`,
    /// `first_ms`, `bytes`, `runs`. `npm run bench` runs this for every preset.
    #[command(args_override_self = true)]
    Bench(BenchArgs),
    /// Generate many trees on every core: GLB files and a manifest
    ///
    /// The trees are every `--preset` (the defaults without one) with every seed of `--seeds` (the
    /// preset's own seed without it), then the `--set` values; or the trees of `--list`, a JSON
    /// array of `{"preset": NAME, "seed": N, "set": {"id": value, ...}, "name": FILE}` (each key
    /// optional). Each tree is generated on one of `--threads` worker threads (default: every
    /// core) and, with `--out DIR`, written to `DIR/NAME.glb` (NAME: `preset_seed`, `default_seed`
    /// or the list's `name`), the same bytes as `sylva generate --out` writes for that tree. Prints
    /// the manifest, one JSON object (also written to `DIR/manifest.json`): `trees`, per tree
    /// `name`, `preset`, `seed`, `file`, `hash`, `vertices`, `triangles`, `leaves`, `generate_ms`
    /// and `ms` (generation and writing), and `count`, `failed`, `threads`, `total_ms`,
    /// `trees_per_second`. A tree that fails (a budget) has `error` instead, and the batch exits
    /// with status 2 after the others are written.
    #[command(args_override_self = true)]
    Batch(BatchArgs),
    /// Generate one leaf and print it as JSON
    ///
    /// The JSON holds the outline, the triangulation, the auxin sources, the vein nodes, edges,
    /// links and loops, the leaf's hash and `ms` per stage. `--svg` writes the leaf inspector's
    /// drawing: the blade and margin, auxin sources, veins with their pipe widths and loop links.
    #[command(args_override_self = true)]
    Leaf(LeafArgs),
    /// Time the leaf pipeline: the median per stage over N runs after a warm-up
    ///
    /// Without `--preset` it runs Oak (Open venation) and Maple (Closed). Unless
    /// `--set leaf_vein_density=...` is given, the density is set to its maximum, so each leaf gets
    /// the full 5,000 auxin sources. `--json` prints `target`, `runs` and `results`, per preset
    /// `preset`, `venation`, `auxins`, `vein_nodes`, `loops`, `triangles`, `median_ms`,
    /// `stage_median_ms`, `hash` and `params` (its leaf values that differ from the defaults).
    #[command(name = "bench-leaf", args_override_self = true)]
    BenchLeaf(BenchLeafArgs),
    /// Print this command-line reference as Markdown (docs/cli.md)
    ///
    /// With `--json`: the same reference as data, which the docs page's Command line section
    /// shows (`web/src/docs/cli.json`). `npm run docs` writes both files.
    #[command(name = "cli-reference", args_override_self = true)]
    CliReference {
        /// Print the reference as JSON instead
        #[arg(long)]
        json: bool,
    },
}

/// The tree: a preset, then the seed and `--set` values in command-line order, volumes and edits.
#[derive(Args, Debug)]
pub struct TreeArgs {
    /// Start from this tree preset (`sylva presets` lists them) instead of the defaults
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// Random seed, the same as `--set seed=N`
    #[arg(long, value_name = "N")]
    pub seed: Option<String>,
    /// The tree's age in years, the same as `--set age=N`: below the preset's Mature Age a
    /// younger tree, its growth replayed (docs/user-guide.md, Growth over years)
    #[arg(long, value_name = "YEARS")]
    pub age: Option<String>,
    /// The `--set` values.
    #[command(flatten)]
    pub set: Sets,
    /// Growth volume primitives: a JSON array of spheres, boxes and cylinders (docs/formats.md)
    #[arg(long, value_name = "FILE.json")]
    pub volumes: Option<String>,
    /// Hand edits (paint, crown, cut, bend): a JSON document `{"version": 1, "edits": [...]}` (docs/formats.md)
    #[arg(long, value_name = "FILE.json")]
    pub edits: Option<String>,
    /// `--seed`, `--age` and `--set` in the order they were given (filled in by `main`).
    #[arg(skip)]
    pub in_order: Vec<(String, String)>,
}

/// `--set id=value`, repeatable (`generate`, `bench`, `leaf`, `bench-leaf`).
#[derive(Args, Debug)]
pub struct Sets {
    /// Set one parameter (repeatable; applied in order, over the preset)
    #[arg(long = "set", value_name = "id=value", value_parser = key_value)]
    pub set: Vec<(String, String)>,
}

/// How an export is written (`generate --out`, `bench --glb`).
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// How leaves are written: instanced (default; GLB: EXT_mesh_gpu_instancing, for engines and
    /// three.js), baked into one mesh (for Blender and other editors), or none
    #[arg(long, value_name = "instanced|baked|none", value_parser = leaf_mode)]
    pub leaves: Option<LeafMode>,
    /// No images: plain material colours
    #[arg(long)]
    pub no_textures: bool,
    /// GLB: no TANGENT attribute (viewers compute their own); the largest share of a big export
    #[arg(long)]
    pub no_tangents: bool,
    /// No wind attributes
    #[arg(long)]
    pub no_wind: bool,
    /// GLB for Godot and strict importers: no glTF extension (float normals and tangents, no
    /// KHR_mesh_quantization; instanced leaves written baked)
    #[arg(long)]
    pub strict: bool,
}

/// `sylva generate`.
#[derive(Args, Debug)]
pub struct GenerateArgs {
    /// The tree.
    #[command(flatten)]
    pub tree: TreeArgs,
    /// Write the tree as GLB or OBJ (the format follows the extension)
    #[arg(long, value_name = "FILE.glb|FILE.obj")]
    pub out: Option<String>,
    /// With `--out FILE.glb`: every level of detail in one GLB, root node FILE with children
    /// FILE_LOD0, FILE_LOD1, FILE_LOD2 and the screen-size thresholds in extras
    #[arg(long, requires = "out")]
    pub lods: bool,
    /// With `--out FILE.glb`: the GLB with its growth animation, year 0 to the Age at one second a
    /// year (morph targets between key years, leaves baked; docs/formats.md, Growth animation)
    #[arg(long, requires = "out", conflicts_with = "lods")]
    pub growth_animation: bool,
    /// Also write the growth as a zip of one GLB per whole year up to the Age (year_001.glb, ...),
    /// each the tree generated at that Age with the export options
    #[arg(long, value_name = "FILE.zip")]
    pub growth_years: Option<String>,
    /// The export options.
    #[command(flatten)]
    pub export: ExportArgs,
    /// Add every stem (skeleton), the mesh's topology, welds, forks and holes (mesh), or the
    /// leaves on the tree and on the ground and every set of flowers, fruit, catkins and buds
    /// with its instances' origins (foliage) to the output; repeatable
    #[arg(long, value_name = "skeleton|mesh|foliage", value_parser = report)]
    pub report: Vec<String>,
}

/// `sylva bench`.
#[derive(Args, Debug)]
pub struct BenchArgs {
    /// The tree.
    #[command(flatten)]
    pub tree: TreeArgs,
    /// Number of timed runs
    #[arg(long, value_name = "N", value_parser = runs, default_value_t = 30)]
    pub runs: usize,
    /// Print one JSON object instead of a line of text
    #[arg(long)]
    pub json: bool,
    /// Also time the GLB export
    #[arg(long)]
    pub glb: bool,
    /// The export options (for `--glb`).
    #[command(flatten)]
    pub export: ExportArgs,
}

/// `sylva batch`.
#[derive(Args, Debug)]
pub struct BatchArgs {
    /// A tree preset (repeatable; `sylva presets` lists them; default: the defaults)
    #[arg(long, value_name = "NAME", conflicts_with = "list")]
    pub preset: Vec<String>,
    /// The seeds: N, A-B (inclusive) or a comma-separated list of them, for every preset
    #[arg(long, value_name = "LIST", conflicts_with = "list")]
    pub seeds: Option<String>,
    /// The `--set` values, applied to every tree after its preset and seed.
    #[command(flatten)]
    pub set: Sets,
    /// The trees as a JSON array of `{"preset", "seed", "set", "name"}` instead
    #[arg(long, value_name = "FILE.json")]
    pub list: Option<String>,
    /// Write DIR/NAME.glb per tree and DIR/manifest.json (created if missing)
    #[arg(long, value_name = "DIR")]
    pub out: Option<String>,
    /// Worker threads (default: every core)
    #[arg(long, value_name = "N", value_parser = threads)]
    pub threads: Option<usize>,
    /// The export options.
    #[command(flatten)]
    pub export: ExportArgs,
}

/// `sylva leaf`.
#[derive(Args, Debug)]
pub struct LeafArgs {
    /// Start from this leaf preset instead of the defaults
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// The `--set` values.
    #[command(flatten)]
    pub set: Sets,
    /// Write the SVG drawing to FILE
    #[arg(long, value_name = "FILE")]
    pub svg: Option<String>,
    /// Write the blade mesh (LOD0, with the petiole) to FILE as Wavefront OBJ
    #[arg(long, value_name = "FILE")]
    pub obj: Option<String>,
    /// Draw the venation as it was after growth step N (default: finished)
    #[arg(long, value_name = "N", value_parser = step)]
    pub step: Option<u32>,
    /// Draw the triangulation in the SVG
    #[arg(long)]
    pub triangulation: bool,
}

/// `sylva bench-leaf`.
#[derive(Args, Debug)]
pub struct BenchLeafArgs {
    /// A leaf preset to time (repeatable; default: oak and maple)
    #[arg(long, value_name = "NAME")]
    pub preset: Vec<String>,
    /// The `--set` values.
    #[command(flatten)]
    pub set: Sets,
    /// Number of timed runs
    #[arg(long, value_name = "N", value_parser = runs, default_value_t = 30)]
    pub runs: usize,
    /// Print one JSON object instead of lines of text
    #[arg(long)]
    pub json: bool,
}

/// Examples shown under each command's `--help` and in the references: every one is a valid
/// command line (a test parses them all).
pub const EXAMPLES: &[(&str, &[&str])] = &[
    (
        "generate",
        &[
            "sylva generate --preset quaking_aspen --seed 7 --set levels=3 --out aspen.glb",
            "sylva generate --preset fir --seed 7 --out fir.obj",
            "sylva generate --age 40 --growth-animation --out growing.glb --growth-years years.zip",
            "sylva generate --preset oak --set hole_count=3 --report mesh",
        ],
    ),
    (
        "params",
        &[
            "sylva params --markdown",
            "sylva params --typescript",
            "sylva params --payloads",
            "sylva params --python-stub",
        ],
    ),
    ("presets", &["sylva presets"]),
    ("leaf-presets", &["sylva leaf-presets"]),
    ("envelope", &["sylva envelope --shape flame --samples 11"]),
    ("bench", &["sylva bench --preset fir --runs 50 --json", "sylva bench --preset ca_black_oak --glb --runs 7"]),
    (
        "batch",
        &[
            "sylva batch --preset oak --preset fir --seeds 1-50 --out forest",
            "sylva batch --list trees.json --out trees --threads 4",
        ],
    ),
    (
        "leaf",
        &[
            "sylva leaf --preset maple --svg maple.svg --step 40 --triangulation",
            "sylva leaf --preset oak --obj oak.obj",
        ],
    ),
    ("bench-leaf", &["sylva bench-leaf --json"]),
    ("cli-reference", &["sylva cli-reference --json"]),
];

/// The declared interface, completed with what only the core knows (crown shape names, leaf
/// presets), each command's full synopsis as its usage line, its examples, and an overview of
/// every command's synopsis under `sylva help`.
pub fn command() -> clap::Command {
    let shapes = CrownShape::LABELS.join(", ");
    let leaf_presets: Vec<&str> = sylva_core::leaf::presets::LEAF_PRESETS.iter().map(|p| p.name).collect();
    let leaf_presets = leaf_presets.join(", ");
    let mut overview = String::from("Every command:\n");
    let cmd = Cli::command().max_term_width(WIDTH).mut_subcommands(|c| {
        let name = c.get_name().to_string();
        let c = c.max_term_width(WIDTH).mut_args(|a| match (name.as_str(), a.get_id().as_str()) {
            ("envelope", "shape") => a.help(format!("The crown shape by name: {shapes} (case and separators ignored)")),
            ("leaf", "preset") => {
                a.help(format!("Start from this leaf preset ({leaf_presets}) instead of the defaults"))
            }
            ("bench-leaf", "preset") => {
                a.help(format!("A leaf preset to time ({leaf_presets}; repeatable; default: oak and maple)"))
            }
            _ => a,
        });
        overview.push_str(&format!("  {}\n", crate::synopsis::synopsis_wrapped(&c, 2, WIDTH)));
        let usage = crate::synopsis::synopsis_wrapped(&c, "Usage: ".len(), WIDTH);
        let examples: Vec<String> = examples(&name).iter().map(|e| format!("  {e}")).collect();
        c.override_usage(usage).after_help(format!("Examples:\n{}", examples.join("\n")))
    });
    cmd.after_help(overview.trim_end().to_string())
}

/// Help is wrapped at this many columns (or the terminal's width, when narrower).
const WIDTH: usize = 100;

/// The examples of command `name`.
pub fn examples(name: &str) -> &'static [&'static str] {
    EXAMPLES.iter().find(|(n, _)| *n == name).map_or(&[], |(_, e)| e)
}

/// `--set id=value`.
fn key_value(kv: &str) -> Result<(String, String), String> {
    let (k, v) = kv.split_once('=').ok_or_else(|| format!("--set takes id=value, got '{kv}'"))?;
    Ok((k.to_string(), v.to_string()))
}

/// `--leaves instanced|baked|none`.
fn leaf_mode(v: &str) -> Result<LeafMode, String> {
    LeafMode::from_name(v).ok_or_else(|| format!("--leaves takes 'instanced', 'baked' or 'none', got '{v}'"))
}

/// `--report skeleton|mesh|foliage`.
fn report(what: &str) -> Result<String, String> {
    if what == "skeleton" || what == "mesh" || what == "foliage" {
        Ok(what.to_string())
    } else {
        Err(format!("--report takes 'skeleton', 'mesh' or 'foliage', got '{what}'"))
    }
}

/// `--runs N`.
fn runs(v: &str) -> Result<usize, String> {
    v.parse().map_err(|_| "--runs takes a whole number".to_string())
}

/// `--threads N`, at least 1.
fn threads(v: &str) -> Result<usize, String> {
    match v.parse() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!("--threads takes a whole number of at least 1, got '{v}'")),
    }
}

/// `--step N`.
fn step(v: &str) -> Result<u32, String> {
    v.parse().map_err(|_| "--step takes a whole number".to_string())
}

/// `--samples N`, 2 to 100000.
fn samples(v: &str) -> Result<usize, String> {
    let n: usize = v.parse().map_err(|_| "--samples takes a whole number".to_string())?;
    if (2..=100_000).contains(&n) {
        Ok(n)
    } else {
        Err(format!("--samples must be between 2 and 100000, got {n}"))
    }
}

/// `--shape NAME`.
fn crown_shape(v: &str) -> Result<CrownShape, String> {
    CrownShape::from_name(v)
        .ok_or_else(|| format!("unknown crown shape '{v}' (known: {})", CrownShape::LABELS.join(", ")))
}
