// The File > Open dialog's listing (file_browser.h): model files by extension in any case,
// folders first, hidden entries left out, a folder that cannot be listed gives one error line.
#include "file_browser.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace cetview::test {
namespace {

namespace fs = std::filesystem;

TEST(FileBrowser, RecognisesModelFileNames) {
  for (const char* name : {"part.step", "PART.STP", "a.b.iges", "x.IGS", "shape.brep", "s.Brp"})
    EXPECT_TRUE(isModelFileName(name)) << name;
  for (const char* name : {"notes.txt", "step", ".step", "part.step.bak", "part.", "stp"})
    EXPECT_FALSE(isModelFileName(name)) << name;
}

TEST(FileBrowser, ListsFoldersFirstThenModelFilesByName) {
  const fs::path dir = fs::temp_directory_path() / ("cetview_browse_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  fs::create_directories(dir / ".git");
  for (const char* name : {"b.step", "A.STP", "notes.txt", ".hidden.step", "c.brep"})
    std::ofstream(dir / name) << "0123456789";
  const BrowserListing listing = listModelDirectory((dir / "sub" / "..").string());
  EXPECT_TRUE(listing.error.empty()) << listing.error;
  EXPECT_EQ(listing.directory, dir.string());
  std::vector<std::string> names;
  for (const BrowserEntry& e : listing.entries) names.push_back(e.name + (e.directory ? "/" : ""));
  EXPECT_EQ(names, (std::vector<std::string>{"sub/", "A.STP", "b.step", "c.brep"}));
  EXPECT_EQ(listing.entries[1].bytes, 10u);
  fs::remove_all(dir);
}

TEST(FileBrowser, AFolderThatCannotBeListedGivesOneErrorLine) {
  const BrowserListing listing = listModelDirectory("/nonexistent/models");
  EXPECT_TRUE(listing.entries.empty());
  EXPECT_EQ(listing.error.rfind("/nonexistent/models: ", 0), 0u) << listing.error;
  EXPECT_EQ(listing.error.find('\n'), std::string::npos);
}

TEST(FileBrowser, SizesReadAsPeopleWriteThem) {
  EXPECT_EQ(humanBytes(80), "80 B");
  EXPECT_EQ(humanBytes(512 * 1024), "512 KB");
  EXPECT_EQ(humanBytes(3 * 1024 * 1024 + 300 * 1024), "3.3 MB");
}

}  // namespace
}  // namespace cetview::test
