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


def test_dask_futures_relative_paths_and_a_missing_frame(client, data, tmp_path, monkeypatch):
    """Issue 46: results came back only as gathered lists (nothing for progress() or
    as_completed); one missing frame lost the whole report; relative frame paths were sent as
    they were (wrong on another node's working folder); a missing output folder failed only after
    every task had run."""
    from distributed import Future, as_completed

    files = sorted(glob.glob(str(data / "passes" / "*.frd")))
    futures = lwd.submit_passes(client, files + [str(tmp_path / "gone.frd")], str(tmp_path / "out"))
    assert len(futures) == 4 and all(isinstance(f, Future) for f in futures)
    done = {f.key: f.result() for f in as_completed(futures)}
    results = [done[f.key] for f in futures]
    assert [r["status"] for r in results[:3]] == [r["status"] for r in lwd.reprocess_passes(client, files, str(tmp_path / "again"))]
    assert results[3]["status"] == "failed" and "gone.frd" in results[3]["reason"]
    # frames given relative to the client's folder, one of them missing: the report holds every
    # frame (the missing one rejected, as laserwb-cli footprint --keep-going writes it) by its absolute path
    monkeypatch.chdir(data / "shots")
    shots = sorted(glob.glob("shot_*.png"))[:5] + ["missing.png"]
    futures = lwd.submit_frames(client, shots, batch=2)
    assert len(futures) == 3 and all(isinstance(f, Future) for f in futures)
    lwd.reprocess_frames(client, shots, str(tmp_path / "dask.csv"), batch=2)
    absolute = [os.path.abspath(s) for s in shots]
    cli("footprint", "--keep-going", *absolute, "-o", tmp_path / "cli.csv", "-q")
    same_bytes(tmp_path / "cli.csv", tmp_path / "dask.csv")
    rows = open(tmp_path / "dask.csv").read().splitlines()
    assert len(rows) == 7 and rows[-1].startswith(absolute[-1] + ",") and ",rejected," in rows[-1]
    # an output folder that does not exist: refused before any task is submitted
    class Counting:  # the client, counting what is submitted through it
        def __init__(self, c):
            self.c, self.submitted = c, 0

        def submit(self, *args, **kw):
            self.submitted += 1
            return self.c.submit(*args, **kw)

        def gather(self, futures):
            return self.c.gather(futures)

    counting = Counting(client)
    with pytest.raises(FileNotFoundError):
        lwd.reprocess_frames(counting, shots, str(tmp_path / "nowhere" / "r.csv"))
    assert counting.submitted == 0
    lwd.reprocess_frames(counting, shots, str(tmp_path / "counted.csv"), batch=3)
    assert counting.submitted == 2


def test_both_workers_take_tasks(client):
    import time

    def where(_):
        time.sleep(0.2)
        from distributed import get_worker
        return get_worker().address

    addresses = set(client.gather(client.map(where, range(6), pure=False)))
    assert len(addresses) == 2
