// The procedural layer's public API (Morkel): polygon meshes with labels, procedures, seeds and
// caching, and the mesh tools.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/bezier_curve.hpp"
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/stitching.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"
#include "genmod/procedural/procedure_layer.hpp"
