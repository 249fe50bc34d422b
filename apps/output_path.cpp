// check_output_writable (output_path.hpp).
#include "output_path.hpp"

#include "commands.hpp"

#include <unistd.h>

#include <filesystem>

namespace genmod::app {

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
