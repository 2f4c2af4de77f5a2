"""Issue 29 item 5 (session 16): tilt, capacity and sweep report the canonical mechanism by
default, in 2D and 3D; ``raw=True`` the solver's own (the CLI's ``--raw``), with the same λ,
tilt and works. The CLI is the reference: the same JSON either way."""

import json

import voussoir as v


def test_issue29_item5_tilt_capacity_sweep_raw_keyword(cli, tmp_path, paper_arch):
    vault = tmp_path / "vault.json"
    cli("gen", "vault", "--live", "full", "--depth", "1", "--rings", "3", "-o", vault)
    m = v.Model.from_json(vault)
    d, r = v.tilt(m).to_dict(), v.tilt(m, raw=True).to_dict()
    assert d["limit"]["canonical"]["mechanism"]["unique"] is True
    assert r["limit"].get("canonical") is None
    assert abs(d["tilt_angle"] - r["tilt_angle"]) <= 1e-9 * abs(r["tilt_angle"])
    assert v.tilt(m, raw=True).to_json() == cli("tilt", vault, "--raw", "--json").stdout
    assert v.tilt(m).to_json() == cli("tilt", vault, "--json").stdout
    # 2D capacity: the settlement mechanism selected by default, the steps with canonical_steps.
    a = v.Model.from_json(paper_arch)
    c = v.capacity(a, move={"right": (0.02, 0)}, steps=4).to_dict()
    s = v.capacity(a, move={"right": (0.02, 0)}, steps=4, canonical_steps=True).to_dict()
    w = v.capacity(a, move={"right": (0.02, 0)}, steps=4, raw=True).to_dict()
    assert c["canonical"]["steps"] is False and c["canonical"]["settlement"]["unique"] is True
    assert s["canonical"]["steps"] is True and s["canonical"]["steps_selected"] == 5
    assert w.get("canonical") is None
    for p, q in zip(s["curve"], w["curve"]):
        assert abs(p["load_multiplier"] - q["load_multiplier"]) <= 1e-9 * w["curve"][0]["load_multiplier"]
    ref = json.loads(
        cli("capacity", paper_arch, "--move", "right=0.02,0", "--steps", "4", "--canonical-steps", "--json").stdout
    )
    assert ref["canonical"] == s["canonical"]
    # A sweep: the same works with raw=True.
    d = v.sweep(m, move={"right": (0.01, 0, 0)}, magnitudes=2)
    r = v.sweep(m, move={"right": (0.01, 0, 0)}, magnitudes=2, raw=True)
    for x, y in zip(d.records, r.records):
        assert abs(x["work_dead_loads"] - y["work_dead_loads"]) <= 1e-9 * y["work_dead_loads"]
