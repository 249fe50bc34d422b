// Uniform lattice evaluation with subfunction tables (Snyder 1991, §4.2.1 / research §6.2).
//
// A lattice is a list of axes; axis i samples the coordinate x(axes[i].coordinate) at
//
//   x_k = a + (k * (b - a)) / (N - 1),   k = 0 .. N - 1     (x_0 = a when N == 1)
//
// computed in double precision exactly in that order (lattice_coordinate()), so a caller can
// reproduce every lattice point bit for bit. Points are numbered with the first axis varying
// fastest: p = k_0 + N_0 * (k_1 + N_1 * (k_2 + ...)).
//
// Table lookup (the thesis's speedup, [FRAN81]): every DAG node depends on a subset of the
// lattice coordinates. The kernel's stage_by_inputs (genmod/kernel/input_stages.hpp) groups
// the nodes by that subset ("stage") and compiles each stage into its own tape, where values
// of lower-dimensional subfunctions are read from their tables instead of being recomputed;
// here each stage is evaluated (batch evaluator) once per point of its own sub-lattice. So e^{x2} in (x1 x2 + x2 x3) e^{x2} is computed N_2 times, not
// N_1 N_2 N_3 times. Every node is evaluated by the same clause on the same operand values as
// in a plain tape, so results are bitwise equal to point evaluation (NaN = error in both).
// A stage whose rewrite would change the DAG's structure (an operand reorder of min/max, or
// more tables than free coordinates) falls back to recomputing its subfunctions from the
// lattice coordinates, which is still exact, only slower; LatticeStats reports it.
//
// Example:
//   Fn surface = cat({x(0), x(1), x(0) * x(1)});
//   Lattice lat({{0, 0.0, 1.0, 256}, {1, 0.0, 1.0, 256}});
//   LatticeStats stats;
//   std::vector<double> xyz = evaluate_lattice(surface, lat, LatticeMethod::Tables, &stats);
//   // xyz[p * surface.dim() + j] = component j at lattice point p
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/opcode.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace genmod {

// One axis of a lattice: `samples` points from `lo` to `hi` in x(coordinate).
struct LatticeAxis {
  int coordinate = 0;
  double lo = 0.0;
  double hi = 1.0;
  std::size_t samples = 2;
};

class Lattice {
 public:
  // Throws std::invalid_argument for no axes, a repeated or out-of-range coordinate, a
  // non-finite bound, or zero samples.
  explicit Lattice(std::vector<LatticeAxis> axes);

  const std::vector<LatticeAxis>& axes() const noexcept { return axes_; }
  std::size_t num_axes() const noexcept { return axes_.size(); }
  std::size_t num_points() const noexcept { return num_points_; }
  // The value of axis `axis` at index k: lo + (k * (hi - lo)) / (samples - 1).
  double coordinate(std::size_t axis, std::size_t k) const;
  // Point p as values of x(0) .. x(max coordinate) (unused coordinates are 0), for
  // point evaluation of the same function.
  std::vector<double> point(std::size_t p) const;

 private:
  std::vector<LatticeAxis> axes_;
  std::size_t num_points_ = 1;
};

double lattice_coordinate(const LatticeAxis& axis, std::size_t k);

enum class LatticeMethod {
  Plain,   // one tape of f, every node evaluated at every lattice point
  Tables,  // subfunction tables (see above)
};

// Primitive operations performed, per tape opcode (Load / Const / CallOut excluded: they are
// data movement, not arithmetic).
struct LatticeStats {
  static constexpr std::size_t kNumOps = static_cast<std::size_t>(Op::CallOut) + 1;
  std::array<std::uint64_t, kNumOps> op_counts{};
  std::size_t tables = 0;           // stage tables built (Tables only)
  std::size_t table_entries = 0;    // values stored in them
  std::size_t fallback_stages = 0;  // stages recomputed from coordinates (see header comment)

  std::uint64_t count(Op op) const noexcept { return op_counts[static_cast<std::size_t>(op)]; }
  std::uint64_t multiplies() const noexcept { return count(Op::Mul) + count(Op::MulImm); }
  std::uint64_t adds() const noexcept { return count(Op::Add) + count(Op::AddImm); }
  std::uint64_t exps() const noexcept { return count(Op::Exp); }
  std::uint64_t total() const noexcept;
};

// Evaluates f at every lattice point: result[p * f.dim() + j] is component j at point p.
// Every coordinate f depends on must be a lattice axis (std::invalid_argument names a
// missing one). `stats`, if given, is overwritten.
std::vector<double> evaluate_lattice(const Fn& f, const Lattice& lattice,
                                     LatticeMethod method = LatticeMethod::Tables,
                                     LatticeStats* stats = nullptr);

}  // namespace genmod
