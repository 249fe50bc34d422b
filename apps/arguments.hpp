// A small command-line scanner: positional arguments and `--name value` options.
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace genmod::app {

class Arguments {
 public:
  // `flags` are options without a value, `valued` options take the next argument. Both list
  // every spelling (e.g. "-o", "--output"). Throws UsageError for an unknown option or a
  // missing value.
  Arguments(std::span<const std::string> args, std::span<const char* const> flags,
            std::span<const char* const> valued);

  const std::vector<std::string>& positional() const noexcept { return positional_; }
  bool has(std::string_view name) const;
  // The value of the last occurrence of an option (any of its spellings), if given.
  std::optional<std::string> value(std::initializer_list<std::string_view> names) const;
  // An integer option in [min, max]; UsageError names the option and the bad value.
  int int_value(std::initializer_list<std::string_view> names, int fallback, int min, int max) const;

 private:
  std::vector<std::string> positional_;
  std::vector<std::pair<std::string, std::string>> options_;  // (name, value), in order
};

}  // namespace genmod::app
