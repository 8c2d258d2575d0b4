//! A tree's flowers, fruit, catkins and buds for Python (`sylva_core::organs::OrganSet`): each
//! set's arrays moved into read-only NumPy arrays as the leaves' are (no copy), handed out as a
//! list of dicts; the sets' other fields stay in the tree for the exporters.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use sylva_core::organs::OrganSet;

use crate::buffer::Buffer;

/// One set's arrays in NumPy.
pub(crate) struct OrganBuffers {
    positions: Buffer,
    normals: Buffer,
    uvs: Buffer,
    indices: Buffer,
    matrices: Buffer,
    colors: Buffer,
    /// `(count, 4, 4)` view of `matrices` as matrices that multiply column vectors.
    transforms: Py<PyAny>,
}

impl OrganBuffers {
    /// Moves `set`'s arrays into NumPy (the set keeps its kind, name, colour and roughness).
    pub(crate) fn take(py: Python<'_>, set: &mut OrganSet) -> PyResult<Self> {
        let take = std::mem::take::<Vec<f32>>;
        let m = &mut set.mesh;
        let (positions, normals, uvs) = (
            Buffer::new(py, take(&mut m.positions), 3)?,
            Buffer::new(py, take(&mut m.normals), 3)?,
            Buffer::new(py, take(&mut m.uvs), 2)?,
        );
        let indices = Buffer::new(py, std::mem::take(&mut m.indices), 3)?;
        let matrices = Buffer::new(py, take(&mut set.matrices), 16)?;
        let colors = Buffer::new(py, take(&mut set.colors), 3)?;
        let transforms = matrices.transposed(py)?;
        Ok(OrganBuffers { positions, normals, uvs, indices, matrices, colors, transforms })
    }

    /// The arrays copied back into `set`, for the exporters.
    pub(crate) fn restore(&self, py: Python<'_>, set: &mut OrganSet) -> PyResult<()> {
        let m = &mut set.mesh;
        (m.positions, m.normals, m.uvs, m.indices) =
            (self.positions.to_vec(py)?, self.normals.to_vec(py)?, self.uvs.to_vec(py)?, self.indices.to_vec(py)?);
        (set.matrices, set.colors) = (self.matrices.to_vec(py)?, self.colors.to_vec(py)?);
        Ok(())
    }
}

/// The sets as a list of dicts: `kind`, `name`, `color` (sRGB, 3 floats), `roughness`,
/// `positions` and `normals` (float32 `(vertices, 3)`, metres), `indices` (uint32
/// `(triangles, 3)`), `transforms` (float32 `(count, 4, 4)`, `transforms[i] @ [x, y, z, 1]`)
/// and `colors` (float32 `(count, 3)`, linear tints multiplying `color`).
pub(crate) fn as_list<'py>(
    py: Python<'py>,
    sets: &[OrganSet],
    buffers: &[OrganBuffers],
) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for (set, b) in sets.iter().zip(buffers) {
        let d = PyDict::new(py);
        let kind = serde_json::to_value(set.kind).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default();
        d.set_item("kind", kind)?;
        d.set_item("name", set.name)?;
        d.set_item("color", (set.color[0], set.color[1], set.color[2]))?;
        d.set_item("roughness", set.roughness)?;
        d.set_item("positions", b.positions.shaped.clone_ref(py))?;
        d.set_item("normals", b.normals.shaped.clone_ref(py))?;
        d.set_item("indices", b.indices.shaped.clone_ref(py))?;
        d.set_item("transforms", b.transforms.clone_ref(py))?;
        d.set_item("colors", b.colors.shaped.clone_ref(py))?;
        list.append(d)?;
    }
    Ok(list)
}
