"""The Python API itself: arrays, pickling, dataframes, drawings, errors, executors."""

import concurrent.futures as cf
import json
import math
import pickle

import numpy as np
import pytest

import voussoir as v


@pytest.fixture(scope="module")
def arch():
    return v.generate.arch(live="full")


def test_model_arrays(arch):
    assert len(arch) == 64 and len(arch.blocks) == 64
    b0 = arch.blocks[0]
    assert isinstance(b0, np.ndarray) and b0.shape == (4, 2)
    # Every voussoir lies in the ring R_i = 2.86 ≤ r ≤ R_e = 3.19 (the paper's arch).
    r = np.hypot(*np.vstack(arch.blocks).T)
    assert r.min() == pytest.approx(2.86, abs=1e-9) and r.max() == pytest.approx(3.19, abs=1e-9)
    names = [s.name for s in arch.supports]
    assert names == ["left", "right"] == arch.support_names
    assert arch.supports[0].motion.tolist() == [0.0, 0.0, 0.0]
    assert arch.check() == (64, 65, 2)  # 63 joints between voussoirs + 2 springings
    assert v.Model.from_json(arch.to_json()) == arch
    assert v.Model.from_dict(arch.to_dict()) == arch


def test_results_arrays_and_statics(arch):
    r = v.limit(arch)
    assert r.block_motions.shape == (64, 3)
    assert r.joint_forces.shape == (65, 2)
    pts = r.point_results
    assert pts.shape == (130, 7)
    assert (r.point_openings >= -1e-12).all()
    # Global equilibrium (an independent check of the arrays): the reactions carry the weight
    # and λ times the live load. The voussoirs are straight-sided: the ring is the difference of
    # two half 64-gons, area ½·64·sin(π/64)·(R_e² − R_i²).
    gamma, ri, re = 18.0, 2.86, 3.19
    weight = gamma * 0.5 * 64 * math.sin(math.pi / 64) * (re**2 - ri**2)
    live = 1.0 * 2 * re  # 1 kN/m² on the horizontal projection of the extrados
    fy = sum(x[1] for x in r.reactions.values())
    assert fy == pytest.approx(weight + r.load_multiplier * live, rel=1e-9)
    # Symmetric load on a symmetric arch: the symmetric five-hinge mechanism (springings,
    # haunches, crown).
    assert len(r.hinges) == 5
    assert r.hinges[:, 0].astype(int).tolist() == r.hinge_joints


def test_settlement_result_fields(arch):
    r = v.settle(arch, move={"right": (0.01, 0)})
    assert r.status and r.message
    c = r.certificate
    assert c["ok"] and c["relative_gap"] == r.duality_gap
    # The dual optimum is the work of the reactions on the settlement: H_right × 0.01.
    h = r.reactions["right"][0]
    assert r.work_reactions == pytest.approx(-h * 0.01, rel=1e-9) or r.work_reactions == pytest.approx(h * 0.01, rel=1e-9)


def test_pickle_models_and_results(arch):
    r = v.settle(arch, move={"right": (0.01, 0)})
    for obj in (arch, r, v.limit(arch)):
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and back.to_json() == obj.to_json()
    s = v.sweep(arch, move={"right": (0.01, 0)}, steps=3)
    assert pickle.loads(pickle.dumps(s)) == s


def test_dataframes(arch):
    pd = pytest.importorskip("pandas")  # optional dependency; installed by requirements-test.txt
    r = v.limit(arch)
    df = r.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) == 130
    assert df["normal_force"].to_numpy() == pytest.approx(r.point_results[:, 5])
    assert len(r.to_dataframe("joints")) == 65 and len(r.to_dataframe("blocks")) == 64
    c = v.capacity(arch, move={"right": (0.02, 0)}, steps=4)
    assert list(c.to_dataframe().columns) == ["settlement", "load_multiplier", "valid", "status"]
    s = v.sweep(arch, move={"right": (0.01, 0)}, steps=2)
    assert "motion.right.u" in s.to_dataframe().columns


def test_drawings(arch, tmp_path):
    r = v.settle(arch, move={"right": (0.01, 0)})
    svg = r._repr_svg_()
    assert svg.startswith("<svg") and "</svg>" in svg
    assert r.svg() == svg  # deterministic
    assert "<svg" in r._repr_html_()
    r.save_png(tmp_path / "r.png")
    assert (tmp_path / "r.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    c = v.capacity(arch, move={"right": (0.02, 0)}, steps=4)
    assert "<svg" in c._repr_svg_()
    assert "<html" in c.report().lower()
    assert arch._repr_svg_().startswith("<svg")
    t = v.tilt(v.generate.wall(live="horizontal"))
    assert t._repr_svg_().startswith("<svg")


def test_png_matches_cli(cli, paper_arch, tmp_path):
    r = v.settle(v.Model.from_json(paper_arch), move={"right": (0.01, 0)})
    r.save_png(tmp_path / "py.png")
    cli("settle", paper_arch, "--move", "right=0.01,0", "--png", tmp_path / "cli.png")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()


def test_errors_are_exceptions_not_crashes(arch):
    with pytest.raises(v.ModelError, match="at least 2 voussoirs"):
        v.generate.arch(voussoirs=0)
    with pytest.raises(v.ModelError):
        v.Model.from_json("{not json")
    with pytest.raises(ValueError):
        v.limit(arch, method="simplex-please")
    with pytest.raises(v.ModelError, match="capacity needs a settlement"):
        v.capacity(arch)
    with pytest.raises(v.ModelError, match="settle needs a support motion"):
        v.settle(arch)
    with pytest.raises(v.ModelError, match="friction"):
        v.limit(arch, friction=-1)
    assert issubclass(v.SolverError, v.VoussoirError) and issubclass(v.ModelError, v.VoussoirError)


def test_single_analysis_on_executor(arch):
    with cf.ThreadPoolExecutor(2) as ex:
        fut = v.limit(arch, executor=ex)
        assert isinstance(fut, cf.Future)
        assert fut.result() == v.limit(arch)
    with cf.ProcessPoolExecutor(1) as ex:
        r = v.settle(arch, move={"right": (0.01, 0)}, executor=ex).result()
    assert r == v.settle(arch, move={"right": (0.01, 0)})


def test_sweep_matches_cli_jsonl_and_csv(cli, paper_arch, tmp_path):
    args = ["--move", "right=0.01,-0.004", "--move", "left=-0.005,-0.002", "--samples", "12", "--seed", "7"]
    cli("sweep", paper_arch, *args, "--jsonl", tmp_path / "s.jsonl", "--csv", tmp_path / "s.csv")
    s = v.sweep(
        v.Model.from_json(paper_arch),
        move={"right": (0.01, -0.004), "left": (-0.005, -0.002)},
        samples=12,
        seed=7,
    )
    assert s.to_jsonl() == (tmp_path / "s.jsonl").read_text()
    assert s.to_csv() == (tmp_path / "s.csv").read_text()
    # Shards partition the tasks.
    a = v.sweep(paper_arch, move={"right": (0.01, -0.004), "left": (-0.005, -0.002)}, samples=12, seed=7, shard="0/2")
    b = v.sweep(paper_arch, move={"right": (0.01, -0.004), "left": (-0.005, -0.002)}, samples=12, seed=7, shard=(1, 2))
    assert sorted(a.records + b.records, key=lambda r: r["index"]) == s.records
    with pytest.raises(ValueError, match="exactly one"):
        v.sweep(paper_arch, move={"right": (0.01, 0)})
