// Parametric surface meshing on a lattice (see mesh.hpp); file I/O is in mesh_io.cpp.
#include "genmod/tessellate/mesh.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

namespace {

void check_axis(const LatticeAxis& a, bool periodic, const char* name) {
  const std::size_t min_samples = periodic ? 3 : 2;
  if (a.samples < min_samples)
    throw std::invalid_argument(std::string("genmod: mesh_parametric: axis ") + name + " needs at least " +
                                std::to_string(min_samples) + " samples" + (periodic ? " when periodic" : "") +
                                ", got " + std::to_string(a.samples));
}

}  // namespace

Mesh mesh_parametric(const Fn& surface, const LatticeAxis& u, const LatticeAxis& v,
                     const ParametricMeshOptions& options) {
  if (surface.dim() != 3)
    throw std::invalid_argument("genmod: mesh_parametric: the surface must have dimension 3, got " +
                                std::to_string(surface.dim()));
  check_axis(u, options.periodic_u, "u");
  check_axis(v, options.periodic_v, "v");
  const std::size_t nu = u.samples, nv = v.samples;
  if (nu * nv > 0xffffffffu) throw std::invalid_argument("genmod: mesh_parametric: too many vertices");
  // A periodic axis samples one more point (the seam copy of the first) and drops it.
  LatticeAxis lu = u, lv = v;
  if (options.periodic_u) lu.samples = nu + 1;
  if (options.periodic_v) lv.samples = nv + 1;
  const Lattice lattice({lu, lv});
  const std::vector<double> xyz = evaluate_lattice(surface, lattice, options.method);

  Mesh mesh;
  mesh.vertices.reserve(nu * nv);
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) {
      const std::size_t p = i + lu.samples * j;
      mesh.vertices.push_back({xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]});
    }
  const std::size_t qu = options.periodic_u ? nu : nu - 1;
  const std::size_t qv = options.periodic_v ? nv : nv - 1;
  mesh.triangles.reserve(2 * qu * qv);
  auto id = [nu](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>(i + nu * j); };
  for (std::size_t j = 0; j < qv; ++j)
    for (std::size_t i = 0; i < qu; ++i) {
      const std::size_t i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      mesh.triangles.push_back({id(i, j), id(i1, j), id(i1, j1)});
      mesh.triangles.push_back({id(i, j), id(i1, j1), id(i, j1)});
    }
  return mesh;
}

}  // namespace genmod
