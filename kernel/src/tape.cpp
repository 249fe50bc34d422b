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
  std::vector<std::uint32_t> ssa_call_args, reg_call_args;
  std::uint32_t num_registers = 0;
  std::uint32_t num_slots = 0;
  bool has_choices = false;
};

namespace {

constexpr std::uint32_t kUnused = 0xffffffffu;

// The SSA operands of a clause that are register values (not immediates or slots).
template <class F>
void for_each_operand(const Clause& cl, std::span<const std::uint32_t> call_args, std::span<const CallSite> calls,
                      F&& f) {
  if (cl.op == Op::Call) {
    const CallSite& cs = calls[cl.a];
    for (std::uint32_t k = 0; k < cs.num_args; ++k) f(call_args[cs.first_arg + k]);
    return;
  }
  if (cl.op == Op::CallOut) {
    f(cl.b);  // ordering dependency on the call, not a register read
    return;
  }
  const int n = arity(cl.op);
  if (n >= 1) f(cl.a);
  if (n >= 2) f(cl.b);
  if (n >= 3) f(cl.c);
}

// Linear-scan register allocation over the SSA clauses (no reordering).
void allocate_registers(Tape::Data& d) {
  const std::size_t n = d.ssa.size();
  std::vector<std::uint32_t> last_use(n, kUnused);
  auto note_use = [&](std::uint32_t v, std::uint32_t at) {
    if (last_use[v] == kUnused || last_use[v] < at) last_use[v] = at;
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    const Clause& cl = d.ssa[i];
    if (cl.op == Op::CallOut) {
      note_use(cl.b, i);
      continue;
    }
    for_each_operand(cl, d.ssa_call_args, d.calls, [&](std::uint32_t v) { note_use(v, i); });
  }
  for (std::uint32_t v : d.ssa_outputs) last_use[v] = static_cast<std::uint32_t>(n);  // live to the end

  std::vector<std::uint32_t> reg_of(n, kUnused);
  std::vector<std::uint32_t> free_list;
  std::uint32_t next = 0;
  d.reg.resize(n);
  d.reg_call_args.assign(d.ssa_call_args.size(), 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Clause& s = d.ssa[i];
    Clause r = s;
    const int ar = arity(s.op);
    if (ar >= 1) r.a = reg_of[s.a];
    if (ar >= 2 && s.op < Op::AddImm) r.b = reg_of[s.b];
    if (ar >= 3) r.c = reg_of[s.c];
    if (s.op == Op::Call) {
      const CallSite& cs = d.calls[s.a];
      for (std::uint32_t k = 0; k < cs.num_args; ++k)
        d.reg_call_args[cs.first_arg + k] = reg_of[d.ssa_call_args[cs.first_arg + k]];
    }
    // Free operands whose last use is here (the result may reuse one: evaluators read all
    // operands of a clause before writing its result).
    if (s.op != Op::CallOut) {
      for_each_operand(s, d.ssa_call_args, d.calls, [&](std::uint32_t v) {
        if (last_use[v] == i && reg_of[v] != kUnused) {
          free_list.push_back(reg_of[v]);
          last_use[v] = kUnused - 1;  // freed once even if used twice by this clause
        }
      });
    }
    if (s.op == Op::Call) {
      r.out = 0;  // writes call slots, not a register
      reg_of[i] = kUnused;
    } else {
      std::uint32_t reg;
      if (!free_list.empty()) {
        reg = free_list.back();
        free_list.pop_back();
      } else {
        reg = next++;
      }
      reg_of[i] = reg;
      r.out = reg;
      if (last_use[i] == kUnused) free_list.push_back(reg);  // dead value
    }
    d.reg[i] = r;
  }
  d.reg_outputs.clear();
  for (std::uint32_t v : d.ssa_outputs) d.reg_outputs.push_back(reg_of[v]);
  d.num_registers = std::max<std::uint32_t>(next, 1);
  d.has_choices = std::any_of(d.ssa.begin(), d.ssa.end(), [](const Clause& c) { return has_choice(c.op); });
}

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
      cs.op_id = n.custom;
      cs.first_arg = static_cast<std::uint32_t>(d_.ssa_call_args.size());
      cs.num_args = static_cast<std::uint32_t>(args.size());
      for (NodeId a : args) d_.ssa_call_args.push_back(value(a));
      cs.first_slot = d_.num_slots;
      cs.num_outputs = static_cast<std::uint32_t>(dag::custom(n.custom).num_outputs());
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
  Compiler(*d, inputs).compile(f);
  allocate_registers(*d);
  return d;
}

}  // namespace

Tape::Tape(const Fn& f) : data_(compile(f, f.inputs())) {}
Tape::Tape(const Fn& f, std::span<const int> inputs) : data_(compile(f, inputs)) {}

std::span<const Clause> Tape::clauses() const noexcept { return data_->reg; }
std::span<const std::uint32_t> Tape::output_registers() const noexcept { return data_->reg_outputs; }
std::span<const std::uint32_t> Tape::call_arg_registers() const noexcept { return data_->reg_call_args; }
std::uint32_t Tape::num_registers() const noexcept { return data_->num_registers; }
std::span<const Clause> Tape::ssa() const noexcept { return data_->ssa; }
std::span<const double> Tape::constants() const noexcept { return *data_->constants; }
std::span<const int> Tape::inputs() const noexcept { return data_->inputs; }
std::span<const CallSite> Tape::calls() const noexcept { return data_->calls; }
std::uint32_t Tape::num_call_slots() const noexcept { return data_->num_slots; }
bool Tape::has_choices() const noexcept { return data_->has_choices; }

Tape Tape::simplify(std::span<const std::uint8_t> choices) const {
  const Data& d = *data_;
  const std::size_t n = d.ssa.size();
  if (choices.size() != n)
    throw std::invalid_argument("genmod: Tape::simplify: " + std::to_string(choices.size()) + " choices for " +
                                std::to_string(n) + " clauses");
  if (!d.has_choices) return *this;

  // Backward pass: which values are needed, and which clauses collapse to one operand.
  std::vector<std::uint8_t> live(n, 0);
  for (std::uint32_t v : d.ssa_outputs) live[v] = 1;
  bool removed = false;
  for (std::size_t i = n; i-- > 0;) {
    if (!live[i]) {
      removed = true;
      continue;
    }
    const Clause& cl = d.ssa[i];
    const std::uint8_t ch = has_choice(cl.op) ? choices[i] : std::uint8_t{kChoiceBoth};
    if (ch != kChoiceBoth) {
      removed = true;
      if (cl.op == Op::Select) live[ch == kChoiceFirst ? cl.b : cl.c] = 1;
      else if (ch == kChoiceFirst || cl.op == Op::Min || cl.op == Op::Max) live[ch == kChoiceFirst ? cl.a : cl.b] = 1;
      // MinImm/MaxImm choosing the immediate needs no operand.
      continue;
    }
    for_each_operand(cl, d.ssa_call_args, d.calls, [&](std::uint32_t v) { live[v] = 1; });
  }
  if (!removed) return *this;

  // Forward pass: emit the live clauses, forwarding collapsed ones to their chosen operand.
  auto out = std::make_shared<Data>();
  out->constants = d.constants;
  out->inputs = d.inputs;
  std::vector<std::uint32_t> remap(n, kUnused);
  auto push = [&](Clause c) {
    c.out = static_cast<std::uint32_t>(out->ssa.size());
    out->ssa.push_back(c);
    return c.out;
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!live[i]) continue;
    Clause cl = d.ssa[i];
    const std::uint8_t ch = has_choice(cl.op) ? choices[i] : std::uint8_t{kChoiceBoth};
    if (ch != kChoiceBoth) {
      if (cl.op == Op::Select) remap[i] = remap[ch == kChoiceFirst ? cl.b : cl.c];
      else if (ch == kChoiceFirst) remap[i] = remap[cl.a];
      else if (cl.op == Op::Min || cl.op == Op::Max) remap[i] = remap[cl.b];
      else remap[i] = push({Op::Const, {}, 0, cl.b, 0, 0});  // the immediate itself
      continue;
    }
    if (cl.op == Op::Call) {
      CallSite cs = d.calls[cl.a];
      const std::uint32_t first = static_cast<std::uint32_t>(out->ssa_call_args.size());
      for (std::uint32_t k = 0; k < cs.num_args; ++k) out->ssa_call_args.push_back(remap[d.ssa_call_args[cs.first_arg + k]]);
      cs.first_arg = first;
      out->calls.push_back(cs);
      out->num_slots = d.num_slots;  // slot numbering is kept
      cl.a = static_cast<std::uint32_t>(out->calls.size() - 1);
    } else if (cl.op == Op::CallOut) {
      cl.b = remap[cl.b];
    } else {
      const int ar = arity(cl.op);
      if (ar >= 1) cl.a = remap[cl.a];
      if (ar >= 2 && cl.op < Op::AddImm) cl.b = remap[cl.b];
      if (ar >= 3) cl.c = remap[cl.c];
    }
    remap[i] = push(cl);
  }
  for (std::uint32_t v : d.ssa_outputs) out->ssa_outputs.push_back(remap[v]);
  allocate_registers(*out);
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
      case Op::Call: os << " #" << c.a << " (" << dag::custom(data_->calls[c.a].op_id).name() << ')'; break;
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
