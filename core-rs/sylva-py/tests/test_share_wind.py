"""Share links, growth primitives, wind records and textures of the Python package, from its
installed wheel: the links are the studio's (the fixtures its codec is tested against), the
trees the CLI's, the wind records the GLB's."""

import json
import os
import struct
import subprocess
from pathlib import Path

import numpy as np

import sylva_trees

ROOT = Path(__file__).resolve().parents[3]
CLI = os.environ.get("SYLVA_CLI") or str(ROOT / "target/release/sylva")
FIXTURES = json.loads((ROOT / "core-rs/sylva-core/tests/share_links.json").read_text())["links"]
VOLUMES = [
    {"kind": "sphere", "group": "crown", "centre": [0, 5.5, 0], "radius": 2},
    {"kind": "box", "group": "shadow", "centre": [-2, 1.5, 0.125], "size": [1, 3, 2]},
]


def cli(*args):
    """`sylva generate ARGS`'s JSON report."""
    out = subprocess.run([CLI, "generate", *args], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def test_links_are_the_studios():
    for f in FIXTURES:
        link = sylva_trees.share_link(
            preset=f.get("preset"), params=f["values"], edits=f.get("edits"), volumes=f.get("volumes")
        )
        assert link == f["link"], f["name"]


def test_a_link_grows_the_same_tree():
    f = next(f for f in FIXTURES if f["name"] == "a preset and a seed")
    read = sylva_trees.read_share_link("http://localhost:5173/?" + f["link"])
    assert read["messages"] == [] and read["edits"] == [] and read["volumes"] == []
    tree = sylva_trees.generate(params=read["params"])
    assert tree.hash == sylva_trees.generate(preset="oak", seed=7).hash == cli("--preset", "oak", "--seed", "7")["hash"]
    # Every value, so the defaults of the reader do not matter.
    assert len(read["params"]) == len(sylva_trees.params())


def test_a_bad_link_value_keeps_its_default_with_a_message():
    read = sylva_trees.read_share_link("?v=1&scale=huge&levels=2")
    assert read["params"]["levels"] == 2
    assert read["params"]["scale"] == next(p["default"] for p in sylva_trees.params() if p["id"] == "scale")
    assert len(read["messages"]) == 1 and read["messages"][0].startswith('Ignored "scale" from the link')


def test_volumes_are_the_clis_and_survive_a_link(tmp_path):
    path = tmp_path / "volumes.json"
    path.write_text(json.dumps(VOLUMES))
    params = {"growth_mode": 1, "crown_volume": 2, "markers": 800}
    tree = sylva_trees.generate(params=params, volumes=VOLUMES)
    sets = [a for k, v in params.items() for a in ("--set", f"{k}={v}")]
    assert tree.hash == cli(*sets, "--volumes", str(path))["hash"]
    read = sylva_trees.read_share_link(sylva_trees.share_link(params=params, volumes=VOLUMES))
    assert sylva_trees.generate(params=read["params"], volumes=read["volumes"]).hash == tree.hash


def test_wind_records_are_the_glbs(tmp_path):
    tree = sylva_trees.generate(params={"levels": 2})
    wind = tree.wind
    assert wind.shape == (len(tree.positions), 8) and wind.dtype == np.float32
    assert set(np.unique(wind[:, 3])) <= {0.0, 1.0, 2.0}
    # The trunk's pivot is its base; phase and stiffness lie in 0..1.
    assert np.allclose(wind[wind[:, 3] == 0, :3], 0.0, atol=1e-3)
    assert wind[:, 4:6].min() >= 0.0 and wind[:, 4:6].max() <= 1.0
    # The GLB quantises the pivot, distance and radius over the tree's own range: offset to
    # offset + scale is the range of these records.
    glb = tree.glb("none")
    length = struct.unpack_from("<I", glb, 12)[0]
    extras = json.loads(glb[20 : 20 + length])["meshes"][0]["extras"]["wind_attributes"]
    for name, k, column in (("_WIND_PIVOT", 0, 0), ("_WIND_PIVOT", 1, 1), ("_WIND_PIVOT", 2, 2),
                            ("_WIND_PARAMS", 2, 6), ("_WIND_PARAMS", 3, 7)):
        lo, scale = extras[name]["offset"][k], extras[name]["scale"][k]
        assert abs(wind[:, column].min() - lo) < 1e-3 and abs(wind[:, column].max() - (lo + scale)) < 1e-3, name
    assert not wind.flags.writeable


def test_textures_are_pngs():
    leafy = sylva_trees.generate(params={"levels": 2}).textures(bark_size=64)
    assert set(leafy) == {"bark_color", "bark_normal", "cut_face_color", "cut_face_normal", "leaf_color", "leaf_normal"}
    assert all(png.startswith(b"\x89PNG\r\n\x1a\n") for png in leafy.values())
    assert struct.unpack(">II", leafy["bark_color"][16:24]) == (64, 64)
    bare = sylva_trees.generate(params={"levels": 2, "leaves": 0}).textures(bark_size=64)
    assert "leaf_color" not in bare
