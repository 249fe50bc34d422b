// The public API of the tessellate layer.
#pragma once

#include "genmod/tessellate/batch.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/image.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/kd_tree.hpp"
#include "genmod/tessellate/lattice.hpp"
#include "genmod/tessellate/mesh.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/preview.hpp"
#include "genmod/tessellate/raster2d.hpp"
#include "genmod/tessellate/validate.hpp"
