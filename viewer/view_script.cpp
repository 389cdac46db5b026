#include "view_script.h"

#include <fstream>
#include <sstream>
#include <utility>

namespace cetview {
namespace {

struct Arity {
  const char* name;
  int min, max;
};
constexpr Arity kCommands[] = {
    {"deflection", 1, 1}, {"angle", 1, 1},   {"view", 1, 1},   {"projection", 1, 1}, {"display", 1, 1},
    {"colors", 1, 1},     {"heatmap", 1, 1}, {"fit", 0, 0},    {"panel", 2, 2},      {"orbit", 2, 2},
    {"pan", 2, 2},        {"zoom", 1, 1},    {"wait", 2, 2},   {"screenshot", 1, 1}, {"open", 1, 1},
    {"quit", 0, 0},       {"cancel", 0, 0},  {"browse", 1, 1},
};

}  // namespace

ScriptParse parseScript(const std::string& text, const std::string& fileName) {
  ScriptParse out;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    ScriptCommand cmd;
    cmd.line = number;
    if (!(words >> cmd.name)) continue;
    for (std::string w; words >> w;) cmd.args.push_back(w);
    const Arity* arity = nullptr;
    for (const Arity& a : kCommands) {
      if (cmd.name == a.name) arity = &a;
    }
    const std::string where = fileName + ":" + std::to_string(number) + ": ";
    if (!arity) {
      out.error = where + "unknown command '" + cmd.name + "'";
      return out;
    }
    const int n = static_cast<int>(cmd.args.size());
    if (n < arity->min || n > arity->max) {
      out.error = where + "'" + cmd.name + "' takes " + std::to_string(arity->min) +
                  (arity->max != arity->min ? " to " + std::to_string(arity->max) : "") +
                  " argument(s), not " + std::to_string(n);
      return out;
    }
    if (cmd.name == "wait" && cmd.args[0] != "level" && cmd.args[0] != "frames" && cmd.args[0] != "seconds") {
      out.error = where + "'wait' needs 'level K|target', 'frames N' or 'seconds S'";
      return out;
    }
    out.commands.push_back(std::move(cmd));
  }
  return out;
}

ScriptParse loadScript(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    ScriptParse out;
    out.error = "cannot read script '" + path + "'";
    return out;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parseScript(buffer.str(), path);
}

}  // namespace cetview
