// genmod render MODEL --3d: a shaded picture of a 3-D implicit model (a .vm file or an implicit
// gallery name) by render_shaded.
#include "arguments.hpp"
#include "commands.hpp"
#include "model_file.hpp"
#include "option_values.hpp"

#include "genmod/models/implicit_gallery.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/shaded_render.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace genmod::app {
namespace {

// The model turned so that the view direction becomes -z, and the render box: a cube around
// the model box's circumscribed ball (it holds the turned box), or the box itself from the top.
struct View {
  Fn f;
  Box3 box;
};

View turn(const Fn& f, const Box3& box, const std::string& name) {
  if (name == "top") return {f, box};
  // Rows of R: the screen's right, up and toward-the-viewer axes in model coordinates.
  std::array<std::array<double, 3>, 3> r{};
  if (name == "front") {
    r = {{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};
  } else if (name == "iso") {
    const double s2 = std::sqrt(2.0), s6 = std::sqrt(6.0), s3 = std::sqrt(3.0);
    r = {{{1 / s2, 1 / s2, 0}, {-1 / s6, 1 / s6, 2 / s6}, {1 / s3, -1 / s3, 1 / s3}}};
  } else {
    throw UsageError("--view must be top, front or iso, got '" + name + "'");
  }
  // A model point p shows at q = R (p - c); so f is evaluated at p = c + R^T q.
  std::array<double, 3> c{};
  double radius2 = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    c[k] = 0.5 * (box[k].lo() + box[k].hi());
    radius2 += std::pow(0.5 * (box[k].hi() - box[k].lo()), 2);
  }
  const double radius = std::sqrt(radius2);
  const Fn q[3] = {x(0), x(1), x(2)};
  Fn p[3];
  for (std::size_t k = 0; k < 3; ++k) p[k] = c[k] + r[0][k] * q[0] + r[1][k] * q[1] + r[2][k] * q[2];
  const std::array<int, 3> inputs{0, 1, 2};
  const Interval side(-radius, radius);
  return {compose_all(f, inputs, cat({p[0], p[1], p[2]})), Box3{side, side, side}};
}

}  // namespace

int run_render_shaded(std::span<const std::string> args) {
  static constexpr std::array<const char*, 2> kFlags{"--3d", "--brute-force"};
  static constexpr std::array<const char*, 7> kValued{"--size", "-o", "--output", "--threads",
                                                      "--box",  "--view", "--depth"};
  const Arguments a(args, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("render --3d takes one model, got " + std::to_string(a.positional().size()) + " arguments");
  const std::string& name = a.positional()[0];
  const models::ImplicitModel* model = models::find_implicit_model(name);
  ShadedOptions options;
  options.size = a.int_value({"--size"}, options.size, 1, kMaxShadedSize);
  options.depth = a.int_value({"--depth"}, 0, 0, kMaxShadedSize);
  options.threads = a.int_value({"--threads"}, 0, 0, 1024);
  const std::string output = a.value({"-o", "--output"}).value_or("out.png");
  check_writable(output);
  const std::optional<std::string> box_text = a.value({"--box"});
  const Box3 box = box_text ? parse_box(*box_text)
                 : model  ? model->box
                          : Box3{Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};
  const Fn f = load_implicit_model(name);
  const View view = turn(f, box, a.value({"--view"}).value_or(model ? "iso" : "top"));
  options.box = view.box;
  const Tape tape = [&] {
    try {
      return Tape(view.f);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }();
  const auto start = std::chrono::steady_clock::now();
  ShadedStats stats;
  ShadedImage shot;
  try {
    shot = a.has("--brute-force") ? render_shaded_brute_force(tape, options) : render_shaded(tape, options, &stats);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  write_png(output, shot.image);
  std::printf("rendered %s: %d x %d x %d voxels in %.2f ms -> %s\n", name.c_str(), options.size, options.size,
              shot.depth, ms, output.c_str());
  if (!a.has("--brute-force"))
    std::printf("tape %llu clauses; cubes %llu (inside %llu, outside %llu, ambiguous %llu), hidden %llu, voxels %llu\n",
                static_cast<unsigned long long>(stats.full_tape), static_cast<unsigned long long>(stats.cubes),
                static_cast<unsigned long long>(stats.inside), static_cast<unsigned long long>(stats.outside),
                static_cast<unsigned long long>(stats.ambiguous), static_cast<unsigned long long>(stats.hidden),
                static_cast<unsigned long long>(stats.voxels_evaluated));
  return 0;
}

}  // namespace genmod::app
