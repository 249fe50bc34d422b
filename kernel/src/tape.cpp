// Tape compilation (DAG -> SSA), register allocation and choice-driven simplification.
#include "genmod/kernel/tape.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "dag.hpp"
#include "tape_data.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace genmod {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;      // no register
constexpr std::uint32_t kCallLive = 0xfffffffeu;  // a Call some CallOut needs (calls have no register)

// What a choice does to its clause.
enum Outcome : std::uint8_t {
  kKeep = 0,                     // the clause stays
  kToA = 1, kToB = 2, kToC = 3,  // the clause is forwarded to its operand a / b / c
  kToImmediate = 4               // min / max with a constant where the constant wins: that constant
};

// Outcome by opcode and choice (a table, as the choices of a tape follow no pattern a branch
// predictor could learn).
constexpr auto kOutcomes = [] {
  std::array<std::array<std::uint8_t, 4>, 256> t{};
  const auto set = [&](Op op, Outcome first, Outcome second) {
    t[static_cast<std::size_t>(op)][kChoiceFirst] = first;
    t[static_cast<std::size_t>(op)][kChoiceSecond] = second;
  };
  set(Op::Min, kToA, kToB);
  set(Op::Max, kToA, kToB);
  set(Op::MinImm, kToA, kToImmediate);
  set(Op::MaxImm, kToA, kToImmediate);
  set(Op::Select, kToB, kToC);
  return t;
}();

std::uint8_t outcome(const Clause& c, std::uint8_t choice) noexcept {
  return kOutcomes[static_cast<std::size_t>(c.op)][choice & 3u];
}

// Field k of out, a, b, c (k = kKeep, kToA, kToB, kToC), read straight from the clause: a
// branch per clause would be mispredicted, and copying the four into an array would store
// and load them back at once (a store-forwarding stall).
std::uint32_t field(const Clause& c, unsigned k) noexcept {
  static_assert(offsetof(Clause, a) == offsetof(Clause, out) + 4 && offsetof(Clause, b) == offsetof(Clause, out) + 8 &&
                offsetof(Clause, c) == offsetof(Clause, out) + 12);
  std::uint32_t v;
  std::memcpy(&v, reinterpret_cast<const char*>(&c) + offsetof(Clause, out) + 4 * k, sizeof v);
  return v;
}

// plain_op() as a table.
constexpr auto kPlain = [] {
  std::array<bool, 256> t{};
  for (int op = 0; op < kNumOps; ++op) t[static_cast<std::size_t>(op)] = plain_op(static_cast<Op>(op));
  return t;
}();

// Register operands by opcode (arity() as a table).
constexpr auto kArity = [] {
  std::array<std::uint8_t, 256> t{};
  for (int op = 0; op < kNumOps; ++op) t[static_cast<std::size_t>(op)] = static_cast<std::uint8_t>(arity(static_cast<Op>(op)));
  return t;
}();

}  // namespace

// The simplifier's scratch: between calls reg_of_ holds no register and alias_ is the
// identity, so a call needs no clearing of arrays as long as the compiled tape.
class TapeSimplifier::Impl {
 public:
  struct Source;
  class Registers;
  std::shared_ptr<TapeData> rebuild(const Source& src, std::span<const std::uint8_t> choices);
  bool note_aliases(const Source& src, std::span<const std::uint8_t> choices);
  void prepare(std::size_t num_values, std::size_t length);

 private:
  void keep_call_or_out(const Source& src, const Clause& c, std::size_t position, Registers& regs, Clause& reg);
  void finish_calls(const Source& src, std::size_t first, TapeData& out);

  std::vector<std::uint32_t> reg_of_;  // by value id: its register while live (walking backward)
  std::vector<std::uint32_t> alias_;   // by value id: the value it stands for (one-sided choices)
  std::vector<std::uint32_t> free_;    // stack of the registers free at the current clause
  std::vector<Clause> reg_out_, ssa_out_;  // emitted clauses, written from the end
  struct EmittedCall {
    std::uint32_t position, call, first_arg;
  };
  std::vector<EmittedCall> calls_;            // last first
  std::vector<std::uint32_t> call_regs_, call_values_;
  bool clean_ = true;  // false from note_aliases() to the end of rebuild(): after an exception, prepare() resets
};

TapeSimplifier::TapeSimplifier() : impl_(std::make_unique<Impl>()) {}
TapeSimplifier::~TapeSimplifier() = default;
TapeSimplifier::TapeSimplifier(const TapeSimplifier&) : impl_(std::make_unique<Impl>()) {}
TapeSimplifier& TapeSimplifier::operator=(const TapeSimplifier&) { return *this; }  // keeps its own scratch
TapeSimplifier::TapeSimplifier(TapeSimplifier&&) noexcept = default;
TapeSimplifier& TapeSimplifier::operator=(TapeSimplifier&&) noexcept = default;

// The SSA form a rebuild reads: a tape's, or the compiler's before registers are allocated.
struct TapeSimplifier::Impl::Source {
  std::span<const Clause> ssa;
  std::span<const std::uint32_t> outputs;  // values
  std::span<const CallSite> calls;
  std::span<const std::uint32_t> call_args;  // values
  std::shared_ptr<const TapeCommon> common;
};

// Linear-scan register allocation walking backward over a tape: a value takes a register at
// its last use and gives it back at its definition. Works on the simplifier's arrays through
// plain pointers, so the hot loop keeps its state in registers.
class TapeSimplifier::Impl::Registers {
 public:
  // free_stack: room for one register per value, from free_stack[1].
  Registers(std::uint32_t* reg_of, std::uint32_t* free_stack) : reg_of_(reg_of), free_(free_stack) {}

  bool live(std::uint32_t v) const noexcept { return reg_of_[v] != kNone; }
  // A use of v: its register.
  std::uint32_t use(std::uint32_t v) noexcept {
    std::uint32_t& r = reg_of_[v];
    if (r == kNone) r = top_ > 0 ? free_[top_--] : next_++;
    return r;
  }
  // The definition of live value v: its register, free again before this clause.
  std::uint32_t release(std::uint32_t v) noexcept {
    const std::uint32_t r = reg_of_[v];
    reg_of_[v] = kNone;
    if (r != kCallLive) free_[++top_] = r;
    return r;
  }
  // A Call clause needed by one of its outputs (calls have no register).
  void keep_call(std::uint32_t call) noexcept {
    if (reg_of_[call] == kNone) reg_of_[call] = kCallLive;
  }
  std::uint32_t count() const noexcept { return next_; }

 private:
  std::uint32_t* reg_of_;
  std::uint32_t* free_;  // the free registers: free_[1 .. top_]
  std::uint32_t top_ = 0;
  std::uint32_t next_ = 0;
};

void TapeSimplifier::Impl::prepare(std::size_t num_values, std::size_t length) {
  if (!clean_) {  // a rebuild was interrupted by an exception
    std::fill(reg_of_.begin(), reg_of_.end(), kNone);
    std::iota(alias_.begin(), alias_.end(), 0u);
    clean_ = true;
  }
  if (reg_of_.size() < num_values) {
    const std::size_t old = alias_.size();
    reg_of_.resize(num_values, kNone);
    alias_.resize(num_values);
    std::iota(alias_.begin() + static_cast<std::ptrdiff_t>(old), alias_.end(), static_cast<std::uint32_t>(old));
  }
  if (reg_out_.size() < length) {
    reg_out_.resize(length);
    ssa_out_.resize(length);
  }
}

// Forward: points alias_ of each clause a one-sided choice forwards at the value it stands for
// (chains followed, as its operand was resolved before). Returns whether some choice is
// one-sided, i.e. whether the tape changes (a tape never holds dead clauses). No branch per
// clause: alias_ is the identity for the others.
bool TapeSimplifier::Impl::note_aliases(const Source& src, std::span<const std::uint8_t> choices) {
  clean_ = false;  // until rebuild() has undone the aliases
  std::uint8_t any = kKeep;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    const Clause& c = src.ssa[i];
    const std::uint8_t o = outcome(c, choices[i]);
    any |= o;
    alias_[c.out] = alias_[field(c, o & 3u)];  // kKeep and kToImmediate: itself
  }
  if (any == kKeep) clean_ = true;  // every alias_ entry was written with itself
  return any != kKeep;
}

// One backward pass: drops values nothing needs (and the clauses note_aliases forwarded, which
// nothing refers to any more), allocates registers by linear scan (a value's register is
// taken at its last use and released at its definition) and writes both forms of the kept
// clauses from the end of reg_out_ / ssa_out_, so they come out in order. Leaves reg_of_ all
// kNone and alias_ the identity again: every value met is defined further back on the tape.
std::shared_ptr<TapeData> TapeSimplifier::Impl::rebuild(const Source& src, std::span<const std::uint8_t> choices) {
  const std::size_t n = src.ssa.size();
  if (clean_) prepare(src.common->num_values, n);  // else note_aliases() has prepared
  clean_ = false;
  free_.resize(n + 1);  // at most one register per value
  calls_.clear();
  call_regs_.clear();
  call_values_.clear();
  Registers regs(reg_of_.data(), free_.data());
  std::uint32_t* const alias = alias_.data();

  auto out = std::make_shared<TapeData>();
  out->common = src.common;
  out->outputs.resize(2 * src.outputs.size());
  // Outputs are live to the end: they take their registers first.
  for (std::size_t j = 0; j < src.outputs.size(); ++j) {
    const std::uint32_t v = alias[src.outputs[j]];
    out->outputs[j] = regs.use(v);
    out->outputs[src.outputs.size() + j] = v;
  }
  Clause* const reg_out = reg_out_.data();
  Clause* const ssa_out = ssa_out_.data();
  std::size_t w = n;  // reg_out[w, n) and ssa_out[w, n) are the kept clauses
  bool has_choices = false, plain = true;
  for (std::size_t i = n; i-- > 0;) {
    const std::uint32_t id = src.ssa[i].out;
    alias[id] = id;                 // all its uses are behind us
    if (!regs.live(id)) continue;  // dead (or forwarded to an operand)
    --w;
    // Both forms are written in place: a Clause built in registers and copied out whole
    // would be stored field by field and loaded back at once (a store-forwarding stall).
    Clause& ssa = ssa_out[w] = src.ssa[i];
    if (outcome(ssa, choices[i]) == kToImmediate) ssa = Clause{Op::Const, {}, id, ssa.b, 0, 0};
    Clause& reg = reg_out[w] = ssa;
    reg.out = regs.release(id);
    if (ssa.op >= Op::Call) [[unlikely]] {
      keep_call_or_out(src, ssa, w, regs, reg);
    } else {
      const int ar = kArity[static_cast<std::size_t>(ssa.op)];
      if (ar >= 1) reg.a = regs.use(ssa.a = alias[ssa.a]);
      if (ar >= 2) reg.b = regs.use(ssa.b = alias[ssa.b]);
      if (ar >= 3) reg.c = regs.use(ssa.c = alias[ssa.c]);
    }
    has_choices = has_choices || has_choice(ssa.op);
    plain = plain && kPlain[static_cast<std::size_t>(ssa.op)];
  }

  out->clauses.reserve(2 * (n - w));
  out->clauses.insert(out->clauses.end(), reg_out + w, reg_out + n);
  out->clauses.insert(out->clauses.end(), ssa_out + w, ssa_out + n);
  if (!calls_.empty()) finish_calls(src, w, *out);
  out->num_registers = std::max<std::uint32_t>(regs.count(), 1);
  out->has_choices = has_choices;
  out->plain = plain;
  clean_ = true;
  return out;
}

// Call and CallOut clauses (rare): a call has no register and uses its arguments; an output
// keeps its call (an ordering dependency).
void TapeSimplifier::Impl::keep_call_or_out(const Source& src, const Clause& c, std::size_t position, Registers& regs,
                                            Clause& reg) {
  if (c.op == Op::CallOut) {
    regs.keep_call(c.b);
    return;
  }
  reg.out = 0;
  const CallSite& cs = src.calls[c.a];
  calls_.push_back({static_cast<std::uint32_t>(position), c.a, static_cast<std::uint32_t>(call_regs_.size())});
  for (std::uint32_t k = 0; k < cs.num_args; ++k) {
    const std::uint32_t v = alias_[src.call_args[cs.first_arg + k]];
    call_regs_.push_back(regs.use(v));
    call_values_.push_back(v);
  }
}

// Numbers the kept calls in tape order and points their clauses at them; `first` is where
// the kept clauses start in reg_out_.
void TapeSimplifier::Impl::finish_calls(const Source& src, std::size_t first, TapeData& out) {
  const std::size_t m = out.size();
  std::vector<std::uint32_t> regs, values;
  for (std::size_t j = calls_.size(); j-- > 0;) {
    const EmittedCall& e = calls_[j];
    CallSite cs = src.calls[e.call];
    cs.first_arg = static_cast<std::uint32_t>(regs.size());
    regs.insert(regs.end(), call_regs_.begin() + e.first_arg, call_regs_.begin() + e.first_arg + cs.num_args);
    values.insert(values.end(), call_values_.begin() + e.first_arg, call_values_.begin() + e.first_arg + cs.num_args);
    const auto index = static_cast<std::uint32_t>(out.calls.size());
    out.calls.push_back(cs);
    out.clauses[e.position - first].a = index;
    out.clauses[m + e.position - first].a = index;
  }
  out.call_args = std::move(regs);
  out.call_args.insert(out.call_args.end(), values.begin(), values.end());
}

namespace {

// The compiler's output: SSA clauses (clause i defines value i) before register allocation.
struct CompiledSsa {
  std::vector<Clause> ssa;
  std::vector<std::uint32_t> outputs;
  std::vector<CallSite> calls;
  std::vector<std::uint32_t> call_args;
  std::uint32_t num_slots = 0;
};

// DAG -> SSA clauses.
class Compiler {
 public:
  Compiler(CompiledSsa& d, std::span<const int> inputs) : d_(d) {
    for (std::size_t k = 0; k < inputs.size(); ++k) position_[inputs[k]] = static_cast<std::uint32_t>(k);
  }

  void compile(const Fn& f) {
    for (NodeId id : dag::topological_order(f.nodes())) {
      const Node& n = dag::node(id);
      if (n.op != Op::Const) emit_node(id, n);  // constants are emitted only where a register needs them
    }
    for (NodeId id : f.nodes()) d_.outputs.push_back(value(id));
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
      cs.first_arg = static_cast<std::uint32_t>(d_.call_args.size());
      cs.num_args = static_cast<std::uint32_t>(args.size());
      for (NodeId a : args) d_.call_args.push_back(value(a));
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

  CompiledSsa& d_;
  std::unordered_map<int, std::uint32_t> position_;
  std::unordered_map<NodeId, std::uint32_t> ssa_of_;
  std::map<double, std::uint32_t> const_index_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> call_of_;

 public:
  std::vector<double> constants_;
  std::vector<std::shared_ptr<const CustomOp>> ops_;
};

}  // namespace

std::shared_ptr<const TapeData> Tape::compile(const Fn& f, std::span<const int> inputs) {
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    if (inputs[k] < 0 || inputs[k] >= kMaxInputs)
      throw std::invalid_argument("genmod: Tape: input coordinate " + std::to_string(inputs[k]) + " is out of range");
    for (std::size_t j = 0; j < k; ++j)
      if (inputs[j] == inputs[k])
        throw std::invalid_argument("genmod: Tape: input coordinate " + std::to_string(inputs[k]) + " is listed twice");
  }
  CompiledSsa ssa;
  Compiler compiler(ssa, inputs);
  compiler.compile(f);
  auto common = std::make_shared<TapeCommon>();
  common->constants = std::move(compiler.constants_);
  common->inputs.assign(inputs.begin(), inputs.end());
  common->ops = std::move(compiler.ops_);
  common->num_values = static_cast<std::uint32_t>(ssa.ssa.size());
  common->num_slots = ssa.num_slots;
  // Register allocation is a rebuild with no choice made.
  const std::vector<std::uint8_t> no_choices(ssa.ssa.size(), kChoiceBoth);
  return TapeSimplifier::Impl().rebuild({ssa.ssa, ssa.outputs, ssa.calls, ssa.call_args, std::move(common)}, no_choices);
}

Tape::Tape(const Fn& f) : data_(compile(f, f.inputs())) {}
Tape::Tape(const Fn& f, Coordinates inputs) : data_(compile(f, inputs)) {}

namespace detail {
const TapeData& tape_data(const Tape& tape) noexcept { return *tape.data_; }
}  // namespace detail

std::span<const double> Tape::constants() const noexcept { return data_->common->constants; }
std::span<const int> Tape::inputs() const noexcept { return data_->common->inputs; }
std::size_t Tape::num_outputs() const noexcept { return data_->reg_outputs().size(); }
std::size_t Tape::size() const noexcept { return data_->size(); }
std::uint32_t Tape::num_registers() const noexcept { return data_->num_registers; }
std::size_t Tape::count(Op op) const noexcept {
  const auto reg = data_->reg();
  return static_cast<std::size_t>(std::count_if(reg.begin(), reg.end(), [op](const Clause& c) { return c.op == op; }));
}
std::size_t Tape::memory_bytes() const noexcept {
  return sizeof(TapeData) + data_->clauses.size() * sizeof(Clause) + data_->outputs.size() * sizeof(std::uint32_t) +
         data_->calls.size() * sizeof(CallSite) + data_->call_args.size() * sizeof(std::uint32_t);
}
bool Tape::has_choices() const noexcept { return data_->has_choices; }

Tape Tape::simplify(std::span<const std::uint8_t> choices) const {
  TapeSimplifier scratch;
  return simplify(choices, scratch);
}

Tape Tape::simplify(std::span<const std::uint8_t> choices, TapeSimplifier& scratch) const {
  const Data& d = *data_;
  if (choices.size() != d.size())
    throw std::invalid_argument("genmod: Tape::simplify: " + std::to_string(choices.size()) + " choices for " +
                                std::to_string(d.size()) + " clauses");
  if (!d.has_choices) return *this;
  const TapeSimplifier::Impl::Source src{d.ssa(), d.ssa_outputs(), d.calls, d.ssa_call_args(), d.common};
  TapeSimplifier::Impl& impl = *scratch.impl_;
  impl.prepare(d.common->num_values, d.size());
  if (!impl.note_aliases(src, choices)) return *this;  // nothing is one-sided: nothing changes
  return Tape(impl.rebuild(src, choices));
}

std::string Tape::disassemble() const {
  std::ostringstream os;
  const auto k = constants();
  for (const Clause& c : data_->reg()) {
    os << 'r' << c.out << " = " << op_name(c.op);
    switch (c.op) {
      case Op::Const: os << ' ' << k[c.a]; break;
      case Op::Load: os << " input" << c.a; break;
      case Op::Call: os << " #" << c.a << " (" << data_->calls[c.a].op->name() << ')'; break;
      case Op::CallOut: os << " slot" << c.a; break;
      default: {
        const int ar = arity(c.op);
        if (ar >= 1) os << " r" << c.a;
        if (has_immediate(c.op)) os << ' ' << k[c.b];
        else if (ar >= 2) os << " r" << c.b;
        if (ar >= 3) os << " r" << c.c;
      }
    }
    os << '\n';
  }
  os << "outputs:";
  for (std::uint32_t r : data_->reg_outputs()) os << " r" << r;
  os << '\n';
  return os.str();
}

}  // namespace genmod
