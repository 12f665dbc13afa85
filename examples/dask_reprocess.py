# %% [markdown]
# # Reprocessing folders on a Dask cluster
# A folder of CRD passes (one task per pass) and a folder of frames (one task per batch) on a
# Dask cluster: a LocalCluster on this machine by default, or any scheduler given with
# --scheduler tcp://HOST:8786 (docs/scale.md: dask-jobqueue on Slurm, dask-ssh). The products are
# the files laserwb-cli writes for the same inputs.
#
#     python3 examples/dask_reprocess.py WORKDIR [--workers N] [--scheduler ADDRESS]
#         [--passes DIR] [--frames DIR] [--batch N]
# (Everything runs under main(): Dask's worker processes import this file again.)

# %%
import argparse
import glob
import os
import sys
import time

import laserwb.distributed as lwd
from _inputs import finish, simulate, workdir


def inputs(args):
    """The folders to reprocess: given, or simulated (6 LAGEOS-like passes, 64 shots)."""
    passes = args.passes or os.path.join(args.work, "passes")
    if not args.passes:
        os.makedirs(passes, exist_ok=True)
        for seed in range(1, 7):
            simulate("slr", "--kind", "conventional", "--seed", seed, os.path.join(passes, f"pass{seed}.frd"))
    frames = args.frames or os.path.join(args.work, "shots")
    if not args.frames:
        simulate("footprint", "--count", 64, "--seed", 1, frames)
    found = (sorted(glob.glob(os.path.join(passes, "*.frd")) + glob.glob(os.path.join(passes, "*.frd.gz"))),
             sorted(glob.glob(os.path.join(frames, "*.png"))))
    for what, folder, files in (("CRD files (*.frd, *.frd.gz)", passes, found[0]), ("frames (*.png)", frames, found[1])):
        if not files:  # (the throughput below divided by zero)
            raise SystemExit(f"dask_reprocess: {folder} holds no {what}")
    return found


# %%
def main():
    from distributed import Client, LocalCluster

    ap = argparse.ArgumentParser()
    ap.add_argument("work")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster here)")
    ap.add_argument("--passes", help="folder of CRD files (default: 6 simulated passes)")
    ap.add_argument("--frames", help="folder of frames (default: 64 simulated 32x32 shots)")
    ap.add_argument("--batch", type=int, default=16)
    # (in a notebook the kernel's own arguments are not ours: a temporary folder, the defaults)
    args = ap.parse_args([workdir()] if "ipykernel" in sys.modules else None)
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    passes, shots = inputs(args)

    # The cluster: here, or the scheduler of a cluster of several nodes
    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        # (the workers' scratch space in the work folder: nothing left in the system's)
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None, silence_logs=40,
                               local_directory=os.path.join(args.work, "dask-worker-space"))
        client = Client(cluster)
    print(client)

    # One task per pass
    t0 = time.perf_counter()
    results = lwd.reprocess_passes(client, passes, os.path.join(args.work, "slr"))
    wall = time.perf_counter() - t0
    for r in results:
        print(f"{os.path.basename(r['input'])}: {r['status']} {r.get('accepted', '')} {r['reason']}")
    busy = sum(r["seconds"] for r in results)  # time inside the tasks, over all workers
    print(f"{len(passes)} passes in {wall:.2f} s: {len(passes) / wall:.2f} passes/s; "
          f"per worker busy {len(passes) / busy:.2f} passes/s")

    # One task per batch of frames
    t0 = time.perf_counter()
    busy = sum(lwd.reprocess_frames(client, shots, os.path.join(args.work, "footprint.csv"), batch=args.batch))
    wall = time.perf_counter() - t0
    print(f"{len(shots)} frames in {wall:.2f} s: {len(shots) / wall:.1f} frames/s; "
          f"per worker busy {len(shots) / busy:.1f} frames/s")
    client.close()
    if cluster is not None:
        cluster.close()
    finish()


if __name__ == "__main__":
    main()
