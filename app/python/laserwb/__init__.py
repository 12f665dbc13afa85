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

# numpy: the module is built against the system's (Debian's python3-numpy). An interpreter that
# cannot import it (a pyenv python3, an isolated venv) is told so; the package does not change
# sys.path (it once appended Debian's dist-packages, and a venv then imported dask from there).
try:
    import numpy as _np
except ImportError as _e:
    raise ImportError(
        f"laserwb needs numpy, which {_sys.executable} cannot import ({_e}): run Debian's "
        "/usr/bin/python3 (python3-numpy), make the venv with --system-site-packages, or install "
        "numpy in it") from _e

from ._laserwb import Error, ParameterError, __version__, write_text  # noqa: E402
from ._laserwb import calib, footprint, radiometry, slr, trend  # noqa: E402


for _name in ("footprint", "slr", "trend", "calib", "radiometry"):
    _sys.modules[__name__ + "." + _name] = globals()[_name]


class _Stage:
    """The parameters of one stage (``p.screen``): attributes read and set ``p["screen.NAME"]``."""

    __slots__ = ("_params", "_prefix")

    def __init__(self, params, prefix):
        object.__setattr__(self, "_params", params)
        object.__setattr__(self, "_prefix", prefix)

    def _names(self):
        n = len(self._prefix) + 1
        return sorted({k[n:].split(".")[0] for k in self._params.keys() if k.startswith(self._prefix + ".")})

    def __getattr__(self, name):
        return _attribute(self._params, self._prefix + "." + name, name)

    def __setattr__(self, name, value):
        key = self._prefix + "." + name
        if key not in self._params:
            raise AttributeError(_unknown(self._params, key, name))
        self._params[key] = value

    def __dir__(self):
        return self._names()

    def __repr__(self):
        return f"<{type(self._params).__name__} {self._prefix}: " + ", ".join(
            f"{n}={self._params[self._prefix + '.' + n]!r}" for n in self._names()
            if self._prefix + "." + n in self._params) + ">"


def _unknown(params, key, name):
    import difflib

    close = difflib.get_close_matches(key, params.keys(), n=3) or difflib.get_close_matches(
        name, [k.split(".")[-1] for k in params.keys()], n=3)
    return f"{type(params).__name__} has no parameter {name!r}" + (
        f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else "")


def _attribute(params, key, name):
    if key in params:
        return params[key]
    if any(k.startswith(key + ".") for k in params.keys()):
        return _Stage(params, key)
    raise AttributeError(_unknown(params, key, name))


def _full_key(params, name):
    """A keyword's key: the full key with "__" for ".", or a parameter's last name when only one
    parameter has it (max_iterations is in several stages: screen__max_iterations then)."""
    key = name.replace("__", ".")
    if key in params:
        return key
    owners = [k for k in params.keys() if k.split(".")[-1] == name]
    if len(owners) == 1:
        return owners[0]
    if owners:
        raise ParameterError(f"{name!r} is a parameter of several stages: give one of "
                             + ", ".join(k.replace(".", "__") for k in owners))
    raise ParameterError(_unknown(params, key, name))


def _params_class(cls):
    """The Python side of a family's parameter class: keyword arguments, attributes by stage,
    the mapping protocol and from_json (the schema's keys throughout)."""
    construct = cls.__init__

    def __init__(self, values=None, **keywords):
        construct(self, values)
        for name, value in keywords.items():
            self[_full_key(self, name)] = value

    __init__.__doc__ = (f"{cls.__name__}(values=None, **keywords): the command's defaults, then `values` "
                        "({key: value}) and the keywords: a parameter's name where only one stage has it "
                        "(cosine_c=0.97) or its key with '__' for '.' (screen__cosine_c=0.97).")

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        if any(k == name or k.startswith(name + ".") for k in self.keys()):
            return _attribute(self, name, name)
        return self[_full_key(self, name)] if name in {k.split(".")[-1] for k in self.keys()} else _attribute(self, name, name)

    def __setattr__(self, name, value):
        self[_full_key(self, name)] = value

    def __dir__(self):
        return sorted(set(object.__dir__(self)) | {k.split(".")[0] for k in self.keys()})

    def items(self):
        return [(k, self[k]) for k in self.keys()]

    def values(self):
        return [self[k] for k in self.keys()]

    def get(self, key, default=None):
        return self[key] if key in self else default

    @classmethod
    def from_json(klass, text):
        """Parameters from JSON text (what to_json and --print-config write), over the defaults."""
        import tempfile

        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            f.write(text)
        try:
            p = klass()
            p.load(f.name)
            return p
        finally:
            _os.unlink(f.name)

    for name, fn in (("__init__", __init__), ("__getattr__", __getattr__), ("__setattr__", __setattr__),
                     ("__dir__", __dir__), ("items", items), ("values", values), ("get", get)):
        setattr(cls, name, fn)
    cls.from_json = from_json


for _cls in (footprint.FootprintParams, slr.SlrParams, trend.TrendParams, calib.CalibParams,
             radiometry.RadiometryParams):
    _params_class(_cls)


def _records(columns):
    """{column: array} as a numpy structured array (one record per row)."""
    names = list(columns)
    return _np.rec.fromarrays([columns[n] for n in names], names=names)


def _fit(roi, params=None, preset=None, method=None, centre=None):
    """Fits one ROI (a 2-D array) and returns its report row as {column: value}.

    The row is that of ``laserwb-cli footprint`` for the same frame: x, y (px), verdict, reasons,
    sigma_x, sigma_y, snr, crlb_px, ... (``footprint.csv_header()``). ``centre``: (x, y), the
    nominal spot centre (``--center``); without it the brightest spot-like blob or the whole ROI.
    Numbers at the core's full precision; ``file`` is None (an array names no file).
    """
    report = footprint.fit_batch(roi, params=params, preset=preset, method=method,
                                 centres=None if centre is None else [centre], threads=1, names=[""])
    row = {k: v[0].item() for k, v in report.columns().items()}
    row["file"] = None
    return row


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


# ---- epochs as datetimes, and every result as a pandas DataFrame ------------------------------

def _pandas():
    try:
        import pandas
    except ImportError as e:
        raise ImportError(f"to_pandas() needs pandas, which {_sys.executable} cannot import ({e}): "
                          "Debian's python3-pandas") from e
    return pandas


def _datetimes(mjd, seconds):
    """Seconds of the day `mjd` as numpy datetime64[ns] (UTC); NaT where the day is unknown."""
    seconds = _np.asarray(seconds, dtype=float)
    if mjd is None:
        return _np.full(seconds.shape, _np.datetime64("NaT"), "datetime64[ns]")
    day = _np.datetime64("1858-11-17T00:00:00", "ns") + _np.timedelta64(int(mjd), "D")
    return day + _np.round(seconds * 1e9).astype("timedelta64[ns]")


def _frame(table):
    """A DataFrame of {column: array} (one row per element), of {group: {column: value}} (one row
    per group), of a dict of scalars (one row), or of a list of dicts (one row each)."""
    pd = _pandas()
    if isinstance(table, dict):
        if table and all(isinstance(v, dict) for v in table.values()):  # {group: {column: value}}
            return pd.DataFrame([{"group": k, **v} for k, v in table.items()])
        if table and all(_np.ndim(v) == 1 for v in table.values()):
            return pd.DataFrame({k: _np.asarray(v) for k, v in table.items()})
        return pd.DataFrame([table])
    return pd.DataFrame(list(table))


def _utc(frame, column):
    frame[column] = frame[column].dt.tz_localize("UTC")
    return frame


def _pass_epochs(self):
    """The pass's epochs as numpy datetime64[ns] (UTC; NaT for an O-C table, whose day is not known)."""
    return _datetimes(self.start_mjd, self.t)


def _pass_frame(self):
    """The pass as a DataFrame: epoch (UTC), t_s, oc_s, and tof_s and station_flag where the file has them."""
    cols = {"epoch": self.epochs, "t_s": self.t, "oc_s": self.oc}
    if len(self.tof):
        cols["tof_s"] = self.tof
    if len(self.station_flag):
        cols["station_flag"] = self.station_flag
    return _utc(_frame(cols), "epoch")


def _result_frame(self, table="points"):
    """A DataFrame of the result: table="points" (one row per point: epoch, t_s, oc_s, class,
    accepted, kept, residual_s) or "normal_points" (the normal points delivered, with their epoch)."""
    if table == "points":
        cols = {"epoch": _datetimes(self.start_mjd, self.t), "t_s": self.t, "oc_s": self.oc, "class": self.classes,
                "accepted": self.accepted}
        if len(self.kept):
            cols["kept"] = self.kept
        if len(self.residuals):
            cols["residual_s"] = self.residuals
        return _utc(_frame(cols), "epoch")
    if table == "normal_points":
        nps = dict(self.normal_points)
        frame = _frame({"epoch": _datetimes(self.start_mjd, nps["epoch_s"]), **nps})
        return _utc(frame, "epoch")
    raise ValueError(f"table must be 'points' or 'normal_points', not {table!r}")


def _summary_repr(self):
    """A result's repr: its family and class, its size and its headline values."""
    cls = type(self)
    parts = []
    if hasattr(cls, "__len__"):
        parts.append(f"{len(self)} rows")
    for attr in ("centre", "waveform", "fit"):
        d = getattr(self, attr, None)
        if isinstance(d, dict):
            parts.append(", ".join(f"{k} {v:.6g}" for k, v in d.items()
                                   if isinstance(v, (int, float)) and not isinstance(v, bool)) or "")
            break
    if isinstance(getattr(self, "beams", None), list):
        parts.append(f"{len(self.beams)} beams")
    if callable(getattr(self, "groups", None)):
        parts.append(f"{len(self.groups())} groups")
    for attr in ("reflectance", "image"):
        a = getattr(self, attr, None)
        if getattr(a, "ndim", 0) == 2:
            parts.append(f"{attr} {a.shape[1]}x{a.shape[0]} px")
            break
    for attr in ("doubts", "warnings"):
        v = getattr(self, attr, None)
        if v:
            parts.append(f"{len(v)} {attr}")
    return f"<laserwb.{cls.__module__.rsplit('.', 1)[-1]}.{cls.__name__}: " + "; ".join(p for p in parts if p) + ">"


for _cls in (trend.Trend, calib.DetectorFit, calib.PointingFit, calib.Stats, calib.WaveformFit,
             radiometry.ReflectanceFit, radiometry.Mosaic, radiometry.GcpMap, radiometry.Reflectance, radiometry.Check):
    _cls.__repr__ = _summary_repr

slr.Pass.epochs = property(_pass_epochs)
slr.Pass.to_pandas = _pass_frame
slr.PassResult.to_pandas = _result_frame
for _cls, _table in ((footprint.Report, lambda r: r.columns()), (trend.Trend, lambda r: r.columns()),
                     (calib.DetectorFit, lambda r: r.centre), (calib.PointingFit, lambda r: r.beams),
                     (calib.Stats, lambda r: r.groups()), (calib.WaveformFit, lambda r: r.waveform),
                     (radiometry.ReflectanceFit, lambda r: r.fit), (radiometry.Check, lambda r: r.table)):
    def _to_pandas(self, _table=_table):
        """The result's table as a pandas DataFrame (the columns of its CSV)."""
        return _frame(_table(self))

    _cls.to_pandas = _to_pandas

__all__ = ["Error", "ParameterError", "__version__", "write_text", "footprint", "slr", "trend", "calib",
           "radiometry"]
