"""Issue 31 item 1, the rest of the front door in Python: incremental, identify, sweep, tilt,
safety and least thickness are requests run by the library's one entry (``_native.run``), for
models of either dimension. References: the CLI (same bytes), the half-loaded arch's λ at the
start of its incremental curve (0.2189, the paper) and its vault (the same curve), a forward
settlement identified back, a block's overturning tilt (tan α = b / h), Milankovitch's least
thickness of a semicircular arch (t/R = 0.1075)."""

import json
import math
from concurrent.futures import ThreadPoolExecutor

import pytest

import voussoir as v


@pytest.fixture(scope="module")
def half(tmp_path_factory, cli):
    d = tmp_path_factory.mktemp("half")
    cli("gen", "arch", "--live", "left", "-o", d / "arch.json")
    cli("gen", "vault", "--live", "left", "--depth", "1", "-o", d / "vault.json")
    return d


def test_issue31_item1_incremental_of_vault_equals_arch_and_cli(half, cli):
    arch = v.Model.from_json(half / "arch.json")
    vault = v.Model.from_json(half / "vault.json")
    ra = v.incremental(arch, control=(0.0, 3.19), max=0.002, step=0.0005)
    rv = v.incremental(vault, control=(0.0, 0.5, 3.19), direction="+x", max=0.002, step=0.0005)
    ca = json.loads(ra.to_json())["curve"]
    cv = json.loads(rv.to_json())["curve"]
    assert abs(ca[0]["load_multiplier"] - 0.2189) < 5e-4
    assert len(ca) == len(cv)
    for a, b in zip(ca, cv):
        assert abs(a["load_multiplier"] - b["load_multiplier"]) < 1e-6
    # The CLI's bytes, 3D included.
    out = cli(
        "incremental", half / "vault.json", "--control", "0,0.5,3.19", "--max", "2mm",
        "--step", "0.5mm", "--json",
    ).stdout
    assert rv.to_json() == out
    # Errors name the keyword.
    with pytest.raises(v.ModelError, match="control=0,3.19"):
        v.incremental(vault, control=(0.0, 3.19))


def test_issue31_item1_identify_recovers_a_spreading():
    arch = v.generate.arch(live="none")
    f = json.loads(v.settle(arch, move={"right": (0.01, 0.0)}).to_json())
    omax = max(p["opening"] for j in f["joints"] for p in j["points"])
    cracks = [
        {"joint": j["id"], "opening": [p["opening"] if p["opening"] > 1e-7 * omax else 0.0
                                        for p in j["points"]]}
        for j in f["joints"]
        if any(p["opening"] > 1e-7 * omax for p in j["points"])
    ]
    for unknowns in ({"right": "u"}, ["right=u"]):
        r = v.identify(arch, {"cracks": cracks}, unknowns, ranges=False)
        u = json.loads(r.to_json())["unknowns"][0]["value"]
        assert abs(u - 0.01) < 1e-6, u


def test_issue31_item1_sweep_with_and_without_executor(half):
    arch = v.Model.from_json(half / "arch.json")
    a = v.sweep(arch, move={"right": (0.0, -0.01)}, magnitudes=2)
    with ThreadPoolExecutor(2) as ex:
        b = v.sweep(arch, move={"right": (0.0, -0.01)}, magnitudes=2, executor=ex)
    assert a._lines == b._lines
    w = [json.loads(line)["work_dead_loads"] for line in a._lines]
    # A settlement's work is linear in its magnitude.
    assert abs(2 * w[0] - w[1]) <= 1e-7 * abs(w[1])


def test_issue31_item1_tilt3d_and_safety_through_the_request():
    # A 1 × 1 × 2 m block tips over at tan α = b / h = 0.5 (friction not limiting).
    b = v.generate.block(size=(1.0, 1.0, 2.0))
    t = v.tilt(b, direction="+x", friction=1.0)
    assert abs(math.tan(math.radians(t.tilt_angle)) - 0.5) < 1e-6
    s = v.safety(b, friction=1.0)
    assert s.stands
    # The exact friction cone: the same tipping angle (it overturns before it slides).
    te = v.tilt(b, direction="+x", friction=1.0, friction_cone="exact")
    assert abs(math.tan(math.radians(te.tilt_angle)) - 0.5) < 1e-5


def test_issue31_item1_least_thickness_milankovitch():
    r = v.least_thickness("arch", live="none", voussoirs=64, bisection_tolerance=1e-4)
    assert abs(r.thickness_over_radius - 0.1075) < 0.01 * 0.1075
    assert len(r.model) == 64
    with pytest.raises(ValueError, match="bisection_tolerance=2"):
        v.least_thickness("arch", bisection_tolerance=2.0)
