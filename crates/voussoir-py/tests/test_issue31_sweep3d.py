"""Issue 31 item 2: 3D sweeps from Python with ``executor=``.

A sweep of a barrel vault (the paper's arch extruded, 3D) over support settlements, its
scenarios submitted to a ``concurrent.futures`` executor, equals the serial sweep record for
record (byte-identical JSON lines and CSV), equals the CLI's ``voussoir sweep --jsonl`` on the
same model, and each record's motions have six components that are the base motions scaled or
rotated by hand.
"""

import concurrent.futures
import json
import math

import pytest

import voussoir as v

MOVES = {"right": (0.01, 0.0, -0.005), "left": (0.0, 0.0, -0.003)}


@pytest.fixture(scope="module")
def vault():
    return v.generate.vault(voussoirs=16, depth=1.0, rings=2)


def test_issue31_item2_3d_sweep_with_executor_equals_serial(vault):
    serial = v.sweep(vault, move=MOVES, samples=6, seed=5, threads=1)
    assert len(serial) == 6
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as ex:
        threaded = v.sweep(vault, move=MOVES, samples=6, seed=5, executor=ex)
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as ex:
        processes = v.sweep(vault, move=MOVES, samples=6, seed=5, executor=ex)
    for other in (threaded, processes):
        assert other.to_jsonl() == serial.to_jsonl()
        assert other.to_csv() == serial.to_csv()
    assert serial.certified.all()
    # Each support's motion is its base motion times one random factor (six components).
    for r in serial.records:
        for name, base in MOVES.items():
            m = r["motions"][name]
            assert len(m) == 6
            f = m[2] / base[2]
            want = [base[0] * f, base[1] * f, base[2] * f, 0.0, 0.0, 0.0]
            assert m == pytest.approx(want, rel=1e-12, abs=1e-15)
    # A shard of the executor's sweep is the serial sweep's tasks ≡ 1 (mod 2).
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as ex:
        shard = v.sweep(vault, move=MOVES, samples=6, seed=5, shard=(1, 2), executor=ex)
    assert shard.records == serial.records[1::2]


def test_issue31_item2_3d_angle_sweep_rotates_in_the_xz_plane_and_equals_the_cli(vault, cli, tmp_path):
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as ex:
        r = v.sweep(vault, move=MOVES, angles=4, executor=ex)
    assert list(r.parameters) == [0.0, 90.0, 180.0, 270.0]
    for rec in r.records:
        a = math.radians(rec["parameter"])
        u, _, w = MOVES["right"]
        want = [math.cos(a) * u - math.sin(a) * w, 0.0, math.sin(a) * u + math.cos(a) * w, 0.0, 0.0, 0.0]
        assert rec["motions"]["right"] == pytest.approx(want, abs=1e-15)
    path = tmp_path / "vault.json"
    vault.to_json(path)
    out = tmp_path / "cli.jsonl"
    cli("sweep", path, "--move", "right=0.01,0,-0.005", "--move", "left=0,0,-0.003",
        "--angles", "4", "--jsonl", out)
    assert out.read_text() == r.to_jsonl()
    try:
        import pandas  # noqa: F401  (optional dependency of to_dataframe)
    except ImportError:
        return
    df = r.to_dataframe()
    assert list(df["motion.right.w"]) == [rec["motions"]["right"][2] for rec in r.records]
    assert "motion.right.theta_z" in df.columns


def test_issue31_item2_3d_sweep_refuses_the_exact_cone(vault):
    with pytest.raises(v.ModelError, match="friction_cone"):
        v.sweep(vault, move=MOVES, magnitudes=2, friction_cone="exact")
