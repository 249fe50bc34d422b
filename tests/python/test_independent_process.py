"""Values, bounds and derivatives from Python equal those of a separate C++ process bitwise:
random functions are written as .vm files, and genmod_vm_oracle (tests/python/vm_oracle.cpp,
the scalar point and interval evaluators on the function read back) computes them again."""
import os
import pathlib
import subprocess

import numpy as np

import genmod as gm
from random_functions import random_function


def oracle_path():
    """The oracle ctest names, or the one of the build tree the module comes from."""
    if "GENMOD_VM_ORACLE" in os.environ:
        return os.environ["GENMOD_VM_ORACLE"]
    build = pathlib.Path(gm.__file__).resolve().parents[2]
    return str(build / "tests" / "genmod_vm_oracle")


def test_python_equals_a_separate_cpp_process_bitwise(tmp_path):
    oracle = oracle_path()
    assert os.access(oracle, os.X_OK), f"the oracle program {oracle} is not built"
    rng = np.random.default_rng(2026)
    points = rng.uniform(-2, 2, size=(200, 3))
    points.tofile(tmp_path / "points.bin")
    compared = 0
    for k in range(40):
        f = random_function(rng, 4)
        lo = rng.uniform(-2, 1, size=3)
        box = np.stack([lo, lo + rng.uniform(0, 1, size=3)], axis=1)
        box.tofile(tmp_path / "box.bin")
        gm.save_vm(f, str(tmp_path / "f.vm"))
        subprocess.run([oracle, str(tmp_path / "f.vm"), str(tmp_path / "points.bin"), str(tmp_path / "box.bin"),
                        str(tmp_path / "out.bin")], check=True)
        out = np.fromfile(tmp_path / "out.bin")
        n = len(points)
        values, bound, partials = out[:n], out[n:n + 2], out[n + 2:].reshape(n, 3)
        assert gm.Tape(f, 3)(points)[:, 0].tobytes() == values.tobytes(), f"values of function {k}"
        assert f.bound(box)[0].tobytes() == bound.tobytes(), f"bound of function {k}"
        mine = np.stack([gm.Tape(gm.derivative(f, i), 3)(points)[:, 0] for i in range(3)], axis=1)
        assert mine.tobytes() == partials.tobytes(), f"derivatives of function {k}"
        compared += 1
    assert compared == 40
