"""carry: golf impact and ball flight over numpy arrays.

The Rust engine of the ``carry`` command line (its library layers: carry-io, carry-lab),
called from Python:

* :func:`impact` — club delivery → ball launch (``carry impact``),
* :func:`flight` — launch → flight (``carry flight``),
* :func:`shot` — delivery → launch → flight (``carry shot``),
* :func:`estimate` — ball data → club data, the impact model run backwards
  (``carry estimate``),
* :func:`launch_from_flight` — the launch quantities a monitor did not measure (spin, axis,
  …) fitted to what it saw of the flight: summaries, a track, a Doppler trace
  (``carry estimate --from flight``),
* :func:`fit` — fit an aerodynamic model or contact law to measured shots (``carry fit``),
* :func:`optimize`, :func:`sweep`, :func:`dispersion`, :func:`normalize` — the analyses
  (``carry optimize``, …): the best delivery, the ball position along a swing, Monte-Carlo
  dispersion, carry in standard conditions.

Keyword arguments are the command line's options in snake_case (``club_speed``,
``launch_angle``, ``wind_speed``, ``club``, ``aero``, ``ground``, ``precision``, ``units``,
…) in the same units (``units="imperial"`` for mph, yards, feet, inches and °F; results are
always SI). Numeric arguments take scalars or numpy arrays, broadcast together by numpy's
rules; every element is one shot, computed in parallel on all cores with the GIL released.

The result is a dict of float64 arrays of the broadcast shape, keyed like the CLI's batch
CSV columns (``carry_m``, ``apex_m``, ``ball_speed_mps``, ``landing_position_m_x``, …),
plus ``errors``: an object array holding ``None`` or the message of a row that failed
(its numbers are NaN). ``raise_on_error=True`` raises :class:`ShotError` instead.

    >>> import numpy as np, carry
    >>> r = carry.flight(ball_speed=np.linspace(60, 80, 5), launch_angle=12, spin=2500)
    >>> r["carry_m"].shape
    (5,)
"""

# The helpers' imports are private (a leading underscore): `dir(carry)` lists the API only.
import csv as _csv
import math as _math
import os as _os
import re as _re
import tempfile as _tempfile
import warnings as _warnings
from typing import Any as _Any, Dict as _Dict, Mapping as _Mapping

import numpy as _np

from . import _carry

__all__ = [
    "impact", "flight", "shot", "estimate", "fit", "optimize", "sweep", "dispersion", "normalize",
    "launch_from_flight", "columns", "inputs", "ShotError", "LaunchFitError",
    "InconsistentDataError",
]
__version__ = "0.1.0"

_NUMERIC = ("number", "radius")
_TEXT = ("preset", "contact", "aero", "ground", "convention")
_INPUTS = {mode: dict(_carry.inputs(mode)) for mode in ("impact", "flight", "shot", "estimate")}
_ALL_NAMES = set().union(*_INPUTS.values())


class ShotError(ValueError):
    """A row failed and ``raise_on_error=True``: :attr:`index` is its position in the
    broadcast shape, :attr:`message` the reason (``"club_speed: must be positive"``)."""

    def __init__(self, index: tuple, message: str) -> None:
        # A scalar call has one row and no index to name.
        super().__init__(f"row {index}: {message}" if index else message)
        self.index = index
        self.message = message


class InconsistentDataError(ShotError):
    """:func:`estimate` with ``raise_on_error=True`` on a row whose data disagree with each
    other or with the club (issue 34; docs/estimate.md §8): the consistency check failed.
    :attr:`datum` names the worst datum as its argument (``"club_speed"``, ``"ball_speed"``,
    …, or ``"club"`` when the ball data need a delivery far from the club's typical one),
    :attr:`sd` by how many of its σ the most probable delivery misses it, :attr:`chi2` and
    :attr:`bound` the χ² test. A :class:`ShotError`, so code that catches that still does."""

    def __init__(self, index: tuple, message: str) -> None:
        super().__init__(index, message)
        self.datum = message.partition(": ")[0]
        found = _re.search(r"χ² ([0-9.eE+-]+) of \d+ data, bound ([0-9.eE+-]+)", message)
        worst = _re.search(r"worst ([0-9.eE+-]+)σ", message)
        self.chi2 = float(found.group(1)) if found else _math.nan
        self.bound = float(found.group(2)) if found else _math.nan
        self.sd = float(worst.group(1)) if worst else _math.nan


def _inconsistent(message: str) -> bool:
    """Whether a row's error is the estimator's consistency check (lab's
    ``request::inconsistent`` words it)."""
    return ": disagrees with the other data (" in message or \
        "the ball data disagree with this club" in message


class LaunchFitError(ValueError):
    """:func:`launch_from_flight` refused: bad input, too few observations, a quantity the
    observations do not determine, no convergence. :attr:`option` names what to fix as the
    CLI does (``"--spin-axis"``, ``"--carry"``, ``"--apex-height, --carry, …, --track"``),
    :attr:`message` says why."""

    def __init__(self, text: str) -> None:
        super().__init__(text)
        option, _, message = text.partition(": ")
        self.option = option
        self.message = message


def inputs(mode: str) -> _Dict[str, str]:
    """The keyword arguments of ``impact``, ``flight``, ``shot`` or ``estimate`` and their kinds
    (``number``, ``radius``, ``vector``, ``tensor``, ``preset``, ``contact``, ``aero``,
    ``bool``, ``ground`` or ``setting``)."""
    if mode not in _INPUTS:
        raise ValueError(f"mode: unknown '{mode}' (one of: impact, flight, shot, estimate)")
    return dict(_INPUTS[mode])


def columns(mode: str, ground: bool = False) -> list:
    """The result keys of ``mode`` (without ``errors``), in the CLI's CSV column order;
    ``ground`` adds the bounce-and-roll columns (``total_m``, ``roll_m``, …)."""
    return list(_carry.columns(mode, ground))


def _number_text(name: str, value: _Any) -> str:
    if isinstance(value, (bool, _np.bool_)) or not isinstance(value, (int, float, _np.number)):
        raise ValueError(f"{name}: expected a number, got {type(value).__name__}")
    x = float(value)
    if not _math.isfinite(x):
        raise ValueError(f"{name}: '{x}' is not a finite number")
    return repr(x)


def _option_text(mode: str, name: str, kind: str, value: _Any) -> str:
    """The CLI text of a whole-call option."""
    if kind == "setting":
        if name in ("step", "tolerance"):
            return _number_text(name, value)
        if name == "scene" and isinstance(value, _os.PathLike):
            return _os.fspath(value)
        if not isinstance(value, str):
            raise ValueError(f"{name}: expected a string, got {type(value).__name__}")
        return value
    if kind == "bool":
        if not isinstance(value, (bool, _np.bool_)):
            raise ValueError(f"{name}: expected True or False, got {type(value).__name__}")
        return "true" if value else "false"
    if kind in ("vector", "tensor"):
        sizes = (3,) if kind == "vector" else (3, 9)
        try:
            v = _np.asarray(value, dtype=_np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"{name}: expected {' or '.join(map(str, sizes))} numbers") from None
        if v.ndim != 1 or v.size not in sizes:
            raise ValueError(
                f"{name}: expected {' or '.join(map(str, sizes))} numbers, got shape {v.shape}"
                + (f" (per-row values: {name}_x, {name}_y, {name}_z)" if kind == "vector" else "")
            )
        return ",".join(repr(float(x)) for x in v)
    # preset, contact, aero, ground: a name or a file
    if isinstance(value, _os.PathLike):
        return _os.fspath(value)
    if not isinstance(value, str):
        raise ValueError(f"{name}: expected a name (str), got {type(value).__name__}")
    return value


def _numeric_array(name: str, kind: str, value: _Any) -> _np.ndarray:
    if kind == "radius" and isinstance(value, str) and value.strip().lower() == "flat":
        return _np.asarray(_np.inf)
    if isinstance(value, (str, bytes)) or _np.asarray(value).dtype.kind in "USV":
        raise ValueError(f"{name}: expected a number or an array of numbers, got text")
    try:
        arr = _np.asarray(value, dtype=_np.float64)
    except (TypeError, ValueError):
        raise ValueError(
            f"{name}: expected a number or an array of numbers, got {type(value).__name__}"
        ) from None
    return arr


def _run(mode: str, kwargs: _Mapping[str, _Any], raise_on_error: bool) -> _Dict[str, _np.ndarray]:
    kinds = _INPUTS[mode]
    names, arrays, options = [], [], []
    for name, value in kwargs.items():
        kind = kinds.get(name)
        if kind is None:
            if name in _ALL_NAMES:
                raise ValueError(f"{name}: is not an argument of carry.{mode}")
            raise ValueError(f"{name}: unknown argument of carry.{mode}")
        if value is None:
            continue
        if kind in _NUMERIC:
            names.append(name)
            arrays.append(_numeric_array(name, kind, value))
        else:
            options.append((name, _option_text(mode, name, kind, value)))
    try:
        shape = _np.broadcast_shapes(*(a.shape for a in arrays)) if arrays else ()
    except ValueError:
        shapes = ", ".join(f"{n} {a.shape}" for n, a in zip(names, arrays))
        raise ValueError(f"{', '.join(names)}: shapes do not broadcast ({shapes})") from None
    rows = _math.prod(shape)
    flat = [_np.ascontiguousarray(_np.broadcast_to(a, shape), dtype=_np.float64).reshape(-1) for a in arrays]
    keys, data, failed = _carry.run(mode, names, flat, options, rows)
    if raise_on_error and failed:
        i, message = failed[0]
        index = tuple(int(j) for j in _np.unravel_index(i, shape))
        if mode == "estimate" and _inconsistent(message):
            raise InconsistentDataError(index, message)
        raise ShotError(index, message)
    # Column views of the (rows, columns) result: no copy.
    out: _Dict[str, _Any] = {k: data[:, j].reshape(shape) for j, k in enumerate(keys)}
    err = _np.full(rows, None, dtype=object)
    for i, message in failed:
        err[i] = message
    out["errors"] = err.reshape(shape)
    return out


def impact(*, raise_on_error: bool = False, **kwargs: _Any) -> _Dict[str, _np.ndarray]:
    """Club delivery → ball launch, as ``carry impact``.

    Arguments: delivery (``club_speed``, ``attack_angle``, ``club_path``, ``face_angle``,
    ``dynamic_loft``, ``lie``, ``club_spin`` or ``club_spin_x/_y/_z``, ``impact_height``,
    ``impact_toe``), club (``club`` preset, ``contact``, ``spin_axis_share``, ``club_mass``, ``loft``, ``cor``,
    …), ball (``ball_mass``, ``ball_radius``), ``solver``, ``precision``, ``units``.
    Returns the launch (``ball_speed_mps``, ``launch_angle_deg``, ``spin_rpm``,
    ``smash_factor``, …), the club after impact and the impulse.
    """
    return _run("impact", kwargs, raise_on_error)


def flight(*, raise_on_error: bool = False, **kwargs: _Any) -> _Dict[str, _np.ndarray]:
    """Launch → flight, as ``carry flight``.

    Arguments: launch (``ball_speed``, ``launch_angle``, ``launch_direction``, and
    ``backspin`` + ``sidespin`` or ``spin`` + ``spin_axis``), scene (``air_density`` or
    ``temperature``, ``humidity``, ``pressure``/``altitude``; ``wind_speed`` +
    ``wind_direction`` or ``wind``/``wind_x/_y/_z``; ``landing_height``, ``aero``,
    ``ground``, ``stimp``, …, or a ``scene`` file), ``integrator``, ``step``,
    ``tolerance``, ``precision``, ``units``.
    Returns the launch and the flight (``carry_m``, ``side_m``, ``apex_m``,
    ``flight_time_s``, ``landing_position_m_x``, …; with a ground ``total_m``, ``roll_m``, …).
    """
    return _run("flight", kwargs, raise_on_error)


def shot(*, raise_on_error: bool = False, **kwargs: _Any) -> _Dict[str, _np.ndarray]:
    """Club delivery → launch → flight, as ``carry shot``: the arguments of
    :func:`impact` and the scene and integrator arguments of :func:`flight`; returns the
    columns of both."""
    return _run("shot", kwargs, raise_on_error)


def estimate(*, raise_on_error: bool = False, **kwargs: _Any) -> _Dict[str, _np.ndarray]:
    """Ball data → club data, as ``carry estimate``: the impact model run backwards
    (a maximum a posteriori fit; docs/estimate.md).

    Arguments: the measured launch as :func:`flight` takes it (``ball_speed``,
    ``launch_angle``, ``launch_direction``, and ``spin`` + ``spin_axis`` or ``backspin`` +
    ``sidespin``), whatever the launch monitor measured of the club (``club_speed``,
    ``attack_angle``, ``club_path``, ``face_angle``, ``dynamic_loft``; each optional), the
    club (``club`` preset, ``contact``, ``loft``, ``cor``, …), ball (``ball_mass``,
    ``ball_radius``), ``precision``, ``units``, ``posterior`` (``"profile"``, the default:
    posterior mean and calibrated 1σ; ``"laplace"``: the most probable delivery and the
    Gauss–Newton 1σ, about half the cost).
    Returns the estimated delivery in TrackMan's convention, each datum with its 1σ
    (``face_angle_deg`` and ``face_angle_deg_sd``, ``club_path_deg``, ``face_to_path_deg``,
    ``dynamic_loft_deg``, ``attack_angle_deg``, ``spin_loft_deg``, ``impact_toe_m``,
    ``impact_height_m``, ``club_speed_mps``, ``smash_factor``), ``club_speed_estimated``
    (1 where the club speed was not measured), the residuals (modelled − measured ball
    data) and ``iterations``.
    A row whose data disagree with each other or with the club (the consistency check,
    docs/estimate.md §8) has NaN numbers and its ``errors`` entry names the worst datum
    (``"club_speed: disagrees with the other data (χ² …; worst 45.6σ, bound 4σ)"``); with
    ``raise_on_error=True`` it raises :class:`InconsistentDataError`.
    """
    return _run("estimate", kwargs, raise_on_error)


def _column_text(values: _np.ndarray) -> list:
    if values.dtype.kind in "fiub":
        return ["" if not _math.isfinite(x) else repr(x) for x in values.astype(_np.float64).tolist()]
    out = []
    for x in values.tolist():
        if x is None or (isinstance(x, float) and _math.isnan(x)):
            out.append("")
        elif isinstance(x, float):
            out.append(repr(x))
        else:
            out.append(str(x))
    return out


def _table(data: _Any, name: str = "data") -> _Dict[str, _np.ndarray]:
    """Columns of a DataFrame, a mapping of arrays or a structured array (``name``: the
    argument, for the error)."""
    if isinstance(data, _np.ndarray) and data.dtype.names:
        return {n: _np.asarray(data[n]) for n in data.dtype.names}
    if hasattr(data, "columns") and hasattr(data, "__getitem__"):  # pandas DataFrame
        return {str(c): _np.asarray(data[c]) for c in data.columns}
    if isinstance(data, _Mapping):
        return {str(k): _np.atleast_1d(_np.asarray(v)) for k, v in data.items()}
    raise ValueError(
        f"{name}: expected a DataFrame, a dict of arrays, a structured array or a CSV path, "
        f"got {type(data).__name__}"
    )


def fit(
    data: _Any,
    *,
    family: str = "modern",
    evaluate: "str | None" = None,
    output: "str | _os.PathLike | None" = None,
    cross_validation: bool = True,
    units: str = "si",
    air_density: "float | None" = None,
    temperature: "float | None" = None,
    humidity: "float | None" = None,
    pressure: "float | None" = None,
    altitude: "float | None" = None,
    also: _Any = (),
    table_weight: "float | None" = None,
) -> _Dict[str, _Any]:
    """Fit a model family to measured shots, as ``carry fit --json``.

    ``data``: a pandas DataFrame, a dict of arrays, a numpy structured array or a CSV
    path, with ``carry fit``'s columns (``ball_speed``, ``launch_angle``, ``spin`` or
    ``backspin``, ``carry``, ``apex``, ``land_angle``, …; a unit suffix such as ``_mph`` or
    ``_yd`` overrides ``units``). ``family``: ``modern``, ``quintavalla`` or ``compliant``
    (the contact law, on ``club_delivery.csv``'s columns). The conditions apply to rows
    without their own. ``output`` writes the fitted model (TOML, for ``aero=``/``contact=``).
    ``also``: more data fitted jointly (``carry fit --also``), each a path or a table as
    ``data``; a single-drive TrackMan export among them (a path, recognised by its header)
    weighs ``1/table_weight`` times the tables (``--table-weight``, default 1).

    Returns the JSON document: ``family``, ``rows``, ``ignored_columns``,
    ``coefficients`` (name → value) and ``fit`` (``parameters``, ``quantities``, per-row
    ``rows`` with ``observed``/``predicted``/``loo_predicted``, ``summary`` and
    ``loo_summary`` with mean and max errors, ``converged``, …).
    """
    for name, value in (("air_density", air_density), ("temperature", temperature),
                        ("humidity", humidity), ("pressure", pressure), ("altitude", altitude)):
        if value is not None:
            _number_text(name, value)
    for name, value in (("family", family), ("units", units)):
        if not isinstance(value, str):
            raise ValueError(f"{name}: expected a string, got {type(value).__name__}")
    opts = dict(
        family=family,
        evaluate=evaluate,
        output=_os.fspath(output) if output is not None else None,
        cross_validation=bool(cross_validation),
        units=units,
        air_density=air_density,
        temperature=temperature,
        humidity=humidity,
        pressure=pressure,
        altitude=altitude,
    )
    if table_weight is not None:
        _number_text("table_weight", table_weight)
        opts["table_weight"] = table_weight
    if isinstance(also, (str, _os.PathLike)) or not isinstance(also, (list, tuple)):
        also = [also]
    with _tempfile.TemporaryDirectory() as tmp:

        def as_path(name: str, value: _Any) -> str:
            if isinstance(value, (str, _os.PathLike)):
                return _os.fspath(value)
            table = _table(value, name)
            if len({len(v) for v in table.values()}) > 1:
                raise ValueError(f"{name}: columns differ in length")
            path = _os.path.join(tmp, f"{len(_os.listdir(tmp))}.csv")
            with open(path, "w", newline="") as f:
                w = _csv.writer(f)
                w.writerow(list(table))
                w.writerows(zip(*(_column_text(v) for v in table.values())))
            return path

        opts["also"] = [as_path(f"also[{i}]", a) for i, a in enumerate(also)]
        return _carry.fit_csv(as_path("data", data), **opts)


def _option_value(name: str, value: _Any) -> str:
    """One option value as the command line takes it: a number, a string or path, or a
    sequence joined by commas (``dynamic_loft_range=(8, 20)``)."""
    if isinstance(value, (str, _os.PathLike)):
        return _os.fspath(value)
    if isinstance(value, (list, tuple, _np.ndarray)):
        return ",".join(_number_text(name, v) for v in _np.asarray(value).ravel())
    if isinstance(value, (int, _np.integer)) and not isinstance(value, (bool, _np.bool_)):
        return str(int(value))
    return _number_text(name, value)


def _analysis(command: str, kwargs: _Mapping[str, _Any]) -> _Dict[str, _Any]:
    """lab's typed ``command`` request with ``kwargs`` as its options (``True`` sets a flag,
    ``False``/``None`` leaves the option out); returns the document ``carry <command>
    --json`` prints, as Python objects. An option the analysis replaces (e.g. ``attack_angle``
    with ``attack_angle_range``) gives a :class:`UserWarning` naming it."""
    options = []
    for name, value in kwargs.items():
        if name in ("json", "csv"):
            raise ValueError(f"{name}: the Python functions always return the JSON document")
        if value is None or value is False:
            continue
        options.append((name, "true" if value is True else _option_value(name, value)))
    doc, notes = _carry.analysis(command, options)
    for note in notes:
        _warnings.warn(f"carry.{command}: {note}", stacklevel=3)
    return doc


def optimize(**kwargs: _Any) -> _Dict[str, _Any]:
    """The delivery that maximises carry (or total, or minimises dispersion), as
    ``carry optimize --json``: ``club``, ``club_speed``, ``dynamic_loft_range=(lo, hi)``,
    ``attack_angle_range``, ``impact_height_range``, ``objective``, ``starts``, … A given
    ``dynamic_loft``, ``attack_angle`` or ``impact_height`` holds that variable (its range
    frees it again, with a warning). With
    ``chart=True``, ``club_speeds=(from, to, step)`` and ``attack_angles=(…)``: the optimizer
    chart. Returns the JSON document (``dynamic_loft_deg``, ``attack_angle_deg``,
    ``carry_m``, the launch, evaluations, flatness)."""
    return _analysis("optimize", kwargs)


def sweep(**kwargs: _Any) -> _Dict[str, _Any]:
    """Carry, side, launch and spin against the ball position along a swing, as
    ``carry sweep --json``: ``swing`` (a CSV of club-head samples; without it the built-in
    example swing), ``ball_positions=(from, to, step)``, the club and scene options."""
    return _analysis("sweep", kwargs)


def dispersion(**kwargs: _Any) -> _Dict[str, _Any]:
    """Monte-Carlo dispersion over delivery noise, as ``carry dispersion --json``:
    ``face_angle_sd``, ``club_path_sd``, ``attack_angle_sd``, ``dynamic_loft_sd``,
    ``club_speed_sd``, ``impact_height_sd``, ``impact_toe_sd``, ``shots``, ``seed``, … Returns
    ``carry_mean_m``, ``carry_sd_m``, ``side_mean_m``, ``side_sd_m``, the covariance and the
    95 % ellipse. No progress bar unless ``no_progress=False``."""
    kwargs = dict(kwargs)
    kwargs.setdefault("no_progress", True)
    return _analysis("dispersion", kwargs)


def normalize(**kwargs: _Any) -> _Dict[str, _Any]:
    """A launch's carry in standard conditions (sea level, 21 °C, 50 % RH, no wind) and in
    the given ones, as ``carry normalize --json``: the launch options, the conditions and
    ``to="standard"`` (default) or ``"conditions"``."""
    return _analysis("normalize", kwargs)


def launch_from_flight(
    *,
    t: _Any = None,
    x: _Any = None,
    y: _Any = None,
    z: _Any = None,
    radial_speed: _Any = None,
    **kwargs: _Any,
) -> _Dict[str, _Any]:
    """The launch from the flight (issue 36, docs/launch_fit.md), as ``carry estimate
    --from flight --json``: the launch quantities not given — by default ``spin`` and
    ``spin_axis`` — fitted to the observations, each with its 1σ and its source.

    Keywords (the CLI's options, in ``units``): the measured launch ``ball_speed``,
    ``launch_angle``, ``launch_direction``, ``spin``, ``spin_axis`` (given: measured; not
    given: fitted) and the summaries ``apex_height``, ``apex_time``, ``carry``, ``side``,
    ``flight_time``, ``land_angle`` (degrees), each with an optional ``<name>_sd`` (1σ; the
    CLI's defaults otherwise); ``fit_wind=True``, ``fit_air_density=True``; the scene and
    ball options (``air_density``, ``temperature``, ``aero``, ``ground``, …),
    ``precision``. A track: numpy arrays ``t`` (s) with ``x``, ``y``, ``z`` (m, the shot's
    frame, the tee at the origin; at most 64 points) or with ``radial_speed`` (m/s away from
    the radar at ``radar_position``, default ``(-2.5, 0.3, 0)``; at most 256), always SI,
    each with 1σ ``track_sd``.

    Returns a dict: ``ball_speed_mps``, ``launch_angle_deg``, ``launch_direction_deg``,
    ``spin_rpm``, ``spin_axis_deg``, each with ``_sd`` and ``_source`` (``"measured"`` or
    ``"fitted to the flight"``); ``wind_mps``, ``air_density_kgm3`` (``None`` unless
    fitted); the fitted launch's ``carry_m``, ``side_m``, ``apex_m``, ``flight_time_s``,
    ``land_angle_deg`` (and ``total_m``, ``roll_m`` with a ``ground``); ``chi2``,
    ``observations``, ``worst_observation``, ``worst_residual_sigma``, ``iterations``,
    ``flights``. Raises :class:`LaunchFitError` (a ``ValueError``) naming the option.
    """
    options = []
    for name, value in kwargs.items():
        if name in ("json", "csv", "track"):
            raise LaunchFitError(
                f"--{name.replace('_', '-')}: the Python function takes the track as arrays "
                "(t with x, y, z or radial_speed) and returns the JSON record")
        if value is None or value is False:
            continue
        options.append((name, "true" if value is True else _option_value(name, value)))

    def column(name: str, v: _Any) -> _Any:
        if v is None:
            return None
        a = _np.asarray(v)
        if a.dtype.kind not in "biuf":
            raise LaunchFitError(f"--{name.replace('_', '-')}: expected an array of numbers")
        return _np.ascontiguousarray(a, dtype=_np.float64).ravel()

    arrays = {name: column(name, v) for name, v in
              (("t", t), ("x", x), ("y", y), ("z", z), ("radial_speed", radial_speed))}
    try:
        return _carry.launch_from_flight(options, **arrays)
    except ValueError as e:
        raise LaunchFitError(str(e)) from None
