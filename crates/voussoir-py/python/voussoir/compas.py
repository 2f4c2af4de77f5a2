"""COMPAS interoperability: COMPAS block assemblies (``compas_assembly`` / ``compas_cra``) saved
as JSON, read as voussoir models, and results written back for COMPAS viewers.

3D assemblies of block meshes (compas_assembly, compas_dem) are read by
:func:`read_assembly3d` and results written back by :func:`write_results3d` (module
``voussoir._compas3d``). For 2D analyses of prisms:

* **Input**: the JSON that ``compas.json_dump(assembly)`` writes for a
  ``compas_assembly.datastructures.Assembly`` (COMPAS 1.x/2.x: ``{"dtype":
  "compas_assembly.datastructures/Assembly", "data": {"graph": {"data": {"node": {...}}}}}``),
  also without the outer ``dtype``/``data`` wrapper, and the older
  ``{"assembly": …, "blocks": {key: mesh data}}`` layout. Each node's ``block`` is a COMPAS
  mesh (``vertex``: key → {x, y, z}; ``face``: key → vertex keys); a node whose attribute
  ``is_support`` is true becomes a voussoir support named ``support<key>``, every other node a
  block (in increasing key order).
* **Only prisms**: every block must be a right prism extruded along one axis, ``y`` (COMPAS's
  z-up convention: the section lies in the x–z plane and z is vertical) or ``z`` (the section
  lies in the x–y plane and y is vertical); the cross-section polygon is read from the block's
  cap faces (triangulated caps are fine). A block that is not such a prism is refused with a
  :class:`voussoir.ModelError` naming its node. The out-of-plane width of each block is its
  extent along the extrusion axis; the unit weight is the ``unit_weight`` keyword (kN/m³) or the
  block's ``unit_weight`` attribute.
* **Output** (:func:`write_results`): a copy of the assembly JSON in which each graph edge
  between two touching nodes carries ``interfaces``: one ``compas_assembly`` Interface per
  voussoir joint, whose ``points`` are the joint's two collocation points at both faces of the
  prism (4 points), ``frame`` has ``zaxis`` = the joint normal (from the edge's first node into
  its second, as voussoir's normal from body *a* into *b*), ``xaxis`` in the section plane and
  ``yaxis`` = the extrusion axis, and ``forces`` lists per point ``{"c_np", "c_nn", "c_u",
  "c_v"}`` (compressive normal force, 0, shear along ``xaxis``, 0), in kN, half of each
  collocation point's force on each face — the structure ``compas_cra``'s viewers read. Each
  free node gets ``displacement`` = [dx, dy, dz, rx, ry, rz] (m, rad) of its block centroid.
  Edges are written for every voussoir joint (interfaces detected by voussoir, not by
  ``compas_assembly``).
"""

from __future__ import annotations

import copy
import json
import math
import os
from typing import Any, Dict, List, Optional, Tuple, Union

from ._compas3d import assembly_model3d, read_assembly3d, write_results3d
from ._model import Model
from ._native import ModelError

__all__ = [
    "read_assembly",
    "assembly_model",
    "write_results",
    "read_assembly3d",
    "assembly_model3d",
    "write_results3d",
]

_AXES = {"y": (0, 2, 1), "z": (0, 1, 2)}  # (section x, section y, extrusion) coordinate indices


def _load(src: Union[str, "os.PathLike[str]", dict]) -> dict:
    if isinstance(src, dict):
        return src
    text = os.fspath(src)
    if isinstance(text, str) and text.lstrip().startswith("{"):
        return json.loads(text)
    try:
        with open(text, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise ModelError(f"cannot read {text}: {e.strerror}") from None
    except ValueError as e:
        raise ModelError(f"{text}: not JSON: {e}") from None


def _unwrap(d: Any) -> Any:
    """COMPAS data objects are ``{"dtype": …, "data": {…}}``; return the inner data."""
    while isinstance(d, dict) and "dtype" in d and "data" in d:
        d = d["data"]
    return d


def _nodes(data: dict) -> List[Tuple[str, dict, bool, dict]]:
    """(key, mesh data, is_support, node attributes) of each node, by increasing key."""
    d = _unwrap(data)
    if isinstance(d, dict) and "assembly" in d and "blocks" in d:  # older layout
        a = _unwrap(d["assembly"])
        attrs = a.get("vertex") or a.get("node") or {}
        out = []
        for key, mesh in d["blocks"].items():
            at = attrs.get(key, {})
            out.append((str(key), _unwrap(mesh), bool(at.get("is_support", False)), at))
    else:
        g = _unwrap(d.get("graph", d)) if isinstance(d, dict) else None
        nodes = g.get("node") if isinstance(g, dict) else None
        if not isinstance(nodes, dict):
            raise ModelError(
                "not a COMPAS assembly: expected data.graph.data.node (compas_assembly Assembly JSON)"
            )
        out = []
        for key, at in nodes.items():
            block = at.get("block")
            if block is None:
                raise ModelError(f"COMPAS node {key}: has no block mesh")
            out.append((str(key), _unwrap(block), bool(at.get("is_support", False)), at))

    def order(k):
        try:
            return (0, int(k[0]), "")
        except ValueError:
            return (1, 0, k[0])

    return sorted(out, key=order)


def _section(key: str, mesh: dict, axis: str, tol: float) -> Tuple[List[List[float]], float]:
    """The cross-section polygon (counter-clockwise) and width of a prism mesh."""
    ix, iy, ie = _AXES[axis]
    verts = mesh.get("vertex")
    faces = mesh.get("face")
    if not isinstance(verts, dict) or not isinstance(faces, dict) or not verts or not faces:
        raise ModelError(f"COMPAS node {key}: block is not a mesh (expected vertex and face)")
    xyz = {}
    for vk, v in verts.items():
        try:
            xyz[str(vk)] = (float(v["x"]), float(v["y"]), float(v["z"]))
        except (KeyError, TypeError, ValueError):
            raise ModelError(f"COMPAS node {key}: vertex {vk} has no x, y, z") from None
    es = [p[ie] for p in xyz.values()]
    lo, hi = min(es), max(es)
    size = max(max(p[i] for p in xyz.values()) - min(p[i] for p in xyz.values()) for i in range(3))
    eps = tol * max(size, 1e-12)
    width = hi - lo
    if width <= eps:
        raise ModelError(f"COMPAS node {key}: block has no extent along {axis}")
    bottom = {k for k, p in xyz.items() if abs(p[ie] - lo) <= eps}
    top = {k for k, p in xyz.items() if abs(p[ie] - hi) <= eps}
    if len(bottom) + len(top) != len(xyz):
        raise ModelError(
            f"COMPAS node {key}: block is not a prism extruded along {axis} (vertices between its two faces); only 2D prisms are supported until 3D lands"
        )
    sec = lambda k: (xyz[k][ix], xyz[k][iy])  # noqa: E731
    low = sorted(sec(k) for k in bottom)
    high = sorted(sec(k) for k in top)
    if len(low) != len(high) or any(
        math.hypot(a[0] - b[0], a[1] - b[1]) > eps for a, b in zip(low, high)
    ):
        raise ModelError(
            f"COMPAS node {key}: block is not a right prism extruded along {axis} (its two faces differ)"
        )
    # Boundary of the bottom cap: edges of cap faces used once (caps may be triangulated).
    count: Dict[Tuple[str, str], int] = {}
    for f in faces.values():
        fk = [str(x) for x in f]
        if not fk or not all(x in bottom for x in fk):
            continue
        for a, b in zip(fk, fk[1:] + fk[:1]):
            e = (min(a, b), max(a, b))
            count[e] = count.get(e, 0) + 1
    boundary = {e for e, c in count.items() if c == 1}
    if not boundary:
        raise ModelError(f"COMPAS node {key}: block has no cap face normal to {axis}")
    nxt: Dict[str, str] = {}
    for f in faces.values():
        fk = [str(x) for x in f]
        if not fk or not all(x in bottom for x in fk):
            continue
        for a, b in zip(fk, fk[1:] + fk[:1]):
            if (min(a, b), max(a, b)) in boundary:
                if a in nxt:
                    raise ModelError(f"COMPAS node {key}: cap face boundary is not one loop")
                nxt[a] = b
    start = next(iter(nxt))
    loop = [start]
    while True:
        n = nxt.get(loop[-1])
        if n is None:
            raise ModelError(f"COMPAS node {key}: cap face boundary is not closed")
        if n == start:
            break
        if n in loop:
            raise ModelError(f"COMPAS node {key}: cap face boundary is not one loop")
        loop.append(n)
    if len(loop) != len(nxt) or len(loop) < 3:
        raise ModelError(
            f"COMPAS node {key}: block section is not a single polygon (holes are not supported)"
        )
    poly = [list(sec(k)) for k in loop]
    area2 = sum(
        poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
        for i in range(len(poly))
    )
    if area2 < 0:
        poly.reverse()
    # Drop vertices on straight edges (a cap triangulation may add none, but meshes may carry
    # collinear points that would make zero-length joints).
    out = []
    n = len(poly)
    for i in range(n):
        a, b, c = poly[i - 1], poly[i], poly[(i + 1) % n]
        cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        if abs(cross) > eps * eps:
            out.append(b)
    return out, width


def _detect_axis(nodes, tol: float) -> str:
    for axis in ("y", "z"):
        try:
            for key, mesh, _, _ in nodes:
                _section(key, mesh, axis, tol)
            return axis
        except ModelError:
            continue
    # Report the first failure for the default axis.
    for key, mesh, _, _ in nodes:
        _section(key, mesh, "y", tol)
    raise ModelError("COMPAS assembly: blocks are not prisms along y or z")  # pragma: no cover


def read_assembly(
    src: Union[str, "os.PathLike[str]", dict],
    *,
    axis: Optional[str] = None,
    unit_weight: float = 18.0,
    tolerance: float = 1e-6,
    description: str = "",
) -> Model:
    """Read a COMPAS block assembly (a JSON path, JSON text or the loaded dict) as a
    :class:`voussoir.Model`; see the module docstring for what is supported.

    ``axis``: the extrusion axis, ``"y"`` or ``"z"`` (default: the first that fits every block).
    ``unit_weight``: kN/m³ (a node's ``unit_weight`` attribute overrides it). ``tolerance``:
    relative tolerance of the prism check. The model has self-weight only (add live loads with
    :meth:`Model.to_dict` / :meth:`Model.from_dict`)."""
    return assembly_model(src, axis=axis, unit_weight=unit_weight, tolerance=tolerance, description=description)[0]


def assembly_model(
    src: Union[str, "os.PathLike[str]", dict],
    *,
    axis: Optional[str] = None,
    unit_weight: float = 18.0,
    tolerance: float = 1e-6,
    description: str = "",
) -> Tuple[Model, Dict[str, Any]]:
    """As :func:`read_assembly`, also returning the mapping used by :func:`write_results`:
    ``{"axis", "blocks": [node keys], "supports": {name: node key}, "offset": extrusion
    coordinate of each block's faces}``."""
    data = _load(src)
    nodes = _nodes(data)
    if not nodes:
        raise ModelError("COMPAS assembly: no blocks")
    if axis is None:
        axis = _detect_axis(nodes, tolerance)
    if axis not in _AXES:
        raise ValueError(f"axis={axis!r}: expected 'y' or 'z'")
    materials: Dict[str, dict] = {}
    blocks, supports, block_keys, support_keys, faces = [], [], [], {}, {}
    for key, mesh, is_support, attrs in nodes:
        poly, width = _section(key, mesh, axis, tolerance)
        ie = _AXES[axis][2]
        lo = min(float(v["xyz"[ie]]) for v in mesh["vertex"].values())
        faces[key] = (lo, lo + width)
        if is_support:
            name = f"support{key}"
            supports.append({"name": name, "polygon": poly})
            support_keys[name] = key
            continue
        gamma = float(attrs.get("unit_weight", unit_weight))
        mat = f"w{width:.9g}_g{gamma:.9g}"
        materials.setdefault(mat, {"unit_weight": gamma, "width": width})
        blocks.append({"polygon": poly, "material": mat})
        block_keys.append(key)
    if not supports:
        raise ModelError("COMPAS assembly: no node has is_support = true (a structure needs a support)")
    model = {
        "description": description or "COMPAS assembly (prisms along " + axis + ")",
        "materials": materials,
        "blocks": blocks,
        "supports": supports,
    }
    mapping = {"axis": axis, "blocks": block_keys, "supports": support_keys, "faces": faces}
    return Model.from_dict(model), mapping


def _to3(axis: str, x: float, y: float, e: float) -> List[float]:
    ix, iy, ie = _AXES[axis]
    p = [0.0, 0.0, 0.0]
    p[ix], p[iy], p[ie] = x, y, e
    return p


def write_results(
    src: Union[str, "os.PathLike[str]", dict],
    result,
    path: Optional[Union[str, "os.PathLike[str]"]] = None,
    *,
    axis: Optional[str] = None,
    tolerance: float = 1e-6,
) -> dict:
    """Write a limit or settlement result of the model read from ``src`` back into a copy of the
    assembly: interface forces on the edges and block displacements on the nodes (see the module
    docstring). Returns the new assembly dict; also writes it as JSON to ``path`` if given."""
    from ._io import write_atomic

    data = copy.deepcopy(_load(src))
    _, mapping = assembly_model(data, axis=axis, tolerance=tolerance)
    axis = mapping["axis"]
    ix, iy, ie = _AXES[axis]
    r = result.to_dict()
    if "limit" in r and "joints" not in r:  # a tilt result: its limit analysis
        r = r["limit"]
    if "joints" not in r or "blocks" not in r:
        raise ValueError("write_results needs a limit, settlement or tilt result")
    keys = mapping["blocks"]
    if len(r["blocks"]) != len(keys):
        raise ModelError(
            f"the result has {len(r['blocks'])} blocks, the assembly {len(keys)}: not its result"
        )

    def node_of(body) -> str:
        if isinstance(body, dict):  # BodyName serialised as {"block": i} / {"support": name}
            if "block" in body:
                return keys[int(body["block"])]
            return mapping["supports"][body["support"]]
        if isinstance(body, int):
            return keys[body]
        if body in mapping["supports"]:
            return mapping["supports"][body]
        return keys[int(body)]

    g = _unwrap(data)
    g = _unwrap(g.get("graph", g)) if "assembly" not in g else _unwrap(g["assembly"])
    nodes = g.get("node") or g.get("vertex")
    edges = g.setdefault("edge", {})
    adjacency = g.setdefault("adjacency", {})
    # A rotation θ about voussoir's out-of-plane axis is a rotation about ê_x × ê_y of the
    # section, which is −y for sections in x–z, +z for sections in x–y.
    rot_axis = [0.0, 0.0, 0.0]
    rot_axis[ie] = -1.0 if axis == "y" else 1.0
    for b, key in zip(r["blocks"], keys):
        d = [0.0] * 6
        d[ix], d[iy] = b["u"], b["v"]
        for i in range(3):
            d[3 + i] = b["theta"] * rot_axis[i]
        nodes[key]["displacement"] = d
    new_edges: Dict[Tuple[str, str], list] = {}
    for j in r["joints"]:
        u, v = node_of(j["a"]), node_of(j["b"])
        n = j["normal"]
        w = _to3(axis, n[0], n[1], 0.0)
        ev = [0.0, 0.0, 0.0]
        ev[ie] = 1.0
        # xaxis = yaxis × zaxis so that (x, y, z) is right-handed with z the normal.
        xa = [
            ev[1] * w[2] - ev[2] * w[1],
            ev[2] * w[0] - ev[0] * w[2],
            ev[0] * w[1] - ev[1] * w[0],
        ]
        # Shear in voussoir is along t = (−n_y, n_x); its component along xaxis:
        t3 = _to3(axis, -n[1], n[0], 0.0)
        sgn = 1.0 if sum(a * b for a, b in zip(xa, t3)) > 0 else -1.0
        lo = max(mapping["faces"][u][0], mapping["faces"][v][0])
        hi = min(mapping["faces"][u][1], mapping["faces"][v][1])
        pts, forces = [], []
        for e in (lo, hi):
            for p in j["points"]:
                pts.append(_to3(axis, p["x"], p["y"], e))
                forces.append(
                    {
                        "c_np": 0.5 * p["normal_force"],
                        "c_nn": 0.0,
                        "c_u": 0.5 * sgn * p["shear_force"],
                        "c_v": 0.0,
                    }
                )
        if not pts:
            continue
        c = [sum(p[i] for p in pts) / len(pts) for i in range(3)]
        length = 0.0
        if len(j["points"]) == 2:
            a, b = j["points"]
            length = math.hypot(a["x"] - b["x"], a["y"] - b["y"])
        interface = {
            "dtype": "compas_assembly.datastructures/Interface",
            "data": {
                "points": pts,
                "type": "face_face",
                "size": length * (hi - lo),
                "frame": {"point": c, "xaxis": xa, "yaxis": ev},
                "forces": forces,
            },
        }
        new_edges.setdefault((u, v), []).append(interface)
    for (u, v), ifs in new_edges.items():
        edges.setdefault(u, {}).setdefault(v, {})["interfaces"] = ifs
        adjacency.setdefault(u, {})[v] = None
        adjacency.setdefault(v, {})[u] = None
    if path is not None:
        write_atomic(path, json.dumps(data).encode("utf-8"))
    return data
