"""Session 28 (issue 29): above masonry's friction the default least-μ search stops and states
the bracket (docs/canonical.md "The forces"), in Python as in the CLI (one request layer: the
same bytes). The bracket is checked in Rust against an independent bisection to 1e-6
(crates/voussoir/tests/issue29_session28_friction_limit.rs); here: Python says what the CLI
says, and the field holds Coulomb's rule at the μ it states."""

import voussoir as v


def test_session28_least_mu_above_two_is_a_bracket_as_in_the_cli(cli, tmp_path):
    path = tmp_path / "wall.json"
    # 1,815 blocks: a force program of more than 20,000 columns, where the policy applies.
    cli("gen", "wall", "--courses", "30", "--units", "60", "--unit", "1,0.5", "-o", path)
    r = v.settle(path, profile="uniform:0,18,-0.01")
    f = r.to_dict()["canonical"]["forces"]
    assert f["least_friction_above"] == 2.0
    assert 2.0 < f["least_friction"] <= f["friction"]
    big = 0.0
    worst = float("-inf")
    for j in r.to_dict()["joints"]:
        for p in j["points"]:
            worst = max(worst, abs(p["shear_force"]) - f["friction"] * p["normal_force"])
            big = max(big, abs(p["normal_force"]), abs(p["shear_force"]))
    assert worst <= 1e-7 * big, (worst, big)
    out = cli("settle", path, "--profile", "uniform:0,18,-0.01", "--json").stdout
    assert r.to_json() == out
