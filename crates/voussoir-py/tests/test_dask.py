"""A 200-scenario Monte Carlo sweep on a local Dask cluster (two worker processes) equals the
serial sweep scenario by scenario, and the serial sweep equals the CLI's."""

import pytest

import voussoir as v

distributed = pytest.importorskip("distributed")  # installed by requirements-test.txt

MOVES = {"right": (0.01, -0.004), "left": (-0.005, -0.002)}


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_dask_sweep_equals_serial(client, paper_arch, cli, tmp_path):
    model = v.Model.from_json(paper_arch)
    serial = v.sweep(model, move=MOVES, samples=200, seed=3, threads=1)
    assert len(serial) == 200
    on_dask = v.sweep(model, move=MOVES, samples=200, seed=3, executor=client.get_executor())
    assert len(on_dask) == 200
    for a, b in zip(serial.records, on_dask.records):
        assert a == b, a["index"]
    assert on_dask == serial
    # The Client itself works as an executor (submit/result).
    assert v.sweep(model, move=MOVES, samples=20, seed=3, executor=client).records == serial.records[:20]
    # Both ran on the cluster's workers: two processes.
    assert len(client.scheduler_info()["workers"]) == 2
    # Certified scenarios (the LPs' duality gap) and the CLI agree with the serial run.
    assert serial.certified.all()
    cli("sweep", paper_arch, "--move", "right=0.01,-0.004", "--move", "left=-0.005,-0.002",
        "--samples", "200", "--seed", "3", "--jsonl", tmp_path / "cli.jsonl")
    assert serial.to_jsonl() == (tmp_path / "cli.jsonl").read_text()


def test_models_and_results_travel_to_workers(client, paper_arch):
    model = v.Model.from_json(paper_arch)
    fut = client.submit(v.limit, model)
    assert fut.result() == v.limit(model)
