// genmod preview MESH -o out.png [--size N]: a shaded picture of any mesh file.
#include "arguments.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "option_values.hpp"

#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/preview.hpp"

#include <array>
#include <cstdio>
#include <optional>
#include <string>

namespace genmod::app {
namespace {

int run_preview(std::span<const std::string> args) {
  static constexpr std::array<const char*, 0> kFlags{};
  static constexpr std::array<const char*, 3> kValued{"--size", "-o", "--output"};
  const Arguments a(args, kFlags, kValued);
  const std::string& input = mesh_file_argument(a);
  const std::optional<std::string> output = a.value({"-o", "--output"});
  if (!output) throw UsageError("missing output file (-o FILE.png)");
  const int size = a.int_value({"--size"}, 512, 1, 8192);
  check_writable(*output);
  const Mesh mesh = read_mesh(input);
  if (mesh.triangles.empty()) throw MeshFileError("genmod: preview: '" + input + "' has no triangles");
  write_png(*output, preview(mesh, {.width = size, .height = size}));
  std::printf("%s: %zu vertices, %zu triangles -> %s (%d x %d)\n", input.c_str(), mesh.vertices.size(),
              mesh.triangles.size(), output->c_str(), size, size);
  return 0;
}

}  // namespace

const Command kPreviewCommand{
    "preview", "MESH -o FILE.png [--size N]",
    "a shaded picture of a mesh file (OBJ, PLY, STL, OFF) as a PNG; back faces dark",
    "  -o, --output  PNG file to write\n"
    "  --size N      image width and height in pixels, 1..8192 (default 512)\n"
    "the view is orthographic from (1, -1.5, 1.2), z up; faces seen from behind (inside-out\n"
    "parts, holes) are drawn dark\n",
    run_preview};

}  // namespace genmod::app
