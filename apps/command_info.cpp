// genmod info MODEL.vm: what a model compiles to and what intervals say about it.
#include "arguments.hpp"
#include "commands.hpp"
#include "model_file.hpp"

#include "genmod/kernel/expression.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace genmod::app {
namespace {

// Upper bound on the sub-boxes of the pruning report (k parts per input, k^n of them).
constexpr std::size_t kMaxSubBoxes = 256;

// Lines of the file that define something (not blank, not only a comment).
std::size_t count_definitions(const std::string& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) {
    line.resize(std::min(line.size(), line.find('#')));
    if (line.find_first_not_of(" \t\r") != std::string::npos) ++n;
  }
  return n;
}

std::string describe(const Interval& v, std::uint8_t err) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  if (err == kCertainError) os << " (certain error)";
  else if (err != kNoError) os << " (error possible)";
  return os.str();
}

// Parts per input such that parts^n <= kMaxSubBoxes; 1 if even 2^n is too many.
std::size_t parts_per_input(std::size_t n) {
  std::size_t k = 1;
  auto boxes = [n](std::size_t parts) {
    std::size_t total = 1;
    for (std::size_t i = 0; i < n && total <= kMaxSubBoxes; ++i) total *= parts;
    return total;
  };
  while (boxes(k + 1) <= kMaxSubBoxes) ++k;
  return k;
}

// Tape lengths after pruning over each sub-box of [-1,1]^n split into k parts per input.
void report_pruning(const Tape& tape) {
  const std::size_t n = tape.num_inputs();
  const std::size_t k = n == 0 ? 1 : parts_per_input(n);
  if (k < 2) {
    std::printf("one pruning level: skipped (%zu inputs are too many to split)\n", n);
    return;
  }
  IntervalEvaluator ev;
  std::vector<std::size_t> index(n, 0);
  std::vector<Interval> box(n);
  std::size_t boxes = 0, total = 0, shortest = std::numeric_limits<std::size_t>::max();
  const double step = 2.0 / static_cast<double>(k);  // k is small: the splits are exact
  for (bool more = true; more;) {
    for (std::size_t i = 0; i < n; ++i)
      box[i] = Interval(-1.0 + step * static_cast<double>(index[i]), -1.0 + step * static_cast<double>(index[i] + 1));
    ev.eval(tape, box);
    const std::size_t length = tape.simplify(ev.choices()).size();
    ++boxes;
    total += length;
    shortest = std::min(shortest, length);
    more = false;  // next multi-index, odometer style
    for (std::size_t i = 0; i < n && !more; ++i) {
      if (++index[i] < k) more = true;
      else index[i] = 0;
    }
  }
  std::printf("one pruning level (%zu sub-boxes, %zu per input): tape length mean %.1f, min %zu\n", boxes, k,
              static_cast<double>(total) / static_cast<double>(boxes), shortest);
}

int run_info(std::span<const std::string> args) {
  const Arguments a(args, {}, {});
  if (a.positional().size() != 1)
    throw UsageError("info takes one model file, got " + std::to_string(a.positional().size()) + " arguments");
  const std::string& path = a.positional()[0];
  const Fn f = load_model(path);
  const Tape tape(f);

  std::printf("model: %s\n", path.c_str());
  std::printf("definitions read: %zu\n", count_definitions(path));
  std::printf("DAG nodes: %zu\n", count_nodes(f));
  std::printf("tape: %zu clauses, %u registers, %zu constants\n", tape.size(), tape.num_registers(),
              tape.constants().size());
  std::printf("inputs:");
  for (int i : tape.inputs()) {
    if (i < 3) std::printf(" %c", "xyz"[i]);
    else std::printf(" x(%d)", i);
  }
  std::printf("%s\n", tape.num_inputs() == 0 ? " none" : "");
  std::printf("outputs: %zu\n", tape.num_outputs());

  IntervalEvaluator ev;
  const std::vector<Interval> box(tape.num_inputs(), Interval(-1.0, 1.0));
  const auto bounds = ev.eval(tape, box);
  for (std::size_t j = 0; j < bounds.size(); ++j)
    std::printf("output %zu over [-1,1]^%zu: %s\n", j, tape.num_inputs(), describe(bounds[j], ev.errors()[j]).c_str());
  report_pruning(tape);
  return 0;
}

}  // namespace

const Command kInfoCommand{"info", "MODEL.vm",
                           "print the tape size, inputs, outputs and interval bounds of a model", "", run_info};

}  // namespace genmod::app
