// The continuation polygonizer's evaluation of f (batches of points on genmod's
// BatchEvaluator, counted) and its search for a seed point on the surface.
#pragma once

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/box3.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace genmod::continuation {

// The side of a value: inside the solid where f < 0; f >= 0 and errors (NaN) are outside.
inline bool is_inside(double v) { return v < 0.0; }

// Evaluates f at points (array of structures in, structure of arrays to the batch evaluator)
// and counts the points evaluated.
class Evaluator {
 public:
  explicit Evaluator(const Tape& f) : f_(f) {}
  // Values at the points, valid until the next call.
  std::span<const double> eval(std::span<const std::array<double, 3>> points);
  std::size_t count = 0;

 private:
  const Tape& f_;
  BatchEvaluator batch_;
  std::vector<double> out_;
};

// A point on the surface near `start`: f is sampled at the start and at points of a box
// around it whose half-width grows geometrically from cube_size / 2 to `radius` over
// `samples` samples, until a point on the other side is found; the segment between them is
// bisected to within cube_size * 2^-(bisections + 1). Throws std::runtime_error naming the
// start, the radius and the side when no sample is on the other side.
std::array<double, 3> search_around(Evaluator& f, const std::array<double, 3>& start, double radius, int samples,
                                    double cube_size, int bisections);

// A point on the surface inside a bounded box: `samples` points of the box (a Halton
// sequence) until one inside and one outside the solid are found, then bisection between them.
std::array<double, 3> search_box(Evaluator& f, const Box3& box, int samples, double cube_size, int bisections);

}  // namespace genmod::continuation
