"""frictionviz: friction reduction by in-plane vibrations (Tsai & Tseng 2006) from Python.

The same solver and the same numbers as the command line ``frictionviz`` (docs/cli.md), over numpy arrays:

    >>> import frictionviz as fv
    >>> res = fv.ratio(zeta=[0.1, 0.5, 1.0], theta_deg=90, rdisp=2, i=1)
    >>> res.r_x.shape
    (3,)

Angles are in DEGREES everywhere (``theta_deg``), as on the command line, in the data files' ``theta_deg``
column and in the paper's figures. Out-of-range values raise ``ValueError`` with the command line's message.
See docs/python.md.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, List, Optional

import numpy as np

from . import _core

__all__ = [
    "ratio",
    "rigid_ratio",
    "trace",
    "read_measurements",
    "fit",
    "RatioResult",
    "Trace",
    "Measurements",
    "FitResult",
    "NumericalFailure",
    "DEFAULT_TOLERANCE",
    "figures",
    "render",
    "Figure",
]

#: The ode scheme's default target for |r - r(dtau -> 0)| (the command line's default ``--tolerance``).
DEFAULT_TOLERANCE: float = _core.default_tolerance


class NumericalFailure(ArithmeticError):
    """Some point's result is not one the solver vouches for (the command line's exit status 3).

    ``result`` is the whole result (every point, failed ones with their best values and status);
    ``failed`` the indices of the failed points (tuples, as ``np.argwhere`` gives them).
    """

    def __init__(self, message: str, result: Any = None, failed: Optional[List[tuple]] = None):
        super().__init__(message)
        self.result = result
        self.failed = failed or []


def _float64(x: Any, name: str) -> np.ndarray:
    # The one conversion of an input: none when it is float64 already (a view, whatever its strides, is passed
    # as is; broadcasting is done by strides in _core, not by copying).
    a = np.asarray(x)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be real numbers, not {a.dtype}")
    return a if a.dtype == np.float64 else a.astype(np.float64)


def _scalar_or_array(a: np.ndarray):
    # numpy's convention for 0-d results (as ufuncs): a numpy scalar, not a 0-d array.
    return a[()] if a.ndim == 0 else a


@dataclass(frozen=True)
class RatioResult:
    """Steady-state friction ratios over the broadcast shape of the inputs.

    r_x, r_y        the friction ratios (Eq. (33) and its y-twin), float64
    error_estimate  the solver's estimate of |r - exact| (force units; 1e-12-ish for the rigid model)
    periods         vibration periods integrated (0 for the rigid model), int64
    status          as the command line prints it: 'ok', 'period_k' (a k-period steady state, valid),
                    or the failure's word: 'not_converged', 'integration_failed', 'non_finite', 'unsettled',
                    'not_periodic'
    ok              status is 'ok' or 'period_k': a result the solver vouches for

    A failed point keeps its best values (NaN only where they are not finite) and says so in ``status``:
    check ``ok`` (or pass ``raise_on_failure=True``). For 0-d inputs the fields are numpy scalars.
    """

    r_x: Any
    r_y: Any
    error_estimate: Any
    periods: Any
    status: Any
    ok: Any
    shape: tuple = field(default=())

    @property
    def failed(self) -> List[tuple]:
        """Indices of the points that failed (empty when all are ok)."""
        return [tuple(int(j) for j in ix) for ix in np.argwhere(~np.asarray(self.ok))]

    def __repr__(self) -> str:
        n = int(np.prod(self.shape)) if self.shape else 1
        bad = len(self.failed)
        return f"RatioResult(shape={self.shape}, points={n}, failed={bad})"


def _failure_message(res: RatioResult, inputs: dict) -> str:
    failed = res.failed
    n = int(np.prod(res.shape)) if res.shape else 1
    lines = [f"{len(failed)} of {n} points failed"]
    status = np.asarray(res.status)
    full = {k: np.broadcast_to(v, res.shape) for k, v in inputs.items() if v is not None}
    for ix in failed[:10]:
        where = ", ".join(f"{k}={float(v[ix]):.17g}" for k, v in full.items())
        lines.append(f"  {ix if res.shape else '()'}: {where}: {status[ix]}")
    if len(failed) > 10:
        lines.append(f"  ... and {len(failed) - 10} more")
    return "\n".join(lines)


def ratio(
    zeta,
    theta_deg,
    rdisp=None,
    i=None,
    model: str = "dahl",
    tolerance: float = DEFAULT_TOLERANCE,
    threads: int = 0,
    start: str = "rest",
    raise_on_failure: bool = False,
) -> RatioResult:
    """Steady-state friction ratios r_x, r_y, broadcast over every argument (numpy's rules).

    zeta       velocity ratio v_b/v_v, Eq. (6); in [0, 100]
    theta_deg  vibration angle to v_b in DEGREES, Eq. (1); in [0, 180] (the CLI's --theta)
    rdisp      displacement ratio x_v/z_ss, Eq. (34); in (0, 10000]; Dahl model only
    i          Dahl shape exponent, Eq. (12); in [0, 10]; 0 is the stiction model, Eq. (27); Dahl model only
    model      'dahl' or 'rigid' (Eq. (9); rdisp and i are ignored, but checked when given)
    tolerance  the ode scheme's target for |r - r(dtau -> 0)|; in [1e-12, 1e-4] (the CLI's --tolerance)
    threads    worker threads; 0: all cores. The GIL is released while the points are computed.
    start      'rest' (the paper's start) or 'sliding': which steady state where two coexist (--start)
    raise_on_failure  raise NumericalFailure naming the failed points instead of returning them

    The values equal `frictionviz ratio` / `frictionviz sweep` at the same points, bit for bit. Raises
    ValueError (the CLI's message, with the element's index for arrays) for a value out of range.
    """
    inputs = {
        "zeta": _float64(zeta, "zeta"),
        "theta_deg": _float64(theta_deg, "theta_deg"),
        "rdisp": None if rdisp is None else _float64(rdisp, "rdisp"),
        "i": None if i is None else _float64(i, "i"),
    }
    d = _core.ratio(model, inputs["zeta"], inputs["theta_deg"], inputs["rdisp"], inputs["i"],
                    float(tolerance), start, int(threads))
    shape = d["r_x"].shape
    res = RatioResult(**{k: _scalar_or_array(v) for k, v in d.items()}, shape=shape)
    if raise_on_failure and res.failed:
        raise NumericalFailure("frictionviz.ratio: " + _failure_message(res, inputs), res, res.failed)
    return res


def rigid_ratio(zeta, theta_deg):
    """(r_x, r_y) of the rigid Coulomb model, Eq. (9) and its y-twin, broadcast over both arguments.

    zeta in [0, 100]; theta_deg in DEGREES, [0, 180]. Exact quadrature (error below 1e-12), no failures.
    Returns numpy scalars for scalar inputs.
    """
    rx, ry = _core.rigid_ratio(_float64(zeta, "zeta"), _float64(theta_deg, "theta_deg"))
    return _scalar_or_array(rx), _scalar_or_array(ry)


@dataclass(frozen=True)
class Trace:
    """One steady period of the Dahl model (`frictionviz trace`): 1024 samples at tau = 2 pi k/1024.

    tau, Px, Py, Tx, Ty, z, Fx, Fy  arrays (dimensionless; P the body point, T the asperity tip,
                                    z = |P - T|, F = (P - T)/z_ss the friction force over F_c)
    stick    the tip did not move since the previous sample (stuck); ~stick: slipping
    r_x, r_y, error_estimate, periods, status   as in RatioResult, for this point
    """

    tau: np.ndarray
    Px: np.ndarray
    Py: np.ndarray
    Tx: np.ndarray
    Ty: np.ndarray
    z: np.ndarray
    Fx: np.ndarray
    Fy: np.ndarray
    stick: np.ndarray
    r_x: float
    r_y: float
    error_estimate: float
    periods: int
    status: str

    @property
    def ok(self) -> bool:
        return self.status == "ok" or self.status.startswith("period_")


def trace(zeta: float, theta_deg: float, rdisp: float, i: float, tolerance: float = DEFAULT_TOLERANCE,
          start: str = "rest", raise_on_failure: bool = False) -> Trace:
    """One steady-state period of the Dahl model, as `frictionviz trace` (theta_deg in DEGREES).

    Raises NumericalFailure with raise_on_failure=True when the steady state behind the period failed.
    """
    d = _core.trace(float(zeta), float(theta_deg), float(rdisp), float(i), float(tolerance), start)
    t = Trace(**d)
    if raise_on_failure and not t.ok:
        raise NumericalFailure(
            f"frictionviz.trace: the steady state behind the trace failed at zeta={zeta}, "
            f"theta_deg={theta_deg}, rdisp={rdisp}, i={i}: {t.status}", t, [()])
    return t


@dataclass(frozen=True)
class Measurements:
    """Measured r_x(zeta) (the data files of `frictionviz fit --data`, docs/cli.md).

    zeta, r_x arrays; theta_deg and sigma arrays or None (the file has no such column); vb (m/s) when zeta was
    converted from a vb column; label (list of str); line (the file's line of each point).
    """

    file: str
    zeta: np.ndarray
    r_x: np.ndarray
    theta_deg: Optional[np.ndarray]
    sigma: Optional[np.ndarray]
    vb: Optional[np.ndarray]
    label: List[str]
    line: np.ndarray
    synthetic: bool

    def __len__(self) -> int:
        return len(self.zeta)


def read_measurements(path, amplitude_um: Optional[float] = None,
                      frequency_khz: Optional[float] = None) -> Measurements:
    """Reads a data file as `frictionviz fit --data` does; errors are ValueError "FILE:LINE:COL: message".

    amplitude_um and frequency_khz convert a vb column to zeta (the CLI's --amplitude, --frequency).
    """
    return Measurements(**_core.read_measurements(os.fspath(path), amplitude_um, frequency_khz))


@dataclass(frozen=True)
class FitResult:
    """The fit of r_disp (`frictionviz fit`): ``best`` and ``candidates`` are dicts with the keys of the CLI's
    JSON candidates (i, rdisp, rdisp_sigma, log_rdisp_sigma, chi2, dof, reduced_chi2, aic, model, residuals,
    zss_um, zss_um_sigma, at_bound, converged, evaluations, unsteady, weighted); status as the CLI's."""

    best: dict
    candidates: List[dict]
    status: str
    detail: str
    file: str

    @property
    def rdisp(self) -> float:
        return self.best["rdisp"]

    @property
    def i(self) -> float:
        return self.best["i"]

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def fit(data, theta_deg: Optional[float] = None, i="auto", amplitude_um: Optional[float] = None,
        frequency_khz: Optional[float] = None, threads: int = 0, raise_on_failure: bool = False) -> FitResult:
    """Fits r_disp of the Dahl model to measured r_x(zeta): the same numbers as `frictionviz fit`.

    data        a path to a data file (read as the CLI reads --data), or a Measurements
    theta_deg   the angle in DEGREES for data without a theta_deg column (the CLI's --theta)
    i           0, 1 or 'auto' (both, the smaller AIC wins)
    """
    shape = {0: "0", 1: "1", "0": "0", "1": "1", "auto": "auto"}.get(i, repr(i)) if isinstance(i, (int, str)) \
        else repr(i)
    if isinstance(data, Measurements):
        d = _core.fit(None, _float64(data.zeta, "zeta"), _float64(data.r_x, "r_x"),
                      None if data.theta_deg is None else _float64(data.theta_deg, "theta_deg"),
                      None if data.sigma is None else _float64(data.sigma, "sigma"),
                      theta_deg, shape, amplitude_um, frequency_khz, int(threads))
    else:
        d = _core.fit(os.fspath(data), None, None, None, None, theta_deg, shape, amplitude_um, frequency_khz,
                      int(threads))
    r = FitResult(**d)
    if raise_on_failure and not r.ok:
        raise NumericalFailure(f"frictionviz.fit: {r.status} ({r.detail})", r, [])
    return r


# ---------------------------------------------------------------------------------------------------------
# Figures (the registry of `frictionviz render`), rendered headless: present when the module was built with
# the figures layer (_core.figures exists).

def _write_file(path, data: bytes) -> None:
    """Writes as `frictionviz render` writes: atomically (a temporary file renamed over the target), never a
    half-written file; OSError with the one-line reason (a missing folder, a directory, ...)."""
    try:
        _core.write_file(os.fspath(path), data)
    except ValueError as e:
        raise OSError(str(e)) from None


def _csv_column(cells: tuple) -> np.ndarray:
    """One CSV column as an array: float64 where every cell is a number or empty (empty: NaN, as the command
    line leaves a value that does not apply or is not finite), else str."""
    try:
        return np.array([float(c) if c else np.nan for c in cells], dtype=np.float64)
    except ValueError:
        return np.array(cells, dtype=str)


def _csv_array(text: str) -> np.ndarray:
    """A table the command line writes (a header line, then comma-separated rows; no quoting: no cell holds a
    comma) as a numpy structured array, one field per column, named by the header."""
    lines = text.splitlines()
    names = lines[0].split(",")
    rows = [line.split(",") for line in lines[1:]]
    columns = list(zip(*rows)) if rows else [()] * len(names)
    arrays = [_csv_column(c) for c in columns]
    out = np.empty(len(rows), dtype=[(n, a.dtype) for n, a in zip(names, arrays)])
    for n, a in zip(names, arrays):
        out[n] = a
    return out


class Figure:
    """A rendered figure: its ``data`` bytes (PNG, SVG or PDF), ``title``, ``caption`` (naming every parameter
    behind it, as ID.json's) and ``parameters`` (a dict: the spec `frictionviz render --spec` reads, so the
    command line draws the same figure from it). Shown inline by Jupyter (``_repr_png_`` / ``_repr_svg_``);
    ``save(path)`` writes the bytes (``data=True``: the tables too), ``save_spec(path)`` the parameters as
    JSON.

    The numbers behind it: ``tables``, a dict from each table's name (the file name `frictionviz render`
    writes without ``.csv``: ``"map"``, ``"map-best-angle"``) to a numpy structured array with the CSV's
    columns (numbers as float64, empty cells NaN; text columns such as ``model`` and ``status`` as str), and
    ``csv(name)``, the CSV text itself, byte for byte the command line's file."""

    def __init__(self, id: str, data: bytes, format: str, title: str = "", caption: str = "",
                 parameters: Optional[dict] = None, csv: Optional[List[tuple]] = None):
        self.id = id
        self.format = format
        self.data = data
        self.title = title
        self.caption = caption
        self.parameters = parameters or {}
        # "ID<suffix>" -> CSV text, in the command line's order (ID.csv first).
        self._csv = {name[: -len(".csv")]: text for name, text in (csv or [])}
        self._tables: Optional[dict] = None

    @property
    def tables(self) -> dict:
        if self._tables is None:  # parsed on first use: a family of maps has 10^5 rows
            self._tables = {name: _csv_array(text) for name, text in self._csv.items()}
        return self._tables

    def csv(self, name: Optional[str] = None) -> str:
        """The CSV text of table ``name`` (default: the figure's main table, named by its id), as
        `frictionviz render` writes it; KeyError naming the tables there are for another name."""
        key = self.id if name is None else (name[: -len(".csv")] if name.endswith(".csv") else name)
        if key not in self._csv:
            raise KeyError(f"{name!r}: {self.id} has the tables {', '.join(self._csv) or 'none'}")
        return self._csv[key]

    def _repr_png_(self):
        return self.data if self.format == "png" else None

    def _repr_svg_(self):
        return self.data.decode("utf-8") if self.format == "svg" else None

    def save(self, path, data: bool = False) -> None:
        """Writes the picture to ``path``; with ``data=True`` also each table beside it as `frictionviz
        render` names them, the picture's stem in place of the id (``out/m.png``: ``out/m.csv``,
        ``out/m-best-angle.csv`` for a map), the same bytes as the command line's files."""
        path = os.fspath(path)
        _write_file(path, self.data)
        if not data:
            return
        stem = os.path.splitext(path)[0]
        for name, text in self._csv.items():
            _write_file(stem + name[len(self.id):] + ".csv", text.encode("utf-8"))

    def save_spec(self, path) -> None:
        _write_file(path, (json.dumps(self.parameters) + "\n").encode("utf-8"))

    def __repr__(self) -> str:
        return f"Figure({self.id!r}, {self.format}, {len(self.data)} bytes, tables {list(self._csv)})"


# The Python keyword of each spec key where it differs: the unit in the name, so that an angle in radians or
# an amplitude in metres is not passed by mistake.
_KEYWORD = {"theta": "theta_deg", "amplitude": "amplitude_um", "frequency": "frequency_khz"}
_SPEC_KEY = {v: k for k, v in _KEYWORD.items()}


def figures() -> List[tuple]:
    """The figures `frictionviz render` knows: [(id, title, [parameter keywords])], in the registry's order."""
    return [(i, t, [_KEYWORD.get(k, k) for k in p]) for i, t, p in _core.figures()]


def _spec_value(name: str, value):
    """A keyword's value as the spec file takes it: numbers exact (json writes repr), sequences and arrays as
    lists, a (FROM, TO) zeta range as a list of two, strings as they are."""
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    a = np.asarray(value)
    if a.dtype.kind in "US":
        return a.tolist()
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name}: expected a number, a list of numbers or a string, got {type(value).__name__}")
    a = a.astype(np.float64)
    if not np.isfinite(a).all():
        bad = a[~np.isfinite(a)].ravel()[0]
        raise ValueError(f"{name} = {bad} is not a finite number")
    return a.tolist()


def render(id: str, out=None, format: str = "png", size=(1280, 800), scale: float = 1.0, **params):
    """Renders figure ``id`` headless (OSMesa for PNG, cairo for SVG and PDF), as `frictionviz render` does.

    params  the figure's parameters (figures() lists them): zeta, theta_deg (DEGREES), rdisp, i, model, data
            (a path), amplitude_um, frequency_khz, start. rx and ry take lists for theta_deg, rdisp, i and
            model (one curve per combination) and a (FROM, TO) zeta range; map lists for rdisp, i and model
            (one map per combination, at most 6, as small multiples); none given: the figure's example
            inputs (as `render --figure all`)
    size    (width, height) in pixels; scale the CLI's --scale
    out     None: returns a Figure (bytes in .data, inline in Jupyter; its tables in .tables and .csv());
            a path: writes the bytes there (atomically) and returns the path

    The checks and messages are those of `frictionviz render --spec` (ValueError); the PNG bytes equal the
    CLI's for the same figure, size and parameters (tests/test_render.py).
    """
    spec = {"id": id}
    for name, value in params.items():
        if name in _SPEC_KEY.values():
            raise TypeError(f"render: {name}: use {_KEYWORD[name]} (the unit is in the name)")
        spec[_SPEC_KEY.get(name, name)] = _spec_value(name, value)
    w, h = size
    data, title, caption, parameters, csv = _core.render(json.dumps(spec), not params, int(w), int(h),
                                                         float(scale), format)
    fig = Figure(id, data, format, title, caption, json.loads(parameters), csv)
    if out is None:
        return fig
    _write_file(out, data)
    return out
