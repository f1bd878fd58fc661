"""The GIL is released during a call: other Python threads run, and concurrent calls give
the serial results."""

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import carry


def launches(seed, n):
    rng = np.random.default_rng(seed)
    return dict(
        ball_speed=rng.uniform(30, 85, n),
        launch_angle=rng.uniform(5, 30, n),
        spin=rng.uniform(1500, 9000, n),
        spin_axis=rng.uniform(-15, 15, n),
    )


def test_threaded_calls_match_serial_calls():
    inputs = [launches(s, 3000) for s in range(4)]
    serial = [carry.flight(**kw)["carry_m"] for kw in inputs]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(lambda kw: carry.flight(**kw)["carry_m"], inputs))
    for a, b in zip(serial, threaded):
        np.testing.assert_array_equal(a, b)


def test_other_threads_run_during_a_long_call():
    ticks = []
    done = threading.Event()

    def ticker():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    kw = launches(1, 60_000)
    t = threading.Thread(target=ticker)
    t.start()
    try:
        start = time.perf_counter()
        carry.flight(**kw)
        end = time.perf_counter()
    finally:
        done.set()
        t.join()
    during = [x for x in ticks if start < x < end]
    # With the GIL held for the whole call the ticker could not run at all in between.
    assert end - start > 0.02
    assert len(during) >= 3, (len(during), end - start)
