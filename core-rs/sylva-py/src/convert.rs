//! Python values to the core's inputs and the core's errors to Python exceptions: a dict of
//! parameter values applied like the CLI's `--set` (numbers, booleans, enum option labels), a
//! hand edit list and growth primitives from dicts or JSON, JSON text to Python objects.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};
use sylva_core::params::{edits::Edit, norm, spec, ParamKind, TreeParams};
use sylva_core::SylvaError;

pyo3::create_exception!(
    sylva_trees,
    BudgetError,
    PyValueError,
    "The tree would exceed a budget (vertices, stems, leaves, ...): the message names the budget parameter."
);

/// The core's error as a Python exception with the core's message: a budget overrun is a
/// [`BudgetError`], everything else a `ValueError`.
pub fn py_err(e: SylvaError) -> PyErr {
    match e {
        SylvaError::Budget { message, .. } => BudgetError::new_err(message),
        other => PyValueError::new_err(other.to_string()),
    }
}

/// Sets every `id: value` of the mapping `values` on `p`, in the mapping's order, checked
/// against the registry like every other input.
pub fn apply_params(p: &mut TreeParams, values: &Bound<'_, PyAny>) -> PyResult<()> {
    let dict = values.cast::<PyDict>().map_err(|_| PyValueError::new_err("params must be a dict of id: number"))?;
    for (key, value) in dict.iter() {
        let id: String =
            key.extract().map_err(|_| PyValueError::new_err("params' keys must be parameter ids (str)"))?;
        let v = value_of(&id, &value)?;
        p.set(&id, v).map_err(py_err)?;
    }
    Ok(())
}

/// The wire number of one parameter value: a number, a bool (0 or 1), or an enum option's label
/// (compared without case or separators, as the CLI's `--set` does).
fn value_of(id: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    if let Ok(b) = value.cast::<PyBool>() {
        return Ok(f64::from(u8::from(b.is_true())));
    }
    let unknown = || {
        py_err(SylvaError::UnknownParam {
            param: id.into(),
            message: format!("unknown parameter '{id}' (see sylva_trees.params())"),
        })
    };
    if let Ok(label) = value.cast::<PyString>() {
        let spec = spec(id).ok_or_else(unknown)?;
        let label: String = label.extract()?;
        let label = label.as_str();
        let found = (spec.kind == ParamKind::Enum)
            .then(|| spec.options.iter().flatten().position(|o| norm(o) == norm(label)))
            .flatten();
        return found.map(|i| i as f64).ok_or_else(|| {
            let options = spec.options.as_deref().unwrap_or_default().join(", ");
            let expected =
                if options.is_empty() { "a number".to_string() } else { format!("a number or one of {options}") };
            PyValueError::new_err(format!("{id} ({}) must be {expected}, got '{label}'", spec.label))
        });
    }
    value.extract::<f64>().map_err(|_| {
        let label = spec(id).map_or(String::new(), |s| format!(" ({})", s.label));
        PyValueError::new_err(format!("{id}{label} must be a number, got {}", type_name(value)))
    })
}

fn type_name(value: &Bound<'_, PyAny>) -> String {
    value.get_type().name().map_or_else(|_| "?".to_string(), |n| n.to_string())
}

/// A hand edit list: JSON text, or Python lists and dicts in the same form (turned into that
/// text by Python's `json`), parsed and checked by the core.
pub fn edits(value: &Bound<'_, PyAny>) -> PyResult<Vec<Edit>> {
    let text: String = match value.cast::<PyString>() {
        Ok(s) => s.extract()?,
        Err(_) => value.py().import("json")?.call_method1("dumps", (value,))?.extract()?,
    };
    sylva_core::params::edits::from_json(&text).map_err(py_err)
}

/// Growth primitives: JSON text, or Python lists and dicts in the `"volumes"` form, parsed and
/// checked by the core.
pub fn volumes(value: &Bound<'_, PyAny>) -> PyResult<Vec<sylva_core::params::VolumePrimitive>> {
    let text: String = match value.cast::<PyString>() {
        Ok(s) => s.extract()?,
        Err(_) => value.py().import("json")?.call_method1("dumps", (value,))?.extract()?,
    };
    sylva_core::params::volumes::from_json(&text).map_err(py_err)
}

/// JSON text as Python objects (`json.loads`).
pub fn json_loads<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}
