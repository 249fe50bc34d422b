// Option values shared by the commands: numbers, boxes, and output paths checked before the
// work starts. Every problem is a UsageError naming the option.
#pragma once

#include "arguments.hpp"
#include "genmod/tessellate/box3.hpp"

#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace genmod::app {

// A finite number; `option` names it in the error.
double parse_number(const std::string& option, const std::string& text);

// A number option > 0 (or >= 0 when zero_allowed), `fallback` when absent.
double positive_option(const Arguments& a, std::initializer_list<std::string_view> names, double fallback,
                       bool zero_allowed);

// "x0,y0,z0,x1,y1,z1" with x0 < x1, y0 < y1, z0 < z1.
Box3 parse_box(const std::string& text);
// "a,b,c,...": every comma-separated field a number (errors name `option`).
std::vector<double> parse_numbers(const std::string& option, const std::string& text);

// The output must be writable: an existing file (not a directory) writable itself, a new one
// in an existing, writable directory; so that a long computation does not end in a failed
// write.
void check_writable(const std::string& output);

// Takes every `--param NAME=VALUE` (or `-p`) out of `args` and returns the values; the other
// arguments go to `rest`, in order. A parameter given twice is a UsageError, not "last wins".
std::map<std::string, double> take_param_options(std::span<const std::string> args, std::vector<std::string>& rest);

}  // namespace genmod::app
