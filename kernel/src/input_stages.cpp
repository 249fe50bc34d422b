// stage_by_inputs: a function split into tapes by the input sets of its nodes (see
// input_stages.hpp).
#include "genmod/kernel/input_stages.hpp"

#include "dag.hpp"

#include <algorithm>
#include <bit>
#include <unordered_map>
#include <utility>

namespace genmod {
namespace {

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

// Constants and coordinates are read where they are used, never tabulated.
bool tabulable(const Node& n) { return n.op != Op::Const && n.op != Op::Var; }

}  // namespace

StagedFunction stage_by_inputs(const Fn& f) {
  const std::vector<NodeId> order = dag::topological_order(f.nodes());
  auto inputs_of = [](NodeId id) { return dag::node(id).inputs; };

  // Nodes needed as stage outputs: read by a node of another stage, or a component of f.
  std::unordered_map<NodeId, bool> needed;
  for (NodeId id : order)
    for (NodeId c : children(dag::node(id)))
      if (tabulable(dag::node(c)) && inputs_of(c) != inputs_of(id)) needed[c] = true;
  for (NodeId c : f.nodes())
    if (tabulable(dag::node(c))) needed[c] = true;

  // Input sets in order of size: every stage a stage reads comes before it.
  std::vector<std::uint64_t> masks;
  for (NodeId id : order)
    if (tabulable(dag::node(id)) && std::find(masks.begin(), masks.end(), inputs_of(id)) == masks.end())
      masks.push_back(inputs_of(id));
  std::stable_sort(masks.begin(), masks.end(),
                   [](std::uint64_t a, std::uint64_t b) { return std::popcount(a) < std::popcount(b); });

  // Coordinates f does not use stand for lower stages' outputs inside a stage.
  std::vector<int> free_coords;
  for (int c = 0; c < kMaxInputs; ++c)
    if (!(f.input_mask() & (std::uint64_t{1} << c))) free_coords.push_back(c);

  StagedFunction staged;
  std::unordered_map<NodeId, StageSource> where;  // a stage output's node -> its source
  for (std::uint64_t mask : masks) {
    std::vector<NodeId> outs;
    for (NodeId id : order)
      if (inputs_of(id) == mask && needed.count(id)) outs.push_back(id);
    if (outs.empty()) continue;

    // Rewrite the stage: lower-stage operands become placeholder coordinates.
    dag::Refs refs;  // the rewritten nodes, until stage_fn holds them
    std::unordered_map<NodeId, NodeId> mapped;
    std::vector<NodeId> placeholders;  // original nodes, in placeholder order
    bool ok = true;
    for (NodeId id : order) {
      if (!ok) break;
      if (inputs_of(id) != mask || !tabulable(dag::node(id))) continue;
      const Node& n = dag::node(id);
      std::vector<NodeId> args;
      for (NodeId c : children(n)) {
        const Node& cn = dag::node(c);
        if (!tabulable(cn) || inputs_of(c) == mask) {
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
    for (NodeId id : outs) stage_nodes.push_back(ok ? mapped.at(id) : id);
    const Fn stage_fn(stage_nodes);
    const std::uint64_t used = stage_fn.input_mask();
    std::vector<int> tape_inputs;
    std::vector<StageSource> sources;
    for (int c = 0; c < kMaxInputs; ++c)
      if ((mask & used & (std::uint64_t{1} << c))) {
        tape_inputs.push_back(c);
        sources.push_back({StageSource::Kind::Coordinate, c});
      }
    if (ok) {
      for (std::size_t k = 0; k < placeholders.size(); ++k) {
        const int c = free_coords[k];
        if (!(used & (std::uint64_t{1} << c))) continue;
        tape_inputs.push_back(c);
        sources.push_back(where.at(placeholders[k]));
      }
    } else {
      ++staged.fallback_stages;
    }
    for (std::size_t j = 0; j < outs.size(); ++j)
      where[outs[j]] = {StageSource::Kind::Stage, -1, staged.stages.size(), j};
    staged.stages.push_back(InputStage{mask, Tape(stage_fn, tape_inputs), std::move(sources)});
  }

  for (NodeId c : f.nodes()) {
    const Node& n = dag::node(c);
    if (tabulable(n)) staged.components.push_back(where.at(c));
    else if (n.op == Op::Var) staged.components.push_back({StageSource::Kind::Coordinate, n.index});
    else staged.components.push_back({StageSource::Kind::Constant, -1, 0, 0, n.value});
  }
  return staged;
}

}  // namespace genmod
