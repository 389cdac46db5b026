// The bad-input corpus (cases.txt): every case through the cetview executable, with its expected
// exit code and message, under a time bound. Never a crash, never a hang, one line per error.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace cetview {
namespace {

constexpr int kTimeBoundSeconds = 120;  // generous for sanitizer builds; a hang is far longer

struct Case {
  std::string name;
  int exitCode = 0;
  std::string message;
  std::string arguments;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
}

std::vector<Case> readCases() {
  std::vector<Case> cases;
  std::ifstream in(CETVIEW_HARDENING_DIR "/cases.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, '|');) fields.push_back(trim(f));
    if (fields.size() != 4) {
      ADD_FAILURE() << "cases.txt: not 4 fields: " << line;
      continue;
    }
    cases.push_back({fields[0], std::stoi(fields[1]), fields[2], fields[3]});
  }
  return cases;
}

std::size_t lineCount(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n' ? 1 : 0;
  return n + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

// The output file a successful case wrote: {out} with the extension its arguments give.
std::string writtenOutput(const std::string& arguments, const std::string& out) {
  const auto at = arguments.find("{out}");
  std::string path = out;
  for (std::size_t i = at + 5; i < arguments.size() && arguments[i] != ' '; ++i) path += arguments[i];
  return path;
}

TEST(BadInput, EveryCaseEndsAsExpected) {
  const std::vector<Case> cases = readCases();
  ASSERT_GE(cases.size(), 30u) << "cases.txt was not read";
  const std::string dir = CETVIEW_TEST_OUTPUT_DIR;
  ::mkdir(dir.c_str(), 0755);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name + ": cetview " + c.arguments);
    const std::string out = dir + "/" + c.name;
    std::string arguments = c.arguments;
    replaceAll(arguments, "{corpus}", CETVIEW_HARDENING_DIR "/corpus");
    replaceAll(arguments, "{out}", out);
    const std::string output = writtenOutput(c.arguments, out);
    std::remove(output.c_str());
    const test::CommandResult r = test::runCommand(
        "timeout " + std::to_string(kTimeBoundSeconds) + " " CETVIEW_EXE " " + arguments, out + ".stderr");
    ASSERT_NE(r.exitCode, 124) << "did not finish within " << kTimeBoundSeconds << " s (a hang)";
    ASSERT_EQ(r.exitCode, c.exitCode) << "stderr: " << r.err;
    if (c.exitCode != 0) {
      EXPECT_EQ(lineCount(r.err), 1u) << "an error is one line; stderr: " << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << "stderr: " << r.err;
      continue;
    }
    if (c.message.empty()) {
      EXPECT_TRUE(r.err.empty()) << "stderr: " << r.err;
    } else {
      EXPECT_NE(r.err.find(c.message), std::string::npos) << "stderr: " << r.err;
    }
    struct stat st {};
    EXPECT_EQ(::stat(output.c_str(), &st), 0) << output << " was not written";
    EXPECT_GT(st.st_size, 0) << output << " is empty";
  }
}

}  // namespace
}  // namespace cetview
