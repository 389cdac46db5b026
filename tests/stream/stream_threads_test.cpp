// Threads and rings kept across models (stream_threads.h): streams made one after another run their
// coordinator on the one kept thread, their workers on the one kept pool and write into the kept
// rings, and end in the same meshes as a tessellator and stream with threads of their own; a stream
// after one dropped with records unread reads none of them; a second stream made while the kept
// thread is taken starts its own and completes too. Run under -DCETVIEW_SANITIZE=thread.
#include "stream/stream_threads.h"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <vector>

#include "brep/model.h"
#include "brep/tessellator.h"
#include "stream/progressive_stream.h"
#include "stream/stream_consumer.h"

namespace cetview::stream {
namespace {

// What a renderer keeps: per face, the triangles' corner positions.
struct Mirror : MeshSink {
  std::vector<StreamVertex> vertices;
  std::vector<std::vector<float>> faces;
  explicit Mirror(std::size_t faceCount) : faces(faceCount) {}
  std::uint32_t appendVertices(const StreamVertex* v, std::size_t count) override {
    const auto first = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), v, v + count);
    return first;
  }
  void setFaceIndices(std::uint32_t face, const std::uint32_t* idx, std::size_t count) override {
    std::vector<float>& out = faces.at(face);
    out.clear();
    for (std::size_t i = 0; i < count; ++i)
      out.insert(out.end(), vertices.at(idx[i]).position, vertices.at(idx[i]).position + 3);
  }
  void setEdgePolyline(std::uint32_t, const float*, std::size_t) override {}
};

std::unique_ptr<brep::Model> demoModel() {
  auto loaded = brep::loadModel("demo");
  EXPECT_TRUE(loaded) << loaded.error;
  return std::move(loaded.model);
}

brep::MeshParams params(double chordal) {
  brep::MeshParams p;
  p.chordal.value = chordal;  // relative to the diagonal
  return p;
}

// A stream of `tess` on two threads: on the kept ones when given and free, else on its own.
std::unique_ptr<ProgressiveStream> startStream(brep::Tessellator& tess, StreamThreads* kept) {
  StreamOptions o;
  o.threads = 2;
  o.kept = kept;
  return std::make_unique<ProgressiveStream>(tess, tess.lastLevel(), o);
}

// A tessellator and its stream on the kept threads, held while the test does something else.
struct HeldStream {
  std::unique_ptr<brep::Tessellator> tess;
  std::unique_ptr<ProgressiveStream> stream;  // destroyed first
};
HeldStream holdStream(const brep::Model& model, double chordal, StreamThreads& kept) {
  HeldStream held;
  held.tess = brep::Tessellator::create(model, params(chordal), kept.pool()).tessellator;
  EXPECT_TRUE(held.tess);
  if (!held.tess) return held;
  held.stream = startStream(*held.tess, &kept);
  EXPECT_TRUE(held.stream->onKeptThread());
  return held;
}

// One stream from a new tessellator to its last level; returns the consumer's faces. The consumer's
// level records must be this stream's own. `onKept` and `keptRings`, when given, say whether the
// stream ran its coordinator on the kept thread and wrote into the kept rings.
std::vector<std::vector<float>> streamToEnd(const brep::Model& model, const brep::MeshParams& p,
                                            StreamThreads* kept, bool* onKept = nullptr,
                                            bool* keptRings = nullptr) {
  auto created = brep::Tessellator::create(model, p, kept ? kept->pool() : nullptr);
  EXPECT_TRUE(created.tessellator) << created.error;
  brep::Tessellator& tess = *created.tessellator;
  const auto started = startStream(tess, kept);
  ProgressiveStream& stream = *started;
  if (onKept) *onKept = stream.onKeptThread();
  if (keptRings) *keptRings = kept && &stream.workerRing(0) == &kept->workerRing(0);
  StreamConsumer consumer(stream, model.faces().size());
  Mirror mirror(model.faces().size());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (consumer.completeLevel() < tess.lastLevel() && std::chrono::steady_clock::now() < deadline) {
    if (consumer.poll(1 << 20, mirror) == 0)
      stream.waitForLevel(consumer.completeLevel() + 1, std::chrono::milliseconds(1));
  }
  EXPECT_EQ(consumer.completeLevel(), tess.lastLevel());
  const auto& stats = consumer.levelStats();
  EXPECT_EQ(stats.size(), tess.schedule().size());
  for (std::size_t k = 0; k < stats.size() && k < tess.schedule().size(); ++k) {
    EXPECT_EQ(stats[k].chordal, tess.schedule()[k].chordal) << "level " << k;
    EXPECT_EQ(stats[k].triangles, tess.triangleCount(static_cast<int>(k))) << "level " << k;
  }
  return mirror.faces;
}

TEST(StreamThreads, StreamsOneAfterAnotherUseTheKeptThreads) {
  const auto model = demoModel();
  const auto coarse = streamToEnd(*model, params(0.004), nullptr);
  const auto fine = streamToEnd(*model, params(0.002), nullptr);
  StreamThreads kept(2);
  EXPECT_EQ(kept.threads(), 2u);
  EXPECT_EQ(kept.pool()->start(2), 1u);  // the helper is there before any model
  EXPECT_EQ(streamToEnd(*model, params(0.004), &kept), coarse);
  EXPECT_EQ(kept.tasksRun(), 1u);  // the stream's coordinator ran on the kept thread
  EXPECT_EQ(streamToEnd(*model, params(0.002), &kept), fine);
  EXPECT_EQ(kept.tasksRun(), 2u);
  EXPECT_GT(kept.pool()->joins(), 0u);   // the kept helper worked for the tessellators
  EXPECT_EQ(kept.pool()->start(2), 1u);  // and no other helper was started
}

// A stream dropped after its first level, its records unread, leaves them in the kept rings; the
// next stream empties them first (without, its consumer took the dropped stream's level 0, of
// another tolerance, for its own).
TEST(StreamThreads, AStreamAfterOneDroppedUnreadReadsOnlyItsOwnRecords) {
  const auto model = demoModel();
  const auto clean = streamToEnd(*model, params(0.002), nullptr);
  StreamThreads kept(2);
  {
    const HeldStream dropped = holdStream(*model, 0.01, kept);
    ASSERT_TRUE(dropped.stream);
    ProgressiveStream& stream = *dropped.stream;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (stream.progress().lastCompleteLevel < 0 && std::chrono::steady_clock::now() < deadline)
      stream.waitForLevel(0, std::chrono::milliseconds(1));
    EXPECT_GT(kept.controlRing().usedBytes(), 0u);  // its level 0's records, never read
  }
  EXPECT_EQ(streamToEnd(*model, params(0.002), &kept), clean);
}

// While one stream holds the kept thread and rings (the window's model, say), another stream starts
// a thread and rings of its own and completes; once the first is gone the next one gets them again.
// The two tessellators share the kept pool meanwhile.
TEST(StreamThreads, AStreamMadeWhileTheThreadIsTakenStartsItsOwn) {
  const auto model = demoModel();
  const auto clean = streamToEnd(*model, params(0.002), nullptr);
  StreamThreads kept(2);
  bool onKept = true, keptRings = true;
  {
    const HeldStream held = holdStream(*model, 0.002, kept);
    ASSERT_TRUE(held.stream);
    EXPECT_EQ(streamToEnd(*model, params(0.002), &kept, &onKept, &keptRings), clean);
    EXPECT_FALSE(onKept);
    EXPECT_FALSE(keptRings);
  }
  EXPECT_EQ(kept.tasksRun(), 1u);  // the held stream's coordinator alone ran there
  EXPECT_EQ(streamToEnd(*model, params(0.002), &kept, &onKept, &keptRings), clean);
  EXPECT_TRUE(onKept);
  EXPECT_TRUE(keptRings);
  EXPECT_EQ(kept.tasksRun(), 2u);
}

}  // namespace
}  // namespace cetview::stream
