"""COMPAS block assemblies of 3D meshes (compas_assembly ``Assembly``, compas_dem ``BlockModel``)
read as 3D voussoir models, and results written back in COMPAS's own JSON.

No ``compas`` import: the JSON that ``compas.json_dump`` writes (COMPAS 2.x; 1.x's ``value``
for ``data`` is read too) is read and written as plain data.

Read (:func:`read_assembly3d`):

* ``compas_assembly.datastructures/Assembly``: ``data.graph`` (a COMPAS Graph, wrapped or not)
  whose nodes hold ``block`` (a COMPAS Mesh: ``vertex`` key → {x, y, z}, ``face`` key → vertex
  keys) and ``is_support``;
* ``compas_dem.models/BlockModel``: ``data.elements`` (guid → Block element with ``geometry``, a
  Mesh, and ``is_support``), ordered by ``data.graph``'s nodes (``element`` = the guid).

Every node whose ``is_support`` is true is a support named ``support<key>`` (its graph key);
every other node a block, in increasing key order. A block's unit weight is its node's (or
element's) ``unit_weight`` attribute, else the ``unit_weight`` keyword (kN/m³); z is up, as in
COMPAS. Interfaces are found by voussoir (the assembly's own, if any, are not read).

Write (:func:`write_results3d`), into a copy of the assembly:

* per voussoir joint between nodes u and v, on the graph edge (u, v) — or (v, u) if only that
  one exists —, an interface: compas_assembly ``Interface`` in the edge's ``interfaces``, or
  compas_dem ``FrictionContact`` in its ``contacts``; ``points`` the joint's contact points,
  ``frame`` (``compas.geometry/Frame``) with ``zaxis`` = the joint normal from u into v and
  ``xaxis``, ``yaxis`` = the tangents t₁, t₂ of the result's shear components, ``size`` the
  contact area, ``forces`` per point ``{"c_np", "c_nn", "c_u", "c_v"}`` in kN: the force that u
  exerts on v is c_np·z − c_nn·z + c_u·x + c_v·y (c_nn = 0: no tension);
* per block node, ``displacement`` = [u, v, w, θx, θy, θz] of its centroid (m, rad; per unit
  of the normalisation for a limit mechanism), compas_assembly's node attribute of that name.
"""

from __future__ import annotations

import copy
import json
import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from ._model import Model
from ._native import ModelError

Source = Union[str, "os.PathLike[str]", dict]


def _load(src: Source) -> dict:
    if isinstance(src, dict):
        return src
    text = os.fspath(src)
    if text.lstrip().startswith("{"):
        return json.loads(text)
    try:
        with open(text, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise ModelError(f"cannot read {text}: {e.strerror}") from None
    except ValueError as e:
        raise ModelError(f"{text}: not JSON: {e}") from None


def _unwrap(d: Any) -> Any:
    """COMPAS data objects are ``{"dtype": …, "data": {…}}`` (1.x: ``"value"``)."""
    while isinstance(d, dict) and "dtype" in d and ("data" in d or "value" in d):
        d = d["data"] if "data" in d else d["value"]
    return d


def _key_order(k: str):
    try:
        return (0, int(k), "")
    except ValueError:
        return (1, 0, k)


def _truthy(x) -> bool:
    return bool(x) and x not in ("false", "False", "0")


def _nodes(data: dict) -> Tuple[str, List[Tuple[str, dict, bool, dict]], dict, Optional[dict]]:
    """(kind, [(key, mesh data, is_support, attributes)] by key, graph data, elements)."""
    d = _unwrap(data)
    if not isinstance(d, dict):
        raise ModelError("not a COMPAS assembly: expected a JSON object")
    graph = _unwrap(d.get("graph")) if isinstance(d.get("graph"), dict) else None
    if isinstance(d.get("elements"), dict):  # compas_dem BlockModel
        elements = d["elements"]
        if graph is None or not isinstance(graph.get("node"), dict):
            raise ModelError("COMPAS BlockModel: expected data.graph with nodes naming their element")
        out = []
        for key, at in graph["node"].items():
            guid = (at or {}).get("element")
            el = elements.get(guid)
            if el is None:
                raise ModelError(f"COMPAS BlockModel node {key}: element {guid!r} is not in data.elements")
            e = _unwrap(el)
            mesh = _unwrap(e.get("geometry") or e.get("modelgeometry") or e.get("shape"))
            if not isinstance(mesh, dict):
                raise ModelError(f"COMPAS BlockModel node {key}: element {guid} has no mesh geometry")
            attrs = dict(e)
            attrs.update(at or {})
            out.append((str(key), mesh, _truthy(attrs.get("is_support")), attrs))
        return "compas_dem", sorted(out, key=lambda t: _key_order(t[0])), graph, elements
    if graph is None or not isinstance(graph.get("node"), dict):
        raise ModelError(
            "not a COMPAS assembly: expected data.graph.data.node (compas_assembly Assembly) or data.elements (compas_dem BlockModel)"
        )
    out = []
    for key, at in graph["node"].items():
        block = (at or {}).get("block")
        if block is None:
            raise ModelError(f"COMPAS node {key}: has no block mesh")
        out.append((str(key), _unwrap(block), _truthy(at.get("is_support")), at))
    return "compas_assembly", sorted(out, key=lambda t: _key_order(t[0])), graph, None


def _polyhedron(key: str, mesh: dict) -> Tuple[List[List[float]], List[List[int]]]:
    verts = mesh.get("vertex")
    faces = mesh.get("face")
    if not isinstance(verts, dict) or not isinstance(faces, dict) or not verts or not faces:
        raise ModelError(f"COMPAS node {key}: block is not a mesh (expected vertex and face)")
    index: Dict[str, int] = {}
    vertices = []
    for vk in sorted(verts, key=_key_order):
        v = verts[vk]
        try:
            vertices.append([float(v["x"]), float(v["y"]), float(v["z"])])
        except (KeyError, TypeError, ValueError):
            raise ModelError(f"COMPAS node {key}: vertex {vk} has no x, y, z") from None
        index[str(vk)] = len(vertices) - 1
    out = []
    for fk in sorted(faces, key=_key_order):
        try:
            out.append([index[str(x)] for x in faces[fk]])
        except KeyError as e:
            raise ModelError(f"COMPAS node {key}: face {fk} names vertex {e.args[0]}, which the mesh does not have") from None
    return vertices, out


def assembly_model3d(
    src: Source, *, unit_weight: float = 18.0, description: str = ""
) -> Tuple[Model, Dict[str, Any]]:
    """As :func:`read_assembly3d`, also returning the mapping :func:`write_results3d` uses:
    ``{"kind", "blocks": [node keys], "supports": {name: node key}}``."""
    data = _load(src)
    kind, nodes, _, _ = _nodes(data)
    if not nodes:
        raise ModelError("COMPAS assembly: no blocks")
    materials: Dict[str, dict] = {}
    blocks, supports, block_keys, support_keys = [], [], [], {}
    for key, mesh, is_support, attrs in nodes:
        vertices, faces = _polyhedron(key, mesh)
        if is_support:
            name = f"support{key}"
            supports.append({"name": name, "vertices": vertices, "faces": faces})
            support_keys[name] = key
            continue
        gamma = float(attrs.get("unit_weight", unit_weight))
        mat = "default" if gamma == float(unit_weight) else f"g{gamma:.9g}"
        materials.setdefault(mat, {"unit_weight": gamma})
        blocks.append({"vertices": vertices, "faces": faces, "material": mat})
        block_keys.append(key)
    if not supports:
        raise ModelError("COMPAS assembly: no node has is_support = true (a structure needs a support)")
    model = {
        "description": description or f"COMPAS {kind} assembly ({len(blocks)} blocks)",
        "materials": materials,
        "blocks": blocks,
        "supports": supports,
    }
    return Model.from_dict(model), {"kind": kind, "blocks": block_keys, "supports": support_keys}


def read_assembly3d(src: Source, *, unit_weight: float = 18.0, description: str = "") -> Model:
    """Read a COMPAS assembly of 3D block meshes (a JSON path, JSON text or the loaded dict)
    as a 3D :class:`voussoir.Model` (see the module docstring). The model has self-weight
    only; add loads with :meth:`Model.to_dict` / :meth:`Model.from_dict`, move supports with
    ``settle(model, move={"support3": (0, 0, -0.01)})``."""
    return assembly_model3d(src, unit_weight=unit_weight, description=description)[0]


def _frame_dict(point, xaxis, yaxis) -> dict:
    return {
        "dtype": "compas.geometry/Frame",
        "data": {"point": [float(x) for x in point], "xaxis": [float(x) for x in xaxis], "yaxis": [float(x) for x in yaxis]},
    }


def _area(points: np.ndarray, n: np.ndarray) -> float:
    if len(points) < 3:
        return 0.0
    s = np.zeros(3)
    for i in range(len(points)):
        s += np.cross(points[i], points[(i + 1) % len(points)])
    return float(abs(np.dot(s, n)) / 2.0)


def write_results3d(src: Source, result, path: Optional[Union[str, "os.PathLike[str]"]] = None) -> dict:
    """Write a 3D limit, settlement or tilt result of the model read from ``src`` back into a
    copy of the assembly: interfaces with their points, frames and forces on the graph edges,
    block displacements on the nodes (see the module docstring). Returns the new assembly
    dict; also writes it as JSON (atomically) to ``path`` if given."""
    from ._io import write_atomic
    from ._results3d import tangents

    data = copy.deepcopy(_load(src))
    _, mapping = assembly_model3d(data)
    kind, _, graph, elements = _nodes(data)
    r = result.to_dict()
    if "limit" in r and "joints" not in r:  # a tilt result: its limit analysis
        r = r["limit"]
    if "joints" not in r or "blocks" not in r:
        raise ValueError("write_results3d needs a limit, settlement or tilt result")
    keys = mapping["blocks"]
    if len(r["blocks"]) != len(keys):
        raise ModelError(f"the result has {len(r['blocks'])} blocks, the assembly {len(keys)}: not its result")
    if r["blocks"] and "w" not in r["blocks"][0]:
        raise ValueError("write_results3d needs the result of a 3D analysis (this one is 2D)")

    def node_of(body) -> str:
        if isinstance(body, int):
            return keys[body]
        if isinstance(body, dict):
            if "block" in body:
                return keys[int(body["block"])]
            body = body["support"]
        return mapping["supports"][body]

    nodes = graph["node"]
    for b, key in zip(r["blocks"], keys):
        disp = [b["u"], b["v"], b["w"], b["theta_x"], b["theta_y"], b["theta_z"]]
        nodes[key]["displacement"] = [float(x) for x in disp]
    edges = graph.setdefault("edge", {})
    written: Dict[Tuple[str, str], list] = {}
    for j in r["joints"]:
        u, v = node_of(j["a"]), node_of(j["b"])
        n = np.array(j["normal"], dtype=float)
        t1, t2 = tangents(n)
        pts = np.array([[p["x"], p["y"], p["z"]] for p in j["points"]], dtype=float).reshape(-1, 3)
        forces = [
            {
                "c_np": max(float(p["normal_force"]), 0.0),
                "c_nn": max(-float(p["normal_force"]), 0.0),
                "c_u": float(p["shear_force"][0]),
                "c_v": float(p["shear_force"][1]),
            }
            for p in j["points"]
        ]
        # Stored on (u, v) unless only (v, u) exists: then seen from v, z = −n, x = t₂, y = t₁
        # (right-handed) and the force v exerts on u is the opposite one.
        if v in edges.get(u, {}) or u not in edges.get(v, {}):
            edge, frame = (u, v), (t1, t2)
        else:
            edge, frame = (v, u), (t2, t1)
            forces = [dict(f, c_u=-f["c_v"], c_v=-f["c_u"]) for f in forces]
        c = pts.mean(axis=0) if len(pts) else np.zeros(3)
        body = {
            "points": pts.tolist(),
            "frame": _frame_dict(c, *frame),
            "size": _area(pts, n),
            "forces": forces,
            "mesh": None,
        }
        if kind == "compas_dem":
            item = {"dtype": "compas_dem.interactions/FrictionContact", "data": dict(body, name="FrictionContact")}
        else:
            item = {"dtype": "compas_assembly.datastructures/Interface", "data": body}
        written.setdefault(edge, []).append(item)
    field = "contacts" if kind == "compas_dem" else "interfaces"
    for (u, v), items in written.items():
        attrs = edges.setdefault(u, {}).setdefault(v, {})
        if attrs is None:
            attrs = edges[u][v] = {}
        attrs[field] = items
        if "adjacency" in graph:  # COMPAS 1.x graphs keep an undirected adjacency
            graph["adjacency"].setdefault(u, {})[v] = None
            graph["adjacency"].setdefault(v, {})[u] = None
    if path is not None:
        write_atomic(path, json.dumps(data).encode("utf-8"))
    return data
