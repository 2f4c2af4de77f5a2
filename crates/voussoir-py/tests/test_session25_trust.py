"""Session 25, trust (helper h-trust): the Python API refuses what the CLI refuses, with the
same words (the checks sit in the request layer both call), and an option given at its
default's value where it does nothing is refused as any other value is."""

import re

import pytest

import voussoir as v


@pytest.fixture(scope="module")
def arch(tmp_path_factory, cli):
    """The paper's arch (16 voussoirs, live load on the whole span), by the CLI."""
    path = tmp_path_factory.mktemp("s25") / "arch.json"
    cli("gen", "arch", "--voussoirs", "16", "--live", "full", "-o", path)
    return path


def cli_refusal(cli, *args):
    r = cli(*args, check=False)
    assert r.returncode != 0, args
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), r.stderr
    return lines[0]


def same_words(cli_line, py_error, phrase):
    """Both messages carry `phrase` (the request layer's words; the option's name differs:
    `--keep-fixed` / `keep_fixed`)."""
    assert phrase in cli_line, cli_line
    assert phrase in str(py_error), str(py_error)


def test_session25_sweep_options_of_another_mode_at_their_default(arch, cli):
    move = {"right": (0.01, 0.0)}
    for kw, name in ((dict(seed=1), "seed=1"), (dict(cov=0.3), "cov=0.3")):
        with pytest.raises(ValueError) as e:
            v.sweep(str(arch), move=move, magnitudes=2, **kw)
        assert f"{name}: applies to the Monte Carlo samples of samples=N only" in str(e.value)
    line = cli_refusal(cli, "sweep", arch, "--move", "right=0.01,0", "--magnitudes", "2", "--seed", "1")
    assert "--seed 1: applies to the Monte Carlo samples of --samples N only" in line
    # With samples, seed=1 and cov=0.3 are the defaults: the same records, the CLI's.
    a = v.sweep(str(arch), move=move, samples=2)
    assert a == v.sweep(str(arch), move=move, samples=2, seed=1, cov=0.3)
    assert a != v.sweep(str(arch), move=move, samples=2, seed=2)


def test_session25_crushing_and_shape_parameters_where_they_do_nothing(arch, cli):
    for c in ("linear", "conic"):
        with pytest.raises(ValueError) as e:
            v.limit(str(arch), crushing=c)
        line = cli_refusal(cli, "limit", arch, "--crushing", c)
        same_words(line, e.value, "needs a compressive strength")
    plain = v.limit(str(arch), compressive_strength=5000).load_multiplier
    assert plain == v.limit(str(arch), compressive_strength=5000, crushing="linear").load_multiplier
    with pytest.raises(ValueError, match=re.escape("half_angle=60: applies to shape=segmental only")):
        v.generate.arch(half_angle=60)
    with pytest.raises(ValueError, match=re.escape("offset=0.5: applies to shape=pointed only")):
        v.generate.vault(shape="segmental", offset=0.5)
    assert v.generate.arch(shape="segmental", half_angle=60) == v.generate.arch(shape="segmental")


def test_session25_refusals_of_sessions_23_24_in_python(arch, cli, tmp_path):
    cases = [
        # keep_fixed without a fixed support
        (
            lambda: v.capacity(str(arch), move={"right": (0.01, 0.0)}, keep_fixed=True, steps=2),
            ["capacity", arch, "--move", "right=0.01,0", "--keep-fixed", "--steps", "2"],
            "keeps fixed supports fixed, but no support is fixed",
        ),
        # a profile that moves no support
        (
            lambda: v.settle(str(arch), profile="uniform:20,30,-0.01"),
            ["settle", arch, "--profile", "uniform:20,30,-0.01"],
            "the profile moves no support",
        ),
        # a motion within the round-off of the coordinates
        (
            lambda: v.settle(str(arch), move={"right": (1e-30, 0.0)}),
            ["settle", arch, "--move", "right=1e-30,0"],
            "below 1e-14 of the structure's size",
        ),
        # non-associative friction without friction
        (
            lambda: v.limit(str(arch), non_associative=True),
            ["limit", arch, "--non-associative"],
            "needs friction: no joint has a friction coefficient",
        ),
        (
            lambda: v.settle(str(arch), move={"right": (0.01, 0.0)}, non_associative=True),
            ["settle", arch, "--move", "right=0.01,0", "--non-associative"],
            "needs friction: no joint has a friction coefficient",
        ),
        # capacity cold with friction
        (
            lambda: v.capacity(str(arch), move={"right": (0.01, 0.0)}, cold=True, friction=0.6, steps=2),
            ["capacity", arch, "--move", "right=0.01,0", "--cold", "--friction", "0.6", "--steps", "2"],
            "are solved from scratch already",
        ),
        # friction above 1e4
        (
            lambda: v.limit(str(arch), friction=1e5),
            ["limit", arch, "--friction", "1e5"],
            "above 10000, which no joint has",
        ),
    ]
    for py, args, phrase in cases:
        with pytest.raises(ValueError) as e:
            py()
        same_words(cli_refusal(cli, *args), e.value, phrase)
