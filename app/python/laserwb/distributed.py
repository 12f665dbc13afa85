"""Folders of SLR passes and of footprint frames on a Dask cluster (dask.distributed).

One task per CRD file (a pass) and one task per batch of frames; every task runs the core
through this module, so the products are the bytes ``laserwb-cli`` writes for the same inputs:

- ``submit_passes(client, crd_files, out_dir)``: one future per file NAME.frd (for
  ``distributed.progress``, ``as_completed``, ``wait``), each writing ``out_dir/NAME.csv``,
  ``NAME.flagged.frd`` and ``NAME.npt`` as ``laserwb-cli slr NAME.frd -o NAME.csv --crd-out
  NAME.flagged.frd --npt-out NAME.npt`` and resolving to a dict (status, reason, counts, files);
  ``reprocess_passes`` gathers them in order.
- ``submit_frames(client, frame_files, batch=...)``: one future per batch of frames, each the
  batch's report rows; ``reprocess_frames(client, frame_files, out_csv)`` gathers them and writes
  the report of ``laserwb-cli footprint --keep-going FILES -o OUT.csv`` in input order (a frame that
  cannot be read is a rejected row, as with ``--keep-going``, not the loss of the report).

Paths are made absolute on the client (a worker on another node has another working folder);
the output folder is checked before any task is submitted. The client may be a
``LocalCluster``'s or one of a multi-node cluster (docs/scale.md): the workers need ``laserwb``
importable and the same file system paths.
"""
import ctypes
import errno
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
    except (laserwb.Error, OSError) as e:  # (a file that cannot be read: this pass fails, not the run)
        return {"input": path, "status": "failed", "reason": str(e), "seconds": time.perf_counter() - t0}
    return {"input": path, "status": "doubtful" if r.doubt else "ok", "reason": r.doubt, "points": len(r.accepted),
            "accepted": r.accepted_count, "normal_points": len(r.normal_points["epoch_s"]),
            "seconds": time.perf_counter() - t0, **outs}


def _writable_folder(folder):
    """Raises FileNotFoundError / NotADirectoryError / PermissionError for an output folder that
    cannot take files, before any task runs (it failed after every task had run)."""
    if not os.path.exists(folder):
        raise FileNotFoundError(errno.ENOENT, "output folder does not exist", folder)
    if not os.path.isdir(folder):
        raise NotADirectoryError(errno.ENOTDIR, "output folder is not a folder", folder)
    if not os.access(folder, os.W_OK | os.X_OK):
        raise PermissionError(errno.EACCES, "output folder is not writable", folder)


def submit_passes(client, crd_files, out_dir, params=None, preset=None, satellite=None, cpf=None, stations=None):
    """One Dask future per CRD file (its first full-rate pass), in order; out_dir is created."""
    os.makedirs(out_dir, exist_ok=True)
    _writable_folder(out_dir)
    absolute = (lambda f: None if f is None else os.path.abspath(os.fspath(f)))
    return [client.submit(_pass_task, absolute(f), absolute(out_dir), params, absolute(preset), satellite,
                          absolute(cpf), absolute(stations), pure=False) for f in crd_files]


def reprocess_passes(client, crd_files, out_dir, params=None, preset=None, satellite=None, cpf=None, stations=None):
    """submit_passes, gathered: one dict per file, in order."""
    return client.gather(submit_passes(client, crd_files, out_dir, params, preset, satellite, cpf, stations))


def _frames_task(files, params, preset, method, centres):
    import laserwb

    _undo_nanny_malloc_trim()
    t0 = time.perf_counter()
    # One thread per task: the cluster's workers are the parallelism. An unreadable frame is a
    # rejected row (--keep-going): one missing file does not lose the report.
    rep = laserwb.footprint.fit_batch(files, params=params, preset=preset, method=method, centres=centres, threads=1,
                                      keep_going=True)
    return rep.csv_rows(), len(files), time.perf_counter() - t0


def submit_frames(client, frame_files, batch=16, params=None, preset=None, method=None, centres=None):
    """One Dask future per `batch` frames, in order; each resolves to (report rows as CSV text,
    frames, seconds). The report's file column holds the absolute paths."""
    if batch < 1:
        raise ValueError(f"batch must be at least 1, not {batch}")
    files = [os.path.abspath(os.fspath(f)) for f in frame_files]
    return [client.submit(_frames_task, files[i:i + batch], params, preset, method, centres, pure=False)
            for i in range(0, len(files), batch)]


def reprocess_frames(client, frame_files, out_csv, batch=16, params=None, preset=None, method=None, centres=None):
    """The footprint report of frame_files (laserwb-cli footprint --keep-going), one Dask task per
    `batch` frames; returns the seconds of each task. The report is written atomically by the
    core, header and rows in input order; its folder is checked before anything is submitted."""
    import laserwb

    _writable_folder(os.path.dirname(os.path.abspath(os.fspath(out_csv))))
    parts = client.gather(submit_frames(client, frame_files, batch, params, preset, method, centres))
    laserwb.write_text(os.fspath(out_csv), laserwb.footprint.csv_header() + "".join(p[0] for p in parts))
    return [p[2] for p in parts]
