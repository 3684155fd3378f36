"""A sweep on a dask.distributed cluster (a local one: two worker processes) gives the table
threads give."""

import pytest

from kresling.sweeps import design_grid, sweep

distributed = pytest.importorskip("distributed", reason="the 'dask' extra is not installed")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            yield client


@pytest.mark.parametrize("as_executor", [False, True], ids=["client", "client.get_executor()"])
def test_dask_cluster_equals_threads(client, as_executor, tmp_path):
    grid = design_grid((4, 8), 3)
    by_threads = sweep(grid, ["kb_ratio", "psi_ratio"], workers=1, progress=False)
    executor = client.get_executor() if as_executor else client
    on_cluster = sweep(grid, ["kb_ratio", "psi_ratio"], executor=executor, workers=2,
                       out=tmp_path / "sweep", progress=False)
    for column in ("kb_ratio", "kb_con", "psi_ratio", "status", "iterations", "index"):
        assert on_cluster[column].tolist() == by_threads[column].tolist()
    resumed = sweep(grid, ["kb_ratio", "psi_ratio"], executor=executor, out=tmp_path / "sweep",
                    progress=False)
    assert resumed.attrs["computed"] == 0


def test_cli_on_a_scheduler(client, tmp_path, capsys):
    from kresling.cli import main

    address = client.scheduler.address
    assert main(["sweep", "--n", "6", "--grid", "3", "--metrics", "kb_ratio", "--scheduler",
                 address, "--out", str(tmp_path), "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert "9 designs: 9 computed" in printed and "on 2 workers" in printed
    assert "optimum (kb_ratio): n = 6, Lc = 15 mm, lam = 0.9" in printed
