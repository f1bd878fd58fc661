#!/usr/bin/env python3
"""carry against a peer: opengolfcoach (PyPI; a Rust flight engine, explicit Euler at 500 Hz,
with a Python binding). Issue 6.

    python3 -m venv /tmp/ogc && /tmp/ogc/bin/pip install opengolfcoach==0.3.0
    /tmp/ogc/bin/python bench/peer_opengolfcoach.py [--rows 200000] [--repeats 5]

One run times the same launches through both engines and compares their carries with
carry's f64 reference (Dormand–Prince 5(4) at 1e-12):

* opengolfcoach: `calculate_derived_values(json)` per shot from Python (the JSON strings are
  built beforehand; the time includes the binding's JSON parse and serialise — its only
  interface — and the Python call, but not `json.loads` of the answer).
* carry, end to end: `carry batch flight --threads 1` on a CSV of the same launches repeated
  to --rows rows, wall time per shot including process start, CSV parsing and CSV output;
* carry, compute only: the criterion bench `peer_launches/f64_default` (the same 12
  launches, `cargo bench -p carry-core --bench shot -- peer_launches`), run by this script
  unless --no-criterion.
* opengolfcoach's fixed overhead (binding, JSON, derived values) is estimated with a
  near-zero flight (0.5 m/s, 1°), so its integration cost can be told apart.

Atmosphere: both at 15 °C, 0 % humidity, 101325 Pa (ρ = 1.225 kg/m³ in carry; opengolfcoach
takes temperature_kelvin / humidity_percent / pressure_pascals and computes its own density).
The two engines use different aerodynamic models (carry: Quintavalla's coefficients;
opengolfcoach: its own drag/lift fits), so the carry difference is model + discretisation;
carry's own Euler at 500 Hz is shown to isolate what the integrator alone costs in accuracy.
"""

import argparse
import csv
import io
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import opengolfcoach

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (name, ball speed m/s, launch angle deg, total spin rpm, spin axis deg): straight shots
# from the golden flight set (standard air, no wind) plus a typical bag.
LAUNCHES = [
    ("reference_driver_impact", 65.87976772775029, 8.744649330360067, 2257.99909553281, 0.0),
    ("tour_driver", 74.65568, 10.9, 2686.0, 0.0),
    ("long_drive_90mps", 90.0, 12.0, 2200.0, 0.0),
    ("amateur_driver", 63.0, 13.0, 3000.0, 0.0),
    ("3wood", 70.0, 9.2, 3655.0, 0.0),
    ("tour_7iron", 53.6448, 16.3, 7097.0, 0.0),
    ("5iron", 59.0, 12.1, 5361.0, 0.0),
    ("tour_pw", 45.59808, 24.2, 9304.0, 0.0),
    ("wedge_58", 21.75, 36.6, 6447.0, 0.0),
    ("chip_low_slow", 12.0, 30.0, 4000.0, 0.0),
    ("knuckleball", 60.0, 14.0, 0.0, 0.0),
    ("high_80deg", 40.0, 80.0, 9000.0, 0.0),
]

AIR = {"temperature_kelvin": 288.15, "humidity_percent": 0.0, "pressure_pascals": 101325.0}


def ogc_inputs():
    out = []
    for _, v, a, s, axis in LAUNCHES:
        shot = {
            "ball_speed_meters_per_second": v,
            "vertical_launch_angle_degrees": a,
            "horizontal_launch_angle_degrees": 0.0,
            "total_spin_rpm": s,
            "spin_axis_degrees": axis,
        }
        shot.update(AIR)
        out.append(json.dumps(shot))
    return out


def time_ogc(inputs, repeats, min_s=0.5):
    """Median over repeats of (time per call), each repeat ≥ min_s of calls over the set."""
    f = opengolfcoach.calculate_derived_values
    for s in inputs:  # warm-up
        f(s)
    per = []
    for _ in range(repeats):
        n = 0
        t0 = time.perf_counter()
        while True:
            for s in inputs:
                f(s)
            n += len(inputs)
            dt = time.perf_counter() - t0
            if dt >= min_s:
                break
        per.append(dt / n)
    return statistics.median(per) * 1e6


def carry_bin():
    subprocess.run(
        ["cargo", "build", "--quiet", "--release", "-p", "carry-cli"], cwd=ROOT, check=True
    )
    return os.path.join(ROOT, "target", "release", "carry")


def write_csv(path, rows):
    with open(path, "w") as f:
        f.write("ball_speed,launch_angle,spin,spin_axis\n")
        for i in range(rows):
            _, v, a, s, axis = LAUNCHES[i % len(LAUNCHES)]
            f.write(f"{v!r},{a!r},{s!r},{axis!r}\n")


def carry_run(carry, path, *extra):
    out = subprocess.run(
        [carry, "batch", "flight", "--no-progress", "-i", path, *extra],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    return list(csv.DictReader(io.StringIO(out)))


def time_carry(carry, path, rows, repeats):
    per = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        subprocess.run(
            [carry, "batch", "flight", "--no-progress", "--threads", "1", "-i", path],
            check=True,
            stdout=subprocess.DEVNULL,
        )
        per.append((time.perf_counter() - t0) / rows)
    return statistics.median(per) * 1e6


def criterion_us():
    """carry's compute-only µs per flight: criterion's median for the 12 peer launches."""
    subprocess.run(
        ["cargo", "bench", "--quiet", "-p", "carry-core", "--bench", "shot", "--",
         "peer_launches", "--warm-up-time", "1", "--measurement-time", "2"],
        cwd=ROOT, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    path = os.path.join(ROOT, "target", "criterion", "peer_launches", "f64_default", "new",
                        "estimates.json")
    with open(path) as f:
        ns = json.load(f)["median"]["point_estimate"]
    return ns / 1e3 / len(LAUNCHES)


def ogc_overhead_us(repeats):
    """opengolfcoach per call on a near-zero flight: its fixed cost without integration."""
    shot = {"ball_speed_meters_per_second": 0.5, "vertical_launch_angle_degrees": 1.0,
            "horizontal_launch_angle_degrees": 0.0, "total_spin_rpm": 0.0,
            "spin_axis_degrees": 0.0}
    shot.update(AIR)
    return statistics.median(time_ogc([json.dumps(shot)], 1, 0.3) for _ in range(repeats))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rows", type=int, default=200_000, help="carry batch rows to time")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument(
        "--no-criterion",
        action="store_true",
        help="skip carry's compute-only criterion measurement",
    )
    ap.add_argument("--json", action="store_true", help="print JSON instead of Markdown")
    args = ap.parse_args()

    carry = carry_bin()
    inputs = ogc_inputs()
    with tempfile.TemporaryDirectory() as tmp:
        one = os.path.join(tmp, "launches.csv")
        write_csv(one, len(LAUNCHES))
        big = os.path.join(tmp, "many.csv")
        write_csv(big, args.rows)
        reference = carry_run(carry, one, "--integrator", "dp45", "--tolerance", "1e-12")
        default = carry_run(carry, one)
        euler = carry_run(carry, one, "--integrator", "euler", "--step", "0.002")
        # Timing, interleaved so both see the same machine load.
        ogc_us, carry_us = [], []
        for _ in range(args.repeats):
            ogc_us.append(time_ogc(inputs, 1))
            carry_us.append(time_carry(carry, big, args.rows, 1))
    ogc_us = statistics.median(ogc_us)
    carry_us = statistics.median(carry_us)
    overhead_us = ogc_overhead_us(args.repeats)
    compute_us = None if args.no_criterion else criterion_us()

    rows = []
    for (name, *_), s, r, d, e in zip(LAUNCHES, inputs, reference, default, euler):
        o = json.loads(opengolfcoach.calculate_derived_values(s))["open_golf_coach"]
        ref = float(r["carry_m"])
        rows.append(
            {
                "shot": name,
                "reference_carry_m": ref,
                "carry_default_error_m": float(d["carry_m"]) - ref,
                "carry_euler_500hz_error_m": float(e["carry_m"]) - ref,
                "ogc_carry_m": o["carry_distance_meters"],
                "ogc_error_m": o["carry_distance_meters"] - ref,
                "ogc_apex_m": o["peak_height_meters"],
                "reference_apex_m": float(r["apex_m"]),
                "ogc_flight_time_s": o["hang_time_seconds"],
                "reference_flight_time_s": float(r["flight_time_s"]),
            }
        )
    worst = lambda k: max(abs(x[k]) for x in rows)
    summary = {
        "load_average": os.getloadavg()[0],
        "launches": len(LAUNCHES),
        "ogc_version": opengolfcoach.__version__,
        "ogc_us_per_shot": ogc_us,
        "carry_batch_us_per_shot": carry_us,
        "ratio_batch": ogc_us / carry_us,
        "ogc_overhead_us_per_call": overhead_us,
        "carry_compute_us_per_shot": compute_us,
        "ratio_compute": ogc_us / compute_us if compute_us else None,
        "ratio_integration_only": (ogc_us - overhead_us) / compute_us if compute_us else None,
        "worst_carry_error_m": {
            "carry_default": worst("carry_default_error_m"),
            "carry_euler_500hz": worst("carry_euler_500hz_error_m"),
            "opengolfcoach": worst("ogc_error_m"),
        },
        "rows": rows,
    }
    if args.json:
        json.dump(summary, sys.stdout, indent=1)
        print()
        return
    print(f"# carry vs opengolfcoach {opengolfcoach.__version__} "
          f"(load {summary['load_average']:.2f}, {len(LAUNCHES)} launches, 15 °C, 0 % RH, 101325 Pa)\n")
    print("| shot | reference carry (m) | carry default − ref | carry Euler 500 Hz − ref | opengolfcoach − ref | apex ref / ogc (m) | flight time ref / ogc (s) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for x in rows:
        print(f"| {x['shot']} | {x['reference_carry_m']:.3f} | {x['carry_default_error_m']*1e3:+.3f} mm "
              f"| {x['carry_euler_500hz_error_m']*1e3:+.1f} mm | {x['ogc_error_m']:+.3f} m "
              f"| {x['reference_apex_m']:.2f} / {x['ogc_apex_m']:.2f} "
              f"| {x['reference_flight_time_s']:.3f} / {x['ogc_flight_time_s']:.3f} |")
    w = summary["worst_carry_error_m"]
    print(f"\nWorst |carry − reference|: carry default {w['carry_default']*1e3:.3f} mm, "
          f"carry Euler 500 Hz {w['carry_euler_500hz']*1e3:.1f} mm, opengolfcoach {w['opengolfcoach']:.3f} m.")
    print(f"\nPer shot: opengolfcoach {ogc_us:.1f} µs (Python call + JSON in/out), "
          f"carry batch flight --threads 1 {carry_us:.2f} µs (process + CSV in/out, {args.rows} rows) "
          f"→ carry {summary['ratio_batch']:.0f}× faster per shot.")
    print(f"opengolfcoach's fixed cost per call (near-zero flight): {overhead_us:.1f} µs.")
    if compute_us:
        print(f"Compute only: carry {compute_us:.2f} µs per flight (criterion, same launches) → "
              f"{summary['ratio_compute']:.0f}× per shot; "
              f"{summary['ratio_integration_only']:.0f}× counting only opengolfcoach's time above its fixed cost.")


if __name__ == "__main__":
    main()
