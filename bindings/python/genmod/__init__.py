"""genmod: generative modeling with interval arithmetic.

A shape is a function built from the parametric coordinates x(i) with Python's operators and
the functions of this module; every function has point values, a symbolic derivative and an
interval enclosure.

    import numpy as np
    import genmod as gm
    circle = gm.sqrt(gm.x(0) ** 2 + gm.x(1) ** 2) - 0.5   # an implicit disk: inside where < 0
    circle(np.array([[0.3, 0.4]]))                     # [[0.]]
    circle.bound(np.array([[0, 1], [0, 1]]))           # [[-0.5, 0.9142...]]
    gm.derivative(circle, 0)
"""
from ._genmod import *  # noqa: F401,F403
from ._genmod import Fn, Mesh, Tape, x  # noqa: F401
from . import batch, gallery, procedural  # noqa: F401
