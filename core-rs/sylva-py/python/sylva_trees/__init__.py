"""Sylva's procedural trees in Python: the Rust core through a thin pyo3 binding.

``generate(preset="oak")`` grows a tree whose ``hash`` is the one ``sylva generate`` and the
studio show for the same input; its mesh is in NumPy arrays that own the core's buffers (no
copy), and ``to_glb``/``to_obj`` write the files ``sylva generate --out`` writes. ``presets()``
and ``params()`` list what there is, with the registry's labels, ranges and descriptions.
Invalid input raises ``ValueError`` with the core's message; a budget overrun raises
``BudgetError`` (a ``ValueError``). ``share_link`` and ``read_share_link`` exchange trees with
the studio's share links. See docs/python.md.
"""

from ._sylva import (
    BudgetError,
    Tree,
    core_version,
    generate,
    params,
    presets,
    read_share_link,
    share_link,
)

__all__ = [
    "BudgetError",
    "Tree",
    "core_version",
    "generate",
    "params",
    "presets",
    "read_share_link",
    "share_link",
]
