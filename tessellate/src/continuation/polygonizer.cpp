// polygonize_continuation: the cube walk, the corner and vertex caches and the bisection of
// lattice edges (the method is described in continuation_polygonizer.hpp).
//
// Threads. The walk (which cubes, triangles and vertex numbers) depends only on the corners'
// sides, so it runs on one thread; a vertex's position and normal depend only on its lattice
// edge. So the walk numbers each new vertex and records its edge, and every kPlaceEvery new
// vertices (and at the end) they are placed together: bisection and normals in chunks of
// kPlaceChunk vertices, the chunks spread over the threads. The chunks are fixed by the
// vertex numbers alone, so each point is evaluated in the same batch whatever the thread
// count, and the mesh is bitwise the same. Bisection and normals are ~95% of the evaluations.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "continuation/seed_search.hpp"
#include "thread_arena.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace genmod {

namespace {

using continuation::Evaluator;
using continuation::is_inside;
using Point = std::array<double, 3>;
using Cell = std::array<std::int64_t, 3>;

// Lattice keys: three coordinates of 20 bits (offset by 2^19) in the low 60 bits; an edge is
// the key of one end shifted by 4 with the index of its direction (13 directions: the
// offsets in {-1, 0, 1}^3 whose first non-zero component is positive) in the low 4 bits.
constexpr std::int64_t kOffset = std::int64_t{1} << 19;
constexpr std::int64_t kMaxCoordinate = kOffset - 2;  // a cube's far corner stays in range

// Vertices placed per round (bounds the memory of unplaced edges and the delay of a stop
// request), and per chunk of a round (one batch evaluation per halving).
constexpr std::size_t kPlaceEvery = 4096;
constexpr std::size_t kPlaceChunk = 16;

std::uint64_t corner_key(std::int64_t i, std::int64_t j, std::int64_t k) {
  return (static_cast<std::uint64_t>(i + kOffset) << 40) | (static_cast<std::uint64_t>(j + kOffset) << 20) |
         static_cast<std::uint64_t>(k + kOffset);
}

std::uint64_t edge_key(const Cell& a, const Cell& b) {
  std::int64_t d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Cell* from = &a;
  const std::int64_t first = d[0] != 0 ? d[0] : d[1] != 0 ? d[1] : d[2];
  if (first < 0) {
    from = &b;
    for (auto& c : d) c = -c;
  }
  const auto direction = static_cast<std::uint64_t>(9 * d[0] + 3 * d[1] + d[2] - 1);  // 0..12
  return (corner_key((*from)[0], (*from)[1], (*from)[2]) << 4) | direction;
}

void check_settings(const ContinuationSettings& s) {
  const std::string where = "genmod: polygonize_continuation: ";
  if (!std::isfinite(s.cube_size) || !(s.cube_size > 0.0))
    throw std::invalid_argument(where + "cube_size must be finite and positive, got " + std::to_string(s.cube_size));
  if (s.bisections < 1 || s.bisections > 60)
    throw std::invalid_argument(where + "bisections must be in 1..60, got " + std::to_string(s.bisections));
  if (s.max_cubes < 1) throw std::invalid_argument(where + "max_cubes must be at least 1");
  if (s.search_samples < 1)
    throw std::invalid_argument(where + "search_samples must be at least 1, got " + std::to_string(s.search_samples));
  if (!std::isfinite(s.search_radius) || s.search_radius < 0.0 ||
      (s.search_radius > 0.0 && s.search_radius < 0.5 * s.cube_size))
    throw std::invalid_argument(where + "search_radius must be 0 (default) or finite and at least cube_size / 2, got " +
                                std::to_string(s.search_radius));
  for (std::size_t n = 0; n < s.starts.size(); ++n)
    for (double c : s.starts[n])
      if (!std::isfinite(c))
        throw std::invalid_argument(where + "start point " + std::to_string(n) + " has a coordinate that is not finite");
  if (s.bounds) {
    const char* axis[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
      if ((*s.bounds)[k].is_empty())
        throw std::invalid_argument(where + "the bounds' " + axis[k] + " range is empty");
    if (s.starts.empty())
      for (int k = 0; k < 3; ++k)
        if (!(*s.bounds)[k].is_bounded())
          throw std::invalid_argument(where + "without start points the bounds are searched for the surface, so they must be "
                                      "bounded; the " + axis[k] + " range is not");
  } else if (s.starts.empty()) {
    throw std::invalid_argument(where + "no start point and no bounds to search for the surface");
  }
}

void check_tape(const Tape& f) {
  const auto in = f.inputs();
  if (f.num_outputs() != 1 || in.size() != 3 || in[0] != 0 || in[1] != 1 || in[2] != 2)
    throw std::invalid_argument(
        "genmod: polygonize_continuation: the tape must be scalar with the inputs x(0), x(1), x(2) in that order, got " +
        std::to_string(f.num_outputs()) + " outputs and " + std::to_string(in.size()) + " inputs");
}

class Polygonizer {
 public:
  Polygonizer(const Tape& f, const ContinuationSettings& s) : s_(s), eval_(f), workers_([&f] { return Evaluator(f); }) {}

  ContinuationMesh run() {
    const double radius = s_.search_radius > 0.0 ? s_.search_radius : 16.0 * s_.cube_size;
    std::vector<Point> seeds;
    if (s_.starts.empty()) {
      seeds.push_back(continuation::search_box(eval_, *s_.bounds, s_.search_samples, s_.cube_size, s_.bisections));
    } else {
      for (const Point& p : s_.starts)
        seeds.push_back(continuation::search_around(eval_, p, radius, s_.search_samples, s_.cube_size, s_.bisections));
    }
    for (int k = 0; k < 3; ++k) origin_[k] = seeds[0][k] - 0.5 * s_.cube_size;
    out_.stats.search_evaluations = eval_.count;  // everything so far; the rest is counted apart
    // One continuation per seed, each finished before the next starts, so a later start on a
    // piece already polygonized is recognised.
    for (const Point& seed : seeds) {
      start_from(seed);
      while (!stack_.empty()) {
        if (s_.cancel != nullptr && s_.cancel->load(std::memory_order_relaxed)) {
          limit_[kCancelled] = true;
          stack_.clear();
          break;
        }
        const Cell c = stack_.back();
        stack_.pop_back();
        polygonize(c);
      }
    }
    place();
    out_.stats.cubes = visited_.size();
    const char* names[4] = {"cubes", "bounds", "lattice", "cancelled"};
    for (int k = 0; k < 4; ++k)
      if (limit_[k]) out_.stats.limits_hit.emplace_back(names[k]);
    return std::move(out_);
  }

 private:
  enum Limit { kCubes = 0, kBounds = 1, kLattice = 2, kCancelled = 3 };

  Point corner_point(const Cell& c) const {
    return {origin_[0] + s_.cube_size * static_cast<double>(c[0]), origin_[1] + s_.cube_size * static_cast<double>(c[1]),
            origin_[2] + s_.cube_size * static_cast<double>(c[2])};
  }

  static Cell corner_of(const Cell& cube, int c) { return {cube[0] + (c & 1), cube[1] + (c >> 1 & 1), cube[2] + (c >> 2 & 1)}; }

  // The eight corner values of a cube, from the cache or evaluated together.
  std::array<double, 8> corners(const Cell& cube) {
    std::array<double, 8> value{};
    int missing[8], n = 0;
    for (int c = 0; c < 8; ++c) {
      const Cell p = corner_of(cube, c);
      const auto it = corner_cache_.find(corner_key(p[0], p[1], p[2]));
      if (it != corner_cache_.end()) {
        value[c] = it->second;
      } else {
        missing[n] = c;
        points_[n] = corner_point(p);
        ++n;
      }
    }
    if (n > 0) {
      const std::size_t before = eval_.count;
      const std::span<const double> v = eval_.eval(std::span<const Point>(points_.data(), n));
      out_.stats.corner_evaluations += eval_.count - before;
      for (int m = 0; m < n; ++m) {
        const Cell p = corner_of(cube, missing[m]);
        if (!std::isfinite(v[m])) ++out_.stats.nonfinite_corners;
        corner_cache_.emplace(corner_key(p[0], p[1], p[2]), v[m]);
        value[missing[m]] = v[m];
      }
    }
    return value;
  }

  static unsigned inside_mask(const std::array<double, 8>& v) {
    unsigned mask = 0;
    for (int c = 0; c < 8; ++c)
      if (is_inside(v[c])) mask |= 1u << c;
    return mask;
  }

  // Whether a cube may be visited; records the limit that forbids it.
  bool allowed(const Cell& c) {
    for (std::int64_t x : c)
      if (x < -kMaxCoordinate || x > kMaxCoordinate) {
        limit_[kLattice] = true;
        return false;
      }
    if (s_.bounds) {
      const Point lo = corner_point(c);
      for (int k = 0; k < 3; ++k) {
        const double centre = lo[k] + 0.5 * s_.cube_size;
        if (!((*s_.bounds)[k].lo() <= centre && centre <= (*s_.bounds)[k].hi())) {
          limit_[kBounds] = true;
          return false;
        }
      }
    }
    if (visited_.size() >= s_.max_cubes) {
      limit_[kCubes] = true;
      return false;
    }
    return true;
  }

  void visit(const Cell& c) {
    visited_.insert(corner_key(c[0], c[1], c[2]));
    stack_.push_back(c);
  }

  // Starts a continuation at the seed's cube, or at the first cube around it that straddles
  // the surface.
  void start_from(const Point& seed) {
    if (visited_.size() >= s_.max_cubes) {  // no room for another piece: the limit, not an error
      limit_[kCubes] = true;
      return;
    }
    Cell home;
    for (int k = 0; k < 3; ++k)
      home[k] = static_cast<std::int64_t>(std::floor((seed[k] - origin_[k]) / s_.cube_size));
    for (int n = 0; n < 27; ++n) {
      // The home cube first, then its neighbours in a fixed order.
      const int m = (n + 13) % 27;
      const Cell c{home[0] + m / 9 - 1, home[1] + m / 3 % 3 - 1, home[2] + m % 3 - 1};
      bool in_range = true;
      for (std::int64_t x : c) in_range = in_range && x >= -kMaxCoordinate && x <= kMaxCoordinate;
      if (!in_range) continue;
      const unsigned mask = inside_mask(corners(c));
      if (mask == 0 || mask == 255) continue;
      if (visited_.contains(corner_key(c[0], c[1], c[2]))) {
        ++out_.stats.starts_in_visited_cubes;
        return;
      }
      if (!allowed(c)) continue;
      out_.stats.seeds.push_back(seed);
      visit(c);
      return;
    }
    std::ostringstream msg;
    msg.precision(17);
    msg << "genmod: polygonize_continuation: no cube of size " << s_.cube_size << " at or next to the surface point ("
        << seed[0] << ", " << seed[1] << ", " << seed[2]
        << ") has corners on both sides of the surface (or every such cube is outside the bounds or limits): the "
           "surface there is smaller than a cube; use a smaller cube_size";
    throw std::runtime_error(msg.str());
  }

  void polygonize(const Cell& cube) {
    const std::array<double, 8> value = corners(cube);
    const unsigned mask = inside_mask(value);
    triangles_.clear();
    if (s_.decomposition == CellDecomposition::tetrahedra) {
      const auto tets = cube_tetrahedra();
      for (int t = 0; t < 6; ++t) {
        unsigned m = 0;
        for (int i = 0; i < 4; ++i)
          if (mask >> tets[t][i] & 1) m |= 1u << i;
        for (const CaseTriangle& tri : tetrahedron_case(t, m)) triangles_.push_back(tri);
      }
    } else {
      for (const CaseTriangle& tri : cube_case(mask)) triangles_.push_back(tri);
    }
    emit(cube);
    propagate(cube, value);
  }

  // Looks up or computes the vertices of the cube's triangles and appends the triangles.
  void emit(const Cell& cube) {
    // Vertex per local corner pair: -1 unknown, -2 pending (computed below), else its id.
    std::int64_t local[64];
    std::fill(std::begin(local), std::end(local), -1);
    pending_.clear();
    for (const CaseTriangle& tri : triangles_)
      for (const CornerPair& e : tri) {
        const int slot = e[0] * 8 + e[1];
        if (local[slot] != -1) continue;
        const auto it = vertex_cache_.find(edge_key(corner_of(cube, e[0]), corner_of(cube, e[1])));
        if (it != vertex_cache_.end()) {
          local[slot] = it->second;
        } else {
          local[slot] = -2;
          pending_.push_back(slot);
        }
      }
    if (!pending_.empty()) bisect(cube, local);
    for (const CaseTriangle& tri : triangles_) {
      std::array<std::uint32_t, 3> t;
      for (int k = 0; k < 3; ++k) t[k] = static_cast<std::uint32_t>(local[tri[k][0] * 8 + tri[k][1]]);
      out_.mesh.triangles.push_back(t);
    }
  }

  // Numbers the pending edges' vertices in the order they were first needed; place() computes
  // their positions (and normals) later, in parallel.
  void bisect(const Cell& cube, std::int64_t* local) {
    for (const int slot : pending_) {
      const auto id = static_cast<std::int64_t>(out_.mesh.vertices.size());
      out_.mesh.vertices.push_back({0.0, 0.0, 0.0});
      if (s_.normals) out_.normals.push_back({0.0, 0.0, 0.0});
      unplaced_.push_back({corner_point(corner_of(cube, slot / 8)), corner_point(corner_of(cube, slot % 8))});
      local[slot] = id;
      vertex_cache_.emplace(edge_key(corner_of(cube, slot / 8), corner_of(cube, slot % 8)), static_cast<std::uint32_t>(id));
    }
    if (unplaced_.size() >= kPlaceEvery) place();
  }

  // Places the vertices numbered since the last round: the last unplaced_.size() vertices.
  void place() {
    const std::size_t n = unplaced_.size();
    if (n == 0) return;
    const std::size_t first = out_.mesh.vertices.size() - n, chunks = (n + kPlaceChunk - 1) / kPlaceChunk;
    brackets_.assign(chunks, 0.0);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
      const std::size_t b = c * kPlaceChunk, e = std::min(n, b + kPlaceChunk);
      brackets_[c] = place_chunk(workers_.local(), first, b, e);
    });
    for (double b : brackets_) out_.stats.max_bracket = std::max(out_.stats.max_bracket, b);
    out_.stats.bisection_evaluations += n * static_cast<std::size_t>(s_.bisections);
    if (s_.normals) out_.stats.normal_evaluations += 4 * n;
    unplaced_.clear();
  }

  // Bisects the edges unplaced_[b, e) together (one batch evaluation per halving), writes
  // their vertices (numbers first + b ...) and normals; returns the longest final bracket.
  double place_chunk(Evaluator& f, std::size_t first, std::size_t b, std::size_t e) {
    const std::size_t n = e - b;
    std::array<Point, kPlaceChunk> in, out, mid;
    for (std::size_t i = 0; i < n; ++i) in[i] = unplaced_[b + i][0], out[i] = unplaced_[b + i][1];
    for (int step = 0; step < s_.bisections; ++step) {
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) mid[i][k] = 0.5 * (in[i][k] + out[i][k]);
      const std::span<const double> v = f.eval(std::span<const Point>(mid.data(), n));
      for (std::size_t i = 0; i < n; ++i) (is_inside(v[i]) ? in[i] : out[i]) = mid[i];
    }
    double bracket = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) mid[i][k] = 0.5 * (in[i][k] + out[i][k]);
      bracket = std::max(bracket, std::hypot(out[i][0] - in[i][0], out[i][1] - in[i][1], out[i][2] - in[i][2]));
      out_.mesh.vertices[first + b + i] = mid[i];  // distinct elements per chunk: no race
    }
    if (s_.normals) normals(f, std::span<const Point>(mid.data(), n), first + b);
    return bracket;
  }

  // Forward differences at the vertices p (numbers first, first + 1, ...), step cube_size / 100.
  void normals(Evaluator& f, std::span<const Point> p, std::size_t first) {
    const double delta = 0.01 * s_.cube_size;
    std::array<Point, 4 * kPlaceChunk> probes;
    for (std::size_t e = 0; e < p.size(); ++e) {
      probes[4 * e] = p[e];
      for (int k = 0; k < 3; ++k) {
        probes[4 * e + 1 + k] = p[e];
        probes[4 * e + 1 + k][k] += delta;
      }
    }
    const std::span<const double> v = f.eval(std::span<const Point>(probes.data(), 4 * p.size()));
    for (std::size_t e = 0; e < p.size(); ++e) {
      Point g{v[4 * e + 1] - v[4 * e], v[4 * e + 2] - v[4 * e], v[4 * e + 3] - v[4 * e]};
      const double len = std::hypot(g[0], g[1], g[2]);
      if (len > 0.0 && std::isfinite(len)) {
        for (double& c : g) c /= len;
      } else {
        g = {0.0, 0.0, 0.0};
      }
      out_.normals[first + e] = g;
    }
  }

  // Visits the neighbours across the faces the surface crosses, in the order -x +x -y +y -z +z.
  void propagate(const Cell& cube, const std::array<double, 8>& value) {
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        int inside = 0;
        for (int c = 0; c < 8; ++c)
          if ((c >> axis & 1) == side && is_inside(value[c])) ++inside;
        if (inside == 0 || inside == 4) continue;
        ++out_.stats.surface_faces;
        Cell next = cube;
        next[axis] += side == 0 ? -1 : 1;
        if (visited_.contains(corner_key(next[0], next[1], next[2])) || !allowed(next)) continue;
        visit(next);
      }
  }

  const ContinuationSettings& s_;
  Evaluator eval_;  // the walk's (seed search and corners)
  tbb::enumerable_thread_specific<Evaluator> workers_;  // place()'s, one per thread
  Point origin_{};
  std::unordered_map<std::uint64_t, double> corner_cache_;
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_cache_;
  std::unordered_set<std::uint64_t> visited_;
  std::vector<Cell> stack_;
  bool limit_[4] = {false, false, false, false};
  ContinuationMesh out_;
  // Scratch.
  std::array<Point, 8> points_{};
  std::vector<CaseTriangle> triangles_;
  std::vector<int> pending_;
  std::vector<std::array<Point, 2>> unplaced_;  // (inside, outside) corner of each vertex's edge
  std::vector<double> brackets_;                 // per chunk of a round
};

}  // namespace

ContinuationMesh polygonize_continuation(const Tape& f, const ContinuationSettings& settings) {
  check_tape(f);
  check_settings(settings);
  ContinuationMesh m;
  raster_detail::run_with_threads(settings.threads, "polygonize_continuation", [&] { m = Polygonizer(f, settings).run(); });
  return m;
}

ContinuationMesh polygonize_continuation(const Fn& f, const ContinuationSettings& settings) {
  if (f.dim() != 1)
    throw std::invalid_argument("genmod: polygonize_continuation: the function must be scalar, got dimension " +
                                std::to_string(f.dim()));
  for (int i : f.inputs())
    if (i > 2)
      throw std::invalid_argument("genmod: polygonize_continuation: the function depends on x(" + std::to_string(i) +
                                  "); an implicit surface is a function of x(0), x(1), x(2) only");
  check_settings(settings);  // before compiling
  const int xyz[3] = {0, 1, 2};
  return polygonize_continuation(Tape(f, xyz), settings);
}

}  // namespace genmod
