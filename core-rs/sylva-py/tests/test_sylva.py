"""The Python package `sylva_trees` end to end, from its installed wheel: the same hash and the
same export bytes as the `sylva` CLI (the binary in $SYLVA_CLI, scripts/python.sh builds it),
NumPy arrays that view the core's buffers without a copy, the registry and presets, and the
core's error messages as Python exceptions."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import sylva_trees

CLI = os.environ.get("SYLVA_CLI") or str(Path(__file__).resolve().parents[3] / "target/release/sylva")


def cli(*args):
    """`sylva generate ARGS`'s JSON report."""
    out = subprocess.run([CLI, "generate", *args], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


@pytest.fixture(scope="module")
def oak():
    return sylva_trees.generate(preset="oak")


def test_the_hash_is_the_clis(oak):
    assert oak.hash == cli("--preset", "oak")["hash"]
    # The golden hash of core-rs/sylva-core/tests/determinism.rs (the studio's, through wasm).
    assert oak.hash == "4a112b7870f4654e"
    assert sylva_trees.generate(seed=7).hash == cli("--seed", "7")["hash"]
    assert sylva_trees.generate(seed=7).hash != sylva_trees.generate().hash


def test_params_apply_over_the_preset_like_set(oak):
    tree = sylva_trees.generate(preset="oak", params={"l1_branches": 12, "leaves": False, "bark_type": "smooth banded"})
    want = cli("--preset", "oak", "--set", "l1_branches=12", "--set", "leaves=false", "--set", "bark_type=smooth-banded")
    assert tree.hash == want["hash"]
    assert tree.hash != oak.hash
    assert tree.leaf_colors.shape == (0, 3)


def test_edits_as_dicts_or_json_are_the_clis(tmp_path):
    plain = sylva_trees.generate()
    # A cut at the bark point farthest out along +x (resolves), and a bend in the air (does not).
    tip = plain.positions[np.argmax(plain.positions[:, 0])].tolist()
    edits = [{"op": "cut", "at": tip}, {"op": "bend", "at": [2.0, 5.5, 0.0], "to": [2.3, 4.6, 0.0]}]
    path = tmp_path / "edits.json"
    path.write_text(json.dumps(edits))
    want = cli("--edits", str(path))
    from_dicts = sylva_trees.generate(edits=edits)
    assert from_dicts.hash == want["hash"]
    assert sylva_trees.generate(edits=json.dumps(edits)).hash == want["hash"]
    assert from_dicts.edits == want["edits"]
    assert [e["resolved"] for e in from_dicts.edits] == [True, False]
    assert from_dicts.hash != plain.hash


def test_arrays_are_read_only_views_of_the_cores_buffers(oak):
    meta = oak.meta
    shapes = {
        "positions": (meta["vertices"], 3),
        "normals": (meta["vertices"], 3),
        "uvs": (meta["vertices"], 2),
        "indices": (meta["triangles"], 3),
        "leaf_colors": (meta["leaves"], 3),
        "leaf_transforms": (meta["leaves"], 4, 4),
    }
    for name, shape in shapes.items():
        array = getattr(oak, name)
        assert isinstance(array, np.ndarray) and array.shape == shape, name
        assert array.dtype == (np.uint32 if name == "indices" else np.float32), name
        # No copy: the array does not own its data; its base chain ends in the moved Rust Vec.
        assert not array.flags.owndata and array.base is not None, name
        assert not array.flags.writeable, name
        with pytest.raises(ValueError):
            array.setflags(write=True)
        # The same memory every time it is read.
        assert array.__array_interface__["data"][0] == getattr(oak, name).__array_interface__["data"][0]
    assert oak.leaf_positions.shape[1] == 3 and oak.leaf_indices.dtype == np.uint32
    assert int(oak.indices.max()) < meta["vertices"]
    assert np.allclose(np.linalg.norm(oak.normals[:1000], axis=1), 1.0, atol=1e-3)
    # The transforms multiply column vectors: the last row is (0, 0, 0, 1).
    assert np.array_equal(oak.leaf_transforms[:, 3], np.tile([0, 0, 0, 1], (meta["leaves"], 1)))
    lo, hi = oak.positions.min(axis=0), oak.positions.max(axis=0)
    assert np.allclose(lo, meta["bounds"]["min"], atol=1e-4) and np.allclose(hi, meta["bounds"]["max"], atol=1e-4)


@pytest.mark.parametrize("leaves", ["instanced", "baked"])
def test_glb_bytes_are_the_clis(oak, tmp_path, leaves):
    ours, theirs = tmp_path / "py.glb", tmp_path / "cli.glb"
    written = oak.to_glb(ours, leaves=leaves)
    cli("--preset", "oak", "--leaves", leaves, "--out", str(theirs))
    assert ours.read_bytes() == theirs.read_bytes()
    assert written == theirs.stat().st_size
    assert oak.glb(leaves) == theirs.read_bytes()


def test_obj_files_are_the_clis(tmp_path):
    tree = sylva_trees.generate(preset="fir")
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    written = tree.to_obj(tmp_path / "py" / "fir.obj")
    cli("--preset", "fir", "--out", str(tmp_path / "cli" / "fir.obj"))
    names = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(p.name for p in written) == names and "fir.mtl" in names
    for name in names:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name


def test_presets_and_params_carry_the_registry():
    presets = {p["name"]: p for p in sylva_trees.presets()}
    assert {"default", "oak", "fir", "weeping_willow"} <= presets.keys()
    assert presets["oak"]["label"] and presets["oak"]["description"]
    params = {p["id"]: p for p in sylva_trees.params()}
    assert params["l1_length"]["min"] == 0 and params["l1_length"]["max"] == 2
    assert params["bark_type"]["kind"] == "enum" and "Smooth-banded" in params["bark_type"]["options"]
    assert all(p["label"] and p["description"] for p in params.values())


def test_errors_are_value_errors_with_the_cores_messages():
    with pytest.raises(ValueError, match=r"^l1_length \(Length\) is -1: allowed range is 0 to 2$"):
        sylva_trees.generate(params={"l1_length": -1})
    with pytest.raises(ValueError, match=r"^unknown parameter 'no_such'"):
        sylva_trees.generate(params={"no_such": 1})
    with pytest.raises(ValueError, match=r"^unknown preset 'elm' \(known: default, .*oak"):
        sylva_trees.generate(preset="elm")
    with pytest.raises(ValueError, match=r"^bark_type \(Bark Type\) must be a number or one of .*Smooth-banded"):
        sylva_trees.generate(params={"bark_type": "velvet"})
    with pytest.raises(ValueError, match=r"must be a number, got list"):
        sylva_trees.generate(params={"scale": [1]})
    with pytest.raises(ValueError, match=r"^edits"):
        sylva_trees.generate(edits=[{"op": "fly"}])
    with pytest.raises(ValueError, match="leaves"):
        sylva_trees.generate().glb(leaves="flat")


def test_a_budget_overrun_is_a_budget_error():
    params = {p["id"]: p for p in sylva_trees.params()}
    assert "max_vertices" in params
    with pytest.raises(sylva_trees.BudgetError, match="max_vertices") as caught:
        sylva_trees.generate(preset="oak", params={"max_vertices": params["max_vertices"]["min"]})
    assert isinstance(caught.value, ValueError)


def test_the_type_stub_matches_the_package_and_the_registry():
    """The installed stub (generated by `sylva params --python-stub`) names what there is."""
    import ast

    stub = Path(sylva_trees.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text(encoding="utf-8"))
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    keys = [n.target.id for n in classes["Params"].body if isinstance(n, ast.AnnAssign)]
    assert keys == [p["id"] for p in sylva_trees.params()]
    literals = {
        n.targets[0].id: [e.value for e in n.value.slice.elts] for n in tree.body
        if isinstance(n, ast.Assign) and isinstance(n.value, ast.Subscript)
    }
    assert literals["PresetName"] == [p["name"] for p in sylva_trees.presets()]
    assert literals["BarkTypeOption"] == next(p["options"] for p in sylva_trees.params() if p["id"] == "bark_type")
    members = {n.name for n in classes["Tree"].body if isinstance(n, ast.FunctionDef)}
    assert members == {m for m in dir(sylva_trees.Tree) if not m.startswith("_")}
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert functions | {"BudgetError", "Tree"} == set(sylva_trees.__all__)
    # Every key carries the registry's description as its docstring.
    scale = keys.index("scale")
    docs = [n.value.value for n in classes["Params"].body if isinstance(n, ast.Expr)][1:]
    assert docs[scale].startswith("Scale (Tree, float; 0.1 to 100 m; default 13 m): Overall size")
