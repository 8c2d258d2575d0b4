"""The tree's settings on its bark object (`object.sylva`), built from the core's parameter
registry (`sylva_trees.params()`): one property per parameter with the registry's label, range,
step and description, so the panel lists every parameter without a hand-written list. A change
regenerates the tree. Seeds reach 4,294,967,295, past Blender's 32-bit integers: those are text
fields holding the whole number."""

import json

import bpy
import sylva_trees

#: Integers above this do not fit a Blender IntProperty.
INT_MAX = 2**31 - 1

REGISTRY = sylva_trees.params()
PRESETS = sylva_trees.presets()
BY_ID = {spec["id"]: spec for spec in REGISTRY}

#: While true, property updates do not regenerate (a preset or a link sets many at once).
_quiet = [False]


def wide(spec):
    """Whether the parameter is a whole number too large for an IntProperty."""
    return spec["kind"] == "int" and spec["max"] > INT_MAX


def _regenerate(self, context):
    if not _quiet[0] and self.is_tree:
        from . import build

        build.regenerate(self.id_data)


def _decimals(step):
    text = f"{step:.10f}".rstrip("0")
    return max(0, len(text.split(".")[1])) if "." in text else 0


def _label(spec):
    return f"{spec['label']} ({spec['unit']})" if spec["unit"] else spec["label"]


def _property(spec):
    """The Blender property of one registry entry."""
    name, text = _label(spec), spec["description"]
    kind = spec["kind"]
    if kind == "bool":
        return bpy.props.BoolProperty(name=name, description=text, default=bool(spec["default"]), update=_regenerate)
    if kind == "enum":
        items = [(str(i), label, text) for i, label in enumerate(spec["options"])]
        return bpy.props.EnumProperty(
            name=name, description=text, items=items, default=str(int(spec["default"])), update=_regenerate
        )
    if wide(spec):
        default = str(int(spec["default"]))
        return bpy.props.StringProperty(name=name, description=text, default=default, update=_regenerate)
    if kind == "int":
        return bpy.props.IntProperty(
            name=name, description=text, default=int(spec["default"]), min=int(spec["min"]), max=int(spec["max"]),
            update=_regenerate,
        )
    return bpy.props.FloatProperty(
        name=name, description=text, default=spec["default"], min=spec["min"], max=spec["max"],
        step=max(1, round(spec["step"] * 100)), precision=min(6, max(1, _decimals(spec["step"]))),
        update=_regenerate,
    )


def _apply_preset(self, context):
    if self.preset != "CUSTOM" and not _quiet[0]:
        set_values(self, preset_values(self.preset))
        _regenerate(self, context)


def preset_values(name):
    """Every parameter's value for preset `name`: the defaults, then the preset's values."""
    values = {spec["id"]: spec["default"] for spec in REGISTRY}
    values.update(next(p for p in PRESETS if p["name"] == name)["values"])
    return values


def values(settings):
    """The parameters as wire numbers by id, the form `sylva_trees.generate(params=...)` takes."""
    out = {}
    for spec in REGISTRY:
        v = getattr(settings, spec["id"])
        if spec["kind"] == "enum":
            v = int(v)
        elif wide(spec):
            v = int(v) if v.strip().isdigit() else spec["default"]
        out[spec["id"]] = float(v) if spec["kind"] == "float" else int(v)
    return out


def set_values(settings, numbers):
    """Sets the properties from wire numbers by id without regenerating."""
    _quiet[0] = True
    try:
        for key, v in numbers.items():
            spec = BY_ID.get(key)
            if spec is None:
                continue
            if spec["kind"] == "enum":
                v = str(int(v))
            elif spec["kind"] == "bool":
                v = bool(v)
            elif wide(spec):
                v = str(int(v))
            elif spec["kind"] == "int":
                v = int(v)
            setattr(settings, key, v)
    finally:
        _quiet[0] = False


def structured(settings):
    """The growth primitives and hand edits a pasted link brought, as `generate` takes them."""
    return json.loads(settings.volumes_json or "[]"), json.loads(settings.edits_json or "[]")


def _settings_class():
    annotations = {
        "is_tree": bpy.props.BoolProperty(default=False, options={"HIDDEN"}),
        "preset": bpy.props.EnumProperty(
            name="Preset",
            description="Set every parameter to a preset's values",
            items=[(p["name"], p["label"], p["description"]) for p in PRESETS]
            + [("CUSTOM", "Custom", "Values from a share link")],
            update=_apply_preset,
        ),
        "tree_hash": bpy.props.StringProperty(name="Hash", description="The core's content hash of this tree"),
        "volumes_json": bpy.props.StringProperty(options={"HIDDEN"}),
        "edits_json": bpy.props.StringProperty(options={"HIDDEN"}),
        "leaves_object": bpy.props.PointerProperty(type=bpy.types.Object, options={"HIDDEN"}),
        "leaf_shape_object": bpy.props.PointerProperty(type=bpy.types.Object, options={"HIDDEN"}),
    }
    for spec in REGISTRY:
        assert spec["id"] not in annotations, f"parameter {spec['id']} clashes with a setting"
        annotations[spec["id"]] = _property(spec)
    return type("SylvaTreeSettings", (bpy.types.PropertyGroup,), {"__annotations__": annotations})


_classes = []


def register():
    cls = _settings_class()
    bpy.utils.register_class(cls)
    _classes.append(cls)
    bpy.types.Object.sylva = bpy.props.PointerProperty(type=cls)


def unregister():
    del bpy.types.Object.sylva
    while _classes:
        bpy.utils.unregister_class(_classes.pop())
