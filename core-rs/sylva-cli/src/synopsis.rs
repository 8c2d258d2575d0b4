//! A command's synopsis (`sylva NAME [--flag VALUE]...`) from its clap declaration: the usage
//! line of `sylva help` ([`crate::cli`]) and of the generated references ([`crate::reference`]).
//! A module of its own so that both use it without importing each other.

use clap::ArgAction;

/// A command's full synopsis: `sylva NAME` and every option, `[--flag VALUE]`, `...` when it
/// repeats, without brackets when it is required.
pub fn synopsis(cmd: &clap::Command) -> String {
    synopsis_parts(cmd).join(" ")
}

/// [`synopsis`] wrapped at `width` columns for text that starts at column `column`: the
/// continuation lines are indented by `column + 4`.
pub fn synopsis_wrapped(cmd: &clap::Command, column: usize, width: usize) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for part in synopsis_parts(cmd) {
        if !line.is_empty() && column + line.len() + 1 + part.len() > width {
            lines.push(std::mem::take(&mut line));
            line = " ".repeat(4);
        }
        if !line.trim().is_empty() {
            line.push(' ');
        }
        line.push_str(&part);
    }
    lines.push(line);
    lines.join(&format!("\n{}", " ".repeat(column)))
}

/// The words of [`synopsis`]: the command, then one per option.
fn synopsis_parts(cmd: &clap::Command) -> Vec<String> {
    let mut parts = vec![format!("sylva {}", cmd.get_name())];
    for a in cmd.get_arguments().filter(|a| shown(a)) {
        let mut s = flag(a);
        if !a.is_required_set() {
            s = format!("[{s}]");
        }
        if matches!(a.get_action(), ArgAction::Append) {
            s.push_str("...");
        }
        parts.push(s);
    }
    parts
}

/// Declared options (not clap's own `--help`, nor hidden ones).
pub fn shown(a: &clap::Arg) -> bool {
    !a.is_hide_set() && a.get_id() != "help" && a.get_long().is_some()
}

/// `--flag` or `--flag VALUE`.
pub fn flag(a: &clap::Arg) -> String {
    let long = format!("--{}", a.get_long().unwrap_or_default());
    match (a.get_action().takes_values(), a.get_value_names()) {
        (true, Some(names)) => format!("{long} {}", names.iter().map(|n| n.as_str()).collect::<Vec<_>>().join(" ")),
        _ => long,
    }
}
