// genmod mesh NAME [--tolerance W] [--no-check] -o FILE: a CSG model of trimmed surfaces
// (Algorithm 5.4, trimmed_csg.hpp), e.g. the drilled bumpy sphere.
#include "arguments.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "option_values.hpp"

#include "genmod/models/trimmed_csg.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace genmod::app {

int run_mesh_csg(std::span<const std::string> args) {
  static constexpr std::array<const char*, 1> kFlags{"--no-check"};
  static constexpr std::array<const char*, 3> kValued{"-o", "--output", "--tolerance"};
  const Arguments a(args, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("expected one model name, got " + std::to_string(a.positional().size()));
  const std::string& name = a.positional()[0];
  const std::string output = mesh_output_argument(a);
  models::TrimmedCsgOptions options;
  if (const auto text = a.value({"--tolerance"})) {
    options.tolerance = parse_number("--tolerance", *text);
    if (!(options.tolerance > 0)) throw UsageError("--tolerance must be > 0");
  }
  check_writable(output);
  const models::TrimmedCsgResult r = models::mesh_csg_model(name, options);
  write_mesh(r.mesh, output);
  std::printf("%s (CSG of trimmed surfaces): %zu vertices, %zu triangles (%zu + %zu), %zu seam vertices, in %.3f s -> %s\n",
              name.c_str(), r.mesh.vertices.size(), r.mesh.triangles.size(), r.triangles_first, r.triangles_second,
              r.seam.size(), r.seconds, output.c_str());
  if (a.has("--no-check")) return 0;
  const MeshValidity v = validate(read_mesh(output));
  std::printf("%s", describe(v).c_str());
  return v.valid() ? 0 : 1;
}

}  // namespace genmod::app
