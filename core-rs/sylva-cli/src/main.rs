//! `sylva`: the command line of Sylva's core.
//!
//! The interface is declared once, in [`cli`] (clap's derive): `sylva help`, each command's
//! `--help`, docs/cli.md and the docs page's Command line section are generated from it
//! ([`mod@reference`]). Errors (unknown options, invalid values and parameters, budgets) print
//! `error: ...` to stderr and exit with status 2.

mod batch;
mod cli;
mod leaf;
mod memory;
mod payloads;
mod python;
mod reference;
mod synopsis;
mod tree;
mod typescript;

use clap::error::{ContextKind, ErrorKind};
use clap::{ArgMatches, FromArgMatches};
use cli::{Cli, Command, TreeArgs};
use std::process::ExitCode;
use sylva_core::params::{ParamKind, TreeParams};
use sylva_core::{presets, SylvaError};

fn main() -> ExitCode {
    memory::keep_freed_memory();
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(out) => {
            // A closed pipe (`sylva params | head`) is not an error worth a panic.
            use std::io::Write;
            let _ = writeln!(std::io::stdout().lock(), "{out}");
            ExitCode::SUCCESS
        }
        Err(msg) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
    }
}

/// Runs the command line `args` (without the program name): the text to print, or the error.
fn run(args: &[String]) -> Result<String, String> {
    let argv = std::iter::once("sylva".to_string()).chain(args.iter().cloned());
    let matches = match cli::command().try_get_matches_from(argv) {
        Ok(m) => m,
        // `sylva help`, `--help`, `-h`: printed like any output.
        Err(e) if e.kind() == ErrorKind::DisplayHelp => return Ok(e.render().to_string().trim_end().to_string()),
        Err(e) => return Err(usage_error(e)),
    };
    let mut cli = Cli::from_arg_matches(&matches).map_err(|e| e.to_string())?;
    // `--seed` and `--set seed=...` apply in the order given, like every `--set`.
    if let Some((_, m)) = matches.subcommand() {
        match &mut cli.command {
            Some(Command::Generate(a)) => a.tree.in_order = ordered_sets(m),
            Some(Command::Bench(a)) => a.tree.in_order = ordered_sets(m),
            _ => {}
        }
    }
    let Some(command) = cli.command else {
        return if cli.version { Ok(sylva_core::VERSION.to_string()) } else { Err(help_hint("no command given")) };
    };
    match command {
        Command::Generate(a) => tree::generate(&a),
        Command::Params { typescript: true, .. } => Ok(typescript::params_module()),
        Command::Params { payloads: true, .. } => Ok(payloads::payloads_module()),
        Command::Params { python_stub: true, .. } => Ok(python::stub()),
        Command::Params { markdown: true, .. } => Ok(reference::params_markdown()),
        Command::Params { .. } => Ok(sylva_core::params::registry_json()),
        Command::Presets => Ok(presets::presets_json()),
        Command::LeafPresets => Ok(sylva_core::leaf::presets::presets_json()),
        Command::Envelope { shape, samples } => {
            serde_json::to_string(&sylva_core::crown::envelope_profile(shape, samples)).map_err(|e| e.to_string())
        }
        Command::Bench(a) => tree::bench(&a),
        Command::Batch(a) => batch::batch(&a),
        Command::Leaf(a) => leaf::leaf(&a),
        Command::BenchLeaf(a) => leaf::bench(&a),
        Command::CliReference { json: true } => Ok(reference::cli_reference_json()),
        Command::CliReference { json: false } => Ok(reference::cli_reference_markdown()),
    }
}

/// `message` and where to read more.
fn help_hint(message: &str) -> String {
    format!("{message}\n{}", cli::command().render_usage())
}

/// clap's verdict in this command line's own words: a value parser's message is printed as it is; unknown options and commands, missing values and
/// missing options keep the messages the CLI always had.
fn usage_error(e: clap::Error) -> String {
    let context = |kind| e.get(kind).map(|v| v.to_string()).unwrap_or_default();
    // `--preset <NAME>` → `--preset`.
    let flag = || context(ContextKind::InvalidArg).split(' ').next().unwrap_or_default().to_string();
    let usage = || context(ContextKind::Usage);
    match e.kind() {
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => format!("no command given\n{}", e.render()),
        ErrorKind::ValueValidation => match std::error::Error::source(&e) {
            Some(inner) => inner.to_string(),
            None => e.to_string(),
        },
        ErrorKind::UnknownArgument => format!("unknown option '{}'\n{}", context(ContextKind::InvalidArg), usage()),
        ErrorKind::InvalidSubcommand => {
            format!("unknown command '{}'\n{}", context(ContextKind::InvalidSubcommand), usage())
        }
        ErrorKind::InvalidValue if context(ContextKind::InvalidValue).is_empty() => format!("{} needs a value", flag()),
        ErrorKind::MissingRequiredArgument => format!("{} is required", flag()),
        _ => e.to_string().trim_start_matches("error: ").trim_end().to_string(),
    }
}

/// The `--seed`, `--age` and `--set` values of a `generate` or `bench` command line, in the
/// order given.
fn ordered_sets(m: &ArgMatches) -> Vec<(String, String)> {
    let mut all: Vec<(usize, (String, String))> = Vec::new();
    for id in ["seed", "age"] {
        if let (Some(at), Some(values)) = (m.indices_of(id), m.get_many::<String>(id)) {
            all.extend(at.zip(values.map(|v| (id.to_string(), v.clone()))));
        }
    }
    if let (Some(at), Some(values)) = (m.indices_of("set"), m.get_many::<(String, String)>("set")) {
        all.extend(at.zip(values.cloned()));
    }
    all.sort_by_key(|(at, _)| *at);
    all.into_iter().map(|(_, kv)| kv).collect()
}

/// The tree of a command line: the preset (or the defaults), the `--seed`/`--set` values in
/// order, the volume primitives and the hand edits.
fn tree_params(a: &TreeArgs) -> Result<TreeParams, String> {
    let known: Vec<&str> = presets::PRESETS.iter().map(|p| p.name).collect();
    let find = |name: &str| presets::find(name).map(|p| p.params());
    let mut params = preset_with_sets(a.preset.as_deref(), "preset", &known, find, &a.in_order)?;
    if let Some(path) = &a.volumes {
        let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read --volumes {path}: {e}"))?;
        params.skeleton.volumes = sylva_core::params::volumes::from_json(&text).map_err(|e| e.to_string())?;
    }
    if let Some(path) = &a.edits {
        let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read --edits {path}: {e}"))?;
        params.skeleton.edits =
            sylva_core::params::edits::from_json(&text).map_err(|e| format!("--edits {path}: {e}"))?;
    }
    Ok(params)
}

/// The parameters of preset `name` (or the defaults) with `sets` applied in order. `find` looks
/// a preset up; an unknown one is an error `unknown {what} 'name' (known: ...)` listing `known`.
fn preset_with_sets<E: std::fmt::Display>(
    name: Option<&str>,
    what: &str,
    known: &[&str],
    find: impl Fn(&str) -> Option<Result<TreeParams, E>>,
    sets: &[(String, String)],
) -> Result<TreeParams, String> {
    let mut p = match name {
        Some(name) => find(name)
            .ok_or_else(|| format!("unknown {what} '{name}' (known: {})", known.join(", ")))?
            .map_err(|e| e.to_string())?,
        None => TreeParams::default(),
    };
    for (k, v) in sets {
        p.set(k, parse_value(k, v)?).map_err(|e| e.to_string())?;
    }
    Ok(p)
}

/// A `--set` value: a number, `true`/`false`, or an enum option label.
fn parse_value(id: &str, v: &str) -> Result<f64, String> {
    if let Ok(n) = v.parse::<f64>() {
        return Ok(n);
    }
    match v {
        "true" => return Ok(1.0),
        "false" => return Ok(0.0),
        _ => {}
    }
    let spec = sylva_core::params::spec(id).ok_or_else(|| {
        SylvaError::UnknownParam { param: id.into(), message: format!("unknown parameter '{id}' (see `sylva params`)") }
            .to_string()
    })?;
    if spec.kind == ParamKind::Enum {
        let norm = |s: &str| s.chars().filter(|c| c.is_ascii_alphanumeric()).collect::<String>().to_ascii_lowercase();
        if let Some(i) = spec.options.iter().flatten().position(|o| norm(o) == norm(v)) {
            return Ok(i as f64);
        }
    }
    Err(format!("{id} ({}) must be a number, got '{v}'", spec.label))
}

/// The median of `v` (sorted in place).
fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(line: &str) -> Vec<String> {
        line.split_whitespace().skip(1).map(String::from).collect()
    }

    #[test]
    fn every_example_is_a_valid_command_line_and_every_command_has_one() {
        let cmd = cli::command();
        for c in cmd.get_subcommands() {
            assert!(!cli::examples(c.get_name()).is_empty(), "{} has no example", c.get_name());
        }
        for (name, examples) in cli::EXAMPLES {
            assert!(cmd.find_subcommand(name).is_some(), "example for unknown command {name}");
            for e in *examples {
                let argv = std::iter::once("sylva".to_string()).chain(args(e));
                assert!(cli::command().try_get_matches_from(argv).is_ok(), "{e}");
            }
        }
    }

    #[test]
    fn seed_and_set_apply_in_the_order_given() {
        let parse = |line: &str| {
            let argv = std::iter::once("sylva".to_string()).chain(args(line));
            let m = cli::command().try_get_matches_from(argv).expect("valid");
            ordered_sets(m.subcommand().expect("a command").1)
        };
        let kv = |k: &str, v: &str| (k.to_string(), v.to_string());
        assert_eq!(
            parse("sylva generate --set seed=5 --seed 3 --set levels=2"),
            [kv("seed", "5"), kv("seed", "3"), kv("levels", "2")]
        );
        assert_eq!(parse("sylva bench --seed 3 --set seed=5"), [kv("seed", "3"), kv("seed", "5")]);
        assert_eq!(
            parse("sylva generate --age 12 --set age=20 --seed 2"),
            [kv("age", "12"), kv("age", "20"), kv("seed", "2")]
        );
    }
}
