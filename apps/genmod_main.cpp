// genmod: the command-line program. Each subcommand is a row of the command table.
#include "commands.hpp"

#include <array>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace genmod::app {
namespace {

constexpr std::array<const Command*, 7> kCommands{&kRenderCommand,  &kInfoCommand,  &kListCommand, &kMeshCommand,
                                                  &kPreviewCommand, &kCheckCommand, &kBatchCommand};

bool is_help(const std::string& s) { return s == "--help" || s == "-h" || s == "help"; }

void print_help() {
  std::printf("usage: genmod COMMAND [ARGS...]\n\ncommands:\n");
  for (const Command* c : kCommands)
    std::printf("  %-8.*s %.*s\n", static_cast<int>(c->name.size()), c->name.data(),
                static_cast<int>(c->summary.size()), c->summary.data());
  std::printf("\n`genmod COMMAND --help` describes a command's arguments.\n");
}

void print_command_help(const Command& c) {
  std::printf("usage: genmod %.*s %.*s\n%.*s\n%.*s", static_cast<int>(c.name.size()), c.name.data(),
              static_cast<int>(c.usage.size()), c.usage.data(), static_cast<int>(c.summary.size()), c.summary.data(),
              static_cast<int>(c.details.size()), c.details.data());
}

const Command* find_command(const std::string& name) {
  for (const Command* c : kCommands)
    if (c->name == name) return c;
  return nullptr;
}

int run(const std::vector<std::string>& args) {
  if (args.empty()) {
    print_help();
    return 2;
  }
  if (is_help(args[0])) {
    print_help();
    return 0;
  }
  const Command* command = find_command(args[0]);
  if (command == nullptr) throw UsageError("unknown command '" + args[0] + "' (try `genmod --help`)");
  const std::span<const std::string> rest(args.begin() + 1, args.end());
  if (!rest.empty() && is_help(rest[0])) {
    print_command_help(*command);
    return 0;
  }
  try {
    return command->run(rest);
  } catch (const UsageError& e) {
    throw UsageError(std::string(e.what()) + "\nusage: genmod " + std::string(command->name) + " " +
                     std::string(command->usage));
  }
}

}  // namespace
}  // namespace genmod::app

int main(int argc, char** argv) {
  try {
    return genmod::app::run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const genmod::app::UsageError& e) {
    std::fprintf(stderr, "genmod: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
