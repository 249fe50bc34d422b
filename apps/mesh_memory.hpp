// The memory a lattice mesh of a gallery model needs, estimated before anything is allocated,
// so that `genmod mesh NAME --res N` refuses a request the machine cannot hold instead of
// ending in std::bad_alloc.
#pragma once

#include "genmod/models/gallery.hpp"

#include <cstddef>

namespace genmod::app {

// Bytes to mesh `model` at n x n samples per patch (mesh_model's lattice): for each of its
// patches (a solid's six faces, or the surface and its extra patches, model_patches) meshed
// one at a time: the lattice evaluation's full-lattice tables and result (3 x (n + 1)^2
// doubles each, the +1 being a periodic axis's seam copy) and the patch's vertices and
// triangles; plus, for more than one patch, the object's mesh holding them all. `patches`
// is ignored for a solid (six).
std::size_t lattice_mesh_bytes(const models::Model& model, std::size_t patches, std::size_t n);

// Half the physical memory (sysconf), or half the address-space limit (ulimit -v) if that is
// lower: the default limit of `genmod mesh --max-memory`.
std::size_t default_mesh_memory_limit();

// Peak bytes per kd-tree leaf of the adaptive mesher (leaves, sample points, triangles, the
// mesh), measured on the gallery: `--max-memory` becomes a leaf limit with it.
constexpr double kAdaptiveBytesPerLeaf = 600.0;

}  // namespace genmod::app
