// polygonize_regions: the lattice, the edge vertices (sampling and refinement), the face
// records (line matching, face vertices), the polygons of each tetrahedron and the walk (the
// method is described in nonmanifold_polygonizer.hpp).
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "nonmanifold/face_follower.hpp"
#include "nonmanifold/lattice_simplex.hpp"
#include "nonmanifold/post_process.hpp"
#include "nonmanifold/region_evaluator.hpp"
#include "thread_arena.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace genmod {

namespace {

using nonmanifold::LatticeSimplex;
using nonmanifold::Point;
using nonmanifold::RegionEvaluator;
using Coord = std::array<std::int64_t, 3>;

const std::string kWhere = "genmod: polygonize_regions: ";

Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point midpoint(const Point& a, const Point& b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}; }

// The five tetrahedra of a cube by the parity of i + j + k: a central one on four corners no
// two of which share a cube edge, and the four corners cut off around it. Corners are
// numbered c = x + 2y + 4z.
constexpr std::uint8_t kTets[2][5][4] = {
    {{1, 2, 4, 7}, {0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}},
    {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}},
};

struct Candidate {
  Point p{};
  RegionVertexKind kind = RegionVertexKind::edge;
  int a = -1, b = -1;         // edge vertex: regions before and after it, lower to higher corner
  Point in_a{}, in_b{};       // its last interval: an end in region a and one in region b
  std::uint64_t lo = 0, hi = 0;  // its edge's corner keys
  LatticeSimplex cell;        // the lattice edge, face or tetrahedron it lies in
  std::int64_t mesh = -1;     // mesh vertex, once used
};

struct EdgeRecord {
  std::vector<int> vertices;  // candidates, from the lower corner to the higher
  std::size_t evaluations = 0;
};

// A face line. The triangle (p, q, inner), for a point `inner` on the side of the face away
// from which the face's canonical normal points, has its normal toward region `right` (and
// toward `left` for an inner point on the other side).
struct Line {
  int p, q;
  int right, left;
  bool loop;  // both ends on one edge: a looped intersection, ignored
};

struct FaceRecord {
  std::array<Point, 3> corners;  // canonical order (increasing corner keys)
  std::vector<Line> lines;       // lines of interest only
  int face_vertex = -1;          // candidate, when the face holds a junction of interest
};

struct Key3Hash {
  std::size_t operator()(const std::array<std::uint64_t, 3>& k) const noexcept {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h ^= k[1] + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= k[2] + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

std::string text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

void check_settings(std::size_t k, const NonmanifoldSettings& s) {
  if (!std::isfinite(s.cube_size) || !(s.cube_size > 0.0))
    throw std::invalid_argument(kWhere + "cube_size must be finite and positive, got " + text(s.cube_size));
  const char* axis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (s.bounds[a].is_empty()) throw std::invalid_argument(kWhere + "the bounds' " + axis[a] + " range is empty");
    if (!s.bounds[a].is_bounded() || !std::isfinite(s.bounds[a].lo()) || !std::isfinite(s.bounds[a].hi()))
      throw std::invalid_argument(kWhere + "the bounds' " + axis[a] + " range is not bounded (the lattice fills it)");
  }
  for (const auto& [a, b] : s.interest) {
    if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= k || static_cast<std::size_t>(b) >= k)
      throw std::invalid_argument(kWhere + "interest pair (" + std::to_string(a) + ", " + std::to_string(b) +
                                  ") names a region that does not exist (there are " + std::to_string(k) + ")");
    if (a == b)
      throw std::invalid_argument(kWhere + "interest pair (" + std::to_string(a) + ", " + std::to_string(b) +
                                  ") is not a pair of different regions");
  }
  if (s.sections < 1 || s.sections > 4096)
    throw std::invalid_argument(kWhere + "sections must be in 1..4096, got " + std::to_string(s.sections));
  if (s.steps < 0 || s.steps > 40)
    throw std::invalid_argument(kWhere + "steps must be in 0..40, got " + std::to_string(s.steps));
  if (!std::isfinite(s.close_factor) || s.close_factor < 0.0)
    throw std::invalid_argument(kWhere + "close_factor must be finite and >= 0, got " + text(s.close_factor));
  if (s.max_cubes < 1) throw std::invalid_argument(kWhere + "max_cubes must be at least 1");
}

void check_regions(std::span<const Fn> regions) {
  if (regions.size() < 2)
    throw std::invalid_argument(kWhere + "at least two region functions are needed, got " +
                                std::to_string(regions.size()));
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (regions[i].dim() != 1)
      throw std::invalid_argument(kWhere + "region function " + std::to_string(i) + " must be scalar, got dimension " +
                                  std::to_string(regions[i].dim()));
    for (int in : regions[i].inputs())
      if (in > 2)
        throw std::invalid_argument(kWhere + "region function " + std::to_string(i) + " depends on x(" +
                                    std::to_string(in) + "); a region function is a function of x(0), x(1), x(2) only");
  }
}

class Polygonizer {
 public:
  Polygonizer(std::span<const Fn> regions, const NonmanifoldSettings& s)
      : s_(s), f_(regions), k_(static_cast<int>(regions.size())), workers_([this] { return f_.worker(); }) {
    interest_.assign(static_cast<std::size_t>(k_ * k_), s.interest.empty());
    for (const auto& [a, b] : s.interest) interest_[a * k_ + b] = interest_[b * k_ + a] = true;
    double corners = 1.0;
    for (int a = 0; a < 3; ++a) {
      origin_[a] = s.bounds[a].lo();
      const double cells = std::ceil((s.bounds[a].hi() - s.bounds[a].lo()) / s.cube_size);
      n_[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::min(cells, 1e9)));
      corners *= static_cast<double>(n_[a] + 1);
    }
    if (corners > static_cast<double>(s.max_corners))
      throw std::invalid_argument(kWhere + "the lattice of cubes of size " + text(s.cube_size) + " over the bounds has " +
                                  std::to_string(n_[0] + 1) + " x " + std::to_string(n_[1] + 1) + " x " +
                                  std::to_string(n_[2] + 1) + " corners, more than max_corners = " +
                                  std::to_string(s.max_corners) + "; use a larger cube_size or smaller bounds");
    corner_count_ = static_cast<std::uint64_t>(corners);
    out_.stats.eps = s.cube_size * std::sqrt(2.0) / (std::ldexp(1.0, s.steps + 1) * s.sections);
  }

  RegionMesh run() {
    scan_corners();
    if (cancelled_) {
      out_.stats.limits_hit.emplace_back("cancelled");
      return std::move(out_);
    }
    visited_.assign(static_cast<std::size_t>(n_[0] * n_[1] * n_[2]), 0);
    for (std::int64_t i = 0; i < n_[0]; ++i)
      for (std::int64_t j = 0; j < n_[1]; ++j)
        for (std::int64_t k = 0; k < n_[2]; ++k) {
          const Coord c{i, j, k};
          const int r0 = corner_region(c);
          bool mixed = false;
          for (int v = 1; v < 8 && !mixed; ++v) mixed = corner_region(corner_of(c, v)) != r0;
          if (mixed) enqueue(c);
        }
    while (!queue_.empty()) {
      if (stop_requested()) {
        cancelled_ = true;
        queue_.clear();
        break;
      }
      if (prepared_front_ == 0) prepare_edges();
      const Coord c = queue_.front();
      queue_.pop_front();
      --prepared_front_;
      polygonize(c);
    }
    if (limit_cubes_) out_.stats.limits_hit.emplace_back("cubes");
    if (limit_bounds_) out_.stats.limits_hit.emplace_back("bounds");
    if (cancelled_) out_.stats.limits_hit.emplace_back("cancelled");
    out_.stats.face_evaluations = face_evaluations_;
    if (s_.close_factor > 0.0) nonmanifold::remove_small_triangles(out_, s_.close_factor * out_.stats.eps, cells_);
    return std::move(out_);
  }

 private:
  static constexpr std::uint64_t kScanChunk = 4096;     // corners per batch of the scan
  static constexpr std::size_t kPrepareCubes = 256;      // queued cubes whose edges are computed ahead

  // Lattice.
  std::uint64_t key(const Coord& c) const {
    return static_cast<std::uint64_t>((c[0] * (n_[1] + 1) + c[1]) * (n_[2] + 1) + c[2]);
  }
  Point position(const Coord& c) const {
    return {origin_[0] + s_.cube_size * static_cast<double>(c[0]), origin_[1] + s_.cube_size * static_cast<double>(c[1]),
            origin_[2] + s_.cube_size * static_cast<double>(c[2])};
  }
  static Coord corner_of(const Coord& cube, int c) { return {cube[0] + (c & 1), cube[1] + (c >> 1 & 1), cube[2] + (c >> 2 & 1)}; }
  int corner_region(const Coord& c) const { return corner_regions_[key(c)]; }
  bool interesting(int a, int b) const { return interest_[a * k_ + b]; }

  // f_reg at every lattice corner, in chunks of kScanChunk corners in key order (a corner's
  // key is its position in the i, j, k loops), the chunks spread over the threads: each corner
  // is evaluated in the same batch whatever the thread count.
  void scan_corners() {
    corner_regions_.resize(corner_count_);
    const std::uint64_t chunks = (corner_count_ + kScanChunk - 1) / kScanChunk;
    std::atomic<bool> stopped{false};
    tbb::parallel_for(std::uint64_t{0}, chunks, [&](std::uint64_t c) {
      if (stopped.load(std::memory_order_relaxed) || stop_requested()) {
        stopped = true;  // run() returns at once: no corner is used
        return;
      }
      const std::uint64_t begin = c * kScanChunk, end = std::min(corner_count_, begin + kScanChunk);
      std::vector<Point> batch;
      batch.reserve(static_cast<std::size_t>(end - begin));
      const auto nj = static_cast<std::uint64_t>(n_[1] + 1), nk = static_cast<std::uint64_t>(n_[2] + 1);
      for (std::uint64_t key = begin; key < end; ++key)
        batch.push_back(position({static_cast<std::int64_t>(key / (nj * nk)), static_cast<std::int64_t>(key / nk % nj),
                                  static_cast<std::int64_t>(key % nk)}));
      const std::span<const int> r = workers_.local().regions(batch);
      std::copy(r.begin(), r.end(), corner_regions_.begin() + static_cast<std::ptrdiff_t>(begin));
    });
    cancelled_ = stopped.load();
    if (!cancelled_) out_.stats.corner_evaluations = corner_count_;
  }

  void enqueue(const Coord& c) {
    auto& v = visited_[static_cast<std::size_t>((c[0] * n_[1] + c[1]) * n_[2] + c[2])];
    if (v) return;
    if (cubes_queued_ >= s_.max_cubes) {
      limit_cubes_ = true;
      return;
    }
    v = 1;
    ++cubes_queued_;
    queue_.push_back(c);
  }

  // Edge vertices (§5.7.3).
  int new_candidate(Candidate c) {
    candidates_.push_back(c);
    return static_cast<int>(candidates_.size() - 1);
  }

  // One lattice edge's crossings, computed apart from the walk (a pure function of the edge:
  // the samples and halvings below, on the caller's evaluator), so that edges can be computed
  // ahead in parallel and taken in the walk's order (prepare_edges).
  struct EdgeWork {
    std::vector<Candidate> found;  // in the order the halvings find them
    std::size_t samples = 0, refines = 0;
  };

  static std::uint64_t edge_key(std::uint64_t ka, std::uint64_t kb, std::uint64_t corner_count) {
    return std::min(ka, kb) * corner_count + std::max(ka, kb);
  }

  void refine(RegionEvaluator& f, EdgeWork& w, const Candidate& proto, const Point& x0, int r0, const Point& x1, int r1,
              int depth) const {
    const Point xm = midpoint(x0, x1);
    const int rm = f.region(xm);
    ++w.refines;
    const bool known = rm == r0 || rm == r1;
    if ((depth >= s_.steps && known) || depth >= s_.steps + 40) {
      Candidate c = proto;
      c.p = xm;
      c.a = r0;
      c.b = r1;
      c.in_a = rm == r0 ? xm : x0;
      c.in_b = rm == r1 ? xm : x1;
      w.found.push_back(c);
      return;
    }
    if (rm == r0) {
      refine(f, w, proto, xm, rm, x1, r1, depth + 1);
    } else if (rm == r1) {
      refine(f, w, proto, x0, r0, xm, rm, depth + 1);
    } else {  // a foreign region: a crossing on each side of it
      refine(f, w, proto, x0, r0, xm, rm, depth + 1);
      refine(f, w, proto, xm, rm, x1, r1, depth + 1);
    }
  }

  EdgeWork compute_edge(RegionEvaluator& f, const Coord& a, const Coord& b) const {
    const std::uint64_t ka = key(a), kb = key(b);
    const Coord& lo = ka < kb ? a : b;
    const Coord& hi = ka < kb ? b : a;
    EdgeWork w;
    const Point pa = position(lo), pb = position(hi);
    const int n = s_.sections;
    if (n < 1) return w;  // checked with the settings; tells the compiler x and r are not empty
    std::vector<Point> x(static_cast<std::size_t>(n + 1));
    std::vector<int> r(static_cast<std::size_t>(n + 1));
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      for (int d = 0; d < 3; ++d) x[static_cast<std::size_t>(i)][d] = pa[d] + t * (pb[d] - pa[d]);
    }
    x.front() = pa;  // the ends exactly
    x.back() = pb;
    r.front() = corner_region(lo);
    r.back() = corner_region(hi);
    if (n > 1) {
      const std::span<const int> v = f.regions(std::span<const Point>(x.data() + 1, static_cast<std::size_t>(n - 1)));
      std::copy(v.begin(), v.end(), r.begin() + 1);
      w.samples = static_cast<std::size_t>(n - 1);
    }
    Candidate proto;
    proto.lo = std::min(ka, kb);
    proto.hi = std::max(ka, kb);
    const std::uint64_t ends[2] = {proto.lo, proto.hi};
    proto.cell = nonmanifold::make_simplex(ends, std::array<Point, 2>{pa, pb}.data(), 2);
    for (int i = 0; i < n; ++i)
      if (r[static_cast<std::size_t>(i)] != r[static_cast<std::size_t>(i + 1)])
        refine(f, w, proto, x[static_cast<std::size_t>(i)], r[static_cast<std::size_t>(i)], x[static_cast<std::size_t>(i + 1)],
               r[static_cast<std::size_t>(i + 1)], 0);
    return w;
  }

  // The edge's record: on first use its crossings (computed ahead by prepare_edges, or now)
  // become candidates, numbered in the order of first use, as a one-thread walk makes them.
  const EdgeRecord& edge(const Coord& a, const Coord& b) {
    const std::uint64_t k = edge_key(key(a), key(b), corner_count_);
    const auto it = edge_index_.find(k);
    if (it != edge_index_.end()) return edges_[it->second];
    EdgeWork w;
    if (const auto ready = ready_.find(k); ready != ready_.end()) {
      w = std::move(ready->second);
      ready_.erase(ready);
    } else {
      w = compute_edge(f_, a, b);
    }
    edge_index_.emplace(k, edges_.size());
    edges_.emplace_back();
    EdgeRecord& e = edges_.back();
    for (const Candidate& c : w.found) e.vertices.push_back(new_candidate(c));
    e.evaluations = w.samples + w.refines;
    out_.stats.sample_evaluations += w.samples;
    out_.stats.refine_evaluations += w.refines;
    return e;
  }

  // The edges of the next kPrepareCubes queued cubes that are not computed yet, computed in
  // parallel (each edge on its own, so the result does not depend on the threads) and kept
  // until edge() takes them. Every queued cube is polygonized, and its five tetrahedra use all
  // their edges, so nothing is computed that the one-thread walk would not.
  void prepare_edges() {
    std::vector<std::array<Coord, 2>> todo;
    std::unordered_set<std::uint64_t> seen;
    const std::size_t cubes = std::min(queue_.size(), kPrepareCubes);
    for (std::size_t q = 0; q < cubes; ++q) {
      const Coord& cube = queue_[q];
      const int parity = static_cast<int>((cube[0] + cube[1] + cube[2]) & 1);
      for (const auto& tet : kTets[parity])
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) {
            const Coord a = corner_of(cube, tet[i]), b = corner_of(cube, tet[j]);
            const std::uint64_t k = edge_key(key(a), key(b), corner_count_);
            if (edge_index_.contains(k) || ready_.contains(k) || !seen.insert(k).second) continue;
            todo.push_back({a, b});
          }
    }
    prepared_front_ = cubes;
    std::vector<EdgeWork> done(todo.size());
    tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t i) {
      done[i] = compute_edge(workers_.local(), todo[i][0], todo[i][1]);
    });
    for (std::size_t i = 0; i < todo.size(); ++i)
      ready_.emplace(edge_key(key(todo[i][0]), key(todo[i][1]), corner_count_), std::move(done[i]));
  }

  // Faces (§5.7.4), in canonical corner order.
  struct Entry {
    int vertex;
    int x, y;  // regions before and after it along the walk
    int side;  // which face edge it is on
  };

  int face(std::array<Coord, 3> c) {
    std::sort(c.begin(), c.end(), [&](const Coord& u, const Coord& v) { return key(u) < key(v); });
    const std::array<std::uint64_t, 3> k{key(c[0]), key(c[1]), key(c[2])};
    const auto it = face_index_.find(k);
    if (it != face_index_.end()) return it->second;
    FaceRecord rec;
    for (int i = 0; i < 3; ++i) rec.corners[static_cast<std::size_t>(i)] = position(c[static_cast<std::size_t>(i)]);
    std::vector<Entry> walk;
    for (int side = 0; side < 3; ++side) {
      const Coord& from = c[static_cast<std::size_t>(side)];
      const Coord& to = c[static_cast<std::size_t>((side + 1) % 3)];
      // Used before the next edge() call, which may grow edges_.
      const std::vector<int>& v = edge(from, to).vertices;
      if (key(from) < key(to)) {
        for (int id : v) walk.push_back({id, candidates_[id].a, candidates_[id].b, side});
      } else {
        for (auto r = v.rbegin(); r != v.rend(); ++r) walk.push_back({*r, candidates_[*r].b, candidates_[*r].a, side});
      }
    }
    // Pair neighbours with reversed pairs until none are left: the stack test (what is left
    // does not depend on the order, as in the reduction of a cyclic word). Looped
    // intersections (neighbours on one edge) go first: they are neighbours in every face
    // around that edge, so every tetrahedron around it ignores them alike and the mesh stays
    // closed.
    for (int phase = 0; phase < 2; ++phase)
    for (bool found = true; found && walk.size() >= 2;) {
      found = false;
      for (std::size_t i = 0; i < walk.size(); ++i) {
        const std::size_t j = (i + 1) % walk.size();
        const Entry& v = walk[i];
        const Entry& w = walk[j];
        if (v.x != w.y || v.y != w.x || (phase == 0 && v.side != w.side)) continue;
        if (interesting(v.x, v.y)) rec.lines.push_back({w.vertex, v.vertex, v.y, v.x, v.side == w.side});
        walk.erase(walk.begin() + static_cast<std::ptrdiff_t>(std::max(i, j)));
        walk.erase(walk.begin() + static_cast<std::ptrdiff_t>(std::min(i, j)));
        found = true;
        break;
      }
    }
    bool junction_of_interest = false;
    for (const Entry& e : walk) junction_of_interest = junction_of_interest || interesting(e.x, e.y);
    if (junction_of_interest) {
      rec.face_vertex = face_vertex(rec.corners, walk);
      candidates_[rec.face_vertex].cell = nonmanifold::make_simplex(k.data(), rec.corners.data(), 3);
      for (const Entry& e : walk)
        if (interesting(e.x, e.y)) rec.lines.push_back({rec.face_vertex, e.vertex, e.y, e.x, false});
    }
    face_index_.emplace(k, static_cast<int>(faces_.size()));
    faces_.push_back(std::move(rec));
    return static_cast<int>(faces_.size() - 1);
  }

  int face_vertex(const std::array<Point, 3>& corners, const std::vector<Entry>& open) {
    ++out_.stats.face_vertices;
    const std::size_t before = f_.count;
    double perimeter = 0.0;
    for (int i = 0; i < 3; ++i) {
      const Point d = sub(corners[static_cast<std::size_t>((i + 1) % 3)], corners[static_cast<std::size_t>(i)]);
      perimeter += std::sqrt(dot(d, d));
    }
    std::optional<Point> found;
    for (const Entry& e : open) {
      if (!interesting(e.x, e.y)) continue;
      const Candidate& c = candidates_[e.vertex];
      Point pa = c.in_a, pb = c.in_b;
      // Two more halvings: a strip of side at most eps / 2.
      bool ok = true;
      for (int h = 0; h < 2 && ok; ++h) {
        const Point m = midpoint(pa, pb);
        const int r = f_.region(m);
        if (r == c.a) pa = m;
        else if (r == c.b) pb = m;
        else ok = false;
      }
      if (!ok) continue;
      const Point d = sub(pb, pa);
      const double side = std::sqrt(dot(d, d));
      const auto steps = static_cast<std::size_t>(4.0 * perimeter / std::max(side, 1e-300)) + 16;
      found = nonmanifold::follow_to_junction(f_, corners, pa, pb, c.a, c.b, std::min<std::size_t>(steps, 1u << 22));
      if (found) break;
    }
    face_evaluations_ += f_.count - before;
    Candidate v;
    v.kind = RegionVertexKind::face;
    if (found) {
      v.p = *found;
    } else {
      ++out_.stats.face_vertex_fallbacks;
      for (const Entry& e : open)
        for (int d = 0; d < 3; ++d) v.p[d] += candidates_[e.vertex].p[d] / static_cast<double>(open.size());
    }
    return new_candidate(v);
  }

  // Output.
  std::uint32_t use(int candidate) {
    Candidate& c = candidates_[candidate];
    if (c.mesh < 0) {
      c.mesh = static_cast<std::int64_t>(out_.mesh.vertices.size());
      out_.mesh.vertices.push_back(c.p);
      out_.vertex_kinds.push_back(c.kind);
      cells_.push_back(c.cell);
    }
    return static_cast<std::uint32_t>(c.mesh);
  }

  // The triangle of `line` with a third vertex on the side `flip` says (see Line).
  void emit(int p, int q, int third, const Line& line, bool flip) {
    if (p == q || p == third || q == third) return;
    const int toward = flip ? line.left : line.right;
    const int lo = std::min(line.left, line.right), hi = std::max(line.left, line.right);
    std::array<std::uint32_t, 3> t = toward == hi ? std::array<std::uint32_t, 3>{use(p), use(q), use(third)}
                                                  : std::array<std::uint32_t, 3>{use(q), use(p), use(third)};
    out_.mesh.triangles.push_back(t);
    out_.regions.emplace_back(lo, hi);
  }

  // One tetrahedron; returns the cube faces (bit 2 * axis + side) it has lines of interest on.
  unsigned tetrahedron(const Coord& cube, const std::uint8_t* local) {
    std::array<Coord, 4> corner;
    std::array<std::uint64_t, 4> keys;
    std::array<Point, 4> pos;
    for (int i = 0; i < 4; ++i) {
      corner[static_cast<std::size_t>(i)] = corner_of(cube, local[i]);
      keys[static_cast<std::size_t>(i)] = key(corner[static_cast<std::size_t>(i)]);
      pos[static_cast<std::size_t>(i)] = position(corner[static_cast<std::size_t>(i)]);
    }
    // The cost model of claim 35.
    std::size_t evaluations = 0, crossed = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const EdgeRecord& e = edge(corner[static_cast<std::size_t>(i)], corner[static_cast<std::size_t>(j)]);
        evaluations += e.evaluations;
        if (!e.vertices.empty()) ++crossed;
      }
    if (crossed > 0) {
      ++out_.stats.crossing_tetrahedra;
      out_.stats.crossing_tetrahedron_edge_evaluations += evaluations;
      out_.stats.crossing_tetrahedron_crossed_edges += crossed;
    }
    std::array<int, 4> faces;
    std::array<bool, 4> flip;
    unsigned cube_faces = 0;
    std::vector<int> face_vertices;
    for (int f = 0; f < 4; ++f) {
      std::array<Coord, 3> c;
      std::array<int, 3> l;
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != f) {
          l[static_cast<std::size_t>(n)] = local[i];
          c[static_cast<std::size_t>(n++)] = corner[static_cast<std::size_t>(i)];
        }
      faces[static_cast<std::size_t>(f)] = face(c);
      const FaceRecord& rec = faces_[static_cast<std::size_t>(faces[static_cast<std::size_t>(f)])];
      const Point normal = cross(sub(rec.corners[1], rec.corners[0]), sub(rec.corners[2], rec.corners[0]));
      flip[static_cast<std::size_t>(f)] = dot(normal, sub(rec.corners[0], pos[static_cast<std::size_t>(f)])) <= 0.0;
      if (rec.face_vertex >= 0) face_vertices.push_back(rec.face_vertex);
      if (!rec.lines.empty())
        for (int axis = 0; axis < 3; ++axis) {
          const int bit = l[0] >> axis & 1;
          if ((l[1] >> axis & 1) == bit && (l[2] >> axis & 1) == bit) cube_faces |= 1u << (2 * axis + bit);
        }
    }
    const std::size_t before = out_.mesh.triangles.size();
    if (!face_vertices.empty()) {
      int centre = face_vertices[0];
      if (face_vertices.size() > 1) {
        Candidate v;
        v.kind = RegionVertexKind::internal;
        for (int id : face_vertices)
          for (int d = 0; d < 3; ++d) v.p[d] += candidates_[id].p[d] / static_cast<double>(face_vertices.size());
        v.cell = nonmanifold::make_simplex(keys.data(), pos.data(), 4);
        centre = new_candidate(v);
        ++out_.stats.internal_vertices;
      }
      for (int f = 0; f < 4; ++f)
        for (const Line& line : faces_[static_cast<std::size_t>(faces[static_cast<std::size_t>(f)])].lines)
          if (!line.loop) emit(line.p, line.q, centre, line, flip[static_cast<std::size_t>(f)]);
    } else {
      chain_polygons(keys, faces, flip);
    }
    if (out_.mesh.triangles.size() > before) ++out_.stats.tetrahedra;
    return cube_faces;
  }

  // The cosine of the angle between the normals of triangles (a, b, c) and (a, c, d): 1 when
  // the quadrilateral a b c d split along a-c is flat.
  double bend_cosine(int a, int b, int c, int d) const {
    const Point& pa = candidates_[a].p;
    const Point n1 = cross(sub(candidates_[b].p, pa), sub(candidates_[c].p, pa));
    const Point n2 = cross(sub(candidates_[c].p, pa), sub(candidates_[d].p, pa));
    const double l = std::sqrt(dot(n1, n1) * dot(n2, n2));
    return l > 0.0 ? dot(n1, n2) / l : -1.0;
  }

  // Lines chained across the tetrahedron's faces into polygons (the disjoint case).
  void chain_polygons(const std::array<std::uint64_t, 4>& keys, const std::array<int, 4>& faces,
                      const std::array<bool, 4>& flip) {
    std::array<std::vector<bool>, 4> used;
    for (int f = 0; f < 4; ++f)
      used[static_cast<std::size_t>(f)].assign(faces_[static_cast<std::size_t>(faces[static_cast<std::size_t>(f)])].lines.size(), false);
    const auto lines = [&](int f) -> const std::vector<Line>& {
      return faces_[static_cast<std::size_t>(faces[static_cast<std::size_t>(f)])].lines;
    };
    for (int f0 = 0; f0 < 4; ++f0)
      for (std::size_t l0 = 0; l0 < lines(f0).size(); ++l0) {
        const Line& first = lines(f0)[l0];
        if (first.loop || used[static_cast<std::size_t>(f0)][l0]) continue;
        used[static_cast<std::size_t>(f0)][l0] = true;
        std::vector<int> polygon{first.p, first.q};
        int f = f0, at = first.q;
        bool closed = false;
        for (int step = 0; step < 16 && !closed; ++step) {
          const Candidate& c = candidates_[at];
          int next_face = -1;
          for (int g = 0; g < 4; ++g)
            if (g != f && keys[static_cast<std::size_t>(g)] != c.lo && keys[static_cast<std::size_t>(g)] != c.hi) next_face = g;
          if (next_face < 0) break;
          int next = -1;
          const std::vector<Line>& ls = lines(next_face);
          for (std::size_t l = 0; l < ls.size() && next < 0; ++l) {
            if (used[static_cast<std::size_t>(next_face)][l]) continue;
            const Line& line = ls[l];
            if (std::min(line.left, line.right) != std::min(first.left, first.right) ||
                std::max(line.left, line.right) != std::max(first.left, first.right))
              continue;
            if (line.p == at || line.q == at) {
              used[static_cast<std::size_t>(next_face)][l] = true;
              next = line.p == at ? line.q : line.p;
            }
          }
          if (next < 0) break;
          if (next == polygon[0]) {
            closed = true;
          } else {
            polygon.push_back(next);
            at = next;
            f = next_face;
          }
        }
        if (!closed) {
          ++out_.stats.open_polygons;
          continue;
        }
        if (polygon.size() < 3) continue;
        // Orientation from the first line with the third polygon vertex as the inner point.
        const int toward = flip[static_cast<std::size_t>(f0)] ? first.left : first.right;
        if (toward != std::max(first.left, first.right)) std::reverse(polygon.begin() + 1, polygon.end());
        const Line up{0, 0, std::max(first.left, first.right), std::min(first.left, first.right), false};
        // A quadrilateral is split along the diagonal whose two triangles bend least.
        if (polygon.size() == 4 && bend_cosine(polygon[1], polygon[2], polygon[3], polygon[0]) >
                                       bend_cosine(polygon[0], polygon[1], polygon[2], polygon[3]))
          std::rotate(polygon.begin(), polygon.begin() + 1, polygon.end());
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i) emit(polygon[0], polygon[i], polygon[i + 1], up, false);
      }
  }

  void polygonize(const Coord& cube) {
    ++out_.stats.cubes;
    const int parity = static_cast<int>((cube[0] + cube[1] + cube[2]) & 1);
    unsigned cube_faces = 0;
    for (const auto& tet : kTets[parity]) cube_faces |= tetrahedron(cube, tet);
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        if (!(cube_faces >> (2 * axis + side) & 1)) continue;
        Coord next = cube;
        next[static_cast<std::size_t>(axis)] += side == 0 ? -1 : 1;
        if (next[static_cast<std::size_t>(axis)] < 0 || next[static_cast<std::size_t>(axis)] >= n_[axis]) {
          limit_bounds_ = true;
          continue;
        }
        enqueue(next);
      }
  }

  const NonmanifoldSettings& s_;
  RegionEvaluator f_;
  int k_;
  std::vector<bool> interest_;
  Point origin_{};
  std::int64_t n_[3] = {1, 1, 1};
  std::uint64_t corner_count_ = 0;
  std::vector<int> corner_regions_;
  std::vector<std::uint8_t> visited_;
  std::size_t cubes_queued_ = 0;
  std::deque<Coord> queue_;
  bool limit_cubes_ = false, limit_bounds_ = false, cancelled_ = false;
  bool stop_requested() const { return s_.cancel != nullptr && s_.cancel->load(std::memory_order_relaxed); }
  std::vector<Candidate> candidates_;
  std::vector<EdgeRecord> edges_;
  std::unordered_map<std::uint64_t, std::size_t> edge_index_;
  std::vector<FaceRecord> faces_;
  std::unordered_map<std::array<std::uint64_t, 3>, int, Key3Hash> face_index_;
  std::size_t face_evaluations_ = 0;
  RegionMesh out_;
  std::vector<LatticeSimplex> cells_;  // per mesh vertex
  // Edges computed ahead of the walk (prepare_edges), by key, until first used; the queued
  // cubes at the front whose edges were prepared; the evaluators of the threads.
  std::unordered_map<std::uint64_t, EdgeWork> ready_;
  std::size_t prepared_front_ = 0;
  tbb::enumerable_thread_specific<RegionEvaluator> workers_;
};

}  // namespace

RegionMesh polygonize_regions(std::span<const Fn> regions, const NonmanifoldSettings& settings) {
  check_regions(regions);
  check_settings(regions.size(), settings);
  RegionMesh m;
  raster_detail::run_with_threads(settings.threads, "polygonize_regions", [&] { m = Polygonizer(regions, settings).run(); });
  return m;
}

std::vector<int> region_at(std::span<const Fn> regions, std::span<const std::array<double, 3>> points) {
  check_regions(regions);
  nonmanifold::RegionEvaluator f(regions);
  const std::span<const int> r = f.regions(points);
  return {r.begin(), r.end()};
}

}  // namespace genmod
