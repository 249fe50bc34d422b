// Option values shared by the commands (see option_values.hpp).
#include "option_values.hpp"

#include "commands.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

namespace genmod::app {

double parse_number(const std::string& option, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    throw UsageError(option + ": '" + text + "' is not a finite number");
  return v;
}

double positive_option(const Arguments& a, std::initializer_list<std::string_view> names, double fallback,
                       bool zero_allowed) {
  const std::optional<std::string> text = a.value(names);
  if (!text) return fallback;
  const std::string name(*names.begin());
  const double v = parse_number(name, *text);
  if (v < 0 || (v == 0 && !zero_allowed))
    throw UsageError(name + " must be " + (zero_allowed ? ">= 0" : "> 0") + ", got " + *text);
  return v;
}

std::vector<double> parse_numbers(const std::string& option, const std::string& text) {
  std::vector<double> v;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    v.push_back(parse_number(option, text.substr(begin, end - begin)));
    begin = end + 1;
  }
  return v;
}

// "x0,y0,z0,x1,y1,z1".
Box3 parse_box(const std::string& text) {
  const std::vector<double> v = parse_numbers("--box", text);
  if (v.size() != 6) throw UsageError("--box expects x0,y0,z0,x1,y1,z1 (6 numbers), got '" + text + "'");
  Box3 box;
  for (int k = 0; k < 3; ++k) {
    if (!(v[static_cast<std::size_t>(k)] < v[static_cast<std::size_t>(k + 3)]))
      throw UsageError("--box: the low corner must be below the high corner on every axis, got '" + text + "'");
    box[static_cast<std::size_t>(k)] = Interval(v[static_cast<std::size_t>(k)], v[static_cast<std::size_t>(k + 3)]);
  }
  return box;
}

// The output's directory must exist and be writable before minutes of meshing start. An
// existing file needs only to be writable itself: a device such as /dev/full passes here (its
// write errors are caught by the writers) even where its directory is not writable.
void check_writable(const std::string& output) {
  std::error_code ec;
  if (std::filesystem::exists(output, ec)) {
    if (std::filesystem::is_directory(output, ec)) throw UsageError("output '" + output + "' is a directory");
    if (::access(output.c_str(), W_OK) != 0) throw UsageError("output '" + output + "': file is not writable");
    return;
  }
  const std::filesystem::path dir = std::filesystem::absolute(output).parent_path();
  if (!std::filesystem::is_directory(dir)) throw UsageError("output '" + output + "': no such directory " + dir.string());
  if (::access(dir.c_str(), W_OK) != 0) throw UsageError("output '" + output + "': directory is not writable");
}

namespace {

// One `--param k=v`: the name and the value (UsageError naming the bad argument otherwise).
std::pair<std::string, double> parse_param(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw UsageError("--param expects NAME=VALUE, got '" + text + "'");
  const std::string value_text = text.substr(eq + 1);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(value_text.c_str(), &end);
  if (end != value_text.c_str() + value_text.size() || errno == ERANGE || !std::isfinite(value))
    throw UsageError("--param " + text.substr(0, eq) + ": '" + value_text + "' is not a finite number");
  return {text.substr(0, eq), value};
}

}  // namespace

std::map<std::string, double> take_param_options(std::span<const std::string> args, std::vector<std::string>& rest) {
  std::map<std::string, double> overrides;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--param" || args[i] == "-p") {
      if (i + 1 >= args.size()) throw UsageError("option " + args[i] + " needs a value");
      const auto [name, value] = parse_param(args[++i]);
      if (!overrides.emplace(name, value).second)
        throw UsageError("--param " + name + " is given more than once (set each parameter once)");
    } else {
      rest.push_back(args[i]);
    }
  }
  return overrides;
}

}  // namespace genmod::app
