"""Type stubs of the Python package ``carry`` (see ``carry/__init__.py``)."""

from __future__ import annotations

import os
from typing import Any, Dict, Literal, Union

import numpy as np
import numpy.typing as npt

_Num = Union[float, int, npt.ArrayLike]
"""A number or an array of numbers (broadcast with the other numeric arguments)."""
_Radius = Union[float, int, Literal["flat"], npt.ArrayLike]
_Vec = Union[tuple, list, npt.ArrayLike]
"""Three numbers x,y,z (club_inertia: three or nine), shared by every row."""
_Path = Union[str, os.PathLike[str]]
"""A built-in name or a file."""

Result = Dict[str, np.ndarray]
"""float64 arrays of the broadcast shape keyed like the CLI's batch CSV columns, and
``errors``: an object array of ``None`` or each failed row's message."""

__version__: str

class ShotError(ValueError):
    """A failed row with ``raise_on_error=True``."""

    index: tuple
    message: str

def inputs(mode: Literal["impact", "flight", "shot", "estimate"]) -> Dict[str, str]: ...
def columns(mode: Literal["impact", "flight", "shot", "estimate"], ground: bool = False) -> list[str]: ...
def impact(
    *,
    raise_on_error: bool = False,
    club_speed: _Num | None = ...,
    attack_angle: _Num | None = ...,
    club_path: _Num | None = ...,
    face_angle: _Num | None = ...,
    dynamic_loft: _Num | None = ...,
    lie: _Num | None = ...,
    club_spin: _Vec | None = ...,
    club_spin_x: _Num | None = ...,
    club_spin_y: _Num | None = ...,
    club_spin_z: _Num | None = ...,
    impact_height: _Num | None = ...,
    impact_toe: _Num | None = ...,
    cor: _Num | None = ...,
    spin_axis_share: _Num | None = ...,
    club: str | None = ...,
    contact: _Path | None = ...,
    club_mass: _Num | None = ...,
    club_inertia: _Vec | None = ...,
    loft: _Num | None = ...,
    bulge: _Radius | None = ...,
    roll: _Radius | None = ...,
    face_depth_radius: _Radius | None = ...,
    cg_to_face: _Vec | None = ...,
    cg_to_face_x: _Num | None = ...,
    cg_to_face_y: _Num | None = ...,
    cg_to_face_z: _Num | None = ...,
    ball_mass: _Num | None = ...,
    ball_radius: _Num | None = ...,
    units: Literal["si", "imperial"] | None = ...,
    precision: Literal["f64", "f32"] | None = ...,
    solver: Literal["reduced", "full"] | None = ...,
) -> Result:
    """Club delivery → ball launch (``carry impact``); see the module docstring."""

def estimate(
    *,
    raise_on_error: bool = False,
    ball_mass: _Num | None = ...,
    ball_radius: _Num | None = ...,
    ball_speed: _Num | None = ...,
    launch_angle: _Num | None = ...,
    launch_direction: _Num | None = ...,
    backspin: _Num | None = ...,
    sidespin: _Num | None = ...,
    spin: _Num | None = ...,
    spin_axis: _Num | None = ...,
    club_speed: _Num | None = ...,
    attack_angle: _Num | None = ...,
    club_path: _Num | None = ...,
    face_angle: _Num | None = ...,
    dynamic_loft: _Num | None = ...,
    club: _Path | None = ...,
    contact: _Path | None = ...,
    club_mass: _Num | None = ...,
    club_inertia: _Vec | None = ...,
    loft: _Num | None = ...,
    bulge: _Radius | None = ...,
    roll: _Radius | None = ...,
    face_depth_radius: _Radius | None = ...,
    cg_to_face: _Vec | None = ...,
    cg_to_face_x: _Num | None = ...,
    cg_to_face_y: _Num | None = ...,
    cg_to_face_z: _Num | None = ...,
    cor: _Num | None = ...,
    spin_axis_share: _Num | None = ...,
    units: Literal["si", "imperial"] | None = ...,
    precision: Literal["f64", "f32"] | None = ...,
    posterior: Literal["profile", "laplace"] | None = ...,
) -> Result:
    """Ball data (and any measured club data) → the club delivery with 1σ each
    (``carry estimate``); see ``carry.estimate``'s docstring."""

def flight(
    *,
    raise_on_error: bool = False,
    ball_mass: _Num | None = ...,
    ball_radius: _Num | None = ...,
    ball_speed: _Num | None = ...,
    launch_angle: _Num | None = ...,
    launch_direction: _Num | None = ...,
    backspin: _Num | None = ...,
    sidespin: _Num | None = ...,
    spin: _Num | None = ...,
    spin_axis: _Num | None = ...,
    air_density: _Num | None = ...,
    temperature: _Num | None = ...,
    humidity: _Num | None = ...,
    pressure: _Num | None = ...,
    altitude: _Num | None = ...,
    wind: _Vec | None = ...,
    wind_x: _Num | None = ...,
    wind_y: _Num | None = ...,
    wind_z: _Num | None = ...,
    wind_speed: _Num | None = ...,
    wind_direction: _Num | None = ...,
    wind_reference_height: _Num | None = ...,
    wind_exponent: _Num | None = ...,
    landing_height: _Num | None = ...,
    time_limit: _Num | None = ...,
    no_drag: bool | None = ...,
    no_lift: bool | None = ...,
    no_spin_decay: bool | None = ...,
    aero: _Path | None = ...,
    ground: _Path | None = ...,
    stimp: _Num | None = ...,
    ground_slope: _Num | None = ...,
    ground_slope_direction: _Num | None = ...,
    ground_restitution: _Num | None = ...,
    ground_friction: _Num | None = ...,
    rolling_resistance: _Num | None = ...,
    crater_scale: _Num | None = ...,
    grass_height: _Num | None = ...,
    units: Literal["si", "imperial"] | None = ...,
    scene: _Path | None = ...,
    precision: Literal["f64", "f32"] | None = ...,
    integrator: Literal["euler", "rk4", "dp45"] | None = ...,
    step: float | None = ...,
    tolerance: float | None = ...,
) -> Result:
    """Launch → flight (``carry flight``); see the module docstring."""

def shot(
    *,
    raise_on_error: bool = False,
    club_speed: _Num | None = ...,
    attack_angle: _Num | None = ...,
    club_path: _Num | None = ...,
    face_angle: _Num | None = ...,
    dynamic_loft: _Num | None = ...,
    lie: _Num | None = ...,
    club_spin: _Vec | None = ...,
    club_spin_x: _Num | None = ...,
    club_spin_y: _Num | None = ...,
    club_spin_z: _Num | None = ...,
    impact_height: _Num | None = ...,
    impact_toe: _Num | None = ...,
    cor: _Num | None = ...,
    spin_axis_share: _Num | None = ...,
    club: str | None = ...,
    contact: _Path | None = ...,
    club_mass: _Num | None = ...,
    club_inertia: _Vec | None = ...,
    loft: _Num | None = ...,
    bulge: _Radius | None = ...,
    roll: _Radius | None = ...,
    face_depth_radius: _Radius | None = ...,
    cg_to_face: _Vec | None = ...,
    cg_to_face_x: _Num | None = ...,
    cg_to_face_y: _Num | None = ...,
    cg_to_face_z: _Num | None = ...,
    ball_mass: _Num | None = ...,
    ball_radius: _Num | None = ...,
    air_density: _Num | None = ...,
    temperature: _Num | None = ...,
    humidity: _Num | None = ...,
    pressure: _Num | None = ...,
    altitude: _Num | None = ...,
    wind: _Vec | None = ...,
    wind_x: _Num | None = ...,
    wind_y: _Num | None = ...,
    wind_z: _Num | None = ...,
    wind_speed: _Num | None = ...,
    wind_direction: _Num | None = ...,
    wind_reference_height: _Num | None = ...,
    wind_exponent: _Num | None = ...,
    landing_height: _Num | None = ...,
    time_limit: _Num | None = ...,
    no_drag: bool | None = ...,
    no_lift: bool | None = ...,
    no_spin_decay: bool | None = ...,
    aero: _Path | None = ...,
    ground: _Path | None = ...,
    stimp: _Num | None = ...,
    ground_slope: _Num | None = ...,
    ground_slope_direction: _Num | None = ...,
    ground_restitution: _Num | None = ...,
    ground_friction: _Num | None = ...,
    rolling_resistance: _Num | None = ...,
    crater_scale: _Num | None = ...,
    grass_height: _Num | None = ...,
    units: Literal["si", "imperial"] | None = ...,
    scene: _Path | None = ...,
    precision: Literal["f64", "f32"] | None = ...,
    solver: Literal["reduced", "full"] | None = ...,
    integrator: Literal["euler", "rk4", "dp45"] | None = ...,
    step: float | None = ...,
    tolerance: float | None = ...,
) -> Result:
    """Club delivery → launch → flight (``carry shot``); see the module docstring."""

def fit(
    data: Any,
    *,
    family: Literal["modern", "quintavalla", "compliant"] | str = "modern",
    evaluate: str | None = None,
    output: _Path | None = None,
    cross_validation: bool = True,
    units: Literal["si", "imperial"] = "si",
    air_density: float | None = None,
    temperature: float | None = None,
    humidity: float | None = None,
    pressure: float | None = None,
    altitude: float | None = None,
    also: Any = (),
    table_weight: float | None = None,
) -> Dict[str, Any]:
    """``carry fit --json`` on a DataFrame, dict of arrays, structured array or CSV path;
    ``also``: more data fitted jointly (paths or tables), ``table_weight`` as
    ``--table-weight``."""

def optimize(**kwargs: Any) -> Dict[str, Any]:
    """``carry optimize --json`` with ``kwargs`` as its options (snake_case)."""
    ...

def sweep(**kwargs: Any) -> Dict[str, Any]:
    """``carry sweep --json`` with ``kwargs`` as its options (snake_case)."""
    ...

def dispersion(**kwargs: Any) -> Dict[str, Any]:
    """``carry dispersion --json`` with ``kwargs`` as its options (snake_case)."""
    ...

def normalize(**kwargs: Any) -> Dict[str, Any]:
    """``carry normalize --json`` with ``kwargs`` as its options (snake_case)."""
    ...


class InconsistentDataError(ShotError):
    datum: str
    sd: float
    chi2: float
    bound: float
    def __init__(self, index: tuple, message: str) -> None: ...

class LaunchFitError(ValueError):
    option: str
    message: str
    def __init__(self, text: str) -> None: ...

def launch_from_flight(
    *,
    t: _Num | None = ...,
    x: _Num | None = ...,
    y: _Num | None = ...,
    z: _Num | None = ...,
    radial_speed: _Num | None = ...,
    ball_speed: float | None = ...,
    launch_angle: float | None = ...,
    launch_direction: float | None = ...,
    spin: float | None = ...,
    spin_axis: float | None = ...,
    apex_height: float | None = ...,
    apex_time: float | None = ...,
    carry: float | None = ...,
    side: float | None = ...,
    flight_time: float | None = ...,
    land_angle: float | None = ...,
    track_sd: float | None = ...,
    radar_position: _Vec | None = ...,
    fit_wind: bool = ...,
    fit_air_density: bool = ...,
    **kwargs: Any,
) -> Dict[str, Any]: ...
