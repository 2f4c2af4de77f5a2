"""Issue 29 item 5 (session 18): the incremental analysis settles by the canonical settlement
mechanism by default; ``raw=True`` by the solver's own (the CLI's ``--raw``);
``canonical_steps=True`` selects every step's collapse mechanism too (``--canonical-steps``),
with λ unchanged; both together are refused. The CLI is the reference: the same JSON."""

import json

import pytest

import voussoir as v


def test_issue29_item5_incremental_raw_and_canonical_steps(cli, tmp_path):
    half = tmp_path / "half.json"
    cli("gen", "arch", "--live", "left", "-o", half)
    m = v.Model.from_json(half)
    kw = dict(control=(0, 3.19), max=0.002, step=0.0002, move={"right": (0, -0.0025)}, fixed="right")
    d = v.incremental(m, **kw).to_dict()
    r = v.incremental(m, raw=True, **kw).to_dict()
    s = v.incremental(m, canonical_steps=True, **kw).to_dict()
    # The paper's case has unique optima: the same path, recorded or not.
    assert d["canonical"]["settlement"]["unique"] is True and d["canonical"]["steps"] is False
    assert r.get("canonical") is None
    assert s["canonical"]["steps"] is True and s["canonical"]["steps_changed"] == 0
    assert s["canonical"]["steps_selected"] == len([p for p in s["curve"] if not p.get("before_closure", False)])
    for p, q in zip(s["curve"], r["curve"]):
        assert abs(p["load_multiplier"] - q["load_multiplier"]) <= 1e-9
    args = ["incremental", half, "--control", "0,3.19", "--max", "0.002", "--step", "0.0002",
            "--move", "right=0,-0.0025", "--fixed", "right", "--json"]
    assert json.loads(cli(*args, "--canonical-steps").stdout) == s
    assert json.loads(cli(*args, "--raw").stdout) == r
    with pytest.raises(ValueError, match="canonical_steps"):
        v.incremental(m, raw=True, canonical_steps=True, **kw)
