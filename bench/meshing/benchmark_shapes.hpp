// The peers' benchmark shapes that the meshing and 3-D rendering benchmarks share:
// libfive's sphere-gyroid over [-5,5]^3 and the tanglecube over [-2.5,2.5]^3.
#pragma once

#include "genmod/kernel/vm_format.hpp"
#include "genmod/tessellate/box3.hpp"

#include <string>

namespace genmod::bench {

struct BenchmarkShape {
  const char* name;
  const char* file;  // in data/
  double half;       // the box is [-half, half]^3

  Fn load() const { return load_vm(std::string(GENMOD_DATA_DIR) + "/" + file); }
  Box3 box() const { return {Interval(-half, half), Interval(-half, half), Interval(-half, half)}; }
};

inline constexpr BenchmarkShape kBenchmarkShapes[] = {{"sphere_gyroid", "sphere_gyroid.vm", 5.0},
                                                      {"tanglecube", "tanglecube.vm", 2.5}};

}  // namespace genmod::bench
