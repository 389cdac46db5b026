// cetview: one executable, one subcommand per job (DESIGN.md "Command line"). The only file that
// includes CLI11: the commands describe themselves (commands.h) and are turned into CLI11 options here.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "commands.h"

namespace {

void addCommand(CLI::App& app, const cetview::Command& command, int& exitCode) {
  CLI::App* sub = app.add_subcommand(command.name, command.description);
  for (const cetview::CommandOption& option : command.options) {
    CLI::Option* added = std::visit(
        [&](auto* target) -> CLI::Option* {
          if constexpr (std::is_same_v<decltype(target), bool*>)
            return sub->add_flag(option.names, *target, option.help);
          else
            return sub->add_option(option.names, *target, option.help);
        },
        option.target);
    if (option.required) added->required();
    if (option.showDefault) added->capture_default_str();
  }
  sub->callback([&command, &exitCode] { exitCode = command.run(); });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cetview: progressive Vulkan viewer for B-rep CAD models (STEP, IGES, .brep)", "cetview"};
  app.set_version_flag("--version", std::string("cetview ") + CETVIEW_VERSION);
  app.require_subcommand(1);
  // Usage errors are one line, like every other error of cetview.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("cetview: ") + e.what() + " (see cetview --help)\n";
  });
  int exitCode = 0;
  const std::vector<cetview::Command> commands = {cetview::cdtCommand(), cetview::exportCommand(),
                                                  cetview::benchCommand(), cetview::renderCommand(),
                                                  cetview::viewCommand()};
  for (const cetview::Command& command : commands) addCommand(app, command, exitCode);
  // `view` is the default: `cetview`, `cetview MODEL` and `cetview --frames 5 ...` open the window.
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool help = !args.empty() && (args[0] == "-h" || args[0] == "--help" || args[0] == "--version");
  bool known = false;
  if (!args.empty()) {
    for (const cetview::Command& command : commands) known = known || args[0] == command.name;
  }
  if (!help && !known) args.insert(args.begin(), "view");
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments reversed
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  return exitCode;
}
