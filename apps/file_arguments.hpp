// The mesh files a command reads (genmod check, genmod preview) and writes (genmod mesh).
#pragma once

#include "arguments.hpp"

#include <string>

namespace genmod::app {

// The single positional argument, a mesh file with a mesh extension (UsageError otherwise).
const std::string& mesh_file_argument(const Arguments& a);
// The value of -o / --output, a file with a mesh extension (UsageError when it is missing or
// has another extension).
std::string mesh_output_argument(const Arguments& a);

}  // namespace genmod::app
