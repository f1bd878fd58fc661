"""A large shot sweep on a Dask cluster: `carry.shot` mapped over DataFrame partitions.

Each partition's deliveries are drawn on the workers from their own seed (nothing large
travels to the cluster), flown with one vectorised `carry.shot` call per partition
(`dask.dataframe` `map_partitions`), and the result columns come back as one pandas
DataFrame. `--check` recomputes the sweep in this process, in one call, and requires exact
equality (the engine is deterministic: same inputs, same bits, whatever the partitioning).

    python python/examples/dask_sweep.py --shots 1000000               # LocalCluster
    python python/examples/dask_sweep.py --shots 20000 --workers 2 --check
    python python/examples/dask_sweep.py --scheduler tcp://host:8786   # an existing cluster
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np
import pandas as pd

import carry

#: The result columns kept (the engine's names; see `carry.columns("shot")`).
KEEP = ["ball_speed_mps", "launch_angle_deg", "spin_rpm", "carry_m", "side_m", "apex_m", "flight_time_s"]


def deliveries(partition: int, size: int, seed: int) -> pd.DataFrame:
    """The deliveries of one partition: a 7-iron to a driver, off-centre, in the wind."""
    rng = np.random.default_rng([seed, partition])
    return pd.DataFrame(
        {
            "club_speed": rng.uniform(32.0, 52.0, size),
            "attack_angle": rng.uniform(-5.0, 3.0, size),
            "dynamic_loft": rng.uniform(10.0, 32.0, size),
            "club_path": rng.uniform(-5.0, 5.0, size),
            "face_angle": rng.uniform(-4.0, 4.0, size),
            "impact_toe": rng.uniform(-0.015, 0.015, size),
            "impact_height": rng.uniform(-0.008, 0.008, size),
            "wind_speed": rng.uniform(0.0, 8.0, size),
            "wind_direction": rng.uniform(0.0, 360.0, size),
        }
    )


def fly(part: pd.DataFrame) -> pd.DataFrame:
    """One partition through `carry.shot` (one call: all the worker's cores, GIL released)."""
    r = carry.shot(**{c: part[c].to_numpy() for c in part.columns})
    out = pd.DataFrame({k: r[k] for k in KEEP}, index=part.index)
    # Arrow-backed strings (missing = no error): cheap to move between processes.
    out["error"] = pd.Series(r["errors"], index=part.index, dtype="string[pyarrow]")
    return out


def sizes(shots: int, partitions: int) -> list:
    base, extra = divmod(shots, partitions)
    return [base + (i < extra) for i in range(partitions)]


def sweep_on_cluster(client, shots: int, partitions: int, seed: int) -> pd.DataFrame:
    import dask.dataframe as dd

    n = sizes(shots, partitions)
    inputs = dd.from_map(lambda i: deliveries(i, n[i], seed), list(range(partitions)))
    meta = pd.DataFrame({k: pd.Series(dtype="float64") for k in KEEP} | {"error": pd.Series(dtype="string[pyarrow]")})
    return inputs.map_partitions(fly, meta=meta).compute().reset_index(drop=True)


def sweep_here(shots: int, partitions: int, seed: int) -> pd.DataFrame:
    n = sizes(shots, partitions)
    inputs = pd.concat([deliveries(i, n[i], seed) for i in range(partitions)], ignore_index=True)
    return fly(inputs)


def same(a: pd.DataFrame, b: pd.DataFrame) -> bool:
    if list(a.columns) != list(b.columns) or len(a) != len(b):
        return False
    numbers = all(np.array_equal(a[k].to_numpy(), b[k].to_numpy(), equal_nan=True) for k in KEEP)
    return numbers and a["error"].equals(b["error"])


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--shots", type=int, default=1_000_000, help="shots in the sweep (default 1e6)")
    p.add_argument("--partitions", type=int, default=0, help="partitions (default: one per 50,000 shots, at least 2 per worker)")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    p.add_argument("--threads-per-worker", type=int, default=1, help="Dask threads per worker (default 1: carry parallelises each call)")
    p.add_argument("--carry-threads", type=int, default=0, help="carry's threads per LocalCluster worker (RAYON_NUM_THREADS; default: cores / workers)")
    p.add_argument("--scheduler", help="address of an existing Dask scheduler instead of a LocalCluster")
    p.add_argument("--seed", type=int, default=2026)
    p.add_argument("--check", action="store_true", help="recompute in this process and require exact equality")
    p.add_argument("--json", action="store_true", help="print the timings as JSON")
    a = p.parse_args(argv)
    if a.shots < 1:
        p.error("--shots must be positive")
    partitions = a.partitions or max(2 * a.workers, -(-a.shots // 50_000))

    from dask.distributed import Client, LocalCluster

    cluster = None
    if a.scheduler:
        client = Client(a.scheduler)
    else:
        # One carry pool per worker process, sized so the workers share the cores.
        threads = a.carry_threads or max(1, (os.cpu_count() or 1) // a.workers)
        cluster = LocalCluster(
            n_workers=a.workers,
            threads_per_worker=a.threads_per_worker,
            processes=True,
            dashboard_address=None,
            env={"RAYON_NUM_THREADS": str(threads)},
        )
        client = Client(cluster)
    try:
        t0 = time.perf_counter()
        result = sweep_on_cluster(client, a.shots, partitions, a.seed)
        t_cluster = time.perf_counter() - t0
    finally:
        client.close()
        if cluster is not None:
            cluster.close()

    failed = int(result["error"].notna().sum())
    report = {
        "shots": a.shots,
        "partitions": partitions,
        "workers": a.workers if not a.scheduler else None,
        "cluster_s": round(t_cluster, 3),
        "shots_per_s": round(a.shots / t_cluster),
        "failed_rows": failed,
        "carry_m_mean": float(np.nanmean(result["carry_m"])),
    }
    ok = True
    if a.check:
        t0 = time.perf_counter()
        local = sweep_here(a.shots, partitions, a.seed)
        report["single_process_s"] = round(time.perf_counter() - t0, 3)
        ok = same(result, local)
        report["identical_to_single_process"] = ok
    if a.json:
        print(json.dumps(report))
    else:
        for k, v in report.items():
            print(f"{k:30} {v}")
    return 0 if ok and len(result) == a.shots else 1


if __name__ == "__main__":
    sys.exit(main())
