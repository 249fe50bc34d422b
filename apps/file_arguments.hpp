// The mesh file a command reads (genmod check, genmod preview).
#pragma once

#include "arguments.hpp"

#include <string>

namespace genmod::app {

// The single positional argument, a mesh file with a mesh extension (UsageError otherwise).
const std::string& mesh_file_argument(const Arguments& a);

}  // namespace genmod::app
