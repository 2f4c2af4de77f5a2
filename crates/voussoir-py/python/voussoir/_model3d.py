"""3D models: OBJ/PLY meshes, supports as polyhedra, the dimension of a model's JSON."""

from __future__ import annotations

import os
from typing import List, NamedTuple, Optional, Sequence, Union

import numpy as np

from . import _native

PathOrStr = Union[str, "os.PathLike[str]"]


class Support3d(NamedTuple):
    """A support of a 3D model: its name, vertices (n×3, m), faces (vertex index lists),
    prescribed motion (u, v, w in m; θx, θy, θz in rad about its centroid) and connection
    (``"contact"`` or ``"fixed"``)."""

    name: str
    vertices: np.ndarray
    faces: List[List[int]]
    motion: np.ndarray
    connection: str


def dim_of(d: dict) -> int:
    """3 when the model's first block (or, without blocks, first support) has ``vertices``,
    as the library decides (``AnyModel::from_json``)."""
    for key in ("blocks", "supports"):
        items = d.get(key) or []
        if items:
            return 3 if "vertices" in items[0] else 2
    return 2


def supports3d(d: dict) -> List[Support3d]:
    return [
        Support3d(
            s["name"],
            np.array(s["vertices"], dtype=float).reshape(-1, 3),
            [list(f) for f in s["faces"]],
            np.array(s.get("motion", [0.0] * 6), dtype=float),
            s.get("connection", "contact"),
        )
        for s in d["supports"]
    ]


def is_mesh(path: str) -> bool:
    return os.path.splitext(path)[1].lower() in (".obj", ".ply")


def read_mesh(
    path: PathOrStr,
    *,
    units: Optional[str] = None,
    unit_weight: float = 18.0,
    supports: Union[str, Sequence[str]] = (),
    support_prefix: Optional[str] = None,
    weld: Optional[float] = None,
    live: str = "horizontal",
):
    if isinstance(supports, str):
        supports = [supports]
    return _native.model_from_mesh(
        os.fspath(path),
        units,
        float(unit_weight),
        [str(s) for s in supports],
        support_prefix,
        None if weld is None else float(weld),
        str(live),
    )
