// The procedural layer's public API (Morkel): polygon meshes with labels, procedures, seeds and
// caching, and the mesh tools.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"
#include "genmod/procedural/procedure_layer.hpp"
