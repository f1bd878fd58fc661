"""Per-shot cost from Python: `carry.flight` on N random launches in one call vs
opengolfcoach's `calculate_derived_values` called once per shot, in the same process.

    pip install ./python opengolfcoach numpy
    python bench/python_vs_opengolfcoach.py               # 20,000 launches, 7 + 3 repetitions
    python bench/python_vs_opengolfcoach.py --json

opengolfcoach (PyPI, a Rust engine behind PyO3) takes one shot as a JSON string and returns
a JSON string, so its per-shot cost includes encoding the shot and decoding the result, as
its documented use does; the `--no-json` figure times the bare call on pre-encoded inputs.
carry's figure includes broadcasting the arrays and building the result dict. Medians of
the repetitions; the ratio is opengolfcoach's median per-shot time over carry's.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time

import numpy as np

import carry


def launches(n: int, seed: int) -> dict:
    """Random launches from wedges to drivers (m/s, degrees, rpm)."""
    rng = np.random.default_rng(seed)
    return {
        "ball_speed": rng.uniform(30.0, 80.0, n),
        "launch_angle": rng.uniform(8.0, 30.0, n),
        "launch_direction": rng.uniform(-5.0, 5.0, n),
        "spin": rng.uniform(2000.0, 9000.0, n),
        "spin_axis": rng.uniform(-20.0, 20.0, n),
    }


def ogc_shots(l: dict) -> list:
    return [
        {
            "ball_speed_meters_per_second": float(s),
            "vertical_launch_angle_degrees": float(a),
            "horizontal_launch_angle_degrees": float(d),
            "total_spin_rpm": float(w),
            "spin_axis_degrees": float(x),
        }
        for s, a, d, w, x in zip(l["ball_speed"], l["launch_angle"], l["launch_direction"], l["spin"], l["spin_axis"])
    ]


def time_it(fn, reps: int) -> list:
    out = []
    for _ in range(reps):
        t0 = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t0)
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--shots", type=int, default=20_000)
    p.add_argument("--carry-reps", type=int, default=7)
    p.add_argument("--ogc-reps", type=int, default=3)
    p.add_argument("--seed", type=int, default=13)
    p.add_argument("--json", action="store_true")
    a = p.parse_args(argv)

    try:
        import opengolfcoach
    except ImportError as e:
        print(f"opengolfcoach is not installed ({e}); pip install opengolfcoach", file=sys.stderr)
        return 2

    l = launches(a.shots, a.seed)
    carry.flight(**{k: v[:100] for k, v in l.items()})  # warm-up (thread pool)
    carry_times = time_it(lambda: carry.flight(**l), a.carry_reps)

    shots = ogc_shots(l)
    encoded = [json.dumps(s) for s in shots]
    calc = opengolfcoach.calculate_derived_values

    def ogc_loop():
        return [json.loads(calc(json.dumps(s)))["open_golf_coach"]["carry_distance_meters"] for s in shots]

    def ogc_bare():
        for s in encoded:
            calc(s)

    ogc_times = time_it(ogc_loop, a.ogc_reps)
    bare_times = time_it(ogc_bare, a.ogc_reps)

    # Context, not a verdict: the two engines' carries on the same launches (different
    # aerodynamic models and air; opengolfcoach's defaults are 25 °C, 50 %).
    ours = carry.flight(**l)["carry_m"]
    theirs = np.array(ogc_loop())

    per = lambda ts: statistics.median(ts) / a.shots  # noqa: E731
    report = {
        "shots": a.shots,
        "cores": os.cpu_count(),
        "carry_call_median_s": statistics.median(carry_times),
        "carry_per_shot_us": per(carry_times) * 1e6,
        "opengolfcoach_loop_median_s": statistics.median(ogc_times),
        "opengolfcoach_per_shot_us": per(ogc_times) * 1e6,
        "opengolfcoach_bare_call_per_shot_us": per(bare_times) * 1e6,
        "ratio": per(ogc_times) / per(carry_times),
        "ratio_vs_bare_call": per(bare_times) / per(carry_times),
        "carry_repetitions_s": carry_times,
        "opengolfcoach_repetitions_s": ogc_times,
        "carry_minus_opengolfcoach_carry_m_median": float(np.median(ours - theirs)),
        "opengolfcoach_version": getattr(opengolfcoach, "__version__", "?"),
    }
    if a.json:
        print(json.dumps(report, indent=1))
    else:
        print(f"{a.shots} random launches, {os.cpu_count()} cores; medians of {a.carry_reps} (carry) and {a.ogc_reps} (opengolfcoach) repetitions")
        print(f"  carry.flight, one call           {report['carry_call_median_s'] * 1e3:9.1f} ms   {report['carry_per_shot_us']:8.2f} us/shot")
        print(f"  opengolfcoach, per shot (JSON)   {report['opengolfcoach_loop_median_s'] * 1e3:9.1f} ms   {report['opengolfcoach_per_shot_us']:8.2f} us/shot")
        print(f"  opengolfcoach, bare call         {'':9}      {report['opengolfcoach_bare_call_per_shot_us']:8.2f} us/shot")
        print(f"  ratio (per shot)                 {report['ratio']:9.0f} x   (vs bare call {report['ratio_vs_bare_call']:.0f} x)")
        print(f"  median carry difference, carry - opengolfcoach: {report['carry_minus_opengolfcoach_carry_m_median']:+.2f} m (different models and air)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
