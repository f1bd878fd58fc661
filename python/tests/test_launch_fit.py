"""carry.launch_from_flight (issue 36): a known launch flown forward and its spin and axis
fitted back, from its summaries and from a track of numpy arrays; the CLI's numbers; the
typed error."""

import json
import subprocess

import numpy as np
import pytest

import carry

SPIN, AXIS = 2800.0, 5.0


def forward(**scene):
    return carry.flight(ball_speed=70.0, launch_angle=12.0, launch_direction=0.0, spin=SPIN,
                        spin_axis=AXIS, raise_on_error=True, **scene)


def summaries():
    f = forward()
    return dict(apex_height=float(f["apex_m"]), carry=float(f["carry_m"]),
                side=float(f["side_m"]), flight_time=float(f["flight_time_s"]),
                land_angle=float(f["land_angle_deg"]))


MEASURED = dict(ball_speed=70.0, launch_angle=12.0, launch_direction=0.0)


def test_spin_and_axis_from_the_summaries_within_their_sigma():
    r = carry.launch_from_flight(**MEASURED, **summaries())
    assert abs(r["spin_rpm"] - SPIN) < r["spin_rpm_sd"]
    assert abs(r["spin_axis_deg"] - AXIS) < r["spin_axis_deg_sd"]
    assert 0 < r["spin_rpm_sd"] < 300
    assert r["spin_rpm_source"] == "fitted to the flight"
    assert r["ball_speed_mps_source"] == "measured"
    assert r["observations"] == 5 and r["flights"] > 0
    assert r["wind_mps"] is None and r["total_m"] is None


def test_spin_and_axis_from_track_arrays():
    # Points of the true trajectory: where the descending ball crosses 0, 4, …, 24 m.
    heights = np.arange(0.0, 25.0, 4.0)
    f = forward(landing_height=heights)
    t = f["flight_time_s"][::-1]
    x, y, z = (f[f"landing_position_m_{c}"][::-1] for c in "xyz")
    r = carry.launch_from_flight(**MEASURED, t=t, x=x, y=y, z=z, track_sd=0.05)
    assert r["observations"] == 3 * len(heights)
    assert abs(r["spin_rpm"] - SPIN) < r["spin_rpm_sd"], r
    assert abs(r["spin_axis_deg"] - AXIS) < r["spin_axis_deg_sd"], r
    assert r["worst_observation"].startswith("track point")


def test_the_cli_gives_the_same_fit(cli):
    s = summaries()
    r = carry.launch_from_flight(**MEASURED, **s, carry_sd=2.0)
    args = [cli, "estimate", "--from", "flight", "--json", "--carry-sd", "2"]
    for name, value in {**MEASURED, **s}.items():
        args += [f"--{name.replace('_', '-')}", repr(value)]
    doc = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    assert doc == r


def test_refusals_are_typed_and_name_the_option():
    s = summaries()
    with pytest.raises(carry.LaunchFitError) as e:
        carry.launch_from_flight(**MEASURED, carry=s["carry"])
    assert e.value.option == "--apex-height, --carry, --side, --flight-time, --land-angle, --track"
    assert e.value.message.startswith("too few flight observations")
    assert isinstance(e.value, ValueError)
    with pytest.raises(carry.LaunchFitError, match="^--spin-axis: the flight observations do not"):
        carry.launch_from_flight(**MEASURED, apex_height=31.9, carry=222.4, flight_time=6.7)
    with pytest.raises(carry.LaunchFitError, match="^--carry: its 1σ must be positive"):
        carry.launch_from_flight(**MEASURED, **s, carry_sd=-1.0)
    with pytest.raises(carry.LaunchFitError, match="^--backspin, --sidespin: "):
        carry.launch_from_flight(**MEASURED, **s, backspin=2500.0)
    with pytest.raises(carry.LaunchFitError, match="^--x: 2 values for 3 times"):
        carry.launch_from_flight(**MEASURED, t=[0.1, 0.2, 0.3], x=[1, 2], y=[1, 2, 3],
                                 z=[0, 0, 0])
    with pytest.raises(carry.LaunchFitError, match="^--lie: "):
        carry.launch_from_flight(**MEASURED, **s, lie=2.0)
