// Tape compilation (DAG -> SSA), register allocation and choice-driven simplification.
#include "genmod/kernel/tape.hpp"

#include "genmod/kernel/custom_op.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace genmod {

struct Tape::Data {
  std::vector<Clause> ssa, reg;
  std::shared_ptr<const std::vector<double>> constants;
  std::vector<int> inputs;
  std::vector<std::uint32_t> ssa_outputs, reg_outputs;
  std::vector<CallSite> calls;
  // The operators the call sites point to, kept alive as long as the tape (and the tapes
  // simplified from it) even when the Fn it was compiled from is gone.
  std::shared_ptr<const std::vector<std::shared_ptr<const CustomOp>>> ops;
  std::vector<std::uint32_t> ssa_call_args, reg_call_args;
  std::uint32_t num_registers = 0;
  std::uint32_t num_slots = 0;
  bool has_choices = false;
};

namespace {

constexpr std::uint32_t kUnused = 0xffffffffu;

// Rebuilds a tape from SSA clauses in one backward pass: drops values nothing needs, forwards
// min / max / select clauses whose choice is one-sided to the chosen operand, allocates
// registers (linear scan, backward: a value's register is taken at its last use and released
// at its definition), and renumbers the SSA form. `choices` may be empty (nothing collapses):
// that is how a freshly compiled tape gets its registers. Sets *changed if a clause was
// dropped or collapsed.
class Rebuilder {
 public:
  Rebuilder(const Tape::Data& src, std::span<const std::uint8_t> choices) : src_(src), choices_(choices) {}

  std::shared_ptr<Tape::Data> run(bool* changed) {
    const std::size_t n = src_.ssa.size();
    resolve_aliases();
    needed_.assign(n, 0);
    reg_of_.assign(n, kUnused);
    auto out = std::make_shared<Tape::Data>();
    out->constants = src_.constants;
    out->ops = src_.ops;
    out->inputs = src_.inputs;
    out->num_slots = src_.num_slots;
    // Outputs are live to the end: they take their registers first.
    for (std::uint32_t v : src_.ssa_outputs) use(resolved_[v]);
    std::vector<Clause> rev_reg, rev_ssa;  // emitted clauses, last first
    std::vector<std::uint32_t> rev_call_args;
    bool any_dropped = false;
    for (std::size_t i = n; i-- > 0;) {
      if (!needed_[i]) {
        any_dropped = true;
        continue;
      }
      Clause ssa = src_.ssa[i];
      Clause reg = ssa;
      if (collapses_to_immediate(i)) {
        // min/max with a constant, where the constant wins over the whole box.
        any_dropped = true;
        ssa = reg = Clause{Op::Const, {}, 0, ssa.b, 0, 0};
      }
      // The result's register is free before this definition (walking backward).
      reg.out = reg_of_[i];
      if (reg.op != Op::Call) free_.push_back(reg_of_[i]);
      switch (reg.op) {
        case Op::Call: {
          const CallSite& cs = src_.calls[ssa.a];
          for (std::uint32_t k = 0; k < cs.num_args; ++k) use(resolved_[src_.ssa_call_args[cs.first_arg + k]]);
          reg.out = 0;
          break;
        }
        case Op::CallOut: needed_[ssa.b] = 1; break;  // keeps its call (an ordering dependency)
        default: {
          const int ar = arity(ssa.op);
          const bool imm = ssa.op >= Op::AddImm && ssa.op <= Op::MaxImm;
          if (ar >= 1) reg.a = use(ssa.a = resolved_[ssa.a]);
          if (ar >= 2 && !imm) reg.b = use(ssa.b = resolved_[ssa.b]);
          if (ar >= 3) reg.c = use(ssa.c = resolved_[ssa.c]);
        }
      }
      ssa.out = static_cast<std::uint32_t>(i);  // old id for now; renumbered below
      rev_reg.push_back(reg);
      rev_ssa.push_back(ssa);
    }
    if (changed) *changed = any_dropped;

    // Forward order and new SSA numbering.
    const std::size_t m = rev_ssa.size();
    std::vector<std::uint32_t> new_id(n, kUnused);
    for (std::size_t k = 0; k < m; ++k) new_id[rev_ssa[m - 1 - k].out] = static_cast<std::uint32_t>(k);
    out->ssa.resize(m);
    out->reg.resize(m);
    for (std::size_t k = 0; k < m; ++k) {
      Clause ssa = rev_ssa[m - 1 - k];
      const int ar = arity(ssa.op);
      const bool imm = ssa.op >= Op::AddImm && ssa.op <= Op::MaxImm;
      if (ar >= 1) ssa.a = new_id[ssa.a];
      if (ar >= 2 && !imm) ssa.b = new_id[ssa.b];
      if (ar >= 3) ssa.c = new_id[ssa.c];
      if (ssa.op == Op::CallOut) ssa.b = new_id[ssa.b];
      if (ssa.op == Op::Call) {
        CallSite cs = src_.calls[ssa.a];
        const std::uint32_t first = static_cast<std::uint32_t>(out->ssa_call_args.size());
        for (std::uint32_t j = 0; j < cs.num_args; ++j) {
          const std::uint32_t v = resolved_[src_.ssa_call_args[cs.first_arg + j]];
          out->ssa_call_args.push_back(new_id[v]);
          out->reg_call_args.push_back(reg_of_[v]);
        }
        cs.first_arg = first;
        out->calls.push_back(cs);
        ssa.a = static_cast<std::uint32_t>(out->calls.size() - 1);
      }
      ssa.out = static_cast<std::uint32_t>(k);
      Clause reg = rev_reg[m - 1 - k];
      if (reg.op == Op::Call) reg.a = ssa.a;
      out->ssa[k] = ssa;
      out->reg[k] = reg;
      if (has_choice(ssa.op)) out->has_choices = true;
    }
    for (std::uint32_t v : src_.ssa_outputs) {
      out->ssa_outputs.push_back(new_id[resolved_[v]]);
      out->reg_outputs.push_back(reg_of_[resolved_[v]]);
    }
    out->num_registers = std::max<std::uint32_t>(next_reg_, 1);
    return out;
  }

 private:
  // resolved_[v]: the value v stands for after collapsing one-sided choices (chains followed).
  void resolve_aliases() {
    const std::size_t n = src_.ssa.size();
    resolved_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      resolved_[i] = i;
      if (choices_.empty()) continue;
      const Clause& c = src_.ssa[i];
      if (!has_choice(c.op) || choices_[i] == kChoiceBoth) continue;
      if (c.op == Op::Select) resolved_[i] = resolved_[choices_[i] == kChoiceFirst ? c.b : c.c];
      else if (choices_[i] == kChoiceFirst) resolved_[i] = resolved_[c.a];
      else if (c.op == Op::Min || c.op == Op::Max) resolved_[i] = resolved_[c.b];
      // MinImm / MaxImm choosing the immediate stay themselves (emitted as a Const).
    }
  }
  bool collapses_to_immediate(std::size_t i) const {
    const Clause& c = src_.ssa[i];
    return !choices_.empty() && (c.op == Op::MinImm || c.op == Op::MaxImm) && choices_[i] == kChoiceSecond;
  }
  // A use of value v (walking backward): v is needed and holds a register from here back to
  // its definition.
  std::uint32_t use(std::uint32_t v) {
    needed_[v] = 1;
    if (reg_of_[v] == kUnused) {
      if (!free_.empty()) {
        reg_of_[v] = free_.back();
        free_.pop_back();
      } else {
        reg_of_[v] = next_reg_++;
      }
    }
    return reg_of_[v];
  }

  const Tape::Data& src_;
  std::span<const std::uint8_t> choices_;
  std::vector<std::uint32_t> resolved_, reg_of_, free_;
  std::vector<std::uint8_t> needed_;
  std::uint32_t next_reg_ = 0;
};

// DAG -> SSA clauses.
class Compiler {
 public:
  Compiler(Tape::Data& d, std::span<const int> inputs) : d_(d) {
    for (std::size_t k = 0; k < inputs.size(); ++k) position_[inputs[k]] = static_cast<std::uint32_t>(k);
  }

  void compile(const Fn& f) {
    for (NodeId id : dag::topological_order(f.nodes())) {
      const Node& n = dag::node(id);
      if (n.op != Op::Const) emit_node(id, n);  // constants are emitted only where a register needs them
    }
    for (NodeId id : f.nodes()) d_.ssa_outputs.push_back(value(id));
    d_.constants = std::make_shared<const std::vector<double>>(std::move(constants_));
  }

 private:
  std::uint32_t constant_index(double v) {
    auto [it, inserted] = const_index_.emplace(v, static_cast<std::uint32_t>(constants_.size()));
    if (inserted) constants_.push_back(v);
    return it->second;
  }
  std::uint32_t push(Clause c) {
    c.out = static_cast<std::uint32_t>(d_.ssa.size());
    d_.ssa.push_back(c);
    return c.out;
  }
  // The SSA value of a node, emitting a Const clause for a constant on first use.
  std::uint32_t value(NodeId id) {
    if (auto it = ssa_of_.find(id); it != ssa_of_.end()) return it->second;
    const Node& n = dag::node(id);
    if (n.op != Op::Const) throw std::logic_error("genmod: tape compiler visited a node out of order");
    const std::uint32_t v = push({Op::Const, {}, 0, constant_index(n.value), 0, 0});
    ssa_of_.emplace(id, v);
    return v;
  }
  bool is_const(NodeId id, double* v) const {
    const Node& n = dag::node(id);
    if (n.op != Op::Const) return false;
    *v = n.value;
    return true;
  }

  void emit_node(NodeId id, const Node& n) {
    std::uint32_t v;
    switch (n.op) {
      case Op::Var: {
        auto it = position_.find(n.index);
        if (it == position_.end())
          throw std::invalid_argument("genmod: Tape: the function depends on x(" + std::to_string(n.index) +
                                      "), which is not in the tape's input list");
        v = push({Op::Load, {}, 0, it->second, 0, 0});
        break;
      }
      case Op::Custom: v = emit_custom(n); break;
      default: v = emit_arith(n); break;
    }
    ssa_of_.emplace(id, v);
  }

  std::uint32_t emit_arith(const Node& n) {
    const int ar = arity(n.op);
    if (ar == 2) {
      double k = 0.0;
      const NodeId a = n.arg[0], b = n.arg[1];
      const bool ka = is_const(a, &k);
      double kb_value = 0.0;
      const bool kb = is_const(b, &kb_value);
      // Only finite constants become immediates (an infinite one needs the [DBL_MAX, inf]
      // enclosure that a Const clause gives it).
      if (ka != kb && std::isfinite(ka ? k : kb_value)) {
        const NodeId reg_node = ka ? b : a;
        const double kv = ka ? k : kb_value;
        Op imm = Op::Const;
        double stored = kv;
        switch (n.op) {
          case Op::Add: imm = Op::AddImm; break;
          case Op::Mul: imm = Op::MulImm; break;
          case Op::Min: imm = Op::MinImm; break;
          case Op::Max: imm = Op::MaxImm; break;
          case Op::Sub:
            if (kb) { imm = Op::AddImm; stored = -kv; }  // a - k == a + (-k) exactly
            else imm = Op::SubImm;                       // k - a
            break;
          case Op::Div: imm = kb ? Op::DivImmR : Op::DivImmL; break;
          default: break;
        }
        if (imm != Op::Const) return push({imm, {}, 0, value(reg_node), constant_index(stored), 0});
      }
    }
    Clause c{n.op, {}, 0, 0, 0, 0};
    if (ar >= 1) c.a = value(n.arg[0]);
    if (ar >= 2) c.b = value(n.arg[1]);
    if (ar >= 3) c.c = value(n.arg[2]);
    return push(c);
  }

  std::uint32_t emit_custom(const Node& n) {
    const std::span<const NodeId> args = dag::custom_args(n);
    const auto key = std::make_pair(n.custom, n.arg[0]);  // operator + interned argument list
    std::uint32_t call;
    if (auto it = call_of_.find(key); it != call_of_.end()) {
      call = it->second;
    } else {
      CallSite cs{};
      ops_.push_back(dag::custom_shared(n.custom));
      cs.op = ops_.back().get();
      cs.op_index = static_cast<std::uint32_t>(ops_.size() - 1);
      cs.first_arg = static_cast<std::uint32_t>(d_.ssa_call_args.size());
      cs.num_args = static_cast<std::uint32_t>(args.size());
      for (NodeId a : args) d_.ssa_call_args.push_back(value(a));
      cs.first_slot = d_.num_slots;
      cs.num_outputs = static_cast<std::uint32_t>(cs.op->num_outputs());
      d_.num_slots += cs.num_outputs;
      d_.calls.push_back(cs);
      call = push({Op::Call, {}, 0, static_cast<std::uint32_t>(d_.calls.size() - 1), 0, 0});
      call_of_.emplace(key, call);
    }
    const CallSite& cs = d_.calls[d_.ssa[call].a];
    return push({Op::CallOut, {}, 0, cs.first_slot + static_cast<std::uint32_t>(n.index), call, 0});
  }

  Tape::Data& d_;
  std::unordered_map<int, std::uint32_t> position_;
  std::unordered_map<NodeId, std::uint32_t> ssa_of_;
  std::map<double, std::uint32_t> const_index_;
  std::vector<double> constants_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> call_of_;

 public:
  std::vector<std::shared_ptr<const CustomOp>> ops_;
};

std::shared_ptr<Tape::Data> compile(const Fn& f, std::span<const int> inputs) {
  auto d = std::make_shared<Tape::Data>();
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    if (inputs[k] < 0 || inputs[k] >= kMaxInputs)
      throw std::invalid_argument("genmod: Tape: input coordinate " + std::to_string(inputs[k]) + " is out of range");
    for (std::size_t j = 0; j < k; ++j)
      if (inputs[j] == inputs[k])
        throw std::invalid_argument("genmod: Tape: input coordinate " + std::to_string(inputs[k]) + " is listed twice");
  }
  d->inputs.assign(inputs.begin(), inputs.end());
  Compiler compiler(*d, inputs);
  compiler.compile(f);
  d->ops = std::make_shared<const std::vector<std::shared_ptr<const CustomOp>>>(std::move(compiler.ops_));
  return Rebuilder(*d, {}).run(nullptr);
}

}  // namespace

Tape::Tape(const Fn& f) : data_(compile(f, f.inputs())) {}
Tape::Tape(const Fn& f, Coordinates inputs) : data_(compile(f, inputs)) {}

std::span<const Clause> Tape::clauses() const noexcept { return data_->reg; }
std::span<const std::uint32_t> Tape::output_registers() const noexcept { return data_->reg_outputs; }
std::span<const std::uint32_t> Tape::call_arg_registers() const noexcept { return data_->reg_call_args; }
std::uint32_t Tape::num_registers() const noexcept { return data_->num_registers; }
std::span<const Clause> Tape::ssa() const noexcept { return data_->ssa; }
std::span<const std::uint32_t> Tape::output_values() const noexcept { return data_->ssa_outputs; }
std::span<const double> Tape::constants() const noexcept { return *data_->constants; }
std::span<const int> Tape::inputs() const noexcept { return data_->inputs; }
std::span<const CallSite> Tape::calls() const noexcept { return data_->calls; }
std::span<const std::shared_ptr<const CustomOp>> Tape::custom_ops() const noexcept {
  if (!data_->ops) return {};
  return *data_->ops;
}
std::uint32_t Tape::num_call_slots() const noexcept { return data_->num_slots; }
bool Tape::has_choices() const noexcept { return data_->has_choices; }

Tape Tape::simplify(std::span<const std::uint8_t> choices) const {
  const Data& d = *data_;
  if (choices.size() != d.ssa.size())
    throw std::invalid_argument("genmod: Tape::simplify: " + std::to_string(choices.size()) + " choices for " +
                                std::to_string(d.ssa.size()) + " clauses");
  if (!d.has_choices) return *this;
  bool changed = false;
  auto out = Rebuilder(d, choices).run(&changed);
  if (!changed) return *this;
  return Tape(std::shared_ptr<const Data>(std::move(out)));
}

std::string Tape::disassemble() const {
  std::ostringstream os;
  const auto& k = *data_->constants;
  for (const Clause& c : data_->reg) {
    os << 'r' << c.out << " = " << op_name(c.op);
    switch (c.op) {
      case Op::Const: os << ' ' << k[c.a]; break;
      case Op::Load: os << " input" << c.a; break;
      case Op::Call: os << " #" << c.a << " (" << data_->calls[c.a].op->name() << ')'; break;
      case Op::CallOut: os << " slot" << c.a; break;
      default: {
        const int ar = arity(c.op);
        if (ar >= 1) os << " r" << c.a;
        if (c.op >= Op::AddImm && c.op <= Op::MaxImm) os << ' ' << k[c.b];
        else if (ar >= 2) os << " r" << c.b;
        if (ar >= 3) os << " r" << c.c;
      }
    }
    os << '\n';
  }
  os << "outputs:";
  for (std::uint32_t r : data_->reg_outputs) os << " r" << r;
  os << '\n';
  return os.str();
}

}  // namespace genmod
