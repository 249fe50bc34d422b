// Uniform lattice evaluation, plain and with subfunction tables (see lattice.hpp).
#include "genmod/tessellate/lattice.hpp"

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/dag.hpp"
#include "genmod/kernel/tape.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

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

std::vector<NodeId> children(const Node& n) {
  if (n.op == Op::Custom) {
    const auto args = dag::custom_args(n);
    return {args.begin(), args.end()};
  }
  std::vector<NodeId> c;
  for (int i = 0; i < arity(n.op); ++i) c.push_back(n.arg[i]);
  return c;
}

// Rebuilds node n with its operands replaced by `mapped`; returns kNoNode when the DAG's
// construction rules would not reproduce the same operation on the same operands in the
// same order (then the tape would not compute the same bits). The nodes made are owned by
// `refs`.
NodeId rebuild(const Node& n, const std::vector<NodeId>& mapped, dag::Refs& refs) {
  if (n.op == Op::Custom) return refs.own(dag::make_custom(n.custom, n.index, mapped));
  const NodeId r = refs.own(dag::make(n.op, mapped[0], mapped.size() > 1 ? mapped[1] : kNoNode,
                                      mapped.size() > 2 ? mapped[2] : kNoNode));
  const Node& rn = dag::node(r);
  if (rn.op != n.op) return kNoNode;
  bool same = true;
  for (std::size_t i = 0; i < mapped.size(); ++i) same = same && rn.arg[i] == mapped[i];
  if (same) return r;
  // Operands swapped by the commutative ordering: bitwise harmless except for min / max,
  // whose result on (+0, -0) and on two NaNs depends on the order.
  const bool swapped = mapped.size() == 2 && rn.arg[0] == mapped[1] && rn.arg[1] == mapped[0];
  if (swapped && n.op != Op::Min && n.op != Op::Max) return r;
  return kNoNode;
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

std::vector<double> evaluate_tables(const Fn& f, const Lattice& lattice, LatticeStats& stats) {
  const std::vector<NodeId> order = dag::topological_order(f.nodes());
  std::unordered_map<NodeId, std::uint64_t> axis_mask;  // node -> lattice axes it depends on
  std::vector<int> coord_to_axis(kMaxInputs, -1);
  for (std::size_t i = 0; i < lattice.num_axes(); ++i)
    coord_to_axis[static_cast<std::size_t>(lattice.axes()[i].coordinate)] = static_cast<int>(i);
  for (NodeId id : order) {
    std::uint64_t in = dag::node(id).inputs, am = 0;
    while (in) {
      const int c = std::countr_zero(in);
      in &= in - 1;
      am |= std::uint64_t{1} << coord_to_axis[static_cast<std::size_t>(c)];
    }
    axis_mask[id] = am;
  }
  auto tabulable = [](const Node& n) { return n.op != Op::Const && n.op != Op::Var; };

  // Nodes needed as tables: used by a node of another stage, or a component of f.
  std::unordered_map<NodeId, bool> needed;
  for (NodeId id : order) {
    const Node& n = dag::node(id);
    for (NodeId c : children(n))
      if (tabulable(dag::node(c)) && axis_mask[c] != axis_mask[id]) needed[c] = true;
  }
  for (NodeId c : f.nodes())
    if (tabulable(dag::node(c))) needed[c] = true;

  // Stages in order of dimension: every table a stage reads is built before it.
  std::vector<std::uint64_t> masks;
  for (NodeId id : order)
    if (tabulable(dag::node(id)) && std::find(masks.begin(), masks.end(), axis_mask[id]) == masks.end())
      masks.push_back(axis_mask[id]);
  std::stable_sort(masks.begin(), masks.end(),
                   [](std::uint64_t a, std::uint64_t b) { return std::popcount(a) < std::popcount(b); });

  struct Table {
    SubLattice sub;
    std::vector<double> values;  // output-major: values[slot * sub.size + point]
  };
  std::vector<Table> tables;
  tables.reserve(masks.size());
  std::unordered_map<NodeId, std::pair<std::size_t, std::size_t>> where;  // node -> (table, slot)
  std::vector<int> free_coords;
  const std::uint64_t used_coords = coordinate_mask(lattice);
  for (int c = 0; c < kMaxInputs; ++c)
    if (!(used_coords & (std::uint64_t{1} << c))) free_coords.push_back(c);
  const std::vector<std::vector<double>> coords = coordinate_values(lattice);
  BatchEvaluator ev;

  for (std::uint64_t mask : masks) {
    std::vector<NodeId> outs;
    for (NodeId id : order)
      if (axis_mask[id] == mask && needed.count(id)) outs.push_back(id);
    if (outs.empty()) continue;
    Table table{sub_lattice(lattice, mask), {}};

    // Rewrite the stage: lower-stage operands become placeholder coordinates.
    dag::Refs refs;  // the rewritten nodes, until stage_fn holds them
    std::unordered_map<NodeId, NodeId> mapped;
    std::vector<NodeId> placeholders;  // original nodes, in placeholder order
    bool ok = true;
    for (NodeId id : order) {
      if (!ok) break;
      if (axis_mask[id] != mask || !tabulable(dag::node(id))) continue;
      const Node& n = dag::node(id);
      std::vector<NodeId> args;
      for (NodeId c : children(n)) {
        const Node& cn = dag::node(c);
        if (!tabulable(cn) || axis_mask[c] == mask) {
          args.push_back(tabulable(cn) ? mapped.at(c) : c);
          continue;
        }
        auto it = mapped.find(c);
        if (it == mapped.end()) {
          if (placeholders.size() >= free_coords.size()) {
            ok = false;
            break;
          }
          it = mapped.emplace(c, refs.own(dag::var(free_coords[placeholders.size()]))).first;
          placeholders.push_back(c);
        }
        args.push_back(it->second);
      }
      if (!ok) break;
      const NodeId r = rebuild(n, args, refs);
      if (r == kNoNode) ok = false;
      else mapped[id] = r;
    }

    std::vector<NodeId> stage_nodes;
    std::vector<int> tape_inputs;
    std::vector<Source> sources;
    for (NodeId id : outs) stage_nodes.push_back(ok ? mapped.at(id) : id);
    const Fn stage_fn(stage_nodes);
    const std::uint64_t stage_inputs = stage_fn.input_mask();
    for (std::size_t pos = 0; pos < table.sub.axes.size(); ++pos) {
      const int c = lattice.axes()[table.sub.axes[pos]].coordinate;
      if (stage_inputs & (std::uint64_t{1} << c)) {
        tape_inputs.push_back(c);
        sources.push_back(coordinate_source(coords, table.sub, pos));
      }
    }
    if (ok) {
      for (std::size_t k = 0; k < placeholders.size(); ++k) {
        const int c = free_coords[k];
        if (!(stage_inputs & (std::uint64_t{1} << c))) continue;
        const auto [t, slot] = where.at(placeholders[k]);
        const Table& src = tables[t];
        tape_inputs.push_back(c);
        sources.push_back(Source{src.values.data() + slot * src.sub.size, table_strides(src.sub, table.sub)});
      }
    } else {
      ++stats.fallback_stages;
    }
    const Tape tape(stage_fn, tape_inputs);
    table.values.resize(outs.size() * table.sub.size);
    std::vector<double*> out_ptr(outs.size());
    for (std::size_t j = 0; j < outs.size(); ++j) out_ptr[j] = table.values.data() + j * table.sub.size;
    run_stage(tape, table.sub, sources, out_ptr, ev);
    count_ops(tape, table.sub.size, stats);
    ++stats.tables;
    stats.table_entries += table.values.size();
    for (std::size_t j = 0; j < outs.size(); ++j) where[outs[j]] = {tables.size(), j};
    tables.push_back(std::move(table));
  }

  // Assemble the components over the full lattice by table lookup.
  const std::size_t m = f.dim(), total = lattice.num_points();
  std::vector<double> result(m * total);
  const std::uint64_t all = lattice.num_axes() == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << lattice.num_axes()) - 1;
  const SubLattice full = sub_lattice(lattice, all);
  for (std::size_t j = 0; j < m; ++j) {
    const NodeId c = f.node(j);
    const Node& n = dag::node(c);
    if (tabulable(n)) {
      const auto [t, slot] = where.at(c);
      gather(tables[t].values.data() + slot * tables[t].sub.size, table_strides(tables[t].sub, full), full, 0,
             total, result.data() + j, m);
    } else if (n.op == Op::Var) {
      const Source src = coordinate_source(coords, full, axis_of(lattice, n.index));
      gather(src.values, src.stride, full, 0, total, result.data() + j, m);
    } else {
      for (std::size_t p = 0; p < total; ++p) result[p * m + j] = n.value;
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
