"""Shared inputs of the Python tests: simulated with the CLI's simulators (exact truth), in one
temporary folder per session. ctest sets PYTHONPATH (the build's python/ folder), LWB_CLI (the
build's laserwb-cli) and SOURCE_DATE_EPOCH (the normal-point files' production date: fixed, so
the CLI's and Python's files can be compared byte for byte)."""
import os
import subprocess

import pytest

os.environ.setdefault("SOURCE_DATE_EPOCH", "1700000000")

CLI = os.environ.get("LWB_CLI", "")
SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHARED = os.environ.get("LWB_SHARED_DIR", os.path.join(SOURCE_DIR, "..", "shared"))


def cli(*args, ok=(0,), cwd=None):
    """Runs laserwb-cli; returns the CompletedProcess (exit code must be in `ok`)."""
    assert CLI and os.path.exists(CLI), "LWB_CLI must name the build's laserwb-cli"
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert p.returncode in ok, f"laserwb-cli {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}"
    return p


def same_bytes(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        da, db = fa.read(), fb.read()
    assert len(da) > 0, f"{a} is empty"
    assert da == db, f"{a} and {b} differ"


@pytest.fixture(scope="session")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("inputs")
    cli("simulate", "footprint", "--count", 12, "--seed", 7, "-q", d / "shots")
    cli("simulate", "footprint", "--full-frame", "--count", 2, "--seed", 2, "-q", d / "frames")
    cli("simulate", "trend", "--months", 6, "--seed", 4, "-q", d / "centroids.csv")
    (d / "passes").mkdir()
    for seed, kind in ((3, "conventional"), (4, "leo"), (5, "conventional")):
        cli("simulate", "slr", "--kind", kind, "--seed", seed, "-q", d / "passes" / f"pass{seed}.frd")
    cli("simulate", "slr", "--kind", "khz", "--points", 5000, "--signal-fraction", 0.2, "--seed", 1, "-q", d / "pass.csv")
    cli("simulate", "calib", "--seed", 5, "-q", d / "calib")
    return d
