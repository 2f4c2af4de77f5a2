"""Issue 29 item 3 (session 17): a "cannot stand" answer carries the certificate that no
equilibrium exists (``no_equilibrium``: the elastic program's Farkas certificate), in Python as
in the CLI (the same JSON). The model, by hand (crates/voussoir/tests/issue29_cannot_stand_certified.rs):
a 1 m cube on a support under x in [0, 0.45] (its weight at x = 0.5, outside its base) beside a
second cube that carries the live load; with the support under [0, 0.55] it stands."""

import json

import voussoir as v


def _model(tmp_path, edge):
    m = {
        "blocks": [
            {"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]},
            {"polygon": [[3, 0], [4, 0], [4, 1], [3, 1]]},
        ],
        "supports": [
            {"name": "a", "polygon": [[-1, -1], [edge, -1], [edge, 0], [-1, 0]]},
            {"name": "b", "polygon": [[2, -1], [5, -1], [5, 0], [2, 0]]},
        ],
        "loads": {"live": [{"type": "point", "block": 1, "at": [3.5, 1.0], "force": [-1.0, 0.0]}]},
    }
    p = tmp_path / f"stack-{edge}.json"
    p.write_text(json.dumps(m))
    return p


def test_issue29_item3_cannot_stand_certified_like_the_cli(cli, tmp_path):
    path = _model(tmp_path, 0.45)
    r = v.limit(path)
    c = r.no_equilibrium
    assert r.to_dict()["status"] == "no_equilibrium" and r.load_multiplier is None
    assert c is not None and c["ok"] is True and c["violation"] > 1e-6, c
    ref = json.loads(cli("limit", path, "--json").stdout)
    assert ref["no_equilibrium"] == c
    s = v.settle(path, move=["b=0,-0.01"])
    assert s.to_dict()["status"] == "cannot_stand"
    assert s.no_equilibrium is not None and s.no_equilibrium["ok"] is True
    assert "certified" in s.to_dict()["message"]


def test_issue29_item3_no_certificate_where_it_stands(tmp_path):
    path = _model(tmp_path, 0.55)
    r = v.limit(path)
    assert r.no_equilibrium is None
    # λ by hand: the second cube (W = 18 kN) tips about (3, 0) under λ·1 kN at height 1 m.
    assert abs(r.load_multiplier - 9.0) < 1e-7
