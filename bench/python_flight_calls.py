"""The carry part of `python_vs_opengolfcoach.py` alone, for callgrind: `reps` calls of
`carry.flight` on the same N random launches (the bench's draw), nothing else.

    RAYON_NUM_THREADS=1 valgrind --tool=callgrind python bench/python_flight_calls.py 0
    RAYON_NUM_THREADS=1 valgrind --tool=callgrind python bench/python_flight_calls.py 3

The difference of the two runs' instruction counts over 3 x 4,096 is carry's cost a shot
(the Python wrapper, the extension and the kernel); docs/scale.md has the figures.
"""

from __future__ import annotations

import argparse

import numpy as np

import carry


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("reps", type=int, nargs="?", default=3)
    p.add_argument("--shots", type=int, default=4096)
    p.add_argument("--seed", type=int, default=13)
    a = p.parse_args()
    rng = np.random.default_rng(a.seed)
    n = a.shots
    launches = {
        "ball_speed": rng.uniform(30.0, 80.0, n),
        "launch_angle": rng.uniform(8.0, 30.0, n),
        "launch_direction": rng.uniform(-5.0, 5.0, n),
        "spin": rng.uniform(2000.0, 9000.0, n),
        "spin_axis": rng.uniform(-20.0, 20.0, n),
    }
    r = None
    for _ in range(a.reps):
        r = carry.flight(**launches)
    if r is not None:
        # A checksum of two columns, to compare builds: equal sums of equal bits.
        print(f"carry_m sum {float(np.sum(r['carry_m'])).hex()}, apex_m sum {float(np.sum(r['apex_m'])).hex()}")


if __name__ == "__main__":
    main()
