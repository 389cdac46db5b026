// `cetview cdt` as a user runs it: exit codes, one-line errors, output files, --json.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "run_command.h"

namespace {

using CliResult = cetview::test::CommandResult;

// stderr goes to a file of the running test's own: ctest runs these tests as parallel processes,
// and one shared file let a test read another's (empty) stderr.
CliResult run(const std::string& args) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return cetview::test::runCommand(std::string(CETVIEW_EXE) + " " + args,
                                   ::testing::TempDir() + "/cdt_cli_" + test + ".err");
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(CdtCli, TriangulatesAndPrintsJson) {
  const std::string in = write("ok.poly", "4 2 0 0\n1 0 0\n2 2 0\n3 2 2\n4 0 2\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  const std::string out = ::testing::TempDir() + "/ok_out";
  const CliResult r = run("cdt " + in + " -o " + out + " --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find("{\""), 0u);
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << "exactly one line";
  for (const char* key : {"\"points\":4", "\"segments\":4", "\"triangles\":2", "\"ms\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  std::ifstream ele(out + ".ele");
  std::string header;
  std::getline(ele, header);
  EXPECT_EQ(header, "2 3 0");
}

TEST(CdtCli, BadInputExitsTwoWithOneLine) {
  const std::string cases[] = {
      write("range.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n0\n"),
      write("nan.poly", "3 2 0 0\n1 0 0\n2 nan 0\n3 0 1\n0 0\n0\n"),
      write("cross.poly", "4 2 0 0\n1 0 0\n2 2 2\n3 0 2\n4 2 0\n2 0\n1 1 2\n2 3 4\n0\n"),
      write("junk.poly", std::string("\x7f" "ELF\0\1\2", 7)),
      ::testing::TempDir() + "/missing.poly",
  };
  for (const std::string& in : cases) {
    const CliResult r = run("cdt " + in + " -o " + ::testing::TempDir() + "/bad_out");
    EXPECT_EQ(r.exitCode, 2) << in;
    EXPECT_FALSE(r.err.empty()) << in;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
}

TEST(CdtCli, CollinearInputGivesEmptyResult) {
  const std::string in = write("line.poly", "3 2 0 0\n0 0 0\n1 1 1\n2 2 2\n0 0\n0\n");
  const CliResult r = run("cdt " + in + " -o " + ::testing::TempDir() + "/line_out --json");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"triangles\":0"), std::string::npos) << r.out;
}

TEST(CdtCli, HelpAndVersion) {
  EXPECT_EQ(run("--version").exitCode, 0);
  EXPECT_NE(run("--version").out.find("cetview"), std::string::npos);
  EXPECT_EQ(run("--help").exitCode, 0);
  EXPECT_EQ(run("cdt").exitCode, 2);  // missing input
}

}  // namespace
