// Runs a command line as a user would (through the shell) for tests of the cetview executable:
// its exit code, its stdout, and optionally its stderr.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

namespace cetview::test {

struct CommandResult {
  int exitCode = -1;  // -1 when it did not exit normally
  std::string out;
  std::string err;    // only when an errPath was given
};

// Runs `command`; with a non-empty `errPath`, stderr goes to that file and is read back.
inline CommandResult runCommand(const std::string& command, const std::string& errPath = {}) {
  const std::string cmd = errPath.empty() ? command : command + " 2>" + errPath;
  CommandResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) r.out += buffer.data();
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (!errPath.empty()) {
    std::ifstream err(errPath);
    r.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  }
  return r;
}

}  // namespace cetview::test
