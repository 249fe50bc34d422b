// Numbers in model and curve files: one reader for every format, independent of the C++
// locale, that reads back every double genmod writes (subnormals included), and a quoting
// helper that keeps control bytes from the input out of error messages.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace genmod {

// The double spelled by the whole of `text` in C syntax (decimal or exponent form, an
// optional sign, "inf", "nan"), or nothing: for an empty or partly numeric word, and for a
// value out of double's range (1e309, or 1e-330 that would round to zero). Subnormal values
// are read exactly. Never depends on the global locale.
std::optional<double> parse_double(std::string_view text);

// The shortest text that parse_double reads back as exactly `value` (locale-independent).
std::string format_double(double value);

// `text` with bytes below 0x20, 0x7f and above (non-ASCII) written as \xHH, cut to `limit`
// bytes with "..." after: safe to put in an error message.
std::string printable(std::string_view text, std::size_t limit = 80);

}  // namespace genmod
