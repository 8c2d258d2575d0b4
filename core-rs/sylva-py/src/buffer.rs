//! One core buffer in NumPy ([`Buffer`]): the `Vec` moved (not copied) into a read-only array,
//! its shaped view, and the copy back for the exporters. The tree's and the organ sets' arrays
//! are all such buffers.

use numpy::{Element, PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// One buffer: the flat array that owns the core's `Vec` and its shaped, read-only view.
pub(crate) struct Buffer {
    flat: Py<PyAny>,
    pub(crate) shaped: Py<PyAny>,
}

impl Buffer {
    /// Moves `data` into NumPy (the array takes the `Vec`'s allocation) and views it as rows of
    /// `width`; both are read-only, so the arrays stay the tree the hash was taken of.
    pub(crate) fn new<T: Element>(py: Python<'_>, data: Vec<T>, width: usize) -> PyResult<Self> {
        let rows = data.len() / width;
        let flat = PyArray1::from_vec(py, data);
        let no_write = PyDict::new(py);
        no_write.set_item("write", false)?;
        flat.call_method("setflags", (), Some(&no_write))?;
        let shaped = flat.reshape([rows, width])?;
        Ok(Buffer { flat: flat.into_any().unbind(), shaped: shaped.into_any().unbind() })
    }

    /// A copy of the data back in a `Vec`, for the exporters.
    pub(crate) fn to_vec<T: Element + Copy>(&self, py: Python<'_>) -> PyResult<Vec<T>> {
        let array = self.flat.bind(py).cast::<PyArray1<T>>()?;
        Ok(array.readonly().as_slice()?.to_vec())
    }

    /// Rows of 16 column-major floats as `(count, 4, 4)` matrices that multiply column vectors:
    /// rows of 16 as (4, 4) are the transposes, so the last two axes are swapped (a strided
    /// view, no copy).
    pub(crate) fn transposed(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let count = self.shaped.bind(py).len()?;
        Ok(self
            .flat
            .bind(py)
            .call_method1("reshape", ((count, 4, 4),))?
            .call_method1("transpose", ((0, 2, 1),))?
            .unbind())
    }
}
