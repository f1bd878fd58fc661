"""The Python results against the `carry` CLI's own JSON and batch CSV output."""

import csv
import io
import json
import subprocess

import numpy as np
import pytest

import carry

TOL_M = 1e-9


def cli_json(cli, command, options):
    args = [cli, command, "--json"]
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if value is True:
            args.append(flag)
        else:
            args.append(f"{flag}={value}")
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def flatten(doc):
    flat = {}
    for section, values in doc.items():
        if isinstance(values, list):  # impulse_ns
            values = {"": values}
        for key, value in values.items():
            name = key if section in ("launch", "flight") else section if not key else f"{section}_{key}"
            if isinstance(value, list):
                for axis, x in zip("xyz", value):
                    flat[f"{name}_{axis}"] = x
            elif isinstance(value, bool):
                flat[name] = float(value)
            else:
                flat[name] = value
    return flat


CASES = [
    ("flight", dict(ball_speed=70, launch_angle=12, spin=2600, spin_axis=-8)),
    ("flight", dict(ball_speed=52, launch_angle=18.5, backspin=7000, sidespin=300, wind_speed=5, wind_direction=135)),
    ("flight", dict(ball_speed=80, launch_angle=10, spin=2300, temperature=32, humidity=70, altitude=1600, ground="fairway")),
    ("flight", dict(units="imperial", ball_speed=160, launch_angle=11, spin=2800, landing_height=-20, aero="quintavalla")),
    ("flight", dict(ball_speed=66, launch_angle=14, spin=3000, precision="f32", integrator="rk4", step=0.002)),
    ("shot", dict(club="7iron", club_speed=38, face_angle=1.5, club_path=-2)),
    ("shot", dict(club_speed=47, impact_toe=0.012, impact_height=0.005, contact="rolling", wind_speed=4, wind_direction=180)),
    ("shot", dict(units="imperial", club="driver", club_speed=105, impact_toe=0.5, temperature=85, precision="f32")),
    ("shot", dict(club="pw", ground="green", stimp=11, tolerance=1e-8)),
    # The issue-35 turfs by name: the drives' and the joint (drives and 2010 chart) fairway.
    ("flight", dict(ball_speed=68, launch_angle=11, spin=2700, ground="fairway-trackman")),
    ("flight", dict(ball_speed=68, launch_angle=11, spin=2700, ground="fairway-joint")),
    ("impact", dict(club_speed=40, attack_angle=-4, dynamic_loft=25, solver="full", contact="rolling")),
]


@pytest.mark.parametrize("command, options", CASES)
def test_single_shots_match_cli_json(cli, command, options):
    expected = flatten(cli_json(cli, command, options))
    got = getattr(carry, command)(raise_on_error=True, **options)
    assert set(expected) <= set(got), set(expected) - set(got)
    for key, value in expected.items():
        if key.endswith("_m"):
            assert abs(float(got[key]) - value) <= TOL_M, key
        assert float(got[key]) == pytest.approx(value, rel=1e-12, abs=1e-12), key


def test_batch_csv_matches_one_python_call(cli, tmp_path):
    rng = np.random.default_rng(11)
    n = 200
    cols = {
        "ball_speed": rng.uniform(30, 85, n),
        "launch_angle": rng.uniform(4, 35, n),
        "spin": rng.uniform(1500, 9000, n),
        "spin_axis": rng.uniform(-20, 20, n),
        "wind_speed": rng.uniform(0, 8, n),
        "wind_direction": rng.uniform(0, 360, n),
    }
    cols["ball_speed"][5] = -1.0  # a bad row
    path = tmp_path / "in.csv"
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(list(cols))
        w.writerows(zip(*([repr(float(x)) for x in v] for v in cols.values())))
    text = subprocess.run(
        [cli, "batch", "flight", "--input", str(path), "--no-progress"], check=True, capture_output=True, text=True
    ).stdout
    rows = list(csv.DictReader(io.StringIO(text)))
    got = carry.flight(**cols)
    header = list(rows[0])
    assert header[1:-1] == carry.columns("flight")
    worst = 0.0
    for i, row in enumerate(rows):
        if row["error"]:
            assert got["errors"][i] == row["error"].split(": ", 1)[1] or row["error"].endswith(got["errors"][i])
            assert np.isnan(got["carry_m"][i])
            continue
        assert got["errors"][i] is None
        for key in header[1:-1]:
            assert got[key][i] == float(row[key]), (i, key)
        worst = max(worst, abs(got["carry_m"][i] - float(row["carry_m"])))
    assert worst <= TOL_M
    assert sum(1 for r in rows if r["error"]) == 1
