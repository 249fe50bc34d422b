// genmod check MESH: the validity report of a mesh file, as it is written (no welding).
#include "arguments.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "model_file.hpp"

#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace genmod::app {
namespace {

// The implicit surface a mesh is measured against: a gallery name or a .vm file in x, y, z.
Tape surface_tape(const std::string& name) { return Tape(load_implicit_model(name), std::vector<int>{0, 1, 2}); }

int run_check(std::span<const std::string> args) {
  static constexpr std::array<const char*, 0> kFlags{};
  static constexpr std::array<const char*, 3> kValued{"--threads", "--surface", "--face-samples"};
  const Arguments a(args, kFlags, kValued);
  const std::string& input = mesh_file_argument(a);
  const int threads = a.int_value({"--threads"}, 0, 0, 1024);
  const int face_samples = a.int_value({"--face-samples"}, 1, 0, 64);
  const std::optional<std::string> surface_name = a.value({"--surface"});
  const std::optional<Tape> surface = surface_name ? std::optional<Tape>(surface_tape(*surface_name)) : std::nullopt;
  const Mesh mesh = read_mesh(input);
  const MeshValidity v =
      validate(mesh, {.surface = surface ? &*surface : nullptr, .face_samples = face_samples, .threads = threads});
  std::printf("%s\n%s", input.c_str(), describe(v).c_str());
  return v.valid() ? 0 : 1;
}

}  // namespace

const Command kCheckCommand{
    "check", "MESH [--surface MODEL] [--face-samples N] [--threads N]",
    "validate a mesh file: closed, manifold, oriented outward, no self-intersections (exit 1 if not)",
    "  --threads N         worker threads (default: all cores)\n"
    "  --surface MODEL     also measure the distance to the surface f = 0 of MODEL (a .vm file in\n"
    "                      x, y, z or an implicit gallery name): certified per vertex, estimated on faces\n"
    "  --face-samples N    sample points per triangle for the face estimate (default 1)\n"
    "the mesh is checked as written: vertices are not merged, so a mesh closed only after\n"
    "welding is reported open (STL files are welded by exact position when read)\n",
    run_check};

}  // namespace genmod::app
