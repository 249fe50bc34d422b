// Typed parameter values of registered procedures (Morkel's int, double, boolean, String,
// vector). A value knows its type, so a call can be checked against the callee's declaration.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

namespace genmod {

enum class ParamType { Double, Integer, Boolean, String, Vector };

// The Java wrapper name of a type, used by the thesis's signature strings ("Double",
// "Integer", "Boolean", "String"). The thesis never shows the vector's; we write "Vector".
std::string_view java_type_name(ParamType type);

class ParamValue {
 public:
  // Explicit constructors per C++ type, so that an int literal is an Integer, not a bool or
  // double, and a string literal is a String, not a bool.
  ParamValue(double v) : value_(v) {}
  ParamValue(int v) : value_(std::int64_t{v}) {}
  ParamValue(std::int64_t v) : value_(v) {}
  ParamValue(bool v) : value_(v) {}
  ParamValue(const char* v) : value_(std::string(v)) {}
  ParamValue(std::string v) : value_(std::move(v)) {}
  ParamValue(const Vec3& v) : value_(v) {}

  ParamType type() const { return static_cast<ParamType>(value_.index()); }
  double as_double() const { return std::get<double>(value_); }
  std::int64_t as_integer() const { return std::get<std::int64_t>(value_); }
  bool as_bool() const { return std::get<bool>(value_); }
  const std::string& as_string() const { return std::get<std::string>(value_); }
  const Vec3& as_vector() const { return std::get<Vec3>(value_); }

  // Exact canonical bytes (type tag, then doubles as bit patterns, strings length-prefixed):
  // the cache key of §1.10 without Java's lossy toString.
  void append_key_bytes(std::string& out) const;

  bool operator==(const ParamValue& other) const { return value_ == other.value_; }

 private:
  // Order matches ParamType.
  std::variant<double, std::int64_t, bool, std::string, Vec3> value_;
};

}  // namespace genmod
