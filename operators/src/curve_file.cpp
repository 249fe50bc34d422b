#include "genmod/operators/curve_file.hpp"

#include "genmod/kernel/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

namespace genmod {

CurveFileError::CurveFileError(const std::string& source, int line, const std::string& what)
    : std::invalid_argument("genmod: curve file " + source + ":" + std::to_string(line) + ": " + what), line_(line) {}

namespace {

// "prefix" + word, built by appending (GCC 12 warns falsely about const char* + string&&).
std::string text(const char* prefix, std::string_view word) {
  std::string s(prefix);
  s.append(printable(word));
  return s;
}

// Takes the file one line at a time (so a file is read as a stream, never held whole), then
// builds the curve.
class Parser {
 public:
  explicit Parser(std::string source) : source_(std::move(source)) {}

  void line(int line_no, std::string_view line) {
    last_line_ = line_no;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::vector<std::string_view> words = split(line);
    if (words.empty()) return;
    const std::string keyword(words[0]);
    words.erase(words.begin());
    if (!seen_header_) {
      if (keyword != "crv") fail(line_no, "expected the header `crv 1`, got `" + printable(keyword) + "`");
      if (count(line_no, words, 1, "crv") && integer(line_no, words[0]) != 1)
        fail(line_no, text("unsupported format version ", words[0]) + " (this reader knows 1)");
      seen_header_ = true;
      return;
    }
    statement(line_no, keyword, words);
  }

  Curve finish() {
    if (!seen_header_) fail(last_line_, "empty curve file (expected the header `crv 1`)");
    return build();
  }

  private:
  [[noreturn]] void fail(int line, const std::string& what) const { throw CurveFileError(source_, line, what); }

  static std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      const std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
  }

  bool count(int line, const std::vector<std::string_view>& words, std::size_t n, const char* keyword) const {
    if (words.size() != n)
      fail(line, std::string(keyword) + " takes " + std::to_string(n) + " value" + (n == 1 ? "" : "s") + ", got " +
                     std::to_string(words.size()));
    return true;
  }

  double number(int line, std::string_view word) const {
    const std::optional<double> v = parse_double(word);
    if (!v || !std::isfinite(*v)) fail(line, text("`", word) + "` is not a finite number");
    return *v;
  }

  int integer(int line, std::string_view word) const {
    int v = 0;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (ec != std::errc() || ptr != word.data() + word.size()) fail(line, text("`", word) + "` is not an integer");
    return v;
  }

  void statement(int line, const std::string& keyword, const std::vector<std::string_view>& words) {
    if (keyword == "type") {
      count(line, words, 1, "type");
      static const char* kinds[] = {"polyline", "bezier", "bspline", "nurbs", "hermite", "catmull-rom"};
      type_ = std::string(words[0]);
      if (std::find(std::begin(kinds), std::end(kinds), type_) == std::end(kinds))
        fail(line, "unknown curve type `" + printable(type_) + "` (polyline, bezier, bspline, nurbs, hermite, catmull-rom)");
      type_line_ = line;
    } else if (keyword == "dimension") {
      count(line, words, 1, "dimension");
      dim_ = integer(line, words[0]);
      if (dim_ < 1 || dim_ > 16) fail(line, "dimension " + std::to_string(dim_) + " is outside 1..16");
    } else if (keyword == "degree") {
      count(line, words, 1, "degree");
      degree_ = integer(line, words[0]);
      if (degree_ < 1 || degree_ > 12) fail(line, "degree " + std::to_string(degree_) + " is outside 1..12");
      degree_line_ = line;
    } else if (keyword == "clamped") {
      count(line, words, 1, "clamped");
      if (words[0] != "yes" && words[0] != "no") fail(line, "clamped takes yes or no");
      clamped_ = words[0] == "yes";
    } else if (keyword == "knots") {
      if (words.empty()) fail(line, "knots needs at least one value");
      for (std::string_view w : words) {
        const double u = number(line, w);
        if (!knots_.empty() && u < knots_.back())
          fail(line, text("the knot vector is not nondecreasing (", w) + " after " + std::to_string(knots_.back()) + ")");
        knots_.push_back(u);
      }
      knots_line_ = line;
    } else if (keyword == "point" || keyword == "tangent") {
      if (type_.empty() || dim_ == 0) fail(line, keyword + " before `type` and `dimension`");
      const bool weighted = keyword == "point" && type_ == "nurbs";
      const std::size_t expected = static_cast<std::size_t>(dim_) + (weighted ? 1 : 0);
      if (words.size() != expected)
        fail(line, keyword + " has " + std::to_string(words.size()) + " numbers, expected " + std::to_string(expected) +
                       (weighted ? " (coordinates, then the weight)" : ""));
      std::vector<double> p;
      for (std::size_t i = 0; i < static_cast<std::size_t>(dim_); ++i) p.push_back(number(line, words[i]));
      if (keyword == "tangent") {
        if (type_ != "hermite") fail(line, "tangent is only for hermite curves");
        tangents_.push_back(std::move(p));
        return;
      }
      if (weighted) {
        const double w = number(line, words.back());
        if (!(w > 0.0)) fail(line, text("weight ", words.back()) + " is not positive");
        weights_.push_back(w);
      }
      points_.push_back(std::move(p));
    } else if (keyword == "crv") {
      fail(line, "a second `crv` header");
    } else {
      fail(line, "unknown keyword `" + printable(keyword) + "`");
    }
  }

  Curve build() {
    if (type_.empty()) fail(last_line_, "no `type` statement");
    if (dim_ == 0) fail(last_line_, "no `dimension` statement");
    const bool spline = type_ == "bspline" || type_ == "nurbs";
    if (spline && degree_ == 0) fail(type_line_, type_ + " needs a `degree` statement");
    if (!spline && degree_ != 0) fail(degree_line_, "degree is only for bspline and nurbs curves");
    if (!spline && !knots_.empty()) fail(knots_line_, "knots are only for bspline and nurbs curves");
    const std::size_t min_points = spline ? static_cast<std::size_t>(degree_) + 1 : 2;
    if (points_.size() < min_points)
      fail(last_line_, type_ + (spline ? " of degree " + std::to_string(degree_) : std::string()) + " needs at least " +
                           std::to_string(min_points) + " points, got " + std::to_string(points_.size()));
    if (type_ == "hermite" && tangents_.size() != points_.size())
      fail(last_line_, std::to_string(points_.size()) + " points need as many tangents, got " +
                           std::to_string(tangents_.size()));
    if (!knots_.empty() && knots_.size() != points_.size() + static_cast<std::size_t>(degree_) + 1)
      fail(knots_line_, std::to_string(points_.size()) + " points of degree " + std::to_string(degree_) + " need " +
                            std::to_string(points_.size() + static_cast<std::size_t>(degree_) + 1) + " knots, got " +
                            std::to_string(knots_.size()));
    if (type_ == "nurbs" && !clamped_) fail(type_line_, "nurbs supports only clamped uniform default knots");
    try {
      if (type_ == "polyline") return Curve::polyline(points_);
      if (type_ == "bezier") return Curve::bezier(points_);
      if (type_ == "hermite") return Curve::hermite(points_, tangents_);
      if (type_ == "catmull-rom") return Curve::catmull_rom(points_);
      if (type_ == "nurbs") return Curve::nurbs(points_, weights_, degree_, knots_);
      if (knots_.empty()) return Curve::uniform_bspline(points_, degree_, clamped_);
      return Curve::bspline(points_, degree_, knots_);
    } catch (const std::invalid_argument& e) {
      fail(knots_.empty() ? last_line_ : knots_line_, e.what());
    }
  }

  std::string source_;
  bool seen_header_ = false;
  int last_line_ = 0, type_line_ = 0, degree_line_ = 0, knots_line_ = 0;
  std::string type_;
  int dim_ = 0, degree_ = 0;
  bool clamped_ = true;
  std::vector<double> knots_, weights_;
  Curve::Points points_, tangents_;
};

}  // namespace

Curve parse_curve(std::string_view text, const std::string& source) {
  Parser parser(source);
  int line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    parser.line(++line_no, text.substr(pos, end - pos));
    pos = end + 1;
  }
  return parser.finish();
}

namespace {

Curve read_lines(LineReader& reader, const std::string& source) {
  Parser parser(source);
  std::string line;
  for (;;) {
    try {
      if (!reader.next(line)) break;
    } catch (const TextReadError& e) {
      throw CurveFileError(source, e.line(), e.what());
    }
    parser.line(reader.line_number(), line);
  }
  return parser.finish();
}

}  // namespace

Curve read_curve(std::istream& in, const std::string& source, const CurveReadLimits& limits) {
  LineReader reader(in, limits);
  return read_lines(reader, source);
}

Curve load_curve(const std::string& path, const CurveReadLimits& limits) {
  // stdio tells a read error (a directory) from the end of the file; a file stream does not.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw CurveFileError(path, 0, std::string("cannot open the file: ") + std::strerror(errno));
  LineReader reader(file.get(), limits);
  return read_lines(reader, path);
}

Fn crv(const std::string& path, const Fn& in) { return load_curve(path)(in); }

}  // namespace genmod
