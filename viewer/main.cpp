// cetview: one executable, one subcommand per job (DESIGN.md "Command line").
#include <cstdio>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"cetview: progressive Vulkan viewer for B-rep CAD models (STEP, IGES, .brep)", "cetview"};
  app.set_version_flag("--version", std::string("cetview ") + CETVIEW_VERSION);
  app.require_subcommand(1);
  int exitCode = 0;
  cetview::addCdtCommand(app, exitCode);
  cetview::addExportCommand(app, exitCode);
  cetview::addBenchCommand(app, exitCode);
  cetview::addRenderCommand(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  return exitCode;
}
