"""meshio reads every VTK piece that `voussoir … --vtk out.vtm` writes (issue 28, item 7).

vtkio declared the cells' connectivity and offsets UInt64, which meshio refused (UFuncTypeError on
the blocks, cracks and supports pieces); they are Int64 now, as VTK's own writers write them. Each
test runs the CLI on a 3D model, reads the `.vtm`, opens EVERY file it lists with meshio and checks
the point and cell counts (and the block vertices) against the model and the result JSON. VTK
output is for 3D models only: a 2D model's `--vtk` is refused in one line.
"""

import json
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def listed_pieces(vtm):
    """(part name, file path or None) for every DataSet of a .vtm, in order."""
    root = ET.parse(vtm).getroot()
    out = []
    for ds in root.iter("DataSet"):
        f = ds.get("file")
        out.append((ds.get("name"), vtm.parent / f if f else None))
    return out


def cell_count(mesh):
    return sum(len(block.data) for block in mesh.cells)


def expected_counts(model, result):
    """Points and cells of each part, from the model's polyhedra and the result's joints."""
    cracked = [j for j in result["joints"] if j["state"] != "closed" and j["points"]]
    return {
        "blocks": (
            sum(len(b["vertices"]) for b in model["blocks"]),
            sum(len(b["faces"]) for b in model["blocks"]),
        ),
        "contacts": (
            sum(len(j["points"]) for j in result["joints"]),
            sum(len(j["points"]) for j in result["joints"]),
        ),
        "cracks": (sum(len(j["points"]) for j in cracked), len(cracked)),
        "supports": (
            sum(len(s["vertices"]) for s in model["supports"]),
            sum(len(s["faces"]) for s in model["supports"]),
        ),
    }


def check_every_piece(vtm, model, result):
    pieces = listed_pieces(vtm)
    assert [p for p, _ in pieces] == ["blocks", "contacts", "cracks", "supports"]
    want = expected_counts(model, result)
    read = {}
    for part, path in pieces:
        if path is None:
            # An empty block (VTK's own writer lists one so): only the cracks, when none.
            assert part == "cracks" and want["cracks"] == (0, 0), (part, want[part])
            continue
        mesh = meshio.read(path)
        assert (len(mesh.points), cell_count(mesh)) == want[part], (part, path)
        read[part] = mesh
    # The blocks' points are the model's vertices, block after block, exactly (binary Float64).
    vertices = np.array([v for b in model["blocks"] for v in b["vertices"]], dtype=float)
    assert np.array_equal(read["blocks"].points, vertices)
    # Each face knows its block.
    block_ids = np.concatenate(read["blocks"].cell_data["block"])
    faces_per_block = [len(b["faces"]) for b in model["blocks"]]
    assert np.array_equal(block_ids, np.repeat(np.arange(len(faces_per_block)), faces_per_block))
    return read


def test_limit_of_a_vault_reads_in_meshio(cli, tmp_path):
    model_path = tmp_path / "vault.json"
    cli("gen", "vault", "--live", "left", "-o", model_path)
    vtm = tmp_path / "vault.vtm"
    result_path = tmp_path / "r.json"
    cli("limit", model_path, "--vtk", vtm, "-o", result_path)
    model = json.loads(model_path.read_text())
    result = json.loads(result_path.read_text())
    read = check_every_piece(vtm, model, result)
    # A mechanism has cracks: the piece is there and holds the joints that are not closed.
    assert "cracks" in read
    assert cell_count(read["cracks"]) >= 1
    # 64 voussoirs of 6 faces (the vault's default: 16 per ring, 4 rings).
    assert cell_count(read["blocks"]) == 6 * len(model["blocks"])


def test_settlement_without_cracks_lists_an_empty_cracks_block(cli, tmp_path):
    # One box on a base that moves down by 1 cm: a rigid translation, every joint stays closed.
    model_path = tmp_path / "block.json"
    cli("gen", "block", "--size", "1,1,2", "-o", model_path)
    vtm = tmp_path / "s.vtm"
    result_path = tmp_path / "s.json"
    cli("settle", model_path, "--move", "base=0,0,-0.01", "--vtk", vtm, "-o", result_path)
    model = json.loads(model_path.read_text())
    result = json.loads(result_path.read_text())
    read = check_every_piece(vtm, model, result)
    assert "cracks" not in read
    assert not (tmp_path / "s_cracks.vtu").exists()
    # The box's 8 vertices and 6 faces; its 4 contact corners; the base's 8 and 6.
    assert (len(read["blocks"].points), cell_count(read["blocks"])) == (8, 6)
    assert (len(read["contacts"].points), cell_count(read["contacts"])) == (4, 4)
    assert (len(read["supports"].points), cell_count(read["supports"])) == (8, 6)
    # The supports' displacement is the prescribed motion, −0.01 m along z at every vertex.
    disp = read["supports"].point_data["displacement"]
    assert np.allclose(disp, [0.0, 0.0, -0.01], rtol=0, atol=1e-15)


def test_settlement_with_cracks_reads_in_meshio(cli, tmp_path):
    # The vault with one springing moving out: joints open, every piece is written. (A tilt of
    # the L walls' single ground is a rigid motion: it opens nothing, issue 28 item 8.)
    model_path = tmp_path / "vault.json"
    cli("gen", "vault", "--live", "full", "-o", model_path)
    vtm = tmp_path / "w.vtm"
    result_path = tmp_path / "w.json"
    cli("settle", model_path, "--move", "right=0.01,0,0", "--vtk", vtm, "-o", result_path)
    model = json.loads(model_path.read_text())
    result = json.loads(result_path.read_text())
    read = check_every_piece(vtm, model, result)
    assert set(read) == {"blocks", "contacts", "cracks", "supports"}


def test_a_2d_model_is_refused_in_one_line(cli, paper_arch, tmp_path):
    r = cli("limit", paper_arch, "--vtk", tmp_path / "a.vtm", check=False)
    assert r.returncode != 0
    assert len(r.stderr.strip().splitlines()) == 1
    assert "--vtk" in r.stderr and "3D" in r.stderr
    assert not list(tmp_path.iterdir())
