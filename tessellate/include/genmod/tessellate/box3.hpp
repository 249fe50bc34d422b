// A box in 3-D: one interval per axis x, y, z.
#pragma once

#include "genmod/kernel/interval.hpp"

#include <array>

namespace genmod {

using Box3 = std::array<Interval, 3>;

}  // namespace genmod
