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


def notebooks():
    build = os.path.dirname(os.environ.get("PYTHONPATH", "").split(os.pathsep)[0])
    folder = os.path.join(build, "examples")
    return sorted(os.path.join(folder, f) for f in os.listdir(folder) if f.endswith(".ipynb")) if os.path.isdir(folder) else []


def test_every_example_is_a_notebook():
    assert {os.path.basename(n)[:-6] + ".py" for n in notebooks()} == set(WRITES)


@pytest.mark.parametrize("notebook", notebooks(), ids=os.path.basename)
def test_notebook_executes(notebook, tmp_path):
    """Issue 46: the examples as notebooks (written from the scripts' `# %%` cells by the build),
    executed as Jupyter executes them (nbconvert, a Python kernel), leaving nothing behind."""
    env = dict(os.environ, TMPDIR=str(tmp_path / "tmp"), PYDEVD_DISABLE_FILE_VALIDATION="1")
    os.makedirs(env["TMPDIR"])
    p = subprocess.run([sys.executable, "-m", "jupyter", "nbconvert", "--to", "notebook", "--execute",
                        "--ExecutePreprocessor.timeout=240", "--output-dir", str(tmp_path), notebook],
                       capture_output=True, text=True, env=env, timeout=300, cwd=os.path.dirname(notebook))
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    import json

    done = json.load(open(tmp_path / os.path.basename(notebook)))
    code = [c for c in done["cells"] if c["cell_type"] == "code"]
    assert code and all(c["execution_count"] for c in code)
    assert not any(o.get("output_type") == "error" for c in code for o in c["outputs"])
    assert [f for f in os.listdir(env["TMPDIR"]) if f.startswith("laserwb-example-")] == []
