// `cetview view` in a real window: each test runs the executable under xvfb-run (its own X server,
// lavapipe or any Vulkan device) with the validation layer on (--validate: any report fails the
// run), drives it by --script, and checks the --screenshot by pixel: the model is drawn over the
// background gradient and ImGui's panels are where the viewer puts them. Skipped without xvfb-run.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "engine/image.h"
#include "support/on_path.h"

namespace cetview::test {
namespace {

std::string outputPath(const std::string& name) {
  mkdir(CETVIEW_TEST_OUTPUT_DIR, 0755);
  return std::string(CETVIEW_TEST_OUTPUT_DIR) + "/" + name;
}

std::string writeScript(const std::string& name, const std::string& text) {
  const std::string path = outputPath(name);
  std::ofstream(path) << text;
  return path;
}

// Runs `cetview ARGS` in a fresh X server; returns the exit code, with stdout+stderr in `log`, or
// with `err` given, stdout in `log` and stderr in `*err`. `env` ("NAME=value ...") prefixes the run.
int runViewer(const std::string& args, std::string& log, std::string* err = nullptr,
              const std::string& env = {}) {
  const std::string logPath =
      outputPath(std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".log");
  const std::string errPath = logPath + ".err";
  // cetview's own exit code goes to a file: xvfb-run's (5 when it cannot clean up its temporary
  // directory, which happened once under load after cetview had exited) would hide it.
  const std::string codePath = logPath + ".code";
  const std::string command = env + " xvfb-run -a -s '-screen 0 1024x768x24' sh -c '" +
                              std::string(CETVIEW_EXE) + " " + args + "; echo $? > " + codePath + "' > " +
                              logPath + (err ? " 2>" + errPath : " 2>&1");
  int code = -1;
  // xvfb-run -a can race another test's server for a display number: try again then.
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::remove(codePath.c_str());
    const int status = std::system(command.c_str());
    std::ifstream in(logPath);
    log.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    std::string errors;
    if (err) {
      std::ifstream errIn(errPath);
      err->assign(std::istreambuf_iterator<char>(errIn), std::istreambuf_iterator<char>());
      errors = *err;
    }
    code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream codeIn(codePath);
    const bool ran = static_cast<bool>(codeIn >> code);  // cetview ran to its end
    const std::string all = log + errors;
    if (ran || (all.find("xvfb-run: error") == std::string::npos &&
                all.find("Server is already active") == std::string::npos))
      break;
  }
  return code;
}

// Runs `cetview ARGS --screenshot OUTPUT/NAME` (a stale picture removed first): the exit code goes
// to `code`, the output to `log`; returns the picture read back (an error when there is none).
engine::Result<engine::RgbaImage> runForScreenshot(const std::string& args, const std::string& name,
                                                   std::string& log, int& code) {
  const std::string shot = outputPath(name);
  std::remove(shot.c_str());
  code = runViewer(args + " --screenshot " + shot, log);
  return engine::readPng(shot);
}

// The occt-misc sample at `relative` under its data folder, or empty when it is not installed.
std::string occData(const std::string& relative) {
  const std::string path = std::string(CETVIEW_OCC_DATA) + "/" + relative;
  return access(path.c_str(), R_OK) == 0 ? path : std::string();
}

struct Pixel {
  int r, g, b;
};
Pixel at(const engine::RgbaImage& image, std::uint32_t x, std::uint32_t y) {
  const std::uint8_t* p = &image.pixels[(std::size_t{y} * image.width + x) * 4];
  return {p[0], p[1], p[2]};
}
int difference(Pixel a, Pixel b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

// ImGui's dark theme: panel bodies and the menu bar are near black over the light background.
bool imguiDark(Pixel p) {
  return p.r < 70 && p.g < 70 && p.b < 80;
}

// Fraction of the centre region (between the side panels) whose pixels differ from the background
// gradient; the gradient is vertical, so column x = width - 3 (right of every panel) is the
// background of each row.
double modelCoverage(const engine::RgbaImage& image, int* coloured = nullptr) {
  std::size_t differ = 0, total = 0;
  if (coloured) *coloured = 0;
  for (std::uint32_t y = 60; y < image.height - 60; y += 2) {
    const Pixel background = at(image, image.width - 3, y);
    for (std::uint32_t x = 330; x < image.width - 330; x += 2) {
      const Pixel p = at(image, x, y);
      ++total;
      if (difference(p, background) > 24) ++differ;
      if (coloured && std::abs(p.r - p.b) > 60) ++*coloured;
    }
  }
  return static_cast<double>(differ) / static_cast<double>(total);
}

// A number from the viewer's closing JSON line: {"frames":..,"target_level":..,...}.
long long jsonNumber(const std::string& log, const std::string& key) {
  const std::size_t at = log.rfind("\"" + key + "\":");
  if (at == std::string::npos) return -1;
  return std::atoll(log.c_str() + at + key.size() + 3);
}

// After `wait level target`, every face shows the target level: the triangles shown are the level's.
void expectWholeLevelShown(const std::string& log) {
  EXPECT_GE(jsonNumber(log, "complete_level"), jsonNumber(log, "target_level")) << log;
  EXPECT_GT(jsonNumber(log, "level_triangles"), 0) << log;
  EXPECT_EQ(jsonNumber(log, "shown_triangles"), jsonNumber(log, "level_triangles")) << log;
}

class ViewerWindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb, xauth)";
  }
};

TEST_F(ViewerWindowTest, DemoWithPanelsSliderMovesAndIsValidationClean) {
  const std::string script = writeScript("demo.script",
                                         "wait level target\n"
                                         "deflection 0.5%\n"
                                         "wait level target\n"
                                         "deflection 0.05%\n"
                                         "wait level target\n"
                                         "quit\n");
  std::string log;
  int rc = -1;
  auto image =
      runForScreenshot("view demo --size 960x600 --validate --frames 3000 --threads 2 --script " + script,
                       "demo.png", log, rc);
  ASSERT_EQ(rc, 0) << log;
  expectWholeLevelShown(log);
  EXPECT_EQ(jsonNumber(log, "target_level"), 5) << log;  // 0.05% of the demo's diagonal
  ASSERT_TRUE(image.ok()) << image.error().message;
  ASSERT_EQ(image->width, 960u);
  ASSERT_EQ(image->height, 600u);
  EXPECT_GT(modelCoverage(*image), 0.15);
  // Menu bar, Tessellation panel (left), Display panel (right), Stats panel (bottom left).
  EXPECT_TRUE(imguiDark(at(*image, 500, 8)));
  EXPECT_TRUE(imguiDark(at(*image, 250, 190)));
  EXPECT_TRUE(imguiDark(at(*image, 920, 215)));
  EXPECT_TRUE(imguiDark(at(*image, 250, 585)));
  // The background's light gradient where no panel is.
  const Pixel corner = at(*image, 957, 590);
  EXPECT_GT(corner.r + corner.g + corner.b, 3 * 120);
}

TEST_F(ViewerWindowTest, OccModelHeatMapViewsAndPanelToggle) {
  const std::string model = occData("occ/bottle.brep");
  if (model.empty()) GTEST_SKIP() << "occ/bottle.brep is missing (Debian: occt-misc)";
  const std::string script = writeScript("bottle.script",
                                         "wait level target\n"
                                         "deflection 0.3%\n"
                                         "heatmap on\n"
                                         "wait level target\n"
                                         "view front\n"
                                         "orbit 30 -20\n"
                                         "display shaded\n"
                                         "projection orthographic\n"
                                         "panel progress off\n"
                                         "wait frames 2\n"
                                         "quit\n");
  std::string log;
  int rc = -1;
  auto image =
      runForScreenshot(model + " --size 960x600 --validate --frames 3000 --threads 2 --script " + script,
                       "bottle.png", log, rc);  // no `view`: the default subcommand
  ASSERT_EQ(rc, 0) << log;
  expectWholeLevelShown(log);
  ASSERT_TRUE(image.ok()) << image.error().message;
  int coloured = 0;
  EXPECT_GT(modelCoverage(*image, &coloured), 0.15);
  EXPECT_GT(coloured, 1000);                      // heat-map colours, not the file's grey
  EXPECT_TRUE(imguiDark(at(*image, 250, 190)));   // Tessellation panel
  EXPECT_FALSE(imguiDark(at(*image, 150, 300)));  // where the Progress panel was
}

TEST_F(ViewerWindowTest, ScriptOpensAnotherModel) {
  const std::string model = occData("occ/Pump_Nut.brep");
  if (model.empty()) GTEST_SKIP() << "occ/Pump_Nut.brep is missing (Debian: occt-misc)";
  const std::string script = writeScript("open.script",
                                         "wait level 0\n"
                                         "open " +
                                             model +
                                             "\n"
                                             "open /nonexistent/model.step\n"  // reported, the viewer goes on
                                             "wait level target\n"
                                             "quit\n");
  std::string log;
  ASSERT_EQ(runViewer("--size 640x400 --frames 3000 --threads 2 --script " + script, log), 0) << log;
  EXPECT_NE(log.find("opened: demo"), std::string::npos) << log;
  EXPECT_NE(log.find("opened: " + model), std::string::npos) << log;
  EXPECT_NE(log.find("/nonexistent/model.step"), std::string::npos) << log;
}

// A file loads on a thread of its own while the window goes on: a load cancelled right after it
// started leaves the current model shown, and the file is never opened.
TEST_F(ViewerWindowTest, ScriptCancelsALoadAndTheCurrentModelStays) {
  const std::string model = occData("occ/Bottom.brep");
  if (model.empty()) GTEST_SKIP() << "occ/Bottom.brep is missing (Debian: occt-misc)";
  const std::string script = writeScript("cancel.script",
                                         "wait level target\n"
                                         "open " +
                                             model +
                                             "\n"
                                             "cancel\n"
                                             "wait frames 2\n"
                                             "wait level target\n"
                                             "quit\n");
  std::string log;
  ASSERT_EQ(runViewer("view demo --size 640x400 --frames 3000 --threads 2 --script " + script, log), 0)
      << log;
  EXPECT_NE(log.find("opened: demo"), std::string::npos) << log;
  EXPECT_NE(log.find("cancelled: " + model), std::string::npos) << log;
  EXPECT_EQ(log.find("opened: " + model), std::string::npos) << log;
  expectWholeLevelShown(log);
}

// The command line's model cancelled before it loaded: the window goes on with no model, and a
// file that then fails to open is reported without ending the run (only the command line's model
// failing does).
TEST_F(ViewerWindowTest, WithTheFirstLoadCancelledTheWindowGoesOnWithoutAModel) {
  const std::string script = writeScript("nomodel.script",
                                         "cancel\n"
                                         "open /nonexistent/model.step\n"
                                         "wait frames 3\n"
                                         "quit\n");
  std::string log;
  ASSERT_EQ(runViewer("view demo --size 640x400 --validate --threads 2 --script " + script, log), 0) << log;
  EXPECT_NE(log.find("cancelled: demo"), std::string::npos) << log;
  EXPECT_NE(log.find("/nonexistent/model.step: no such file"), std::string::npos) << log;
  EXPECT_EQ(log.find("opened:"), std::string::npos) << log;
  EXPECT_NE(log.find("\"model\":null"), std::string::npos) << log;
}

// While a file loads, the window draws the current model and a Loading panel (top centre) with
// the file's progress; quitting then ends the load.
TEST_F(ViewerWindowTest, TheLoadingPanelShowsWhileAFileLoads) {
  const std::string model = occData("occ/Bottom.brep");
  if (model.empty()) GTEST_SKIP() << "occ/Bottom.brep is missing (Debian: occt-misc)";
  const std::string script = writeScript("loading.script",
                                         "panel tessellation off\n"
                                         "panel display off\n"
                                         "wait level target\n"
                                         "open " +
                                             model +
                                             "\n"
                                             "quit\n");  // in the frame the load starts
  std::string log;
  int rc = -1;
  auto image =
      runForScreenshot("view demo --size 960x600 --validate --frames 3000 --threads 2 --script " + script,
                       "loading.png", log, rc);
  ASSERT_EQ(rc, 0) << log;
  EXPECT_EQ(log.find("opened: " + model), std::string::npos) << log;
  ASSERT_TRUE(image.ok()) << image.error().message;
  EXPECT_GT(modelCoverage(*image), 0.1);          // the demo, still shown
  EXPECT_TRUE(imguiDark(at(*image, 600, 110)));   // the Loading panel, top centre, beside its button
  EXPECT_TRUE(imguiDark(at(*image, 680, 56)));    // ... and beside the file's name
  EXPECT_FALSE(imguiDark(at(*image, 480, 200)));  // below it, the scene
}

// File > Open lists a folder's subfolders and model files (the script's `browse` opens the dialog
// as the menu does): the dialog is drawn over the model, the folder's entries in it.
TEST_F(ViewerWindowTest, TheOpenDialogListsAFolder) {
  const std::string folder = occData("occ");
  if (folder.empty()) GTEST_SKIP() << "occ/ is missing (Debian: occt-misc)";
  const std::string script = writeScript("browse.script",
                                         "panel tessellation off\n"
                                         "panel progress off\n"
                                         "panel display off\n"
                                         "panel model off\n"
                                         "panel stats off\n"
                                         "wait level target\n"
                                         "browse " +
                                             folder +
                                             "\n"
                                             "wait frames 3\n"
                                             "quit\n");
  std::string log;
  int rc = -1;
  auto image =
      runForScreenshot("view demo --size 960x600 --validate --frames 3000 --threads 2 --script " + script,
                       "browse.png", log, rc);
  ASSERT_EQ(rc, 0) << log;
  ASSERT_TRUE(image.ok()) << image.error().message;
  // The dialog (620x440, centred) covers the model with ImGui's dark panel (the side panels are
  // off: without the dialog, under a tenth of this region is dark, the model's edge lines).
  int dark = 0, all = 0;
  for (std::uint32_t y = 150; y < 460; y += 2)
    for (std::uint32_t x = 180; x < 780; x += 2, ++all) dark += imguiDark(at(*image, x, y));
  EXPECT_GT(dark, all * 7 / 10) << dark << " of " << all;
  // The listing: light text on more than twelve rows of 17 pixels (the folder has 40 entries).
  int textRows = 0;
  for (std::uint32_t y = 150; y < 460; y += 17) {
    bool text = false;
    for (std::uint32_t x = 186; x < 400 && !text; ++x) {
      const Pixel p = at(*image, x, y + 8);
      text = p.r > 150 && p.g > 150 && p.b > 150;
    }
    textRows += text;
  }
  EXPECT_GT(textRows, 12);
}

// Once the model is shown and nothing moves, the viewer stops drawing (redraw on change): over two
// still seconds it draws a few settling frames, where drawing every pass would draw a hundred or more.
TEST_F(ViewerWindowTest, StillModelIsNotRedrawn) {
  const std::string script = writeScript("still.script",
                                         "wait level target\n"
                                         "wait seconds 2\n"
                                         "quit\n");
  std::string log;
  ASSERT_EQ(runViewer("view demo --size 640x400 --threads 2 --script " + script, log), 0) << log;
  expectWholeLevelShown(log);
  EXPECT_LE(jsonNumber(log, "frames_while_waiting_seconds"), 8) << log;
  EXPECT_GE(jsonNumber(log, "frames_while_waiting_seconds"), 0) << log;
}

// One bad face (a bow-tie wire) is reported by id and reason on the terminal, and the rest of the
// model shows.
TEST_F(ViewerWindowTest, BadFaceIsReportedAndTheRestShows) {
  const std::string script = writeScript("badface.script", "wait level target\nwait frames 2\nquit\n");
  std::string log;
  int rc = -1;
  auto image = runForScreenshot(
      std::string(CETVIEW_HARDENING_CORPUS) +
          "/self_intersecting_wire.brep --size 960x600 --validate --frames 3000 --script " + script,
      "badface.png", log, rc);
  ASSERT_EQ(rc, 0) << log;
  // The window's target level is a coarse one: the face's line there says which levels show no
  // triangles and why.
  const std::size_t at = log.find("cetview view: face 7: empty: ");
  ASSERT_NE(at, std::string::npos) << log;
  const std::string line = log.substr(at, log.find('\n', at) - at);
  EXPECT_NE(line.find("boundary crosses itself in UV"), std::string::npos) << line;
  expectWholeLevelShown(log);
  ASSERT_TRUE(image.ok()) << image.error().message;
  EXPECT_GT(modelCoverage(*image), 0.05);
}

// A lost Vulkan device mid-loop (simulated through the viewer's test hook: lavapipe never loses
// it) ends the window with exit code 1 and exactly one line on stderr that says so; the teardown
// (ImGui's Vulkan backend, swapchain, device) is validation-clean and does not crash.
TEST_F(ViewerWindowTest, DeviceLossEndsWithOneLineAndExitCodeOne) {
  const std::string shot = outputPath("device_loss.png");
  // Lost in a drawn frame, then in the capture of the last frame (--screenshot).
  for (const bool screenshot : {false, true}) {
    std::string out, err;
    std::string args = "view demo --size 640x400 --validate --frames 20 --threads 2";
    if (screenshot) args += " --screenshot " + shot;
    std::remove(shot.c_str());
    const std::string env = std::string("CETVIEW_TEST_DEVICE_LOSS_AT_FRAME=") + (screenshot ? "19" : "5");
    const int rc = runViewer(args, out, &err, env);
    EXPECT_EQ(rc, 1) << out << err;
    ASSERT_FALSE(err.empty()) << out;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << "not exactly one line:\n" << err;
    EXPECT_EQ(err.rfind("cetview view: the Vulkan device was lost (VK_ERROR_DEVICE_LOST in ", 0), 0u) << err;
    EXPECT_NE(err.find("; restart cetview (or pick another device with --device)\n"), std::string::npos)
        << err;
    // Nothing from the validation layer (it prints "vulkan: Validation Error: ...").
    EXPECT_EQ(err.find("vulkan:"), std::string::npos) << err;
    EXPECT_EQ(err.find("Validation"), std::string::npos) << err;
    EXPECT_EQ(out.find("\"frames\":"), std::string::npos) << "the closing line of a clean run:\n" << out;
    EXPECT_NE(access(shot.c_str(), F_OK), 0) << "no screenshot after the loss";
  }
}

TEST_F(ViewerWindowTest, BadInputIsExitCode2) {
  std::string log;
  EXPECT_EQ(runViewer("view /nonexistent/model.step --frames 2", log), 2) << log;
  const std::string script = writeScript("bad.script", "spin 3\n");
  EXPECT_EQ(runViewer("--frames 2 --script " + script, log), 2) << log;
  EXPECT_NE(log.find("unknown command 'spin'"), std::string::npos) << log;
  EXPECT_EQ(runViewer("view --size 10x10", log), 2) << log;
}

}  // namespace
}  // namespace cetview::test
