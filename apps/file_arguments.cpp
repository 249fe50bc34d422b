// mesh_file_argument and check_output_writable (file_arguments.hpp).
#include "file_arguments.hpp"

#include "commands.hpp"

#include "genmod/tessellate/mesh_io.hpp"

#include <unistd.h>

#include <filesystem>

namespace genmod::app {

const std::string& mesh_file_argument(const Arguments& a) {
  if (a.positional().size() != 1)
    throw UsageError(a.positional().empty() ? "missing mesh file"
                                            : "expected one mesh file, got " + std::to_string(a.positional().size()));
  const std::string& input = a.positional()[0];
  if (!mesh_format(input)) throw UsageError("input '" + input + "': unknown mesh extension (use .obj, .ply, .stl or .off)");
  return input;
}

void check_output_writable(const std::string& output) {
  std::error_code ec;
  if (std::filesystem::exists(output, ec)) {
    if (std::filesystem::is_directory(output, ec)) throw UsageError("output '" + output + "' is a directory");
    if (::access(output.c_str(), W_OK) != 0) throw UsageError("output '" + output + "': file is not writable");
    return;
  }
  const std::filesystem::path dir = std::filesystem::absolute(output).parent_path();
  if (!std::filesystem::is_directory(dir, ec))
    throw UsageError("output '" + output + "': no such directory " + dir.string());
  if (::access(dir.c_str(), W_OK) != 0) throw UsageError("output '" + output + "': directory is not writable");
}

}  // namespace genmod::app
