"""Folders of SLR passes and of footprint frames on a Dask cluster (dask.distributed).

One task per CRD file (a pass) and one task per batch of frames; every task runs the core
through this module, so the products are the bytes ``laserwb-cli`` writes for the same inputs:

- ``reprocess_passes(client, crd_files, out_dir)``: per file NAME.frd, ``out_dir/NAME.csv``,
  ``NAME.flagged.frd`` and ``NAME.npt``, as ``laserwb-cli slr NAME.frd -o NAME.csv --crd-out
  NAME.flagged.frd --npt-out NAME.npt``;
- ``reprocess_frames(client, frame_files, out_csv, batch=...)``: the report of ``laserwb-cli
  footprint FILES -o OUT.csv``, its rows made in batches on the workers and written in input
  order by the client.

The client may be a ``LocalCluster``'s or one of a multi-node cluster (docs/scale.md): the workers
need ``laserwb`` importable and the same file system paths.
"""
import ctypes
import os
import time

_tuned = False


def _undo_nanny_malloc_trim():
    """Dask's nanny starts its workers with MALLOC_TRIM_THRESHOLD_=65536 (the config key
    distributed.nanny.pre-spawn-environ). A fixed trim threshold also switches off glibc's
    dynamic mmap threshold, so every large temporary array of a pass is a fresh mmap: a pass took
    4 times as long in a worker (0.67 against 2.8 passes/s, docs/scale.md). In such a process the
    two thresholds are set as glibc's dynamic ones would grow (256 MiB trim, 32 MiB mmap); nothing
    changes where the variable is not set."""
    global _tuned
    if _tuned or not os.environ.get("MALLOC_TRIM_THRESHOLD_"):
        return
    try:
        libc = ctypes.CDLL("libc.so.6")
        libc.mallopt(-1, 256 << 20)  # M_TRIM_THRESHOLD
        libc.mallopt(-3, 32 << 20)  # M_MMAP_THRESHOLD
    except (OSError, AttributeError):  # not glibc: nothing to undo
        pass
    _tuned = True


def _pass_task(path, out_dir, params, preset, satellite, cpf, stations):
    import laserwb  # (imported on the worker)

    _undo_nanny_malloc_trim()
    laserwb.slr.set_search_threads(1)  # one core per task: the cluster's workers are the parallelism
    stem = os.path.splitext(os.path.basename(path))[0]
    outs = {k: os.path.join(out_dir, stem + ext) for k, ext in (("csv", ".csv"), ("crd", ".flagged.frd"), ("npt", ".npt"))}
    t0 = time.perf_counter()
    try:
        r = laserwb.slr.process(path, params=params, preset=preset, satellite=satellite, cpf=cpf, stations=stations, **outs)
    except laserwb.Error as e:
        return {"input": path, "status": "failed", "reason": str(e), "seconds": time.perf_counter() - t0}
    return {"input": path, "status": "doubtful" if r.doubt else "ok", "reason": r.doubt, "points": len(r.accepted),
            "accepted": r.accepted_count, "normal_points": len(r.normal_points["epoch_s"]),
            "seconds": time.perf_counter() - t0, **outs}


def reprocess_passes(client, crd_files, out_dir, params=None, preset=None, satellite=None, cpf=None, stations=None):
    """One Dask task per CRD file (its first full-rate pass); returns one dict per file, in order."""
    os.makedirs(out_dir, exist_ok=True)
    futures = [client.submit(_pass_task, os.path.abspath(f), os.path.abspath(out_dir), params, preset, satellite, cpf,
                             stations, pure=False) for f in crd_files]
    return client.gather(futures)


def _frames_task(files, params, preset, method, centres):
    import laserwb

    _undo_nanny_malloc_trim()
    t0 = time.perf_counter()
    # One thread per task: the cluster's workers are the parallelism.
    rep = laserwb.footprint.fit_batch(files, params=params, preset=preset, method=method, centres=centres, threads=1)
    return rep.csv_rows(), len(files), time.perf_counter() - t0


def reprocess_frames(client, frame_files, out_csv, batch=16, params=None, preset=None, method=None, centres=None):
    """The footprint report of frame_files, one Dask task per `batch` frames; returns the seconds of
    each task. The report is written atomically by the core, header and rows in input order."""
    import laserwb

    files = [os.fspath(f) for f in frame_files]  # (as given: the report's file column; absolute on a cluster)
    futures = [client.submit(_frames_task, files[i:i + batch], params, preset, method, centres, pure=False)
               for i in range(0, len(files), batch)]
    parts = client.gather(futures)
    laserwb.write_text(out_csv, laserwb.footprint.csv_header() + "".join(p[0] for p in parts))
    return [p[2] for p in parts]
