#!/usr/bin/python3
"""The cost of the Python layer: a model evaluated at 1 M points from a numpy array through
genmod.Tape against the C++ batch evaluator on the same layout (bench/points), measured
alternately in one run; median CPU seconds and their ratio. A Fortran-ordered (N, 3) array is
compared with three C++ coordinate arrays, a C-ordered one with a C++ row-major array (both
read in place with strides), each with a new result array or into a reused one (out=; the C++
side reuses its output buffer).

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
    cpp_columns, cpp_rows, c_py, f_py, c_out, f_out = [], [], [], [], [], []
    for _ in range(args.rounds):  # alternate, so load on the shared machine hits all three alike
        run = subprocess.run([args.cpp, args.model, str(args.points), "5"], check=True, capture_output=True, text=True)
        columns, rows = run.stdout.split()
        cpp_columns.append(float(columns))
        cpp_rows.append(float(rows))
        c_py.append(python_seconds(tape, c_order, 5))
        f_py.append(python_seconds(tape, f_order, 5))
        c_out.append(python_seconds(tape, c_order, 5, out))
        f_out.append(python_seconds(tape, f_order, 5, out))
    print(f"{os.path.basename(args.model)}, {args.points} points, {tape.size} clauses, median of {args.rounds} rounds")
    for label, base, cases in (
            ("C++, three coordinate arrays", cpp_columns,
             (("Python, Fortran-ordered (N, 3)", f_py), ("  the same into out=", f_out))),
            ("C++, one row-major (N, 3) array", cpp_rows,
             (("Python, C-ordered (N, 3)", c_py), ("  the same into out=", c_out)))):
        b = statistics.median(base)
        print(f"{label:34}{b * 1e3:9.2f} ms")
        for case, times in cases:
            t = statistics.median(times)
            print(f"{case:34}{t * 1e3:9.2f} ms  {t / b:5.3f}x")


if __name__ == "__main__":
    main()
