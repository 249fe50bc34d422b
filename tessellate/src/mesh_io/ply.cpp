// PLY: written as binary_little_endian with double coordinates; read in all three encodings
// with any scalar types. Elements other than vertex and face, and properties other than x, y, z
// and vertex_indices (or vertex_index), are read past and dropped.
#include "mesh_io_internal.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

namespace genmod::mesh_io {
namespace {

enum class Encoding { Ascii, LittleEndian, BigEndian };

struct ScalarType {
  int bytes = 0;
  bool is_float = false;
  bool is_signed = false;
};

std::optional<ScalarType> scalar_type(std::string_view name) {
  if (name == "char" || name == "int8") return ScalarType{1, false, true};
  if (name == "uchar" || name == "uint8") return ScalarType{1, false, false};
  if (name == "short" || name == "int16") return ScalarType{2, false, true};
  if (name == "ushort" || name == "uint16") return ScalarType{2, false, false};
  if (name == "int" || name == "int32") return ScalarType{4, false, true};
  if (name == "uint" || name == "uint32") return ScalarType{4, false, false};
  if (name == "float" || name == "float32") return ScalarType{4, true, true};
  if (name == "double" || name == "float64") return ScalarType{8, true, true};
  return std::nullopt;
}

struct Property {
  std::string name;
  ScalarType type;
  bool is_list = false;
  ScalarType count_type;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  std::size_t body = 0;  // offset of the first byte after end_header's line
};

Header read_header(std::string_view bytes, const std::filesystem::path& path) {
  const std::size_t end = bytes.find("end_header");
  if (bytes.substr(0, 3) != "ply") fail_reading(path, "not a PLY file (it does not start with 'ply')");
  if (end == std::string_view::npos) fail_reading(path, "no 'end_header' line");
  const std::size_t newline = bytes.find('\n', end);
  Header h;
  h.body = newline == std::string_view::npos ? bytes.size() : newline + 1;
  TextReader r(bytes.substr(0, h.body), path);
  r.next_line();  // "ply"
  bool have_format = false;
  while (r.next_line()) {
    const std::string_view key = r.token();
    if (key == "end_header") break;
    if (key == "comment" || key == "obj_info" || key.empty()) continue;
    if (key == "format") {
      const std::string_view enc = r.token();
      if (enc == "ascii") h.encoding = Encoding::Ascii;
      else if (enc == "binary_little_endian") h.encoding = Encoding::LittleEndian;
      else if (enc == "binary_big_endian") h.encoding = Encoding::BigEndian;
      else r.fail("unknown PLY format '" + std::string(enc) + "'");
      have_format = true;
    } else if (key == "element") {
      Element e;
      e.name = std::string(r.token());
      if (e.name.empty()) r.fail("element without a name");
      e.count = r.next_count("element count");
      h.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (h.elements.empty()) r.fail("property before any element");
      Property p;
      std::string_view type = r.token();
      if (type == "list") {
        p.is_list = true;
        const std::string_view count_type = r.token();
        const auto ct = scalar_type(count_type);
        if (!ct || ct->is_float) r.fail("bad list count type '" + std::string(count_type) + "'");
        p.count_type = *ct;
        type = r.token();
      }
      const auto t = scalar_type(type);
      if (!t) r.fail("unknown property type '" + std::string(type) + "'");
      p.type = *t;
      p.name = std::string(r.token());
      if (p.name.empty()) r.fail("property without a name");
      h.elements.back().properties.push_back(std::move(p));
    } else {
      r.fail("unknown header line '" + std::string(key) + "'");
    }
  }
  if (!have_format) fail_reading(path, "no 'format' line in the header");
  return h;
}

// The values of the body, one at a time, in either encoding.
class BodyReader {
 public:
  BodyReader(std::string_view bytes, const Header& h, const std::filesystem::path& path)
      : bytes_(bytes), encoding_(h.encoding), pos_(h.body), path_(path), text_(bytes.substr(h.body), path),
        header_lines_(static_cast<std::size_t>(std::count(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(h.body), '\n'))) {}

  void start_item(const Element& e, std::uint64_t index) {
    element_ = &e;
    index_ = index;
    if (encoding_ == Encoding::Ascii && !text_.next_line()) fail("the file ends before it");
  }

  double value(const ScalarType& t) {
    if (encoding_ == Encoding::Ascii) {
      const std::string_view token = text_.token();
      if (token.empty()) fail("too few values on its line");
      double v = 0;
      if (!parse_double(token, v)) fail(quoted(token) + " is not a finite number");
      return v;
    }
    if (pos_ + static_cast<std::size_t>(t.bytes) > bytes_.size()) fail("the file ends inside it");
    std::uint64_t raw = 0;
    for (int k = 0; k < t.bytes; ++k) {
      const int shift = encoding_ == Encoding::LittleEndian ? 8 * k : 8 * (t.bytes - 1 - k);
      raw |= std::uint64_t{static_cast<unsigned char>(bytes_[pos_ + static_cast<std::size_t>(k)])} << shift;
    }
    pos_ += static_cast<std::size_t>(t.bytes);
    double v = 0;
    if (t.is_float) v = t.bytes == 4 ? double(std::bit_cast<float>(static_cast<std::uint32_t>(raw))) : std::bit_cast<double>(raw);
    else if (t.is_signed) v = double(static_cast<std::int64_t>(raw << (64 - 8 * t.bytes)) >> (64 - 8 * t.bytes));
    else v = double(raw);
    if (!std::isfinite(v)) fail("a value that is not finite");
    return v;
  }

  void end_item() {
    if (encoding_ == Encoding::Ascii && !text_.token().empty()) fail("more values than its properties on its line");
  }

  void end_body() {
    if (encoding_ == Encoding::Ascii) {
      while (text_.next_line())
        if (!text_.token().empty()) text_.fail("data after the last element");
    } else if (pos_ != bytes_.size()) {
      fail_reading(path_, std::to_string(bytes_.size() - pos_) + " bytes after the last element");
    }
  }

  [[noreturn]] void fail(const std::string& what) {
    const std::string where = element_->name + " " + std::to_string(index_);
    if (encoding_ == Encoding::Ascii && text_.line_number() > 0)
      fail_reading(path_, "line " + std::to_string(header_lines_ + text_.line_number()) + " (" + where + "): " + what);
    fail_reading(path_, where + ": " + what);
  }

 private:
  std::string_view bytes_;
  Encoding encoding_;
  std::size_t pos_;
  const std::filesystem::path& path_;
  TextReader text_;
  std::size_t header_lines_;
  const Element* element_ = nullptr;
  std::uint64_t index_ = 0;
};

std::string number_text(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}

void put_double(std::string& out, double d) {
  const auto v = std::bit_cast<std::uint64_t>(d);
  for (int k = 0; k < 8; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}

}  // namespace

void write_ply(const Mesh& mesh, OutputFile& out) {
  out.write("ply\nformat binary_little_endian 1.0\ncomment genmod mesh\nelement vertex ");
  out.write_uint(mesh.vertices.size());
  out.write("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  out.write_uint(mesh.triangles.size());
  out.write("\nproperty list uchar uint vertex_indices\nend_header\n");
  std::string record;
  for (const auto& p : mesh.vertices) {
    record.clear();
    for (double c : p) put_double(record, c);
    out.write(record);
  }
  for (const auto& t : mesh.triangles) {
    record.assign(1, '\3');
    for (std::uint32_t i : t) put_u32(record, i);
    out.write(record);
  }
}

Mesh read_ply(std::string_view bytes, const std::filesystem::path& path) {
  const Header h = read_header(bytes, path);
  BodyReader body(bytes, h, path);
  Mesh mesh;
  bool have_vertices = false;
  std::vector<std::uint32_t> corners;
  std::vector<std::pair<std::uint64_t, std::vector<double>>> faces;  // checked once the vertices are known
  for (const Element& e : h.elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int axis_of[3] = {-1, -1, -1};
    int index_list = -1;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const Property& p = e.properties[k];
      if (is_vertex && !p.is_list && (p.name == "x" || p.name == "y" || p.name == "z")) axis_of[p.name[0] - 'x'] = int(k);
      if (is_face && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) index_list = int(k);
    }
    if (is_vertex) {
      for (int a = 0; a < 3; ++a)
        if (axis_of[a] < 0) fail_reading(path, std::string("the vertex element has no property ") + char('x' + a));
      if (e.count > 0xffffffffu) fail_reading(path, "more vertices than 32-bit indices can address");
      have_vertices = true;
      mesh.vertices.reserve(e.count);
    }
    if (is_face && index_list < 0) fail_reading(path, "the face element has no vertex_indices list");
    for (std::uint64_t i = 0; i < e.count; ++i) {
      body.start_item(e, i);
      std::array<double, 3> p{};
      std::vector<double> polygon;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& prop = e.properties[k];
        if (prop.is_list) {
          const double n = body.value(prop.count_type);
          if (n < 0) body.fail("a negative list length");
          for (double j = 0; j < n; ++j) {
            const double v = body.value(prop.type);
            if (int(k) == index_list) polygon.push_back(v);
          }
        } else {
          const double v = body.value(prop.type);
          for (int a = 0; a < 3; ++a)
            if (axis_of[a] == int(k)) p[static_cast<std::size_t>(a)] = v;
        }
      }
      body.end_item();
      if (is_vertex) mesh.vertices.push_back(p);
      if (is_face) {
        if (polygon.size() < 3) body.fail("a face needs at least 3 corners, got " + std::to_string(polygon.size()));
        faces.emplace_back(i, std::move(polygon));
      }
    }
  }
  body.end_body();
  if (!have_vertices) fail_reading(path, "no vertex element");
  for (const auto& [index, polygon] : faces) {
    corners.clear();
    for (double v : polygon) {
      if (!(v >= 0) || v != std::floor(v) || v >= double(mesh.vertices.size()))
        fail_reading(path, "face " + std::to_string(index) + ": vertex index " + number_text(v) +
                               " is not one of the " + std::to_string(mesh.vertices.size()) + " vertices");
      corners.push_back(static_cast<std::uint32_t>(v));
    }
    add_polygon(mesh, corners.data(), corners.size());
  }
  return mesh;
}

}  // namespace genmod::mesh_io
