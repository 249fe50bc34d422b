#include "implicit/cell_mesher.hpp"

#include "implicit/qef.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace genmod::implicit {
namespace {

Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
  // Coordinates equal at both ends stay exact (points on a face plane stay on it).
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

double distance(const Vec3& a, const Vec3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

bool is_inside(double g) { return g < 0.0; }  // NaN (an error) counts as outside

using Point2 = std::array<double, 2>;

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Strictly inside the convex polygon, at least `margin` from every edge line.
bool inside_convex(const Point2& q, std::span<const Point2> p, double margin) {
  double area = 0;
  for (std::size_t i = 0; i < p.size(); ++i) area += cross2(p[0], p[i], p[(i + 1) % p.size()]);
  const double s = area > 0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (len == 0) continue;
    if (!(s * cross2(a, b, q) > margin * len)) return false;
  }
  return true;
}

// The largest t with q + t d in the convex polygon (q inside it).
double exit_parameter(const Point2& q, const Point2& d, std::span<const Point2> p) {
  double area = 0;
  for (std::size_t i = 0; i < p.size(); ++i) area += cross2(p[0], p[i], p[(i + 1) % p.size()]);
  const double s = area > 0 ? 1.0 : -1.0;
  double t = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    // Inward normal of edge a -> b.
    const Point2 n{-s * (b[1] - a[1]), s * (b[0] - a[0])};
    const double along = n[0] * d[0] + n[1] * d[1];
    if (along < 0) t = std::min(t, (n[0] * (q[0] - a[0]) + n[1] * (q[1] - a[1])) / -along);
  }
  return t;
}

}  // namespace

CellMesher::Region CellMesher::cell_region() const {
  return {{cell_lo_[0], cell_lo_[1], cell_lo_[2]}, {cell_hi_[0], cell_hi_[1], cell_hi_[2]}};
}

void CellMesher::mesh(const Cell& cell, CellOutput& out) {
  out = CellOutput{};
  tapes_ = &ctx_.octree->tapes(cell);
  const std::uint32_t s = cell.size();
  const Vec3 lo = ctx_.frame->point(cell.corner);
  const Vec3 hi = ctx_.frame->point({cell.corner[0] + s, cell.corner[1] + s, cell.corner[2] + s});
  for (int k = 0; k < 3; ++k) {
    cell_lo_[k] = lo[k];
    cell_hi_[k] = hi[k];
  }
  cell_size_ = hi[0] - lo[0];
  gather_pieces(cell);
  std::vector<Vec3> points(sample_keys_.size());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = ctx_.frame->point(sample_keys_[i]);
  evaluate(points, sample_g_);
  boundary_g_.resize(boundary_.size());
  for (std::size_t i = 0; i < boundary_.size(); ++i) boundary_g_[i] = sample(boundary_[i]);
  for (Piece& p : pieces_) p.center_g = sample(p.center);
  choose_modes(out);

  std::vector<Segment> segments;
  trace(polygons_, polygon_keys_, polygon_g_, out, segments);

  // Chain the segments into loops: every trace vertex starts one segment and ends one.
  std::vector<std::uint32_t> next(out.vertices.size(), kNone);
  for (const Segment& seg : segments) {
    if (next[seg.from] != kNone) throw std::logic_error("genmod: mesh_implicit: a trace vertex starts two segments");
    next[seg.from] = seg.to;
  }
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<char> seen(out.vertices.size(), 0);
  for (const Segment& seg : segments) {
    if (seen[seg.from]) continue;
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v = seg.from; !seen[v]; v = next[v]) {
      if (next[v] == kNone) throw std::logic_error("genmod: mesh_implicit: the trace of a cell is not closed");
      seen[v] = 1;
      loop.push_back(v);
    }
    loops.push_back(std::move(loop));
  }
  if (loops.size() <= 1) out.direct_pieces.clear();  // only a fallback needs them as fans
  if (loops.empty()) return;
  if (loops.size() == 1) {
    cone(cell, loops[0], out);
    return;
  }
  std::vector<PieceId> direct = std::move(out.direct_pieces);
  out = CellOutput{};
  out.multi_loop = true;
  out.wants_split = true;
  if (!direct.empty()) {
    out.direct_pieces = std::move(direct);  // meshed again once these are fans
    return;
  }
  tetrahedra(cell, out);
}

void CellMesher::side_points(const Cell& cell, const Octree::Neighborhood& nb, int axis,
                             const std::array<std::uint32_t, 3>& on, std::uint32_t t0, std::uint32_t t1) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // An edge of the cell itself whose three other cells around it are leaves has no points.
  if (t1 - t0 == cell.size()) {
    bool leaves = true;
    const std::int64_t size = cell.size();
    for (int quadrant = 0; quadrant < 4 && leaves; ++quadrant) {
      int offset[3] = {0, 0, 0};
      const std::int64_t qu = static_cast<std::int64_t>(on[u]) - (quadrant & 1 ? size : 0);
      const std::int64_t qv = static_cast<std::int64_t>(on[v]) - (quadrant & 2 ? size : 0);
      offset[u] = qu < cell.corner[u] ? -1 : qu >= cell.corner[u] + size ? 1 : 0;
      offset[v] = qv < cell.corner[v] ? -1 : qv >= cell.corner[v] + size ? 1 : 0;
      const std::uint32_t n = nb[static_cast<std::size_t>(9 * (offset[2] + 1) + 3 * (offset[1] + 1) + (offset[0] + 1))];
      leaves = n == kNone || ctx_.octree->cell(n).kind != CellKind::Internal;
    }
    if (leaves) {
      line_points_.clear();
      return;
    }
  }
  // Each side is asked for by the two faces (or pieces) that share it: remember the answers.
  const Side key{axis, on[u], on[v], t0, t1, 0, 0};
  for (const Side& sd : sides_)
    if (sd.axis == key.axis && sd.a == key.a && sd.b == key.b && sd.t0 == t0 && sd.t1 == t1) {
      line_points_.assign(side_store_.begin() + sd.first, side_store_.begin() + sd.first + sd.count);
      return;
    }
  ctx_.octree->points_on_segment(cell, nb, axis, on, t0, t1, line_points_);
  Side added = key;
  added.first = static_cast<std::uint32_t>(side_store_.size());
  added.count = static_cast<std::uint32_t>(line_points_.size());
  side_store_.insert(side_store_.end(), line_points_.begin(), line_points_.end());
  sides_.push_back(added);
}

void CellMesher::gather_pieces(const Cell& cell) {
  const Octree& tree = *ctx_.octree;
  pieces_.clear();
  boundary_.clear();
  sample_keys_.clear();
  sides_.clear();
  side_store_.clear();
  const Octree::Neighborhood nb = tree.neighborhood(cell);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side : {-1, 1}) {
      const std::uint32_t w = cell.corner[axis] + (side > 0 ? cell.size() : 0);
      tree.face_pieces(cell, nb, axis, side, rects_);
      for (const auto& rect : rects_) {
        auto at = [&](std::uint32_t pu, std::uint32_t pv) {
          std::array<std::uint32_t, 3> q{};
          q[axis] = w;
          q[u] = pu;
          q[v] = pv;
          return q;
        };
        const std::uint32_t u0 = rect[0], v0 = rect[1], u1 = rect[2], v1 = rect[3];
        Piece p;
        p.axis = axis;
        p.center = pack(at((u0 + u1) / 2, (v0 + v1) / 2));
        p.half = (u1 - u0) / 2;
        p.region = {ctx_.frame->point(at(u0, v0)), ctx_.frame->point(at(u1, v1))};
        p.first = static_cast<std::uint32_t>(boundary_.size());
        p.fan = false;
        // Counter-clockwise in (u, v), i.e. seen from +axis; reversed below for side -1.
        boundary_.push_back(pack(at(u0, v0)));
        side_points(cell, nb, u, at(u0, v0), u0, u1);
        for (std::uint32_t t : line_points_) boundary_.push_back(pack(at(t, v0)));
        boundary_.push_back(pack(at(u1, v0)));
        side_points(cell, nb, v, at(u1, v0), v0, v1);
        for (std::uint32_t t : line_points_) boundary_.push_back(pack(at(u1, t)));
        boundary_.push_back(pack(at(u1, v1)));
        side_points(cell, nb, u, at(u0, v1), u0, u1);
        for (auto it = line_points_.rbegin(); it != line_points_.rend(); ++it) boundary_.push_back(pack(at(*it, v1)));
        boundary_.push_back(pack(at(u0, v1)));
        side_points(cell, nb, v, at(u0, v0), v0, v1);
        for (auto it = line_points_.rbegin(); it != line_points_.rend(); ++it) boundary_.push_back(pack(at(u0, *it)));
        p.count = static_cast<std::uint32_t>(boundary_.size()) - p.first;
        if (side < 0) std::reverse(boundary_.begin() + p.first, boundary_.end());
        sample_keys_.push_back(p.center);
        sample_keys_.insert(sample_keys_.end(), boundary_.begin() + p.first, boundary_.end());
        pieces_.push_back(p);
      }
    }
  }
  const std::uint32_t h = cell.size() / 2;
  sample_keys_.push_back(pack(cell.corner[0] + h, cell.corner[1] + h, cell.corner[2] + h));
  std::sort(sample_keys_.begin(), sample_keys_.end());
  sample_keys_.erase(std::unique(sample_keys_.begin(), sample_keys_.end()), sample_keys_.end());
}

double CellMesher::sample(Key k) const {
  const auto it = std::lower_bound(sample_keys_.begin(), sample_keys_.end(), k);
  if (it == sample_keys_.end() || *it != k) throw std::logic_error("genmod: mesh_implicit: a sample is missing");
  return sample_g_[static_cast<std::size_t>(it - sample_keys_.begin())];
}


void CellMesher::add_fan_triangles(const Piece& p, std::vector<Polygon>& polygons, std::vector<Key>& keys,
                                   std::vector<double>& values) const {
  for (std::uint32_t i = 0; i < p.count; ++i) {
    const std::uint32_t j = p.first + i, k = p.first + (i + 1) % p.count;
    const Key b0 = boundary_[j], b1 = boundary_[k];
    values.insert(values.end(), {p.center_g, boundary_g_[j], boundary_g_[k]});
    Polygon t;
    t.first = static_cast<std::uint32_t>(keys.size());
    t.count = 3;
    t.axis = p.axis;
    t.outer = true;
    t.feature_key = {VertexKind::FacePoint, p.center, std::min(b0, b1), std::max(b0, b1)};
    t.region = p.region;
    keys.insert(keys.end(), {p.center, b0, b1});
    polygons.push_back(t);
  }
}

void CellMesher::choose_modes(CellOutput& out) {
  polygons_.clear();
  polygon_keys_.clear();
  polygon_g_.clear();
  for (Piece& p : pieces_) {
    int crossings = 0;
    for (std::uint32_t i = 0; i < p.count; ++i)
      crossings += is_inside(boundary_g_[p.first + i]) != is_inside(boundary_g_[p.first + (i + 1) % p.count]);
    const bool forced = std::binary_search(ctx_.fan_pieces->begin(), ctx_.fan_pieces->end(),
                                           PieceId{p.center, static_cast<std::uint8_t>(p.axis), p.half});
    if (crossings == 0) {
      // Only the center can show an island inside the piece.
      p.fan = is_inside(p.center_g) != is_inside(boundary_g_[p.first]);
    } else {
      p.fan = forced || crossings != 2;
    }
    if (p.fan) {
      add_fan_triangles(p, polygons_, polygon_keys_, polygon_g_);
    } else if (crossings == 2) {
      Polygon d;
      d.first = static_cast<std::uint32_t>(polygon_keys_.size());
      d.count = p.count;
      d.axis = p.axis;
      d.outer = true;
      d.feature_key = {VertexKind::FacePoint, p.center, kNoKey, static_cast<Key>(p.axis)};
      d.region = p.region;
      polygon_keys_.insert(polygon_keys_.end(), boundary_.begin() + p.first, boundary_.begin() + p.first + p.count);
      polygon_g_.insert(polygon_g_.end(), boundary_g_.begin() + p.first, boundary_g_.begin() + p.first + p.count);
      polygons_.push_back(d);
      out.direct_pieces.push_back({p.center, static_cast<std::uint8_t>(p.axis), p.half});
    }
  }
}

void CellMesher::evaluate(std::span<const Vec3> points, std::vector<double>& g, std::vector<double>* f) {
  const std::size_t n = points.size();
  xs_.resize(n);
  ys_.resize(n);
  zs_.resize(n);
  fs_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    xs_[i] = points[i][0];
    ys_[i] = points[i][1];
    zs_[i] = points[i][2];
  }
  const double* in[3] = {xs_.data(), ys_.data(), zs_.data()};
  double* outp[1] = {fs_.data()};
  if (n > 0) batch_.eval(tapes_->value, in, n, outp);
  g.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double c = ctx_.frame->clip(points[i]);
    g[i] = std::isnan(fs_[i]) ? fs_[i] : std::max(fs_[i], c);
  }
  if (f) f->assign(fs_.begin(), fs_.end());
}

void CellMesher::normals(std::span<const Vec3> points, std::span<const double> f, std::span<const Region> regions,
                         std::vector<Vec3>& out, std::vector<double>* lengths, std::vector<char>* symbolic) {
  const std::size_t n = points.size();
  xs_.resize(n);
  ys_.resize(n);
  zs_.resize(n);
  gx_.resize(n);
  gy_.resize(n);
  gz_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    xs_[i] = points[i][0];
    ys_[i] = points[i][1];
    zs_[i] = points[i][2];
  }
  const double* in[3] = {xs_.data(), ys_.data(), zs_.data()};
  double* outp[3] = {gx_.data(), gy_.data(), gz_.data()};
  if (n > 0) batch_.eval(tapes_->gradient, in, n, outp);
  out.resize(n);
  if (lengths) lengths->assign(n, 0.0);
  if (symbolic) symbolic->assign(n, 1);
  // Points whose symbolic gradient is unusable (a formula like |max(q, 0)| has 0/0 in its
  // derivative where it is flat) get central differences.
  std::vector<std::uint32_t> fallback;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 g = f[i] >= ctx_.frame->clip(points[i]) ? Vec3{gx_[i], gy_[i], gz_[i]}
                                                       : ctx_.frame->clip_gradient(points[i]);
    const double len = std::sqrt(dot(g, g));
    if (len > 0 && std::isfinite(len)) {
      out[i] = {g[0] / len, g[1] / len, g[2] / len};
      if (lengths) (*lengths)[i] = len;
    } else {
      fallback.push_back(static_cast<std::uint32_t>(i));
    }
  }
  if (fallback.empty()) return;
  fd_points_.clear();
  std::vector<std::array<double, 3>> spans;  // per fallback point and axis: b - a (0 = no step)
  for (std::uint32_t i : fallback) {
    const Region& r = regions.size() == 1 ? regions[0] : regions[i];
    // The step depends on the region only, so cells sharing a face piece agree.
    const double step = 1e-6 * std::max({r.hi[0] - r.lo[0], r.hi[1] - r.lo[1], r.hi[2] - r.lo[2]});
    std::array<double, 3> sp{};
    for (int k = 0; k < 3; ++k) {
      Vec3 a = points[i], b = points[i];
      a[k] = std::clamp(a[k] - step, r.lo[k], r.hi[k]);
      b[k] = std::clamp(b[k] + step, r.lo[k], r.hi[k]);
      sp[static_cast<std::size_t>(k)] = b[k] - a[k];
      fd_points_.push_back(a);
      fd_points_.push_back(b);
    }
    spans.push_back(sp);
  }
  evaluate(fd_points_, fd_g_);
  for (std::size_t j = 0; j < fallback.size(); ++j) {
    const std::uint32_t i = fallback[j];
    Vec3 g{0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      const double d = fd_g_[6 * j + 2 * static_cast<std::size_t>(k) + 1] - fd_g_[6 * j + 2 * static_cast<std::size_t>(k)];
      if (spans[j][static_cast<std::size_t>(k)] > 0 && std::isfinite(d)) g[k] = d / spans[j][static_cast<std::size_t>(k)];
    }
    const double len = std::sqrt(dot(g, g));
    const bool ok = len > 0 && std::isfinite(len);
    out[i] = ok ? Vec3{g[0] / len, g[1] / len, g[2] / len} : Vec3{0, 0, 0};
    if (lengths) (*lengths)[i] = ok ? len : 0.0;
    if (symbolic) (*symbolic)[i] = 0;
  }
}

void CellMesher::find_roots(std::span<const Vec3> a, std::span<const Vec3> b, std::span<const double> ga,
                            std::span<const double> gb, std::vector<double>& t, std::vector<double>& error) {
  // Illinois (modified regula falsi) on all segments at once, with bisection when the outside
  // value is an error or the bracket stops shrinking fast.
  const std::size_t n = a.size();
  RootScratch& rs = roots_;
  auto& lo = rs.lo;
  auto& hi = rs.hi;
  auto& flo = rs.flo;
  auto& fhi = rs.fhi;
  auto& length = rs.length;
  auto& last_width = rs.last_width;
  auto& side = rs.side;
  auto& active = rs.active;
  auto& trial_points = rs.trial_points;
  auto& trial_t = rs.trial_t;
  auto& trial_g = rs.trial_g;
  auto& still = rs.still;
  lo.assign(n, 0.0);
  hi.assign(n, 1.0);
  flo.assign(ga.begin(), ga.end());
  fhi.assign(gb.begin(), gb.end());
  length.resize(n);
  last_width.assign(n, 2.0);
  side.assign(n, 0);
  active.clear();
  for (std::size_t i = 0; i < n; ++i) {
    length[i] = distance(a[i], b[i]);
    if (length[i] > ctx_.root_tolerance) active.push_back(static_cast<std::uint32_t>(i));
  }
  for (int iteration = 0; iteration < 100 && !active.empty(); ++iteration) {
    trial_points.clear();
    trial_t.clear();
    for (std::uint32_t i : active) {
      const double w = hi[i] - lo[i];
      double s = 0.5 * (lo[i] + hi[i]);
      const bool regula = std::isfinite(fhi[i]) && w < 0.75 * last_width[i];
      if (regula) {
        const double r = lo[i] + w * (flo[i] / (flo[i] - fhi[i]));
        if (r > lo[i] + 0.01 * w && r < hi[i] - 0.01 * w) s = r;
      }
      last_width[i] = regula ? w : 2.0 * w;  // after a bisection, regula falsi again
      trial_t.push_back(s);
      trial_points.push_back(lerp(a[i], b[i], s));
    }
    evaluate(trial_points, trial_g);
    still.clear();
    for (std::size_t k = 0; k < active.size(); ++k) {
      const std::uint32_t i = active[k];
      const double s = trial_t[k], v = trial_g[k];
      if (is_inside(v)) {
        lo[i] = s;
        flo[i] = v;
        if (side[i] == -1) fhi[i] *= 0.5;  // Illinois: halve the stale end
        side[i] = -1;
      } else {
        hi[i] = s;
        fhi[i] = v;
        if (side[i] == 1) flo[i] *= 0.5;
        side[i] = 1;
      }
      if ((hi[i] - lo[i]) * length[i] > ctx_.root_tolerance) still.push_back(i);
    }
    active.swap(still);
  }
  t.resize(n);
  error.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 0.5 * (lo[i] + hi[i]);
    error[i] = 0.5 * (hi[i] - lo[i]) * length[i];
  }
}

std::uint32_t CellMesher::vertex(CellOutput& out, const VertexKey& key, const Vec3& p, double error) {
  for (std::size_t i = 0; i < out.vertices.size(); ++i)
    if (out.vertices[i].key == key) return static_cast<std::uint32_t>(i);
  out.vertices.push_back({key, p, error});
  return static_cast<std::uint32_t>(out.vertices.size() - 1);
}

void CellMesher::trace(const std::vector<Polygon>& polygons, const std::vector<Key>& keys,
                       const std::vector<double>& values, CellOutput& out, std::vector<Segment>& segments) {
  const Frame& frame = *ctx_.frame;
  auto key_at = [&](const Polygon& p, std::uint32_t i) { return keys[p.first + i % p.count]; };
  auto in_at = [&](const Polygon& p, std::uint32_t i) { return is_inside(values[p.first + i % p.count]); };
  auto g_at = [&](const Polygon& p, std::uint32_t i) { return values[p.first + i % p.count]; };
  // Polygon edges with a sign change, inside end first.
  std::vector<Root> roots;
  for (const Polygon& poly : polygons)
    for (std::uint32_t j = 0; j < poly.count; ++j) {
      const Key p = key_at(poly, j), q = key_at(poly, j + 1);
      const bool ip = in_at(poly, j), iq = in_at(poly, j + 1);
      if (ip != iq)
        roots.push_back(ip ? Root{p, q, g_at(poly, j), g_at(poly, j + 1)} : Root{q, p, g_at(poly, j + 1), g_at(poly, j)});
    }
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  const std::size_t nr = roots.size();
  std::vector<Vec3> a(nr), b(nr);
  std::vector<double> ga(nr), gb(nr), t, error;
  for (std::size_t i = 0; i < nr; ++i) {
    a[i] = frame.point(roots[i].in);
    b[i] = frame.point(roots[i].out);
    ga[i] = roots[i].g_in;
    gb[i] = roots[i].g_out;
  }
  find_roots(a, b, ga, gb, t, error);
  std::vector<Vec3> points(nr);
  for (std::size_t i = 0; i < nr; ++i) points[i] = lerp(a[i], b[i], t[i]);
  std::vector<double> g, f;
  std::vector<Vec3> normal3;
  std::vector<char> symbolic;
  evaluate(points, g, &f);
  const Region whole = cell_region();
  std::vector<double> lengths;
  normals(points, f, std::span(&whole, 1), normal3, &lengths, &symbolic);
  std::vector<std::uint32_t> root_vertex(nr);
  for (std::size_t i = 0; i < nr; ++i)
    root_vertex[i] = vertex(out, {VertexKind::EdgePoint, roots[i].in, roots[i].out, 0}, points[i], error[i]);
  normal_.assign(out.vertices.size(), Vec3{0, 0, 0});
  grad_length_.assign(out.vertices.size(), 0.0);
  for (std::size_t i = 0; i < nr; ++i) {
    normal_[root_vertex[i]] = normal3[i];
    grad_length_[root_vertex[i]] = lengths[i];
  }
  auto root_of = [&](Key in, Key outk) {
    return static_cast<std::uint32_t>(std::lower_bound(roots.begin(), roots.end(), Root{in, outk, 0, 0}) - roots.begin());
  };

  // Entry (outside -> inside, walking counter-clockwise) and exit roots of each polygon.
  std::vector<std::array<std::uint32_t, 2>> crossing(polygons.size(), {kNone, kNone});
  for (std::size_t pi = 0; pi < polygons.size(); ++pi) {
    const Polygon& poly = polygons[pi];
    for (std::uint32_t j = 0; j < poly.count; ++j) {
      const Key p = key_at(poly, j), q = key_at(poly, j + 1);
      const bool ip = in_at(poly, j), iq = in_at(poly, j + 1);
      if (ip == iq) continue;
      std::uint32_t& slot = crossing[pi][ip ? 1 : 0];
      if (slot != kNone) throw std::logic_error("genmod: mesh_implicit: a trace polygon has more than one segment");
      slot = ip ? root_of(p, q) : root_of(q, p);
    }
  }

  // Feature points: where the tangent lines at a segment's two ends meet inside the polygon.
  // Computed from the polygon's data in a canonical order, so both cells on a face get the
  // same point, and kept only when a sign change within the tolerance certifies it.
  struct Candidate {
    std::size_t polygon;
    Vec3 q, plus, minus;
    double r_plus, r_minus;
  };
  std::vector<Candidate> candidates;
  std::vector<Point2> corners;
  for (std::size_t pi = 0; pi < polygons.size() && ctx_.sharp_features; ++pi) {
    const Polygon& poly = polygons[pi];
    if (crossing[pi][0] == kNone || !poly.outer) continue;
    const int axis = poly.axis, u = (axis + 1) % 3, v = (axis + 2) % 3;
    const std::uint32_t r1 = std::min(crossing[pi][0], crossing[pi][1]), r2 = std::max(crossing[pi][0], crossing[pi][1]);
    const Vec3& e1 = points[r1];
    const Vec3& e2 = points[r2];
    // Where the symbolic gradient fails, differences within the face piece (not the cell),
    // so that both cells on the face get the same normal.
    Vec3 n1 = normal3[r1], n2 = normal3[r2];
    if (!symbolic[r1] || !symbolic[r2]) {
      const Vec3 ends[2] = {e1, e2};
      const double fe[2] = {f[r1], f[r2]};
      std::vector<Vec3> in_plane;
      normals(ends, fe, std::span(&poly.region, 1), in_plane);
      if (!symbolic[r1]) n1 = in_plane[0];
      if (!symbolic[r2]) n2 = in_plane[1];
    }
    const Point2 m1{n1[u], n1[v]}, m2{n2[u], n2[v]};
    const double l1 = std::hypot(m1[0], m1[1]), l2 = std::hypot(m2[0], m2[1]);
    if (!(l1 > 1e-3) || !(l2 > 1e-3)) continue;
    if ((m1[0] * m2[0] + m1[1] * m2[1]) / (l1 * l2) > ctx_.feature_cos) continue;  // smooth
    const double det = m1[0] * m2[1] - m1[1] * m2[0];
    if (det == 0.0) continue;
    const double c1 = m1[0] * e1[u] + m1[1] * e1[v], c2 = m2[0] * e2[u] + m2[1] * e2[v];
    const Point2 q2{(c1 * m2[1] - c2 * m1[1]) / det, (m1[0] * c2 - m2[0] * c1) / det};
    corners.clear();
    for (std::uint32_t i = 0; i < poly.count; ++i) {
      const Vec3 pc = frame.point(key_at(poly, i));
      corners.push_back({pc[u], pc[v]});
    }
    const double size = std::max(poly.region.hi[u] - poly.region.lo[u], poly.region.hi[v] - poly.region.lo[v]);
    if (!inside_convex(q2, corners, 1e-6 * size)) continue;
    // Certification probes along the bisector of the two in-plane normals.
    Point2 d{m1[0] / l1 + m2[0] / l2, m1[1] / l1 + m2[1] / l2};
    const double dl = std::hypot(d[0], d[1]);
    if (!(dl > 1e-6)) continue;
    d = {d[0] / dl, d[1] / dl};
    const double rp = std::min(ctx_.tolerance, 0.999 * exit_parameter(q2, d, corners));
    const double rm = std::min(ctx_.tolerance, 0.999 * exit_parameter(q2, {-d[0], -d[1]}, corners));
    Vec3 q3 = e1;  // e1 lies on the face plane exactly: keep its axis coordinate
    q3[u] = q2[0];
    q3[v] = q2[1];
    Vec3 plus = q3, minus = q3;
    plus[u] += rp * d[0];
    plus[v] += rp * d[1];
    minus[u] -= rm * d[0];
    minus[v] -= rm * d[1];
    candidates.push_back({pi, q3, plus, minus, rp, rm});
  }
  std::vector<std::uint32_t> feature(polygons.size(), kNone);
  if (!candidates.empty()) {
    std::vector<Vec3> probe;
    for (const Candidate& c : candidates) probe.insert(probe.end(), {c.q, c.plus, c.minus});
    std::vector<double> pg;
    evaluate(probe, pg);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const double g0 = pg[3 * k], gp = pg[3 * k + 1], gm = pg[3 * k + 2];
      if (std::isnan(g0)) continue;
      double bound = -1.0;
      if (g0 == 0.0) bound = 0.0;
      else if (is_inside(g0) != is_inside(gp)) bound = candidates[k].r_plus;
      else if (is_inside(g0) != is_inside(gm)) bound = candidates[k].r_minus;
      if (bound < 0.0) continue;
      feature[candidates[k].polygon] = vertex(out, polygons[candidates[k].polygon].feature_key, candidates[k].q, bound);
    }
  }
  normal_.resize(out.vertices.size(), Vec3{0, 0, 0});
  grad_length_.resize(out.vertices.size(), 0.0);

  segments.clear();
  for (std::size_t pi = 0; pi < polygons.size(); ++pi) {
    if (crossing[pi][0] == kNone) continue;
    const std::uint32_t from = root_vertex[crossing[pi][0]], to = root_vertex[crossing[pi][1]];
    const auto index = static_cast<std::uint32_t>(pi);
    if (feature[pi] != kNone) {
      segments.push_back({from, feature[pi], index});
      segments.push_back({feature[pi], to, index});
    } else {
      segments.push_back({from, to, index});
    }
  }
}

CellMesher::ShrunkCell CellMesher::shrunk_cell() const {
  // A margin keeps moved vertices off the cell's faces, where the neighbours' vertices are.
  const double margin = 1e-4 * cell_size_;
  ShrunkCell c;
  for (int k = 0; k < 3; ++k) {
    c.lo[k] = cell_lo_[k] + margin;
    c.hi[k] = cell_hi_[k] - margin;
  }
  return c;
}

Vec3 CellMesher::ShrunkCell::clamp(const Vec3& p) const {
  Vec3 q;
  for (int k = 0; k < 3; ++k) q[k] = std::clamp(p[k], lo[k], hi[k]);
  return q;
}

double CellMesher::ShrunkCell::reach(const Vec3& x, const Vec3& d) const {
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] > 0) t = std::min(t, (hi[k] - x[k]) / d[k]);
    if (d[k] < 0) t = std::min(t, (lo[k] - x[k]) / d[k]);
  }
  return t;
}

bool CellMesher::snap(const Vec3& start, Vec3& apex, double& error) {
  // From `start` (inside the shrunk cell) along the gradient toward the other sign as far as
  // the shrunk cell allows; then the root between. The root is bracketed, so the vertex is
  // certified however far it moved.
  const ShrunkCell cell = shrunk_cell();
  const Vec3 x = cell.clamp(start);
  apex = x;
  std::vector<double> g, f;
  std::vector<Vec3> n;
  const Region whole = cell_region();
  evaluate(std::span(&x, 1), g, &f);
  if (g[0] == 0.0) {
    error = 0.0;
    return true;
  }
  normals(std::span(&x, 1), f, std::span(&whole, 1), n);
  if (!(dot(n[0], n[0]) > 0) || std::isnan(g[0])) return false;
  const double s = is_inside(g[0]) ? 1.0 : -1.0;  // toward the other sign
  const Vec3 dir{s * n[0][0], s * n[0][1], s * n[0][2]};
  const double reach = cell.reach(x, dir);
  const Vec3 y = cell.clamp({x[0] + reach * dir[0], x[1] + reach * dir[1], x[2] + reach * dir[2]});
  std::vector<double> gy;
  evaluate(std::span(&y, 1), gy);
  if (is_inside(gy[0]) == is_inside(g[0])) return false;
  const bool x_in = is_inside(g[0]);
  const Vec3& a = x_in ? x : y;
  const Vec3& b = x_in ? y : x;
  const double ga = x_in ? g[0] : gy[0], gb = x_in ? gy[0] : g[0];
  std::vector<double> t, err;
  find_roots(std::span(&a, 1), std::span(&b, 1), std::span(&ga, 1), std::span(&gb, 1), t, err);
  apex = lerp(a, b, t[0]);
  error = err[0];
  return true;
}

bool CellMesher::line_root(const Vec3& start, const Vec3& direction, Vec3& apex, double& error) {
  // The root nearest to `start` on the line through it along `direction`, inside the shrunk
  // cell, from samples across the cell.
  const double len = std::sqrt(dot(direction, direction));
  if (!(len > 0)) return false;
  const Vec3 d{direction[0] / len, direction[1] / len, direction[2] / len};
  const ShrunkCell cell = shrunk_cell();
  const double (&lo)[3] = cell.lo, (&hi)[3] = cell.hi;
  const Vec3 x = cell.clamp(start);
  double t_min = -std::numeric_limits<double>::infinity(), t_max = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] > 0) {
      t_max = std::min(t_max, (hi[k] - x[k]) / d[k]);
      t_min = std::max(t_min, (lo[k] - x[k]) / d[k]);
    } else if (d[k] < 0) {
      t_max = std::min(t_max, (lo[k] - x[k]) / d[k]);
      t_min = std::max(t_min, (hi[k] - x[k]) / d[k]);
    }
  }
  constexpr int kSamples = 8;
  std::vector<Vec3> p(2 * kSamples + 1);
  std::vector<double> t(p.size());
  for (int i = 0; i <= 2 * kSamples; ++i) {
    t[static_cast<std::size_t>(i)] = i < kSamples ? t_min * (kSamples - i) / kSamples : t_max * (i - kSamples) / kSamples;
    for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(i)][k] = std::clamp(x[k] + t[static_cast<std::size_t>(i)] * d[k], lo[k], hi[k]);
  }
  std::vector<double> g;
  evaluate(p, g);
  // Pairs of neighbouring samples with a sign change, nearest to the start (index kSamples).
  for (int step = 0; step < kSamples; ++step)
    for (int side : {1, -1}) {
      const int i = kSamples + side * step, j = i + side;
      if (j < 0 || j > 2 * kSamples) continue;
      const double gi = g[static_cast<std::size_t>(i)], gj = g[static_cast<std::size_t>(j)];
      if (std::isnan(gi) || std::isnan(gj) || is_inside(gi) == is_inside(gj)) continue;
      const bool i_in = is_inside(gi);
      const Vec3& a = p[static_cast<std::size_t>(i_in ? i : j)];
      const Vec3& b = p[static_cast<std::size_t>(i_in ? j : i)];
      const double ga = i_in ? gi : gj, gb = i_in ? gj : gi;
      std::vector<double> tr, err;
      find_roots(std::span(&a, 1), std::span(&b, 1), std::span(&ga, 1), std::span(&gb, 1), tr, err);
      apex = lerp(a, b, tr[0]);
      error = err[0];
      return true;
    }
  return false;
}

bool CellMesher::snap_in_tetrahedron(const Vec3& start, const Vec3 (&t)[4], Vec3& apex, double& error) {
  // Barycentric coordinates are affine: l(start + s d) = l(start) + s dl. Keep every one
  // above 1% of its value at the start, so the vertex stays strictly inside.
  const Vec3 e1 = sub(t[1], t[0]), e2 = sub(t[2], t[0]), e3 = sub(t[3], t[0]);
  const double det = dot(e1, cross(e2, e3));
  if (det == 0.0) return false;
  auto barycentric = [&](const Vec3& q, double l[4]) {
    const Vec3 r = sub(q, t[0]);
    l[1] = dot(r, cross(e2, e3)) / det;
    l[2] = dot(e1, cross(r, e3)) / det;
    l[3] = dot(e1, cross(e2, r)) / det;
    l[0] = 1.0 - l[1] - l[2] - l[3];
  };
  std::vector<double> g, f;
  std::vector<Vec3> n;
  const Region whole = cell_region();
  evaluate(std::span(&start, 1), g, &f);
  if (std::isnan(g[0])) return false;
  if (g[0] == 0.0) {
    apex = start;
    error = 0.0;
    return true;
  }
  normals(std::span(&start, 1), f, std::span(&whole, 1), n);
  if (!(dot(n[0], n[0]) > 0)) return false;
  double l0[4], l1[4];
  barycentric(start, l0);
  const double s = is_inside(g[0]) ? 1.0 : -1.0;
  const Vec3 d{s * n[0][0], s * n[0][1], s * n[0][2]};
  barycentric({start[0] + d[0], start[1] + d[1], start[2] + d[2]}, l1);
  double reach = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const double rate = l1[i] - l0[i];
    if (rate < 0) reach = std::min(reach, 0.99 * l0[i] / -rate);
  }
  if (!std::isfinite(reach) || !(reach > 0)) return false;
  const Vec3 y{start[0] + reach * d[0], start[1] + reach * d[1], start[2] + reach * d[2]};
  std::vector<double> gy;
  evaluate(std::span(&y, 1), gy);
  if (std::isnan(gy[0]) || is_inside(gy[0]) == is_inside(g[0])) return false;
  const bool x_in = is_inside(g[0]);
  const Vec3& a = x_in ? start : y;
  const Vec3& b = x_in ? y : start;
  const double ga = x_in ? g[0] : gy[0], gb = x_in ? gy[0] : g[0];
  std::vector<double> tr, err;
  find_roots(std::span(&a, 1), std::span(&b, 1), std::span(&ga, 1), std::span(&gb, 1), tr, err);
  apex = lerp(a, b, tr[0]);
  error = err[0];
  return true;
}

bool CellMesher::certify(const Vec3& start, std::span<const Vec3> normals, Vec3& apex, double& error) {
  // A sharp point stays where it is when g changes sign within the tolerance of it along the
  // mean of the normals that meet there.
  const double margin = 1e-4 * cell_size_;
  Vec3 x = start, n{0, 0, 0};
  for (const Vec3& m : normals)
    for (int k = 0; k < 3; ++k) n[k] += m[k];
  const double len = std::sqrt(dot(n, n));
  if (!(len > 0)) return false;
  for (int k = 0; k < 3; ++k) {
    x[k] = std::clamp(x[k], cell_lo_[k] + margin, cell_hi_[k] - margin);
    n[k] /= len;
  }
  Vec3 probe[3] = {x, x, x};
  for (int k = 0; k < 3; ++k) {
    probe[1][k] = std::clamp(x[k] + 0.999 * ctx_.tolerance * n[k], cell_lo_[k], cell_hi_[k]);
    probe[2][k] = std::clamp(x[k] - 0.999 * ctx_.tolerance * n[k], cell_lo_[k], cell_hi_[k]);
  }
  std::vector<double> g;
  evaluate(probe, g);
  if (std::isnan(g[0])) return false;
  apex = x;
  if (g[0] == 0.0) {
    error = 0.0;
    return true;
  }
  for (int side = 1; side <= 2; ++side)
    if (is_inside(g[side]) != is_inside(g[0])) {
      error = distance(x, probe[side]);
      return true;
    }
  return false;
}

bool CellMesher::root_in_tetrahedron(const Vec3& start, const Vec3 (&t)[4], Vec3& apex, double& error) {
  // Rays from `start` (strictly inside t) to 0.99 of the way to each corner stay strictly
  // inside; the polygon separates corners of both signs, so one of them crosses the surface.
  // The bracketed root nearest to `start` wins.
  constexpr int kSamples = 8;
  std::vector<Vec3> samples;
  samples.reserve(1 + 4 * kSamples);
  samples.push_back(start);
  for (const Vec3& corner : t)
    for (int i = 1; i <= kSamples; ++i) samples.push_back(lerp(start, corner, 0.99 * i / kSamples));
  return root_on_rays(samples, 4, kSamples, apex, error);
}

bool CellMesher::root_on_rays(std::span<const Vec3> samples, std::size_t rays, int per_ray, Vec3& apex,
                              double& error) {
  std::vector<double> g;
  evaluate(samples, g);
  if (std::isnan(g[0])) return false;
  if (g[0] == 0.0) {
    apex = samples[0];
    error = 0.0;
    return true;
  }
  std::vector<Vec3> a, b;
  std::vector<double> ga, gb;
  const auto n = static_cast<std::size_t>(per_ray);
  for (std::size_t r = 0; r < rays; ++r)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t u = i == 0 ? 0 : 1 + r * n + i - 1, v = 1 + r * n + i;
      if (std::isnan(g[u]) || std::isnan(g[v])) break;
      if (is_inside(g[u]) == is_inside(g[v])) continue;
      const bool u_in = is_inside(g[u]);
      a.push_back(samples[u_in ? u : v]);
      b.push_back(samples[u_in ? v : u]);
      ga.push_back(u_in ? g[u] : g[v]);
      gb.push_back(u_in ? g[v] : g[u]);
      break;
    }
  if (a.empty()) return false;
  std::vector<double> tr, err;
  find_roots(a, b, ga, gb, tr, err);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec3 q = lerp(a[i], b[i], tr[i]);
    const double d = distance(q, samples[0]);
    if (d < best) {
      best = d;
      apex = q;
      error = err[i];
    }
  }
  return true;
}

bool CellMesher::nearest_root(const Vec3& start, std::span<const Vec3> normals, Vec3& apex, double& error) {
  // Rays from `start` along both senses of each normal, of their mean and of the 26 lattice
  // directions, sampled out to the shrunk cell's boundary; on each ray the first pair of
  // neighbouring samples with a sign change brackets a root, and the root nearest to `start`
  // wins. At a crease the gradient of the active piece can lead out of the solid's wedge
  // (snap() then fails), while some of these rays cross into it near the crease.
  const ShrunkCell cell = shrunk_cell();
  const Vec3 x = cell.clamp(start);
  std::vector<Vec3> dirs;
  auto add_both_senses = [&](Vec3 d) {
    const double len = std::sqrt(dot(d, d));
    if (!(len > 0) || !std::isfinite(len)) return;
    for (int k = 0; k < 3; ++k) d[k] /= len;
    dirs.push_back(d);
    dirs.push_back({-d[0], -d[1], -d[2]});
  };
  Vec3 mean{0, 0, 0};
  for (const Vec3& n : normals) {
    add_both_senses(n);
    for (int k = 0; k < 3; ++k) mean[k] += n[k];
  }
  add_both_senses(mean);
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b)
      for (int c = -1; c <= 1; ++c) {
        const double len = std::sqrt(double(a * a + b * b + c * c));
        if (len > 0) dirs.push_back({a / len, b / len, c / len});
      }
  constexpr int kSamples = 8;
  std::vector<Vec3> samples;
  samples.reserve(1 + dirs.size() * kSamples);
  samples.push_back(x);
  for (const Vec3& d : dirs) {
    const double reach = cell.reach(x, d);  // finite: d is a unit vector
    for (int i = 1; i <= kSamples; ++i) {
      const double t = reach * i / kSamples;
      samples.push_back(cell.clamp({x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]}));
    }
  }
  return root_on_rays(samples, dirs.size(), kSamples, apex, error);
}

void CellMesher::cone(const Cell& cell, const std::vector<std::uint32_t>& loop, CellOutput& out) {
  // The apex: the quadric point of the loop's points with normals, or else the loop's
  // centroid, moved onto the surface along the gradient; the first candidate that lands on
  // the surface without folding a triangle against the loop's normals wins.
  std::vector<Vec3> pts, nrm;
  Vec3 centroid{0, 0, 0};
  for (std::uint32_t i : loop) {
    const Vec3& p = out.vertices[i].position;
    for (int k = 0; k < 3; ++k) centroid[k] += p[k] / static_cast<double>(loop.size());
    if (dot(normal_[i], normal_[i]) > 0) {
      pts.push_back(p);
      nrm.push_back(normal_[i]);
    }
  }
  // Candidates in order: a sharp quadric point (an edge or corner) where it is, then the
  // quadric point and the centroid moved onto the surface.
  struct Start {
    Vec3 point;
    bool in_place;
  };
  std::vector<Start> starts;
  int rank = 1;
  if (ctx_.sharp_features && !pts.empty()) {
    const QefPoint q = solve_qef(pts, nrm);
    rank = q.rank;
    if (q.rank >= 2) starts.push_back({q.point, true});
    starts.push_back({q.point, false});
  }
  // A smooth piece needs no interior vertex when its loop triangulates accurately.
  if (rank < 2 && triangulate_loop(out, loop, loop_triangles_)) {
    const Accuracy a = accuracy(out, loop_triangles_);
    if (!a.inaccurate && !a.folded) {
      out.triangles = loop_triangles_;
      return;
    }
  }
  starts.push_back({centroid, false});
  Vec3 mean{0, 0, 0};
  for (const Vec3& m : nrm)
    for (int k = 0; k < 3; ++k) mean[k] += m[k];
  auto folds = [&](const Vec3& apex) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const std::uint32_t a = loop[k], b = loop[(k + 1) % loop.size()];
      const Vec3 normal = cross(sub(out.vertices[a].position, apex), sub(out.vertices[b].position, apex));
      const Vec3 m{normal_[a][0] + normal_[b][0], normal_[a][1] + normal_[b][1], normal_[a][2] + normal_[b][2]};
      if (dot(normal, m) < 0) return true;
    }
    return false;
  };
  // Each candidate once; the first on the surface without a fold wins, else the first on the
  // surface, else the first.
  struct Candidate {
    Vec3 point;
    double error;  // < 0: not on the surface
    bool folds;
  };
  std::vector<Candidate> candidates;
  for (const Start& start : starts) {
    Candidate c{{}, -1.0, false};
    const bool on_surface = (start.in_place ? certify(start.point, nrm, c.point, c.error)
                                            : snap(start.point, c.point, c.error) ||
                                                  line_root(start.point, mean, c.point, c.error)) ||
                            nearest_root(start.point, nrm, c.point, c.error);
    if (!on_surface) c.error = -1.0;
    c.folds = folds(c.point);
    if (on_surface && !c.folds) {
      candidates.assign(1, c);
      break;
    }
    candidates.push_back(c);
  }
  std::size_t best = 0;
  auto find = [&](bool fold_free) {
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (candidates[i].error >= 0 && (!fold_free || !candidates[i].folds)) return i;
    return candidates.size();
  };
  if (const std::size_t i = find(true); i < candidates.size()) best = i;
  else if (const std::size_t j = find(false); j < candidates.size()) best = j;
  const Vec3 apex = candidates[best].point;
  const double apex_error = candidates[best].error;
  if (apex_error < 0) out.inaccurate = out.wants_split = true;
  const std::uint32_t apex_index = vertex(out, {VertexKind::Apex, pack(cell.corner), 0, 0}, apex, apex_error);
  for (std::size_t k = 0; k < loop.size(); ++k)
    out.triangles.push_back({apex_index, loop[k], loop[(k + 1) % loop.size()]});
  const Accuracy a = accuracy(out, out.triangles);
  out.inaccurate = out.inaccurate || a.inaccurate;
  out.folded = a.folded;
  out.wants_split = out.wants_split || a.inaccurate || a.folded;
}

CellMesher::Accuracy CellMesher::accuracy(const CellOutput& out, std::span<const std::array<std::uint32_t, 3>> triangles) {
  // |g| / |grad g| at the triangles' centroids and edge midpoints against the tolerance, with
  // |grad g| from the triangle's trace vertices; and triangles folded against their normals.
  std::vector<Vec3>& probes = probe_points_;
  probes.clear();
  std::vector<double> grad(triangles.size(), 0.0);
  Accuracy a;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    Vec3 c{0, 0, 0}, n{0, 0, 0};
    int known = 0;
    for (std::uint32_t i : tri) {
      for (int k = 0; k < 3; ++k) {
        c[k] += out.vertices[i].position[k] / 3.0;
        n[k] += i < normal_.size() ? normal_[i][k] : 0.0;
      }
      if (i < grad_length_.size() && grad_length_[i] > 0) {
        grad[t] += grad_length_[i];
        ++known;
      }
    }
    grad[t] = known ? grad[t] / known : 0.0;
    const Vec3 normal = cross(sub(out.vertices[tri[1]].position, out.vertices[tri[0]].position),
                              sub(out.vertices[tri[2]].position, out.vertices[tri[0]].position));
    if (dot(normal, n) < 0) a.folded = true;
    probes.push_back(c);
    for (int e = 0; e < 3; ++e) {
      const Vec3& p = out.vertices[tri[e]].position;
      const Vec3& q = out.vertices[tri[(e + 1) % 3]].position;
      probes.push_back({0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])});
    }
  }
  std::vector<double> gp;
  evaluate(probes, gp);
  for (std::size_t i = 0; i < probes.size(); ++i)
    if (!(std::fabs(gp[i]) <= ctx_.tolerance * grad[i / 4])) a.inaccurate = true;
  return a;
}

bool CellMesher::triangulate_loop(const CellOutput& out, const std::vector<std::uint32_t>& loop,
                                  std::vector<std::array<std::uint32_t, 3>>& triangles) {
  // The loop without an interior vertex, by ear clipping in the plane of its mean normal.
  // Valid when (checked here) the loop projects to a simple counter-clockwise polygon and no
  // triangle edge other than a loop segment lies in a face plane of the cell: then every
  // triangle meets the cell's boundary only in the loop, and triangles of the cell project
  // to disjoint regions, so they cannot cross.
  const std::size_t n = loop.size();
  triangles.clear();
  Vec3 nm{0, 0, 0};
  for (std::uint32_t i : loop)
    for (int k = 0; k < 3; ++k) nm[k] += normal_[i][k];
  const double len = std::sqrt(dot(nm, nm));
  if (!(len > 0.5 * static_cast<double>(n))) return false;  // normals spread too wide
  for (double& c : nm) c /= len;
  // An orthonormal basis (e1, e2) of the plane.
  const int a = std::fabs(nm[0]) < 0.6 ? 0 : 1;
  Vec3 e1{0, 0, 0};
  e1[a] = 1;
  const double d = dot(e1, nm);
  for (int k = 0; k < 3; ++k) e1[k] -= d * nm[k];
  const double l1 = std::sqrt(dot(e1, e1));
  for (double& c : e1) c /= l1;
  const Vec3 e2 = cross(nm, e1);
  std::vector<Point2> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& v = out.vertices[loop[i]].position;
    p[i] = {dot(v, e1), dot(v, e2)};
  }
  const double eps = 1e-9 * cell_size_ * cell_size_;
  // Simple: no two non-adjacent segments meet (with a margin).
  auto crosses = [&](const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
    const double d1 = cross2(a0, a1, b0), d2 = cross2(a0, a1, b1), d3 = cross2(b0, b1, a0), d4 = cross2(b0, b1, a1);
    if (std::fabs(d1) < eps || std::fabs(d2) < eps || std::fabs(d3) < eps || std::fabs(d4) < eps) return true;
    return (d1 > 0) != (d2 > 0) && (d3 > 0) != (d4 > 0);
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (crosses(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  double area = 0;
  for (std::size_t i = 0; i < n; ++i) area += cross2(p[0], p[i], p[(i + 1) % n]);
  if (!(area > 0)) return false;  // the loop must turn counter-clockwise about the normal
  // The face planes a vertex lies on (bit 2k: low side of axis k, 2k + 1: high side).
  std::vector<unsigned> planes(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const double c = out.vertices[loop[i]].position[k];
      if (c == cell_lo_[k]) planes[i] |= 1u << (2 * k);
      if (c == cell_hi_[k]) planes[i] |= 1u << (2 * k + 1);
    }
  std::vector<std::size_t> idx(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = i;
  while (idx.size() > 3) {
    bool clipped = false;
    const std::size_t m = idx.size();
    for (std::size_t k = 0; k < m && !clipped; ++k) {
      const std::size_t i0 = idx[(k + m - 1) % m], i1 = idx[k], i2 = idx[(k + 1) % m];
      if (!(cross2(p[i0], p[i1], p[i2]) > eps)) continue;  // reflex or flat
      if (planes[i0] & planes[i2]) continue;               // the chord would lie in a face
      bool empty = true;
      for (std::size_t j : idx) {
        if (j == i0 || j == i1 || j == i2) continue;
        if (cross2(p[i0], p[i1], p[j]) >= -eps && cross2(p[i1], p[i2], p[j]) >= -eps && cross2(p[i2], p[i0], p[j]) >= -eps) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      triangles.push_back({loop[i0], loop[i1], loop[i2]});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>((k) % m));
      clipped = true;
    }
    if (!clipped) return false;
  }
  if (!(cross2(p[idx[0]], p[idx[1]], p[idx[2]]) > eps)) return false;
  triangles.push_back({loop[idx[0]], loop[idx[1]], loop[idx[2]]});
  return true;
}

void CellMesher::tetrahedra(const Cell& cell, CellOutput& out) {
  // Every fan triangle (fc, b_i, b_j) of the cell's pieces with the cell center cc is a
  // tetrahedron; its faces, counter-clockwise seen from outside it: (fc, b_i, b_j),
  // (fc, b_j, cc), (fc, cc, b_i), (b_j, b_i, cc).
  const std::uint32_t h = cell.size() / 2;
  const Key cc = pack(cell.corner[0] + h, cell.corner[1] + h, cell.corner[2] + h);
  std::vector<Polygon> outer, faces;
  std::vector<Key> keys;
  std::vector<double> values;
  for (const Piece& p : pieces_) add_fan_triangles(p, outer, keys, values);
  const double gcc = sample(cc);
  for (const Polygon& t : outer) {
    faces.push_back(t);
    const Key fc = keys[t.first], b0 = keys[t.first + 1], b1 = keys[t.first + 2];
    for (const std::array<Key, 3>& inner : {std::array<Key, 3>{fc, b1, cc}, std::array<Key, 3>{fc, cc, b0},
                                            std::array<Key, 3>{b1, b0, cc}}) {
      Polygon q = t;
      q.first = static_cast<std::uint32_t>(keys.size());
      q.outer = false;
      keys.insert(keys.end(), inner.begin(), inner.end());
      for (Key k : inner) {
        const double v = k == cc ? gcc : values[t.first + (k == fc ? 0 : k == b0 ? 1 : 2)];
        values.push_back(v);
      }
      faces.push_back(q);
    }
  }
  std::vector<Segment> segments;
  trace(faces, keys, values, out, segments);
  // Segments come in polygon order, so each tetrahedron's are consecutive.
  std::vector<std::uint32_t> polygon;
  for (std::size_t s = 0; s < segments.size();) {
    const std::uint32_t tet = segments[s].polygon / 4;
    std::size_t e = s;
    while (e < segments.size() && segments[e].polygon / 4 == tet) ++e;
    polygon.assign(1, segments[s].from);
    while (true) {
      std::size_t k = s;
      while (k < e && segments[k].from != polygon.back()) ++k;
      if (k == e) throw std::logic_error("genmod: mesh_implicit: a tetrahedron's trace is not closed");
      if (segments[k].to == polygon.front()) break;
      polygon.push_back(segments[k].to);
      if (polygon.size() > e - s) throw std::logic_error("genmod: mesh_implicit: a tetrahedron's trace is not one loop");
    }
    bool plain = true;  // only roots on edges: marching tetrahedra's triangle or quad
    for (std::uint32_t i : polygon) plain = plain && out.vertices[i].key.kind == VertexKind::EdgePoint;
    if (polygon.size() == 3) {
      out.triangles.push_back({polygon[0], polygon[1], polygon[2]});
    } else if (polygon.size() == 4 && plain) {
      // Split along the shorter diagonal.
      const auto& v = out.vertices;
      const bool first = distance(v[polygon[0]].position, v[polygon[2]].position) <=
                         distance(v[polygon[1]].position, v[polygon[3]].position);
      const std::uint32_t a = polygon[first ? 0 : 1], b = polygon[first ? 1 : 2], c = polygon[first ? 2 : 3],
                          d = polygon[first ? 3 : 0];
      out.triangles.push_back({a, b, c});
      out.triangles.push_back({a, c, d});
    } else {
      // The cone from the centroid of the polygon, strictly inside the tetrahedron because
      // the polygon does not lie in one of its faces.
      Vec3 c{0, 0, 0};
      for (std::uint32_t i : polygon)
        for (int k = 0; k < 3; ++k) c[k] += out.vertices[i].position[k] / static_cast<double>(polygon.size());
      const Key* t = &keys[outer[tet].first];
      const Vec3 corners[4] = {ctx_.frame->point(cc), ctx_.frame->point(t[0]), ctx_.frame->point(t[1]),
                               ctx_.frame->point(t[2])};
      Vec3 p = c;
      double error = -1.0;
      if (!snap_in_tetrahedron(c, corners, p, error) && !root_in_tetrahedron(c, corners, p, error)) p = c;
      const std::uint32_t apex = vertex(out, {VertexKind::TetApex, t[0], t[1], t[2]}, p, error);
      for (std::size_t k = 0; k < polygon.size(); ++k)
        out.triangles.push_back({apex, polygon[k], polygon[(k + 1) % polygon.size()]});
    }
    s = e;
  }
}

}  // namespace genmod::implicit
