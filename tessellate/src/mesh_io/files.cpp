// The checked output file, whole-file reading and the text reader of the mesh formats.
#include "mesh_io_internal.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

namespace genmod::mesh_io {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

std::string quoted(const std::filesystem::path& path) { return mesh_io::quoted(path.string()); }

}  // namespace

std::string quoted(std::string_view text) {
  std::string q(1, '\'');
  q += text;
  q += '\'';
  return q;
}

OutputFile::OutputFile(const std::filesystem::path& path) : path_(path) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw MeshFileError("genmod: write_mesh: cannot write " + quoted(path) + ": directory " + quoted(dir) +
                        " does not exist");
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr)
    throw MeshFileError("genmod: write_mesh: cannot create " + quoted(path) + ": " + std::strerror(errno));
  buffer_.reserve(kBufferBytes + 4096);
}

OutputFile::~OutputFile() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  std::error_code ec;
  if (std::filesystem::is_regular_file(path_, ec)) std::filesystem::remove(path_, ec);
}

void OutputFile::fail(const std::string& what) {
  const std::string reason = errno != 0 ? std::strerror(errno) : "unknown error";
  std::fclose(file_);
  file_ = nullptr;
  std::error_code ec;
  if (std::filesystem::is_regular_file(path_, ec)) std::filesystem::remove(path_, ec);
  throw MeshFileError("genmod: write_mesh: cannot write " + quoted(path_) + ": " + what + ": " + reason);
}

void OutputFile::flush_buffer() {
  if (buffer_.empty()) return;
  errno = 0;
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) fail("write failed");
  buffer_.clear();
}

void OutputFile::write(std::string_view bytes) {
  buffer_.append(bytes);
  if (buffer_.size() >= kBufferBytes) flush_buffer();
}

void OutputFile::write_double(double v) {
  char text[32];
  const auto r = std::to_chars(text, text + sizeof text, v);
  write(std::string_view(text, static_cast<std::size_t>(r.ptr - text)));
}

void OutputFile::write_uint(std::uint64_t v) {
  char text[24];
  const auto r = std::to_chars(text, text + sizeof text, v);
  write(std::string_view(text, static_cast<std::size_t>(r.ptr - text)));
}

void OutputFile::write_point(const std::array<double, 3>& p) {
  write_double(p[0]);
  write(" ");
  write_double(p[1]);
  write(" ");
  write_double(p[2]);
}

void OutputFile::write_indices(const std::array<std::uint32_t, 3>& t, std::uint64_t offset) {
  write_uint(t[0] + offset);
  write(" ");
  write_uint(t[1] + offset);
  write(" ");
  write_uint(t[2] + offset);
}

void OutputFile::finish() {
  flush_buffer();
  errno = 0;
  if (std::fflush(file_) != 0) fail("flush failed");
  std::FILE* f = file_;
  file_ = nullptr;
  errno = 0;
  if (std::fclose(f) != 0) {
    const std::string reason = std::strerror(errno);
    std::error_code ec;
    if (std::filesystem::is_regular_file(path_, ec)) std::filesystem::remove(path_, ec);
    throw MeshFileError("genmod: write_mesh: cannot write " + quoted(path_) + ": close failed: " + reason);
  }
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail_reading(path, "the file does not exist");
  if (std::filesystem::is_directory(path, ec)) fail_reading(path, "is a directory");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) fail_reading(path, std::string("cannot open: ") + std::strerror(errno));
  std::string bytes;
  char block[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(block, 1, sizeof block, f)) > 0) bytes.append(block, n);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) fail_reading(path, "read error");
  return bytes;
}

void fail_reading(const std::filesystem::path& path, const std::string& what) {
  throw MeshFileError("genmod: read_mesh: " + quoted(path) + ": " + what);
}

bool TextReader::next_line() {
  if (next_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', next_);
  if (end == std::string_view::npos) end = text_.size();
  line_ = text_.substr(next_, end - next_);
  if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
  next_ = end + 1;
  pos_ = 0;
  ++line_number_;
  return true;
}

std::string_view TextReader::token() {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; };
  while (pos_ < line_.size() && space(line_[pos_])) ++pos_;
  const std::size_t begin = pos_;
  while (pos_ < line_.size() && !space(line_[pos_])) ++pos_;
  return line_.substr(begin, pos_ - begin);
}

void TextReader::fail(const std::string& what) const {
  throw MeshFileError("genmod: read_mesh: " + quoted(path_) + " line " + std::to_string(line_number_) + ": " + what);
}

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto r = std::from_chars(token.data(), end, value);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(value);
}

double TextReader::to_double(std::string_view token, std::string_view what) const {
  double v = 0;
  if (!parse_double(token, v))
    fail(std::string(what) + " '" + std::string(token) + "' is not a finite number");
  return v;
}

long long TextReader::to_integer(std::string_view token, std::string_view what) const {
  long long v = 0;
  const char* end = token.data() + token.size();
  const auto r = std::from_chars(token.data(), end, v);
  if (token.empty() || r.ec != std::errc() || r.ptr != end)
    fail(std::string(what) + " '" + std::string(token) + "' is not an integer");
  return v;
}

std::uint64_t TextReader::to_count(std::string_view token, std::string_view what) const {
  const long long v = to_integer(token, what);
  if (v < 0) fail(std::string(what) + " " + std::string(token) + " is negative");
  return static_cast<std::uint64_t>(v);
}

double TextReader::next_double(std::string_view what) {
  const std::string_view t = token();
  if (t.empty()) fail("missing " + std::string(what));
  return to_double(t, what);
}

std::uint64_t TextReader::next_count(std::string_view what) {
  const std::string_view t = token();
  if (t.empty()) fail("missing " + std::string(what));
  return to_count(t, what);
}

void add_polygon(Mesh& mesh, const std::uint32_t* corners, std::size_t count) {
  for (std::size_t k = 1; k + 1 < count; ++k) mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
}

}  // namespace genmod::mesh_io
