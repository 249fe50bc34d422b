#!/usr/bin/python3
"""The cost of the Python layer: a model evaluated at 1 M points from a numpy array through
genmod.Tape against the C++ batch evaluator on the same points layout-free (bench/points,
structure of arrays), measured alternately in one run; median CPU seconds and their ratio, for
an (N, 3) C-ordered array (rows are points: the module regroups them per block), for a
Fortran-ordered one (columns are contiguous: read in place), each with a new result array or
into a reused one (out=; the C++ side reuses its output buffer too).

    /usr/bin/python3 bench/python/numpy_overhead.py [--model data/tanglecube.vm] [--points 1000000]
        [--rounds 7] [--cpp build/release/bench/genmod_points_bench]
"""
import argparse
import os
import statistics
import subprocess
import time

import numpy as np

import genmod as gm

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def python_seconds(tape, points, repeats, out=None):
    times = []
    for _ in range(repeats):
        start = time.process_time()
        tape(points, out=out)
        times.append(time.process_time() - start)
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=os.path.join(ROOT, "data", "tanglecube.vm"))
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--cpp", default=os.path.join(ROOT, "build", "release", "bench", "genmod_points_bench"))
    args = parser.parse_args()
    tape = gm.Tape(gm.load_vm(args.model), 3)
    rng = np.random.default_rng(1)
    c_order = rng.uniform(-2.5, 2.5, size=(args.points, 3))
    f_order = np.asfortranarray(c_order)
    out = np.empty((args.points, 1))
    cpp, c_py, f_py, c_out, f_out = [], [], [], [], []
    for _ in range(args.rounds):  # alternate, so load on the shared machine hits all three alike
        run = subprocess.run([args.cpp, args.model, str(args.points), "5"], check=True, capture_output=True, text=True)
        cpp.append(float(run.stdout))
        c_py.append(python_seconds(tape, c_order, 5))
        f_py.append(python_seconds(tape, f_order, 5))
        c_out.append(python_seconds(tape, c_order, 5, out))
        f_out.append(python_seconds(tape, f_order, 5, out))
    c = statistics.median(cpp)
    print(f"{os.path.basename(args.model)}, {args.points} points, {tape.size} clauses, median of {args.rounds} rounds")
    print(f"{'C++ batch evaluator':32}{c * 1e3:9.2f} ms")
    for label, times in (("Python, C-ordered (N, 3)", c_py), ("Python, Fortran-ordered (N, 3)", f_py),
                         ("  the same into out=", f_out), ("Python, C-ordered into out=", c_out)):
        t = statistics.median(times)
        print(f"{label:32}{t * 1e3:9.2f} ms  {t / c:5.3f}x")


if __name__ == "__main__":
    main()
