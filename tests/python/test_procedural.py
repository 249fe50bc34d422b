"""Morkel's procedural models from Python: listed with typed parameters and signatures, meshed
closed and valid, reproducible from their arguments and seed, cached as the thesis says (a
Luggage on N legs builds its leg once), and bad values refused with the procedure's and the
parameter's names."""
import numpy as np
import pytest

from genmod import procedural


def test_models_are_listed_with_typed_parameters():
    models = {m.name: m for m in procedural.models()}
    assert {"chair", "couch", "table", "luggage", "leg"} <= set(models)
    luggage = models["luggage"]
    kinds = {p.name: (p.type, p.default) for p in luggage.parameters}
    assert kinds["numLegs"] == ("Integer", 4) and kinds["height"][0] == "Double"
    assert "numLegs" in luggage.signature and models["leg"].cacheable


def test_models_mesh_valid_and_reproducibly():
    for name, params in (("chair", {"arms": True}), ("table", {}), ("luggage", {"numLegs": 6})):
        mesh = procedural.mesh(name, seed=5, **params)
        report = mesh.validate()
        assert report["valid"], (name, report["description"])
        again = procedural.mesh(name, seed=5, **params)
        assert mesh.vertices.tobytes() == again.vertices.tobytes()
        assert mesh.triangles.tobytes() == again.triangles.tobytes()
    taller = procedural.mesh("chair", backLength=3.0).vertices[:, 2].max()
    assert taller > procedural.mesh("chair", backLength=2.0).vertices[:, 2].max()


def test_a_lower_level_of_detail_is_coarser_and_still_valid():
    # The tree drops one order of branches per level (7 branches at levels 5 + lod -2), the human
    # one subdivision level; lod 0 is the default mesh.
    tree = procedural.mesh("tree", lod=-2)
    assert len(tree.triangles) == 7 * 44 and tree.validate()["valid"]
    assert procedural.mesh("tree", lod=0).triangles.tobytes() == procedural.mesh("tree").triangles.tobytes()
    coarse, fine = procedural.mesh("human", lod=-1), procedural.mesh("human")
    assert len(coarse.triangles) < len(fine.triangles) and coarse.validate()["valid"]


def test_a_camera_chooses_the_level_of_detail():
    # In front of the chair (its front faces -y, z up): near, the lod 0 chair; far, a coarser one
    # at the lod view() reports; turned away, nothing.
    near = procedural.view("chair", ((1, -6, 1), (1, -1, 0.5)))
    assert near["visible"] and near["lod"] == 0
    seen = procedural.mesh("chair", camera=((1, -6, 1), (1, -1, 0.5)))
    assert seen.triangles.tobytes() == procedural.mesh("chair").triangles.tobytes()
    far = procedural.view("luggage", ((0.5, -200, 1), (0.5, -1, 1)))
    assert far["visible"] and far["lod"] < 0
    coarse = procedural.mesh("luggage", camera=((0.5, -200, 1), (0.5, -1, 1)))
    assert coarse.triangles.tobytes() == procedural.mesh("luggage", lod=far["lod"]).triangles.tobytes()
    assert len(coarse.triangles) < len(procedural.mesh("luggage").triangles) and coarse.validate()["valid"]
    away = ((1, -6, 1), (1, -12, 1))
    assert not procedural.view("chair", away)["visible"]
    assert len(procedural.mesh("chair", camera=away).triangles) == 0
    assert procedural.view("leg", away) is None
    with pytest.raises(ValueError, match="same point"):
        procedural.mesh("chair", camera=((1, 2, 3), (1, 2, 3)))
    with pytest.raises(ValueError, match="vertical"):
        procedural.view("chair", ((1, 2, 3), (1, 2, 0)))
    with pytest.raises(ValueError, match="pair"):
        procedural.mesh("chair", camera=(1, 2, 3))
    with pytest.raises(ValueError, match="not both"):
        procedural.mesh("chair", lod=-1, camera=away)


def test_the_luggage_builds_its_leg_once():
    procedural.set_caching(True)
    procedural.clear_caches()
    procedural.reset_cache_stats("leg")
    cached = procedural.mesh("luggage", numLegs=12)
    assert procedural.cache_stats("leg")["misses"] == 1 and procedural.cache_stats("leg")["hits"] == 11
    procedural.set_caching(False)
    try:
        plain = procedural.mesh("luggage", numLegs=12)
    finally:
        procedural.set_caching(True)
    assert np.array_equal(cached.vertices, plain.vertices) and np.array_equal(cached.triangles, plain.triangles)


def test_bad_values_name_the_procedure_and_the_parameter():
    with pytest.raises(ValueError, match="'chair'.*'length'"):
        procedural.mesh("chair", length=-1.0)
    with pytest.raises(ValueError, match="'chair'.*'no_such'"):
        procedural.mesh("chair", no_such=1.0)
    with pytest.raises(ValueError, match="'luggage'.*'numLegs'"):
        procedural.mesh("luggage", numLegs="four")
    with pytest.raises(ValueError, match="no procedural model named 'sofa'"):
        procedural.mesh("sofa")


def test_procedures_written_in_python_use_the_mesh_tools_and_the_cache():
    reg = procedural.Registry()
    built = []

    def post(args, ctx):
        built.append(args["height"])
        m = procedural.PolyMesh.grid_box((0, 0, 0), (0.2, 0.2, 0.2), 2, "post")
        top = procedural.select(m, m.faces(), (0, 1, 0, 1, 1, 1))
        procedural.extrude(m, top, (0, 0, args["height"]))
        return m

    def table(args, ctx):
        m = procedural.PolyMesh.grid_box((0, 0, 0), (2, 1, 0.1), 4, "top")
        legs = args["legs"]
        posts = [ctx.call("post", height=args["leg_height"]) for _ in range(legs)]
        assert all(p.is_closed_manifold() for p in posts) and ctx.seed == 7
        bottom = procedural.select(m, m.faces(), (0, 1, 0, 1, 0, 0))
        procedural.sqrt2_subdivide(m, bottom, 1, 0.0)
        return m

    reg.add("post", post, params={"height": 0.5}, cacheable=True)
    reg.add("table", table, params={"legs": 4, "leg_height": 0.7})
    assert reg.signature("table") == "OUT:Integer,legs:Double,leg_height"
    t = reg.call("table", seed=7, legs=6)
    assert t.is_closed_manifold() and t.to_mesh().validate()["valid"]
    assert built == [0.7]  # one post built, five served from the cache
    assert reg.cache_stats("post") == {"hits": 5, "misses": 1, "evictions": 0, "entries": 1}
    # A post straight from the registry: extruding the 4 top quads of a closed box adds
    # (+b, +2b, +b) to (V, E, F) for the b = 8 boundary edges of the selection.
    p = reg.call("post")
    v0, e0, f0 = procedural.PolyMesh.grid_box((0, 0, 0), (0.2, 0.2, 0.2), 2).counts
    assert p.counts == (v0 + 8, e0 + 16, f0 + 8)
    with pytest.raises(ValueError, match="'table'.*'legs'"):
        reg.call("table", legs=2.5)
    with pytest.raises(ValueError, match="'table'.*'color'"):
        reg.call("table", color="red")
    with pytest.raises(ValueError, match="not in the mesh"):
        procedural.extrude(p, [10_000], (0, 0, 1))
