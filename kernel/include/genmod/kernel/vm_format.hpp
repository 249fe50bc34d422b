// The `.vm` text format: a scalar function as SSA lines `NAME OP ARGS...`; `#` starts a
// comment; the last definition is the output. Coordinates: var-x, var-y, var-z are x(0),
// x(1), x(2); `var-N` is x(N). Opcodes: those of the Fidget / Prospero models (const add sub
// mul div max min neg square sqrt abs sin cos exp ln) and the rest of genmod's scalar set
// under their op_name() (tan asin acos atan atan2 pow floor ceil lt le gt ge eq ne and or not
// is-error select).
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/line_reader.hpp"

#include <cstddef>
#include <iosfwd>
#include <stdexcept>
#include <string>

namespace genmod {

// A malformed file; what() names the source, the line and the problem.
class VmFormatError : public std::runtime_error {
 public:
  VmFormatError(const std::string& source, int line, const std::string& problem);
  int line() const noexcept { return line_; }

 private:
  int line_;
};

// How much a reader takes before it gives up with a VmFormatError (a model file is text of
// at most a few megabytes; /dev/zero or a wrong path must not fill the memory): at most
// max_bytes in all (default 1 GiB), max_line per line (default 1 MiB).
using VmReadLimits = TextReadLimits;

// Reads a model line by line (streaming); VmFormatError for malformed text, a limit passed,
// or a read error of the stream or file (which is never taken for the end of the file).
Fn read_vm(std::istream& in, const std::string& source_name = "<stream>", const VmReadLimits& limits = {});
Fn load_vm(const std::string& path, const VmReadLimits& limits = {});
// Writes a scalar function (std::invalid_argument for a vector). Custom operators cannot be
// written (std::invalid_argument names the operator).
void write_vm(std::ostream& out, const Fn& f);
void save_vm(const std::string& path, const Fn& f);

}  // namespace genmod
