// De Boor's algorithm on one knot span, as a template over the degree P and the number HD of
// coordinates (homogeneous: dim + 1 for a rational curve), so that the common curves (degree
// 1-3 in 1-4 coordinates) run fully unrolled: curves are evaluated millions of times inside
// solvers and inverse operators. The arithmetic is the same, in the same order, as the
// general loop in BSplineOp::de_boor (no contraction into fused multiply-adds: the build uses
// -ffp-contract=off), so both give the same bits.
#pragma once

#include <cstddef>

namespace genmod::detail {

// Span k (P <= k), parameter params[r - 1] at level r; control rows of HD values in hpoints.
template <int P, int HD>
void de_boor_fixed(const double* knots, const double* hpoints, int k, const double* params, double* out) {
  double d[P + 1][HD];
  for (int j = 0; j <= P; ++j)
    for (int c = 0; c < HD; ++c) d[j][c] = hpoints[static_cast<std::size_t>((j + k - P) * HD + c)];
  for (int r = 1; r <= P; ++r) {
    const double x = params[r - 1];
    for (int j = P; j >= r; --j) {
      const double a = knots[j + k - P];
      const double b = knots[j + 1 + k - r];
      const double alpha = (x - a) / (b - a);
      for (int c = 0; c < HD; ++c) d[j][c] = (1.0 - alpha) * d[j - 1][c] + alpha * d[j][c];
    }
  }
  for (int c = 0; c < HD; ++c) out[c] = d[P][c];
}

using DeBoorKernel = void (*)(const double* knots, const double* hpoints, int k, const double* params, double* out);

// The unrolled kernel for degree p and hd coordinates, or nullptr when none is compiled.
inline DeBoorKernel de_boor_kernel(int p, int hd) noexcept {
#define GENMOD_DE_BOOR_ROW(P) \
  if (p == P) {               \
    switch (hd) {             \
      case 1: return &de_boor_fixed<P, 1>; \
      case 2: return &de_boor_fixed<P, 2>; \
      case 3: return &de_boor_fixed<P, 3>; \
      case 4: return &de_boor_fixed<P, 4>; \
      default: return nullptr;             \
    }                                      \
  }
  GENMOD_DE_BOOR_ROW(1)
  GENMOD_DE_BOOR_ROW(2)
  GENMOD_DE_BOOR_ROW(3)
#undef GENMOD_DE_BOOR_ROW
  return nullptr;
}

}  // namespace genmod::detail
