// Upper bounds of Gaussian field elements and of their first and second derivatives as functions of a
// lower bound of the distance to the skeleton (culled_field.hpp). Internal to operators/.
#pragma once

namespace genmod::detail {

// The nearest distance (in units of the radius) from which the gradient bound below is valid
// and decreasing in the distance, the radius and the taper (see culled_field_bounds.cpp).
inline constexpr double kGradientBoundFrom = 1.5;

// An upper bound of weight * Gauss(delta / radius) for every delta with delta^2 >= d2
// (d2 >= 0 a lower bound of the squared distance), rounded upward, plus a rounding margin.
double gaussian_value_above(double weight, double radius, double d2);

// An upper bound of |dD/dx_k| (any k) for a Gaussian element of this weight, radius and taper
// at every point whose squared distance to the skeleton is at least d2; +infinity when
// d2 < (kGradientBoundFrom radius)^2, where the bound is not claimed.
double gaussian_gradient_above(double weight, double radius, double taper, double d2);

// The squared distance beyond which gaussian_gradient_above(...) <= cull_below (at least
// (kGradientBoundFrom radius)^2); +infinity for cull_below <= 0.
double gaussian_gradient_cull_distance2(double weight, double radius, double taper, double cull_below);

// The same for the second derivatives of constant-radius Gaussian elements (segment
// convolutions with r1 == r2 and point sources): the bound is valid and decreasing from
// kHessianBoundFrom radii on (see culled_field_bounds.cpp).
inline constexpr double kHessianBoundFrom = 2.0;

// An upper bound of |d^2 D / dx_j dx_k| (any j, k) for a constant-radius Gaussian element of
// this weight and radius at every point whose squared distance to the skeleton is at least
// d2; +infinity when d2 < (kHessianBoundFrom radius)^2.
double gaussian_hessian_above(double weight, double radius, double d2);

// The squared distance beyond which gaussian_hessian_above(...) <= cull_below (at least
// (kHessianBoundFrom radius)^2); +infinity for cull_below <= 0.
double gaussian_hessian_cull_distance2(double weight, double radius, double cull_below);

// The bound of the order-th derivatives (0, 1 or 2) of a Gaussian item, or of each item of a
// subtree with its largest parameters, at squared distance >= d2 (the three above).
inline double gaussian_order_above(int order, double weight, double radius, double taper, double d2) {
  switch (order) {
    case 0: return gaussian_value_above(weight, radius, d2);
    case 1: return gaussian_gradient_above(weight, radius, taper, d2);
    default: return gaussian_hessian_above(weight, radius, d2);
  }
}

}  // namespace genmod::detail
