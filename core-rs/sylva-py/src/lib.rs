//! Python binding of `sylva-core`, the extension module `sylva_trees._sylva` of the Python
//! package `sylva-trees` (docs/python.md). Like `sylva-wasm` it only converts: Python values in
//! ([`convert`]), NumPy arrays that own the core's buffers and export files out ([`tree`]),
//! share links to and from the core's codec ([`share`]), the core's errors as Python exceptions
//! with the core's messages.

use pyo3::prelude::*;
use sylva_core::params::TreeParams;
use sylva_core::presets as core_presets;

mod buffer;
mod convert;
mod organs;
mod share;
mod tree;

use convert::{py_err, BudgetError};
use tree::Tree;

/// Grow a tree. `preset` names a preset (see `presets()`; none = the registry's defaults),
/// `params` maps parameter ids (see `params()`) to numbers, booleans or enum option labels and is
/// applied over the preset, `seed` is applied last, `edits` is a list of hand edits (dicts in
/// the edit-list JSON form, or that JSON as a string), `volumes` a list of growth primitives
/// (dicts in the `"volumes"` JSON form, or that JSON). The same input gives the same `hash` as
/// `sylva generate` and the studio. Raises `ValueError` with the core's message for invalid
/// input and `BudgetError` (a `ValueError`) when the tree would exceed a budget.
#[pyfunction]
#[pyo3(signature = (preset=None, seed=None, params=None, edits=None, volumes=None))]
fn generate(
    py: Python<'_>,
    preset: Option<&str>,
    seed: Option<f64>,
    params: Option<&Bound<'_, PyAny>>,
    edits: Option<&Bound<'_, PyAny>>,
    volumes: Option<&Bound<'_, PyAny>>,
) -> PyResult<Tree> {
    let p = tree_params(preset, seed, params, edits, volumes)?;
    let generated = py.detach(|| sylva_core::generate(&p)).map_err(py_err)?;
    Tree::new(py, generated)
}

/// The core's parameters of `generate`'s arguments.
pub(crate) fn tree_params(
    preset: Option<&str>,
    seed: Option<f64>,
    params: Option<&Bound<'_, PyAny>>,
    edits: Option<&Bound<'_, PyAny>>,
    volumes: Option<&Bound<'_, PyAny>>,
) -> PyResult<TreeParams> {
    let mut p = match preset {
        Some(name) => core_presets::find(name).ok_or_else(|| unknown_preset(name))?.params().map_err(py_err)?,
        None => TreeParams::default(),
    };
    if let Some(values) = params {
        convert::apply_params(&mut p, values)?;
    }
    if let Some(seed) = seed {
        p.set("seed", seed).map_err(py_err)?;
    }
    if let Some(edits) = edits {
        p.skeleton.edits = convert::edits(edits)?;
    }
    if let Some(volumes) = volumes {
        p.skeleton.volumes = convert::volumes(volumes)?;
    }
    Ok(p)
}

/// The error for a preset name no preset has, in the CLI's words.
fn unknown_preset(name: &str) -> PyErr {
    let known: Vec<&str> = core_presets::PRESETS.iter().map(|p| p.name).collect();
    pyo3::exceptions::PyValueError::new_err(format!("unknown preset '{name}' (known: {})", known.join(", ")))
}

/// The presets: a list of dicts `{name, label, description, leaf, values}` where `values` maps
/// parameter ids to the preset's numbers (`sylva presets`).
#[pyfunction]
fn presets(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    convert::json_loads(py, &core_presets::presets_json())
}

/// The parameter registry: a list of dicts `{id, group, label, kind, default, min, max, step,
/// unit, description, options?, stage}` in panel order (`sylva params`).
#[pyfunction]
fn params(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    convert::json_loads(py, &sylva_core::params::registry_json())
}

/// The core's version.
#[pyfunction]
fn core_version() -> &'static str {
    sylva_core::VERSION
}

/// The extension module.
#[pymodule]
fn _sylva(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(generate, m)?)?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(params, m)?)?;
    m.add_function(wrap_pyfunction!(core_version, m)?)?;
    m.add_function(wrap_pyfunction!(share::share_link, m)?)?;
    m.add_function(wrap_pyfunction!(share::read_share_link, m)?)?;
    m.add_class::<Tree>()?;
    m.add("BudgetError", m.py().get_type::<BudgetError>())?;
    Ok(())
}
