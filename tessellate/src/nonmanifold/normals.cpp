// Normals per region pair (§5.7.6): f_reg is integer-valued and has no gradient, so each
// sheet's normal is that of the continuous difference of the two region functions.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"

#include <cmath>
#include <stdexcept>

namespace genmod {

std::vector<std::array<double, 3>> region_pair_normals(std::span<const Fn> regions, const Mesh& split,
                                                       std::span<const std::pair<int, int>> vertex_pairs,
                                                       double step) {
  const std::string where = "genmod: region_pair_normals: ";
  if (vertex_pairs.size() != split.vertices.size())
    throw std::invalid_argument(where + "one region pair per vertex is needed, got " +
                                std::to_string(vertex_pairs.size()) + " for " + std::to_string(split.vertices.size()) +
                                " vertices");
  if (!std::isfinite(step) || !(step > 0.0))
    throw std::invalid_argument(where + "step must be finite and positive");
  for (std::size_t i = 0; i < regions.size(); ++i)
    if (regions[i].dim() != 1)
      throw std::invalid_argument(where + "region function " + std::to_string(i) + " must be scalar");
  const int k = static_cast<int>(regions.size());
  for (const auto& [a, b] : vertex_pairs)
    if (a < 0 || b < 0 || a >= k || b >= k)
      throw std::invalid_argument(where + "a region pair names a region that does not exist");
  const int xyz[3] = {0, 1, 2};
  const Tape tape(cat(regions), xyz);
  // Six probes per vertex: +-step along each axis.
  const std::size_t n = 6 * split.vertices.size();
  std::vector<double> in[3], out(n * static_cast<std::size_t>(k));
  for (auto& c : in) c.resize(n);
  for (std::size_t v = 0; v < split.vertices.size(); ++v)
    for (int axis = 0; axis < 3; ++axis)
      for (int sign = 0; sign < 2; ++sign) {
        const std::size_t p = 6 * v + 2 * static_cast<std::size_t>(axis) + static_cast<std::size_t>(sign);
        for (int d = 0; d < 3; ++d) in[d][p] = split.vertices[v][d] + (d == axis ? (sign ? step : -step) : 0.0);
      }
  std::vector<double*> outputs(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) outputs[static_cast<std::size_t>(i)] = out.data() + static_cast<std::size_t>(i) * n;
  const double* inputs[3] = {in[0].data(), in[1].data(), in[2].data()};
  BatchEvaluator batch;
  if (n > 0) batch.eval(tape, inputs, n, outputs);
  std::vector<std::array<double, 3>> normals(split.vertices.size());
  for (std::size_t v = 0; v < split.vertices.size(); ++v) {
    const auto [a, b] = vertex_pairs[v];
    std::array<double, 3> g{};
    for (int axis = 0; axis < 3; ++axis) {
      const std::size_t lo = 6 * v + 2 * static_cast<std::size_t>(axis), hi = lo + 1;
      const double diff_hi = outputs[static_cast<std::size_t>(b)][hi] - outputs[static_cast<std::size_t>(a)][hi];
      const double diff_lo = outputs[static_cast<std::size_t>(b)][lo] - outputs[static_cast<std::size_t>(a)][lo];
      g[static_cast<std::size_t>(axis)] = (diff_hi - diff_lo) / (2.0 * step);
    }
    const double len = std::hypot(g[0], g[1], g[2]);
    if (len > 0.0 && std::isfinite(len))
      for (double& c : g) c /= len;
    else
      g = {0.0, 0.0, 0.0};
    normals[v] = g;
  }
  return normals;
}

}  // namespace genmod
