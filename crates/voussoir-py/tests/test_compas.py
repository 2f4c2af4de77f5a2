"""COMPAS assemblies: prisms read as 2D models, results written back as interface forces and
block displacements in the structure compas_assembly / compas_cra viewers read."""

import json
import math

import numpy as np
import pytest

import voussoir as v
from voussoir import compas as vc


def _prism(poly, y0, y1, triangulate):
    """A COMPAS mesh (data dict) of the polygon (x, z) extruded along y from y0 to y1."""
    n = len(poly)
    vertex = {}
    for i, (x, z) in enumerate(poly):
        vertex[str(i)] = {"x": x, "y": y0, "z": z}
        vertex[str(i + n)] = {"x": x, "y": y1, "z": z}
    faces = []
    if triangulate:
        faces += [[0, i + 1, i] for i in range(1, n - 1)]
        faces += [[n, n + i, n + i + 1] for i in range(1, n - 1)]
    else:
        faces.append(list(reversed(range(n))))
        faces.append(list(range(n, 2 * n)))
    faces += [[i, (i + 1) % n, (i + 1) % n + n, i + n] for i in range(n)]
    return {
        "dtype": "compas_assembly.datastructures/Block",
        "data": {
            "attributes": {"name": None},
            "default_vertex_attributes": {"x": 0.0, "y": 0.0, "z": 0.0},
            "vertex": vertex,
            "face": {str(i): f for i, f in enumerate(faces)},
            "facedata": {},
            "edgedata": {},
        },
    }


def assembly_of(model):
    """The model as compas.json_dump writes an Assembly: supports are nodes 0, 1, …"""
    nodes = {}
    key = 0
    for s in model.supports:
        nodes[str(key)] = {"block": _prism(s.polygon.tolist(), 0.0, 1.0, False), "is_support": True}
        key += 1
    for i, b in enumerate(model.blocks):
        nodes[str(key)] = {"block": _prism(b.tolist(), 0.0, 1.0, i % 2 == 1), "is_support": False}
        key += 1
    return {
        "dtype": "compas_assembly.datastructures/Assembly",
        "data": {
            "attributes": {"name": "Assembly"},
            "graph": {
                "dtype": "compas.datastructures/Graph",
                "data": {
                    "attributes": {},
                    "default_node_attributes": {"block": None, "is_support": False},
                    "default_edge_attributes": {"interfaces": None},
                    "node": nodes,
                    "edge": {k: {} for k in nodes},
                    "adjacency": {k: {} for k in nodes},
                    "max_node": key - 1,
                },
            },
        },
        "guid": "00000000-0000-0000-0000-000000000000",
    }


@pytest.fixture(scope="module")
def arch():
    return v.generate.arch()


@pytest.fixture(scope="module")
def assembly(arch, tmp_path_factory):
    p = tmp_path_factory.mktemp("compas") / "arch_assembly.json"
    p.write_text(json.dumps(assembly_of(arch)))
    return p


def test_read_prisms_as_the_same_structure(arch, assembly):
    m = vc.read_assembly(assembly)
    assert len(m.blocks) == 64 and m.support_names == ["support0", "support1"]
    assert m.check() == arch.check()
    # Same sections (the start vertex may differ): compare vertex sets.
    for a, b in zip(m.blocks, arch.blocks):
        assert sorted(map(tuple, np.round(a, 12))) == sorted(map(tuple, np.round(b, 12)))
    # The paper's spreading mechanism through the COMPAS route: the same hinges (positions)
    # and the same work as the generated model.
    r = v.settle(m, move={"support1": (0.01, 0)})
    ref = v.settle(arch, move={"right": (0.01, 0)})
    assert sorted(map(tuple, np.round(r.hinges[:, 1:], 9))) == sorted(map(tuple, np.round(ref.hinges[:, 1:], 9)))
    assert r.work_dead_loads == pytest.approx(ref.work_dead_loads, rel=1e-9)
    assert r.certified


def test_extrusion_along_z(arch):
    data = assembly_of(arch)
    # Swap y and z: sections in x–y, extruded along z.
    for node in data["data"]["graph"]["data"]["node"].values():
        for vtx in node["block"]["data"]["vertex"].values():
            vtx["y"], vtx["z"] = vtx["z"], vtx["y"]
    m = vc.read_assembly(data)
    assert m.check() == arch.check()
    with pytest.raises(v.ModelError, match="not a prism extruded along y|not a right prism"):
        vc.read_assembly(data, axis="y")


def test_non_prisms_are_refused(arch):
    data = assembly_of(arch)
    node = data["data"]["graph"]["data"]["node"]["5"]["block"]["data"]
    node["vertex"]["4"]["x"] += 0.05  # a top vertex moved: not a right prism
    with pytest.raises(v.ModelError, match=r"COMPAS node 5: block is not a right prism"):
        vc.read_assembly(data, axis="y")
    data = assembly_of(arch)
    node = data["data"]["graph"]["data"]["node"]["7"]["block"]["data"]
    node["vertex"]["4"]["y"] = 0.5  # a vertex between the faces: a 3D block
    with pytest.raises(v.ModelError, match=r"COMPAS node 7: block is not a prism"):
        vc.read_assembly(data, axis="y")
    with pytest.raises(v.ModelError, match="not a COMPAS assembly"):
        vc.read_assembly({"foo": 1})


def test_write_results_forces_and_displacements(arch, assembly, tmp_path):
    m = vc.read_assembly(assembly)
    r = v.settle(m, move={"support1": (0.01, 0)})
    out = vc.write_results(assembly, r, tmp_path / "with_results.json")
    assert json.loads((tmp_path / "with_results.json").read_text()) == out
    g = out["data"]["graph"]["data"]
    # Displacements of the free nodes: [dx, dy, dz, rx, ry, rz] with z up, θ about −y.
    for i, b in enumerate(r.to_dict()["blocks"]):
        d = g["node"][str(i + 2)]["displacement"]
        assert d == [b["u"], 0.0, b["v"], 0.0, -b["theta"], 0.0]
    # Interface forces: per joint, the c_np of its 4 points sum to the joint's normal force.
    joints = r.to_dict()["joints"]
    interfaces = [i for u in g["edge"].values() for e in u.values() for i in e.get("interfaces", [])]
    assert len(interfaces) == len(joints) == 65
    # Equilibrium through the written data, an independent check of every orientation: the
    # forces the supports exert on the arch carry its weight, γ·½·64·sin(π/64)·(R_e² − R_i²)·1 m
    # (straight-sided voussoirs: the ring between two half 64-gons).
    weight = 18.0 * 0.5 * 64 * math.sin(math.pi / 64) * (3.19**2 - 2.86**2)
    total = np.zeros(3)
    support_keys = {"0", "1"}
    for u, targets in g["edge"].items():
        for w_key, e in targets.items():
            for itf in e.get("interfaces", []):
                d = itf["data"]
                fr = d["frame"]
                x, y = np.array(fr["xaxis"]), np.array(fr["yaxis"])
                n = np.cross(x, y)
                f = sum(p["c_np"] * n + p["c_u"] * x for p in d["forces"])  # on the edge's 2nd node
                if u in support_keys and w_key not in support_keys:
                    total += f
                elif w_key in support_keys and u not in support_keys:
                    total -= f
    assert total[2] == pytest.approx(weight, rel=1e-9)
    assert abs(total[0]) < 1e-9 * weight and abs(total[1]) < 1e-12
    # Per joint normal force.
    by_normal = sorted(j["normal_force"] for j in joints)
    written = sorted(sum(p["c_np"] for p in i["data"]["forces"]) for i in interfaces)
    assert written == pytest.approx(by_normal, rel=1e-12, abs=1e-12)
