"""Every examples/*.py (the notebook-style examples, one per family, and the Dask one) runs to
its end and writes what it says it writes."""
import os
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

EXAMPLES = os.path.join(SOURCE_DIR, "examples")
WRITES = {"footprint.py": ["report.csv"], "slr.py": ["screened.csv", "flagged.frd", "pass.npt"],
          "trend.py": ["trend.csv"], "calibration.py": ["centre.csv", "ranking.csv", "beams.csv", "stats.csv"],
          "radiometry.py": ["row.tif", "map.tif", "fit.csv"],
          "dask_reprocess.py": ["footprint.csv", "slr/pass1.npt"]}


def test_every_example_is_listed():
    found = {f for f in os.listdir(EXAMPLES) if f.endswith(".py") and not f.startswith("_")}
    assert found == set(WRITES)


@pytest.mark.parametrize("name", sorted(WRITES))
def test_example_runs(name, tmp_path):
    args = [sys.executable, os.path.join(EXAMPLES, name), str(tmp_path)]
    if name == "dask_reprocess.py":
        args += ["--workers", "2", "--batch", "16"]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([EXAMPLES, os.environ.get("PYTHONPATH", "")]))
    p = subprocess.run(args, capture_output=True, text=True, env=env, timeout=240)
    assert p.returncode == 0, p.stdout + p.stderr
    for out in WRITES[name]:
        assert os.path.getsize(tmp_path / out) > 0, out
    # the examples use `# %%` cells (a notebook in VS Code, Spyder, Jupytext)
    assert "# %%" in open(os.path.join(EXAMPLES, name)).read()


def test_examples_in_a_notebook_kernel_leave_nothing_behind(tmp_path):
    """Issue 46: under Jupyter every example broke on its first cell (workdir() took the kernel's
    "-f CONNECTION_FILE" as its folder) and left /tmp/laserwb-example-* behind. Run as a kernel
    runs it: a temporary folder, removed at exit."""
    env = dict(os.environ, TMPDIR=str(tmp_path), PYTHONPATH=os.pathsep.join([EXAMPLES, os.environ.get("PYTHONPATH", "")]))
    for name in ("slr.py", "trend.py"):
        p = subprocess.run([sys.executable, os.path.join(EXAMPLES, name), "-f", str(tmp_path / "kernel-1.json")],
                           capture_output=True, text=True, env=env, timeout=240)
        assert p.returncode == 0, p.stdout + p.stderr
        assert not (tmp_path / "-f").exists()
        assert [f for f in os.listdir(tmp_path) if f.startswith("laserwb-example-")] == [], os.listdir(tmp_path)


def test_dask_example_refuses_an_empty_folder(tmp_path):
    (tmp_path / "empty").mkdir()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([EXAMPLES, os.environ.get("PYTHONPATH", "")]))
    p = subprocess.run([sys.executable, os.path.join(EXAMPLES, "dask_reprocess.py"), str(tmp_path / "w"), "--passes",
                        str(tmp_path / "empty"), "--frames", str(tmp_path / "empty")],
                       capture_output=True, text=True, env=env, timeout=120)
    assert p.returncode != 0 and "holds no CRD files" in p.stderr and "ZeroDivisionError" not in p.stderr, p.stderr
