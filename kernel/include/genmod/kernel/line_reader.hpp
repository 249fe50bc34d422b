// Reading a text file line by line within limits: the one reader of the model (.vm) and curve
// (.crv) formats. It streams (a file is never held in memory whole), stops at once past a size
// limit (`/dev/zero` has no newline and no end), and tells a read error (a directory, a failing
// disk) from the end of the input.
#pragma once

#include <cstddef>
#include <cstdio>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {

struct TextReadLimits {
  std::size_t max_bytes = std::size_t{1} << 30;  // the whole input
  std::size_t max_line = std::size_t{1} << 20;   // one line, without its newline
};

// A limit passed or a read error, at `line` (1-based; the line being read). Format readers turn
// it into their own error type with the source's name.
class TextReadError : public std::runtime_error {
 public:
  TextReadError(int line, const std::string& problem) : std::runtime_error(problem), line_(line) {}
  int line() const noexcept { return line_; }

 private:
  int line_;
};

class LineReader {
 public:
  // Reads from a stream (a read error is the stream's badbit) or from a stdio file (ferror,
  // with errno's message). The source must outlive the reader.
  LineReader(std::istream& in, const TextReadLimits& limits);
  LineReader(std::FILE* file, const TextReadLimits& limits);

  // The next line, without its newline (a final line without one counts), into `line`; false
  // at the end. Throws TextReadError past a limit or on a read error.
  bool next(std::string& line);
  // The number of the last line returned.
  int line_number() const noexcept { return line_number_; }

 private:
  bool refill();  // false at the end of the input

  std::istream* stream_ = nullptr;
  std::FILE* file_ = nullptr;
  TextReadLimits limits_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, end_ = 0, total_ = 0;
  int line_number_ = 0;
};

}  // namespace genmod
