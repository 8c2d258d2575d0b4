
class _ParamSpecRequired(TypedDict):
    id: ParamId
    group: str
    label: str
    kind: Literal["float", "int", "bool", "enum"]
    default: float
    min: float
    max: float
    step: float
    unit: str
    description: str
    stage: Literal["skeleton", "mesh", "foliage", "leaf", "viewer"]

class ParamSpec(_ParamSpecRequired, total=False):
    """One parameter of the registry, as ``params()`` lists it (``options``: enums only)."""

    options: list[str]

class Preset(TypedDict):
    """One tree preset, as ``presets()`` lists it: ``values`` are its numbers by parameter id."""

    name: PresetName
    label: str
    description: str
    leaf: str
    values: dict[str, float]

class BudgetError(ValueError):
    """The tree would exceed a budget (vertices, stems, leaves, ...): the message names the budget parameter."""

class Tree:
    """A generated tree. The arrays are read-only NumPy views of the core's buffers (no copy)."""

    @property
    def hash(self) -> str:
        """The content hash (16 hex digits): the same as ``sylva generate`` and the studio print."""
    @property
    def positions(self) -> npt.NDArray[np.float32]:
        """Bark vertex positions, ``(vertices, 3)``, metres."""
    @property
    def normals(self) -> npt.NDArray[np.float32]:
        """Bark unit normals, ``(vertices, 3)``."""
    @property
    def uvs(self) -> npt.NDArray[np.float32]:
        """Bark texture coordinates, ``(vertices, 2)``."""
    @property
    def indices(self) -> npt.NDArray[np.uint32]:
        """Bark triangles, ``(triangles, 3)``."""
    @property
    def leaf_positions(self) -> npt.NDArray[np.float32]:
        """The leaf mesh's positions, ``(vertices, 3)``, in leaf units."""
    @property
    def leaf_normals(self) -> npt.NDArray[np.float32]:
        """The leaf mesh's unit normals, ``(vertices, 3)``."""
    @property
    def leaf_uvs(self) -> npt.NDArray[np.float32]:
        """The leaf mesh's texture coordinates, ``(vertices, 2)``."""
    @property
    def leaf_indices(self) -> npt.NDArray[np.uint32]:
        """The leaf mesh's triangles, ``(triangles, 3)``."""
    @property
    def leaf_transforms(self) -> npt.NDArray[np.float32]:
        """One 4x4 matrix per leaf, ``(leaves, 4, 4)``: ``leaf_transforms[i] @ [x, y, z, 1]``."""
    @property
    def leaf_colors(self) -> npt.NDArray[np.float32]:
        """One RGB tint per leaf, ``(leaves, 3)``."""
    @property
    def fallen_leaves(self) -> int:
        """How many leaves, the last rows of ``leaf_transforms`` and ``leaf_colors``, lie on the ground."""
    @property
    def organs(self) -> list[dict[str, Any]]:
        """Flowers, fruit, catkins and buds, one dict per kind of part: ``kind``, ``name``, ``color`` (sRGB), ``roughness``, ``positions``, ``normals``, ``indices``, ``transforms`` ``(count, 4, 4)``, ``colors`` ``(count, 3)``."""
    @property
    def wind(self) -> npt.NDArray[np.float32]:
        """Per bark vertex ``(vertices, 8)``: pivot x, y, z, level, phase, stiffness, distance, radius."""
    def textures(self, bark_size: int = 512) -> dict[str, bytes]:
        """PNG bytes by name: ``bark_color``, ``bark_normal``, ``cut_face_color``, ``cut_face_normal``, ``leaf_color``, ``leaf_normal``."""
    @property
    def meta(self) -> dict[str, Any]:
        """Counts, bounds, groups, leaf facts, hash and stage times (the studio's meta)."""
    @property
    def edits(self) -> list[dict[str, Any]]:
        """What became of each hand edit, in list order: ``{op, resolved, why?}``."""
    def glb(self, leaves: Literal["instanced", "baked", "none"] = "instanced") -> bytes:
        """The tree as glTF 2.0 binary bytes."""
    def to_glb(self, path: str | PathLike[str], leaves: Literal["instanced", "baked", "none"] = "instanced") -> int:
        """Writes the bytes ``sylva generate --out PATH --leaves LEAVES`` writes; returns their count."""
    def to_obj(self, path: str | PathLike[str]) -> list[Path]:
        """Writes OBJ, MTL and PNG textures (named after the OBJ's stem) as ``sylva generate --out PATH``; returns the paths."""

def generate(
    preset: PresetName | None = None,
    seed: float | None = None,
    params: Params | None = None,
    edits: Sequence[Mapping[str, Any]] | Mapping[str, Any] | str | None = None,
    volumes: Sequence[Mapping[str, Any]] | str | None = None,
) -> Tree:
    """Grow a tree: the preset (or the registry's defaults), then ``params``, then ``seed``, then
    the hand edits (dicts in the edit-list JSON form of docs/formats.md, or that JSON as text)
    and the growth primitives (the ``"volumes"`` JSON form). Raises ``ValueError`` with the
    core's message, ``BudgetError`` past a budget."""

def share_link(
    preset: PresetName | None = None,
    seed: float | None = None,
    params: Params | None = None,
    edits: Sequence[Mapping[str, Any]] | Mapping[str, Any] | str | None = None,
    volumes: Sequence[Mapping[str, Any]] | str | None = None,
) -> str:
    """The studio's share-link query (``v=1&id=value&...``) of the tree ``generate`` grows from
    the same arguments."""

class SharedTree(TypedDict):
    """A share link read by ``read_share_link``."""

    params: dict[str, float]
    volumes: list[dict[str, Any]]
    edits: list[dict[str, Any]]
    messages: list[str]

def read_share_link(link: str) -> SharedTree:
    """A share link (an address or its query) read as the studio reads it: every value, the
    primitives, the edits and what was ignored."""

def presets() -> list[Preset]:
    """The tree presets (``sylva presets``)."""

def params() -> list[ParamSpec]:
    """The parameter registry in panel order (``sylva params``)."""

def core_version() -> str:
    """The core's version."""
