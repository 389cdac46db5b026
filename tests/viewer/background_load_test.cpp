// A model loading on its own thread (background_load.h): the result arrives with progress up to
// 100% and a wake-up call; a cancelled load ends cancelled, without a model; destroying a load in
// progress cancels and waits for it.
#include "background_load.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace cetview::test {
namespace {

void waitUntilDone(const BackgroundLoad& load) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!load.done() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(load.done()) << "the load did not finish";
}

TEST(BackgroundLoad, LoadsOnItsThreadReportsProgressAndWakesTheCaller) {
  std::atomic<int> wakes{0};
  BackgroundLoad load("demo", [&] { ++wakes; });
  EXPECT_EQ(load.path(), "demo");
  waitUntilDone(load);
  EXPECT_EQ(wakes.load(), 1);
  const BackgroundLoad::Progress p = load.progress();
  EXPECT_EQ(p.phase, "indexing faces");
  EXPECT_EQ(p.fraction, 1.0);
  brep::LoadResult r = load.take();
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.model->faces().size(), 26u);
}

TEST(BackgroundLoad, ACancelledLoadEndsWithoutAModel) {
  BackgroundLoad load("demo", {});
  load.cancel();  // building the demo takes far longer than this
  EXPECT_TRUE(load.cancelled());
  waitUntilDone(load);
  brep::LoadResult r = load.take();
  EXPECT_FALSE(r);
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.error, "demo: cancelled");
}

TEST(BackgroundLoad, AFailedLoadCarriesItsError) {
  BackgroundLoad load("/nonexistent/part.step", {});
  waitUntilDone(load);
  const brep::LoadResult r = load.take();
  EXPECT_FALSE(r);
  EXPECT_FALSE(r.cancelled);
  EXPECT_EQ(r.error, "/nonexistent/part.step: no such file");
}

TEST(BackgroundLoad, DestroyingALoadInProgressCancelsIt) {
  std::atomic<int> wakes{0};
  {
    BackgroundLoad load("demo", [&] { ++wakes; });
  }  // returns once the thread has
  EXPECT_EQ(wakes.load(), 1);
}

}  // namespace
}  // namespace cetview::test
