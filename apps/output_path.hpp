// Checks of an output path made before a command starts its work, so that minutes of meshing
// are not lost to a typo in -o.
#pragma once

#include <string>

namespace genmod::app {

// Throws UsageError naming `output` when it cannot be written: an existing file that is a
// directory or not writable, or a new file whose directory does not exist or is not writable.
// (An existing device such as /dev/full passes: its write errors are caught when writing.)
void check_output_writable(const std::string& output);

}  // namespace genmod::app
