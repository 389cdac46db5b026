// Progress and cancellation of a load (LoadControl): the demo part written as STEP, IGES and .brep
// loads with its phases reported in order and fractions rising to 1; a load cancelled before it
// starts, inside OpenCASCADE's transfer or reader, or while faces are indexed returns "cancelled"
// without a model at once (no later phase runs); and the same file loads whole afterwards.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <string>
#include <vector>

#include <BRepTools.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>

#include "brep/model.h"
#include "model_impl.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

struct Report {
  std::string phase;
  double fraction;
};

// The demo part as a file of the given kind ("step", "iges", "brep"), written once per process.
std::string demoFile(const std::string& kind) {
  const std::string path = test::tempPath("load_control_demo." + kind);
  const TopoDS_Shape shape = buildDemoPart();
  if (kind == "step") {
    STEPControl_Writer writer;
    EXPECT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
    EXPECT_EQ(writer.Write(path.c_str()), IFSelect_RetDone);
  } else if (kind == "iges") {
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", 1);  // B-rep faces, not trimmed surfaces
    EXPECT_TRUE(writer.AddShape(shape));
    writer.ComputeModel();
    EXPECT_TRUE(writer.Write(path.c_str()));
  } else {
    EXPECT_TRUE(BRepTools::Write(shape, path.c_str()));
  }
  return path;
}

std::vector<Report> loadReporting(const std::string& path, LoadResult& result) {
  std::vector<Report> reports;
  LoadControl control;
  control.progress = [&](const char* phase, double fraction) { reports.push_back({phase, fraction}); };
  result = loadModel(path, control);
  return reports;
}

class LoadControlTest : public ::testing::TestWithParam<const char*> {};

TEST_P(LoadControlTest, ReportsItsPhasesInOrderWithRisingFractions) {
  const std::string path = demoFile(GetParam());
  LoadResult result;
  const std::vector<Report> reports = loadReporting(path, result);
  ASSERT_TRUE(result) << result.error;
  EXPECT_GT(result.model->faces().size(), 20u);
  ASSERT_GE(reports.size(), 3u);
  EXPECT_EQ(reports.front().phase, "reading");
  EXPECT_EQ(reports.front().fraction, 0.0);
  EXPECT_EQ(reports.back().phase, "indexing faces");
  EXPECT_EQ(reports.back().fraction, 1.0);
  std::vector<std::string> phases;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    if (phases.empty() || phases.back() != reports[i].phase) phases.push_back(reports[i].phase);
    if (i > 0) {
      EXPECT_GE(reports[i].fraction, reports[i - 1].fraction) << "report " << i;
    }
  }
  const std::string kind = GetParam();
  if (kind == "brep") {
    EXPECT_EQ(phases, (std::vector<std::string>{"reading", "indexing faces"}));
  } else {
    EXPECT_EQ(phases, (std::vector<std::string>{"reading", "transferring", "indexing faces"}));
  }
  // Reports within a phase, not only its start: the faces are indexed one by one.
  std::size_t indexing = 0;
  for (const Report& r : reports) indexing += r.phase == "indexing faces";
  EXPECT_GT(indexing, 5u);
}

// Cancelled from the progress callback at the start of `phase`: the load returns cancelled, no
// later phase reports, and the phase itself stops at its next check. OpenCASCADE closes its
// progress scopes on the way out, which reports a jump or two to the phase's end; a transfer or
// reader that went on would report its way there in steps of half a per cent (dozens of reports).
// With `from` > 0 the cancel comes at the phase's first report at or beyond that fraction.
void expectCancelledIn(const std::string& path, const std::string& phase, double from = 0.0) {
  std::atomic<bool> cancel{false};
  std::vector<std::string> after;
  LoadControl control;
  control.cancel = &cancel;
  control.progress = [&](const char* p, double fraction) {
    if (cancel.load()) after.push_back(p);
    if (p == phase && fraction >= from) cancel = true;
  };
  const LoadResult r = loadModel(path, control);
  EXPECT_FALSE(r) << path;
  EXPECT_TRUE(r.cancelled) << r.error;
  EXPECT_EQ(r.error, path + ": cancelled");
  for (const std::string& p : after) EXPECT_EQ(p, phase) << "a later phase ran after the cancel";
  EXPECT_LE(after.size(), 3u) << phase << " went on after the cancel";
}

TEST_P(LoadControlTest, CancelledInAnyPhaseReturnsCancelledAndLoadsWholeAfterwards) {
  const std::string path = demoFile(GetParam());
  const std::string kind = GetParam();
  // Before it starts.
  std::atomic<bool> raised{true};
  LoadControl control;
  control.cancel = &raised;
  const LoadResult before = loadModel(path, control);
  EXPECT_FALSE(before);
  EXPECT_TRUE(before.cancelled);
  // In each phase (for .brep, inside OpenCASCADE's reader; for STEP and IGES, inside its transfer).
  expectCancelledIn(path, "reading");
  if (kind != "brep") expectCancelledIn(path, "transferring");
  expectCancelledIn(path, "indexing faces");
  expectCancelledIn(path, "indexing faces", 0.9);  // between two faces of the part
  // Nothing stays behind: the same file loads whole.
  LoadResult again = loadModel(path);
  ASSERT_TRUE(again) << again.error;
  EXPECT_EQ(again.model->faces().size(), loadModel(path).model->faces().size());
  EXPECT_FALSE(again.cancelled);
}

INSTANTIATE_TEST_SUITE_P(Formats, LoadControlTest, ::testing::Values("step", "iges", "brep"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param); });

TEST(LoadControl, TheDemoPartReportsAndCancels) {
  LoadResult result;
  const std::vector<Report> reports = loadReporting("demo", result);
  ASSERT_TRUE(result) << result.error;
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.front().phase, "building the demo part");
  EXPECT_EQ(reports.back().fraction, 1.0);
  expectCancelledIn("demo", "indexing faces", 0.9);
}

}  // namespace
}  // namespace cetview::brep
