// An independent C++ process for the Python tests: reads a .vm model (as written by
// genmod.save_vm), N points of (x, y, z) and a box as raw doubles, and writes the values at the
// points (scalar point evaluator), the interval enclosure over the box, and the three partial
// derivatives at the points (symbolic derivative, scalar evaluator), as raw doubles.
//
// Usage: genmod_vm_oracle MODEL.vm POINTS.bin BOX.bin OUT.bin
//   POINTS.bin: N x 3 doubles (row-major); BOX.bin: 3 x 2 doubles [lo, hi] per row;
//   OUT.bin: N values, lo and hi, then N x 3 partial derivatives (row-major).
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/vm_format.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace {

std::vector<double> read_doubles(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string("cannot open ") + path);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error(std::string(path) + " is not a whole number of doubles");
  std::vector<double> v(bytes.size() / sizeof(double));
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(v.data()));
  return v;
}

}  // namespace

int main(int argc, char** argv) try {
  using namespace genmod;
  if (argc != 5) throw std::runtime_error("usage: genmod_vm_oracle MODEL.vm POINTS.bin BOX.bin OUT.bin");
  const Fn f = load_vm(argv[1]);
  const std::vector<double> points = read_doubles(argv[2]), box_bounds = read_doubles(argv[3]);
  if (points.size() % 3 != 0 || box_bounds.size() != 6) throw std::runtime_error("points must be N x 3, the box 3 x 2");
  const std::vector<int> xyz = {0, 1, 2};
  const Tape value(f, xyz);
  const std::array<Tape, 3> partial = {Tape(derivative(f, 0), xyz), Tape(derivative(f, 1), xyz),
                                       Tape(derivative(f, 2), xyz)};
  PointEvaluator ev;
  std::vector<double> out;
  const std::size_t n = points.size() / 3;
  for (std::size_t i = 0; i < n; ++i) out.push_back(ev.eval(value, std::span(points).subspan(3 * i, 3))[0]);
  const std::vector<Interval> box = {Interval(box_bounds[0], box_bounds[1]), Interval(box_bounds[2], box_bounds[3]),
                                     Interval(box_bounds[4], box_bounds[5])};
  IntervalEvaluator iev;
  const Interval y = iev.eval(value, box)[0];
  out.push_back(y.lo());
  out.push_back(y.hi());
  for (std::size_t i = 0; i < n; ++i)
    for (const Tape& d : partial) out.push_back(ev.eval(d, std::span(points).subspan(3 * i, 3))[0]);
  std::ofstream o(argv[4], std::ios::binary);
  o.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size() * sizeof(double)));
  if (!o.flush()) throw std::runtime_error(std::string("cannot write ") + argv[4]);
  return 0;
} catch (const std::exception& e) {
  std::cerr << "genmod_vm_oracle: " << e.what() << "\n";
  return 1;
}
