// Tests of genmod::Interval: construction, the claims of research/snyder.md section 11 about
// interval arithmetic (items 3, 4, 5, 20), empty and unbounded values, outward rounding of
// + - * / against MPFR, isotonicity, containment of point values and the error flags of every
// elementary enclosure. The elementary functions are checked against the MPFI oracle in
// interval_mpfi_test.cpp.
#include "genmod/kernel/interval.hpp"
#include "kernel/mpfr_value.hpp"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using genmod::Interval;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();
constexpr double kHalfPi = 1.5707963267948966;  // nearest double, below pi/2
constexpr double kPi = 3.141592653589793;       // nearest double, below pi

Interval iv(double lo, double hi) { return Interval(lo, hi); }

bool is_legal(const Interval& x) {
  if (std::isnan(x.lo()) || std::isnan(x.hi())) return std::isnan(x.lo()) && std::isnan(x.hi());
  return x.lo() <= x.hi() && x.lo() < kInf && x.hi() > -kInf;
}

// Runs f in the default rounding mode (upward = false) or inside a RoundingScope, as the
// interval evaluators do.
template <class F>
auto in_mode(bool upward, F&& f) {
  if (!upward) return f();
  genmod::RoundingScope scope;
  return f();
}

using genmod::testing::Mpfr;

// ---- random inputs ---------------------------------------------------------------------

// Doubles and intervals of all sizes, signs and the special values that break code.
class Sampler {
 public:
  explicit Sampler(std::uint64_t seed) : rng_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

  // A finite double: mostly moderate, sometimes huge, tiny, integral or special.
  double number() {
    switch (integer(0, 5)) {
      case 0:
        return uniform(-4.0, 4.0);
      case 1:
        return uniform(-100.0, 100.0);
      case 2:
        return std::round(uniform(-6.0, 6.0));
      case 3:
        return (chance(0.5) ? -1.0 : 1.0) * std::pow(10.0, uniform(-30.0, 30.0));
      case 4:
        return (chance(0.5) ? -1.0 : 1.0) * std::pow(10.0, uniform(-310.0, 308.0));
      default: {
        static constexpr double kSpecial[] = {
            0.0, -0.0, 1.0,  -1.0, 0.5,    -0.5, kMax, -kMax, kTiny, -kTiny, std::numeric_limits<double>::min(),
            0.1, 2.0,  -2.0, kPi,  kHalfPi};
        return kSpecial[integer(0, static_cast<int>(std::size(kSpecial)) - 1)];
      }
    }
  }

  // A nonempty interval: a point, a narrow interval, a random pair or (if allowed) unbounded.
  Interval interval(bool allow_unbounded) {
    const double a = number();
    switch (integer(0, allow_unbounded ? 4 : 2)) {
      case 0:
        return iv(a, a);
      case 1: {
        double b = a;
        for (int i = integer(1, 8); i > 0; --i) b = genmod::interval_detail::next_up(b);
        return iv(a, b == kInf ? a : b);
      }
      case 2: {
        const double b = number();
        return iv(std::min(a, b), std::max(a, b));
      }
      case 3:
        return chance(0.5) ? iv(-kInf, a) : iv(a, kInf);
      default:
        return Interval::entire();
    }
  }

  // A finite point of nonempty x, often an end (an infinite end stands for +-DBL_MAX).
  double point_in(const Interval& x) {
    const double lo = std::max(x.lo(), -kMax), hi = std::min(x.hi(), kMax);
    switch (integer(0, 3)) {
      case 0:
        return lo;
      case 1:
        return hi;
      case 2:
        return std::clamp(number(), lo, hi);
      default: {
        const double t = uniform(0.0, 1.0);
        return std::clamp((1.0 - t) * lo + t * hi, lo, hi);
      }
    }
  }

  // A random nonempty subinterval of x, sometimes x itself.
  Interval subinterval(const Interval& x) {
    if (chance(0.1)) return x;
    const double a = point_in(x), b = point_in(x);
    return iv(std::min(a, b), std::max(a, b));
  }

 private:
  std::mt19937_64 rng_;
};

// ---- the functions under test, in one table --------------------------------------------------

using UnaryEnclosure = Interval (*)(const Interval&, std::uint8_t*);
using BinaryEnclosure = Interval (*)(const Interval&, const Interval&, std::uint8_t*);

// Enclosures built from C library values are isotonic only up to a few ulps: two libm values
// may be out of order by up to twice libm's error (about 1.2 ulps in directed modes), and an
// exact bound (exp 0 = 1) may meet a widened one at a neighbouring argument (up to the 3 ulps
// of widening plus the error). kLibmSlack allows for both; exact functions get no slack.
constexpr int kExact = 0;
constexpr int kLibmSlack = 8;

struct UnaryFunction {
  const char* name;
  UnaryEnclosure enclose;
  double (*point)(double);  // genmod's point semantics: NaN is an error
  int isotonic_ulps;
};

struct BinaryFunction {
  const char* name;
  BinaryEnclosure enclose;
  double (*point)(double, double);
  int isotonic_ulps;
};

const std::vector<UnaryFunction>& unary_functions() {
  static const std::vector<UnaryFunction> functions = {
      {"square", [](const Interval& x, std::uint8_t*) { return genmod::square(x); }, [](double v) { return v * v; },
       kExact},
      {"sqrt", [](const Interval& x, std::uint8_t* e) { return genmod::sqrt(x, e); },
       [](double v) { return std::sqrt(v); }, kExact},
      {"exp", [](const Interval& x, std::uint8_t*) { return genmod::exp(x); }, [](double v) { return std::exp(v); },
       kLibmSlack},
      {"log", [](const Interval& x, std::uint8_t* e) { return genmod::log(x, e); }, genmod::point::log, kLibmSlack},
      {"sin", [](const Interval& x, std::uint8_t*) { return genmod::sin(x); }, [](double v) { return std::sin(v); },
       kLibmSlack},
      {"cos", [](const Interval& x, std::uint8_t*) { return genmod::cos(x); }, [](double v) { return std::cos(v); },
       kLibmSlack},
      {"tan", [](const Interval& x, std::uint8_t*) { return genmod::tan(x); }, [](double v) { return std::tan(v); },
       kLibmSlack},
      {"asin", [](const Interval& x, std::uint8_t* e) { return genmod::asin(x, e); },
       [](double v) { return std::asin(v); }, kLibmSlack},
      {"acos", [](const Interval& x, std::uint8_t* e) { return genmod::acos(x, e); },
       [](double v) { return std::acos(v); }, kLibmSlack},
      {"atan", [](const Interval& x, std::uint8_t*) { return genmod::atan(x); }, [](double v) { return std::atan(v); },
       kLibmSlack},
      {"abs", [](const Interval& x, std::uint8_t*) { return genmod::abs(x); }, [](double v) { return std::abs(v); },
       kExact},
      {"floor", [](const Interval& x, std::uint8_t*) { return genmod::floor(x); },
       [](double v) { return std::floor(v); }, kExact},
      {"ceil", [](const Interval& x, std::uint8_t*) { return genmod::ceil(x); }, [](double v) { return std::ceil(v); },
       kExact},
  };
  return functions;
}

const std::vector<BinaryFunction>& binary_functions() {
  static const std::vector<BinaryFunction> functions = {
      {"atan2", [](const Interval& y, const Interval& x, std::uint8_t*) { return genmod::atan2(y, x); },
       [](double y, double x) { return std::atan2(y, x); }, kLibmSlack},
      {"pow", [](const Interval& x, const Interval& y, std::uint8_t* e) { return genmod::pow(x, y, e); },
       genmod::point::pow, kLibmSlack},
      {"min", [](const Interval& a, const Interval& b, std::uint8_t*) { return genmod::min(a, b); }, genmod::point::min,
       kExact},
      {"max", [](const Interval& a, const Interval& b, std::uint8_t*) { return genmod::max(a, b); }, genmod::point::max,
       kExact},
  };
  return functions;
}

// ---- construction ------------------------------------------------------------------------

TEST(IntervalConstruction, RejectsIllegalBounds) {
  EXPECT_THROW(iv(kNaN, 1.0), std::invalid_argument);
  EXPECT_THROW(iv(0.0, kNaN), std::invalid_argument);
  EXPECT_THROW(iv(kNaN, kNaN), std::invalid_argument);
  EXPECT_THROW(iv(2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(iv(kInf, kInf), std::invalid_argument);    // lo must be below +inf
  EXPECT_THROW(iv(-kInf, -kInf), std::invalid_argument);  // hi must be above -inf
  EXPECT_THROW(iv(kInf, -kInf), std::invalid_argument);
}

TEST(IntervalConstruction, AcceptsUnboundedAndPointIntervals) {
  EXPECT_NO_THROW(iv(-kInf, 3.0));
  EXPECT_NO_THROW(iv(3.0, kInf));
  EXPECT_NO_THROW(iv(-kInf, kInf));
  EXPECT_NO_THROW(iv(-0.0, 0.0));
  const Interval p = iv(2.5, 2.5);
  EXPECT_TRUE(p.is_point());
  EXPECT_TRUE(p.contains(2.5));
}

TEST(IntervalConstruction, NumberConversion) {
  EXPECT_EQ(Interval(kInf), iv(kMax, kInf));  // legal stand-in for the point +inf
  EXPECT_EQ(Interval(-kInf), iv(-kInf, -kMax));
  EXPECT_TRUE(Interval(kNaN).is_empty());
  EXPECT_EQ(Interval(0.25), iv(0.25, 0.25));
}

// ---- research/snyder.md section 11 ---------------------------------------------------------

// The tightest double enclosure of a decimal constant.
Interval decimal(const char* text) {
  Mpfr v(300);
  mpfr_set_str(v.get(), text, 10, MPFR_RNDN);
  return iv(mpfr_get_d(v.get(), MPFR_RNDD), mpfr_get_d(v.get(), MPFR_RNDU));
}

// Whether the decimal constant `text` lies in x.
bool contains_decimal(const Interval& x, const char* text) {
  Mpfr v(300);
  mpfr_set_str(v.get(), text, 10, MPFR_RNDN);
  return mpfr_cmp_d(v.get(), x.lo()) >= 0 && mpfr_cmp_d(v.get(), x.hi()) <= 0;
}

// Claim 3: outward rounding. 0.1 + 0.2 != 0.3 in plain doubles, but the interval sum of
// enclosures of 0.1 and 0.2 contains 0.3.
TEST(IntervalSnyderClaims, OutwardRoundingOfDecimalSum) {
  volatile double a = 0.1, b = 0.2;
  ASSERT_NE(a + b, 0.3);  // what makes the claim worth testing
  for (const bool upward : {false, true}) {
    const Interval sum = in_mode(upward, [] { return decimal("0.1") + decimal("0.2"); });
    EXPECT_TRUE(contains_decimal(sum, "0.3")) << sum;
    EXPECT_LT(sum.lo(), sum.hi());
  }
}

// Claim 4: cosine corner cases (the thesis' case table has its middle cases swapped).
TEST(IntervalSnyderClaims, CosineCornerCases) {
  for (const bool upward : {false, true}) {
    const auto cos = [upward](double lo, double hi) {
      return in_mode(upward, [=] { return genmod::cos(iv(lo, hi)); });
    };
    EXPECT_EQ(cos(-0.1, 0.1).hi(), 1.0);
    EXPECT_LE(cos(-0.1, 0.1).lo(), std::cos(0.1));
    EXPECT_EQ(cos(3.0, 3.3).lo(), -1.0);
    EXPECT_GE(cos(3.0, 3.3).hi(), std::cos(3.3));
    EXPECT_EQ(cos(0.0, 7.0), iv(-1.0, 1.0));
    const Interval c = cos(0.5, 1.0);
    EXPECT_LE(c.lo(), std::cos(1.0));
    EXPECT_GE(c.hi(), std::cos(0.5));
    EXPECT_NEAR(c.lo(), std::cos(1.0), 4e-16);  // a few ulps
    EXPECT_NEAR(c.hi(), std::cos(0.5), 4e-16);
  }
}

// Claim 5: square recognizes the dependency that x * x cannot.
TEST(IntervalSnyderClaims, SquareVersusProduct) {
  const Interval x = iv(-2.0, 2.0);
  EXPECT_EQ(genmod::square(x), iv(0.0, 4.0));
  EXPECT_EQ(x * x, iv(-4.0, 4.0));
}

// The union of the two pieces of an extended quotient (order not specified by the API).
std::vector<Interval> pieces(const genmod::IntervalPair& q) {
  std::vector<Interval> out;
  for (const Interval& p : {q.first, q.second})
    if (!p.is_empty()) out.push_back(p);
  if (out.size() == 2 && out[1].lo() < out[0].lo()) std::swap(out[0], out[1]);
  return out;
}

// Claim 20: extended division for interval Newton.
TEST(IntervalSnyderClaims, ExtendedDivision) {
  using V = std::vector<Interval>;
  EXPECT_EQ(pieces(genmod::extended_divide(iv(0, 1), iv(-1, 0))), V{Interval::entire()});
  EXPECT_EQ(pieces(genmod::extended_divide(iv(1, 2), iv(0, 1))), V{iv(1, kInf)});
  EXPECT_EQ(pieces(genmod::extended_divide(iv(-2, -1), iv(-1, 1))), (V{iv(-kInf, -1), iv(1, kInf)}));
  EXPECT_EQ(pieces(genmod::extended_divide(iv(1, 2), iv(0, 0))), V{});
  // 0 = q * 0 for every q.
  EXPECT_EQ(pieces(genmod::extended_divide(iv(-1, 1), iv(0, 0))), V{Interval::entire()});
  // The header's own example.
  EXPECT_EQ(pieces(genmod::extended_divide(iv(1, 2), iv(-1, 1))), (V{iv(-kInf, -1), iv(1, kInf)}));
}

// ---- empty and unbounded values ----------------------------------------------------------

TEST(IntervalEmpty, PropagatesThroughEveryOperation) {
  const Interval e = Interval::empty(), x = iv(1.0, 2.0);
  EXPECT_TRUE(e.is_empty());
  EXPECT_TRUE((e + x).is_empty());
  EXPECT_TRUE((x - e).is_empty());
  EXPECT_TRUE((e * x).is_empty());
  EXPECT_TRUE((-e).is_empty());
  std::uint8_t err = genmod::kNoError;
  EXPECT_TRUE(genmod::divide(x, e, &err).is_empty());
  EXPECT_EQ(err, genmod::kCertainError);
  for (const UnaryFunction& f : unary_functions()) EXPECT_TRUE(f.enclose(e, nullptr).is_empty()) << f.name;
  for (const BinaryFunction& f : binary_functions()) {
    EXPECT_TRUE(f.enclose(e, x, nullptr).is_empty()) << f.name;
    EXPECT_TRUE(f.enclose(x, e, nullptr).is_empty()) << f.name;
  }
  EXPECT_TRUE(hull(e, e).is_empty());
  EXPECT_EQ(hull(e, x), x);
  EXPECT_TRUE(intersect(x, iv(3.0, 4.0)).is_empty());
  EXPECT_TRUE(x.contains(e));
}

TEST(IntervalUnbounded, Arithmetic) {
  const Interval all = Interval::entire();
  EXPECT_EQ(iv(1, kInf) + iv(1, 2), iv(2, kInf));
  EXPECT_EQ(iv(-kInf, 1) + iv(-kInf, 1), iv(-kInf, 2));
  EXPECT_EQ(iv(1, kInf) - iv(1, kInf), all);
  EXPECT_EQ(iv(0, 0) * all, iv(0, 0));  // 0 * x = 0 for every real x
  EXPECT_EQ(iv(0, 0) * iv(1, kInf), iv(0, 0));
  EXPECT_EQ(iv(0, 1) * iv(1, kInf), iv(0, kInf));
  EXPECT_EQ(iv(2, 3) * iv(-kInf, -1), iv(-kInf, -2));
  EXPECT_EQ(iv(-1, 1) * iv(1, kInf), all);
  EXPECT_EQ(iv(1, 2) / iv(1, kInf), iv(0, 2));
  std::uint8_t err = genmod::kNoError;
  EXPECT_EQ(genmod::divide(iv(1, 1), iv(0, 1), &err), iv(1, kInf));
  EXPECT_EQ(err, genmod::kMaybeError);
  err = genmod::kNoError;
  EXPECT_TRUE(genmod::divide(iv(1, 2), iv(0, 0), &err).is_empty());
  EXPECT_EQ(err, genmod::kCertainError);
  EXPECT_EQ(iv(kMax, kMax) + iv(kMax, kMax), iv(kMax, kInf));  // overflow stays enclosed
}

TEST(IntervalUnbounded, ElementaryFunctions) {
  const Interval all = Interval::entire();
  std::uint8_t err = genmod::kNoError;
  EXPECT_EQ(genmod::exp(iv(-kInf, 0)), iv(0, 1));
  EXPECT_EQ(genmod::exp(all), iv(0, kInf));
  EXPECT_EQ(genmod::log(iv(0, 1), &err), iv(-kInf, 0));
  EXPECT_EQ(err, genmod::kMaybeError);
  err = genmod::kNoError;
  EXPECT_EQ(genmod::log(iv(0, kInf), &err), all);
  EXPECT_EQ(err, genmod::kMaybeError);
  err = genmod::kNoError;
  EXPECT_EQ(genmod::sqrt(iv(-kInf, 4), &err), iv(0, 2));
  EXPECT_EQ(err, genmod::kMaybeError);
  EXPECT_EQ(genmod::sqrt(iv(4, kInf)), iv(2, kInf));
  EXPECT_EQ(genmod::square(iv(-kInf, -1)), iv(1, kInf));
  EXPECT_EQ(genmod::square(all), iv(0, kInf));
  // atan(R) is (-pi/2, pi/2); the bounds must lie beyond the doubles nearest +-pi/2.
  const Interval at = genmod::atan(all);
  EXPECT_GT(at.hi(), kHalfPi);
  EXPECT_LT(at.lo(), -kHalfPi);
  EXPECT_LT(at.hi(), 1.6);
  EXPECT_EQ(genmod::sin(all), iv(-1, 1));
  EXPECT_EQ(genmod::cos(iv(kMax, kInf)), iv(-1, 1));
  EXPECT_EQ(genmod::tan(iv(-kInf, 0)), all);
  err = genmod::kNoError;
  const Interval as = genmod::asin(all, &err);
  EXPECT_EQ(err, genmod::kMaybeError);
  EXPECT_TRUE(as.lo() < -kHalfPi && as.hi() > kHalfPi && as.hi() < 1.6) << as;
  const Interval a2 = genmod::atan2(all, all);
  EXPECT_TRUE(a2.lo() < -kPi && a2.hi() > kPi && a2.hi() < 3.2) << a2;
  const Interval quadrant1 = genmod::atan2(iv(1, kInf), iv(1, kInf));
  EXPECT_TRUE(quadrant1.lo() <= 0.0 && quadrant1.hi() > kHalfPi && quadrant1.hi() < 1.6) << quadrant1;
  EXPECT_EQ(genmod::abs(iv(-kInf, -2)), iv(2, kInf));
  EXPECT_EQ(genmod::abs(iv(-kInf, 3)), iv(0, kInf));
  EXPECT_EQ(genmod::floor(iv(-kInf, 2.5)), iv(-kInf, 2));
  EXPECT_EQ(genmod::ceil(iv(kMax, kInf)), iv(kMax, kInf));
  EXPECT_EQ(genmod::min(iv(-kInf, 1), iv(0, kInf)), iv(-kInf, 1));
  EXPECT_EQ(genmod::max(iv(-kInf, 1), iv(0, kInf)), iv(0, kInf));
}

// Equal for infinite or zero `want`, within a few ulps otherwise.
bool close(double got, double want) {
  if (std::isinf(want) || want == 0.0) return got == want;
  return std::abs(got - want) <= 1e-14 * std::abs(want);
}

// pow follows point::pow: std::pow, with 0^negative an error; negative bases only with
// integer exponents.
TEST(IntervalPow, SemanticsAndErrors) {
  struct Case {
    Interval x, y, want;
    std::uint8_t err;
  };
  const Interval all = Interval::entire(), none = Interval::empty();
  const Case cases[] = {
      {iv(2, 3), iv(2, 2), iv(4, 9), genmod::kNoError},
      {iv(-3, 2), iv(2, 2), iv(0, 9), genmod::kNoError},
      {iv(-3, -2), iv(3, 3), iv(-27, -8), genmod::kNoError},
      {iv(-2, 4), iv(-1, -1), all, genmod::kMaybeError},
      {iv(-2, 0), iv(-1, -1), iv(-kInf, -0.5), genmod::kMaybeError},
      {iv(-2, 2), iv(-2, -2), iv(0.25, kInf), genmod::kMaybeError},
      {iv(0, 1), iv(-1, -1), iv(1, kInf), genmod::kMaybeError},
      {iv(0, 0), iv(-1, -1), none, genmod::kCertainError},
      {iv(0, 0), iv(-2, -1), none, genmod::kCertainError},
      {iv(0, 0), iv(0, 0), iv(1, 1), genmod::kNoError},
      {iv(0, 0), iv(-1, 1), iv(0, 1), genmod::kMaybeError},
      {all, iv(0, 0), iv(1, 1), genmod::kNoError},
      {iv(1, 1), all, iv(1, 1), genmod::kNoError},
      {iv(-8, -8), iv(1.0 / 3, 1.0 / 3), none, genmod::kCertainError},
      {iv(-2, -1), iv(0.25, 0.75), none, genmod::kCertainError},
      {iv(-2, 4), iv(0.5, 0.5), iv(0, 2), genmod::kMaybeError},
      {iv(-2, -1), iv(1.5, 2.5), iv(1, 4), genmod::kMaybeError},  // only y = 2 is defined
      {iv(2, 2), iv(-kInf, 0), iv(0, 1), genmod::kNoError},
      {iv(0, kInf), iv(2, 2), iv(0, kInf), genmod::kNoError},
      {all, iv(2, 2), iv(0, kInf), genmod::kNoError},
      {all, iv(3, 3), all, genmod::kNoError},
  };
  for (const Case& c : cases) {
    std::uint8_t err = genmod::kNoError;
    const Interval got = genmod::pow(c.x, c.y, &err);
    EXPECT_EQ(err, c.err) << c.x << " ^ " << c.y;
    if (c.want.is_empty()) {
      EXPECT_TRUE(got.is_empty()) << c.x << " ^ " << c.y << " = " << got;
      continue;
    }
    EXPECT_TRUE(got.contains(c.want)) << c.x << " ^ " << c.y << " = " << got;
    // Tight up to a few ulps of the wanted bounds (exact for 0, 1 and infinite bounds).
    EXPECT_TRUE(close(got.lo(), c.want.lo()) && close(got.hi(), c.want.hi()))
        << c.x << " ^ " << c.y << " = " << got << ", want " << c.want;
  }
  // Several integer exponents over negative bases give both signs.
  const Interval both = genmod::pow(iv(-2, -1), iv(1, 3));
  EXPECT_TRUE(both.contains(iv(-8, 4)) && both.contains(-1.0)) << both;
}

TEST(IntervalDomains, ErrorFlags) {
  std::uint8_t err = genmod::kNoError;
  EXPECT_EQ(genmod::sqrt(iv(4, 9), &err), iv(2, 3));  // perfect squares stay exact
  EXPECT_EQ(err, genmod::kNoError);
  EXPECT_TRUE(genmod::sqrt(iv(-2, -1), &err).is_empty());
  EXPECT_EQ(err, genmod::kCertainError);
  err = genmod::kNoError;
  EXPECT_EQ(genmod::sqrt(iv(-1, 0), &err), iv(0, 0));
  EXPECT_EQ(err, genmod::kMaybeError);
  err = genmod::kNoError;
  EXPECT_TRUE(genmod::log(iv(0, 0), &err).is_empty());  // log 0 is an error
  EXPECT_EQ(err, genmod::kCertainError);
  err = genmod::kNoError;
  EXPECT_EQ(genmod::log(iv(1, 1), &err), iv(0, 0));
  EXPECT_EQ(err, genmod::kNoError);
  EXPECT_TRUE(genmod::asin(iv(1.5, 2), &err).is_empty());
  EXPECT_EQ(err, genmod::kCertainError);
  err = genmod::kNoError;
  const Interval ac = genmod::acos(iv(-2, 1), &err);
  EXPECT_EQ(err, genmod::kMaybeError);
  EXPECT_EQ(ac.lo(), 0.0);
  EXPECT_TRUE(ac.hi() > kPi && ac.hi() < 3.2) << ac;
  EXPECT_EQ(genmod::exp(iv(0, 0)), iv(1, 1));
}

// ---- outward rounding of + - * / -----------------------------------------------------------

using MpfrOp = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);

// op(a, b) correctly rounded to a double in direction rnd. Rounding to 53 bits and then to a
// double in the same direction equals rounding once (the double grid is part of the 53-bit one).
double rounded(MpfrOp op, double a, double b, mpfr_rnd_t rnd) {
  Mpfr x(53), y(53), r(53);
  mpfr_set_d(x.get(), a, MPFR_RNDN);
  mpfr_set_d(y.get(), b, MPFR_RNDN);
  op(r.get(), x.get(), y.get(), rnd);
  return mpfr_get_d(r.get(), rnd);
}

// The tightest double interval holding {op(a, b) : a in x, b in y} when the extremes are at
// the corners (true for + - * and for / when 0 is not in y).
Interval tightest(MpfrOp op, const Interval& x, const Interval& y) {
  double lo = kInf, hi = -kInf;
  for (const double a : {x.lo(), x.hi()}) {
    for (const double b : {y.lo(), y.hi()}) {
      lo = std::min(lo, rounded(op, a, b, MPFR_RNDD));
      hi = std::max(hi, rounded(op, a, b, MPFR_RNDU));
    }
  }
  return Interval::unchecked(lo, hi);
}

// A finite double with a random exponent: mostly moderate, sometimes at the ends of the range
// (overflow, underflow into subnormals).
double random_finite(Sampler& s) {
  const double mantissa = (s.chance(0.5) ? -1.0 : 1.0) * s.uniform(1.0, 2.0);
  if (s.chance(0.05)) return 0.0;
  const int exponent = s.chance(0.8) ? s.integer(-40, 40) : s.integer(-1074, 1023);
  return std::ldexp(mantissa, exponent);
}

Interval random_finite_interval(Sampler& s) {
  const double a = random_finite(s);
  if (s.chance(0.3)) return iv(a, a);
  const double b = random_finite(s);
  return iv(std::min(a, b), std::max(a, b));
}

// Every result must be the tightest outward-rounded interval (this implies containment of the
// exact result, and rules out a missing rounding-mode switch, which would round to nearest).
TEST(IntervalArithmetic, OutwardRoundingMatchesMpfr) {
  struct Op {
    const char* name;
    MpfrOp exact;
    Interval (*enclose)(const Interval&, const Interval&);
  };
  const Op ops[] = {
      {"+", mpfr_add, [](const Interval& a, const Interval& b) { return a + b; }},
      {"-", mpfr_sub, [](const Interval& a, const Interval& b) { return a - b; }},
      {"*", mpfr_mul, [](const Interval& a, const Interval& b) { return a * b; }},
      {"/", mpfr_div, [](const Interval& a, const Interval& b) { return a / b; }},
  };
  Sampler s(20240611);
  int strict_checks = 0;
  for (const Op& op : ops) {
    int failures = 0;
    for (int i = 0; i < 3000 && failures < 10; ++i) {
      const Interval a = random_finite_interval(s);
      Interval b = random_finite_interval(s);
      if (op.exact == mpfr_div && b.contains_zero()) b = iv(1.0, b.hi() <= 1.0 ? 1.0 : b.hi());
      const Interval expected = tightest(op.exact, a, b);
      for (const bool upward : {false, true}) {
        const Interval got = in_mode(upward, [&] { return op.enclose(a, b); });
        if (!(got == expected)) {
          ++failures;
          ADD_FAILURE() << a << ' ' << op.name << ' ' << b << " = " << got << ", tightest " << expected;
        }
        if (a.is_point() && b.is_point() && expected.lo() != expected.hi()) {
          ++strict_checks;
          EXPECT_LT(got.lo(), got.hi()) << "inexact result must not collapse to a point";
        }
      }
    }
  }
  EXPECT_GT(strict_checks, 1000);  // the random inputs do exercise inexact point operations
}

// ---- isotonicity, containment and error flags of the elementary functions -------------------

// x widened outward by `ulps` one-ulp steps.
Interval widened(const Interval& x, int ulps) {
  if (x.is_empty()) return x;
  double lo = x.lo(), hi = x.hi();
  for (int i = 0; i < ulps; ++i) {
    lo = genmod::interval_detail::next_down(lo);
    hi = genmod::interval_detail::next_up(hi);
  }
  return Interval::unchecked(lo, hi);
}

// Isotonicity: Y within Z implies f(Y) within f(Z) (research/snyder.md section 4.1), exactly
// for the exact functions and up to kLibmSlack ulps for those built on the C library.
TEST(IntervalElementary, Isotonic) {
  Sampler s(7);
  for (const bool upward : {false, true}) {
    for (const UnaryFunction& f : unary_functions()) {
      int failures = 0;
      for (int i = 0; i < 3000 && failures < 5; ++i) {
        const Interval z = s.interval(true), y = s.subinterval(z);
        const Interval fz = in_mode(upward, [&] { return f.enclose(z, nullptr); });
        const Interval fy = in_mode(upward, [&] { return f.enclose(y, nullptr); });
        if (!widened(fz, f.isotonic_ulps).contains(fy)) {
          ++failures;
          ADD_FAILURE() << f.name << ": f(" << y << ") = " << fy << " not within f(" << z << ") = " << fz;
        }
      }
    }
    for (const BinaryFunction& f : binary_functions()) {
      int failures = 0;
      for (int i = 0; i < 3000 && failures < 5; ++i) {
        const Interval z1 = s.interval(true), z2 = s.interval(true);
        const Interval y1 = s.subinterval(z1), y2 = s.subinterval(z2);
        const Interval fz = in_mode(upward, [&] { return f.enclose(z1, z2, nullptr); });
        const Interval fy = in_mode(upward, [&] { return f.enclose(y1, y2, nullptr); });
        if (!widened(fz, f.isotonic_ulps).contains(fy)) {
          ++failures;
          ADD_FAILURE() << f.name << ": f(" << y1 << ", " << y2 << ") = " << fy << " not within f(" << z1 << ", " << z2
                        << ") = " << fz;
        }
      }
    }
  }
}

// Checks one enclosure against point evaluations at samples of its argument box: values are
// contained, NaN (an error) is flagged, and a certain error means no valid point at all.
class PointCheck {
 public:
  PointCheck(std::string name, Interval result, std::uint8_t err) : name_(std::move(name)), result_(result), err_(err) {
    EXPECT_TRUE(is_legal(result)) << name << " gave an illegal interval " << result;
    EXPECT_EQ(result.is_empty(), err == genmod::kCertainError) << name << " = " << result;
  }
  // Returns false after reporting a failure.
  bool check(double value, const std::string& at) {
    if (std::isnan(value)) {
      EXPECT_TRUE(err_ & genmod::kMaybeError) << name_ << at << " is an error but not flagged";
      return (err_ & genmod::kMaybeError) != 0;
    }
    EXPECT_TRUE(result_.contains(value)) << name_ << at << " = " << value << " not in " << result_;
    EXPECT_NE(err_, genmod::kCertainError) << name_ << at << " is valid but the error is certain";
    return result_.contains(value) && err_ != genmod::kCertainError;
  }

 private:
  std::string name_;
  Interval result_;
  std::uint8_t err_;
};

std::string text(const Interval& x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string at(double x) { return " at " + text(Interval(x)); }
std::string at(double x, double y) { return " at " + text(Interval(x)) + ", " + text(Interval(y)); }

TEST(IntervalElementary, ContainsPointValuesAndFlagsErrors) {
  Sampler s(11);
  for (const bool upward : {false, true}) {
    for (const UnaryFunction& f : unary_functions()) {
      bool ok = true;
      for (int i = 0; i < 2000 && ok; ++i) {
        const Interval x = s.interval(true);
        std::uint8_t err = genmod::kNoError;
        const Interval fx = in_mode(upward, [&] { return f.enclose(x, &err); });
        PointCheck check(std::string(f.name) + text(x), fx, err);
        for (int k = 0; k < 8 && ok; ++k) {
          const double p = s.point_in(x);
          ok = check.check(f.point(p), at(p));
        }
      }
    }
    for (const BinaryFunction& f : binary_functions()) {
      bool ok = true;
      for (int i = 0; i < 4000 && ok; ++i) {
        const Interval x = s.interval(true);
        // Small integers and their neighbourhoods matter to pow.
        const Interval y = s.chance(0.3) ? Interval(std::round(s.uniform(-4, 4))) : s.interval(true);
        std::uint8_t err = genmod::kNoError;
        const Interval fxy = in_mode(upward, [&] { return f.enclose(x, y, &err); });
        PointCheck check(std::string(f.name) + text(x) + text(y), fxy, err);
        for (int k = 0; k < 8 && ok; ++k) {
          const double p = s.point_in(x);
          const double q =
              (k == 0 && y.lo() <= std::ceil(y.lo()) && std::ceil(y.lo()) <= y.hi() && std::isfinite(std::ceil(y.lo())))
                  ? std::ceil(y.lo())  // an integer of y, where negative bases count
                  : s.point_in(y);
          ok = check.check(f.point(p, q), at(p, q));
        }
      }
    }
  }
}

// Every result is a legal interval, also for extreme arguments in both rounding modes.
TEST(IntervalElementary, ResultsAreLegal) {
  Sampler s(3);
  for (const bool upward : {false, true}) {
    for (int i = 0; i < 4000; ++i) {
      const Interval x = s.interval(true), y = s.interval(true);
      for (const UnaryFunction& f : unary_functions()) {
        const Interval r = in_mode(upward, [&] { return f.enclose(x, nullptr); });
        ASSERT_TRUE(is_legal(r)) << f.name << x << " = " << r;
      }
      for (const BinaryFunction& f : binary_functions()) {
        const Interval r = in_mode(upward, [&] { return f.enclose(x, y, nullptr); });
        ASSERT_TRUE(is_legal(r)) << f.name << x << ", " << y << " = " << r;
      }
    }
  }
}

}  // namespace
