"""--scheduler runs the same tasks on a real Dask cluster, with the same results as local runs."""

from __future__ import annotations

import pytest

from tests.conftest import run_servicebot

distributed = pytest.importorskip("distributed")

SWEEP = {"scenario": "default", "seeds": 2, "set": {"duration_s": 5},
         "grid": {"slip.track_factor": [0.9, 1.1]},
         "sample": {"n": 2, "initial_pose.yaw_rad": {"uniform": [-0.3, 0.3]}},
         "expect": ["collisions == 0"]}


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as local:
        yield local


def test_a_dask_cluster_gives_the_local_results(cluster, write_sweep, tmp_path):
    sweep = write_sweep(SWEEP)
    local = run_servicebot("sweep", sweep, "--out", tmp_path / "local", "--jobs", "2")
    assert local.returncode == 0, local.stderr
    remote = run_servicebot("sweep", sweep, "--out", tmp_path / "dask", "--keep", "csv",
                            "--scheduler", cluster.scheduler_address, timeout=180)
    assert remote.returncode == 0, remote.stderr
    assert f"on Dask at {cluster.scheduler_address}" in remote.stderr
    assert remote.stdout == local.stdout
    assert (tmp_path / "dask" / "runs.csv").read_bytes() == \
        (tmp_path / "local" / "runs.csv").read_bytes()
    assert len(list((tmp_path / "dask").glob("runs/*/csv/ground_truth.csv"))) == 8
    with distributed.Client(cluster) as client:
        prefixes = client.run_on_scheduler(
            lambda dask_scheduler: {name: p.state_counts["memory"]
                                    for name, p in dask_scheduler.task_prefixes.items()})
    assert prefixes.get("simulate_task") == 8
