// Umbrella header: the whole public API of genmod (kernel, operators, solvers, tessellation
// and the model gallery).
#pragma once

#include "genmod/kernel/kernel.hpp"
#include "genmod/operators/operators.hpp"
#include "genmod/solvers/solvers.hpp"
#include "genmod/tessellate/tessellate.hpp"
#include "genmod/procedural/procedural.hpp"
#include "genmod/models/gallery.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/models/procedural_models.hpp"
