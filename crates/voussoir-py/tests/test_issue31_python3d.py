"""Issue 31 item 2: Python in 3D — 3D models (JSON, OBJ, PLY), the 3D generators, every analysis
of a 3D model, safety and least thickness; the CLI is the reference (same numbers, same bytes),
hand calculations where there is one."""

import json
import math
import runpy
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import voussoir as v

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="module")
def vault(cli, tmp_path_factory):
    """The paper's arch extruded over 1 m, live load on the whole span (`voussoir gen vault`)."""
    path = tmp_path_factory.mktemp("models") / "vault.json"
    cli("gen", "vault", "--live", "full", "-o", path)
    return path


def test_issue31_item2_limit_of_vault_json_equals_cli(cli, vault, paper_arch):
    # The issue's must-show: voussoir.limit(Model.from_json("vault.json")) equals the CLI's λ.
    m = v.Model.from_json(vault)
    assert m.dim == 3 and len(m) == 64 and m.support_names == ["left", "right"]
    r = v.limit(m)
    ref = json.loads(cli("limit", vault, "--json").stdout)
    assert r.load_multiplier == ref["load_multiplier"]
    assert r.to_json() == cli("limit", vault, "--json").stdout
    # The vault is the arch extruded: the arch's λ (2D, independent program), to 1e-6.
    lam2d = v.limit(v.Model.from_json(paper_arch)).load_multiplier
    assert abs(r.load_multiplier - lam2d) < 1e-6 * lam2d
    # Arrays: 6-DOF motions, 3D points, two shear components.
    assert r.dim == 3
    assert r.block_motions.shape == (64, 6)
    assert r.joint_forces.shape == (65, 3)
    assert r.point_results.shape[1] == 10 and r.hinges.shape[1] == 4
    # A mechanism of the plane x–z: no v, θx, θz.
    np.testing.assert_allclose(r.block_motions[:, [1, 3, 5]], 0.0, atol=1e-9)
    # Frames are right-handed orthonormal with the normals as third row.
    f = r.joint_frames
    np.testing.assert_allclose(np.cross(f[:, 0], f[:, 1]), f[:, 2], atol=1e-12)
    np.testing.assert_allclose(f[:, 2], r.joint_normals, atol=0)


def test_issue31_item2_generators_byte_identical_to_cli(cli):
    cases = [
        (v.generate.vault(live="full"), ["vault", "--live", "full"]),
        (v.generate.vault(rings=3, bond="running", depth=1.5, voussoirs=12), ["vault", "--rings", "3", "--bond", "running", "--depth", "1.5", "--voussoirs", "12"]),
        (v.generate.dome(), ["dome"]),
        (v.generate.dome(courses=4, segments=8, oculus=20, crown_load=10), ["dome", "--courses", "4", "--segments", "8", "--oculus", "20", "--crown-load", "10"]),
        (v.generate.block(size=(1, 1, 2), direction="+y"), ["block", "--size", "1,1,2", "--direction", "+y"]),
        (v.generate.block(direction=30), ["block", "--direction", "30"]),
        (v.generate.walls(plan="L", courses=4), ["walls", "--plan", "L", "--courses", "4"]),
    ]
    for model, args in cases:
        assert model.dim == 3
        assert model.to_json() == cli("gen", *args).stdout, args
    with pytest.raises(ValueError, match="live_load"):
        v.generate.vault(live_load=2.0)
    with pytest.raises(v.ModelError, match="bond=diagonal"):
        v.generate.vault(bond="diagonal")


def test_issue31_item2_dome_safety_equals_cli(cli, tmp_path):
    # The issue's must-show: generate.dome(…) and safety(…) work.
    d = v.generate.dome(courses=4, segments=8)
    path = tmp_path / "dome.json"
    d.to_json(path)
    s = v.safety(d)
    assert s.to_json() == cli("safety", path, "--json").stdout
    assert s.stands and s.safety_factor > 1.0
    # Each base support carries at most the whole weight (the ranges' upper ends) and the
    # smallest vertical reaction is ≥ 0 (no tension).
    for comps in s.reactions.values():
        lo, hi = comps["fz"]
        assert lo >= -1e-9 and hi > 0
    # Without ranges, as `--no-ranges`.
    assert v.safety(path, ranges=False).to_json() == cli("safety", path, "--no-ranges", "--json").stdout


def test_issue31_item2_safety_and_least_thickness_in_2d(cli, paper_arch):
    s = v.safety(paper_arch)
    assert s.to_json() == cli("safety", paper_arch, "--json").stdout
    lt = v.least_thickness("arch")
    assert lt.to_json() == cli("least-thickness", "arch", "--json").stdout
    # Milankovitch: t/R = 0.1075 at the centreline for a semicircular arch (64 voussoirs: 0.107).
    assert abs(lt.thickness_over_radius - 0.1075) < 0.002
    assert lt.model.to_json() == cli("gen", "arch", "--thickness", repr(lt.thickness)).stdout
    ld = v.least_thickness("dome", courses=4, segments=8)
    assert ld.to_json() == cli("least-thickness", "dome", "--courses", "4", "--segments", "8", "--json").stdout
    assert ld.model.dim == 3
    with pytest.raises(TypeError, match="thickness"):
        v.least_thickness("arch", thickness=0.3)


def vault_weight(gamma=18.0, r=2.86, t=0.33, n=64, depth=1.0):
    """Weight of the generated vault: n voussoirs whose corners lie on the intrados and
    extrados semicircles (each a trapezoid of the two chords)."""
    return gamma * depth * (n / 2) * math.sin(math.pi / n) * ((r + t) ** 2 - r**2)


def test_issue31_item2_settle_vault_equals_cli_and_balances(cli, vault):
    m = v.Model.from_json(vault)
    r = v.settle(m, move={"right": (0.01, 0, 0)})
    assert r.to_json() == cli("settle", vault, "--move", "right=0.01,0,0", "--json").stdout
    assert r.certified
    # The CLI's syntax with units, and a dict of strings, give the same analysis.
    assert v.settle(m, move="right=1cm,0,0") == r
    # Vertical reactions carry the dead load (hand: the trapezoids' area × γ), to 1e-9.
    fz = sum(x[2] for x in r.reactions.values())
    assert abs(fz - vault_weight()) <= 1e-9 * vault_weight()
    # Six numbers: a rotation in degrees (θy = −0.1°), as the CLI's --move.
    r6 = v.settle(m, move={"right": (0, 0, 0, 0, -0.1, 0)})
    assert r6.to_json() == cli("settle", vault, "--move", "right=0,0,0,0,-0.1,0", "--json").stdout
    with pytest.raises(ValueError, match="u, v, w"):
        v.settle(m, move={"right": (0.01, 0)})


def test_issue31_item2_capacity_and_tilt_in_3d(cli, vault, tmp_path):
    c = v.capacity(vault, move={"right": (0.005, 0, 0)}, steps=4)
    assert c.to_json() == cli("capacity", vault, "--move", "right=0.005,0,0", "--steps", "4", "--json").stdout
    assert c.curve.shape == (5, 2)
    # A 1 × 1 × 2 box overturns about its edge: tan α = b / h = 1/2 (hand), towards +y.
    blk = v.generate.block(size=(1, 1, 2), direction="+y")
    t = v.tilt(blk, direction="+y")
    assert abs(t.tilt_angle - math.degrees(math.atan(0.5))) < 1e-6
    path = tmp_path / "block.json"
    blk.to_json(path)
    assert t.to_json() == cli("tilt", path, "--direction", "+y", "--json").stdout
    assert v.tilt(blk, direction=90) == t


def test_issue31_item2_obj_and_ply_models(cli, tmp_path):
    blk = v.generate.block(size=(1, 1, 2))
    obj = tmp_path / "block.obj"
    blk.to_obj(obj)
    m = v.Model.from_json(obj)  # by extension, as the CLI reads a model
    assert m.dim == 3 and len(m) == 1 and m.import_summary is not None
    assert v.limit(m).to_json() == cli("limit", obj, "--json").stdout
    # Overturning about an edge: λ = b/h = 0.5 (hand).
    assert abs(v.limit(m).load_multiplier - 0.5) < 1e-9
    # A PLY of the same box (ASCII), its lowest part the support by default.
    ply = tmp_path / "two.ply"
    verts = []
    faces = []
    for k, (z0, z1, x0, x1) in enumerate([(-0.5, 0.0, -1.0, 2.0), (0.0, 2.0, 0.0, 1.0)]):
        base = len(verts)
        verts += [(x, y, z) for z in (z0, z1) for (x, y) in ((x0, -1.0 if k == 0 else 0.0), (x1, -1.0 if k == 0 else 0.0), (x1, 2.0 if k == 0 else 1.0), (x0, 2.0 if k == 0 else 1.0))]
        fs = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
        faces += [[base + i for i in f] for f in fs]
    lines = ["ply", "format ascii 1.0", f"element vertex {len(verts)}", "property float x",
             "property float y", "property float z", f"element face {len(faces)}",
             "property list uchar int vertex_indices", "end_header"]
    lines += [" ".join(map(str, p)) for p in verts]
    lines += [f"4 {' '.join(map(str, f))}" for f in faces]
    ply.write_text("\n".join(lines) + "\n")
    p = v.Model.from_json(ply)
    assert p.dim == 3 and len(p) == 1 and len(p.supports) == 1
    assert v.limit(p).to_json() == cli("limit", ply, "--json").stdout


def test_issue31_item2_executor_and_refusals(vault):
    m = v.Model.from_json(vault)
    with ThreadPoolExecutor(2) as ex:
        fut = v.limit(m, executor=ex)
        fs = v.safety(v.generate.dome(courses=3, segments=6), executor=ex)
        assert fut.result() == v.limit(m)
        assert fs.result().stands
    # 3D sweeps run (test_issue31_sweep3d.py), and 3D incremental analyses
    # (test_issue31_requests2.py): a 2D control point on a 3D model is refused, named.
    with pytest.raises(ValueError, match="control=0,3: expected three finite numbers"):
        v.incremental(m, control=(0, 3))
    with pytest.raises(v.ModelError, match="crushing"):
        v.limit(m, crushing="conic")
    with pytest.raises(ValueError, match="friction_facets and friction_cone apply to 3D"):
        v.limit(v.generate.arch(), friction_facets=8)
    # The request layer refuses what does not apply (limit with a support motion).
    from voussoir import _analysis3d as a3, _native

    req = a3.request(a3.common3d(move={"right": (0, 0, 0.01)}), {"type": "limit"})
    with pytest.raises(v.ModelError, match="limit takes no support motion"):
        _native.run_request(m._json, req)
    # The exact friction cone, as `--friction-cone exact` (an SOCP: λ of the cone ≥ pyramid's).
    lam_p = v.limit(m, friction=0.6).load_multiplier
    lam_c = v.limit(m, friction=0.6, friction_cone="exact").load_multiplier
    assert lam_c >= lam_p - 1e-6


def test_issue31_item2_example_script_runs(capsys):
    runpy.run_path(str(ROOT / "examples" / "python" / "vault3d.py"), run_name="__main__")
    out = capsys.readouterr().out
    lam = float(out.split("λ = ")[1].split(",")[0])
    assert abs(lam - 0.4346) < 5e-5
    assert "the dome stands" in out
    assert "supports carry" in out
