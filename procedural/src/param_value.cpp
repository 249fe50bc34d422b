#include "genmod/procedural/param_value.hpp"

#include <bit>
#include <cstring>

namespace genmod {

std::string_view java_type_name(ParamType type) {
  switch (type) {
    case ParamType::Double: return "Double";
    case ParamType::Integer: return "Integer";
    case ParamType::Boolean: return "Boolean";
    case ParamType::String: return "String";
    case ParamType::Vector: return "Vector";
  }
  return "?";
}

namespace {
void append_u64(std::string& out, std::uint64_t v) {
  char bytes[8];
  std::memcpy(bytes, &v, 8);
  out.append(bytes, 8);
}
}  // namespace

void ParamValue::append_key_bytes(std::string& out) const {
  out.push_back(static_cast<char>(value_.index()));
  switch (type()) {
    case ParamType::Double: append_u64(out, std::bit_cast<std::uint64_t>(as_double())); break;
    case ParamType::Integer: append_u64(out, static_cast<std::uint64_t>(as_integer())); break;
    case ParamType::Boolean: out.push_back(as_bool() ? 1 : 0); break;
    case ParamType::String:
      append_u64(out, as_string().size());
      out += as_string();
      break;
    case ParamType::Vector:
      for (int a = 0; a < 3; ++a) append_u64(out, std::bit_cast<std::uint64_t>(as_vector()[a]));
      break;
  }
}

}  // namespace genmod
