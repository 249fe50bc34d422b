#include "genmod/kernel/vm_format.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/number_text.hpp"

#include "dag.hpp"

#include <cstdlib>
#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <locale>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace genmod {
namespace {

// Opcode spelling in files; vm-specific aliases first.
Op parse_op(const std::string& word, bool* found) {
  *found = true;
  if (word == "ln") return Op::Log;
  for (int i = static_cast<int>(Op::Neg); i <= static_cast<int>(Op::Select); ++i) {
    const Op op = static_cast<Op>(i);
    if (op_name(op) == word) return op;
  }
  *found = false;
  return Op::Const;
}

// 'word', with control bytes escaped (built by appending: GCC 12 warns falsely about
// const char* + std::string&&).
std::string quoted(std::string_view word) {
  std::string s(1, '\'');
  s += printable(word);
  s += '\'';
  return s;
}

std::string vm_name(Op op) { return op == Op::Log ? "ln" : std::string(op_name(op)); }

}  // namespace

VmFormatError::VmFormatError(const std::string& source, int line, const std::string& problem)
    : std::runtime_error(source + ":" + std::to_string(line) + ": " + problem), line_(line) {}

namespace {

Fn read_lines(LineReader& reader, const std::string& source_name) {
  dag::Refs refs;  // owns the nodes made here until the result holds what it needs
  std::unordered_map<std::string, NodeId> names;
  NodeId last = kNoNode;
  std::string text;
  int line_no = 0;
  for (;;) {
    try {
      if (!reader.next(text)) break;
    } catch (const TextReadError& e) {
      throw VmFormatError(source_name, e.line(), e.what());
    }
    line_no = reader.line_number();
    if (const auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream words(text);
    std::vector<std::string> w;
    for (std::string s; words >> s;) w.push_back(s);
    if (w.empty()) continue;
    auto fail = [&](const std::string& problem) { throw VmFormatError(source_name, line_no, problem); };
    if (w.size() < 2) fail("expected 'NAME OPCODE ARGS...', got " + quoted(w[0]));
    if (names.count(w[0])) fail(quoted(w[0]) + " is defined twice");
    const std::string& opword = w[1];
    const std::size_t nargs = w.size() - 2;
    auto want = [&](std::size_t n) {
      if (nargs != n)
        fail("'" + opword + "' takes " + std::to_string(n) + " operand(s), got " + std::to_string(nargs));
    };
    auto operand = [&](std::size_t k) {
      auto it = names.find(w[2 + k]);
      if (it == names.end()) fail("operand " + quoted(w[2 + k]) + " is not defined above");
      return it->second;
    };
    NodeId id;
    if (opword == "const") {
      want(1);
      const std::optional<double> v = parse_double(w[2]);
      if (!v) fail(quoted(w[2]) + " is not a number (or is out of double's range)");
      id = refs.own(dag::constant(*v));
    } else if (opword.rfind("var-", 0) == 0) {
      want(0);
      const std::string axis = opword.substr(4);
      int index;
      if (axis == "x") index = 0;
      else if (axis == "y") index = 1;
      else if (axis == "z") index = 2;
      else {
        char* end = nullptr;
        const long v = std::strtol(axis.c_str(), &end, 10);
        if (axis.empty() || *end != '\0' || v < 0 || v >= kMaxInputs)
          fail(quoted(opword) + " is not a coordinate (var-x, var-y, var-z or var-N with N < " +
               std::to_string(kMaxInputs) + ")");
        index = static_cast<int>(v);
      }
      id = refs.own(dag::var(index));
    } else {
      bool found;
      const Op op = parse_op(opword, &found);
      if (!found) fail("unknown opcode " + quoted(opword));
      const int ar = arity(op);
      want(static_cast<std::size_t>(ar));
      id = refs.own(dag::make(op, operand(0), ar >= 2 ? operand(1) : kNoNode, ar >= 3 ? operand(2) : kNoNode));
    }
    names.emplace(w[0], id);
    last = id;
  }
  if (last == kNoNode) throw VmFormatError(source_name, line_no, "the file defines nothing");
  return Fn::of(last);
}

}  // namespace

Fn read_vm(std::istream& in, const std::string& source_name, const VmReadLimits& limits) {
  LineReader reader(in, limits);
  return read_lines(reader, source_name);
}

Fn load_vm(const std::string& path, const VmReadLimits& limits) {
  // stdio tells a read error (a directory, a failing disk) from the end of the file; a file
  // stream would report both as the end.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw std::runtime_error("genmod: cannot open '" + path + "': " + std::strerror(errno));
  LineReader reader(file.get(), limits);
  return read_lines(reader, path);
}

void write_vm(std::ostream& out, const Fn& f) {
  if (f.dim() != 1)
    throw std::invalid_argument("genmod: write_vm: the .vm format holds a scalar function, got dimension " +
                                std::to_string(f.dim()));
  std::unordered_map<NodeId, std::string> name;
  std::ostringstream os;
  os.imbue(std::locale::classic());  // names and indices; numbers go through format_double
  for (NodeId id : dag::topological_order(f.nodes())) {
    const Node& n = dag::node(id);
    std::ostringstream label;
    label << '_' << std::hex << name.size();
    const std::string me = label.str();
    os << me << ' ';
    switch (n.op) {
      case Op::Const: os << "const " << format_double(n.value); break;
      case Op::Var:
        if (n.index < 3) os << "var-" << "xyz"[n.index];
        else os << "var-" << n.index;
        break;
      case Op::Custom:
        throw std::invalid_argument("genmod: write_vm: custom operator '" + dag::custom(n.custom).name() +
                                    "' has no .vm form");
      default:
        os << vm_name(n.op);
        for (int k = 0; k < arity(n.op); ++k) os << ' ' << name.at(n.arg[k]);
    }
    os << '\n';
    name.emplace(id, me);
  }
  out << os.str();
}

void save_vm(const std::string& path, const Fn& f) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("genmod: cannot write '" + path + "'");
  write_vm(out, f);
  if (!out) throw std::runtime_error("genmod: error writing '" + path + "'");
}

}  // namespace genmod
