"""carry.estimate: club data from ball data, against the forward model and the CLI."""

import json
import subprocess

import numpy as np
import pytest

import carry


def launch_of(r):
    """The ball data of an impact result, as estimate's launch arguments (SI, deg, rpm)."""
    return dict(
        ball_speed=r["ball_speed_mps"],
        launch_angle=r["launch_angle_deg"],
        launch_direction=r["launch_direction_deg"],
        spin=r["spin_rpm"],
        spin_axis=r["spin_axis_deg"],
    )


def test_round_trip_recovers_face_and_loft_from_the_forward_model():
    faces = np.array([-2.0, 0.0, 1.5, 3.0])
    r = carry.impact(club="driver", club_speed=45.0, attack_angle=-1.0, club_path=2.0,
                     face_angle=faces, dynamic_loft=13.0, raise_on_error=True)
    e = carry.estimate(club="driver", club_speed=45.0, attack_angle=-1.0, club_path=2.0,
                       raise_on_error=True, **launch_of(r))
    assert e["face_angle_deg"].shape == faces.shape
    # Noise-free ball data: the estimate lands within its own 1σ of the truth (the driver's
    # calibrated ball noise, docs/estimate.md §8, lets the prior pull it by a fraction of σ).
    assert np.all(np.abs(e["face_angle_deg"] - faces) < e["face_angle_deg_sd"])
    assert np.all(np.abs(e["dynamic_loft_deg"] - 13.0) < e["dynamic_loft_deg_sd"])
    assert np.all(e["face_angle_deg_sd"] > 0)
    assert np.all(e["club_speed_estimated"] == 0.0)
    assert np.all(e["iterations"] >= 1)
    assert all(x is None for x in e["errors"])


def test_every_column_and_the_errors():
    e = carry.estimate(ball_speed=[68.0, np.nan], launch_angle=12.0, spin=2700, spin_axis=-2)
    assert list(e) == carry.columns("estimate") + ["errors"]
    assert e["face_angle_deg"].shape == (2,)
    assert np.isfinite(e["face_angle_deg"][0]) and e["errors"][0] is None
    assert np.isnan(e["face_angle_deg"][1]) and "ball_speed" in e["errors"][1]
    assert e["club_speed_estimated"][0] == 1.0
    with pytest.raises(carry.ShotError, match=r"^row \(1,\): ball_speed"):
        carry.estimate(ball_speed=[68.0, np.nan], launch_angle=12.0, spin=2700,
                       raise_on_error=True)


def test_arguments_that_are_not_the_estimators_are_named():
    with pytest.raises(ValueError, match="^lie: is not an argument of carry.estimate"):
        carry.estimate(ball_speed=68.0, launch_angle=12.0, spin=2700, lie=2.0)
    with pytest.raises(ValueError, match="^solver: "):
        carry.estimate(ball_speed=68.0, launch_angle=12.0, spin=2700, solver="full")
    assert "club_speed" in carry.inputs("estimate")
    assert "wind_speed" not in carry.inputs("estimate")


def test_imperial_club_speed_is_converted():
    si = carry.estimate(ball_speed=68.0, launch_angle=12.0, spin=2700, club_speed=46.0)
    mph = carry.estimate(units="imperial", ball_speed=68.0 / 0.44704, launch_angle=12.0,
                         spin=2700, club_speed=46.0 / 0.44704)
    assert abs(si["face_angle_deg"] - mph["face_angle_deg"]) < 1e-9
    assert abs(si["club_speed_mps"] - mph["club_speed_mps"]) < 1e-9


def test_matches_the_cli(cli):
    options = dict(club="driver", ball_speed=66.5, launch_angle=13.2, launch_direction=1.1,
                   spin=2900, spin_axis=-4.0, club_speed=45.5)
    args = [cli, "estimate", "--json"] + [f"--{k.replace('_', '-')}={v}" for k, v in options.items()]
    doc = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    e = carry.estimate(raise_on_error=True, **options)
    for name, value in doc.items():
        got = float(e[name])
        want = float(value)
        assert got == pytest.approx(want, rel=1e-12, abs=1e-12), name


def test_the_posterior_summary_is_a_setting(cli):
    options = dict(club="driver", ball_speed=66.5, launch_angle=13.2, launch_direction=1.1,
                   spin=2900, spin_axis=-4.0, club_speed=45.5)
    profile = carry.estimate(raise_on_error=True, **options)
    laplace = carry.estimate(raise_on_error=True, posterior="laplace", **options)
    # the most probable delivery and the posterior mean differ along the height's valley,
    # and so do the Gauss–Newton and the profile 1σ of the strike height
    assert laplace["impact_height_m"] != profile["impact_height_m"]
    assert laplace["impact_height_m_sd"] != profile["impact_height_m_sd"]
    args = [cli, "estimate", "--json", "--posterior=laplace"] + [
        f"--{k.replace('_', '-')}={v}" for k, v in options.items()]
    doc = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    for name, value in doc.items():
        assert float(laplace[name]) == pytest.approx(float(value), rel=1e-12, abs=1e-12), name
    with pytest.raises(ValueError, match="^posterior: invalid value 'mean'"):
        carry.estimate(posterior="mean", **options)
    with pytest.raises(ValueError, match="^posterior: is not an argument of carry.flight"):
        carry.flight(ball_speed=66.5, launch_angle=13.2, spin=2900, posterior="laplace")


def test_inconsistent_data_are_flagged_naming_the_worst_datum():
    # Issue 34's example: a 70 m/s ball from a 5 m/s club. The row fails (NaN numbers, an
    # error naming the club speed); raise_on_error raises the typed InconsistentDataError.
    bad = dict(ball_speed=70.0, launch_angle=12.0, spin=2800, spin_axis=0.0, club_speed=5.0)
    e = carry.estimate(**bad)
    assert np.isnan(e["club_speed_mps"]) and "disagree" in e["errors"].item()
    with pytest.raises(carry.InconsistentDataError) as info:
        carry.estimate(raise_on_error=True, **bad)
    err = info.value
    assert isinstance(err, carry.ShotError) and isinstance(err, ValueError)
    assert err.datum in ("club_speed", "ball_speed"), err.message
    assert err.sd > 4.0 and err.chi2 > err.bound > 0.0
    # The same shot with a club speed that fits is not flagged.
    ok = carry.estimate(raise_on_error=True, **dict(bad, club_speed=47.0))
    assert np.isfinite(ok["club_speed_mps"]) and ok["errors"].item() is None
    # Other failures stay plain ShotErrors.
    with pytest.raises(carry.ShotError) as info:
        carry.estimate(ball_speed=np.nan, launch_angle=12.0, spin=2700, raise_on_error=True)
    assert not isinstance(info.value, carry.InconsistentDataError)
