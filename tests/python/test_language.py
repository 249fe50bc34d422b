"""The shape language from Python: operators build functions, numpy evaluation matches the
compiled C++ evaluators bitwise, bounds contain sampled values, and misuse is refused with a
message."""
import math
import os

import numpy as np
import pytest

import genmod as gm
from random_functions import random_function


def test_operators_build_the_expected_values():
    x, y = gm.x(0), gm.x(1)
    f = gm.cat([x + y, x - 1.0, 2.0 * y, x / 2.0, -x, x ** 2, 2.0 ** y, abs(x - y)])
    assert f.dim == 8 and f.inputs == [0, 1]
    got = f(np.array([0.5, -1.5]))
    assert got.tolist() == [-1.0, -0.5, -3.0, 0.25, -0.5, 0.25, 2.0 ** -1.5, 2.0]
    rel = gm.cat([x < y, x <= 0.5, x == 0.5, x != 0.5, (x > 0) & (y > 0), (x > 0) | (y > 0), ~(x > 0)])
    assert rel(np.array([0.5, -1.5])).tolist() == [0, 1, 1, 0, 0, 1, 0]
    assert f[1](np.array([3.0, 0.0])).tolist() == [2.0]
    assert f[-1].dim == 1


def test_numpy_evaluation_equals_point_evaluation_bitwise():
    rng = np.random.default_rng(7)
    points = rng.uniform(-2, 2, size=(500, 3))
    for _ in range(40):
        f = random_function(rng, 4)
        tape = gm.Tape(f, 3)
        batch = tape(points)
        assert batch.shape == (500, 1)
        for i in range(0, 500, 50):  # one point at a time: the scalar path
            single = tape(points[i])
            assert single.tobytes() == batch[i].tobytes()


def test_bounds_contain_sampled_values():
    rng = np.random.default_rng(11)
    for _ in range(40):
        f = random_function(rng, 4)
        lo = rng.uniform(-2, 1, size=3)
        box = np.stack([lo, lo + rng.uniform(0, 1, size=3)], axis=1)
        enclosure = f.bound(box)[0]
        samples = box[:, 0] + (box[:, 1] - box[:, 0]) * rng.random((200, 3))
        values = gm.Tape(f, 3)(samples)[:, 0]
        finite = values[np.isfinite(values)]
        assert np.all(finite >= enclosure[0]) and np.all(finite <= enclosure[1])


def test_derivatives_match_finite_differences():
    x, y = gm.x(0), gm.x(1)
    f = gm.sin(x * y) + gm.exp(x) * y
    dfdx = gm.derivative(f, 0)
    p = np.array([0.3, 0.7])
    h = 1e-6
    fd = (f(p + [h, 0]) - f(p - [h, 0])) / (2 * h)
    assert math.isclose(dfdx(p)[0], fd[0], rel_tol=1e-7)
    assert gm.compose(f, 1, x)(np.array([0.3]))[0] == pytest.approx(math.sin(0.09) + math.exp(0.3) * 0.3)


def test_misuse_is_refused_with_a_message():
    x = gm.x(0)
    with pytest.raises(TypeError, match="no truth value"):
        if x == 0.5:
            pass
    with pytest.raises(ValueError, match=r"depends on x\(2\)"):
        gm.x(2)(np.zeros((4, 2)))
    with pytest.raises(ValueError, match="dimensions"):
        gm.cat([x, x]) + gm.cat([x, x, x])
    with pytest.raises(ValueError, match="out of range"):
        gm.x(64)
    with pytest.raises(ValueError, match="lo <= hi"):
        x.bound(np.array([[1.0, 0.0]]))
    with pytest.raises(IndexError):
        x[3]


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_memory_stays_flat_while_100000_shapes_are_built_evaluated_and_dropped():
    # Each shape has its own nodes and its own custom operator (a curve); the C++ store reclaims
    # what nothing holds, so the node and operator counts come back to where they were and the
    # resident memory stops growing once the first shapes have warmed the allocator.
    nodes, operators = gm.live_nodes(), gm.live_custom_operators()
    point = np.array([0.1, 0.2])
    warm = None
    for i in range(100_000):
        curve = gm.Curve.bezier([[0.0, 0.0], [1.0, 1.0 + i], [2.0, 0.0]])(gm.x(0))
        f = gm.sqrt(gm.x(0) ** 2 + gm.x(1) ** 2) * (1.0 + i) - curve[1]
        f(point)
        if i == 10_000:
            warm = resident_bytes()
    del f, curve
    assert gm.live_nodes() == nodes and gm.live_custom_operators() == operators
    assert resident_bytes() - warm < 8 << 20, (warm, resident_bytes())


def test_every_layout_and_out_array_give_the_same_bits():
    rng = np.random.default_rng(3)
    points = rng.uniform(-2, 2, size=(10000, 3))
    f = gm.cat([random_function(rng, 4), random_function(rng, 3)])
    tape = gm.Tape(f, 3)
    expected = tape(points)
    fortran = tape(np.asfortranarray(points))
    assert fortran.flags.f_contiguous and fortran.tobytes(order="C") == expected.tobytes()
    assert tape(points[::3]).tobytes() == expected[::3].tobytes()  # a strided view, read in place
    assert tape(points[::-1]).tobytes() == expected[::-1].tobytes()  # backward: copied first
    assert tape(points.astype(np.float32)).shape == (10000, 2)  # converted
    out = np.full((10000, 2), np.nan)
    assert tape(points, out=out) is out and out.tobytes() == expected.tobytes()
    out_f = np.asfortranarray(np.zeros((10000, 2)))
    tape(np.asfortranarray(points), out=out_f)
    assert out_f.tobytes(order="C") == expected.tobytes()
    with pytest.raises(ValueError, match=r"out must have shape \(10000, 2\)"):
        tape(points, out=np.zeros((10000, 1)))
    with pytest.raises(ValueError, match="float64 with forward strides"):
        tape(points, out=np.zeros((10000, 2), dtype=np.float32))
    assert tape(np.zeros((0, 3))).shape == (0, 2)
