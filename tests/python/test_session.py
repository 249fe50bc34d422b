"""A user's session from Python, end to end: a filleted CSG part is built, a ray is shot at it,
points are classified and measured against parametric surfaces, systems are solved and
minimized with certified answers, and the part is meshed and validated. Each answer is checked
against what is known in closed form or by dense sampling, so a lost solution fails."""
import math

import numpy as np
import pytest

import genmod as gm

X, Y, Z = gm.x(0), gm.x(1), gm.x(2)


def filleted_part():
    """A slab with a post on it, joined by a smooth fillet of radius 0.15, with a hole drilled
    through the slab beside the post: an L-shaped solid with a blended inner edge."""
    upright = gm.rotate_x(math.pi / 2)  # turns the cylinders' z axis to y
    slab = gm.implicit_box(gm.cat([1.0, 0.25, 0.6]))
    post = gm.transform_implicit(gm.implicit_cylinder(0.3, 0.6), upright)
    post = gm.translate_implicit(post, gm.cat([-0.4, 0.8, 0.0]))  # y from 0.2 to 1.4
    hole = gm.transform_implicit(gm.implicit_cylinder(0.15, 1.0), upright)
    hole = gm.translate_implicit(hole, gm.cat([0.5, 0.0, 0.0]))
    return gm.csg_difference(gm.smooth_union(slab, post, 0.15), hole)


def test_ray_hits_the_part_first_where_sampling_says():
    f = filleted_part()
    tape = gm.Tape(f, 3)
    rng = np.random.default_rng(3)
    for _ in range(20):
        origin = np.array([rng.uniform(-0.9, 0.9), 3.0, rng.uniform(-0.5, 0.5)])
        direction = np.array([0.0, -1.0, 0.0])
        hit = gm.ray_hit_implicit(f, origin, direction, 6.0, epsilon=1e-10)
        assert hit.complete
        # Dense samples along the ray: the first sign change is inside the reported bracket.
        t = np.linspace(0.0, 6.0, 60001)
        values = tape(origin + t[:, None] * direction)[:, 0]
        inside = np.nonzero(values <= 0)[0]
        if len(inside) == 0:
            assert not hit.hit
            continue
        assert hit.hit
        first = t[inside[0]]
        assert hit.t[0] <= first + 1e-12 and hit.t[0] >= first - 6.0 / 60000 - 1e-9
        assert hit.t[1] - hit.t[0] <= 1e-6
        # The hit point is on the surface.
        point = origin + hit.t.mean() * direction
        assert abs(tape(point)[0]) <= 1e-5


def test_points_are_classified_and_measured_against_a_torus():
    R, r = 1.0, 0.3
    torus = gm.torus_surface(R, r)
    rng = np.random.default_rng(5)
    for _ in range(8):
        p = rng.uniform(-1.5, 1.5, size=3)
        p[2] *= 0.5
        exact = math.hypot(math.hypot(p[0], p[1]) - R, p[2]) - r  # signed distance
        if abs(exact) < 1e-3:
            continue
        near = gm.closest_point(torus, p, epsilon=1e-7)
        assert near.complete
        assert near.distance[0] <= abs(exact) + 1e-9 <= near.distance[1] + 2e-9
        assert np.linalg.norm(near.point - p) <= near.distance[1] + 1e-9
        assert near.candidates.shape[1:] == (2, 2)
        where = gm.classify_point(torus, p)
        assert where.where == ("inside" if exact < 0 else "outside")


def test_a_system_is_solved_with_every_root_certified():
    # x^2 + y^2 = 1 and y = x^3 - x / 2 meet where x^2 + (x^3 - x/2)^2 = 1: two real roots.
    c = (X ** 2 + Y ** 2 == 1.0) & (Y == X ** 3 - 0.5 * X)
    result = gm.solve(c, [0, 1], np.array([[-2.0, 2.0], [-2.0, 2.0]]), epsilon=1e-10)
    assert result.complete and result.limit == "none"
    roots = [z.real for z in np.roots([1, 0, -1, 0, 1.25, 0, -1]) if abs(z.imag) < 1e-12]
    assert result.unique_components == len(roots) == 2
    for xr in roots:
        yr = xr ** 3 - 0.5 * xr
        holding = [k for k in range(len(result)) if np.all(result.boxes[k, :, 0] <= [xr + 1e-12, yr + 1e-12])
                   and np.all([xr - 1e-12, yr - 1e-12] <= result.boxes[k, :, 1])]
        assert holding, f"the root ({xr}, {yr}) is in no returned box"
    assert set(result.status) <= {"certified_unique", "possible"}
    # A limit is reported, never silent: the unexplored boxes still cover the roots.
    cut = gm.solve(c, [0, 1], np.array([[-2.0, 2.0], [-2.0, 2.0]]), epsilon=1e-10, max_boxes=5)
    assert not cut.complete and cut.limit == "max_boxes" and "unexplored" in cut.status


def test_the_closest_point_of_the_part_by_constrained_minimization():
    # The point of the slab's top face nearest to q: minimize |p - q|^2 subject to y = 0.25,
    # inside the slab's top rectangle.
    q = (0.3, 1.0, 0.2)
    objective = (X - q[0]) ** 2 + (Y - q[1]) ** 2 + (Z - q[2]) ** 2
    box = np.array([[-1.0, 1.0], [0.25, 0.25], [-0.6, 0.6]])
    result = gm.minimize(objective, [0, 1, 2], box, epsilon=1e-6, delta=1e-9)
    assert result.complete and result.feasible_found
    assert result.minimum[0] <= 0.75 ** 2 <= result.minimum[1]
    assert np.allclose(result.best_point, [0.3, 0.25, 0.2], atol=1e-3)
    with pytest.raises(ValueError, match="not among the unknowns"):
        gm.minimize(objective, [0, 1], box)
    # Two threads bound the halves of each split at once: the same answer, bitwise.
    two = gm.minimize(objective, [0, 1, 2], box, epsilon=1e-6, delta=1e-9, threads=2)
    assert np.array_equal(two.minimum, result.minimum)
    assert np.array_equal(two.best_point, result.best_point)
    assert np.array_equal(two.candidates, result.candidates)


def test_curves_meet_where_expected():
    circle = gm.cat([gm.cos(2 * math.pi * X), gm.sin(2 * math.pi * X)])
    line = gm.cat([2.0 * X - 1.0, gm.Fn(0.5)])
    hits = gm.curve_intersections(circle, line)
    assert len(hits) == 2 and hits.complete and hits.certified.all()
    assert np.allclose(np.sort(hits.points[:, 0]), [-math.sqrt(3) / 2, math.sqrt(3) / 2], atol=1e-8)


def test_the_part_meshes_valid_within_its_tolerance():
    f = filleted_part()
    box = np.array([[-1.2, 1.2], [-0.4, 1.6], [-0.8, 0.8]])
    mesh, stats = gm.mesh_implicit(f, box, min_feature=0.01, tolerance=0.002)
    report = mesh.validate()
    assert report["valid"], report["description"]
    assert report["euler_characteristic"] == 0  # one hole through the part: genus 1
    assert stats["limits_hit"] == []
    assert stats["max_vertex_error"] <= 0.002 and stats["uncertified_vertices"] == 0
    # f is 1-Lipschitz (exact distances joined by min, max and the smooth minimum), so a vertex
    # within 0.002 of the surface has |f| <= 0.002.
    values = gm.Tape(f, 3)(mesh.vertices)[:, 0]
    assert np.abs(values).max() <= 0.002 + 1e-12
    png = mesh.png(256)
    assert png[:4] == b"\x89PNG"


def test_skeletal_fields_compose_with_the_language():
    arm = gm.distance_surface([gm.distance2_to_segment([0, 0, 0], [1, 0, 0])], [0.2])
    assert gm.Tape(arm, 3)(np.array([0.5, 0.2, 0.0]))[0] == pytest.approx(0.0, abs=1e-12)
    density = gm.segment_convolution([0, 0, 0], [1, 0, 0], 0.2, 0.2)
    field = gm.density_to_implicit(density)
    values = gm.Tape(field, 3)(np.array([[0.5, 0.0, 0.0], [0.5, 1.0, 0.0]]))[:, 0]
    assert values[0] < 0 < values[1]
    lo = np.array([0.3, 0.1, -0.05])
    box = np.stack([lo, lo + 0.1], axis=1)
    enclosure = field.bound(box)[0]
    samples = gm.Tape(field, 3)(lo + 0.1 * np.random.default_rng(1).random((500, 3)))[:, 0]
    assert enclosure[0] <= samples.min() and samples.max() <= enclosure[1]
    blended = gm.rolling_ball_blend(arm, gm.implicit_sphere(0.3, gm.cat([1.0, 0.0, 0.0])), 0.1)
    assert blended.dim == 1 and blended.inputs == [0, 1, 2]
    m = gm.rotate_z(math.pi / 2) @ gm.translate(1.0, 0.0, 0.0)
    assert m.rows == 4 and m.cols == 4
    moved = gm.transform3d(gm.cat([X, Y, Z]), m)
    assert np.allclose(gm.Tape(moved, 3)(np.array([0.0, 0.0, 0.0])), [0.0, 1.0, 0.0], atol=1e-15)


def test_bad_arguments_are_refused_with_their_names():
    with pytest.raises(ValueError, match="box: row 1 is not an interval"):
        gm.solve(X == Y, [0, 1], np.array([[0.0, 1.0], [1.0, 0.0]]))
    with pytest.raises(ValueError, match="shape \\(n, 2\\)"):
        gm.solve(X == Y, [0, 1], np.array([0.0, 1.0]))
    with pytest.raises(ValueError, match="ray_hit: u is not an interval"):
        gm.ray_hit(gm.sphere_surface(), [2, 0, 0], [-1, 0, 0], 5.0, u=(1.0, 0.0))
    with pytest.raises(ValueError, match="closest_point: p: entry 1 is not finite"):
        gm.closest_point(gm.sphere_surface(), np.array([1.0, np.nan, 0.0]))
    with pytest.raises(ValueError, match="epsilon"):
        gm.solve(X == Y, [0, 1], np.array([[0.0, 1.0], [0.0, 1.0]]), epsilon=0.0)
