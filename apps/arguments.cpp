#include "arguments.hpp"

#include "commands.hpp"

#include <algorithm>
#include <charconv>

namespace genmod::app {
namespace {

bool listed(std::span<const char* const> names, const std::string& s) {
  return std::any_of(names.begin(), names.end(), [&](const char* n) { return s == n; });
}

}  // namespace

Arguments::Arguments(std::span<const std::string> args, std::span<const char* const> flags,
                     std::span<const char* const> valued) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a[0] != '-') {
      positional_.push_back(a);
    } else if (listed(flags, a)) {
      options_.emplace_back(a, "");
    } else if (listed(valued, a)) {
      if (i + 1 == args.size()) throw UsageError("option " + a + " needs a value");
      options_.emplace_back(a, args[++i]);
    } else {
      throw UsageError("unknown option '" + a + "'");
    }
  }
}

bool Arguments::has(std::string_view name) const {
  return std::any_of(options_.begin(), options_.end(), [&](const auto& o) { return o.first == name; });
}

std::optional<std::string> Arguments::value(std::initializer_list<std::string_view> names) const {
  std::optional<std::string> found;
  for (const auto& [name, v] : options_)
    if (std::find(names.begin(), names.end(), name) != names.end()) found = v;
  return found;
}

int Arguments::int_value(std::initializer_list<std::string_view> names, int fallback, int min, int max) const {
  const std::optional<std::string> text = value(names);
  if (!text) return fallback;
  int v = 0;
  const char* end = text->data() + text->size();
  const auto [ptr, ec] = std::from_chars(text->data(), end, v);
  if (ec != std::errc() || ptr != end || v < min || v > max)
    throw UsageError("option " + std::string(*names.begin()) + " must be an integer in [" + std::to_string(min) +
                     ", " + std::to_string(max) + "], got '" + *text + "'");
  return v;
}

}  // namespace genmod::app
