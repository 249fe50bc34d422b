// The file arguments of the commands: the one mesh file a command reads, and the check of an
// output path made before a command starts its work (so minutes of meshing are not lost to a
// typo in -o).
#pragma once

#include "arguments.hpp"

#include <string>

namespace genmod::app {

// The single positional argument, a mesh file with a mesh extension (UsageError otherwise).
const std::string& mesh_file_argument(const Arguments& a);

// Throws UsageError naming `output` when it cannot be written: an existing file that is a
// directory or not writable, or a new file whose directory does not exist or is not writable.
// (An existing device such as /dev/full passes: its write errors are caught when writing.)
void check_output_writable(const std::string& output);

}  // namespace genmod::app
