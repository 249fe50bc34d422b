#include "genmod/solvers/cpg.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/branching.hpp"
#include "genmod/operators/offset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("genmod: region_boolean: " + what); }

std::string where(double px, double py) {
  std::ostringstream s;
  s << "(" << px << ", " << py << ")";
  return s.str();
}

// Point values of a curve of x(0) (or a constant), compiled once.
class Sampler {
 public:
  explicit Sampler(const Fn& f) : tape_(f), arg_(tape_.inputs().size(), 0.0) {}
  std::array<double, 2> operator()(double u) {
    std::fill(arg_.begin(), arg_.end(), u);
    const auto y = ev_.eval(tape_, arg_);
    return {y[0], y[1]};
  }

 private:
  Tape tape_;
  PointEvaluator ev_;
  std::vector<double> arg_;
};

double circular_gap(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, 1.0 - d);
}

void validate(const Fn& c, const char* name) {
  if (c.dim() != 2) fail(std::string(name) + " is not planar (dimension " + std::to_string(c.dim()) + ")");
  if (c.input_mask() != 1u) fail(std::string(name) + " is not a curve of x(0) alone");
  Sampler at(c);
  const auto p0 = at(0.0), p1 = at(1.0);
  const double gap = std::hypot(p1[0] - p0[0], p1[1] - p0[1]);
  if (!(gap <= 1e-8 * (1.0 + std::hypot(p0[0], p0[1]))))
    fail(std::string(name) + " is not closed (|" + name + "(1) - " + name + "(0)| = " + std::to_string(gap) + ")");
  double area = 0.0;  // shoelace on samples: the sign gives the orientation
  constexpr int n = 512;
  auto prev = p0;
  for (int i = 1; i <= n; ++i) {
    const auto p = at(static_cast<double>(i) / n);
    area += prev[0] * p[1] - p[0] * prev[1];
    prev = p;
  }
  if (!(area > 0.0)) fail(std::string(name) + " is not counter-clockwise (signed area " + std::to_string(area / 2) + ")");
}

struct Hit {
  double s, t;  // parameters on a and b, in [0, 1]
};

// Interval Newton cannot certify hits on curves whose derivative inclusion is loose or
// piecewise (polylines: curve_intersections reports their tiny hit boxes uncertified). Such a hit
// is accepted when the point tangents there are clearly not parallel (a tangency is refused).
bool transversal(const Fn& a, const Fn& b, double s, double t) {
  Sampler da(derivative(a, 0)), db(derivative(b, 0));
  const auto u = da(s), v = db(t);
  const double cross = u[0] * v[1] - u[1] * v[0];
  return std::abs(cross) > 1e-6 * std::hypot(u[0], u[1]) * std::hypot(v[0], v[1]);
}

// The hits of curve_intersections with the closing-point duplicates (s or t at both 0 and 1)
// merged; every remaining hit must be certified.
std::vector<Hit> crossings(const Fn& a, const Fn& b, const QueryOptions& q, const char* what) {
  const CurveIntersections found = curve_intersections(a, b, Interval(0, 1), Interval(0, 1), q);
  if (!found.complete) fail(std::string("a search limit was hit while intersecting ") + what);
  std::vector<Hit> hits;
  std::vector<bool> certified;
  for (const CurveHit& h : found.hits) {
    const Hit hit{h.s.mid(), h.t.mid()};
    bool merged = false;
    for (std::size_t k = 0; k < hits.size(); ++k)
      if (circular_gap(hits[k].s, hit.s) < 1e-6 && circular_gap(hits[k].t, hit.t) < 1e-6) {
        certified[k] = certified[k] || h.certified;
        merged = true;
      }
    if (merged) continue;
    hits.push_back(hit);
    certified.push_back(h.certified);
  }
  for (std::size_t k = 0; k < hits.size(); ++k)
    if (!certified[k] && !transversal(a, b, hits[k].s, hits[k].t)) {
      Sampler at(a);
      const auto p = at(hits[k].s);
      fail(std::string("an intersection of ") + what + " near " + where(p[0], p[1]) +
           " is not certified (a tangency or touching point)");
    }
  return hits;
}

// Is p inside the closed curve `boundary`? Parity of the certified crossings of a ray from p;
// rays meeting the boundary uncertifiably (tangent, through a closing point) are replaced.
bool inside(const Fn& boundary, std::array<double, 2> p, const QueryOptions& q) {
  Sampler at(boundary);
  double reach = 0.0;
  for (int i = 0; i < 256; ++i) {
    const auto c = at(i / 256.0);
    reach = std::max(reach, std::hypot(c[0] - p[0], c[1] - p[1]));
  }
  const double length = 2.0 * reach + 1.0;  // beyond every point of the boundary
  bool limit = false;
  for (int attempt = 0; attempt < 8; ++attempt) {
    const double angle = 0.7 + 2.399963 * attempt;  // golden-angle steps: unrelated directions
    const Fn ray = cat({p[0] + length * std::cos(angle) * x(0), p[1] + length * std::sin(angle) * x(0)});
    const CurveIntersections found = curve_intersections(boundary, ray, Interval(0, 1), Interval(0, 1), q);
    if (!found.complete) {
      limit = true;
      continue;
    }
    std::vector<Hit> hits;
    bool ok = true;
    for (const CurveHit& h : found.hits) {
      const Hit hit{h.s.mid(), h.t.mid()};
      const bool dup = std::any_of(hits.begin(), hits.end(), [&](const Hit& o) {
        return circular_gap(o.s, hit.s) < 1e-6 && std::abs(o.t - hit.t) < 1e-6;
      });
      if (dup) continue;
      if ((!h.certified && !transversal(boundary, ray, hit.s, hit.t)) || hit.t < 1e-9) ok = false;
      hits.push_back(hit);
    }
    if (ok) return hits.size() % 2 == 1;
  }
  fail(std::string("could not classify the point ") + where(p[0], p[1]) +
       (limit ? ": a search limit was hit" : ": no ray met the other boundary transversally"));
}

// The sub-curve of the closed curve c from parameter p0 to p1 (either may lie outside [0, 1]
// by less than one period: the piece crosses c's closing point and is joined from both ends).
Fn piece(const Fn& c, double p0, double p1) {
  const Fn p = p0 + (p1 - p0) * x(0);
  const double lo = std::min(p0, p1), hi = std::max(p0, p1);
  if (lo >= 0.0 && hi <= 1.0) return compose(c, 0, p);
  if (hi > 1.0) return select(p <= 1.0, compose(c, 0, min(p, 1.0)), compose(c, 0, max(p - 1.0, 0.0)));
  return select(p >= 0.0, compose(c, 0, max(p, 0.0)), compose(c, 0, min(p + 1.0, 1.0)));
}

double polyline_length(const Fn& f) {
  Sampler at(f);
  double len = 0.0;
  auto prev = at(0.0);
  for (int i = 1; i <= 64; ++i) {
    const auto q = at(i / 64.0);
    len += std::hypot(q[0] - prev[0], q[1] - prev[1]);
    prev = q;
  }
  return len;
}

// Concatenation in x(0) with parameter shares proportional to `lengths` (near-uniform speed).
Fn concat_by_length(const std::vector<Fn>& parts, const std::vector<double>& lengths) {
  double total = 0.0;
  for (double l : lengths) total += l;
  std::vector<double> breaks{0.0};
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) breaks.push_back(breaks.back() + lengths[i] / total);
  breaks.push_back(1.0);
  const Fn u = x(0);
  std::vector<Fn> local;
  Fn which(0.0);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double w = breaks[i + 1] - breaks[i];
    local.push_back(compose(parts[i], 0, min(max((u - breaks[i]) / w, 0.0), 1.0)));
    if (i > 0) which += (u >= breaks[i]);
  }
  return index(local, which);
}

struct Segment {
  int curve;        // 0 = a, 1 = b
  double p0, p1;    // curve parameters at the start and end of travel
  int from, to;     // hit indices
  double lo = 0.0, hi = 1.0;  // the part kept (local parameter), trimmed by fillets
  Fn fn() const;
  const Fn* source = nullptr;
};

Fn Segment::fn() const { return piece(*source, p0 + (p1 - p0) * lo, p0 + (p1 - p0) * hi); }

}  // namespace

Fn region_boolean(const Fn& a, const Fn& b, RegionOp op, const CpgOptions& options) {
  validate(a, "a");
  validate(b, "b");
  const double r = options.fillet_radius;
  if (!std::isfinite(r) || r < 0.0) fail("the fillet radius must be finite and >= 0");
  const QueryOptions& q = options.query;

  const std::vector<Hit> hits = crossings(a, b, q, "the boundaries");
  const int n = static_cast<int>(hits.size());
  if (n == 0) fail("the curves do not intersect (disjoint, or one region inside the other)");
  if (n % 2 != 0) fail("the curves cross an odd number of times (" + std::to_string(n) + ")");

  // Pieces of each boundary between consecutive hits, classified against the other region.
  std::vector<Segment> selected;
  for (int c = 0; c < 2; ++c) {
    const Fn& self = c == 0 ? a : b;
    const Fn& other = c == 0 ? b : a;
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
    auto param = [&](int h) { return c == 0 ? hits[static_cast<std::size_t>(h)].s : hits[static_cast<std::size_t>(h)].t; };
    std::sort(order.begin(), order.end(), [&](int i, int j) { return param(i) < param(j); });
    Sampler at(self);
    std::vector<bool> in(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const int h0 = order[static_cast<std::size_t>(k)], h1 = order[static_cast<std::size_t>((k + 1) % n)];
      const double p0 = param(h0), p1 = k + 1 < n ? param(h1) : param(h1) + 1.0;
      const double mid = std::fmod(0.5 * (p0 + p1), 1.0);
      in[static_cast<std::size_t>(k)] = inside(other, at(mid), q);
      if (k > 0 && in[static_cast<std::size_t>(k)] == in[static_cast<std::size_t>(k - 1)])
        fail(std::string("the pieces of ") + (c == 0 ? "a" : "b") +
             " do not alternate inside / outside the other region (the curves do not cross transversally)");
      const bool want_inside = op == RegionOp::Intersection || (op == RegionOp::Difference && c == 1);
      if (in[static_cast<std::size_t>(k)] != want_inside) continue;
      Segment s{c, p0, p1, h0, h1};
      if (op == RegionOp::Difference && c == 1) s = Segment{c, p1, p0, h1, h0};
      s.source = &self;
      selected.push_back(s);
    }
  }

  // Link the segments hit to hit into loops; exactly one is accepted.
  std::vector<int> starting(static_cast<std::size_t>(n), -1);
  for (std::size_t i = 0; i < selected.size(); ++i) {
    int& slot = starting[static_cast<std::size_t>(selected[i].from)];
    if (slot >= 0) fail("two result pieces start at one intersection (inconsistent orientation?)");
    slot = static_cast<int>(i);
  }
  std::vector<bool> used(selected.size(), false);
  std::vector<Segment> loop;
  int loops = 0;
  for (std::size_t first = 0; first < selected.size(); ++first) {
    if (used[first]) continue;
    ++loops;
    for (int i = static_cast<int>(first); !used[static_cast<std::size_t>(i)];) {
      used[static_cast<std::size_t>(i)] = true;
      if (loops == 1) loop.push_back(selected[static_cast<std::size_t>(i)]);
      i = starting[static_cast<std::size_t>(selected[static_cast<std::size_t>(i)].to)];
      if (i < 0) fail("a result piece ends at an intersection where no piece starts (inconsistent orientation?)");
    }
  }
  if (loops != 1)
    fail("the result is not one closed curve: it has " + std::to_string(loops) + " boundary loops");

  std::vector<Fn> parts;
  std::vector<double> lengths;
  std::vector<Fn> arcs(loop.size());
  std::vector<double> arc_lengths(loop.size(), 0.0);
  if (r > 0.0) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      Segment& in = loop[k];
      Segment& out = loop[(k + 1) % loop.size()];
      const Fn fin = in.fn(), fout = out.fn();  // untrimmed here: each corner trims one end
      Sampler din(derivative(fin, 0)), dout(derivative(fout, 0)), pin(fin);
      const auto ti = din(1.0), to = dout(0.0), corner = pin(1.0);
      const double turn = ti[0] * to[1] - ti[1] * to[0];
      const bool convex = turn > 0.0;  // left turn: the center is inside, on the left of travel
      const double signed_r = convex ? r : -r;
      const Fn oin = offset_curve(fin, Fn(signed_r)), oout = offset_curve(fout, Fn(signed_r));
      // Search near the corner only: the feet lie about r tan(turn / 2) from it along each piece.
      const double cosine = (ti[0] * to[0] + ti[1] * to[1]) / (std::hypot(ti[0], ti[1]) * std::hypot(to[0], to[1]));
      const double reach = r * (1.0 + std::tan(0.5 * std::acos(std::clamp(cosine, -1.0, 1.0))));
      const double win_in = std::min(1.0, 3.0 * reach / std::hypot(ti[0], ti[1]));
      const double win_out = std::min(1.0, 3.0 * reach / std::hypot(to[0], to[1]));
      const CurveIntersections found =
          curve_intersections(oin, oout, Interval(1.0 - win_in, 1.0), Interval(0.0, win_out), q);
      if (!found.complete) fail("a search limit was hit while placing the fillet at " + where(corner[0], corner[1]));
      const CurveHit* best = nullptr;
      double best_d = 1e300;
      Sampler po(oin);
      for (const CurveHit& h : found.hits) {
        const auto c = po(h.s.mid());
        const double d = std::hypot(c[0] - corner[0], c[1] - corner[1]);
        if (d < best_d) best_d = d, best = &h;
      }
      if (!best)
        fail("the fillet of radius " + std::to_string(r) + " does not fit at the corner " + where(corner[0], corner[1]) +
             " (the offsets of the adjacent pieces do not meet)");
      if (!best->certified) fail("the fillet center at the corner " + where(corner[0], corner[1]) + " is not certified");
      const auto center = po(best->s.mid());
      const double s_in = best->s.mid(), t_out = best->t.mid();
      const auto foot_in = pin(s_in);
      Sampler pout(fout);
      const auto foot_out = pout(t_out);
      // Trim in local parameters of the untrimmed pieces (loop order visits each end once).
      in.hi = in.lo + (in.hi - in.lo) * s_in;
      out.lo = out.lo + (out.hi - out.lo) * t_out;
      const double phi0 = std::atan2(foot_in[1] - center[1], foot_in[0] - center[0]);
      const double phi1 = std::atan2(foot_out[1] - center[1], foot_out[0] - center[0]);
      double sweep = std::remainder(phi1 - phi0, kTwoPi);
      if (convex != (sweep > 0.0) || std::abs(sweep) >= std::numbers::pi - 1e-12)
        fail("the fillet at the corner " + where(corner[0], corner[1]) + " does not turn with the corner");
      const Fn phi = phi0 + sweep * x(0);
      arcs[k] = cat({center[0] + r * cos(phi), center[1] + r * sin(phi)});
      arc_lengths[k] = r * std::abs(sweep);
    }
  }
  for (std::size_t k = 0; k < loop.size(); ++k) {
    if (!(loop[k].lo < loop[k].hi))
      fail("the fillets at both ends of a piece overlap (fillet radius " + std::to_string(r) + " too large)");
    parts.push_back(loop[k].fn());
    lengths.push_back(polyline_length(parts.back()));
    if (r > 0.0) {
      parts.push_back(arcs[k]);
      lengths.push_back(arc_lengths[k]);
    }
  }
  return concat_by_length(parts, lengths);
}

}  // namespace genmod
