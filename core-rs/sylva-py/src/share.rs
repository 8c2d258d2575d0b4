//! Share links through the core's codec (`sylva_core::share`): a tree's arguments to the
//! studio's `v=1&id=value&...` query, and a link back to every value, the growth primitives, the
//! hand edits and the messages about what was ignored.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use sylva_core::params::{edits, registry, volumes};

use crate::convert::json_loads;

/// The share-link query (`v=1&id=value&...`, no `?`) of the tree `generate` would grow from the
/// same arguments: the studio opens `<its address>?<query>` as the same tree (same `hash`).
/// Hand edits longer than 2,000 characters in the link are left out, as the studio does.
#[pyfunction]
#[pyo3(signature = (preset=None, seed=None, params=None, edits=None, volumes=None))]
pub fn share_link(
    preset: Option<&str>,
    seed: Option<f64>,
    params: Option<&Bound<'_, PyAny>>,
    edits: Option<&Bound<'_, PyAny>>,
    volumes: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    let p = crate::tree_params(preset, seed, params, edits, volumes)?;
    Ok(sylva_core::share::encode(&p))
}

/// Reads a share link (a whole address or its query) as the studio does: a dict with `params`
/// (every parameter's value by id: `generate(params=...)` grows the link's tree), `volumes` and
/// `edits` (the JSON forms `generate` takes) and `messages` (what was ignored and why; a bad
/// value keeps its default). Never raises for a bad link.
#[pyfunction]
pub fn read_share_link<'py>(py: Python<'py>, link: &str) -> PyResult<Bound<'py, PyDict>> {
    let decoded = sylva_core::share::decode(link);
    let p = &decoded.params;
    let values = PyDict::new(py);
    for spec in registry() {
        if let Some(v) = p.get(&spec.id) {
            values.set_item(&spec.id, v)?;
        }
    }
    let out = PyDict::new(py);
    out.set_item("params", values)?;
    out.set_item("volumes", json_loads(py, &volumes::to_json_value(&p.skeleton.volumes).to_string())?)?;
    out.set_item("edits", json_loads(py, &edits::to_json_value(&p.skeleton.edits).to_string())?)?;
    out.set_item("messages", decoded.messages)?;
    Ok(out)
}
