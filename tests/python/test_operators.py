"""The operator families from Python: curves and curve files, sweeps, offsets, paths, vectors,
matrices, shapes and skeletal fields give the values their definitions say, bounds that contain
sampled values, and derivatives that agree with finite differences."""
import math

import numpy as np
import pytest

import genmod as gm

U, V = gm.x(0), gm.x(1)
CIRCLE = gm.cat([gm.cos(2 * math.pi * U), gm.sin(2 * math.pi * U)])


def check_bounds_and_derivatives(f, n, rng, domain=(0.0, 1.0)):
    """Bounds over random sub-boxes contain 300 samples; d/dx(i) matches central differences."""
    tape = gm.Tape(f, n)
    lo_d, hi_d = domain
    for _ in range(10):
        lo = rng.uniform(lo_d, hi_d, size=n)
        hi = np.minimum(lo + rng.uniform(0, 0.3, size=n), hi_d)
        box = np.stack([lo, hi], axis=1)
        enclosure = f.bound(box)
        samples = tape(lo + (hi - lo) * rng.random((300, n)))
        assert np.all(samples >= enclosure[:, 0]) and np.all(samples <= enclosure[:, 1])
    points = rng.uniform(lo_d + 0.05, hi_d - 0.05, size=(20, n))
    h = 1e-6
    for i in range(n):
        step = np.zeros(n)
        step[i] = h
        numeric = (tape(points + step) - tape(points - step)) / (2 * h)
        exact = gm.Tape(gm.derivative(f, i), n)(points)
        assert np.allclose(exact, numeric, rtol=1e-5, atol=1e-5)


def test_curves_interpolate_and_bound_their_values():
    rng = np.random.default_rng(1)
    points = [[0.0, 0.0], [1.0, 2.0], [2.0, -1.0], [3.0, 0.5]]
    cr = gm.Curve.catmull_rom(points)
    assert cr.dimension == 2 and cr.domain == (0.0, 1.0)
    at = gm.Tape(cr(U), 1)(np.array([[0.0], [1 / 3], [2 / 3], [1.0]]))
    assert np.allclose(at, points, atol=1e-14)
    bez = gm.Curve.bezier([[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 1.0]])
    assert np.allclose(bez(U)(np.array([0.5])), [1.0, 0.5, 0.25])
    nurbs = gm.Curve.nurbs([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], [1.0, math.sqrt(0.5), 1.0], 2)
    quarter = gm.Tape(gm.length(nurbs(U)), 1)(np.linspace(0, 1, 50)[:, None])
    assert np.allclose(quarter, 1.0, atol=1e-14)  # a NURBS quarter circle is exact
    for c in (cr, bez, nurbs, gm.Curve.uniform_bspline([[0, 0], [1, 3], [2, 0], [3, 3], [4, 0]], 3)):
        check_bounds_and_derivatives(c(U), 1, rng)
    with pytest.raises(ValueError):
        gm.Curve.nurbs(points[:3], [1.0, -1.0, 1.0], 2)
    assert np.isnan(cr(U)(np.array([1.5]))).all()  # outside the domain: an error, never a clamp


def test_curve_files_parse_and_name_bad_lines(tmp_path):
    path = tmp_path / "c.crv"
    path.write_text(gm_curve_text := "crv 1\ntype polyline\ndimension 2\npoint 0 0\npoint 1 1  # a corner\npoint 2 0\n")
    c = gm.load_curve(str(path))
    assert c.control_points == [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]
    assert gm.parse_curve(gm_curve_text).control_points == c.control_points
    assert np.allclose(gm.crv(str(path), U)(np.array([0.25])), [0.5, 0.5])
    with pytest.raises(ValueError, match=r"<string>:4: point has 3 numbers, expected 2"):
        gm.parse_curve("crv 1\ntype polyline\ndimension 2\npoint 0 0 0\n")


def test_sweeps_offsets_and_paths():
    rng = np.random.default_rng(2)
    profile = gm.Curve.bezier([[0.5, -1.0], [1.5, 0.0], [0.5, 1.0]])(U)
    vase = gm.profile_surface(CIRCLE, profile)
    assert vase.dim == 3 and vase.inputs == [0, 1]
    uv = rng.random((100, 2))
    p = gm.Tape(vase, 2)(uv)
    radius = gm.Tape(profile, 1)(uv[:, 1:2])
    assert np.allclose(np.hypot(p[:, 0], p[:, 1]), radius[:, 0]) and np.allclose(p[:, 2], radius[:, 1])
    check_bounds_and_derivatives(vase, 2, rng)
    # An offset of the unit circle by 0.25 along its normal is a circle of radius 1 -+ 0.25.
    ring = gm.Tape(gm.length(gm.offset_curve(CIRCLE, 0.25)), 1)(rng.random((50, 1)))
    assert np.allclose(ring, 1.0 + 0.25 * np.sign(ring[0] - 1.0)) and abs(abs(ring[0, 0] - 1.0) - 0.25) < 1e-12
    capsule = gm.closed_offset(gm.cat([2.0 * U - 1.0, gm.Fn(0.0)]), 0.2)
    ends = gm.Tape(capsule, 1)(np.array([[0.0], [1.0]]))
    assert np.allclose(ends[0], ends[1])  # closed
    arc = gm.arc_2pt_height(gm.cat([-1.0, 0.0]), gm.cat([1.0, 0.0]), -0.3, U)
    assert np.allclose(arc(np.array([0.5])), [0.0, -0.3])
    square = gm.Path()
    square.move_to(gm.cat([0.0, 0.0]))
    for corner in ([1.0, 0.0], [1.0, 1.0], [0.0, 1.0]):
        square.line_to(gm.cat(corner))
    square.close()
    assert square.pieces == 4
    assert np.allclose(gm.Tape(square.curve(U), 1)(np.array([[0.0], [0.25], [0.625], [1.0]])),
                       [[0, 0], [1, 0], [0.5, 1], [0, 0]])
    rail = gm.rail_surface(gm.cat([2 * U - 1, gm.Fn(0.0)]), gm.cat([U, gm.Fn(0.0)]), gm.cat([U, gm.Fn(1.0)]))
    assert rail.dim == 3


def test_vectors_and_matrices():
    a = gm.cat([U, V, gm.Fn(1.0)])
    b = gm.cat([gm.Fn(1.0), gm.Fn(2.0), U])
    at = np.array([0.3, 0.7])
    assert np.allclose(gm.dot(a, b)(at), [0.3 + 1.4 + 0.3])
    assert np.allclose(gm.cross(a, b)(at), np.cross([0.3, 0.7, 1.0], [1.0, 2.0, 0.3]))
    assert np.allclose(gm.length(gm.normalize(a))(at), [1.0])
    m = gm.Matrix(gm.cat([U, V, gm.Fn(2.0), gm.Fn(3.0)]), 2, 2)
    assert np.allclose(gm.determinant(m)(at), [0.3 * 3 - 0.7 * 2])
    assert np.allclose((m @ gm.inverse(m)).fn(at), [1, 0, 0, 1])
    assert np.allclose(gm.transpose(m)[0, 1](at), [2.0])


def test_higher_order_and_solver_operators():
    rng = np.random.default_rng(4)
    s = gm.x(2)
    ramp = gm.integrate(s, gm.Fn(0.0), U, 2)  # the integral of t from 0 to u: u^2 / 2
    assert np.allclose(gm.Tape(ramp, 1)(np.array([[0.3], [0.8]]))[:, 0], [0.045, 0.32], atol=1e-12)
    check_bounds_and_derivatives(ramp, 1, rng)
    plane = gm.table([0.0, 1.0, 1.0, 2.0], [1, 2, 2], gm.cat([U, V]))
    assert np.allclose(plane(np.array([0.25, 0.5])), [0.75])
    assert np.allclose(gm.interp(U, gm.Fn(2.0), gm.Fn(4.0))(np.array([0.25])), [2.5])
    steps = gm.concat(0, U, [gm.Fn(1.0) + 0 * U, gm.Fn(2.0) + 0 * U])
    assert np.allclose(gm.Tape(steps, 1)(np.array([[0.2], [0.7]]))[:, 0], [1.0, 2.0])
    assert np.allclose(gm.index([gm.Fn(5.0), gm.Fn(6.0)], U)(np.array([1.5])), [6.0])
    assert np.isnan(gm.select_case([U > 2.0], [gm.Fn(1.0)])(np.array([0.5]))).all()
    # m_inverse: the t with t^2 = x(1), i.e. sqrt(x(1)); m_solve the same by the solver.
    root = gm.inverse(gm.x(0) ** 2, gm.x(1), 0)
    assert np.allclose(gm.Tape(root, 2)(np.array([[0.0, 0.49]])), [0.7], atol=1e-10)
    solved = gm.solve_operator(gm.x(0) ** 2 == gm.x(1), [0], np.array([[0.0, 2.0]]), epsilon=1e-10)
    assert np.allclose(gm.Tape(solved, 2)(np.array([[0.0, 0.49]])), [0.7], atol=1e-8)
    lowest = gm.minimum_value_operator((gm.x(0) - gm.x(1)) ** 2 + 1.0, [0], np.array([[0.0, 1.0]]))
    assert np.allclose(gm.Tape(lowest, 2)(np.array([[0.0, 0.3], [0.0, 2.0]]))[:, 0], [1.0, 2.0], atol=1e-6)


def test_more_skeletal_fields():
    cubic = gm.CubicCurve([0, 0, 0], [0, 0, 0], [1, 0, 0], [0, 0, 0])  # the segment (0,0,0)-(1,0,0)
    d2 = gm.distance2_to_cubic(cubic)
    assert np.allclose(gm.Tape(d2, 3)(np.array([[0.5, 0.3, 0.0], [2.0, 0.0, 0.0]]))[:, 0], [0.09, 1.0], atol=1e-9)
    limb = gm.SkeletonLimb([0, 0, 0], [0, 0, 1], 0.2)
    arms = [gm.SkeletonLimb([0, 0, 1], [0.5, 0, 1.5], 0.2 / math.sqrt(2)),
            gm.SkeletonLimb([0, 0, 1], [-0.5, 0, 1.5], 0.2 / math.sqrt(2))]
    tree = gm.ramiform_density(limb, arms)
    assert gm.Tape(tree, 3)(np.array([0.1, 0.0, 0.5]))[0] > 1.0 > gm.Tape(tree, 3)(np.array([0.5, 0.0, 0.5]))[0]
    elements = [gm.FieldElement(gm.segment_convolution([float(i), 0, 0], [i + 0.5, 0, 0], 0.2, 0.2),
                                [float(i), 0, 0], [i + 0.5, 0, 0], 1.0, 0.2, gm.Falloff.gaussian) for i in range(20)]
    field = gm.culled_field(elements)
    box = np.array([[3.1, 3.3], [0.0, 0.2], [-0.1, 0.1]])
    samples = gm.Tape(field, 3)(box[:, 0] + (box[:, 1] - box[:, 0]) * np.random.default_rng(6).random((500, 3)))
    enclosure = field.bound(box)[0]
    assert enclosure[0] <= samples.min() and samples.max() <= enclosure[1]
    # Elements from the factories (Gaussian form declared: their derivatives cull too), with the
    # hierarchy and with the linear scan: the value is the plain sum, and the derivative's
    # bound over boxes near and far contains its sampled values.
    declared = [gm.gaussian_segment_element([float(i), 0, 0], [i + 0.5, 0, 0], 0.2, 0.3) for i in range(20)]
    assert declared[0].taper == pytest.approx(0.2) and declared[0].radius == 0.3
    point = np.array([0.25, 0.1, 0.0])
    plain = sum(gm.Tape(gm.segment_convolution([float(i), 0, 0], [i + 0.5, 0, 0], 0.2, 0.3), 3)(point)[0]
                for i in range(20))
    rng = np.random.default_rng(7)
    for hierarchy in (True, False):
        culled = gm.culled_field(declared, hierarchy=hierarchy)
        assert gm.Tape(culled, 3)(point)[0] == pytest.approx(plain, rel=1e-12)
        d0 = gm.derivative(culled, 0)
        for box in (np.array([[3.6, 4.1], [0.45, 0.9], [-0.2, 0.2]]), np.array([[2.0, 2.4], [1.0, 1.3], [0.0, 0.3]])):
            lo, hi = d0.bound(box)[0]
            values = gm.Tape(d0, 3)(box[:, 0] + (box[:, 1] - box[:, 0]) * rng.random((400, 3)))[:, 0]
            assert lo <= values.min() and values.max() <= hi
    blob = gm.grouped_blend([gm.point_source([0, 0, 0], 0.5), gm.point_source([0.6, 0, 0], 0.5)], [[1], [0]])
    assert gm.Tape(blob, 3)(np.array([0.3, 0.0, 0.0]))[0] < 0  # blended: inside between the two
