// Reading and writing the .vm text format.
#include "genmod/kernel/number_text.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <locale>
#include <sstream>

namespace genmod {
namespace {

Fn read(const std::string& text) {
  std::istringstream in(text);
  return read_vm(in, "test.vm");
}

// The line number and problem of a malformed file.
std::string error_of(const std::string& text, int* line = nullptr) {
  try {
    read(text);
  } catch (const VmFormatError& e) {
    if (line) *line = e.line();
    return e.what();
  }
  return "";
}

TEST(VmFormat, ReadsProspero) {
  const Fn f = load_vm(GENMOD_DATA_DIR "/prospero.vm");
  EXPECT_EQ(f.dim(), 1u);
  EXPECT_EQ(f.inputs(), (std::vector<int>{0, 1}));
  const Tape t(f);
  // 7,866 lines; constants become immediates of the clauses that use them.
  EXPECT_GT(t.size(), 6000u);
  EXPECT_LT(t.size(), 7866u);
}

TEST(VmFormat, EvaluatesAsWritten) {
  const Fn f = read("# a circle of radius 0.5\n_0 var-x\n_1 var-y\n_2 square _0\n_3 square _1\n_4 add _2 _3\n"
                    "_5 sqrt _4\n_6 const 0.5\n_7 sub _5 _6\n");
  EXPECT_DOUBLE_EQ(evaluate(f, std::vector<double>{0.3, 0.4})[0], 0.0);
  EXPECT_DOUBLE_EQ(evaluate(f, std::vector<double>{0.0, 1.0})[0], 0.5);
  const Fn g = read("a var-z\nb ln a\nc var-7\nd mul b c\n");
  EXPECT_EQ(g.inputs(), (std::vector<int>{2, 7}));
}

TEST(VmFormat, MalformedFilesNameTheLineAndProblem) {
  int line = 0;
  EXPECT_NE(error_of("_0 var-x\n_1 frobnicate _0\n", &line).find("unknown opcode 'frobnicate'"), std::string::npos);
  EXPECT_EQ(line, 2);
  EXPECT_NE(error_of("_0 var-x\n\n# note\n_1 add _0 _9\n", &line).find("'_9' is not defined"), std::string::npos);
  EXPECT_EQ(line, 4);
  EXPECT_NE(error_of("_0 var-x\n_0 var-y\n", &line).find("defined twice"), std::string::npos);
  EXPECT_NE(error_of("_0 const 1.5x\n").find("not a number"), std::string::npos);
  EXPECT_NE(error_of("_0 var-x\n_1 add _0\n").find("takes 2 operand(s), got 1"), std::string::npos);
  EXPECT_NE(error_of("_0 var-q\n").find("not a coordinate"), std::string::npos);
  EXPECT_NE(error_of("lonely\n").find("expected 'NAME OPCODE ARGS"), std::string::npos);
  EXPECT_NE(error_of("# nothing\n").find("defines nothing"), std::string::npos);
  EXPECT_NE(error_of("_0 var-x\n_1 add _0 _0\n").find(""), std::string::npos);
  EXPECT_EQ(error_of("_0 var-x\n_1 add _0 _0\n"), "");
  EXPECT_THROW(load_vm("/nonexistent/model.vm"), std::runtime_error);
}

TEST(VmFormat, WriteThenReadGivesTheSameFunction) {
  testing::RandomFunctions rnd(31);
  for (int trial = 0; trial < 200; ++trial) {
    const Fn f = rnd.function(6);
    std::ostringstream out;
    write_vm(out, f);
    const Fn g = read(out.str());
    EXPECT_EQ(g.node(0), f.node(0)) << out.str();  // hash-consing makes equal DAGs identical
  }
  const Fn prospero = load_vm(GENMOD_DATA_DIR "/prospero.vm");
  std::ostringstream out;
  write_vm(out, prospero);
  EXPECT_EQ(read(out.str()).node(0), prospero.node(0));
  EXPECT_THROW(write_vm(out, cat({x(0), x(1)})), std::invalid_argument);
}

// Every double genmod writes reads back exactly: subnormals (the old reader refused them as
// ERANGE), extremes, signed zero, infinities; whatever the stream's locale says about decimal
// points; and the same reader serves the curve files (operators/curve_file.cpp).
TEST(VmFormat, EveryConstantRoundTripsWhateverTheLocale) {
  struct Comma : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    std::string do_grouping() const override { return "\3"; }
  };
  const double values[] = {std::numeric_limits<double>::denorm_min(), 4.9406564584124654e-324, 2.2250738585072009e-308,
                           -std::numeric_limits<double>::max(), 1.0 / 3.0, -0.0, 1234567.0, 0.1,
                           std::numeric_limits<double>::infinity()};
  for (double v : values) {
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new Comma));
    write_vm(out, Fn(v) + x(0));
    const Fn back = read(out.str());
    EXPECT_EQ(back.node(0), (Fn(v) + x(0)).node(0)) << out.str();
  }
  EXPECT_EQ(parse_double("+1.5"), 1.5);
  EXPECT_EQ(parse_double("4.9406564584124654e-324"), std::numeric_limits<double>::denorm_min());
  EXPECT_FALSE(parse_double("1e309"));   // overflow
  EXPECT_FALSE(parse_double("1e-330"));  // underflow to zero
  EXPECT_FALSE(parse_double("1,5"));
  EXPECT_FALSE(parse_double(""));
  EXPECT_FALSE(parse_double("0x1p3"));
}

// Reading has limits: a file without newlines (/dev/zero) or too large ends in an error that
// names the limit, not in a process that fills the memory; a read error is not taken for the
// end of the file.
TEST(VmFormat, ReadingStopsAtItsLimitsAndReportsReadErrors) {
  auto load_error = [](const std::string& path, VmReadLimits limits) {
    try {
      load_vm(path, limits);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(load_error("/dev/zero", {}).find("a line is longer than the limit of 1048576 bytes"), std::string::npos);
  EXPECT_NE(load_error(GENMOD_DATA_DIR "/prospero.vm", {.max_bytes = 1000}).find("larger than the limit of 1000"),
            std::string::npos);
  EXPECT_NE(load_error(GENMOD_DATA_DIR "/prospero.vm", {.max_line = 10}).find("longer than the limit of 10"),
            std::string::npos);
  EXPECT_NE(load_error(GENMOD_DATA_DIR, {}).find("read error"), std::string::npos);  // a directory
  EXPECT_EQ(load_error(GENMOD_DATA_DIR "/prospero.vm", {}), "no exception");
  std::istringstream in("_0 var-x\n_1 add _0 _0\n" + std::string(64, 'x'));
  EXPECT_THROW(read_vm(in, "s", {.max_line = 32}), VmFormatError);
}

TEST(VmFormat, ErrorMessagesEscapeControlBytes) {
  const std::string message = error_of("_0 var-x\n_1 fr\x1b[2Job _0\n");
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
  EXPECT_NE(message.find("fr\\x1b[2Job"), std::string::npos) << message;
  EXPECT_EQ(printable(std::string(100, 'a'), 10), "aaaaaaaaaa...");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\\xc3\\xa9");
}

}  // namespace
}  // namespace genmod
