// genmod check MESH: the validity report of a mesh file, as it is written (no welding).
#include "arguments.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"

#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <cstdio>
#include <string>

namespace genmod::app {
namespace {

int run_check(std::span<const std::string> args) {
  static constexpr std::array<const char*, 0> kFlags{};
  static constexpr std::array<const char*, 1> kValued{"--threads"};
  const Arguments a(args, kFlags, kValued);
  const std::string& input = mesh_file_argument(a);
  const int threads = a.int_value({"--threads"}, 0, 0, 1024);
  const Mesh mesh = read_mesh(input);
  const MeshValidity v = validate(mesh, {.threads = threads});
  std::printf("%s\n%s", input.c_str(), describe(v).c_str());
  return v.valid() ? 0 : 1;
}

}  // namespace

const Command kCheckCommand{
    "check", "MESH [--threads N]",
    "validate a mesh file: closed, manifold, oriented outward, no self-intersections (exit 1 if not)",
    "  --threads N  worker threads for the self-intersection test (default: all cores)\n"
    "the mesh is checked as written: vertices are not merged, so a mesh closed only after\n"
    "welding is reported open (STL files are welded by exact position when read)\n",
    run_check};

}  // namespace genmod::app
