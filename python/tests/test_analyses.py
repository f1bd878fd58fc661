"""`carry.optimize`, `sweep`, `dispersion` and `normalize` against the CLI's `--json`."""

import json
import subprocess

import pytest

import carry


def cli_json(cli, *args):
    out = subprocess.run([cli, *args, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def test_optimize_matches_cli(cli):
    got = carry.optimize(club="7iron", club_speed=40, dynamic_loft_range=(18, 30),
                         attack_angle_range=[-5, 1], starts=2)
    expected = cli_json(cli, "optimize", "--club", "7iron", "--club-speed", "40",
                        "--dynamic-loft-range", "18,30", "--attack-angle-range", "-5,1",
                        "--starts", "2")
    got.pop("elapsed_s"), expected.pop("elapsed_s")  # wall time: the only field that varies
    assert got == expected
    assert 18 <= got["dynamic_loft_deg"] <= 30


def test_total_chart_matches_cli(cli):
    got = carry.optimize(chart=True, objective="total", ground="fairway",
                         club_speeds=(40, 45, 5), attack_angles=(0, 0, 1))
    expected = cli_json(cli, "optimize", "--chart", "--objective", "total", "--ground",
                        "fairway", "--club-speeds", "40,45,5", "--attack-angles", "0,0,1")
    assert got == expected
    assert all(c["total_m"] > c["carry_m"] for c in got["cells"])


def test_dispersion_matches_cli_and_zero_noise_is_the_shot(cli):
    got = carry.dispersion(club="driver", face_angle_sd=2.0, shots=300, seed=7)
    expected = cli_json(cli, "dispersion", "--club", "driver", "--face-angle-sd", "2",
                        "--shots", "300", "--seed", "7", "--no-progress")
    assert got == expected
    calm = carry.dispersion(club="driver", shots=10, seed=1)
    single = carry.shot(club="driver")
    assert calm["carry_sd_m"] == 0.0
    assert calm["carry_mean_m"] == pytest.approx(float(single["carry_m"]), abs=1e-9)


def test_sweep_and_normalize_match_cli(cli):
    assert carry.sweep(ball_positions=(-0.05, 0.05, 0.025)) == cli_json(
        cli, "sweep", "--ball-positions", "-0.05,0.05,0.025")
    got = carry.normalize(ball_speed=70, temperature=35, altitude=1500)
    assert got == cli_json(cli, "normalize", "--ball-speed", "70", "--temperature", "35",
                           "--altitude", "1500")


@pytest.mark.parametrize("call, option", [
    (lambda: carry.optimize(dynamic_loft_range=(30, 18)), "--dynamic-loft-range"),
    (lambda: carry.dispersion(face_angle_sd=-1), "--face-angle-sd"),
    (lambda: carry.normalize(no_such_option=1), "--no-such-option"),
    (lambda: carry.sweep(ball_positions="a,b"), "--ball-positions"),
    (lambda: carry.optimize(starts=float("nan")), "starts"),
    (lambda: carry.optimize(chart=True, objective="total"), "objective"),
])
def test_bad_input_is_a_value_error_naming_the_option(call, option):
    with pytest.raises(ValueError, match=option):
        call()
