"""A folder of CRD passes and a folder of frames reprocessed on a Dask LocalCluster (two worker
processes on 127.0.0.1, one task per pass and per batch of frames): the files are those the CLI
writes for the same inputs, byte for byte."""
import glob
import os

import pytest

from conftest import cli, same_bytes

distributed = pytest.importorskip("distributed")

import laserwb.distributed as lwd  # noqa: E402


@pytest.fixture(scope="module")
def client():
    from distributed import Client, LocalCluster

    # Worker processes inherit PYTHONPATH (the build's laserwb) and SOURCE_DATE_EPOCH.
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                           dashboard_address=None, silence_logs=40)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_dask_passes_are_the_cli_products(client, data, tmp_path):
    files = sorted(glob.glob(str(data / "passes" / "*.frd")))
    assert len(files) == 3
    results = lwd.reprocess_passes(client, files, str(tmp_path / "dask"))
    assert len(results) == 3 and all(r["status"] in ("ok", "doubtful") for r in results), results
    os.makedirs(tmp_path / "cli")
    for f in files:
        stem = os.path.splitext(os.path.basename(f))[0]
        cli("slr", f, "-o", tmp_path / "cli" / f"{stem}.csv", "--crd-out", tmp_path / "cli" / f"{stem}.flagged.frd",
            "--npt-out", tmp_path / "cli" / f"{stem}.npt", "-q", ok=(0, 3))
        for ext in (".csv", ".flagged.frd", ".npt"):
            same_bytes(tmp_path / "cli" / (stem + ext), tmp_path / "dask" / (stem + ext))


def test_dask_frames_are_the_cli_report(client, data, tmp_path):
    shots = sorted(glob.glob(str(data / "shots" / "shot_*.png")))
    seconds = lwd.reprocess_frames(client, shots, str(tmp_path / "dask.csv"), batch=4)
    assert len(seconds) == 3  # 12 frames in batches of 4: three tasks
    cli("footprint", *shots, "-o", tmp_path / "cli.csv", "-q")
    same_bytes(tmp_path / "cli.csv", tmp_path / "dask.csv")


def test_both_workers_take_tasks(client):
    import time

    def where(_):
        time.sleep(0.2)
        from distributed import get_worker
        return get_worker().address

    addresses = set(client.gather(client.map(where, range(6), pure=False)))
    assert len(addresses) == 2
