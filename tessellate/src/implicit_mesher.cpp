// mesh_implicit (implicit_mesher.hpp): settings, the octree, rounds of cell meshing and
// re-splitting, and the assembly of the cells' pieces into one indexed mesh.
#include "genmod/tessellate/implicit_mesher.hpp"

#include "implicit/cell_mesher.hpp"
#include "implicit/octree.hpp"
#include "thread_arena.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

constexpr int kXyz[3] = {0, 1, 2};

const Fn& checked_implicit(const Fn& f) {
  if (f.dim() != 1)
    throw std::invalid_argument("genmod: ImplicitSurface: the function must be scalar, got dimension " +
                                std::to_string(f.dim()));
  for (int i : f.inputs())
    if (i > 2)
      throw std::invalid_argument("genmod: ImplicitSurface: the function depends on x(" + std::to_string(i) +
                                  "); an implicit solid is a function of x(0), x(1), x(2) only");
  return f;
}

}  // namespace

Fn hessian_of(const Fn& f) {
  const Fn fx = derivative(f, 0), fy = derivative(f, 1), fz = derivative(f, 2);
  return cat({derivative(fx, 0), derivative(fx, 1), derivative(fx, 2), derivative(fy, 1), derivative(fy, 2),
              derivative(fz, 2)});
}

ImplicitSurface::ImplicitSurface(const Fn& f)
    : value_(checked_implicit(f), kXyz),
      gradient_(cat({derivative(f, 0), derivative(f, 1), derivative(f, 2)}), kXyz),
      hessian_(hessian_of(f), kXyz) {}

namespace {

using implicit::Cell;
using implicit::CellKind;
using implicit::CellMesher;
using implicit::CellOutput;
using implicit::Frame;
using implicit::Octree;

void check_settings(const Box3& box, const ImplicitMeshSettings& s) {
  const char* axis[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    if (!box[k].is_bounded() || box[k].is_empty() || !(box[k].hi() > box[k].lo()))
      throw std::invalid_argument(std::string("genmod: mesh_implicit: the box's ") + axis[k] +
                                  " range must be bounded with positive width");
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto nonnegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!positive(s.min_feature))
    throw std::invalid_argument("genmod: mesh_implicit: min_feature must be positive and finite, got " +
                                std::to_string(s.min_feature));
  if (!nonnegative(s.tolerance))
    throw std::invalid_argument("genmod: mesh_implicit: tolerance must be >= 0 (0 = min_feature), got " +
                                std::to_string(s.tolerance));
  if (!nonnegative(s.max_cell))
    throw std::invalid_argument("genmod: mesh_implicit: max_cell must be >= 0 (0 = box / 8), got " +
                                std::to_string(s.max_cell));
  if (!(s.feature_angle > 0.0 && s.feature_angle < 3.14159))
    throw std::invalid_argument("genmod: mesh_implicit: feature_angle must be in (0, pi) radians, got " +
                                std::to_string(s.feature_angle));
  if (s.max_rounds < 0) throw std::invalid_argument("genmod: mesh_implicit: max_rounds must be >= 0");
  if (!nonnegative(s.max_seconds)) throw std::invalid_argument("genmod: mesh_implicit: max_seconds must be >= 0");
  if (s.max_cells < 1) throw std::invalid_argument("genmod: mesh_implicit: max_cells must be >= 1");
  if (s.max_memory < 1) throw std::invalid_argument("genmod: mesh_implicit: max_memory must be >= 1");
}

void add_limit(ImplicitMeshStats& stats, const char* name) {
  if (std::find(stats.limits_hit.begin(), stats.limits_hit.end(), name) == stats.limits_hit.end())
    stats.limits_hit.emplace_back(name);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// One vertex occurrence in a cell's output.
struct Occurrence {
  implicit::VertexKey key;
  std::uint32_t cell, local;
};

Mesh assemble(const std::vector<CellOutput>& outputs, ImplicitMeshStats& stats, double tolerance) {
  std::vector<std::size_t> first(outputs.size() + 1, 0);
  for (std::size_t c = 0; c < outputs.size(); ++c) first[c + 1] = first[c] + outputs[c].vertices.size();
  std::vector<Occurrence> all(first.back());
  tbb::parallel_for(std::size_t{0}, outputs.size(), [&](std::size_t c) {
    for (std::size_t i = 0; i < outputs[c].vertices.size(); ++i)
      all[first[c] + i] = {outputs[c].vertices[i].key, static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(i)};
  });
  tbb::parallel_sort(all.begin(), all.end(), [](const Occurrence& a, const Occurrence& b) {
    if (a.key != b.key) return a.key < b.key;
    return a.cell != b.cell ? a.cell < b.cell : a.local < b.local;
  });
  Mesh mesh;
  std::vector<std::uint32_t> global(first.back());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const implicit::OutVertex& v = outputs[all[i].cell].vertices[all[i].local];
    if (i == 0 || all[i].key != all[i - 1].key) {
      mesh.vertices.push_back(v.position);
      if (v.error < 0.0 || v.error > tolerance) ++stats.uncertified_vertices;
      else stats.max_vertex_error = std::max(stats.max_vertex_error, v.error);
      if (v.key.kind == implicit::VertexKind::FacePoint) ++stats.feature_points;
    } else if (mesh.vertices.back() != v.position) {
      throw std::logic_error("genmod: mesh_implicit: two cells computed different positions for one vertex (kind " +
                             std::to_string(static_cast<int>(v.key.kind)) + ")");
    }
    global[first[all[i].cell] + all[i].local] = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
  }
  std::size_t triangles = 0;
  for (const CellOutput& o : outputs) triangles += o.triangles.size();
  mesh.triangles.reserve(triangles);
  for (std::size_t c = 0; c < outputs.size(); ++c)
    for (const auto& t : outputs[c].triangles)
      mesh.triangles.push_back({global[first[c] + t[0]], global[first[c] + t[1]], global[first[c] + t[2]]});
  return mesh;
}

}  // namespace

ImplicitMesh mesh_implicit(const Fn& f, const Box3& box, const ImplicitMeshSettings& settings) {
  return mesh_implicit(ImplicitSurface(f), box, settings);
}

ImplicitMesh mesh_implicit(const ImplicitSurface& surface, const Box3& box, const ImplicitMeshSettings& settings) {
  check_settings(box, settings);
  const auto start = std::chrono::steady_clock::now();
  const auto deadline = settings.max_seconds > 0
                            ? start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                          std::chrono::duration<double>(settings.max_seconds))
                            : std::chrono::steady_clock::time_point::max();
  const Frame frame(box);
  if (settings.min_feature < frame.size(implicit::kMaxLevel))
    throw std::invalid_argument("genmod: mesh_implicit: min_feature " + std::to_string(settings.min_feature) +
                                " is below the finest cell the box allows (" +
                                std::to_string(frame.size(implicit::kMaxLevel)) + ", 2^-19 of the box)");
  const double tolerance = settings.tolerance > 0 ? settings.tolerance : settings.min_feature;
  double largest_side = 0;
  for (const Interval& r : box) largest_side = std::max(largest_side, r.hi() - r.lo());
  const double max_cell = settings.max_cell > 0 ? settings.max_cell : largest_side / 8.0;
  int min_level = 0;
  while (min_level < implicit::kMaxLevel && frame.size(min_level + 1) >= settings.min_feature) ++min_level;
  int max_cell_level = 0;
  while (max_cell_level < min_level && frame.size(max_cell_level) > max_cell) ++max_cell_level;

  ImplicitMesh result;
  ImplicitMeshStats& stats = result.stats;
  stats.full_tape_length = surface.value().size();
  const implicit::ClassifyContext classify{&frame, &settings, &surface.hessian(), min_level, max_cell_level};
  raster_detail::run_with_threads(settings.threads, "mesh_implicit", [&] {
    Octree tree(surface, classify, deadline, settings.cancel, stats);
    stats.seconds_octree = seconds_since(start);
    if (settings.progress) settings.progress(0.2);

    std::vector<implicit::PieceId> fan_pieces;
    const implicit::MeshContext context{&tree,
                                        &frame,
                                        tolerance,
                                        1e-2 * std::min(tolerance, settings.min_feature),
                                        settings.sharp_features,
                                        std::cos(settings.feature_angle),
                                        &fan_pieces};
    tbb::enumerable_thread_specific<CellMesher> meshers([&] { return CellMesher(context); });
    std::vector<std::uint32_t> surface_cells;
    std::vector<CellOutput> outputs;      // per surface cell, in surface_cells order
    // The last output of each surface cell, in a slot per cell (slot_of[cell]).
    std::vector<CellOutput> kept;
    std::vector<std::uint32_t> slot_of;
    std::vector<char> dirty(tree.cells().size(), 1);
    std::vector<std::uint32_t> touched;
    const auto mesh_start = std::chrono::steady_clock::now();
    // Rounds: mesh the surface cells whose neighbourhood changed; split the cells that ask for
    // it (while allowed); force to fan mode the direct pieces of cells with several loops that
    // stay; until nothing changes. Forcing only grows a finite set, so the rounds end even
    // past max_rounds.
    for (int round = 0;; ++round) {
      surface_cells.clear();
      for (std::uint32_t i = 0; i < tree.cells().size(); ++i)
        if (tree.cell(i).kind == CellKind::Surface) surface_cells.push_back(i);
      slot_of.resize(tree.cells().size(), implicit::kNone);
      for (std::uint32_t c : surface_cells)
        if (slot_of[c] == implicit::kNone) {
          slot_of[c] = static_cast<std::uint32_t>(kept.size());
          kept.emplace_back();
        }
      dirty.resize(tree.cells().size(), 1);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, surface_cells.size(), 8), [&](const auto& r) {
        CellMesher& m = meshers.local();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const std::uint32_t c = surface_cells[i];
          if (dirty[c]) m.mesh(tree.cell(c), kept[slot_of[c]]);
        }
      });
      for (std::uint32_t c : surface_cells) stats.cell_meshings += dirty[c] != 0;
      std::fill(dirty.begin(), dirty.end(), 0);
      stats.rounds = round + 1;
      std::size_t triangles = 0, wanting = 0;
      for (std::uint32_t c : surface_cells) {
        triangles += kept[slot_of[c]].triangles.size();
        wanting += kept[slot_of[c]].wants_split && tree.cell(c).level < min_level;
      }
      bool may_split = wanting > 0;
      if (may_split && round >= settings.max_rounds) {
        add_limit(stats, "rounds");
        may_split = false;
      } else if (may_split && triangles > settings.max_triangles) {
        add_limit(stats, "triangles");
        may_split = false;
      } else if (may_split && settings.cancel != nullptr && settings.cancel->load(std::memory_order_relaxed)) {
        add_limit(stats, "cancelled");
        may_split = false;
      } else if (may_split && std::chrono::steady_clock::now() > deadline) {
        add_limit(stats, "seconds");
        may_split = false;
      } else if (may_split && tree.cell_limit_reached()) {
        add_limit(stats, tree.memory_bytes() > settings.max_memory ? "memory" : "cells");
        may_split = false;
      }
      std::vector<std::uint32_t> split;
      std::vector<implicit::PieceId> force;
      for (std::uint32_t c : surface_cells) {
        CellOutput& o = kept[slot_of[c]];
        if (may_split && o.wants_split && tree.cell(c).level < min_level) {
          split.push_back(c);
          stats.splits_for_loops += o.multi_loop;
          stats.splits_for_accuracy += o.inaccurate;
          stats.splits_for_folds += o.folded;
          o = CellOutput{};  // the cell is gone
        } else {
          force.insert(force.end(), o.direct_pieces.begin(), o.direct_pieces.end());
        }
      }
      if (settings.progress) settings.progress(0.2 + 0.7 * std::min(1.0, (round + 1.0) / (settings.max_rounds + 1)));
      if (split.empty() && force.empty()) break;
      // Cells whose pieces or face corners change: every surface leaf touching a split cell
      // (after the split: its children too) or a forced piece.
      for (std::uint32_t c : split) {
        const Cell& cell = tree.cell(c);
        const std::uint32_t sz = cell.size();
        touched.clear();
        tree.surface_leaves_touching(cell.corner, {cell.corner[0] + sz, cell.corner[1] + sz, cell.corner[2] + sz}, touched);
        for (std::uint32_t t : touched) dirty[t] = 1;
      }
      if (!split.empty()) tree.split(split, stats);
      dirty.resize(tree.cells().size(), 1);  // the children
      for (const implicit::PieceId& p : force) {
        std::array<std::uint32_t, 3> lo = implicit::unpack(p.center), hi = lo;
        for (int k = 0; k < 3; ++k)
          if (k != p.axis) {
            lo[k] -= p.half;
            hi[k] += p.half;
          }
        touched.clear();
        tree.surface_leaves_touching(lo, hi, touched);
        for (std::uint32_t t : touched) dirty[t] = 1;
      }
      fan_pieces.insert(fan_pieces.end(), force.begin(), force.end());
      std::sort(fan_pieces.begin(), fan_pieces.end());
      fan_pieces.erase(std::unique(fan_pieces.begin(), fan_pieces.end()), fan_pieces.end());
    }
    outputs.clear();
    for (std::uint32_t c : surface_cells) outputs.push_back(std::move(kept[slot_of[c]]));
    stats.seconds_mesh = seconds_since(mesh_start);

    // Statistics of the final octree and cells.
    std::size_t tape_total = 0;
    bool first_surface = true;
    for (const Cell& c : tree.cells()) {
      if (c.kind == CellKind::Internal) continue;
      ++stats.leaves;
      if (c.kind == CellKind::Inside) ++stats.inside_leaves;
      if (c.kind == CellKind::Outside) ++stats.outside_leaves;
      if (c.kind != CellKind::Surface) continue;
      ++stats.surface_cells;
      tape_total += tree.tapes(c).value.size();
      if (c.certified) ++stats.certified_cells;
      else if (!c.bounded_gradient) ++stats.unbounded_gradient_cells;
      else ++stats.uncertified_cells;
      const int level = c.level;
      stats.min_surface_level = first_surface ? level : std::min(stats.min_surface_level, level);
      stats.max_surface_level = first_surface ? level : std::max(stats.max_surface_level, level);
      first_surface = false;
    }
    stats.mean_tape_length = stats.surface_cells ? static_cast<double>(tape_total) / static_cast<double>(stats.surface_cells) : 0.0;
    stats.smallest_cell = frame.size(stats.max_surface_level);
    stats.largest_surface_cell = frame.size(stats.min_surface_level);
    for (const CellOutput& o : outputs) {
      stats.multi_loop_cells += o.multi_loop;
      stats.inaccurate_cells += o.inaccurate;
      stats.folded_cells += o.folded;
    }
    const auto assemble_start = std::chrono::steady_clock::now();
    result.mesh = assemble(outputs, stats, tolerance);
    stats.seconds_assemble = seconds_since(assemble_start);
    if (result.mesh.triangles.size() > settings.max_triangles) add_limit(stats, "triangles");
  });
  if (settings.progress) settings.progress(1.0);
  return result;
}

}  // namespace genmod
