#!/usr/bin/env python3
"""How two builds of `carry` differ on amateur driver deliveries (docs/impact.md §0.5).

Issue 22 reports its single drives' errors with the defaults of the day (issue 11's
model, commit ed7f14e). The drives are not shared, but the change of model on the same
deliveries is computable: both binaries strike a grid of amateur deliveries with
`carry batch impact --club driver` (club speed 80-110 mph, attack -4..+2 deg, dynamic loft
10-16 deg, face and path -3..+3 / -4..+4 deg, no strike location: each build's typical
strike) and the script prints the change per launch quantity. A uniform change adds to a
reported bias; it says nothing about the scatter around it.

    git worktree add /tmp/wt11 ed7f14e
    (cd /tmp/wt11 && CARGO_TARGET_DIR=/tmp/wt11-target cargo build --release -p carry-cli)
    cargo build --release -p carry-cli
    python3 bench/impact_change.py /tmp/wt11-target/release/carry target/release/carry
"""
import csv
import io
import itertools
import statistics
import subprocess
import sys

GRID = {
    "club_speed": [80, 90, 100, 110],  # mph
    "attack_angle": [-4, -1, 2],
    "dynamic_loft": [10, 13, 16],
    "face_angle": [-3, 0, 3],
    "club_path": [-4, 0, 4],
}


def strike(binary, text):
    out = subprocess.run(
        [binary, "batch", "impact", "--club", "driver", "--units", "imperial",
         "--input", "-", "--no-progress"],
        input=text, capture_output=True, text=True, check=True,
    ).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    bad = [r for r in rows if r["error"]]
    if bad:
        sys.exit(f"{binary}: {len(bad)} rows failed, e.g. {bad[0]['error']}")
    return rows


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    old_bin, new_bin = sys.argv[1:]
    header = ",".join(GRID)
    lines = [",".join(map(str, r)) for r in itertools.product(*GRID.values())]
    text = header + "\n" + "\n".join(lines) + "\n"
    old, new = strike(old_bin, text), strike(new_bin, text)

    def rel(key):
        return [100 * (float(b[key]) / float(a[key]) - 1) for a, b in zip(old, new)]

    def diff(key):
        return [float(b[key]) - float(a[key]) for a, b in zip(old, new)]

    print(f"{len(lines)} deliveries, new - old:\n")
    print("| quantity | mean | median | range |")
    print("|---|---:|---:|---:|")
    for name, xs, unit in [
        ("ball speed", rel("ball_speed_mps"), " %"),
        ("spin", rel("spin_rpm"), " %"),
        ("launch angle", diff("launch_angle_deg"), "°"),
        ("launch direction", diff("launch_direction_deg"), "°"),
        ("spin axis", diff("spin_axis_deg"), "°"),
    ]:
        print(f"| {name} | {statistics.mean(xs):+.2f}{unit} | {statistics.median(xs):+.2f}{unit} "
              f"| {min(xs):+.2f} … {max(xs):+.2f}{unit} |")


if __name__ == "__main__":
    main()
