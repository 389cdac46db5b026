// cetview: one executable, one subcommand per job (DESIGN.md "Command line").
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"cetview: progressive Vulkan viewer for B-rep CAD models (STEP, IGES, .brep)", "cetview"};
  app.set_version_flag("--version", std::string("cetview ") + CETVIEW_VERSION);
  app.require_subcommand(1);
  // Usage errors are one line, like every other error of cetview.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("cetview: ") + e.what() + " (see cetview --help)\n";
  });
  int exitCode = 0;
  cetview::addCdtCommand(app, exitCode);
  cetview::addExportCommand(app, exitCode);
  cetview::addBenchCommand(app, exitCode);
  cetview::addRenderCommand(app, exitCode);
  cetview::addViewCommand(app, exitCode);
  // `view` is the default: `cetview`, `cetview MODEL` and `cetview --frames 5 ...` open the window.
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool help = !args.empty() && (args[0] == "-h" || args[0] == "--help" || args[0] == "--version");
  bool known = false;
  if (!args.empty()) {
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
      known = known || sub->check_name(args[0]);
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
