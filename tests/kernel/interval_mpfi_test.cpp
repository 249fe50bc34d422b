// The elementary enclosures of interval.hpp against an arbitrary-precision oracle.
//
// For each function, thousands of point, narrow, wide and unbounded arguments (random, plus the
// edge cases that break implementations: the doubles nearest to k pi/2 for k up to 1e6 and
// near 1e15, the doubles closest to a multiple of pi/2 in every binade up to 2^1023, 1e300,
// subnormals, +-0, infinite bounds, arguments near +-1 for asin / acos and near 0 and 1 for
// log) go through MPFI at 200 bits. Its result, rounded outward to doubles, is the tightest double
// enclosure of the exact range; genmod's result must contain it. genmod runs in all four IEEE
// rounding modes (the evaluators call it inside a RoundingScope, users in the default mode);
// the oracle always runs in the default mode.
//
// Each test prints (does not assert) how much wider than the tightest enclosure genmod's is, in
// ulps per bound: the mean and max over point and narrow arguments, where it is meaningful.
#include "genmod/kernel/interval.hpp"
#include "kernel/mpfr_value.hpp"

#include <gtest/gtest.h>
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using genmod::Interval;
using genmod::interval_detail::next_down;
using genmod::interval_detail::next_up;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();
constexpr double kMinNormal = std::numeric_limits<double>::min();
constexpr mpfr_prec_t kPrecision = 200;

// ---- MPFR / MPFI values that free themselves -------------------------------------------------

using genmod::testing::Mpfr;

class Mpfi {
 public:
  Mpfi() { mpfi_init2(v_, kPrecision); }
  explicit Mpfi(const Interval& x) : Mpfi() { mpfi_interv_d(v_, x.lo(), x.hi()); }
  ~Mpfi() { mpfi_clear(v_); }
  Mpfi(const Mpfi&) = delete;
  Mpfi& operator=(const Mpfi&) = delete;
  mpfi_ptr get() { return v_; }

  // The tightest double interval containing this one: bounds rounded outward.
  Interval to_doubles() {
    Mpfr lo, hi;
    mpfi_get_left(lo.get(), v_);
    mpfi_get_right(hi.get(), v_);
    return Interval::unchecked(mpfr_get_d(lo.get(), MPFR_RNDD), mpfr_get_d(hi.get(), MPFR_RNDU));
  }

 private:
  mpfi_t v_;
};

using MpfiUnary = int (*)(mpfi_ptr, mpfi_srcptr);
using MpfiBinary = int (*)(mpfi_ptr, mpfi_srcptr, mpfi_srcptr);

Interval mpfi_range(MpfiUnary f, const Interval& x) {
  Mpfi in(x), out;
  f(out.get(), in.get());
  return out.to_doubles();
}

Interval mpfi_range(MpfiBinary f, const Interval& a, const Interval& b) {
  Mpfi in_a(a), in_b(b), out;
  f(out.get(), in_a.get(), in_b.get());
  return out.to_doubles();
}

// x^y exactly (200 bits) rounded outward to doubles, for a point where point::pow is defined.
Interval mpfr_pow_point(double x, double y) {
  Mpfr mx, my, r;
  mpfr_set_d(mx.get(), x, MPFR_RNDN);
  mpfr_set_d(my.get(), y, MPFR_RNDN);
  mpfr_pow(r.get(), mx.get(), my.get(), MPFR_RNDN);
  const double lo = mpfr_get_d(r.get(), MPFR_RNDD), hi = mpfr_get_d(r.get(), MPFR_RNDU);
  return Interval::unchecked(lo, hi);  // may be [inf, inf] for an infinite power: compared only
}

// The double nearest to k pi / 2.
double nearest_half_pi_multiple(double k) {
  Mpfr pi;
  mpfr_set_prec(pi.get(), 400);
  mpfr_const_pi(pi.get(), MPFR_RNDN);
  mpfr_mul_d(pi.get(), pi.get(), k, MPFR_RNDN);  // k <= 2^53 is exact as a double
  mpfr_div_2ui(pi.get(), pi.get(), 1, MPFR_RNDN);
  return mpfr_get_d(pi.get(), MPFR_RNDN);
}

// ---- rounding modes -------------------------------------------------------------------------

struct Mode {
  const char* name;
  int fe;  // -1: a genmod::RoundingScope (upward)
};
constexpr Mode kModes[] = {
    {"nearest", FE_TONEAREST}, {"RoundingScope", -1}, {"downward", FE_DOWNWARD}, {"toward zero", FE_TOWARDZERO}};

Interval run_in(const Mode& mode, const std::function<Interval()>& f) {
  if (mode.fe == -1) {
    genmod::RoundingScope scope;
    return f();
  }
  const int saved = std::fegetround();
  std::fesetround(mode.fe);
  const Interval result = f();
  std::fesetround(saved);
  return result;
}

// ---- checking and tightness ---------------------------------------------------------------

// Position of a double in the ordered sequence of all doubles (-0 and +0 coincide).
std::int64_t ordinal(double x) {
  std::int64_t i;
  std::memcpy(&i, &x, sizeof i);
  return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
}

// How many doubles lie from a up to b (b >= a); exact, since long double holds 64-bit integers.
double ulps_between(double a, double b) {
  return static_cast<double>(static_cast<long double>(ordinal(b)) - static_cast<long double>(ordinal(a)));
}

std::string text(const Interval& x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// "(a, b)" for a message; a stream, since GCC 12 warns falsely on "(" + std::string.
std::string pair_text(const Interval& a, const Interval& b) {
  std::ostringstream os;
  os << '(' << text(a) << ", " << text(b) << ')';
  return os.str();
}

bool is_legal(const Interval& x) {
  if (std::isnan(x.lo()) || std::isnan(x.hi())) return std::isnan(x.lo()) && std::isnan(x.hi());
  return x.lo() <= x.hi() && x.lo() < kInf && x.hi() > -kInf;
}

// Collects the checks of one function: containment failures (asserted) and the excess width
// over the tightest enclosure (printed when the function's test ends).
class OracleCheck {
 public:
  explicit OracleCheck(std::string name) : name_(std::move(name)) {}
  OracleCheck(const OracleCheck&) = delete;
  OracleCheck& operator=(const OracleCheck&) = delete;
  ~OracleCheck() {
    EXPECT_EQ(failures_, 0) << name_ << ": enclosures that miss part of the exact range";
    EXPECT_GT(checks_, 1000) << name_ << ": too few inputs to mean anything";
    print_tightness();
  }

  // got = genmod's result for `input` in `mode`; exact = the oracle's range as doubles
  // (empty when no point of the input is in the domain). `narrow` marks point and narrow
  // inputs, for which the tightness figures are meaningful.
  // `typical` is false for arguments of 2^26 and more, where sin, cos and tan are widened by
  // an absolute error bound (see interval_elementary.cpp) that dwarfs their tiny values near
  // multiples of pi/2; the tightness printout shows the typical cases separately.
  void check(const Interval& got, const Interval& exact, const std::string& input, const Mode& mode, bool narrow,
             bool must_be_tightest = false, bool typical = true) {
    ++checks_;
    const bool legal = is_legal(got);
    const bool ok =
        legal && (exact.is_empty() ? got.is_empty() : got.contains(exact)) && (!must_be_tightest || got == exact);
    if (!ok && ++failures_ <= 10) {
      ADD_FAILURE() << name_ << input << " in mode " << mode.name << " = " << got << (legal ? "" : " (illegal)")
                    << ", exact range " << exact;
    }
    if (ok && narrow && !exact.is_empty()) {
      add_excess(ulps_between(got.lo(), exact.lo()), exact.lo(), got.lo(), typical);
      add_excess(ulps_between(exact.hi(), got.hi()), exact.hi(), got.hi(), typical);
    }
  }

 private:
  void add_excess(double ulps, double exact_bound, double got_bound, bool typical) {
    if (std::isinf(exact_bound) || std::isinf(got_bound)) return;
    excess_.push_back(ulps);
    if (typical) typical_excess_.push_back(ulps);
  }

  static double mean(const std::vector<double>& v) {
    double sum = 0.0;
    for (const double e : v) sum += e;
    return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
  }

  // Mean, median, 99th percentile and max of the excess width per bound, in ulps, over point
  // and narrow arguments (and the mean over typical arguments when some are not).
  void print_tightness() {
    if (excess_.empty()) return;
    std::sort(excess_.begin(), excess_.end());
    const auto at = [&](double q) {
      return excess_[static_cast<std::size_t>(q * static_cast<double>(excess_.size() - 1))];
    };
    std::printf(
        "[ tightness] %-22s %7ld checks; excess width over the tightest enclosure (point/narrow arguments) "
        "in ulps per bound: mean %.3g, median %.0f, 99%% %.0f, max %.3g",
        name_.c_str(), checks_, mean(excess_), at(0.5), at(0.99), excess_.back());
    if (typical_excess_.size() != excess_.size()) std::printf("; mean %.3g below 2^26", mean(typical_excess_));
    std::printf("\n");
  }

  std::string name_;
  long checks_ = 0;
  int failures_ = 0;
  std::vector<double> excess_, typical_excess_;
};

// ---- arguments ------------------------------------------------------------------------------

struct Argument {
  Interval x;
  bool narrow;  // a point or a few ulps wide
};

// Values that break elementary function code, for every function.
std::vector<double> common_edges() {
  std::vector<double> v = {
      0.0,    -0.0,    kTiny, -kTiny, 1e-310, -1e-310, kMinNormal, -kMinNormal, next_down(kMinNormal),
      1e-300, -1e-300, 1e-20, -1e-20, 0.5,    -0.5,    1.0,        -1.0,        2.0,
      -2.0,   10.0,    -10.0, 1e22,   -1e22,  0x1p53,  0x1p53 + 2, 1e300,       -1e300,
      kMax,   -kMax};
  return v;
}

// For every binade 2^e, the doubles closest to a multiple of pi/2: x = q 2^(e-52) with q a
// continued-fraction denominator of frac(2^(e-52) 2/pi) (best approximations make
// q 2^(e-52) 2/pi closest to an integer). The last two with q < 2^53 are kept. These are the
// hardest arguments for trigonometric argument reduction in the whole double range.
std::vector<double> hardest_half_pi_multiples() {
  std::vector<double> out;
  for (int e = 1; e <= 1023; ++e) {
    // Bits for the integer part of 2^(e-52) 2/pi and 300 of its fraction; the expansion up to
    // denominators of 2^53 consumes about 2 x 53 of them.
    const mpfr_prec_t precision = e + 300;
    Mpfr alpha, inverse, digit;
    for (Mpfr* m : {&alpha, &inverse, &digit}) mpfr_set_prec(m->get(), precision);
    mpfr_const_pi(alpha.get(), MPFR_RNDN);
    mpfr_ui_div(alpha.get(), 2, alpha.get(), MPFR_RNDN);
    mpfr_mul_2si(alpha.get(), alpha.get(), e - 52, MPFR_RNDN);
    mpfr_frac(alpha.get(), alpha.get(), MPFR_RNDN);
    double q_prev = 0.0, q = 1.0, last = 0.0, before_last = 0.0;  // denominators q_{-1}, q_0
    mpfr_set(inverse.get(), alpha.get(), MPFR_RNDN);
    while (!mpfr_zero_p(inverse.get())) {
      mpfr_ui_div(inverse.get(), 1, inverse.get(), MPFR_RNDN);
      mpfr_floor(digit.get(), inverse.get());
      mpfr_sub(inverse.get(), inverse.get(), digit.get(), MPFR_RNDN);
      const double next = mpfr_get_d(digit.get(), MPFR_RNDN) * q + q_prev;  // exact below 2^53
      if (next >= 0x1p53) break;
      q_prev = q;
      q = next;
      before_last = last;
      last = q;
    }
    for (const double m : {last, before_last}) {
      const double x = std::ldexp(m, e - 52);
      if (m > 0.0 && x > 1.5 && x < kInf) out.push_back(x);
    }
  }
  return out;
}

// Arguments near multiples of pi/2: the doubles nearest to k pi/2 (and neighbours) for small
// k, k up to 1e6 and k near 1e15, and the hardest ones of every binade (also negated).
std::vector<double> half_pi_multiples(std::mt19937_64& rng) {
  std::vector<double> ks;
  for (int k = -16; k <= 64; ++k) ks.push_back(k);
  std::uniform_real_distribution<double> small(1.0, 1e6), large(6.0e14, 7.0e14);
  for (int i = 0; i < 150; ++i) ks.push_back(std::round(small(rng)));
  for (int i = 0; i < 80; ++i) ks.push_back(std::round(large(rng)));
  std::vector<double> v;
  for (const double k : ks) {
    const double x = nearest_half_pi_multiple(k);
    v.insert(v.end(), {x, next_up(x), next_down(x), next_up(next_up(x)), -x});
  }
  static const std::vector<double> hardest = hardest_half_pi_multiples();
  for (const double x : hardest) v.insert(v.end(), {x, -x});
  return v;
}

std::vector<double> near(double x, int steps) {
  std::vector<double> v = {x};
  double lo = x, hi = x;
  for (int i = 0; i < steps; ++i) v.insert(v.end(), {lo = next_down(lo), hi = next_up(hi)});
  return v;
}

// Random doubles: uniform on [-range, range] and log-uniform magnitudes 10^[-e, e].
std::vector<double> random_values(std::mt19937_64& rng, int count, double range, double max_exponent) {
  std::uniform_real_distribution<double> uniform(-range, range), exponent(-max_exponent, max_exponent), coin(0, 1);
  std::vector<double> v;
  for (int i = 0; i < count; ++i) {
    v.push_back(uniform(rng));
    v.push_back((coin(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng)));
  }
  return v;
}

// Point, narrow, wide and unbounded intervals built from a pool of values.
std::vector<Argument> arguments_from(const std::vector<double>& pool, std::mt19937_64& rng) {
  std::vector<Argument> out;
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  std::uniform_int_distribution<int> steps(1, 6);
  for (const double v : pool) {
    out.push_back({Interval(v, v), true});
    double w = v;
    for (int i = steps(rng); i > 0; --i) w = next_up(w);
    if (w < kInf) out.push_back({Interval(v, w), true});
    const double u = pool[pick(rng)];
    out.push_back({Interval(std::min(u, v), std::max(u, v)), false});
    const double relative = v + std::abs(v) * 1e-9;
    if (relative > v && relative < kInf) out.push_back({Interval(v, relative), false});
  }
  for (int i = 0; i < 40; ++i) {
    const double v = pool[pick(rng)];
    out.push_back({Interval(-kInf, v), false});
    out.push_back({Interval(v, kInf), false});
  }
  out.push_back({Interval::entire(), false});
  return out;
}

// ---- unary functions ------------------------------------------------------------------------

struct UnaryCase {
  const char* name;
  std::function<Interval(const Interval&)> genmod;
  // The exact range of the function over the part of x in its domain, as doubles.
  std::function<Interval(const Interval&)> exact;
  std::vector<double> edges;  // extra values for this function
  double range, max_exponent;
  bool must_be_tightest;           // exact functions
  bool reduces_modulo_pi = false;  // sin, cos, tan: see OracleCheck::check's `typical`
};

// The oracle over the part of x inside [lo, hi]; empty if none.
std::function<Interval(const Interval&)> on_domain(MpfiUnary f, double lo, double hi) {
  return [=](const Interval& x) {
    const Interval inside = intersect(x, Interval::unchecked(lo, hi));
    return inside.is_empty() ? inside : mpfi_range(f, inside);
  };
}

void run_unary(const UnaryCase& c, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> pool = common_edges();
  pool.insert(pool.end(), c.edges.begin(), c.edges.end());
  const std::vector<double> random = random_values(rng, 500, c.range, c.max_exponent);
  pool.insert(pool.end(), random.begin(), random.end());
  OracleCheck check(c.name);
  for (const Argument& arg : arguments_from(pool, rng)) {
    const Interval exact = c.exact(arg.x);
    for (const Mode& mode : kModes) {
      const Interval got = run_in(mode, [&] { return c.genmod(arg.x); });
      const bool typical = !c.reduces_modulo_pi || std::max(std::abs(arg.x.lo()), std::abs(arg.x.hi())) < 0x1p26;
      check.check(got, exact, text(arg.x), mode, arg.narrow, c.must_be_tightest, typical);
    }
  }
}

std::function<Interval(const Interval&)> total(MpfiUnary f) {
  return [=](const Interval& x) { return mpfi_range(f, x); };
}

// Endpoint oracle for the exact, monotone step functions floor and ceil.
std::function<Interval(const Interval&)> monotone_mpfr(int (*f)(mpfr_ptr, mpfr_srcptr)) {
  return [=](const Interval& x) {
    Mpfr lo, hi;
    mpfr_set_d(lo.get(), x.lo(), MPFR_RNDN);
    mpfr_set_d(hi.get(), x.hi(), MPFR_RNDN);
    f(lo.get(), lo.get());
    f(hi.get(), hi.get());
    return Interval::unchecked(mpfr_get_d(lo.get(), MPFR_RNDD), mpfr_get_d(hi.get(), MPFR_RNDU));
  };
}

TEST(IntervalMpfi, Sin) {
  std::mt19937_64 rng(1);
  run_unary({"sin", [](const Interval& x) { return genmod::sin(x); }, total(mpfi_sin), half_pi_multiples(rng), 20.0,
             300.0, false, true},
            101);
}

TEST(IntervalMpfi, Cos) {
  std::mt19937_64 rng(2);
  run_unary({"cos", [](const Interval& x) { return genmod::cos(x); }, total(mpfi_cos), half_pi_multiples(rng), 20.0,
             300.0, false, true},
            102);
}

TEST(IntervalMpfi, Tan) {
  std::mt19937_64 rng(3);
  run_unary({"tan", [](const Interval& x) { return genmod::tan(x); }, total(mpfi_tan), half_pi_multiples(rng), 20.0,
             300.0, false, true},
            103);
}

TEST(IntervalMpfi, Exp) {
  std::vector<double> edges = {
      709.782712893384, 709.7827128933841, 709.0, 710.0, -708.39641853226408, -745.13321910194110, -745.2,
      -744.0,           -1e-300,           1e-300};
  for (const double v : near(0.0, 4)) edges.push_back(v);
  run_unary({"exp", [](const Interval& x) { return genmod::exp(x); }, total(mpfi_exp), edges, 750.0, 3.0, false}, 104);
}

TEST(IntervalMpfi, Log) {
  std::vector<double> edges = near(1.0, 6);
  for (const double v : {kTiny, 2 * kTiny, 1e-320, kMinNormal, 1e-300, 1 + 1e-12, 1 - 1e-12, 2.718281828459045})
    edges.push_back(v);
  // Domain (0, inf]: [0, 0] has no point in it.
  const auto exact = [](const Interval& x) {
    return x.hi() > 0.0 ? on_domain(mpfi_log, 0.0, kInf)(x) : Interval::empty();
  };
  run_unary({"log", [](const Interval& x) { return genmod::log(x); }, exact, edges, 4.0, 300.0, false}, 105);
}

TEST(IntervalMpfi, Sqrt) {
  std::vector<double> edges;
  for (const double r : {1.0, 2.0, 3.0, 1e-5, 12345.0, 1e150, 94906265.0, 1e-160}) {
    const std::vector<double> around = near(r * r, 2);
    edges.insert(edges.end(), around.begin(), around.end());
  }
  run_unary({"sqrt", [](const Interval& x) { return genmod::sqrt(x); }, on_domain(mpfi_sqrt, 0.0, kInf), edges, 100.0,
             300.0, false},
            106);
}

TEST(IntervalMpfi, Asin) {
  std::vector<double> edges;
  for (const double v : {1.0, -1.0, 0.5, -0.5}) {
    const std::vector<double> around = near(v, 6);
    edges.insert(edges.end(), around.begin(), around.end());
  }
  run_unary({"asin", [](const Interval& x) { return genmod::asin(x); }, on_domain(mpfi_asin, -1.0, 1.0), edges, 1.2,
             20.0, false},
            107);
}

TEST(IntervalMpfi, Acos) {
  std::vector<double> edges;
  for (const double v : {1.0, -1.0, 0.5, -0.5}) {
    const std::vector<double> around = near(v, 6);
    edges.insert(edges.end(), around.begin(), around.end());
  }
  run_unary({"acos", [](const Interval& x) { return genmod::acos(x); }, on_domain(mpfi_acos, -1.0, 1.0), edges, 1.2,
             20.0, false},
            108);
}

TEST(IntervalMpfi, Atan) {
  run_unary({"atan",
             [](const Interval& x) { return genmod::atan(x); },
             total(mpfi_atan),
             {1e16, -1e16, 1e8},
             10.0,
             300.0,
             false},
            109);
}

TEST(IntervalMpfi, Square) {
  run_unary({"square",
             [](const Interval& x) { return genmod::square(x); },
             total(mpfi_sqr),
             {1e154, 1.5e154, 1e-162},
             10.0,
             300.0,
             true},
            110);
}

TEST(IntervalMpfi, Abs) {
  run_unary({"abs", [](const Interval& x) { return genmod::abs(x); }, total(mpfi_abs), {}, 10.0, 300.0, true}, 111);
}

TEST(IntervalMpfi, Floor) {
  run_unary({"floor",
             [](const Interval& x) { return genmod::floor(x); },
             monotone_mpfr(mpfr_floor),
             {2.5, -2.5, 0x1p52 + 0.5},
             10.0,
             20.0,
             true},
            112);
}

TEST(IntervalMpfi, Ceil) {
  run_unary({"ceil",
             [](const Interval& x) { return genmod::ceil(x); },
             monotone_mpfr(mpfr_ceil),
             {2.5, -2.5, 0x1p52 + 0.5},
             10.0,
             20.0,
             true},
            113);
}

// ---- binary functions -----------------------------------------------------------------------

// Pairs of arguments: every interval of a small set against every other, plus random pairs.
std::vector<std::pair<Argument, Argument>> argument_pairs(const std::vector<Argument>& small,
                                                          const std::vector<Argument>& large, std::mt19937_64& rng) {
  std::vector<std::pair<Argument, Argument>> out;
  for (const Argument& a : small)
    for (const Argument& b : small) out.emplace_back(a, b);
  std::uniform_int_distribution<std::size_t> pick(0, large.size() - 1);
  for (int i = 0; i < 3000; ++i) out.emplace_back(large[pick(rng)], large[pick(rng)]);
  return out;
}

std::vector<Argument> small_argument_set() {
  std::vector<Argument> v;
  for (const double x : {0.0, -0.0, 1.0, -1.0, 0.5, -2.0, 1e-300, -1e300, kMax}) v.push_back({Interval(x, x), true});
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {-1, 1}, {0, 1}, {-1, 0}, {1, 2}, {-2, -1}, {-kInf, kInf}, {0, kInf}, {-kInf, 0}, {1, kInf}, {-kInf, -1}})
    v.push_back({Interval(lo, hi), false});
  return v;
}

// [-pi, pi] rounded outward.
Interval minus_pi_to_pi() {
  Mpfr pi;
  mpfr_const_pi(pi.get(), MPFR_RNDN);
  return Interval::unchecked(-mpfr_get_d(pi.get(), MPFR_RNDU), mpfr_get_d(pi.get(), MPFR_RNDU));
}

// MPFI has no answer (NaN) for boxes holding the origin. C's atan2 there takes the values 0,
// +-pi/2 and, through the signed zeros of the negative x axis, +-pi: the whole [-pi, pi].
Interval atan2_range(const Interval& y, const Interval& x) {
  const Interval r = mpfi_range(mpfi_atan2, y, x);
  return r.is_empty() ? minus_pi_to_pi() : r;
}

TEST(IntervalMpfi, Atan2) {
  std::mt19937_64 rng(114);
  std::vector<double> pool = common_edges();
  const std::vector<double> random = random_values(rng, 300, 10.0, 300.0);
  pool.insert(pool.end(), random.begin(), random.end());
  OracleCheck check("atan2");
  for (const auto& pair : argument_pairs(small_argument_set(), arguments_from(pool, rng), rng)) {
    const Argument &y = pair.first, &x = pair.second;  // (no structured bindings: Clang 14 cannot capture them)
    const Interval exact = atan2_range(y.x, x.x);
    for (const Mode& mode : kModes) {
      const Interval got = run_in(mode, [&] { return genmod::atan2(y.x, x.x); });
      check.check(got, exact, pair_text(y.x, x.x), mode, y.narrow && x.narrow);
    }
  }
}

TEST(IntervalMpfi, MinMax) {
  std::mt19937_64 rng(115);
  std::vector<double> pool = common_edges();
  const std::vector<double> random = random_values(rng, 300, 10.0, 300.0);
  pool.insert(pool.end(), random.begin(), random.end());
  OracleCheck check_min("min"), check_max("max");
  for (const auto& pair : argument_pairs(small_argument_set(), arguments_from(pool, rng), rng)) {
    const Argument &a = pair.first, &b = pair.second;
    // min and max are monotone in both arguments: the exact range comes from the bounds.
    Mpfr lo_a, lo_b, hi_a, hi_b, r;
    mpfr_set_d(lo_a.get(), a.x.lo(), MPFR_RNDN);
    mpfr_set_d(lo_b.get(), b.x.lo(), MPFR_RNDN);
    mpfr_set_d(hi_a.get(), a.x.hi(), MPFR_RNDN);
    mpfr_set_d(hi_b.get(), b.x.hi(), MPFR_RNDN);
    const auto range = [&](int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t)) {
      f(r.get(), lo_a.get(), lo_b.get(), MPFR_RNDN);
      const double lo = mpfr_get_d(r.get(), MPFR_RNDD);
      f(r.get(), hi_a.get(), hi_b.get(), MPFR_RNDN);
      return Interval::unchecked(lo, mpfr_get_d(r.get(), MPFR_RNDU));
    };
    const Interval exact_min = range(mpfr_min), exact_max = range(mpfr_max);
    const std::string input = pair_text(a.x, b.x);
    for (const Mode& mode : kModes) {
      check_min.check(run_in(mode, [&] { return genmod::min(a.x, b.x); }), exact_min, input, mode, true, true);
      check_max.check(run_in(mode, [&] { return genmod::max(a.x, b.x); }), exact_max, input, mode, true, true);
    }
  }
}

// ---- pow ------------------------------------------------------------------------------------

// pow over boxes with positive, finite bases and finite exponents. The exact range comes from
// the corners (MPFR) and is cross-checked with MPFI's exp(y log x), whose interval evaluation
// is exact up to rounding because y and log x each occur once.
TEST(IntervalMpfi, PowPositiveBases) {
  std::mt19937_64 rng(116);
  std::vector<double> bases = {kTiny, 1e-310, kMinNormal, 1e-300, 0.5, 1.0, 2.0, 10.0, 1e300, kMax};
  for (const double v : near(1.0, 4)) bases.push_back(v);
  std::vector<double> exponents = {0.0, 1.0, 2.0, 3.0, -1.0, -2.0, 0.5, -0.5, 1.0 / 3, 1e-300, 1e3, -1e3, 1e300};
  std::uniform_real_distribution<double> log_base(-300.0, 300.0), exponent(-20.0, 20.0), unit(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    bases.push_back(std::pow(10.0, log_base(rng)));
    bases.push_back(unit(rng) * 10.0 + kTiny);
    exponents.push_back(exponent(rng));
    exponents.push_back(std::round(exponent(rng)));
  }
  const auto positive_finite = [](const std::vector<Argument>& args) {
    std::vector<Argument> out;
    for (const Argument& a : args)
      if (a.x.lo() > 0.0 && a.x.hi() < kInf) out.push_back(a);
    return out;
  };
  const auto finite = [](const std::vector<Argument>& args) {
    std::vector<Argument> out;
    for (const Argument& a : args)
      if (a.x.is_bounded()) out.push_back(a);
    return out;
  };
  const std::vector<Argument> xs = positive_finite(arguments_from(bases, rng));
  const std::vector<Argument> ys = finite(arguments_from(exponents, rng));
  std::uniform_int_distribution<std::size_t> pick_x(0, xs.size() - 1), pick_y(0, ys.size() - 1);
  OracleCheck check("pow");
  for (int i = 0; i < 6000; ++i) {
    const Argument& x = xs[pick_x(rng)];
    const Argument& y = ys[pick_y(rng)];
    // The exact range is the hull of the corner values (x^y is monotone in x and in y for
    // positive x); mpfr_pow gives them correctly rounded, and exact when they are doubles.
    Interval exact = Interval::empty();
    for (const double px : {x.x.lo(), x.x.hi()})
      for (const double py : {y.x.lo(), y.x.hi()}) exact = hull(exact, mpfr_pow_point(px, py));
    // MPFI's evaluation of exp(y log x), independent of that monotonicity argument, must agree
    // up to its own outward rounding.
    Mpfi mx(x.x), my(y.x), r;
    mpfi_log(r.get(), mx.get());
    mpfi_mul(r.get(), r.get(), my.get());
    mpfi_exp(r.get(), r.get());
    const Interval independent = r.to_doubles();
    ASSERT_TRUE(Interval::unchecked(next_down(exact.lo()), next_up(exact.hi())).contains(independent))
        << text(x.x) << " ^ " << text(y.x) << ": corners " << exact << ", MPFI " << independent;
    for (const Mode& mode : kModes) {
      const Interval got = run_in(mode, [&] { return genmod::pow(x.x, y.x); });
      check.check(got, exact, text(x.x) + " ^ " + text(y.x), mode, x.narrow && y.narrow);
    }
  }
}

// pow at points of every kind, including zero and negative bases: the value must contain the
// exact power (MPFR), and an error (point::pow is NaN) must give an empty, certainly-erroneous
// result.
TEST(IntervalMpfi, PowPoints) {
  std::vector<double> bases = {0.0,
                               -0.0,
                               1.0,
                               -1.0,
                               2.0,
                               -2.0,
                               0.5,
                               -0.5,
                               3.0,
                               -3.0,
                               10.0,
                               -10.0,
                               kTiny,
                               -kTiny,
                               1e-300,
                               -1e-300,
                               1e300,
                               -1e300,
                               kMax,
                               -kMax,
                               1.0000000000000002,
                               -0.9999999999999999};
  std::vector<double> exponents = {0.0, -0.0, 1.0, -1.0, 2.0,     -2.0,   3.0,        -3.0,  0.5,    -0.5, 1.0 / 3,
                                   7.0, -7.0, 1e3, -1e3, 1e3 + 1, 0x1p53, 0x1p53 + 2, 1e300, -1e300, 2.5,  kTiny};
  OracleCheck check("pow at points");
  long errors = 0;
  for (const double x : bases) {
    for (const double y : exponents) {
      const bool defined = !std::isnan(genmod::point::pow(x, y));
      const Interval exact = defined ? mpfr_pow_point(x, y) : Interval::empty();
      for (const Mode& mode : kModes) {
        std::uint8_t err = genmod::kNoError;
        const Interval got = run_in(mode, [&] { return genmod::pow(Interval(x), Interval(y), &err); });
        EXPECT_EQ(err, defined ? genmod::kNoError : genmod::kCertainError) << x << " ^ " << y;
        std::ostringstream input_text;  // (a stream: GCC 12 warns falsely on "(" + std::string)
        input_text << '(' << x << ")^(" << y << ')';
        const std::string input = input_text.str();
        if (exact.lo() == kInf) {  // an overflowing power: the bound must reach +inf
          EXPECT_EQ(got.hi(), kInf) << input;
          continue;
        }
        if (exact.hi() == -kInf) {
          EXPECT_EQ(got.lo(), -kInf) << input;
          continue;
        }
        check.check(got, exact, input, mode, true);
      }
      errors += !defined;
    }
  }
  EXPECT_GT(errors, 50);  // the table does exercise the error cases
}

// pow over boxes of every kind (negative and zero bases, integer and non-integer exponents,
// unbounded): at sampled points, including the corners, 0 and the integers of y, every defined
// exact value lies in the enclosure and every undefined one is flagged.
TEST(IntervalMpfi, PowBoxesContainSamples) {
  std::mt19937_64 rng(117);
  std::vector<double> pool = {0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 0.5, -0.5, 3.0, -3.0, 1e-300, 1e300, -1e300};
  std::uniform_real_distribution<double> uniform(-4.0, 4.0), unit(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    pool.push_back(uniform(rng));
    pool.push_back(std::round(uniform(rng)));
  }
  const std::vector<Argument> args = arguments_from(pool, rng);
  std::uniform_int_distribution<std::size_t> pick(0, args.size() - 1);
  OracleCheck check("pow at samples of boxes");
  for (int i = 0; i < 3000; ++i) {
    const Interval x = args[pick(rng)].x, y = args[pick(rng)].x;
    std::vector<double> xs = {x.lo(), x.hi()}, ys = {y.lo(), y.hi()};
    if (x.contains(0.0)) xs.push_back(0.0);
    for (double k = std::ceil(std::max(y.lo(), -5.0)); k <= std::min(y.hi(), 5.0); ++k) ys.push_back(k);
    for (int j = 0; j < 3; ++j) {
      xs.push_back(std::clamp(x.lo() + unit(rng) * std::min(x.width(), 10.0), x.lo(), x.hi()));
      ys.push_back(std::clamp(y.lo() + unit(rng) * std::min(y.width(), 10.0), y.lo(), y.hi()));
    }
    for (const Mode& mode : kModes) {
      std::uint8_t err = genmod::kNoError;
      const Interval got = run_in(mode, [&] { return genmod::pow(x, y, &err); });
      for (const double px : xs) {
        for (const double py : ys) {
          if (!std::isfinite(px) || !std::isfinite(py)) continue;
          const std::string input =
              text(x) + " ^ " + text(y) + " at (" + std::to_string(px) + ", " + std::to_string(py) + ")";
          if (std::isnan(genmod::point::pow(px, py))) {
            EXPECT_TRUE(err & genmod::kMaybeError) << input;
            continue;
          }
          EXPECT_NE(err, genmod::kCertainError) << input;
          const Interval exact = mpfr_pow_point(px, py);
          if (exact.lo() == kInf || exact.hi() == -kInf) {
            EXPECT_TRUE(got.contains(exact.lo() == kInf ? kInf : -kInf)) << input << " = " << got;
            continue;
          }
          check.check(got, exact, input, mode, false);
        }
      }
    }
  }
}

}  // namespace
