// genmod render MODEL.vm: the sign of a 2-D implicit model over [-1,1]^2 as a PNG.
#include "arguments.hpp"
#include "commands.hpp"
#include "model_file.hpp"

#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/raster2d.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <vector>

namespace genmod::app {
namespace {

void print_stats(const RasterStats& s) {
  std::printf("tape: %llu clauses\n", static_cast<unsigned long long>(s.full_tape));
  std::printf("%6s %9s %9s %9s %9s %11s %9s\n", "tile", "tiles", "inside", "outside", "ambiguous", "mean tape",
              "min tape");
  for (const RasterLevelStats& l : s.levels)
    std::printf("%6d %9llu %9llu %9llu %9llu %11.1f %9llu\n", l.tile_size, static_cast<unsigned long long>(l.tiles),
                static_cast<unsigned long long>(l.inside), static_cast<unsigned long long>(l.outside),
                static_cast<unsigned long long>(l.ambiguous), l.mean_tape(),
                static_cast<unsigned long long>(l.min_tape));
  std::printf("pixels evaluated: %llu in %llu tiles, pruned tape mean %.1f, min %llu clauses\n",
              static_cast<unsigned long long>(s.pixels_evaluated), static_cast<unsigned long long>(s.pixel_tiles),
              s.mean_pixel_tape(), static_cast<unsigned long long>(s.min_pixel_tape));
}

// "64,8" -> {64, 8}.
std::vector<int> parse_tile_sizes(const std::string& text) {
  std::vector<int> sizes;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    int v = 0;
    const auto [ptr, ec] = std::from_chars(text.data() + begin, text.data() + end, v);
    if (ec != std::errc() || ptr != text.data() + end || v < 1 || (!sizes.empty() && v >= sizes.back()))
      throw UsageError("option --tiles must be a comma-separated list of decreasing positive tile widths, got '" +
                       text + "'");
    sizes.push_back(v);
    begin = end + 1;
  }
  if (sizes.size() > kMaxTileLevels)
    throw UsageError("option --tiles takes at most " + std::to_string(kMaxTileLevels) + " tile widths, got " +
                     std::to_string(sizes.size()));
  return sizes;
}

int run_render(std::span<const std::string> args) {
  for (const std::string& arg : args)
    if (arg == "--3d") return run_render_shaded(args);
  static constexpr std::array<const char*, 2> kFlags{"--stats", "--brute-force"};
  static constexpr std::array<const char*, 6> kValued{"--size", "-o", "--output", "--threads", "--repeat", "--tiles"};
  const Arguments a(args, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("render takes one model file, got " + std::to_string(a.positional().size()) + " arguments");
  RasterOptions options;
  options.size = a.int_value({"--size"}, options.size, 1, kMaxRasterSize);
  options.threads = a.int_value({"--threads"}, 0, 0, 1024);
  if (const auto tiles = a.value({"--tiles"})) options.tile_sizes = parse_tile_sizes(*tiles);
  const int repeat = a.int_value({"--repeat"}, 1, 1, 10000);
  const std::string output = a.value({"-o", "--output"}).value_or("out.png");

  const Tape tape = load_planar_model(a.positional()[0]);
  const bool brute_force = a.has("--brute-force");
  RasterStats stats;
  Image image;
  std::vector<double> ms;
  for (int i = 0; i < repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    image = brute_force ? render_sign_brute_force(tape, options) : render_sign(tape, options, &stats);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  write_png(output, image);
  std::sort(ms.begin(), ms.end());
  std::printf("rendered %s: %d x %d in %.2f ms", a.positional()[0].c_str(), options.size, options.size,
              ms[ms.size() / 2]);
  if (repeat > 1) std::printf(" (median of %d runs, min %.2f ms)", repeat, ms.front());
  std::printf(" -> %s\n", output.c_str());
  if (a.has("--stats") && !brute_force) print_stats(stats);
  return 0;
}

}  // namespace

const Command kRenderCommand{
    "render", "MODEL.vm [--size N] [-o out.png] [--threads T] [--tiles A,B,..] [--repeat R] [--stats] [--brute-force]\n"
    "       genmod render MODEL.vm|IMPLICIT_NAME --3d [--size N] [--box x0,y0,z0,x1,y1,z1] [--view top|front|iso]\n"
    "                     [--depth D] [-o out.png] [--threads T] [--brute-force]",
    "render the sign of a 2-D implicit model over [-1,1]^2 to a PNG (white where f < 0), or a shaded 3-D picture",
    "  --size N       image width and height in pixels (default 1024)\n"
    "  -o, --output   PNG file to write (default out.png)\n"
    "  --threads T    worker threads, 0 = all cores (default 0)\n"
    "  --tiles A,B,.. tile widths of the subdivision levels below the image, decreasing (default 2048,1024,...,32,16: halving)\n"
    "  --repeat R     render R times and report the median time (default 1)\n"
    "  --stats        print the tile subdivision statistics\n"
    "  --brute-force  evaluate every pixel without intervals (the reference, for comparison)\n"
    "With --3d (a 3-D model: a .vm file in x, y, z or an implicit gallery name):\n"
    "  --size N       image width and height (default 512)\n"
    "  --box B        the region x0,y0,z0,x1,y1,z1 (default: the gallery model's box, else [-1,1]^3)\n"
    "  --view V       top (looking down z; the default for files), front (looking along +y) or iso\n"
    "                 (the default for gallery models); front and iso render a cube around the box's ball\n"
    "  --depth D      voxels along the view (default: cubic voxels)\n"
    "  --brute-force  march every pixel's ray without intervals (the reference)\n",
    run_render};

}  // namespace genmod::app
