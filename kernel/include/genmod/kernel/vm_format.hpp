// The `.vm` text format: a scalar function as SSA lines `NAME OP ARGS...`; `#` starts a
// comment; the last definition is the output. Coordinates: var-x, var-y, var-z are x(0),
// x(1), x(2); `var-N` is x(N). Opcodes: those of the Fidget / Prospero models (const add sub
// mul div max min neg square sqrt abs sin cos exp ln) and the rest of genmod's scalar set
// under their op_name() (tan asin acos atan atan2 pow floor ceil lt le gt ge eq ne and or not
// is-error select).
#pragma once

#include "genmod/kernel/fn.hpp"

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

Fn read_vm(std::istream& in, const std::string& source_name = "<stream>");
Fn load_vm(const std::string& path);
// Writes a scalar function (std::invalid_argument for a vector). Custom operators cannot be
// written (std::invalid_argument names the operator).
void write_vm(std::ostream& out, const Fn& f);
void save_vm(const std::string& path, const Fn& f);

}  // namespace genmod
