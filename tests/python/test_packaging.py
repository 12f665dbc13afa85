"""Issue 46: `pip install --no-build-isolation .` builds and installs the module with the Debian
toolchain, downloading nothing (pyproject.toml, app/python/pep517_backend.py). The build tree of
this test run is reused (LWB_BUILD_DIR): the install is checked, not a second build."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_pip_installs_the_module_without_downloading(data, tmp_path):
    build = os.path.dirname(os.environ["PYTHONPATH"].split(os.pathsep)[0])
    target = tmp_path / "site"
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LWB_CODECS")}
    env.update(LWB_BUILD_DIR=build, PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_CACHE_DIR="1")
    p = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-index",
                        "--target", str(target), SOURCE_DIR], capture_output=True, text=True, env=env, timeout=900)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    for f in ("__init__.py", "distributed.py", "_prefix_paths.py", "liblaserwb_codecs.so"):
        assert (target / "laserwb" / f).exists(), f
    assert [d for d in os.listdir(target) if d.startswith("laserwb-") and d.endswith(".dist-info")]
    # The installed package alone (no build tree on the path, no LWB_CODECS): it imports from the
    # target, reads a frame through its own codec module, and fits it as the build's module does.
    shot = sorted((data / "shots").glob("shot_*.png"))[0]
    code = ("import laserwb, sys; print(laserwb.__file__); print(laserwb.__version__); "
            f"r = laserwb.footprint.fit(laserwb.footprint.read_frame({str(shot)!r})); print(repr(r['x']))")
    q = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=str(tmp_path),
                       env=dict(env, PYTHONPATH=str(target)), timeout=120)
    assert q.returncode == 0, q.stderr
    where, version, x = q.stdout.split("\n")[:3]
    assert where.startswith(str(target)), where
    import laserwb

    assert version == laserwb.__version__
    assert float(x) == laserwb.footprint.fit(laserwb.footprint.read_frame(str(shot)))["x"]


def test_type_stubs_tell_mypy_the_api(tmp_path):
    """Issue 46: `inspect.signature` failed on the compiled functions and editors knew nothing of
    them. The package carries stubs written from the built module (app/python/stubgen.py): every
    public function and class of each family is in them, and mypy (Debian's) checks a script
    against them: a sound one passes, a misspelt keyword and a wrong result type are reported."""
    import ast
    import shutil

    import laserwb

    package = os.path.dirname(laserwb.__file__)
    assert os.path.exists(os.path.join(package, "py.typed"))
    for family in ("footprint", "slr", "trend", "calib", "radiometry"):
        tree = ast.parse(open(os.path.join(package, family + ".pyi")).read())
        declared = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
        public = {n for n in vars(getattr(laserwb, family)) if not n.startswith("_")}
        assert public <= declared, (family, public - declared)
    slr = ast.parse(open(os.path.join(package, "slr.pyi")).read())
    load = next(n for n in slr.body if isinstance(n, ast.FunctionDef) and n.name == "load_pass")
    assert [a.arg for a in load.args.args] == ["path", "pass_number", "cpf", "stations", "params"]
    mypy = shutil.which("mypy")
    if not mypy:  # (make test installs it: .ci/install-deps)
        import pytest
        pytest.skip("mypy is not installed (Debian mypy)")
    good = tmp_path / "good.py"
    good.write_text("import laserwb\n"
                    "p = laserwb.slr.load_pass('pass.frd', pass_number=2)\n"
                    "r = laserwb.slr.run(p, params=laserwb.slr.SlrParams(cosine_c=0.97))\n"
                    "n: int = r.accepted_count + len(p)\n"
                    "rep = laserwb.footprint.fit_batch('shots', keep_going=True)\n")
    bad = tmp_path / "bad.py"
    bad.write_text("import laserwb\n"
                   "p = laserwb.slr.load_pass('pass.frd', pass_nmber=2)\n"
                   "n: str = laserwb.slr.run(p).accepted_count\n")
    env = dict(os.environ, MYPYPATH=os.path.dirname(package))
    run = lambda f: subprocess.run([mypy, "--no-incremental", "--cache-dir", os.devnull, str(f)], capture_output=True,
                                   text=True, env=env, cwd=str(tmp_path), timeout=300)
    g = run(good)
    assert g.returncode == 0, g.stdout + g.stderr
    b = run(bad)
    assert b.returncode == 1
    assert 'Unexpected keyword argument "pass_nmber" for "load_pass"' in b.stdout, b.stdout
    assert 'expression has type "int", variable has type "str"' in b.stdout, b.stdout
