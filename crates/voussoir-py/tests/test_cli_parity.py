"""The package against the CLI: same library, same numbers, same bytes."""

import json
import subprocess
import sys

import pytest

import voussoir as v


def test_must_show_limit_one_liner(cli, paper_arch):
    # The command, verbatim; its output against the CLI's JSON to 1e-12 and against the
    # paper's λ = 0.429 ± 2 % (README verification table: 0.4346).
    out = subprocess.run(
        [
            sys.executable,
            "-c",
            "import voussoir as v; m = v.generate.arch(live='full'); print(v.limit(m).load_multiplier)",
        ],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    lam = float(out)
    ref = json.loads(cli("limit", paper_arch, "--json").stdout)["load_multiplier"]
    assert out.startswith("0.4346")
    assert abs(lam - ref) <= 1e-12
    assert abs(lam - 0.429) / 0.429 < 0.02


def test_generators_byte_identical_to_cli(cli, tmp_path):
    cases = [
        (v.generate.arch(live="full"), ["arch", "--live", "full"]),
        (v.generate.arch(shape="pointed", voussoirs=20), ["arch", "--shape", "pointed", "--voussoirs", "20"]),
        (v.generate.arch(shape="segmental", half_angle=50), ["arch", "--shape", "segmental", "--half-angle", "50"]),
        (v.generate.lintel(compressive_strength=2400), ["lintel", "--compressive-strength", "2400"]),
        (v.generate.wall(first_course="half", live="horizontal"), ["wall", "--first-course", "half", "--live", "horizontal"]),
        (v.generate.facade(element=1.0), ["facade", "--element", "1.0"]),
        (
            v.generate.facade(element=(1.0, 0.5), openings=["rect:2,2,4,5", "rose:11,10,1.5"], mesh="running-bond"),
            ["facade", "--element", "1.0,0.5", "--opening", "rect:2,2,4,5", "--opening", "rose:11,10,1.5", "--mesh", "running-bond"],
        ),
    ]
    for model, args in cases:
        assert model.to_json() == cli("gen", *args).stdout, args


def test_limit_json_byte_identical(cli, paper_arch):
    r = v.limit(v.Model.from_json(paper_arch))
    assert r.to_json() == cli("limit", paper_arch, "--json").stdout
    # A path works as the model too.
    assert v.limit(str(paper_arch)) == r


def test_settle_paper_arch_matches_cli(cli, paper_arch):
    m = v.Model.from_json(paper_arch)
    r = v.settle(m, move={"right": (0.01, 0)})
    ref = json.loads(cli("settle", paper_arch, "--move", "right=0.01,0", "--json").stdout)
    assert r.hinge_joints == [h["joint"] for h in ref["hinges"]]
    # The paper (README verification table): hinges at the crown and the 13th joint from each
    # springing, joints 13, 32, 51 of the 64-voussoir arch.
    assert r.hinge_joints == [13, 32, 51]
    assert r.duality_gap == ref["duality_gap"]
    assert r.duality_gap <= 1e-7 and r.certified
    assert r.work_dead_loads == ref["work_dead_loads"]
    assert r.to_json() == cli("settle", paper_arch, "--move", "right=0.01,0", "--json").stdout
    # Vertical settlement with the springing tied: hinges 1, 13, 32 (README table).
    r2 = v.settle(m, move={"right": (0, -0.01)}, fixed="right")
    out = cli("settle", paper_arch, "--move", "right=0,-0.01", "--fixed", "right", "--json").stdout
    assert r2.to_json() == out
    assert r2.hinge_joints == [1, 13, 32]
    # CLI-style strings are accepted as well.
    assert v.settle(m, move="right=0.01,0") == r


def test_capacity_incremental_tilt_byte_identical(cli, paper_arch, tmp_path):
    m = v.Model.from_json(paper_arch)
    c = v.capacity(m, move={"right": (0.02, 0)}, steps=10)
    assert c.to_json() == cli("capacity", paper_arch, "--move", "right=0.02,0", "--steps", "10", "--json").stdout
    assert c.curve.shape == (11, 2)
    i = v.incremental(m, control=(0, 3.2), max=0.002, step=0.0005)
    assert i.to_json() == cli(
        "incremental", paper_arch, "--control", "0,3.2", "--max", "0.002", "--step", "0.0005", "--json"
    ).stdout
    wall = tmp_path / "wall.json"
    cli("gen", "wall", "--live", "horizontal", "-o", wall)
    t = v.tilt(v.Model.from_json(wall), direction="-x")
    assert t.to_json() == cli("tilt", wall, "--direction", "-x", "--json").stdout
    assert t.tilt_angle is not None and 0 < t.tilt_angle < 90


def _bad_model(tmp_path):
    # Two blocks that overlap: valid JSON, invalid structure.
    d = {
        "blocks": [
            {"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]},
            {"polygon": [[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]]},
        ],
        "supports": [{"name": "base", "polygon": [[-1, -1], [2, -1], [2, 0], [-1, 0]]}],
    }
    p = tmp_path / "bad.json"
    p.write_text(json.dumps(d))
    return p


def test_malformed_model_raises_model_error_with_cli_message(cli, tmp_path):
    # An invalid structure: the message is the CLI's one line (without its "error: " prefix).
    bad = _bad_model(tmp_path)
    r = cli("limit", bad, check=False)
    assert r.returncode == 1
    expected = r.stderr.strip().removeprefix("error: ")
    assert "\n" not in expected and expected.startswith("invalid model")
    with pytest.raises(v.ModelError) as e:
        v.limit(v.Model.from_json(bad))
    assert str(e.value) == expected
    assert isinstance(e.value, v.VoussoirError)
    # Not JSON of a model (unknown field): the CLI's message names the file.
    p = tmp_path / "typo.json"
    p.write_text('{"blocks": [], "supports": [], "suports": []}')
    r = cli("limit", p, check=False)
    with pytest.raises(v.ModelError) as e:
        v.Model.from_json(p)
    assert str(e.value) == r.stderr.strip().removeprefix("error: ")
    # A missing file.
    r = cli("limit", tmp_path / "nope.json", check=False)
    with pytest.raises(v.ModelError) as e:
        v.Model.from_json(tmp_path / "nope.json")
    assert str(e.value) == r.stderr.strip().removeprefix("error: ")
    # An unknown support: the library's request error, as the CLI words it.
    arch = tmp_path / "a.json"
    cli("gen", "arch", "-o", arch)
    r = cli("settle", arch, "--move", "middle=0.01,0", check=False)
    with pytest.raises(v.ModelError) as e:
        v.settle(v.Model.from_json(arch), move={"middle": (0.01, 0)})
    assert str(e.value) == r.stderr.strip().removeprefix("error: ")


def test_absurd_input_is_an_exception_not_a_crash(cli, paper_arch):
    # A settlement of 1e308 m: its work overflows, the program is refused. (1e300 m is
    # answered: the programs are solved in nondimensional form.) The CLI prints one line;
    # Python raises a VoussoirError with that line, and the interpreter lives on.
    r = cli("settle", paper_arch, "--move", "right=1e308,0", check=False)
    assert r.returncode == 1
    with pytest.raises(v.VoussoirError) as e:
        v.settle(v.Model.from_json(paper_arch), move={"right": (1e308, 0)})
    assert str(e.value) == r.stderr.strip().removeprefix("error: ")
    assert v.limit(v.Model.from_json(paper_arch)).load_multiplier > 0


def test_profile_settlement_matches_cli(cli, tmp_path):
    # The default wall (2 m long): its foundation settles 1 cm under x ∈ [1.1, 2.5].
    wall = tmp_path / "wall.json"
    cli("gen", "wall", "-o", wall)
    out = cli("settle", wall, "--profile", "uniform:1.1,2.5,-0.01", "--json").stdout
    m = v.Model.from_json(wall)
    assert v.settle(m, profile="uniform:1.1,2.5,-0.01").to_json() == out
    assert v.settle(m, profile={"type": "uniform", "x0": 1.1, "x1": 2.5, "v": -0.01}).to_json() == out
    r = cli("settle", wall, "--profile", "uniform:2.8", check=False)
    with pytest.raises(v.ModelError) as e:
        v.settle(m, profile="uniform:2.8")
    assert str(e.value) == r.stderr.strip().removeprefix("error: ")
