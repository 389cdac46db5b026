// Progressive loading against BRepMesh, side by side in one run (DESIGN.md "Benchmarks"): time to
// the first complete frame and to each level, next to BRepMesh_IncrementalMesh's full tessellation
// time at the same final deflection; bytes uploaded per frame; the longest frame while loading
// against an idle frame. Headless at 1280x720 on the default Vulkan device (lavapipe without a GPU);
// like the window, the loop draws a frame only when something new arrived.
//   progressive_bench [--threads N] [--deflection 0.1%] [--repeat R] [--no-brepmesh]
//                     [--direct-draws | --indirect-draws] [--fresh-threads] [--first-level-on-workers]
//                     MODEL...
// (MODEL: a file or "demo"; --repeat loads each model R times, BRepMesh once; --no-brepmesh skips
// the reference, for quick runs of the progressive side alone; --direct-draws and --indirect-draws
// force one drawing path (gpu_scene.h) where the device would take the other, to compare them.
// The tessellation threads are started before the first model loads and kept for all, as the
// window keeps them (stream_threads.h); --fresh-threads has each model start its own instead.
// --first-level-on-workers: a small model's level 0 is made by the stream's threads too, not by
// the caller (StreamOptions::firstLevelOnCaller).
// "idle cpu" is the CPU time of drawing one idle frame, driver included; "draws" its draw calls;
// "1st faults" the process's page faults from the end of loading to the first complete frame: on
// the project's virtual machines each costs about 10 us, so the memory a level first touches is
// part of its time.)
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "brep/bench.h"
#include "brep/tessellator.h"
#include "engine/context.h"
#include "engine/renderer.h"
#include "engine/warm_up.h"
#include "frame_pacing.h"
#include "model_scene.h"
#include "stream/progressive_stream.h"
#include "stream/stream_consumer.h"
#include "stream/stream_threads.h"

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }
// CPU time of the calling thread: recording and submitting a frame, driver included.
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
// Minor page faults of the whole process so far (every thread: the workers, lavapipe's).
long pageFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

struct Row {
  std::string model;
  std::size_t faces = 0;
  double brepmesh = 0, firstFrame = 0, lastLevel = 0, longestLoading = 0, idle = 0, idleCpu = 0;
  std::uint32_t drawCalls = 0;  // faces and edges, in an idle frame
  long firstFaults = 0;         // page faults from the end of loading to the first complete frame
  std::vector<double> levelMs;
  double meanBytes = 0, maxBytes = 0;
  std::string error;
};

// Which path draws the faces: the device's default (multi-draw indirect on GPUs, one by one on
// CPU devices), or one of them forced.
enum class Draws { kDefault, kDirect, kIndirect };

Row measure(const std::string& path, const cetview::brep::MeshParams& params, unsigned threads,
            const cetview::engine::Device& device, bool reference, double brepmeshMs, Draws draws,
            cetview::stream::StreamThreads* kept, bool firstLevelOnCaller) {
  namespace brep = cetview::brep;
  namespace engine = cetview::engine;
  Row row;
  row.model = path;
  row.brepmesh = brepmeshMs;
  if (reference) {
    brep::BenchOptions bench;
    bench.params = params;
    bench.threads = 1;
    bench.measure = false;
    const brep::BenchResult result = brep::benchModel(path, bench);
    if (!result.error.empty()) {
      row.error = result.error;
      return row;
    }
    row.brepmesh = result.brepmesh_ms;
  }

  // The window is open before a model loads: the renderer (and its pipelines, which lavapipe
  // compiles when they are created and, for their machine code, at their first draw: warmUp())
  // exists before the clock starts, as in the viewer once it has shown a model.
  engine::RendererOptions rendererOptions;
  rendererOptions.scene.indirectDraws = draws != Draws::kDirect;
  rendererOptions.scene.indirectDrawsOnCpu = draws == Draws::kIndirect;
  auto renderer = engine::Renderer::createHeadless(device, {1280, 720}, rendererOptions);
  if (!renderer) {
    row.error = renderer.error().message;
    return row;
  }
  if (auto warm = engine::warmUp(**renderer); !warm) {
    row.error = warm.error().message;
    return row;
  }
  auto loaded = brep::loadModel(path);
  if (!loaded) {
    row.error = loaded.error;
    return row;
  }
  row.faces = loaded.model->faces().size();
  const auto start = Clock::now();  // the model finished loading
  const long startFaults = pageFaults();
  auto created = brep::Tessellator::create(*loaded.model, params, kept ? kept->pool() : nullptr);
  if (!created.tessellator) {
    row.error = created.error;
    return row;
  }
  engine::Renderer& r = **renderer;
  cetview::ModelScene link(*loaded.model, r.scene());
  const int last = created.tessellator->lastLevel();
  cetview::stream::StreamOptions options;
  options.threads = threads;
  options.kept = kept;
  options.firstLevelOnCaller = firstLevelOnCaller;
  cetview::stream::ProgressiveStream producer(*created.tessellator, last, options);
  cetview::stream::StreamConsumer consumer(producer, row.faces);
  consumer.setShowLevel(last, link);
  const engine::Camera camera = engine::standardView(engine::StandardView::kIso, link.bounds(), r.aspect());
  std::size_t frames = 0;
  double bytes = 0;
  int seen = -1;
  cetview::FramePacing pacing;
  pacing.reset(start);
  for (;;) {
    const auto frameStart = Clock::now();
    const std::size_t polled = consumer.poll(std::size_t{64} << 20, link);
    // As the window does (redraw on change, frame_pacing.h): a frame at once when a level is
    // complete or still uploading, faces of a level in progress at most every 33 ms; otherwise the
    // cores are left to the workers until the next level is complete, or 0.5 ms.
    const bool pending = r.scene().uploadsPending();
    if (!pacing.due(frameStart, consumer.completeLevel(), polled > 0 || pending, pending)) {
      producer.waitForLevel(consumer.completeLevel() + 1, std::chrono::microseconds(500));
      continue;
    }
    auto status = r.drawFrame(camera);
    if (!status) {
      row.error = status.error().message;
      return row;
    }
    row.longestLoading = std::max(row.longestLoading, msSince(frameStart));
    const double b = static_cast<double>(r.lastUploadStats().bytes);
    bytes += b;
    row.maxBytes = std::max(row.maxBytes, b);
    pacing.drawn(frameStart, consumer.completeLevel(), r.scene().uploadsPending());
    ++frames;
    // A level counts once every face reached it and everything it needs is on the GPU.
    while (seen < consumer.completeLevel() && !r.scene().uploadsPending()) {
      ++seen;
      row.levelMs.push_back(msSince(start));
      if (seen == 0) row.firstFaults = pageFaults() - startFaults;
    }
    if (seen == last) break;
  }
  row.firstFrame = row.levelMs.front();
  row.lastLevel = row.levelMs.back();
  row.meanBytes = bytes / static_cast<double>(frames);
  std::vector<double> idle, idleCpu;
  for (int i = 0; i < 9; ++i) {
    const auto t = Clock::now();
    const double cpu = threadCpuMs();
    if (!r.drawFrame(camera)) break;
    idleCpu.push_back(threadCpuMs() - cpu);
    idle.push_back(msSince(t));
  }
  row.drawCalls = r.lastFaceDrawCalls() + r.lastEdgeDrawCalls();
  if (auto s = r.waitIdle(); !s) row.error = s.error().message;
  std::sort(idle.begin(), idle.end());
  std::sort(idleCpu.begin(), idleCpu.end());
  row.idle = idle.empty() ? 0 : idle[idle.size() / 2];
  row.idleCpu = idleCpu.empty() ? 0 : idleCpu[idleCpu.size() / 2];
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  namespace brep = cetview::brep;
  namespace engine = cetview::engine;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  brep::MeshParams params;
  std::vector<std::string> models;
  int repeat = 1;
  bool reference = true;
  Draws draws = Draws::kDefault;
  bool freshThreads = false;
  bool firstLevelOnCaller = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads = static_cast<unsigned>(std::max(1, std::atoi(argv[++i])));
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--no-brepmesh")) {
      reference = false;
    } else if (!std::strcmp(argv[i], "--direct-draws")) {
      draws = Draws::kDirect;
    } else if (!std::strcmp(argv[i], "--fresh-threads")) {
      freshThreads = true;
    } else if (!std::strcmp(argv[i], "--first-level-on-workers")) {
      firstLevelOnCaller = false;
    } else if (!std::strcmp(argv[i], "--indirect-draws")) {
      draws = Draws::kIndirect;
    } else if (!std::strcmp(argv[i], "--deflection") && i + 1 < argc) {
      if (std::string e = brep::parseDeflection(argv[++i], params.chordal); !e.empty()) {
        std::fprintf(stderr, "progressive_bench: %s\n", e.c_str());
        return 2;
      }
    } else {
      models.emplace_back(argv[i]);
    }
  }
  if (models.empty()) models.emplace_back("demo");
  auto instance = engine::createInstance({});
  if (!instance) {
    std::fprintf(stderr, "progressive_bench: %s\n", instance.error().message.c_str());
    return 1;
  }
  auto device = engine::createDevice(*instance, {});
  if (!device) {
    std::fprintf(stderr, "progressive_bench: %s\n", device.error().message.c_str());
    return 1;
  }
  std::printf("device: %s, %u tessellation thread(s)%s%s, 1280x720%s\n", device->name.c_str(), threads,
              freshThreads ? " started per model" : "", firstLevelOnCaller ? "" : ", level 0 on them always",
              draws == Draws::kDirect     ? ", draws one by one"
              : draws == Draws::kIndirect ? ", indirect draws"
                                          : "");
  std::unique_ptr<cetview::stream::StreamThreads> kept;
  if (!freshThreads) kept = std::make_unique<cetview::stream::StreamThreads>(threads);
  std::printf("%-34s %6s %11s %11s %7s %10s %11s %12s %10s %8s %6s %9s %11s  %s\n", "model", "faces",
              "brepmesh ms", "1st frame", "ratio", "1st faults", "final ms", "max frame ms", "idle ms",
              "idle cpu", "draws", "MB/frame", "max MB/frm", "ms per level");
  double brepmeshMs = 0;  // of the model's first run, shown again on its repeats
  for (int run = 0; run < repeat * static_cast<int>(models.size()); ++run) {
    const std::string& m = models[static_cast<std::size_t>(run / repeat)];
    const Row row =
        measure(m, params, threads, *device, reference && run % repeat == 0, brepmeshMs, draws, kept.get(),
                firstLevelOnCaller);
    brepmeshMs = row.brepmesh;
    const std::string name = m.size() > 34 ? "..." + m.substr(m.size() - 31) : m;
    if (!row.error.empty()) {
      std::printf("%-34s error: %s\n", name.c_str(), row.error.c_str());
      continue;
    }
    std::string levels;
    for (double t : row.levelMs) levels += (levels.empty() ? "" : " ") + std::to_string(static_cast<int>(t));
    std::printf("%-34s %6zu %11.1f %11.1f %6.2fx %10ld %11.1f %12.1f %10.1f %8.1f %6u %9.2f %11.2f  %s\n",
                name.c_str(), row.faces, row.brepmesh, row.firstFrame, row.firstFrame / row.brepmesh,
                row.firstFaults, row.lastLevel, row.longestLoading, row.idle, row.idleCpu, row.drawCalls,
                row.meanBytes / 1e6, row.maxBytes / 1e6, levels.c_str());
    std::fflush(stdout);
  }
  engine::destroyDevice(*device);
  engine::destroyInstance(*instance);
  return 0;
}
