"""Session 27 (lead), issue 29: a capacity curve whose structure has no equilibrium right after
the onset of settlement (the grid façade, right half settling 20 cm) reports the zero at the
onset, certified, in Python as in the CLI (the analysis decides; the front ends print)."""

import json

import voussoir as v
from voussoir.generate import facade


def test_the_zero_at_the_onset_of_settlement_as_the_cli_says(tmp_path, cli):
    model = tmp_path / "grid.json"
    facade(element=2.0, live="horizontal").to_json(model)
    r = v.capacity(str(model), profile="uniform:11,22,-0.2", steps=6)
    assert r.zero_capacity_settlement == 0.0
    assert r.zero_capacity_bracket is None
    assert "to 0 at its onset" in r.message and "(certified)" in r.message
    # Every settled step certified without equilibrium.
    statuses = [p["status"] for p in r.to_dict()["curve"]]
    assert statuses[0] == "collapse" and set(statuses[1:]) == {"no_equilibrium"}
    # The CLI's JSON, the same numbers.
    out = tmp_path / "r.json"
    cli("capacity", model, "--profile", "uniform:11,22,-0.2", "--steps", "6", "-o", out)
    c = json.loads(out.read_text())
    assert c["zero_capacity_settlement"] == r.zero_capacity_settlement
    assert c["message"] == r.message
