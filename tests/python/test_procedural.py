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
