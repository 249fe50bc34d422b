// Uniform lattice evaluation, plain and with subfunction tables (see lattice.hpp).
#include "genmod/tessellate/lattice.hpp"

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/input_stages.hpp"
#include "genmod/kernel/tape.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod {

double lattice_coordinate(const LatticeAxis& axis, std::size_t k) {
  if (axis.samples <= 1) return axis.lo;
  // Exactly a + k (b - a) / (N - 1), evaluated left to right.
  return axis.lo + (static_cast<double>(k) * (axis.hi - axis.lo)) / static_cast<double>(axis.samples - 1);
}

Lattice::Lattice(std::vector<LatticeAxis> axes) : axes_(std::move(axes)) {
  if (axes_.empty()) throw std::invalid_argument("genmod: Lattice needs at least one axis");
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    const LatticeAxis& a = axes_[i];
    const std::string name = "genmod: Lattice axis " + std::to_string(i) + " (x(" + std::to_string(a.coordinate) + ")): ";
    if (a.coordinate < 0 || a.coordinate >= kMaxInputs)
      throw std::invalid_argument(name + "coordinate out of range [0, " + std::to_string(kMaxInputs) + ")");
    const std::uint64_t bit = std::uint64_t{1} << a.coordinate;
    if (seen & bit) throw std::invalid_argument(name + "coordinate used by two axes");
    seen |= bit;
    if (!std::isfinite(a.lo) || !std::isfinite(a.hi)) throw std::invalid_argument(name + "bounds must be finite");
    if (a.samples == 0) throw std::invalid_argument(name + "needs at least one sample");
    if (num_points_ > SIZE_MAX / a.samples) throw std::invalid_argument(name + "lattice too large");
    num_points_ *= a.samples;
  }
}

double Lattice::coordinate(std::size_t axis, std::size_t k) const {
  const LatticeAxis& a = axes_.at(axis);
  if (k >= a.samples) throw std::out_of_range("genmod: Lattice::coordinate: index out of range");
  return lattice_coordinate(a, k);
}

std::vector<double> Lattice::point(std::size_t p) const {
  if (p >= num_points_) throw std::out_of_range("genmod: Lattice::point: index out of range");
  int max_coord = 0;
  for (const LatticeAxis& a : axes_) max_coord = std::max(max_coord, a.coordinate);
  std::vector<double> x(static_cast<std::size_t>(max_coord) + 1, 0.0);
  for (const LatticeAxis& a : axes_) {
    x[static_cast<std::size_t>(a.coordinate)] = lattice_coordinate(a, p % a.samples);
    p /= a.samples;
  }
  return x;
}

std::uint64_t LatticeStats::total() const noexcept {
  std::uint64_t t = 0;
  for (std::uint64_t c : op_counts) t += c;
  return t;
}

namespace {

constexpr std::size_t kBlock = 4096;  // points gathered per batch evaluation

void count_ops(const Tape& tape, std::size_t points, LatticeStats& stats) {
  for (int i = 0; i < kNumOps; ++i) {
    const Op op = static_cast<Op>(i);
    if (op != Op::Load && op != Op::Const && op != Op::CallOut) stats.op_counts[static_cast<std::size_t>(i)] += tape.count(op) * points;
  }
}

// Where one tape input of a stage comes from: values indexed by the stage's multi-index k as
// values[sum_a k[a] stride[a]]: a lower stage's table, or a lattice coordinate (the axis's
// sample values with stride 1 on its own position and 0 elsewhere).
struct Source {
  const double* values = nullptr;
  std::vector<std::size_t> stride;  // per stage axis position
};

// A sub-lattice: the lattice axes in `axis_mask`, first one fastest.
struct SubLattice {
  std::vector<std::size_t> axes;  // lattice axis indices
  std::vector<std::size_t> dims;
  std::size_t size = 1;
};

SubLattice sub_lattice(const Lattice& lattice, std::uint64_t axis_mask) {
  SubLattice s;
  for (std::size_t i = 0; i < lattice.num_axes(); ++i)
    if (axis_mask & (std::uint64_t{1} << i)) {
      s.axes.push_back(i);
      s.dims.push_back(lattice.axes()[i].samples);
      s.size *= lattice.axes()[i].samples;
    }
  return s;
}

// Strides of the table of sub-lattice `table` indexed by the multi-index of sub-lattice `by`
// (table axes must be a subset of by's axes).
std::vector<std::size_t> table_strides(const SubLattice& table, const SubLattice& by) {
  std::vector<std::size_t> stride(by.axes.size(), 0);
  std::size_t s = 1;
  for (std::size_t t = 0; t < table.axes.size(); ++t) {
    const auto it = std::find(by.axes.begin(), by.axes.end(), table.axes[t]);
    stride[static_cast<std::size_t>(it - by.axes.begin())] = s;
    s *= table.dims[t];
  }
  return stride;
}

// out[i * out_step] = values[index(k)] for the n points of `sub` from point p0 on (the first
// axis fastest), index(k) = sum_a k[a] stride[a] for the multi-index k of the point. The
// index is updated incrementally, an odometer over the axes, so a gather costs a few adds
// per value.
void gather(const double* values, const std::vector<std::size_t>& stride, const SubLattice& sub, std::size_t p0,
            std::size_t n, double* out, std::size_t out_step) {
  std::vector<std::size_t> k(sub.axes.size());
  std::size_t idx = 0;
  for (std::size_t a = 0; a < k.size(); ++a) {
    k[a] = p0 % sub.dims[a];
    p0 /= sub.dims[a];
    idx += k[a] * stride[a];
  }
  for (std::size_t i = 0; i < n; ++i) {
    out[i * out_step] = values[idx];
    for (std::size_t a = 0; a < k.size(); ++a) {
      idx += stride[a];
      if (++k[a] < sub.dims[a]) break;
      idx -= sub.dims[a] * stride[a];
      k[a] = 0;
    }
  }
}

// The source of lattice coordinate `axis`, which sits at position `pos` of `sub`.
Source coordinate_source(const std::vector<std::vector<double>>& coords, const SubLattice& sub, std::size_t pos) {
  Source src{coords[sub.axes[pos]].data(), std::vector<std::size_t>(sub.axes.size(), 0)};
  src.stride[pos] = 1;
  return src;
}

// Evaluates `tape` at every point of `sub`, reading input s from sources[s]; output j goes to
// outputs[j][0 .. sub.size).
void run_stage(const Tape& tape, const SubLattice& sub, const std::vector<Source>& sources,
               std::span<double* const> outputs, BatchEvaluator& ev) {
  const std::size_t n_in = sources.size();
  std::vector<double> in(n_in * kBlock);
  std::vector<const double*> in_ptr(n_in);
  std::vector<double*> out_ptr(outputs.size());
  for (std::size_t p0 = 0; p0 < sub.size; p0 += kBlock) {
    const std::size_t n = std::min(kBlock, sub.size - p0);
    for (std::size_t s = 0; s < n_in; ++s)
      gather(sources[s].values, sources[s].stride, sub, p0, n, in.data() + s * kBlock, 1);
    for (std::size_t s = 0; s < n_in; ++s) in_ptr[s] = in.data() + s * kBlock;
    for (std::size_t j = 0; j < outputs.size(); ++j) out_ptr[j] = outputs[j] + p0;
    ev.eval(tape, in_ptr, n, out_ptr);
  }
}

std::uint64_t coordinate_mask(const Lattice& lattice) {
  std::uint64_t m = 0;
  for (const LatticeAxis& a : lattice.axes()) m |= std::uint64_t{1} << a.coordinate;
  return m;
}

void check_inputs(const Fn& f, const Lattice& lattice) {
  const std::uint64_t missing = f.input_mask() & ~coordinate_mask(lattice);
  if (missing)
    throw std::invalid_argument("genmod: evaluate_lattice: the function depends on x(" +
                                std::to_string(std::countr_zero(missing)) + "), which is not a lattice axis");
}

std::vector<std::vector<double>> coordinate_values(const Lattice& lattice) {
  std::vector<std::vector<double>> c(lattice.num_axes());
  for (std::size_t i = 0; i < lattice.num_axes(); ++i)
    for (std::size_t k = 0; k < lattice.axes()[i].samples; ++k) c[i].push_back(lattice.coordinate(i, k));
  return c;
}

std::size_t axis_of(const Lattice& lattice, int coordinate) {
  for (std::size_t i = 0; i < lattice.num_axes(); ++i)
    if (lattice.axes()[i].coordinate == coordinate) return i;
  throw std::logic_error("genmod: lattice axis lookup failed");
}

// A stage evaluated with the given tape: sources for each tape input, computed from the
// tape's input coordinates unless `table_inputs` says otherwise.
std::vector<double> evaluate_plain(const Fn& f, const Lattice& lattice, LatticeStats& stats) {
  const std::size_t m = f.dim();
  const std::uint64_t all = lattice.num_axes() == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << lattice.num_axes()) - 1;
  const SubLattice sub = sub_lattice(lattice, all);
  const Tape tape(f);
  const std::vector<std::vector<double>> coords = coordinate_values(lattice);
  std::vector<Source> sources;
  for (int c : tape.inputs())  // sub has every axis: position == axis
    sources.push_back(coordinate_source(coords, sub, axis_of(lattice, c)));
  std::vector<double> out(m * sub.size);
  std::vector<double*> out_ptr(m);
  for (std::size_t j = 0; j < m; ++j) out_ptr[j] = out.data() + j * sub.size;
  BatchEvaluator ev;
  run_stage(tape, sub, sources, out_ptr, ev);
  count_ops(tape, sub.size, stats);
  std::vector<double> result(m * sub.size);
  for (std::size_t p = 0; p < sub.size; ++p)
    for (std::size_t j = 0; j < m; ++j) result[p * m + j] = out[j * sub.size + p];
  return result;
}

// The function split by input sets (stage_by_inputs): each stage is evaluated once per point
// of the sub-lattice of its coordinates, reading lower stages' tables.
std::vector<double> evaluate_tables(const Fn& f, const Lattice& lattice, LatticeStats& stats) {
  const StagedFunction staged = stage_by_inputs(f);
  stats.fallback_stages += staged.fallback_stages;
  // A set of coordinates -> the sub-lattice of their axes.
  auto sub_of = [&lattice](std::uint64_t coordinates) {
    std::uint64_t axes = 0;
    for (std::size_t i = 0; i < lattice.num_axes(); ++i)
      if (coordinates & (std::uint64_t{1} << lattice.axes()[i].coordinate)) axes |= std::uint64_t{1} << i;
    return sub_lattice(lattice, axes);
  };
  struct Table {
    SubLattice sub;
    std::vector<double> values;  // output-major: values[output * sub.size + point]
  };
  std::vector<Table> tables;
  tables.reserve(staged.stages.size());
  const std::vector<std::vector<double>> coords = coordinate_values(lattice);
  // Where a stage input or a component reads its values, indexed by the points of `by`.
  auto source = [&](const StageSource& s, const SubLattice& by) {
    if (s.kind == StageSource::Kind::Coordinate) {
      const std::size_t axis = axis_of(lattice, s.coordinate);
      const auto pos = std::find(by.axes.begin(), by.axes.end(), axis) - by.axes.begin();
      return coordinate_source(coords, by, static_cast<std::size_t>(pos));
    }
    const Table& t = tables[s.stage];
    return Source{t.values.data() + s.output * t.sub.size, table_strides(t.sub, by)};
  };
  BatchEvaluator ev;
  for (const InputStage& stage : staged.stages) {
    Table table{sub_of(stage.inputs), {}};
    std::vector<Source> sources;
    for (const StageSource& s : stage.sources) sources.push_back(source(s, table.sub));
    const std::size_t outs = stage.tape.num_outputs();
    table.values.resize(outs * table.sub.size);
    std::vector<double*> out_ptr(outs);
    for (std::size_t j = 0; j < outs; ++j) out_ptr[j] = table.values.data() + j * table.sub.size;
    run_stage(stage.tape, table.sub, sources, out_ptr, ev);
    count_ops(stage.tape, table.sub.size, stats);
    ++stats.tables;
    stats.table_entries += table.values.size();
    tables.push_back(std::move(table));
  }

  // Assemble the components over the full lattice by table lookup.
  const std::size_t m = f.dim(), total = lattice.num_points();
  std::vector<double> result(m * total);
  const std::uint64_t all = lattice.num_axes() == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << lattice.num_axes()) - 1;
  const SubLattice full = sub_lattice(lattice, all);
  for (std::size_t j = 0; j < m; ++j) {
    const StageSource& c = staged.components[j];
    if (c.kind == StageSource::Kind::Constant) {
      for (std::size_t p = 0; p < total; ++p) result[p * m + j] = c.value;
    } else {
      const Source src = source(c, full);
      gather(src.values, src.stride, full, 0, total, result.data() + j, m);
    }
  }
  return result;
}

}  // namespace

std::vector<double> evaluate_lattice(const Fn& f, const Lattice& lattice, LatticeMethod method, LatticeStats* stats) {
  check_inputs(f, lattice);
  LatticeStats local;
  std::vector<double> r =
      method == LatticeMethod::Plain ? evaluate_plain(f, lattice, local) : evaluate_tables(f, lattice, local);
  if (stats) *stats = local;
  return r;
}

}  // namespace genmod
