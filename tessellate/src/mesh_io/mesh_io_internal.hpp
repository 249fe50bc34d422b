// The pieces the mesh file formats share: a checked output file, number formatting that
// round-trips doubles, and a line-and-token reader that names the line of a problem.
#pragma once

#include "genmod/tessellate/mesh_io.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace genmod::mesh_io {

// A file opened for writing whose every write, flush and close is checked: any failure throws
// MeshFileError naming the path and the system's reason, and removes the partial file when it
// is a regular file (never a device such as /dev/full). Output is buffered here and written in
// large blocks.
class OutputFile {
 public:
  explicit OutputFile(const std::filesystem::path& path);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();  // closes (unchecked) and removes the file if finish() was not reached

  void write(std::string_view bytes);
  void write_double(double v);  // shortest text that reads back as v
  void write_uint(std::uint64_t v);
  // "x y z" / "a b c" (each index plus `offset`), without an end of line.
  void write_point(const std::array<double, 3>& p);
  void write_indices(const std::array<std::uint32_t, 3>& t, std::uint64_t offset = 0);
  // Flushes and closes; throws MeshFileError if the data did not all reach the file.
  void finish();

 private:
  void flush_buffer();
  [[noreturn]] void fail(const std::string& what);

  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  std::string buffer_;
};

// The whole file (MeshFileError naming the path if it cannot be read).
std::string read_file(const std::filesystem::path& path);

// The lines of a text file, with their numbers, split into whitespace-separated tokens.
class TextReader {
 public:
  TextReader(std::string_view text, const std::filesystem::path& path) : text_(text), path_(path) {}

  // The next line (without its end of line); false at the end of the text.
  bool next_line();
  // The next token of the current line; empty at its end.
  std::string_view token();
  std::string_view rest_of_line() const { return line_.substr(pos_); }
  std::size_t line_number() const noexcept { return line_number_; }

  // A finite double / a non-negative integer from `token`; `what` names it in the error.
  double to_double(std::string_view token, std::string_view what) const;
  std::uint64_t to_count(std::string_view token, std::string_view what) const;
  long long to_integer(std::string_view token, std::string_view what) const;
  // The next token as a double / count; an error names `what` when it is missing or malformed.
  double next_double(std::string_view what);
  std::uint64_t next_count(std::string_view what);

  // MeshFileError: "genmod: read_mesh: 'PATH' line N: WHAT".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::string_view text_;
  const std::filesystem::path& path_;
  std::size_t next_ = 0;  // start of the next line in text_
  std::string_view line_;
  std::size_t pos_ = 0;
  std::size_t line_number_ = 0;
};

// A file-level problem: "genmod: read_mesh: 'PATH': WHAT".
[[noreturn]] void fail_reading(const std::filesystem::path& path, const std::string& what);

// Appends the triangles of the polygon `corners` (fanned from the first corner).
void add_polygon(Mesh& mesh, const std::uint32_t* corners, std::size_t count);

// `text` in single quotes, for messages.
std::string quoted(std::string_view text);

// A parse of a finite double (no leading '+' accepted by from_chars: handled here).
bool parse_double(std::string_view token, double& value);

void write_obj(const Mesh& mesh, OutputFile& out);
void write_off(const Mesh& mesh, OutputFile& out);
void write_ply(const Mesh& mesh, OutputFile& out);
void write_stl(const Mesh& mesh, OutputFile& out);
Mesh read_obj(std::string_view text, const std::filesystem::path& path);
Mesh read_off(std::string_view text, const std::filesystem::path& path);
Mesh read_ply(std::string_view bytes, const std::filesystem::path& path);
Mesh read_stl(std::string_view bytes, const std::filesystem::path& path);

}  // namespace genmod::mesh_io
