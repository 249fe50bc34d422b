// Uses an installed genmod: a unit circle evaluated at a point, over a box and rendered.
// Exits non-zero (naming the check) if a result is wrong.
#include <genmod/genmod.hpp>

#include <cstdio>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "genmod install example: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  using namespace genmod;
  const Fn circle = square(x(0)) + square(x(1)) - 1.0;
  const Tape tape(circle);

  // Values chosen so that every operation is exact.
  PointEvaluator point;
  check(point.eval(tape, {0.5, 0.25})[0] == -0.6875, "point value at (0.5, 0.25)");

  // Over [0,1] x [2,3] the natural interval extension is exact: x^2 + y^2 - 1 in [3, 9].
  IntervalEvaluator interval;
  const Interval range = interval.eval(tape, {Interval(0.0, 1.0), Interval(2.0, 3.0)})[0];
  check(range.lo() == 3.0 && range.hi() == 9.0, "interval over [0,1] x [2,3]");

  // The tessellate layer (TBB, PNG) links too: the image center is inside, a corner outside.
  const Image image = render_sign(tape, {.size = 16, .tile_sizes = {8}, .threads = 1});
  check(image.at(8, 8) == kInside && image.at(0, 0) == kOutside, "rendered circle");

  return failures == 0 ? 0 : 1;
}
