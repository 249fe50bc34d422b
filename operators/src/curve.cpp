#include "genmod/operators/curve.hpp"

#include "bspline_op.hpp"
#include "unit_tangent_op.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

namespace {

[[noreturn]] void bad(const char* kind, const std::string& what) {
  throw std::invalid_argument(std::string("genmod: ") + kind + ": " + what);
}

// Flattens the points (point-major) after checking they share one dimension.
std::vector<double> flatten(const Curve::Points& points, const char* kind, std::size_t min_points, int& dim) {
  if (points.size() < min_points)
    bad(kind, "needs at least " + std::to_string(min_points) + " points, got " + std::to_string(points.size()));
  dim = static_cast<int>(points[0].size());
  if (dim < 1) bad(kind, "point 0 has no coordinates");
  std::vector<double> flat;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].size() != points[0].size())
      bad(kind, "point " + std::to_string(i) + " has " + std::to_string(points[i].size()) + " coordinates, point 0 has " +
                    std::to_string(dim));
    flat.insert(flat.end(), points[i].begin(), points[i].end());
  }
  return flat;
}

std::vector<double> clamped_uniform_knots(int n, int degree) {
  std::vector<double> knots(static_cast<std::size_t>(degree) + 1, 0.0);
  const int pieces = n - degree;
  for (int i = 1; i < pieces; ++i) knots.push_back(static_cast<double>(i) / pieces);
  knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, 1.0);
  return knots;
}

void check_degree(const char* kind, int degree) {
  if (degree < 1) bad(kind, "degree " + std::to_string(degree) + " is below 1");
}

}  // namespace

Curve Curve::polyline(const Points& points) {
  int dim = 0;
  std::vector<double> flat = flatten(points, "polyline", 2, dim);
  return Curve(std::make_shared<detail::BSplineOp>(dim, 1, clamped_uniform_knots(static_cast<int>(points.size()), 1),
                                                   std::move(flat), std::vector<double>{}, "polyline"));
}

Curve Curve::bezier(const Points& points) {
  int dim = 0;
  std::vector<double> flat = flatten(points, "bezier", 2, dim);
  const int degree = static_cast<int>(points.size()) - 1;
  return Curve(std::make_shared<detail::BSplineOp>(dim, degree, clamped_uniform_knots(degree + 1, degree),
                                                   std::move(flat), std::vector<double>{}, "bezier"));
}

Curve Curve::bspline(const Points& points, int degree, std::vector<double> knots) {
  check_degree("bspline", degree);
  int dim = 0;
  std::vector<double> flat = flatten(points, "bspline", static_cast<std::size_t>(degree) + 1, dim);
  return Curve(std::make_shared<detail::BSplineOp>(dim, degree, std::move(knots), std::move(flat),
                                                   std::vector<double>{}, "bspline"));
}

Curve Curve::uniform_bspline(const Points& points, int degree, bool clamped) {
  check_degree("uniform_bspline", degree);
  int dim = 0;
  std::vector<double> flat = flatten(points, "uniform_bspline", static_cast<std::size_t>(degree) + 1, dim);
  const int n = static_cast<int>(points.size());
  std::vector<double> knots;
  if (clamped) {
    knots = clamped_uniform_knots(n, degree);
  } else {
    // Equally spaced, scaled so that the domain [u_p, u_n] is [0, 1].
    for (int i = 0; i <= n + degree; ++i) knots.push_back(static_cast<double>(i - degree) / (n - degree));
  }
  return Curve(std::make_shared<detail::BSplineOp>(dim, degree, std::move(knots), std::move(flat),
                                                   std::vector<double>{}, "uniform_bspline"));
}

Curve Curve::nurbs(const Points& points, std::vector<double> weights, int degree, std::vector<double> knots) {
  check_degree("nurbs", degree);
  int dim = 0;
  std::vector<double> flat = flatten(points, "nurbs", static_cast<std::size_t>(degree) + 1, dim);
  if (knots.empty()) knots = clamped_uniform_knots(static_cast<int>(points.size()), degree);
  if (weights.size() != points.size())
    bad("nurbs", std::to_string(points.size()) + " points need as many weights, got " + std::to_string(weights.size()));
  return Curve(std::make_shared<detail::BSplineOp>(dim, degree, std::move(knots), std::move(flat), std::move(weights),
                                                   "nurbs"));
}

Curve Curve::hermite(const Points& points, const Points& tangents) {
  int dim = 0, tdim = 0;
  const std::vector<double> p = flatten(points, "hermite", 2, dim);
  const std::vector<double> t = flatten(tangents, "hermite tangents", 2, tdim);
  if (tangents.size() != points.size())
    bad("hermite", std::to_string(points.size()) + " points need as many tangents, got " + std::to_string(tangents.size()));
  if (tdim != dim) bad("hermite", "tangents have dimension " + std::to_string(tdim) + ", points " + std::to_string(dim));
  // Each segment is a cubic Bezier piece: P_i, P_i + h T_i / 3, P_i+1 - h T_i+1 / 3, P_i+1,
  // joined by triple knots (C0 as a B-spline, C1 by the choice of points).
  const std::size_t n = points.size(), d = static_cast<std::size_t>(dim);
  const double h = 1.0 / static_cast<double>(n - 1);
  std::vector<double> ctrl;
  std::vector<double> knots(4, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (std::size_t c = 0; c < d; ++c) ctrl.push_back(p[i * d + c]);
    for (std::size_t c = 0; c < d; ++c) ctrl.push_back(p[i * d + c] + h * t[i * d + c] / 3.0);
    for (std::size_t c = 0; c < d; ++c) ctrl.push_back(p[(i + 1) * d + c] - h * t[(i + 1) * d + c] / 3.0);
    if (i > 0) knots.insert(knots.end(), 3, static_cast<double>(i) / static_cast<double>(n - 1));
  }
  for (std::size_t c = 0; c < d; ++c) ctrl.push_back(p[(n - 1) * d + c]);
  knots.insert(knots.end(), 4, 1.0);
  return Curve(std::make_shared<detail::BSplineOp>(dim, 3, std::move(knots), std::move(ctrl), std::vector<double>{},
                                                   "hermite"));
}

Curve Curve::catmull_rom(const Points& points) {
  int dim = 0;
  flatten(points, "catmull_rom", 2, dim);
  const std::size_t n = points.size(), d = static_cast<std::size_t>(dim);
  const double inv_h = static_cast<double>(n - 1);
  Points tangents(n, std::vector<double>(d));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? i : i + 1;
    for (std::size_t c = 0; c < d; ++c)
      tangents[i][c] = (points[b][c] - points[a][c]) * inv_h / static_cast<double>(b - a);
  }
  return hermite(points, tangents);
}

int Curve::dimension() const noexcept { return op_->dim(); }
int Curve::degree() const noexcept { return op_->degree(); }
const std::vector<double>& Curve::knots() const noexcept { return op_->knots(); }
const std::vector<double>& Curve::weights() const noexcept { return op_->weights(); }
std::pair<double, double> Curve::domain() const noexcept { return {op_->lo(), op_->hi()}; }

Curve::Points Curve::control_points() const {
  const std::size_t d = static_cast<std::size_t>(op_->dim());
  Points out(static_cast<std::size_t>(op_->num_points()));
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i].assign(op_->points().begin() + static_cast<std::ptrdiff_t>(i * d),
                  op_->points().begin() + static_cast<std::ptrdiff_t>((i + 1) * d));
  return out;
}

Fn Curve::operator()(const Fn& t) const {
  if (t.dim() != 1) bad(op_->name().c_str(), "the parameter has dimension " + std::to_string(t.dim()) + ", expected 1");
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(op_), {t});
}

Fn Curve::unit_tangent(const Fn& t) const {
  if (t.dim() != 1) bad(op_->name().c_str(), "the parameter has dimension " + std::to_string(t.dim()) + ", expected 1");
  if (op_->degree() < 1) bad(op_->name().c_str(), "a curve of degree 0 has no tangent");
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(op_->unit_tangent_op()), {t});
}

std::shared_ptr<const CustomOp> Curve::op() const { return op_; }

}  // namespace genmod
