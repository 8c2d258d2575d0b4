"""Flowers, fruit, catkins and buds from Python (the Season): the oak bearing acorns in September
has its acorn sets as read-only NumPy arrays that view the core's buffers (no copy), with the
layouts the docstrings give; the January tree's fallen leaves are counted; a tree in July has
none; and the GLB written from Python is the CLI's, organ nodes included."""

import json
import os
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pytest

import sylva_trees

CLI = os.environ.get("SYLVA_CLI") or str(Path(__file__).resolve().parents[3] / "target/release/sylva")


@pytest.fixture(scope="module")
def oak_september():
    # Fruit 1 = Acorns (the registry's Fruit options), mid-September.
    return sylva_trees.generate(preset="oak", params={"fruit": 1, "season": 9.5})


def test_the_acorn_sets_and_their_layouts(oak_september):
    sets = oak_september.organs
    assert sorted(s["name"] for s in sets) == ["acorn cups", "acorn stalks", "acorns"]
    acorns = next(s for s in sets if s["name"] == "acorns")
    assert acorns["kind"] == "fruit"
    assert len(acorns["color"]) == 3 and all(0 <= c <= 1 for c in acorns["color"])
    assert 0 < acorns["roughness"] <= 1
    for s in sets:
        n = s["colors"].shape[0]
        assert n > 20, s["name"]
        assert s["transforms"].shape == (n, 4, 4)
        assert s["positions"].dtype == np.float32 and s["positions"].shape[1] == 3
        assert s["normals"].shape == s["positions"].shape
        assert s["indices"].dtype == np.uint32 and s["indices"].max() < s["positions"].shape[0]
        # Matrices that multiply column vectors: the last row is (0, 0, 0, 1).
        assert np.allclose(s["transforms"][:, 3, :], [0, 0, 0, 1])
        for key in ("positions", "normals", "indices", "transforms", "colors"):
            a = s[key]
            assert not a.flags.owndata and a.base is not None, (s["name"], key)
            assert not a.flags.writeable, (s["name"], key)
    # An acorn, its cup and its stalk hang at the same place: the sets pair up.
    cups = next(s for s in sets if s["name"] == "acorn cups")
    assert cups["transforms"].shape == acorns["transforms"].shape
    # The acorns hang in the crown: above the ground, below the tree's top.
    heights = acorns["transforms"][:, 1, 3]
    top = oak_september.meta["bounds"]["max"][1]
    assert heights.min() > 0.5 and heights.max() <= top


def test_july_has_none_and_january_has_fallen_leaves():
    july = sylva_trees.generate(preset="oak")
    assert july.organs == [] and july.fallen_leaves == 0
    january = sylva_trees.generate(params={"season": 1.5})
    assert [s["kind"] for s in january.organs] == ["bud"]
    fallen = january.fallen_leaves
    assert fallen == january.leaf_colors.shape[0] > 100
    # The fallen ones lie on the ground.
    assert np.all(january.leaf_transforms[-fallen:, 1, 3] < 0.3)


def test_the_glb_is_the_clis_with_the_organ_nodes(oak_september):
    glb = oak_september.glb()
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "oak.glb"
        subprocess.run(
            [CLI, "generate", "--preset", "oak", "--set", "fruit=1", "--set", "season=9.5", "--out", str(out)],
            check=True,
            capture_output=True,
        )
        assert out.read_bytes() == glb
    length = int.from_bytes(glb[12:16], "little")
    doc = json.loads(glb[20 : 20 + length])
    names = {n.get("name") for n in doc["nodes"]}
    assert {"acorns", "acorn cups", "acorn stalks"} <= names
