// The cetview subcommands. Each adds itself to the CLI11 app; its callback sets exitCode:
// 0 success, 1 a runtime failure, 2 bad input or usage.
#pragma once

#include <CLI/CLI.hpp>

namespace cetview {

void addCdtCommand(CLI::App& app, int& exitCode);
void addExportCommand(CLI::App& app, int& exitCode);
void addBenchCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addViewCommand(CLI::App& app, int& exitCode);

}  // namespace cetview
