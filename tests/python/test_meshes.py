"""Meshes from Python: the gallery builds and meshes models, the implicit mesher meshes a
function, and the results are checked by the validator, written, read back and previewed."""
import numpy as np
import pytest

import genmod as gm
from genmod import gallery


def test_gallery_lists_builds_and_meshes_models():
    names = {m.name: m for m in gallery.models()}
    assert "doorknob" in names and names["doorknob"].kind == "parametric"
    assert any(m.kind == "implicit" for m in names.values())
    knob = gallery.build("doorknob")
    assert knob.dim == 3 and knob.inputs == [0, 1]
    mesh, info = gallery.mesh("doorknob")
    report = mesh.validate()
    assert report["valid"], report["description"]
    assert info["closed"] and info["distance_bound"] <= info["tolerance"]
    # Surface samples lie within the certified bound of the mesh's vertices' hull scale.
    assert mesh.vertices.shape[1] == 3 and mesh.triangles.max() < len(mesh.vertices)
    with pytest.raises(ValueError, match="no_such_model"):
        gallery.build("no_such_model")


def test_gallery_lists_and_meshes_the_csg_models():
    names = {m.name: m for m in gallery.models()}
    assert names["drilled_sphere"].kind == "csg" and names["drilled_sphere_twice"].kind == "csg"
    mesh, info = gallery.mesh("drilled_sphere")
    report = mesh.validate()
    assert report["valid"], report["description"]
    assert report["euler_characteristic"] == 0  # genus 1: the bore goes through
    assert info["curve_complete"] and info["seam_vertices"] > 0 and info["tolerance"] == 0.05
    with pytest.raises(ValueError, match="not one function"):
        gallery.build("drilled_sphere")
    with pytest.raises(ValueError, match="no parameters"):
        gallery.mesh("drilled_sphere", radius=0.2)


def test_gallery_lists_and_meshes_the_region_models():
    leaf = {m.name: m for m in gallery.models()}["maple_leaf"]
    assert leaf.kind == "regions" and leaf.open and leaf.parameters[0].name == "vein_radius"
    mesh, info = gallery.mesh("maple_leaf", tolerance=0.04, vein_radius=0.05)
    assert set(info["sheets"]) == {"vein | beyond the blade", "vein | below", "vein | above", "below | above"}
    assert sum(info["sheets"].values()) == len(mesh.triangles) and not info["limits_hit"]
    report = mesh.validate()
    assert not report["manifold"] and report["degenerate_triangles"] == 0  # the blade meets the veins
    with pytest.raises(ValueError, match="not one"):
        gallery.build("maple_leaf")
    with pytest.raises(ValueError, match="vein_radius"):
        gallery.mesh("maple_leaf", vein_radius=0.5)


def test_implicit_mesh_is_valid_and_round_trips_through_a_file(tmp_path):
    x, y, z = gm.x(0), gm.x(1), gm.x(2)
    torus = (gm.sqrt(x ** 2 + y ** 2) - 1.0) ** 2 + z ** 2 - 0.09
    box = np.array([[-1.5, 1.5], [-1.5, 1.5], [-0.5, 0.5]])
    mesh, stats = gm.mesh_implicit(torus, box, min_feature=0.05)
    report = mesh.validate()
    assert report["valid"], report["description"]
    assert report["euler_characteristic"] == 0  # a torus
    assert stats["limits_hit"] == []
    # Vertices are on the surface within the mesher's certified bound.
    values = gm.Tape(torus, 3)(mesh.vertices)[:, 0]
    gradient = np.stack([gm.Tape(gm.derivative(torus, i), 3)(mesh.vertices)[:, 0] for i in range(3)], axis=1)
    distance = np.abs(values) / np.linalg.norm(gradient, axis=1)
    assert distance.max() <= 0.05
    path = tmp_path / "torus.ply"
    mesh.write(str(path))
    back = gm.read_mesh(str(path))
    assert np.array_equal(back.vertices, mesh.vertices) and np.array_equal(back.triangles, mesh.triangles)
    png = mesh._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000


def test_meshes_from_arrays_are_checked():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    report = gm.Mesh(v, t).validate()
    assert report["valid"] and report["volume"] == pytest.approx(1 / 6)
    assert not gm.Mesh(v, t[:3]).validate()["closed"]
    with pytest.raises(ValueError, match="names vertex 7"):
        gm.Mesh(v, np.array([[0, 1, 7]]))
    with pytest.raises(RuntimeError):
        gm.Mesh(v, t).write("/nonexistent-dir/x.obj")


def test_continuation_polygonizer_meshes_the_piece_of_the_start():
    x, y, z = gm.x(0), gm.x(1), gm.x(2)
    two = gm.min(gm.sqrt((x + 2.0) ** 2 + y ** 2 + z ** 2), gm.sqrt((x - 2.0) ** 2 + y ** 2 + z ** 2)) - 1.0
    mesh, stats = gm.polygonize_continuation(two, 0.1, starts=np.array([[-1.0, 0.0, 0.0]]))
    report = mesh.validate()
    assert report["valid"], report["description"]
    assert report["euler_characteristic"] == 2 and report["components"] == 1
    assert (mesh.vertices[:, 0] < -0.9).all()  # the sphere at x = -2 only
    assert stats["normals"].shape == mesh.vertices.shape and stats["limits_hit"] == []
    both, _ = gm.polygonize_continuation(two, 0.1, starts=np.array([[-1.0, 0, 0], [1.0, 0, 0]]), cubes=True)
    assert both.validate()["components"] == 2
    # The same mesh on one thread and on two.
    one, _ = gm.polygonize_continuation(two, 0.1, starts=np.array([[-1.0, 0.0, 0.0]]), threads=1)
    pair, _ = gm.polygonize_continuation(two, 0.1, starts=np.array([[-1.0, 0.0, 0.0]]), threads=2)
    assert np.array_equal(one.vertices, pair.vertices) and np.array_equal(one.triangles, pair.triangles)
    with pytest.raises(ValueError, match="cube_size"):
        gm.polygonize_continuation(two, 0.0, starts=np.array([[-1.0, 0, 0]]))
    with pytest.raises(RuntimeError, match="not near the surface"):
        gm.polygonize_continuation(two, 0.1, starts=np.array([[10.0, 0, 0]]))


def test_polygonize_regions_meshes_a_ball_cut_by_a_plane():
    x, y, z = gm.x(0), gm.x(1), gm.x(2)
    d = 0.7 - gm.sqrt(x ** 2 + y ** 2 + z ** 2)
    box = np.array([[-0.93, 0.93]] * 3)
    mesh, pairs, stats = gm.polygonize_regions([gm.min(d, z), gm.min(d, -z), -d], 0.1, box)
    assert pairs.shape == (len(mesh.triangles), 2) and pairs.dtype == np.int32
    assert {tuple(p) for p in pairs} == {(0, 1), (0, 2), (1, 2)}
    assert stats["limits_hit"] == [] and stats["face_vertex_fallbacks"] == 0
    one, pairs1, _ = gm.polygonize_regions([gm.min(d, z), gm.min(d, -z), -d], 0.1, box, threads=1)
    assert np.array_equal(one.vertices, mesh.vertices) and np.array_equal(pairs1, pairs)
    # Edges of degree 3 exactly where the three sheets meet: on the circle r = 0.7, z = 0.
    edges = np.sort(mesh.triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    unique, degree = np.unique(edges, axis=0, return_counts=True)
    assert set(degree) == {2, 3}
    junction = mesh.vertices[np.unique(unique[degree == 3])]
    rho = np.hypot(junction[:, 0], junction[:, 1])
    assert np.abs(junction[:, 2]).max() < 0.01 and np.abs(rho - 0.7).max() < 0.01
    assert (stats["vertex_kinds"][np.unique(unique[degree == 3])] > 0).all()  # face or internal
    # Two regions: the closed sphere, valid, with normals from region 0 (inside) to 1.
    sphere, pairs2, _ = gm.polygonize_regions([d, -d], 0.1, box, interest=[(0, 1)])
    report = sphere.validate()
    assert report["valid"], report["description"]
    assert (pairs2 == [0, 1]).all()
    # Split per sheet: the junction vertices three times, each copy with its sheet's normal.
    split, pairs3, extra = gm.polygonize_regions([gm.min(d, z), gm.min(d, -z), -d], 0.1, box, split=True)
    assert (pairs3 == pairs).all() and len(split.triangles) == len(mesh.triangles)
    assert extra["normals"].shape == split.vertices.shape == (len(extra["origin"]), 3)
    counts = np.bincount(extra["origin"])
    assert set(counts) == {1, 3}
    disc = (extra["vertex_pairs"] == [0, 1]).all(axis=1) & (np.hypot(split.vertices[:, 0], split.vertices[:, 1]) < 0.6)
    assert disc.sum() > 10 and np.allclose(extra["normals"][disc], [0, 0, -1])
    with pytest.raises(ValueError, match="at least two region functions"):
        gm.polygonize_regions([d], 0.1, box)
    with pytest.raises(ValueError, match="cube_size"):
        gm.polygonize_regions([d, -d], -1.0, box)
    with pytest.raises(ValueError, match="must be scalar"):
        gm.polygonize_regions([d, gm.cat([x, y])], 0.1, box)
