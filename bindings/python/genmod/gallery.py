"""The model gallery: the parametric and implicit models of the three sources, with their
parameters, as genmod functions and meshes.

    from genmod import gallery
    [m.name for m in gallery.models()]
    f = gallery.build("doorknob")                  # an Fn of (u, v)
    mesh, info = gallery.mesh("doorknob")          # adaptive; info["distance_bound"]
"""
from dataclasses import dataclass

from . import _genmod


@dataclass(frozen=True)
class Parameter:
    """A model parameter: its name, default value and what it does."""
    name: str
    default: float
    doc: str


@dataclass(frozen=True)
class Model:
    """A gallery model: its name, kind, description, parameters and whether it is open."""
    name: str
    kind: str  # "parametric" (a surface or solid of x(0), x(1), x(2)), "implicit" (f < 0 inside)
    # "csg" (a Boolean combination of trimmed parametric surfaces; meshed, not built) or
    # "regions" (several regions whose boundaries form a non-manifold surface; meshed, not built)
    description: str
    parameters: tuple
    open: bool  # its mesh has a boundary (a sheet, a fillet piece)


def models():
    """Every model, in the gallery's order."""
    return [Model(name, kind, doc, tuple(Parameter(*p) for p in params), is_open)
            for name, kind, doc, params, is_open in _genmod._gallery_models()]


def build(name, **params):
    """The model's function with the given parameters (the others keep their defaults).

    ValueError names an unknown model (and lists the known ones) or a bad parameter."""
    return _genmod._build_model(name, {k: float(v) for k, v in params.items()})


def mesh(name, tolerance=0.0, max_seconds=120.0, threads=0, **params):
    """Meshes the model: parametric models adaptively within `tolerance` (default 1e-3 of the
    model's size), implicit ones with the octree mesher, CSG models by Algorithm 5.4 with
    `tolerance` the sampling box width (default 0.05; `max_seconds` bounds their intersection
    curve), region models by the non-manifold polygonizer with `tolerance` the cube edge
    (default the model's; info["sheets"] counts the triangles between each pair of regions).
    Returns (Mesh, info)."""
    return _genmod._mesh_model(name, {k: float(v) for k, v in params.items()}, float(tolerance),
                               float(max_seconds), int(threads))
