"""Issue 29 item 5 (session 14): the least friction coefficient of the canonical forces to a
stated precision (``least_friction_precision``, the CLI's ``--least-friction-precision``), in 2D
and 3D, and ``canonical=True`` honoured by ``limit`` on a 3D model (it was dropped there). The
CLI is the reference (same bytes); the least μ's reference is an independent bisection to 1e-6
(crates/voussoir/tests/issue29_friction_precision.rs: 1.20280 on the README's wall)."""

import json

import pytest

import voussoir as v


@pytest.fixture(scope="module")
def readme_wall(cli, tmp_path_factory):
    path = tmp_path_factory.mktemp("models") / "wall.json"
    cli("gen", "wall", "--courses", "8", "--units", "10", "--unit", "0.4,0.2", "-o", path)
    return path


@pytest.fixture(scope="module")
def vault(cli, tmp_path_factory):
    path = tmp_path_factory.mktemp("models") / "vault.json"
    cli("gen", "vault", "--live", "full", "--depth", "1", "--rings", "3", "-o", path)
    return path


def test_issue29_item5_least_friction_precision_2d_equals_cli(cli, readme_wall):
    reference = 1.2027998  # independent bisection to 1e-6 (the Rust test)
    for prec in (None, 1e-3):
        kw = {} if prec is None else {"least_friction_precision": prec}
        r = v.settle(readme_wall, profile="uniform:2.8,4.0,-0.01", ranges=False, **kw)
        f = r.to_dict()["canonical"]["forces"]
        p = 0.05 if prec is None else prec
        shown = f["friction_precision"]
        assert 0 < shown <= p
        least = f["least_friction"]
        assert reference * (1 - 1e-5) <= least <= reference / (1 - shown) * (1 + 1e-5), least
        assert f["friction"] >= least and f["friction_demand"] <= f["friction"] * (1 + 1e-6)
        args = ["settle", readme_wall, "--profile", "uniform:2.8,4.0,-0.01", "--no-ranges", "--json"]
        if prec is not None:
            args += ["--least-friction-precision", str(prec)]
        assert r.to_json() == cli(*args).stdout


def test_issue29_item5_least_friction_precision_refused_where_it_does_not_apply(readme_wall):
    with pytest.raises(ValueError, match="least_friction_precision"):
        v.settle(readme_wall, profile="uniform:2.8,4.0,-0.01", least_friction_precision=0.0)
    with pytest.raises(ValueError, match="least_friction_precision"):
        v.settle(readme_wall, profile="uniform:2.8,4.0,-0.01", raw=True,
                 least_friction_precision=1e-3)
    with pytest.raises(ValueError, match="least_friction_precision"):
        v.limit(v.generate.arch(live="full"), least_friction_precision=1e-3)


def test_issue29_item5_limit_canonical_is_honoured_in_3d(cli, vault):
    # λ of the vault is the paper arch's (README: 0.4346); with canonical=True the result
    # carries the canonical record, as the CLI's `limit --canonical`.
    r = v.limit(vault, canonical=True, least_friction_precision=0.01)
    d = r.to_dict()
    assert abs(d["load_multiplier"] - 0.4346) < 5e-5
    assert d["canonical"]["mechanism"]["selected_by"] in ("optimum", "least_crack_area", "generic_vertex")
    ref = cli("limit", vault, "--canonical", "--least-friction-precision", "0.01", "--json").stdout
    assert r.to_json() == ref
    assert "canonical" not in v.limit(vault).to_dict()
