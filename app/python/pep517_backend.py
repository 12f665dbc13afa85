"""The build backend of ``pip install --no-build-isolation .`` (PEP 517; pyproject.toml names it).

It builds the module with the project's own CMake build and the Debian toolchain (nothing is
downloaded) and packs a wheel of the ``laserwb`` package: the compiled ``_laserwb`` module, the
pure-Python parts and the image codec module the core loads (``liblaserwb_codecs.so``, found
through ``_prefix_paths``). The build folder is ``LWB_BUILD_DIR`` when set (an existing,
configured build tree: only the module's targets are brought up to date), else ``build-pip``
beside the sources (configured without the workbench and the tests on first use).
"""
import base64
import hashlib
import os
import re
import subprocess
import sys
import sysconfig
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NAME = "laserwb"


def _version():
    text = open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8").read()
    m = re.search(r"project\(laserwb VERSION ([0-9.]+)", text)
    if not m:
        raise RuntimeError("CMakeLists.txt: no project(laserwb VERSION ...)")
    return m.group(1)


def _build():
    """Builds the module's targets; returns the build folder."""
    build = os.environ.get("LWB_BUILD_DIR") or os.path.join(ROOT, "build-pip")
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DLWB_BUILD_GUI=OFF",
                        "-DLWB_BUILD_TESTS=OFF", "-DLWB_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"],
                       check=True)
    jobs = str(os.cpu_count() or 1)
    subprocess.run(["cmake", "--build", build, "-j", jobs, "--target", "laserwb_python", "laserwb_python_package",
                    "laserwb_python_stubs", "laserwb_codecs"], check=True)
    return build


def _tag():
    impl = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{impl}-{impl}-{platform}"


def _metadata(version):
    return (f"Metadata-Version: 2.1\nName: {NAME}\nVersion: {version}\n"
            "Summary: Laser Workbench: footprint spot review, SLR pass screening, laser calibration\n"
            "Requires-Python: >=3.8\nRequires-Dist: numpy\n"
            "Provides-Extra: dask\nRequires-Dist: distributed; extra == \"dask\"\n"
            "Provides-Extra: pandas\nRequires-Dist: pandas; extra == \"pandas\"\n")


def get_requires_for_build_wheel(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build = _build()
    version = _version()
    package = os.path.join(build, "python", NAME)
    files = {}  # name in the wheel -> bytes
    for f in sorted(os.listdir(package)):
        full = os.path.join(package, f)
        if os.path.isfile(full) and not f.endswith(".pyc") and f != "_prefix_paths.py":
            files[f"{NAME}/{f}"] = open(full, "rb").read()
    codecs = os.path.join(build, "bin", "liblaserwb_codecs.so")
    files[f"{NAME}/liblaserwb_codecs.so"] = open(codecs, "rb").read()
    files[f"{NAME}/_prefix_paths.py"] = (b"# Written by the pip build backend: the codec module is in the package.\n"
                                         b'CODECS = "liblaserwb_codecs.so"\n')
    info = f"{NAME}-{version}.dist-info"
    files[f"{info}/METADATA"] = _metadata(version).encode()
    files[f"{info}/WHEEL"] = (f"Wheel-Version: 1.0\nGenerator: laserwb pep517_backend\nRoot-Is-Purelib: false\n"
                              f"Tag: {_tag()}\n").encode()
    record = []
    for name, data in files.items():
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        record.append(f"{name},sha256={digest},{len(data)}")
    record.append(f"{info}/RECORD,,")
    files[f"{info}/RECORD"] = ("\n".join(record) + "\n").encode()
    wheel = f"{NAME}-{version}-{_tag()}.whl"
    with zipfile.ZipFile(os.path.join(wheel_directory, wheel), "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            z.writestr(zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0)), data,
                       compress_type=zipfile.ZIP_DEFLATED)
    return wheel
