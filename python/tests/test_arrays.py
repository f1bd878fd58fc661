"""Broadcasting, scalar vs array, precisions, per-row errors and argument errors."""

import math

import numpy as np
import pytest

import carry


def test_broadcast_shape_and_elements():
    speeds = np.array([60.0, 70.0, 80.0])[:, None]
    angles = np.array([8.0, 11.0, 14.0, 17.0])
    r = carry.flight(ball_speed=speeds, launch_angle=angles, spin=2600)
    for key in carry.columns("flight"):
        assert r[key].shape == (3, 4), key
        assert r[key].dtype == np.float64
    assert r["errors"].shape == (3, 4)
    assert all(e is None for e in r["errors"].ravel())
    one = carry.flight(ball_speed=70.0, launch_angle=14.0, spin=2600)
    for key in carry.columns("flight"):
        assert r[key][1, 2] == one[key], key


def test_scalar_call_gives_zero_d_arrays():
    r = carry.shot()
    assert r["carry_m"].shape == ()
    assert r["errors"].shape == () and r["errors"][()] is None
    assert math.isfinite(float(r["carry_m"]))


def test_scalar_and_array_calls_agree_exactly():
    rng = np.random.default_rng(7)
    speed = rng.uniform(35, 50, 6)
    path = rng.uniform(-4, 4, 6)
    r = carry.shot(club_speed=speed, club_path=path, club="5iron", wind_speed=3, wind_direction=90)
    for i in range(6):
        s = carry.shot(club_speed=speed[i], club_path=path[i], club="5iron", wind_speed=3, wind_direction=90)
        for key in carry.columns("shot"):
            assert r[key][i] == s[key], key


def test_lists_and_numpy_ints_broadcast_like_arrays():
    a = carry.impact(club_speed=[40, 45], face_angle=np.int64(2))
    b = carry.impact(club_speed=np.array([40.0, 45.0]), face_angle=2.0)
    np.testing.assert_array_equal(a["ball_speed_mps"], b["ball_speed_mps"])


def test_f32_close_to_f64_but_computed_in_f32():
    kw = dict(ball_speed=np.linspace(40, 85, 10), launch_angle=np.linspace(25, 9, 10), spin=np.linspace(8000, 2300, 10))
    r64 = carry.flight(**kw)
    r32 = carry.flight(precision="f32", **kw)
    # The core's f32 contract: carry within 1 cm of f64 at the default fidelity.
    assert np.max(np.abs(r32["carry_m"] - r64["carry_m"])) < 0.01
    assert np.any(r32["carry_m"] != r64["carry_m"])
    # f32 results are f32 values widened to f64.
    np.testing.assert_array_equal(r32["carry_m"].astype(np.float32).astype(np.float64), r32["carry_m"])


def test_imperial_units_convert_inputs_outputs_stay_si():
    si = carry.shot(club_speed=44.704, impact_toe=0.0127, temperature=30.0)
    imp = carry.shot(units="imperial", club_speed=100, impact_toe=0.5, temperature=86.0)
    assert imp["carry_m"] == pytest.approx(float(si["carry_m"]), abs=1e-9)


def test_bad_rows_are_nan_with_their_message():
    r = carry.shot(club_speed=[45.0, -3.0, np.nan, 40.0], impact_toe=[0, 0, 0, 0.3])
    err = r["errors"]
    assert err[0] is None
    assert err[1].startswith("club_speed:")
    assert err[2].startswith("club_speed:") and "finite" in err[2]
    assert "impact_toe" in err[3]
    assert math.isfinite(r["carry_m"][0])
    assert np.all(np.isnan(r["carry_m"][1:]))
    assert np.all(np.isnan(r["smash_factor"][1:]))


def test_raise_on_error_raises_the_first_bad_row():
    with pytest.raises(carry.ShotError, match="club_speed") as e:
        carry.shot(club_speed=[[45.0, 44.0], [-3.0, 40.0]], raise_on_error=True)
    assert e.value.index == (1, 0)
    assert isinstance(e.value, ValueError)
    carry.shot(club_speed=[45.0, 44.0], raise_on_error=True)


@pytest.mark.parametrize(
    "fn, kwargs, name",
    [
        (carry.shot, dict(clubspeed=45), "clubspeed"),
        (carry.shot, dict(club_speed="fast"), "club_speed"),
        (carry.shot, dict(club_speed=[1j]), "club_speed"),
        (carry.shot, dict(club_speed=["45"]), "club_speed"),
        (carry.shot, dict(club="putter"), "club"),
        (carry.shot, dict(club=7), "club"),
        (carry.shot, dict(ball_speed=70), "ball_speed"),
        (carry.impact, dict(wind_speed=3), "wind_speed"),
        (carry.flight, dict(aero="nonsense-model"), "aero"),
        (carry.flight, dict(ground="lava"), "ground"),
        (carry.flight, dict(precision="f16"), "precision"),
        (carry.flight, dict(units="metric"), "units"),
        (carry.flight, dict(integrator="rk4", tolerance=1e-6), "tolerance"),
        (carry.flight, dict(no_drag="yes"), "no_drag"),
        (carry.flight, dict(wind=(1, 2)), "wind"),
        (carry.impact, dict(solver="exact"), "solver"),
        (carry.flight, dict(ball_speed=[1, 2, 3], launch_angle=[1, 2]), "ball_speed"),
    ],
)
def test_bad_arguments_raise_value_error_naming_them(fn, kwargs, name):
    with pytest.raises(ValueError, match=rf"(^|, ){name}\b"):
        fn(**kwargs)


def test_columns_match_the_keys():
    assert set(carry.flight(ball_speed=[60, 70])) == set(carry.columns("flight")) | {"errors"}
    r = carry.flight(ground="fairway")
    assert set(r) == set(carry.columns("flight", ground=True)) | {"errors"}
    assert set(carry.impact()) == set(carry.columns("impact")) | {"errors"}


def test_named_fairways_are_distinct_turfs():
    # The three named fairways run the same flight out differently; the carry is the flight's.
    runs = {g: carry.flight(ball_speed=68, launch_angle=11, spin=2700, ground=g)
            for g in ("fairway", "fairway-trackman", "fairway-joint")}
    carries = {float(r["carry_m"]) for r in runs.values()}
    totals = {float(r["total_m"]) for r in runs.values()}
    assert len(carries) == 1 and len(totals) == 3, runs


def test_per_row_ground_options_add_ground_columns():
    r = carry.flight(stimp=[8, 10, 12], ground="green", ball_speed=30, launch_angle=30, spin=6000)
    assert r["total_m"].shape == (3,)
    assert np.all(np.isfinite(r["total_m"]))


def test_shared_scene_equals_per_row_scene():
    # A scalar scene is prepared once per call; a per-row scene value once per row.
    speeds = np.linspace(40, 80, 7)
    shared = carry.flight(ball_speed=speeds, air_density=1.1, wind_speed=3, wind_direction=45)
    per_row = carry.flight(ball_speed=speeds, air_density=np.full(7, 1.1), wind_speed=3, wind_direction=45)
    for key in carry.columns("flight"):
        np.testing.assert_array_equal(shared[key], per_row[key], err_msg=key)


def test_empty_arrays_give_empty_results():
    r = carry.flight(ball_speed=np.zeros((0, 3)))
    assert r["carry_m"].shape == (0, 3)
    assert r["errors"].shape == (0, 3)


def test_spin_axis_share_scales_the_axis_per_row():
    """Issue 34's empirical D-plane share as a per-row number: the axis tangent scales,
    ball speed and total spin do not; a share outside (0, 1] is that row's error."""
    out = carry.impact(face_angle=3, club_path=-1, spin_axis_share=[1.0, 0.5, 0.0])
    tan = np.tan(np.radians(out["spin_axis_deg"]))
    assert abs(tan[0]) > 0.1
    assert tan[1] == pytest.approx(0.5 * tan[0], rel=1e-9)
    assert out["ball_speed_mps"][1] == out["ball_speed_mps"][0]
    assert out["spin_rpm"][1] == pytest.approx(out["spin_rpm"][0], rel=1e-12)
    assert out["errors"][0] is None and out["errors"][1] is None
    assert "spin_axis_share" in out["errors"][2]
    assert np.isnan(out["spin_axis_deg"][2])
