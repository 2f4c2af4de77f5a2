"""The model: blocks and supports (polygons in metres), materials and loads."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _model3d, _native, _options
from ._io import write_atomic

PathOrStr = Union[str, "os.PathLike[str]"]


class Support(NamedTuple):
    """A support (foundation): its name, polygon (n×2, m), prescribed motion (u, v, θ in m, m,
    rad) and connection (``"contact"`` or ``"fixed"``)."""

    name: str
    polygon: np.ndarray
    motion: np.ndarray
    connection: str


class Model:
    """A 2D or 3D masonry model, as the CLI reads it (README, "Model format"; a 3D model's
    blocks are polyhedra with ``vertices`` and ``faces``, z up: docs/3d.md).

    Build one with :meth:`from_json`, :meth:`from_dxf`, :meth:`from_dict` or a generator in
    :mod:`voussoir.generate`. A model is immutable; :meth:`to_dict` gives an editable copy and
    :meth:`from_dict` reads it back. Models pickle (as their JSON), so they travel to the
    workers of an executor.
    """

    __slots__ = ("_json", "_data", "_import_summary")

    def __init__(self, _json: str, _import_summary: Optional[Tuple[str, List[str]]] = None):
        # Internal: use the constructors below. `_json` is canonical model JSON.
        self._json = _json
        self._data: Optional[dict] = None
        self._import_summary = _import_summary

    # --- constructors -----------------------------------------------------------------------

    @classmethod
    def from_json(cls, path_or_str: Union[PathOrStr, bytes]) -> "Model":
        """A model from a JSON file path, or from JSON text (a string starting with ``{``).

        Raises :class:`voussoir.ModelError` with the CLI's message if the file cannot be read or
        is not a valid model (unknown fields are rejected)."""
        if isinstance(path_or_str, bytes):
            path_or_str = path_or_str.decode("utf-8")
        if isinstance(path_or_str, str) and path_or_str.lstrip().startswith("{"):
            return cls(_native.model_any_from_text(path_or_str)[1])
        path = os.fspath(path_or_str)
        if _model3d.is_mesh(path):
            return cls.from_mesh(path)
        return cls(_native.model_any_from_path(path)[1])

    @classmethod
    def from_mesh(cls, path: PathOrStr, **kw) -> "Model":
        """A 3D model from an OBJ or PLY mesh, as ``voussoir import model.obj`` (docs/import3d.md):
        each OBJ object or group, each closed PLY part, is a block. Keywords are the CLI's mesh
        import flags: ``units`` (``"mm"``, ``"cm"``, ``"m"``; default m), ``unit_weight``
        (kN/m³, default 18), ``supports`` (body names that are supports; default: the bodies on
        the ground plane), ``support_prefix``, ``weld`` (m), ``live`` (``"horizontal"``, the
        default, or ``"none"``). The import summary is in :attr:`import_summary`."""
        text, summary, notes = _model3d.read_mesh(path, **kw)
        return cls(text, (summary, list(notes)))

    @classmethod
    def from_dict(cls, data: Dict[str, Any]) -> "Model":
        """A model from a dict with the JSON model's structure."""
        return cls(_native.model_any_from_text(json.dumps(data))[1])

    @classmethod
    def from_dxf(
        cls,
        path: PathOrStr,
        *,
        units: Optional[str] = None,
        unit_weight: float = 18.0,
        dxf_width: float = 1.0,
        support_layers: Sequence[str] = (),
        support_handles: Sequence[str] = (),
        weld: Optional[float] = None,
        live: Optional[str] = None,
        merge_tolerance: Optional[float] = None,
        dxf_live: Optional[str] = None,
    ) -> "Model":
        """A model from a DXF drawing (closed polylines are blocks), as ``voussoir import``.

        Keywords are the CLI's DXF flags: ``units`` (``"mm"``, ``"cm"``, ``"m"``; default the
        drawing's ``$INSUNITS``), ``unit_weight`` (kN/m³), ``dxf_width`` (m), ``support_layers``
        and ``support_handles`` (default: the lowest, widest polygon is the support ``base``),
        ``weld`` (m; vertices closer are merged), ``live`` (``"horizontal"``, the default:
        tilting-table loads, or ``"none"``). ``merge_tolerance`` and ``dxf_live`` are the old
        names of ``weld`` and ``live``. The import summary is in :attr:`import_summary`."""
        merge_tolerance = _options.renamed("weld", weld, "merge_tolerance", merge_tolerance)
        dxf_live = _options.renamed("live", live, "dxf_live", dxf_live) or "horizontal"
        text, summary, notes = _native.model_from_dxf(
            os.fspath(path),
            units,
            float(unit_weight),
            float(dxf_width),
            [str(s) for s in support_layers],
            [str(s) for s in support_handles],
            merge_tolerance,
            dxf_live,
        )
        return cls(text, (summary, list(notes)))

    # --- views ------------------------------------------------------------------------------

    def _d(self) -> dict:
        if self._data is None:
            self._data = json.loads(self._json)
        return self._data

    def to_json(self, path: Optional[PathOrStr] = None) -> str:
        """The model as JSON (byte-identical to ``voussoir gen … -o``); written atomically to
        ``path`` if given."""
        if path is not None:
            write_atomic(path, self._json.encode("utf-8"))
        return self._json

    def to_dict(self) -> dict:
        """An editable copy of the model as a dict."""
        return json.loads(self._json)

    @property
    def description(self) -> str:
        return self._d().get("description", "")

    @property
    def dim(self) -> int:
        """2 for a planar model (polygons), 3 for a spatial one (polyhedra)."""
        return _model3d.dim_of(self._d())

    @property
    def blocks(self) -> List[np.ndarray]:
        """The block polygons: one (n_i × 2) array of vertices (m) per block; in 3D one
        (n_i × 3) array of each block's vertices (its faces: :attr:`block_faces`)."""
        key = "vertices" if self.dim == 3 else "polygon"
        return [np.array(b[key], dtype=float) for b in self._d()["blocks"]]

    @property
    def block_faces(self) -> List[List[List[int]]]:
        """3D: each block's faces as lists of vertex indices (counter-clockwise seen from
        outside); 2D: raises ``ValueError``."""
        if self.dim != 3:
            raise ValueError("block_faces: the model is 2D (its blocks are polygons)")
        return [[list(f) for f in b["faces"]] for b in self._d()["blocks"]]

    @property
    def supports(self) -> List[Support]:
        """The supports, with their polygons and prescribed motions. In 3D each is a
        :class:`voussoir.Support3d` (vertices, faces, motion u, v, w, θx, θy, θz)."""
        if self.dim == 3:
            return _model3d.supports3d(self._d())
        out = []
        for s in self._d()["supports"]:
            out.append(
                Support(
                    s["name"],
                    np.array(s["polygon"], dtype=float),
                    np.array(s.get("motion", [0.0, 0.0, 0.0]), dtype=float),
                    s.get("connection", "contact"),
                )
            )
        return out

    @property
    def support_names(self) -> List[str]:
        return [s["name"] for s in self._d()["supports"]]

    @property
    def materials(self) -> dict:
        return json.loads(json.dumps(self._d().get("materials", {})))

    @property
    def import_summary(self) -> Optional[str]:
        """For a model read from DXF: the import summary (blocks, supports, units)."""
        return None if self._import_summary is None else self._import_summary[0]

    def check(self, tolerance: Optional[float] = None) -> Tuple[int, int, int]:
        """Validate the model (as every analysis does) and return (blocks, joints, supports).
        Raises :class:`voussoir.ModelError` naming the bad block."""
        return _native.model_any_check(self._json, tolerance)

    def to_obj(self, path: Optional[PathOrStr] = None) -> str:
        """3D: the model as OBJ text (``voussoir export``: each block the object ``block_i``,
        each support ``support_NAME``; :meth:`from_mesh` reads it back); written atomically to
        ``path`` if given."""
        text = _native.model_to_obj(self._json)
        if path is not None:
            write_atomic(path, text.encode("utf-8"))
        return text

    def svg(self, title: Optional[str] = None) -> str:
        """An SVG drawing of the model and its loads (``voussoir plot model.json``)."""
        return _native.draw_svg(self._json, None, False, title)

    def save_png(self, path: PathOrStr, title: Optional[str] = None) -> None:
        """Write a PNG drawing of the model (atomically)."""
        write_atomic(path, _native.svg_to_png(self.svg(title)))

    def _repr_svg_(self) -> Optional[str]:
        try:
            return self.svg()
        except Exception:  # an invalid model has no drawing; the repr must not raise
            return None

    def __repr__(self) -> str:
        d = self._d()
        kind = " 3D" if self.dim == 3 else ""
        return f"<voussoir.Model{kind}: {len(d['blocks'])} blocks, {len(d['supports'])} supports>"

    def __len__(self) -> int:
        return len(self._d()["blocks"])

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Model) and other._json == self._json

    def __hash__(self) -> int:
        return hash(self._json)

    def __reduce__(self):
        return (_model_from_canonical, (self._json, self._import_summary))


def _model_from_canonical(text: str, summary=None) -> Model:
    return Model(text, summary)
