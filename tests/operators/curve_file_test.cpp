// The curve file format: the sample files parse into the curves they describe, every kind
// round-trips, and each malformed input names its line.
#include "genmod/operators/curve_file.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/kernel/point_evaluator.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace genmod {
namespace {

const std::string kCurves = GENMOD_DATA_DIR "/../models/curves/";

TEST(CurveFile, SampleFilesParse) {
  const Fn arc = crv(kCurves + "quarter_circle.crv", x(0));
  for (double u = 0; u <= 1; u += 0.125) EXPECT_NEAR(evaluate(length(arc), std::vector<double>{u})[0], 1.0, 1e-15);
  const Curve profile = load_curve(kCurves + "profile.crv");
  EXPECT_EQ(profile.degree(), 3);
  EXPECT_EQ(profile.knots().size(), 11u);
  EXPECT_EQ(profile.control_points()[6][1], 1.0);
  const auto end = evaluate(profile(x(0)), std::vector<double>{1.0});
  EXPECT_EQ(end[0], 0.5);  // clamped: interpolates the last point
}

TEST(CurveFile, EveryKindParses) {
  const std::string points = "point 0 0\npoint 1 2\npoint 3 1\npoint 4 0\n";
  for (const char* kind : {"polyline", "bezier", "catmull-rom"}) {
    const Curve c = parse_curve(std::string("crv 1\ntype ") + kind + "\ndimension 2\n" + points);
    EXPECT_EQ(c.dimension(), 2);
    EXPECT_EQ(evaluate(c(x(0)), std::vector<double>{1.0})[0], 4.0) << kind;
  }
  const Curve h = parse_curve("crv 1\ntype hermite\ndimension 1\npoint 0\ntangent 1\npoint 1\ntangent 0\n");
  EXPECT_NEAR(evaluate(derivative(h(x(0)), 0), std::vector<double>{0.0})[0], 1.0, 1e-14);
  const Curve u = parse_curve("crv 1\ntype bspline\ndimension 1\ndegree 2\nclamped no\n" + std::string("point 0\npoint 1\npoint 0\npoint 1\n"));
  EXPECT_EQ(u.knots().front(), -1.0);
}

// The line named by the error for `text`, and a check that the message names the problem.
int error_line(const std::string& text, const std::string& problem) {
  try {
    parse_curve(text, "test.crv");
  } catch (const CurveFileError& e) {
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test.crv:" + std::to_string(e.line())), std::string::npos) << e.what();
    return e.line();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return -1;
}

TEST(CurveFile, ErrorsNameTheLine) {
  const std::string head = "crv 1\ntype bspline\ndimension 2\ndegree 2\n";  // lines 1-4
  EXPECT_EQ(error_line("", "empty"), 0);
  EXPECT_EQ(error_line("# comment\ncurve 1\n", "header"), 2);
  EXPECT_EQ(error_line("crv 2\n", "version"), 1);
  EXPECT_EQ(error_line("crv 1\ntype spiral\n", "unknown curve type"), 2);
  EXPECT_EQ(error_line(head + "point 0 0\npoint 1\n", "point has 1 numbers, expected 2"), 6);
  EXPECT_EQ(error_line(head + "point 0 zero\n", "`zero` is not a finite number"), 5);
  EXPECT_EQ(error_line(head + "knots 0 0 0 0.5 0.4 1 1 1\n", "nondecreasing"), 5);
  EXPECT_EQ(error_line(head + "knots 0 0 0 1 1 1\npoint 0 0\npoint 1 1\npoint 2 2\npoint 3 3\n", "need 7 knots, got 6"), 5);
  EXPECT_EQ(error_line(head + "point 0 0\npoint 1 1\n", "at least 3 points"), 6);
  EXPECT_EQ(error_line(head + "colour red\n", "unknown keyword `colour`"), 5);
  EXPECT_EQ(error_line("crv 1\npoint 0 0\n", "before `type`"), 2);
  EXPECT_EQ(error_line("crv 1\ntype nurbs\ndimension 1\ndegree 1\npoint 0 1\npoint 1 -2\n", "weight -2 is not positive"), 6);
  EXPECT_EQ(error_line("crv 1\ntype polyline\ndimension 1\ntangent 1\n", "only for hermite"), 4);
  EXPECT_EQ(error_line("crv 1\ntype hermite\ndimension 1\npoint 0\npoint 1\ntangent 0\n", "tangents"), 6);
  EXPECT_EQ(error_line("crv 1\ntype polyline\ndimension 1\ndegree 2\npoint 0\npoint 1\n", "degree is only"), 4);
  EXPECT_THROW(load_curve(kCurves + "no_such_file.crv"), CurveFileError);
}

// Curve files are read as streams within limits: /dev/zero and a directory end in an error
// naming the problem, a stream gives the same curve as the text, and limits are parameters.
TEST(CurveFile, ReadingStreamsWithinLimitsAndReportsReadErrors) {
  auto load_error = [](const std::string& path, CurveReadLimits limits) {
    try {
      load_curve(path, limits);
    } catch (const CurveFileError& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(load_error("/dev/zero", {}).find("a line is longer than the limit of 1048576 bytes"), std::string::npos);
  EXPECT_NE(load_error(kCurves, {}).find("read error"), std::string::npos);  // a directory
  EXPECT_NE(load_error(kCurves + "profile.crv", {.max_bytes = 20}).find("larger than the limit of 20"),
            std::string::npos);
  EXPECT_EQ(load_error(kCurves + "profile.crv", {}), "no exception");
  const std::string text = "crv 1\ntype bezier\ndimension 2\npoint 0 0\npoint 1 2\npoint 3 1";  // no final newline
  std::istringstream in(text);
  const Curve streamed = read_curve(in, "s");
  EXPECT_EQ(streamed.control_points(), parse_curve(text).control_points());
  std::istringstream long_line("crv 1\n# " + std::string(100, 'x') + "\n");
  try {
    read_curve(long_line, "s", {.max_line = 50});
    ADD_FAILURE() << "a line over the limit was accepted";
  } catch (const CurveFileError& e) {
    EXPECT_EQ(e.line(), 2);
  }
}

}  // namespace
}  // namespace genmod
