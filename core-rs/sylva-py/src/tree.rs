//! A generated tree for Python: the core's buffers moved (not copied) into NumPy arrays, the
//! rest of the core's `Generated` kept for the exporters, and GLB/OBJ export that writes the
//! bytes `sylva generate --out` writes.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use sylva_core::export::ExportOptions;
use sylva_core::export::{bark_pngs, end_grain_pngs, leaf_pngs};
use sylva_core::mesh::WIND_STRIDE;
use sylva_core::Generated;

use crate::buffer::Buffer;
use crate::convert::{json_loads, py_err};
use crate::organs::OrganBuffers;

/// A generated tree. The mesh arrays are read-only NumPy views of the core's buffers (no copy):
/// `positions`, `normals` (float32, one row per vertex), `uvs` (float32, two columns) and
/// `indices` (uint32, one row per triangle) of the bark, the same `leaf_*` of the leaf mesh
/// (in leaf units: each leaf is that mesh placed by its transform), `leaf_transforms` (float32
/// 4x4 per leaf, `leaf_transforms[i] @ [x, y, z, 1]` places a leaf vertex in the tree) and
/// `leaf_colors` (RGB tint per leaf). `hash` is the content hash `sylva generate` prints.
#[pyclass(frozen, module = "sylva_trees")]
pub struct Tree {
    /// `Generated` without the buffers below (they live in NumPy).
    rest: Generated,
    /// The meta JSON, taken while `rest` still had its buffers (it counts them).
    meta_json: String,
    bark: [Buffer; 4],
    leaf: [Buffer; 4],
    matrices: Buffer,
    colors: Buffer,
    wind: Buffer,
    leaf_transforms: Py<PyAny>,
    /// The organ sets' arrays, in the order of `rest.foliage.organs`.
    organs: Vec<OrganBuffers>,
}

impl Tree {
    /// Moves `g`'s buffers into NumPy arrays.
    pub fn new(py: Python<'_>, mut g: Generated) -> PyResult<Self> {
        let meta_json = g.meta_json();
        let take = std::mem::take::<Vec<f32>>;
        let m = &mut g.mesh;
        let bark = [
            Buffer::new(py, take(&mut m.positions), 3)?,
            Buffer::new(py, take(&mut m.normals), 3)?,
            Buffer::new(py, take(&mut m.uvs), 2)?,
            Buffer::new(py, std::mem::take(&mut m.indices), 3)?,
        ];
        let f = &mut g.foliage;
        let leaf = [
            Buffer::new(py, take(&mut f.mesh.positions), 3)?,
            Buffer::new(py, take(&mut f.mesh.normals), 3)?,
            Buffer::new(py, take(&mut f.mesh.uvs), 2)?,
            Buffer::new(py, std::mem::take(&mut f.mesh.indices), 3)?,
        ];
        let wind = Buffer::new(py, take(&mut g.mesh.wind), WIND_STRIDE)?;
        let f = &mut g.foliage;
        let matrices = Buffer::new(py, take(&mut f.matrices), 16)?;
        let colors = Buffer::new(py, take(&mut f.colors), 3)?;
        let leaf_transforms = matrices.transposed(py)?;
        let organs = f.organs.iter_mut().map(|s| OrganBuffers::take(py, s)).collect::<PyResult<Vec<_>>>()?;
        Ok(Tree { rest: g, meta_json, bark, leaf, matrices, colors, wind, leaf_transforms, organs })
    }

    /// The whole `Generated` again (the buffers copied back from NumPy), for the exporters.
    fn whole(&self, py: Python<'_>) -> PyResult<Generated> {
        let mut g = self.rest.clone();
        let [p, n, uv, i] = &self.bark;
        (g.mesh.positions, g.mesh.normals, g.mesh.uvs, g.mesh.indices) =
            (p.to_vec(py)?, n.to_vec(py)?, uv.to_vec(py)?, i.to_vec(py)?);
        g.mesh.wind = self.wind.to_vec(py)?;
        let [p, n, uv, i] = &self.leaf;
        let f = &mut g.foliage;
        (f.mesh.positions, f.mesh.normals, f.mesh.uvs, f.mesh.indices) =
            (p.to_vec(py)?, n.to_vec(py)?, uv.to_vec(py)?, i.to_vec(py)?);
        f.matrices = self.matrices.to_vec(py)?;
        f.colors = self.colors.to_vec(py)?;
        for (set, b) in f.organs.iter_mut().zip(&self.organs) {
            b.restore(py, set)?;
        }
        Ok(g)
    }
}

/// Export options with `leaves` (`"instanced"`, `"baked"` or `"none"`) over the CLI's defaults.
fn options(leaves: &str) -> PyResult<ExportOptions> {
    let json = format!("{{\"leaves\":{}}}", serde_json::to_string(leaves).unwrap_or_default());
    ExportOptions::from_json(&json).map_err(py_err)
}

/// Writes `bytes` to `path`, an `OSError` naming the file when it cannot.
fn write(path: &std::path::Path, bytes: &[u8]) -> PyResult<()> {
    std::fs::write(path, bytes)
        .map_err(|e| pyo3::exceptions::PyOSError::new_err(format!("cannot write {}: {e}", path.display())))
}

#[pymethods]
impl Tree {
    /// The content hash (16 hex digits): the same as `sylva generate` and the studio print.
    #[getter]
    fn hash(&self) -> String {
        self.rest.hash_hex()
    }
    /// Bark vertex positions, float32 `(vertices, 3)`, metres.
    #[getter]
    fn positions(&self, py: Python<'_>) -> Py<PyAny> {
        self.bark[0].shaped.clone_ref(py)
    }
    /// Bark unit normals, float32 `(vertices, 3)`.
    #[getter]
    fn normals(&self, py: Python<'_>) -> Py<PyAny> {
        self.bark[1].shaped.clone_ref(py)
    }
    /// Bark texture coordinates, float32 `(vertices, 2)`.
    #[getter]
    fn uvs(&self, py: Python<'_>) -> Py<PyAny> {
        self.bark[2].shaped.clone_ref(py)
    }
    /// Bark triangles, uint32 `(triangles, 3)`.
    #[getter]
    fn indices(&self, py: Python<'_>) -> Py<PyAny> {
        self.bark[3].shaped.clone_ref(py)
    }
    /// The leaf mesh's positions, float32 `(vertices, 3)`, in leaf units.
    #[getter]
    fn leaf_positions(&self, py: Python<'_>) -> Py<PyAny> {
        self.leaf[0].shaped.clone_ref(py)
    }
    /// The leaf mesh's unit normals, float32 `(vertices, 3)`.
    #[getter]
    fn leaf_normals(&self, py: Python<'_>) -> Py<PyAny> {
        self.leaf[1].shaped.clone_ref(py)
    }
    /// The leaf mesh's texture coordinates, float32 `(vertices, 2)`.
    #[getter]
    fn leaf_uvs(&self, py: Python<'_>) -> Py<PyAny> {
        self.leaf[2].shaped.clone_ref(py)
    }
    /// The leaf mesh's triangles, uint32 `(triangles, 3)`.
    #[getter]
    fn leaf_indices(&self, py: Python<'_>) -> Py<PyAny> {
        self.leaf[3].shaped.clone_ref(py)
    }
    /// One float32 4x4 matrix per leaf, `(leaves, 4, 4)`: `leaf_transforms[i] @ [x, y, z, 1]`.
    #[getter]
    fn leaf_transforms(&self, py: Python<'_>) -> Py<PyAny> {
        self.leaf_transforms.clone_ref(py)
    }
    /// One RGB tint per leaf, float32 `(leaves, 3)`.
    #[getter]
    fn leaf_colors(&self, py: Python<'_>) -> Py<PyAny> {
        self.colors.shaped.clone_ref(py)
    }
    /// How many of the leaves, the last rows of `leaf_transforms` and `leaf_colors`, lie on
    /// the ground (**Fallen Leaves**, the Season); the rows before them are on the tree.
    #[getter]
    fn fallen_leaves(&self) -> usize {
        self.rest.foliage.fallen
    }
    /// The flowers, fruit, catkins and buds the Season gives the tree, one dict per kind of
    /// part: `kind` (`"petals"`, `"flower_centre"`, `"catkin"`, `"bud"`, `"fruit"`,
    /// `"fruit_part"`, `"stalk"`), `name`, `color` (sRGB), `roughness`, the part's mesh in metres
    /// (`positions`, `normals`, `indices`), `transforms` (float32 `(count, 4, 4)`) and `colors`
    /// (float32 `(count, 3)`, linear tints multiplying `color`); read-only NumPy arrays, no copy.
    #[getter]
    fn organs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyList>> {
        crate::organs::as_list(py, &self.rest.foliage.organs, &self.organs)
    }
    /// The wind record of each bark vertex, float32 `(vertices, 8)`: pivot x, y, z (the base of
    /// the vertex's stem, m), level (0 trunk to 3), phase (0..1), stiffness (0..1), distance from
    /// the root along the stems (m) and stem radius (m); `(0, 8)` when the mesh has none. The
    /// GLB's `_WIND_PIVOT` and `_WIND_PARAMS` (docs/formats.md, "Wind attributes") unquantised.
    #[getter]
    fn wind(&self, py: Python<'_>) -> Py<PyAny> {
        self.wind.shaped.clone_ref(py)
    }
    /// The textures the viewer draws, as PNG bytes by name: `bark_color`, `bark_normal`,
    /// `cut_face_color`, `cut_face_normal` (`bark_size` texels square, a power of two) and, when
    /// the tree has leaves, `leaf_color` and `leaf_normal`. Rows run top to bottom as in glTF: a
    /// texture coordinate `v` is a distance down from the top row.
    #[pyo3(signature = (bark_size=512))]
    fn textures<'py>(&self, py: Python<'py>, bark_size: u32) -> PyResult<Bound<'py, PyDict>> {
        let opts = ExportOptions::from_json(&format!("{{\"bark_texture_size\":{bark_size}}}")).map_err(py_err)?;
        let size = opts.bark_texture_size;
        let (bark, grain, leaf) = py.detach(|| {
            (bark_pngs(self.rest.bark, size), end_grain_pngs(self.rest.bark, size), leaf_pngs(&self.rest.foliage))
        });
        let out = PyDict::new(py);
        let put = |name: &str, png: &[u8]| out.set_item(name, pyo3::types::PyBytes::new(py, png));
        put("bark_color", &bark.color)?;
        put("bark_normal", &bark.normal)?;
        put("cut_face_color", &grain.color)?;
        put("cut_face_normal", &grain.normal)?;
        if let Some(leaf) = leaf {
            put("leaf_color", &leaf.color)?;
            put("leaf_normal", &leaf.normal)?;
        }
        Ok(out)
    }
    /// Counts, bounds, groups, leaf facts, hash and stage times as a dict (the studio's meta).
    #[getter]
    fn meta<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_loads(py, &self.meta_json)
    }
    /// What became of each hand edit, in list order: dicts `{op, resolved, why?, ...}`.
    #[getter]
    fn edits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_loads(py, &serde_json::to_string(&self.rest.edits).unwrap_or_default())
    }
    /// The tree as glTF 2.0 binary bytes; `leaves` is `"instanced"`, `"baked"` or `"none"`.
    #[pyo3(signature = (leaves="instanced"))]
    fn glb<'py>(&self, py: Python<'py>, leaves: &str) -> PyResult<Bound<'py, pyo3::types::PyBytes>> {
        let opts = options(leaves)?;
        let g = self.whole(py)?;
        let bytes = py.detach(|| sylva_core::export::to_glb(&g, &opts));
        Ok(pyo3::types::PyBytes::new(py, &bytes))
    }
    /// Writes the tree to `path` as a `.glb`, the bytes `sylva generate --out PATH --leaves
    /// LEAVES` writes. Returns the number of bytes written.
    #[pyo3(signature = (path, leaves="instanced"))]
    fn to_glb(&self, py: Python<'_>, path: std::path::PathBuf, leaves: &str) -> PyResult<usize> {
        let opts = options(leaves)?;
        let g = self.whole(py)?;
        let bytes = py.detach(|| sylva_core::export::to_glb(&g, &opts));
        write(&path, &bytes)?;
        Ok(bytes.len())
    }
    /// Writes the tree to `path` as Wavefront OBJ with its MTL and PNG textures beside it (named
    /// after the OBJ's stem), the files `sylva generate --out PATH` writes. Returns the paths
    /// written.
    fn to_obj(&self, py: Python<'_>, path: std::path::PathBuf) -> PyResult<Vec<std::path::PathBuf>> {
        let opts = ExportOptions::default();
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("tree").to_string();
        let dir = path.parent().map(std::path::Path::to_path_buf).unwrap_or_default();
        let g = self.whole(py)?;
        let files = py.detach(|| sylva_core::export::obj::write(&g, &opts, &stem));
        write(&path, files.obj.as_bytes())?;
        let mut written = vec![path.clone()];
        let side = std::iter::once((format!("{stem}.mtl"), files.mtl.into_bytes())).chain(files.textures);
        for (name, bytes) in side {
            let file = dir.join(name);
            write(&file, &bytes)?;
            written.push(file);
        }
        Ok(written)
    }
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let vertices = self.bark[0].shaped.bind(py).len()?;
        let triangles = self.bark[3].shaped.bind(py).len()?;
        let leaves = self.colors.shaped.bind(py).len()?;
        Ok(format!(
            "Tree(hash='{}', vertices={vertices}, triangles={triangles}, leaves={leaves})",
            self.rest.hash_hex()
        ))
    }
}
