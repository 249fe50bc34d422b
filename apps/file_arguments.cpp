// mesh_file_argument and mesh_output_argument (file_arguments.hpp).
#include "file_arguments.hpp"

#include "commands.hpp"

#include "genmod/tessellate/mesh_io.hpp"

#include <optional>

namespace genmod::app {

const std::string& mesh_file_argument(const Arguments& a) {
  if (a.positional().size() != 1)
    throw UsageError(a.positional().empty() ? "missing mesh file"
                                            : "expected one mesh file, got " + std::to_string(a.positional().size()));
  const std::string& input = a.positional()[0];
  if (!mesh_format(input)) throw UsageError("input '" + input + "': unknown mesh extension (use .obj, .ply, .stl or .off)");
  return input;
}

std::string mesh_output_argument(const Arguments& a) {
  const std::optional<std::string> output = a.value({"-o", "--output"});
  if (!output) throw UsageError("missing output file (-o FILE)");
  if (!mesh_format(*output))
    throw UsageError("output '" + *output + "': unknown mesh extension (use .obj, .ply, .stl or .off)");
  return *output;
}

}  // namespace genmod::app
