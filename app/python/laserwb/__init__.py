"""Laser Workbench from Python: the core's tasks, readers and writers (C++, pybind11).

The same code as ``laserwb-cli`` and the workbench runs here, so the files written from Python
are byte for byte those of the CLI for the same inputs and parameters.

Families (each a submodule, with its parameter class built from the family's schema):

- ``laserwb.footprint``: spot centre and verdict of footprint-camera shots (``fit``,
  ``fit_batch``, ``read_frame``, ``FootprintParams``)
- ``laserwb.slr``: SLR passes (``read_crd``, ``load_pass``, ``run``, ``process``, ``SlrParams``)
- ``laserwb.trend``: monthly centroid trend (``compute``, ``TrendParams``)
- ``laserwb.calib``: altimeter calibration (``detector``, ``waveform``, ``pointing``, ``stats``,
  ``CalibParams``)
- ``laserwb.radiometry``: radiometric calibration (``mosaic``, ``gcp``, ``fit``, ``apply``,
  ``check``, ``read_image``, ``RadiometryParams``); images in and out as numpy arrays or paths
- ``laserwb.distributed``: folders of passes and frames on a Dask cluster

Errors: ``laserwb.ParameterError`` (a ``ValueError``) for a refused parameter, with the schema's
message; Python's ``FileNotFoundError``, ``PermissionError``, ``IsADirectoryError`` for a file
that cannot be opened; ``laserwb.Error`` for anything else (a bad file names FILE:LINE).
"""
import os as _os
import sys as _sys

# An installed package finds the codec module (image reading) in the prefix's libexec/laserwb;
# a build tree's module knows where the build put it. LWB_CODECS, when set, wins.
try:
    from . import _prefix_paths  # written by cmake --install only

    _codecs = _os.path.normpath(_os.path.join(_os.path.dirname(__file__), _prefix_paths.CODECS))
    if not _os.environ.get("LWB_CODECS") and _os.path.exists(_codecs):
        _os.environ["LWB_CODECS"] = _codecs
except ImportError:
    pass

# numpy: the module is built against the system's (Debian's python3-numpy). An interpreter of
# the same version that does not see it (a pyenv or venv python3 first on PATH, as on this
# project's machines) is given Debian's dist-packages as a last resort, so that
# `python3 -c "import laserwb"` works there too; the C ABI of one minor version is shared.
try:
    import numpy as _np
except ImportError:
    import importlib.machinery as _machinery

    _debian = "/usr/lib/python3/dist-packages"
    _here = _os.path.dirname(__file__)
    # only an interpreter that can load this build's extension (same version and ABI tag)
    _loadable = any(_os.path.exists(_os.path.join(_here, "_laserwb" + sfx)) for sfx in _machinery.EXTENSION_SUFFIXES)
    if _loadable and _os.path.isdir(_os.path.join(_debian, "numpy")) and _debian not in _sys.path:
        _sys.path.append(_debian)
    import numpy as _np  # noqa: F811 (an ImportError here says what is missing)

from ._laserwb import Error, ParameterError, __version__, write_text  # noqa: E402
from ._laserwb import calib, footprint, radiometry, slr, trend  # noqa: E402


for _name in ("footprint", "slr", "trend", "calib", "radiometry"):
    _sys.modules[__name__ + "." + _name] = globals()[_name]


def _records(columns):
    """{column: array} as a numpy structured array (one record per row)."""
    names = list(columns)
    return _np.rec.fromarrays([columns[n] for n in names], names=names)


def _fit(roi, params=None, preset=None, method=None, centre=None):
    """Fits one ROI (a 2-D array) and returns its report row as {column: value}.

    The row is that of ``laserwb-cli footprint`` for the same frame: x, y (px), verdict, reasons,
    sigma_x, sigma_y, snr, crlb_px, ... (``footprint.csv_header()``). ``centre``: (x, y), the
    nominal spot centre (``--center``); without it the brightest spot-like blob or the whole ROI.
    """
    report = footprint.fit_batch(roi, params=params, preset=preset, method=method,
                                 centres=None if centre is None else [centre], threads=1)
    cols = report.columns()
    return {k: v[0].item() for k, v in cols.items()}


def _report_records(self):
    """The report as a numpy structured array (one record per ROI)."""
    return _records(self.columns())


footprint.fit = _fit
footprint.Report.to_records = _report_records


def _process(path, csv=None, crd=None, npt=None, pass_number=None, cpf=None, stations=None,
             params=None, preset=None, satellite=None):
    """One pass from its file to its products, as ``laserwb-cli slr PATH -o CSV --crd-out CRD
    --npt-out NPT [--pass K] [--cpf CPF --stations SINEX] [--preset FILE --satellite NAME]``.

    Returns the ``PassResult``; the files are written all or nothing. A doubtful pass is written
    (``result.doubt`` says why) as the CLI writes it (its exit code 3).
    """
    p = slr.load_pass(path, pass_number=pass_number, cpf=cpf, stations=stations)
    r = slr.run(p, params=params, preset=preset, satellite=satellite, stations=stations)
    if csv is not None or crd is not None or npt is not None:
        r.write(csv=csv, crd=crd, npt=npt)
    return r


slr.process = _process

__all__ = ["Error", "ParameterError", "__version__", "write_text", "footprint", "slr", "trend", "calib",
           "radiometry"]
