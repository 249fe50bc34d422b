// Memory estimate of lattice meshes (see mesh_memory.hpp).
#include "mesh_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

namespace genmod::app {

namespace {

// Saturating arithmetic: a huge --res must give a huge estimate, not a wrapped small one.
std::size_t mul(std::size_t a, std::size_t b) {
  if (a != 0 && b > std::numeric_limits<std::size_t>::max() / a) return std::numeric_limits<std::size_t>::max();
  return a * b;
}
std::size_t add(std::size_t a, std::size_t b) {
  return b > std::numeric_limits<std::size_t>::max() - a ? std::numeric_limits<std::size_t>::max() : a + b;
}

constexpr std::size_t kVertexBytes = sizeof(std::array<double, 3>);
constexpr std::size_t kTriangleBytes = sizeof(std::array<std::uint32_t, 3>);

}  // namespace

std::size_t lattice_mesh_bytes(const models::Model& model, std::size_t patches, std::size_t n) {
  const std::size_t faces = model.solid ? 6 : (patches == 0 ? 1 : patches);
  const std::size_t points = mul(n + 1, n + 1), samples = mul(n, n);
  // One patch at a time: the full-lattice tables of its three components, the gathered
  // result (three doubles a point), its vertices and two triangles per cell.
  const std::size_t evaluation = mul(2 * 3 * sizeof(double), points);
  const std::size_t patch_mesh = add(mul(kVertexBytes, samples), mul(2 * kTriangleBytes, samples));
  std::size_t bytes = add(evaluation, patch_mesh);
  // The object's mesh holds every patch (measured: circular_beam at --res 2048 peaks at
  // 1.49 GB, this says 1.61 GB; torus at 2048 0.31 GB, this 0.40 GB).
  if (faces > 1) bytes = add(bytes, mul(faces, patch_mesh));
  return bytes;
}

std::size_t default_mesh_memory_limit() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  std::size_t limit = pages <= 0 || page <= 0 ? std::size_t{8} << 30  // unknown: 8 GiB
                                              : mul(static_cast<std::size_t>(pages), static_cast<std::size_t>(page)) / 2;
  // An address-space limit (ulimit -v) below that ends in std::bad_alloc just the same.
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    limit = std::min<std::size_t>(limit, static_cast<std::size_t>(as.rlim_cur) / 2);
  return limit;
}

}  // namespace genmod::app
