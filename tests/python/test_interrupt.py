"""Ctrl-C from Python stops a long C++ search: the call raises KeyboardInterrupt soon after the
signal, returns nothing half-done, and the module works normally afterwards."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import genmod as gm

BOX = np.array([[-2.0, 2.0], [-2.0, 2.0]])
CIRCLE = gm.x(0) ** 2 + gm.x(1) ** 2 == 1.0


def interrupted_after(seconds, call):
    """Runs call() with a SIGINT sent to this process after `seconds`; returns the time taken
    until KeyboardInterrupt came out of it."""
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
        timer.join()
    return time.monotonic() - start


def test_ctrl_c_stops_a_long_solve():
    # With epsilon 1e-13 the circle needs ~10^14 boxes: hours, unless interrupted.
    elapsed = interrupted_after(0.3, lambda: gm.solve(CIRCLE, [0, 1], BOX, epsilon=1e-13, max_boxes=10 ** 18,
                                                      time_limit=300))
    assert elapsed < 10
    after = gm.solve(CIRCLE & (gm.x(0) == gm.x(1)), [0, 1], BOX, epsilon=1e-9)
    assert after.complete and after.unique_components == 2


def test_ctrl_c_stops_a_long_minimization():
    # The minimizers fill a patch of the sphere |(x0, x1, x2)| = 0.7 (x3 = 0): with epsilon
    # 1e-14 the candidates would never end.
    X = [gm.x(i) for i in range(4)]
    objective = X[0] ** 2 + X[1] ** 2 + X[2] ** 2 + X[3] ** 2
    constraint = X[0] ** 2 + X[1] ** 2 + X[2] ** 2 >= 0.49
    box = np.array([[0.0, 1.0]] * 4)
    elapsed = interrupted_after(0.3, lambda: gm.minimize(objective, [0, 1, 2, 3], box, constraint=constraint,
                                                         epsilon=1e-14, delta=1e-300, max_boxes=10 ** 18,
                                                         time_limit=300))
    assert elapsed < 10


def test_ctrl_c_stops_meshing_and_batches(tmp_path):
    tangle = gm.load_vm(os.path.join(os.path.dirname(__file__), "..", "..", "data", "tanglecube.vm"))
    box = np.array([[-2.5, 2.5]] * 3)
    # min_feature 2e-4 would take minutes and gigabytes; 40 doorknobs at tolerance 1e-4 take
    # minutes too. The bounds below only tell "stopped" from "ran to the end" (a loaded machine
    # took 21 s for the batch, which stops between and within jobs); the file count is exact.
    elapsed = interrupted_after(0.5, lambda: gm.mesh_implicit(tangle, box, min_feature=2e-4, tolerance=1e-5))
    assert elapsed < 60
    jobs = "\n".join(f"doorknob tolerance={1e-4 * (1 + k / 100)} out=knob_{k}.ply" for k in range(40))
    elapsed = interrupted_after(0.5, lambda: gm.batch.run(jobs, tmp_path, threads=1))
    assert elapsed < 60
    assert len(list(tmp_path.iterdir())) < 40  # the jobs after the signal never ran
