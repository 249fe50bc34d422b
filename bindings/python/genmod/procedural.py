"""Morkel's procedural models: registered procedures with typed parameters, each with a
default, called with named arguments and a seed; the same arguments and seed give the same
mesh, and cacheable procedures (the Luggage's legs) are built once per distinct call.

    from genmod import procedural
    [m.name for m in procedural.models()]           # leg, chair, couch, table, luggage, ...
    chair = procedural.mesh("chair", arms=True, backLength=2.0)
    luggage = procedural.mesh("luggage", seed=3, numLegs=12)
    procedural.cache_stats("leg")                    # {'hits': 11, 'misses': 1, ...}

Procedures of your own, in Python, on the same mesh tools:

    reg = procedural.Registry()
    def block(args, ctx):
        m = procedural.PolyMesh.grid_box((0, 0, 0), (1, 1, 1), 4, "block")
        top = procedural.select(m, m.faces(), (0, 1, 0, 1, 1, 1))
        procedural.extrude(m, top, (0, 0, args["height"]))
        return m
    reg.add("block", block, params={"height": 0.5}, cacheable=True)
    mesh = reg.call("block", height=2.0).to_mesh()     # a genmod.Mesh
"""
from dataclasses import dataclass

from . import _genmod
from ._genmod import _procedural as _tools

PolyMesh = _tools.PolyMesh
Registry = _tools.Registry
CallContext = _tools.CallContext
select = _tools.select
extrude = _tools.extrude
sqrt2_subdivide = _tools.sqrt2_subdivide
shape_to_curve = _tools.shape_to_curve
bridge = _tools.bridge
stitch = _tools.stitch


@dataclass(frozen=True)
class Parameter:
    """A procedure parameter: its name, type, default value and what it does."""
    name: str
    type: str  # "Double", "Integer", "Boolean", "String" or "Vector" (the thesis's Java types)
    default: object
    doc: str


@dataclass(frozen=True)
class Model:
    """A procedural model: its name, description, signature, parameters and whether it is cacheable."""
    name: str
    description: str
    signature: str  # the thesis's signature string, e.g. "OUT:Double,height:Integer,numLegs"
    parameters: tuple
    cacheable: bool


def models():
    """Every procedural model, in the gallery's order."""
    return [Model(name, doc, sig, tuple(Parameter(*p) for p in params), cacheable)
            for name, doc, sig, params, cacheable in _genmod._procedural_models()]


def mesh(name, seed=0, lod=0, camera=None, **params):
    """The model's triangle mesh (z up) with the given parameters (the others keep their
    defaults). lod is the level of detail, a refinement offset: 0 as the parameters say, below 0
    coarser for the models that use it (the tree drops branch orders, the human, chair, couch,
    round table and luggage sqrt(2) rounds). camera, a pair (eye, target) of points in the
    mesh's z-up frame, chooses the lod instead from the model's bounding box on screen (see
    view); a model out of its view gives an empty mesh. ValueError names the procedure and the
    parameter of a bad value, or the camera's problem."""
    if camera is None:
        return _genmod._mesh_procedural(name, params, int(seed), int(lod))
    if lod != 0:
        raise ValueError("procedural.mesh: give lod or camera, not both (the camera chooses the lod)")
    eye, target = _camera_points(camera)
    return _genmod._mesh_procedural_camera(name, params, int(seed), eye, target)


def view(name, camera, **params):
    """How a camera (eye, target), +z up and 640 x 480 pixels, sees the model's bounding box:
    {'visible': bool, 'lod': int, 'pixels': float}, the lod mesh(camera=...) builds at; None for
    a model that declares no bounds (the camera neither culls it nor sets its lod)."""
    eye, target = _camera_points(camera)
    return _genmod._procedural_view(name, params, eye, target)


def _camera_points(camera):
    try:
        eye, target = camera
        eye, target = tuple(float(x) for x in eye), tuple(float(x) for x in target)
    except (TypeError, ValueError):
        raise ValueError(f"camera must be a pair (eye, target) of 3-D points, got {camera!r}") from None
    if len(eye) != 3 or len(target) != 3:
        raise ValueError(f"camera must be a pair (eye, target) of 3-D points, got {camera!r}")
    return eye, target


def cache_stats(name):
    """Hits, misses, evictions and entries of a procedure's cache."""
    return _genmod._procedural_cache(name)


def set_caching(on):
    """Switches every procedure cache on or off (the meshes are the same either way)."""
    _genmod._set_procedural_caching(bool(on))


def caching():
    """Whether the procedure caches are on."""
    return _genmod._procedural_caching()


def clear_caches():
    """Drops every cached model; the counters stay."""
    _genmod._clear_procedural_caches()


def reset_cache_stats(name):
    """Sets a procedure's hit, miss and eviction counters back to zero."""
    _genmod._reset_procedural_cache_stats(name)
