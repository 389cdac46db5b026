// The progressive stream on the demo part: level-major completion, a consumer mirror equal to the
// tessellator's own meshes, and a stress run of random tolerance changes and cancellations that
// must end in the same mesh as a clean run (run under -DCETVIEW_SANITIZE=thread for races). And on
// a small model (occt-misc's mal_vis.brep: six faces, planes, cylinders and a torus, 146 to 612
// triangles over its four levels), whose level 0 the stream's caller makes.
#include "stream/progressive_stream.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <random>
#include <thread>

#include "brep/model.h"
#include "stream/stream_consumer.h"

namespace cetview::stream {
namespace {

StreamOptions options(unsigned threads, std::size_t ringBytes) {
  StreamOptions o;
  o.threads = threads;
  o.ringBytes = ringBytes;
  return o;
}

// A MeshSink that keeps what a renderer would: one vertex array, one index array per face.
struct RecordingSink : MeshSink {
  std::vector<StreamVertex> vertices;
  std::map<std::uint32_t, std::vector<std::uint32_t>> faces;
  std::size_t replacements = 0;
  std::map<std::uint32_t, std::vector<float>> edges;
  std::uint32_t appendVertices(const StreamVertex* v, std::size_t count) override {
    const auto first = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), v, v + count);
    return first;
  }
  void setFaceIndices(std::uint32_t face, const std::uint32_t* idx, std::size_t count) override {
    for (std::size_t i = 0; i < count; ++i) EXPECT_LT(idx[i], vertices.size());
    faces[face].assign(idx, idx + count);
    ++replacements;
  }
  void setEdgePolyline(std::uint32_t edge, const float* xyz, std::size_t count) override {
    edges[edge].assign(xyz, xyz + 3 * count);
  }
  // Face f's triangles as position triples, for comparison across runs.
  std::vector<float> trianglePositions(std::uint32_t f) const {
    std::vector<float> out;
    const auto it = faces.find(f);
    if (it == faces.end()) return out;
    for (std::uint32_t i : it->second) out.insert(out.end(), vertices[i].position, vertices[i].position + 3);
    return out;
  }
};

struct Demo {
  std::unique_ptr<brep::Model> model;
  std::unique_ptr<brep::Tessellator> tess;
  explicit Demo(const std::string& path = "demo") {
    auto loaded = brep::loadModel(path);
    EXPECT_TRUE(loaded) << loaded.error;
    model = std::move(loaded.model);
    brep::MeshParams params;
    params.chordal.value = 0.002;  // 0.2%: a few levels, quick even under sanitizers
    auto created = brep::Tessellator::create(*model, params);
    EXPECT_TRUE(created.tessellator) << created.error;
    tess = std::move(created.tessellator);
  }
};

const std::string kSmallModel = std::string(CETVIEW_OCCT_DATA) + "/occ/mal_vis.brep";

// Polls until the consumer has level `level` complete (or a generous time limit passes).
bool pollUntil(StreamConsumer& consumer, RecordingSink& sink, int level) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (consumer.completeLevel() < level) {
    if (consumer.poll(1 << 20, sink) == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (std::chrono::steady_clock::now() > deadline) return false;
  }
  return true;
}

TEST(ProgressiveStream, LevelsCompleteInOrderAndMirrorTheTessellator) {
  Demo demo;
  const int last = demo.tess->lastLevel();
  ASSERT_GE(last, 1) << "the demo must have more than one level";
  ProgressiveStream stream(*demo.tess, last, options(2, 1 << 16));  // small rings: back-pressure
  StreamConsumer consumer(stream, demo.model->faces().size());
  RecordingSink sink;
  ASSERT_TRUE(pollUntil(consumer, sink, last));
  const auto& stats = consumer.levelStats();
  ASSERT_EQ(static_cast<int>(stats.size()), last + 1);
  for (int k = 0; k <= last; ++k) {
    EXPECT_EQ(stats[static_cast<std::size_t>(k)].level, k);
    if (k > 0) {
      EXPECT_GE(stats[static_cast<std::size_t>(k)].ms, stats[static_cast<std::size_t>(k) - 1].ms);
      EXPECT_LT(stats[static_cast<std::size_t>(k)].chordal, stats[static_cast<std::size_t>(k) - 1].chordal);
    }
  }
  EXPECT_EQ(consumer.shownTriangles(), demo.tess->triangleCount(last));
  // Every non-degenerate edge shows its final polyline.
  std::vector<float> xyz;
  std::size_t polylines = 0;
  for (std::uint32_t e = 0; e < demo.model->edgeCount(); ++e) {
    demo.tess->edgePolyline(e, last, xyz);
    if (xyz.empty()) continue;
    ++polylines;
    EXPECT_EQ(sink.edges[e], xyz) << "edge " << e;
  }
  EXPECT_GT(polylines, 20u);
  // Every face shows exactly the tessellator's final triangles, vertex for vertex.
  for (std::uint32_t f = 0; f < demo.model->faces().size(); ++f) {
    const brep::FaceMesh& mesh = demo.tess->faceMesh(f);
    const auto& expected = mesh.levels.back();
    const auto got = sink.trianglePositions(f);
    ASSERT_EQ(got.size(), expected.size() * 3) << "face " << f;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(got[3 * i + static_cast<std::size_t>(c)],
                  static_cast<float>(mesh.positions[3 * expected[i] + static_cast<std::uint32_t>(c)]));
      }
    }
  }
  // Coarser is instant: stored levels, no waiting.
  consumer.setShowLevel(0, sink);
  EXPECT_EQ(consumer.shownTriangles(), stats[0].triangles);
}

// A consumer that sleeps between frames is woken when a level can be shown: waitForLevel()
// returns once the level's record is in the control ring (a level's poll right after it shows the
// level complete), and onLevelPublished is called once per level. The wait is an hour long: without
// the wake-up the test runs into ctest's time limit.
TEST(ProgressiveStream, EachCompletedLevelWakesTheConsumer) {
  Demo demo;
  const int last = demo.tess->lastLevel();
  std::atomic<int> announced{0};
  StreamOptions o = options(2, 1 << 20);
  o.onLevelPublished = [&] { ++announced; };
  ProgressiveStream stream(*demo.tess, last, o);
  StreamConsumer consumer(stream, demo.model->faces().size());
  RecordingSink sink;
  for (int level = 0; level <= last; ++level) {
    stream.waitForLevel(level, std::chrono::hours(1));
    while (consumer.poll(1 << 20, sink) > 0) {
    }
    ASSERT_GE(consumer.completeLevel(), level);
    EXPECT_GE(announced.load(), level + 1);
  }
  EXPECT_EQ(announced.load(), last + 1);
}

void randomTargetChangesEndInTheCleanMesh(const std::string& path) {
  std::vector<std::vector<float>> clean;
  int last = 0;
  {
    Demo demo(path);
    last = demo.tess->lastLevel();
    ProgressiveStream stream(*demo.tess, last, options(2, 1 << 20));
    StreamConsumer consumer(stream, demo.model->faces().size());
    RecordingSink sink;
    ASSERT_TRUE(pollUntil(consumer, sink, last));
    for (std::uint32_t f = 0; f < demo.model->faces().size(); ++f) clean.push_back(sink.trianglePositions(f));
  }
  Demo demo(path);
  ProgressiveStream stream(*demo.tess, 0, options(2, 1 << 14));
  StreamConsumer consumer(stream, demo.model->faces().size());
  RecordingSink sink;
  std::mt19937 rng(2026);
  for (int change = 0; change < 300; ++change) {
    const int level = static_cast<int>(rng() % static_cast<unsigned>(last + 1));
    stream.setTargetLevel(level);
    consumer.setShowLevel(level, sink);
    const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(rng() % 3000);
    while (std::chrono::steady_clock::now() < until) consumer.poll(1 << 16, sink);
  }
  stream.setTargetLevel(last);
  consumer.setShowLevel(last, sink);
  ASSERT_TRUE(pollUntil(consumer, sink, last));
  for (std::uint32_t f = 0; f < demo.model->faces().size(); ++f) {
    EXPECT_EQ(sink.trianglePositions(f), clean[f]) << "face " << f << " differs from the clean run";
  }
}

TEST(ProgressiveStream, RandomTargetChangesEndInTheCleanMesh) { randomTargetChangesEndInTheCleanMesh("demo"); }

TEST(ProgressiveStream, RandomTargetChangesOfASmallModelEndInTheCleanMesh) {
  randomTargetChangesEndInTheCleanMesh(kSmallModel);
}

// Which thread announced each level: the caller makes a small model's level 0 before the stream's
// constructor returns (so the first frame does not wait for sleeping threads to wake), the
// coordinator the rest; every level reaches the consumer and the final one mirrors the tessellator.
std::vector<std::thread::id> announcers(Demo& demo, std::size_t ringBytes, bool firstLevelOnCaller,
                                        bool& firstLevelReadyAtOnce) {
  std::mutex mutex;
  std::vector<std::thread::id> by;
  StreamOptions o = options(2, ringBytes);
  o.firstLevelOnCaller = firstLevelOnCaller;
  o.onLevelPublished = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    by.push_back(std::this_thread::get_id());
  };
  const int last = demo.tess->lastLevel();
  ProgressiveStream stream(*demo.tess, last, o);
  StreamConsumer consumer(stream, demo.model->faces().size());
  RecordingSink sink;
  consumer.poll(1 << 20, sink);
  firstLevelReadyAtOnce = consumer.completeLevel() >= 0;
  EXPECT_EQ(firstLevelReadyAtOnce, stream.firstLevelMadeByCaller());
  EXPECT_TRUE(pollUntil(consumer, sink, last));
  for (std::uint32_t f = 0; f < demo.model->faces().size(); ++f) {
    const brep::FaceMesh& mesh = demo.tess->faceMesh(f);
    std::vector<float> expected;
    for (std::uint32_t i : mesh.levels.back()) {
      for (std::uint32_t c = 0; c < 3; ++c) expected.push_back(static_cast<float>(mesh.positions[3 * i + c]));
    }
    EXPECT_EQ(sink.trianglePositions(f), expected) << "face " << f;
  }
  stream.waitForLevel(last, std::chrono::hours(1));
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(static_cast<int>(by.size()), last + 1);
  return by;
}

TEST(ProgressiveStream, ASmallModelsFirstLevelIsMadeByTheCaller) {
  Demo small(kSmallModel);
  ASSERT_TRUE(firstLevelIsCheap(*small.model));
  ASSERT_GE(small.tess->lastLevel(), 1);
  bool atOnce = false;
  auto by = announcers(small, 1 << 20, true, atOnce);
  ASSERT_FALSE(by.empty());
  EXPECT_TRUE(atOnce) << "level 0 was not ready when the stream's constructor returned";
  EXPECT_EQ(by[0], std::this_thread::get_id());
  for (std::size_t k = 1; k < by.size(); ++k) EXPECT_NE(by[k], std::this_thread::get_id()) << "level " << k;

  // Asked not to, or for a model that is not small, the coordinator makes every level.
  Demo again(kSmallModel);
  by = announcers(again, 1 << 20, false, atOnce);
  ASSERT_FALSE(by.empty());
  EXPECT_NE(by[0], std::this_thread::get_id());
  Demo demo;
  EXPECT_FALSE(firstLevelIsCheap(*demo.model));
  by = announcers(demo, 1 << 20, true, atOnce);
  ASSERT_FALSE(by.empty());
  EXPECT_NE(by[0], std::this_thread::get_id());
}

// Rings too small for level 0's records: the caller cannot wait for a reader that does not exist
// yet (it would wait for ever), so it leaves the level to the coordinator, which ends in the same
// mesh. Without that the constructor never returns and the test runs into ctest's time limit.
TEST(ProgressiveStream, ASmallModelsFirstLevelGoesToTheCoordinatorWhenTheRingsAreFull) {
  Demo small(kSmallModel);
  bool atOnce = true;
  const auto by = announcers(small, 256, true, atOnce);
  ASSERT_FALSE(by.empty());
  EXPECT_FALSE(atOnce);
  EXPECT_NE(by[0], std::this_thread::get_id());
}

TEST(ProgressiveStream, DestroyingMidLevelCancelsTheRest) {
  // Nobody reads, so the small rings fill at once and the workers wait on them. Destroying the
  // stream must end that wait and abandon the model, not finish it first (a hang would time out).
  Demo demo;
  {
    ProgressiveStream stream(*demo.tess, demo.tess->lastLevel(), options(2, 1 << 12));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::size_t unfinished = 0;
  for (std::uint32_t f = 0; f < demo.model->faces().size(); ++f) {
    unfinished += demo.tess->faceLevel(f) < demo.tess->lastLevel() ? 1 : 0;
  }
  EXPECT_GT(unfinished, 0u) << "the stream finished the model instead of cancelling";
}

}  // namespace
}  // namespace cetview::stream
