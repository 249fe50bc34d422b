// genmod mesh NAME [--param K=V ...] [--seed S] [--lod L | --camera EYE,TARGET] -o FILE: a procedural model
// (Morkel's registered procedures, procedural_models.hpp) as the triangulation of the polygon mesh it builds.
// A camera chooses the level of detail from the size of the model's bounding box on screen (camera.hpp),
// and a model it does not see is an error rather than an empty file.
#include "arguments.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "option_values.hpp"

#include "genmod/models/procedural_models.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::app {
namespace {

// The text of `--param name=text` as the type the procedure declares for `name`; a name it
// does not declare is passed as a number so that the registry's refusal names it.
ParamValue parse_value(const ProcedureSpec& spec, const std::string& name, const std::string& text) {
  ParamType type = ParamType::Double;
  for (const ParamDecl& p : spec.params)
    if (p.name == name) type = p.type;
  const std::string what = "--param " + name;
  switch (type) {
    case ParamType::Integer: {
      char* end = nullptr;
      errno = 0;
      const long long v = std::strtoll(text.c_str(), &end, 10);
      if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE)
        throw UsageError(what + ": '" + text + "' is not an integer (" + spec.name + " declares it Integer)");
      return ParamValue(static_cast<std::int64_t>(v));
    }
    case ParamType::Boolean:
      if (text == "true" || text == "1") return ParamValue(true);
      if (text == "false" || text == "0") return ParamValue(false);
      throw UsageError(what + ": '" + text + "' is not true or false (" + spec.name + " declares it Boolean)");
    case ParamType::String:
      return ParamValue(text);
    default:
      return ParamValue(parse_number(what, text));
  }
}

// "ex,ey,ez,tx,ty,tz": a camera at the eye looking at the target, +z up (the frame of the
// written mesh), with camera.hpp's defaults for the rest (640 x 480 pixels, lod -8..0).
Camera parse_camera(const std::string& text) {
  const std::vector<double> v = parse_numbers("--camera", text);
  if (v.size() != 6)
    throw UsageError("--camera expects EX,EY,EZ,TX,TY,TZ (the eye and the point it looks at, 6 numbers), got '" +
                     text + "'");
  try {
    return models::camera_looking_at(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]));
  } catch (const std::invalid_argument& e) {
    throw UsageError("--" + std::string(e.what()) + " ('" + text + "')");  // "--camera: ..."
  }
}

}  // namespace

int run_mesh_procedural(std::span<const std::string> args) {
  std::vector<std::pair<std::string, std::string>> params;
  std::vector<std::string> rest;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--param" || args[i] == "-p") {
      if (i + 1 >= args.size()) throw UsageError("option " + args[i] + " needs a value");
      const std::string& text = args[++i];
      const std::size_t eq = text.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw UsageError("--param expects NAME=VALUE, got '" + text + "'");
      if (!seen.insert(text.substr(0, eq)).second)
        throw UsageError("--param " + text.substr(0, eq) + " is given more than once (set each parameter once)");
      params.emplace_back(text.substr(0, eq), text.substr(eq + 1));
    } else {
      rest.push_back(args[i]);
    }
  }
  static constexpr std::array<const char*, 1> kFlags{"--no-check"};
  static constexpr std::array<const char*, 5> kValued{"-o", "--output", "--seed", "--lod", "--camera"};
  const Arguments a(rest, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("expected one model name, got " + std::to_string(a.positional().size()));
  const std::string& name = a.positional()[0];
  const std::string output = mesh_output_argument(a);
  std::int64_t seed = 0;
  if (const auto text = a.value({"--seed"})) {
    char* end = nullptr;
    errno = 0;
    seed = std::strtoll(text->c_str(), &end, 10);
    if (text->empty() || end != text->c_str() + text->size() || errno == ERANGE)
      throw UsageError("--seed: '" + *text + "' is not an integer");
  }
  int lod = 0;
  if (const auto text = a.value({"--lod"})) {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text->c_str(), &end, 10);
    if (text->empty() || end != text->c_str() + text->size() || errno == ERANGE || v < -64 || v > 64)
      throw UsageError("--lod: '" + *text + "' is not an integer in -64..64");
    lod = static_cast<int>(v);
  }
  std::optional<Camera> camera;
  if (const auto text = a.value({"--camera"})) {
    if (a.value({"--lod"})) throw UsageError("--lod and --camera exclude each other: the camera chooses the lod");
    camera = parse_camera(*text);
  }
  check_writable(output);

  const ProcedureSpec& spec = models::procedural_registry().spec(name);
  NamedArgs named;
  for (const auto& [k, v] : params) named.emplace_back(k, parse_value(spec, k, v));
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  std::string lod_note = lod != 0 ? ", lod " + std::to_string(lod) : "";
  try {
    if (camera) {
      const std::optional<BoxView> view = models::procedural_model_view(name, named, *camera);
      if (!view)
        throw UsageError("--camera: '" + name + "' declares no bounding box, so a camera cannot place it (use --lod)");
      if (!view->visible)
        throw UsageError("--camera: '" + name + "' is out of the camera's view (its bounding box is outside the "
                         "frustum): nothing to mesh");
      lod_note = ", camera lod " + std::to_string(view->lod) + " (" + std::to_string(std::lround(view->pixels)) +
                 " pixels)";
      mesh = models::mesh_procedural_model(name, named, seed, *camera);
    } else {
      mesh = models::mesh_procedural_model(name, named, seed, lod);
    }
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());  // unknown parameter, wrong type, value out of range, bad camera
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_mesh(mesh, output);
  std::printf("%s (procedural, seed %lld%s): %zu vertices, %zu triangles in %.3f s -> %s\n", name.c_str(),
              static_cast<long long>(seed), lod_note.c_str(), mesh.vertices.size(), mesh.triangles.size(), seconds,
              output.c_str());
  if (a.has("--no-check")) return 0;
  // The file as written is what users get: check that, not the mesh in memory.
  const MeshValidity v = validate(read_mesh(output));
  std::printf("%s", describe(v).c_str());
  return v.valid() ? 0 : 1;
}

}  // namespace genmod::app
