"""Issue 31 item 3: COMPAS assemblies of 3D block meshes (compas_assembly Assembly, compas_dem
BlockModel, as ``compas.json_dump`` writes them) read, settled and written back.

The structure (built here, in COMPAS 2.x JSON): two columns 0.4 × 0.4 × 1 m on two support
boxes, x ∈ [0, 0.4] and [1.6, 2.0], and a beam 2.0 × 0.4 × 0.3 m resting on both; γ = 18 kN/m³.
The right support settles by 1 cm. By hand: the right column follows its support; the beam
pivots about the inner edge of the left column's top (x = 0.4, z = 1) and keeps touching the
right column at its outer edge (x = 2.0: touching at x = 1.6 would need a rotation that drives
x = 2.0 into the column), so θy = 0.01 / 1.6 and its centroid (1.0, 0.2, 1.15) moves by
u = θ·0.15, w = −θ·0.6. The beam's weight 4.32 kN is shared by the two lines: 4.32·1.0/1.6 =
2.70 kN on the left, 1.62 kN on the right; the supports carry 2.88 + 2.70 = 5.58 kN and
2.88 + 1.62 = 4.50 kN; together the total weight 10.08 kN.
"""

import json

import numpy as np
import pytest

import voussoir as v
from voussoir import compas as vc

GAMMA = 18.0
BOXES = {  # node key: ((x0, y0, z0), (x1, y1, z1), is_support)
    "0": ((0.0, 0.0, -0.2), (0.4, 0.4, 0.0), True),
    "1": ((1.6, 0.0, -0.2), (2.0, 0.4, 0.0), True),
    "2": ((0.0, 0.0, 0.0), (0.4, 0.4, 1.0), False),
    "3": ((1.6, 0.0, 0.0), (2.0, 0.4, 1.0), False),
    "4": ((0.0, 0.0, 1.0), (2.0, 0.4, 1.3), False),
}
WEIGHTS = {k: GAMMA * np.prod(np.subtract(b[1], b[0])) for k, b in BOXES.items() if not b[2]}
W = sum(WEIGHTS.values())


def box_mesh(lo, hi, dtype="compas.datastructures/Mesh"):
    """A box as COMPAS 2.x writes a Mesh: vertex keys → {x, y, z}, faces counter-clockwise seen
    from outside."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    pts = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)]
    pts += [(x, y, z1) for x, y, _ in pts]
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return {
        "dtype": dtype,
        "data": {
            "attributes": {},
            "default_vertex_attributes": {"x": 0.0, "y": 0.0, "z": 0.0},
            "default_edge_attributes": {},
            "default_face_attributes": {},
            "vertex": {str(i): {"x": p[0], "y": p[1], "z": p[2]} for i, p in enumerate(pts)},
            "face": {str(i): f for i, f in enumerate(faces)},
            "facedata": {str(i): {} for i in range(6)},
            "edgedata": {},
            "max_vertex": 7,
            "max_face": 5,
        },
        "guid": "00000000-0000-0000-0000-00000000000" + "0",
    }


def assembly():
    """compas_assembly's Assembly as ``compas.json_dump`` writes it, with two edges of its own
    (one of them from the column to its support, the other way round from voussoir's joint)."""
    node = {
        k: {"block": box_mesh(*b[:2], "compas_assembly.datastructures/Block"), "is_support": b[2],
            "displacement": [0, 0, 0, 0, 0, 0]}
        for k, b in BOXES.items()
    }
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
                    "node": node,
                    "edge": {"3": {"1": {"interfaces": None}}, "0": {"2": {"interfaces": None}}},
                    "max_node": 4,
                },
                "guid": "graph",
            },
        },
        "guid": "assembly",
    }


def block_model():
    """compas_dem's BlockModel as ``compas.json_dump`` writes it (elements by guid, the graph's
    nodes naming them)."""
    elements = {
        f"guid-{k}": {
            "dtype": "compas_dem.elements/Block",
            "data": {"transformation": None, "features": [], "name": "Block", "material": None,
                     "geometry": box_mesh(*b[:2]), "is_support": b[2]},
            "guid": f"guid-{k}",
        }
        for k, b in BOXES.items()
    }
    return {
        "dtype": "compas_dem.models/BlockModel",
        "data": {
            "transformation": None,
            "elements": elements,
            "materials": {},
            "graph": {
                "attributes": {},
                "default_node_attributes": {"element": None},
                "default_edge_attributes": {"modifiers": None, "contacts": None},
                "node": {k: {"element": f"guid-{k}"} for k in BOXES},
                "edge": {},
                "max_node": 4,
            },
        },
        "guid": "model",
    }


def frame_axes(frame):
    d = frame["data"]
    x, y = np.array(d["xaxis"]), np.array(d["yaxis"])
    return x, y, np.cross(x, y)


def forces_on_blocks(data, field):
    """Per (support key, block key): the force (kN) the support exerts on the block, summed
    over the points of the written interfaces (force of u on v = c_np·z − c_nn·z + c_u·x + c_v·y)."""
    g = data["data"]["graph"]
    g = g.get("data", g)
    support = {k for k, b in BOXES.items() if b[2]}
    out = {}
    for u, nbrs in g["edge"].items():
        for w, attrs in nbrs.items():
            for item in (attrs or {}).get(field) or []:
                i = item["data"]
                x, y, z = frame_axes(i["frame"])
                f = sum((p["c_np"] - p["c_nn"]) * z + p["c_u"] * x + p["c_v"] * y for p in i["forces"])
                if u in support and w not in support:
                    out[(u, w)] = out.get((u, w), 0) + f
                elif w in support and u not in support:
                    out[(w, u)] = out.get((w, u), 0) - f
    return out


def settle(src):
    m = vc.read_assembly3d(src, unit_weight=GAMMA)
    assert m.dim == 3 and len(m) == 3 and m.support_names == ["support0", "support1"]
    r = v.settle(m, move={"support1": (0, 0, -0.01)})
    assert r.certified
    return m, r


def check_displacements(nodes):
    theta = 0.01 / 1.6
    np.testing.assert_allclose(nodes["2"]["displacement"], [0] * 6, atol=1e-9)
    np.testing.assert_allclose(nodes["3"]["displacement"], [0, 0, -0.01, 0, 0, 0], atol=1e-9)
    np.testing.assert_allclose(
        nodes["4"]["displacement"], [theta * 0.15, 0, -theta * 0.6, 0, theta, 0], atol=1e-9
    )



def test_issue31_item3_compas_assembly_read_settled_written_back(tmp_path):
    src = tmp_path / "assembly.json"
    src.write_text(json.dumps(assembly()))
    m, r = settle(src)
    out = tmp_path / "settled.json"
    data = vc.write_results3d(src, r, out)
    assert json.loads(out.read_text()) == data
    assert data["dtype"] == "compas_assembly.datastructures/Assembly"
    g = data["data"]["graph"]["data"]
    check_displacements(g["node"])
    f = forces_on_blocks(data, "interfaces")
    # The supports carry the total weight (hand: 10.08 kN), to 1e-9 relative.
    total = sum(x[2] for x in f.values())
    assert abs(total - W) <= 1e-9 * W, (total, W)
    assert W == pytest.approx(10.08, rel=1e-12)
    # Each support: its column's weight and its share of the beam (hand: 5.58 and 4.50 kN).
    assert f[("0", "2")][2] == pytest.approx(5.58, rel=1e-9)
    assert f[("1", "3")][2] == pytest.approx(4.50, rel=1e-9)
    # No horizontal load: the supports' horizontal forces balance (each alone is not unique: the
    # frame of columns and beam can carry a horizontal self-stress).
    np.testing.assert_allclose(sum(x[:2] for x in f.values()), 0.0, atol=1e-9)
    # The column–support edge given the other way round (3 → 1) got the interface.
    assert g["edge"]["3"]["1"]["interfaces"][0]["dtype"] == "compas_assembly.datastructures/Interface"
    iface = g["edge"]["3"]["1"]["interfaces"][0]["data"]
    assert iface["size"] == pytest.approx(0.16, rel=1e-12)
    assert len(iface["points"]) == len(iface["forces"]) == 4
    # Every interface's frame is orthonormal with zaxis from its edge's first node into the
    # second (the support below the column: the column's frame z points down).
    x, y, z = frame_axes(iface["frame"])
    np.testing.assert_allclose([x @ x, y @ y, x @ y], [1, 1, 0], atol=1e-12)
    np.testing.assert_allclose(z, [0, 0, -1], atol=1e-12)


def test_issue31_item3_compas_dem_block_model_settled(tmp_path):
    m, r = settle(block_model())
    data = vc.write_results3d(block_model(), r)
    g = data["data"]["graph"]
    check_displacements(g["node"])
    f = forces_on_blocks(data, "contacts")
    total = sum(x[2] for x in f.values())
    assert abs(total - W) <= 1e-9 * W
    c = next(iter(next(iter(g["edge"].values())).values()))["contacts"][0]
    assert c["dtype"] == "compas_dem.interactions/FrictionContact"


def test_issue31_item3_compas_refuses_what_it_cannot_read():
    a = assembly()
    for n in a["data"]["graph"]["data"]["node"].values():
        n["is_support"] = False
    with pytest.raises(v.ModelError, match="is_support"):
        vc.read_assembly3d(a)
    a = assembly()
    a["data"]["graph"]["data"]["node"]["4"]["block"]["data"]["face"]["0"] = [0, 3, 2, 99]
    with pytest.raises(v.ModelError, match="node 4: face 0 names vertex 99"):
        vc.read_assembly3d(a)
    m, r = settle(assembly())
    two_d = v.limit(v.generate.arch(live="full"))
    with pytest.raises(v.ModelError, match="64 blocks, the assembly 3"):
        vc.write_results3d(assembly(), two_d)


def test_issue31_item3_compas_optional_written_by_compas_itself():
    """Optional (when the ``compas`` package is installed): the graph and meshes serialised by
    COMPAS's own ``json_dumps`` read as the same model, and every written frame loads back as a
    ``compas.geometry.Frame`` whose zaxis is the frame's x × y."""
    compas = pytest.importorskip("compas")
    from compas.datastructures import Graph, Mesh

    graph = Graph()
    for k, (lo, hi, sup) in BOXES.items():
        mine = box_mesh(lo, hi)["data"]
        verts = [[mine["vertex"][str(i)][c] for c in "xyz"] for i in range(8)]
        mesh = Mesh.from_vertices_and_faces(verts, [mine["face"][str(i)] for i in range(6)])
        graph.add_node(int(k), block=mesh, is_support=sup)
    data = {
        "dtype": "compas_assembly.datastructures/Assembly",
        "data": {"attributes": {}, "graph": json.loads(compas.json_dumps(graph))},
    }
    m = vc.read_assembly3d(data, unit_weight=GAMMA)
    assert m == vc.read_assembly3d(assembly(), unit_weight=GAMMA)
    r = v.settle(m, move={"support1": (0, 0, -0.01)})
    out = vc.write_results3d(data, r)
    g = out["data"]["graph"]["data"]
    frames = [
        i["data"]["frame"]
        for nbrs in g["edge"].values()
        for attrs in nbrs.values()
        for i in (attrs or {}).get("interfaces") or []
    ]
    assert len(frames) == len(r.joint_states)
    for f in frames:
        frame = compas.json_loads(json.dumps(f))
        x, y, z = frame_axes(f)
        np.testing.assert_allclose(list(frame.zaxis), z, atol=1e-12)
