// The shared line reader of the .vm and .crv formats: lines across buffer boundaries, the last
// line without a newline, exact limits, and read errors told from the end of the input.
#include "genmod/kernel/line_reader.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <streambuf>

namespace genmod {
namespace {

std::vector<std::string> all_lines(std::istream& in, TextReadLimits limits = {}) {
  LineReader reader(in, limits);
  std::vector<std::string> lines;
  for (std::string line; reader.next(line);) {
    lines.push_back(line);
    EXPECT_EQ(reader.line_number(), static_cast<int>(lines.size()));
  }
  return lines;
}

TEST(LineReader, SplitsLinesAcrossBufferBoundaries) {
  // Lines of 100,000 bytes cross the 64 KiB read chunks; an empty line, a CR kept, a last line
  // without its newline.
  const std::string big(100000, 'a'), other(70000, 'b');
  std::istringstream in(big + "\n\n" + other + "\r\nend");
  const std::vector<std::string> lines = all_lines(in);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], big);
  EXPECT_EQ(lines[1], "");
  EXPECT_EQ(lines[2], other + "\r");
  EXPECT_EQ(lines[3], "end");
  std::istringstream empty("");
  EXPECT_TRUE(all_lines(empty).empty());
  std::istringstream one_newline("\n");
  EXPECT_EQ(all_lines(one_newline), std::vector<std::string>{""});
}

TEST(LineReader, LimitsAreExactAndNameTheLine) {
  std::istringstream fits("abcd\nefgh\n");  // 10 bytes, lines of 4
  EXPECT_EQ(all_lines(fits, {.max_bytes = 10, .max_line = 4}).size(), 2u);
  std::istringstream too_long("abcd\nefghi\n");
  try {
    all_lines(too_long, {.max_bytes = 100, .max_line = 4});
    ADD_FAILURE() << "a line over the limit was accepted";
  } catch (const TextReadError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("longer than the limit of 4 bytes"), std::string::npos) << e.what();
  }
  std::istringstream too_big("abcd\nefgh\nx");
  try {
    all_lines(too_big, {.max_bytes = 10, .max_line = 4});
    ADD_FAILURE() << "input over the limit was accepted";
  } catch (const TextReadError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("larger than the limit of 10 bytes"), std::string::npos) << e.what();
  }
}

// A stream whose source fails after some bytes (a disk error): the stream sets badbit.
class FailingBuffer : public std::streambuf {
 protected:
  int_type underflow() override {
    if (served_) throw std::runtime_error("disk error");
    served_ = true;
    setg(text_, text_, text_ + 6);
    return traits_type::to_int_type(text_[0]);
  }

 private:
  char text_[7] = "ab\ncd\n";
  bool served_ = false;
};

TEST(LineReader, ReadErrorsAreNotTheEnd) {
  FailingBuffer buffer;
  std::istream in(&buffer);
  EXPECT_THROW(all_lines(in), TextReadError);
  // A directory opened with stdio: fread fails with EISDIR.
  std::FILE* dir = std::fopen(GENMOD_DATA_DIR, "rb");
  ASSERT_NE(dir, nullptr);
  LineReader reader(dir, {});
  std::string line;
  try {
    reader.next(line);
    ADD_FAILURE() << "reading a directory looked like an empty file";
  } catch (const TextReadError& e) {
    EXPECT_NE(std::string(e.what()).find("read error"), std::string::npos) << e.what();
  }
  std::fclose(dir);
}

TEST(LineReader, DevZeroStopsAtTheLineLimit) {
  std::FILE* zero = std::fopen("/dev/zero", "rb");
  ASSERT_NE(zero, nullptr);
  LineReader reader(zero, {.max_bytes = std::size_t{1} << 30, .max_line = 1000});
  std::string line;
  EXPECT_THROW(reader.next(line), TextReadError);
  EXPECT_LE(line.capacity(), std::size_t{1} << 20);  // it never grew toward the byte limit
  std::fclose(zero);
}

}  // namespace
}  // namespace genmod
