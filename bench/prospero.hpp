// The benchmark model: data/prospero.vm (7,866 clauses of min, max and arithmetic), the
// "Prospero challenge" of rendering its sign over [-1,1]^2.
#pragma once

#include "genmod/kernel/tape.hpp"

namespace genmod::bench {

// Compiled once, on first use, and shared by all benchmarks.
const Tape& prospero_tape();

}  // namespace genmod::bench
