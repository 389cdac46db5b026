// cetview_render_bench: how fast the engine draws and uploads, headless, on whatever device it
// picks (lavapipe on a machine without a GPU).
//
//   cetview_render_bench [--device NAME] [--width W] [--height H] [--min-triangles N]
//                        [--max-triangles N] [--seconds S | --frames N] [--section 1|2|3] [--closed-only]
//
// --frames: exactly N measured frames per row of section 1 (for instruction counts under perf stat).
//
// 1. Frame time at W x H (default 1280x720) for 10k .. 2M triangles (grids of 8-face spheres with
//    B-rep edges), shaded with edges: closed solids (back faces culled) and open shells
//    (two-sided) without MSAA (the default on CPU devices), and closed solids with 4x MSAA.
// 2. Upload throughput: a large scene through the upload ring, one unlimited frame and at the
//    default per-frame budget.
// 3. Streaming: the longest and mean frame while a large replacement (every face re-tessellated,
//    same size) streams in at 16 and 4 MiB per frame, against idle frames of the same scene, and
//    without a budget (everything in one frame) for comparison.
#include <dirent.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/context.h"
#include "engine/render_to_png.h"
#include "engine/renderer.h"
#include "test_meshes.h"

using namespace cetview;
using namespace cetview::engine;
using Clock = std::chrono::steady_clock;

namespace {

struct Args {
  std::string device;
  std::uint32_t width = 1280, height = 720;
  std::uint64_t minTriangles = 0;  // rows of section 1 below this are skipped
  std::uint64_t maxTriangles = 2000000;
  int section = 0;          // 0: all three
  bool closedOnly = false;  // section 1: only the closed solid 1x column
  double seconds = 2.0;     // time spent measuring each row
  int frames = 0;           // > 0: frames measured per row of section 1 instead
};

// The largest budget a Renderer takes (512 MiB); "unlimited" in the tables.
constexpr std::uint64_t kUnlimited = std::uint64_t{256} << 20;

std::string budgetLabel(std::uint64_t budget) {
  return budget >= kUnlimited ? "unlimited (256 MiB)" : std::to_string(budget >> 20) + " MiB";
}

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Seconds of CPU time this process (all its threads: ours, lavapipe's queue and rasterisers) used.
double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Spheres of `segments` needed for about `triangles` triangles.
std::uint32_t sphereCount(std::uint64_t triangles, std::uint32_t segments) {
  std::uint64_t perSphere = test::triangleCount(test::sphere(1.0f, segments));
  return static_cast<std::uint32_t>(std::max<std::uint64_t>(1, (triangles + perSphere / 2) / perSphere));
}

// A square grid of `count` closed spheres, `segments` per quarter.
MeshData sphereGrid(std::uint32_t count, std::uint32_t segments) {
  auto side = static_cast<std::uint32_t>(std::ceil(std::sqrt(double(count))));
  MeshData mesh;
  for (std::uint32_t i = 0; i < count; ++i) {
    glm::vec3 c(2.2f * float(i % side), 0.0f, 2.2f * float(i / side));
    test::append(mesh, test::sphere(1.0f, segments, c));
  }
  return mesh;
}

MeshData sphereGridOf(std::uint64_t triangles, std::uint32_t segments) {
  return sphereGrid(sphereCount(triangles, segments), segments);
}

// Segments so that one sphere is about 1/100 of the target (at least 8, at most 96).
std::uint32_t segmentsFor(std::uint64_t triangles) {
  double perSphere = std::max(1000.0, double(triangles) / 100.0);
  return std::clamp<std::uint32_t>(static_cast<std::uint32_t>(std::sqrt(perSphere / 16.0)), 8, 96);
}

struct Session {
  Instance instance;
  Device device;
  ~Session() {
    destroyDevice(device);
    destroyInstance(instance);
  }
};

std::unique_ptr<Renderer> makeRenderer(const Device& device, const Args& args, std::uint32_t msaa,
                                       std::uint64_t budget) {
  RendererOptions options;
  options.msaaSamples = msaa;
  options.uploadBudgetBytes = budget;
  auto r = Renderer::createHeadless(device, {args.width, args.height}, options);
  if (!r) {
    std::fprintf(stderr, "cetview_render_bench: %s\n", r.error().message.c_str());
    std::exit(1);
  }
  return std::move(*r);
}

void check(const Status& s) {
  if (!s) {
    std::fprintf(stderr, "cetview_render_bench: %s\n", s.error().message.c_str());
    std::exit(1);
  }
}

void draw(Renderer& r, const Camera& camera, const ViewStyle& style = {}) {
  auto status = r.drawFrame(camera, style);
  if (!status) check(status.error());
}

// CPU seconds used so far by each thread of this process (Linux /proc), by thread id.
std::map<std::string, double> threadCpuSeconds() {
  std::map<std::string, double> result;
  DIR* dir = opendir("/proc/self/task");
  if (dir == nullptr) return result;
  const double tick = double(sysconf(_SC_CLK_TCK));
  while (dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.') continue;
    std::ifstream file(std::string("/proc/self/task/") + entry->d_name + "/stat");
    std::string line;
    std::getline(file, line);
    std::size_t close = line.rfind(')');
    if (close == std::string::npos) continue;
    // After "pid (comm) ": state is field 3; utime and stime are fields 14 and 15.
    std::istringstream fields(line.substr(close + 2));
    std::string field;
    double utime = 0, stime = 0;
    for (int i = 3; i <= 15 && fields >> field; ++i) {
      if (i == 14) utime = std::atof(field.c_str());
      if (i == 15) stime = std::atof(field.c_str());
    }
    result[entry->d_name] = (utime + stime) / tick;
  }
  closedir(dir);
  return result;
}

struct FrameCost {
  double wallMs = 0.0;     // wall-clock time per frame
  double cpuMs = 0.0;      // CPU time per frame, summed over all threads
  double busiestMs = 0.0;  // CPU time per frame of the busiest thread (lavapipe's front end)
};

// Cost of back-to-back frames (after a warm-up), measured for about `seconds`.
FrameCost frameCost(Renderer& r, const Camera& camera, const ViewStyle& style, double seconds,
                    int exactFrames) {
  for (int i = 0; i < 3; ++i) draw(r, camera, style);
  check(r.waitIdle());
  int frames = 0;
  auto start = Clock::now();
  double cpuStart = cpuSeconds();
  std::map<std::string, double> threadsStart = threadCpuSeconds();
  do {
    draw(r, camera, style);
    ++frames;
  } while (exactFrames > 0 ? frames < exactFrames : since(start) < seconds || frames < 5);
  check(r.waitIdle());
  FrameCost cost{1000.0 * since(start) / frames, 1000.0 * (cpuSeconds() - cpuStart) / frames, 0.0};
  for (const auto& [thread, cpu] : threadCpuSeconds()) {
    cost.busiestMs = std::max(cost.busiestMs, 1000.0 * (cpu - threadsStart[thread]) / frames);
  }
  return cost;
}

// What a machine with `cores` otherwise idle cores would take: the busiest thread and the
// total work per core bound it from below (lavapipe overlaps one frame's front end with the
// previous frame's rasterisation, so the bound is close).
double dedicatedMs(const FrameCost& c, unsigned cores) {
  return std::max(c.busiestMs, c.cpuMs / cores);
}

void frameTimes(const Device& device, const Args& args) {
  unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::printf("\n1. Frame time, %ux%u, shaded with B-rep edges, perspective iso view.\n", args.width,
              args.height);
  std::printf(
      "   ms, fps: wall clock here. cpu: CPU ms per frame over all threads; front: the busiest\n"
      "   thread (lavapipe's queue: vertex shading, setup, binning). est fps: max(front, cpu/%u)\n"
      "   as frame time, an estimate for %u otherwise idle cores (on a shared machine the wall\n"
      "   clock mostly measures the neighbours).\n",
      cores, cores);
  std::printf("%9s %5s | %36s | %36s | %21s\n", "triangles", "faces", "closed solid (culled), 1x",
              "open shell (two-sided), 1x", "closed, 4x MSAA");
  std::printf("%9s %5s | %6s %5s %6s %6s %7s | %6s %5s %6s %6s %7s | %6s %5s %7s\n", "", "", "ms", "fps",
              "cpu", "front", "est fps", "ms", "fps", "cpu", "front", "est fps", "ms", "fps", "est fps");
  const std::uint64_t targets[] = {10000, 100000, 500000, 1000000, 2000000};
  for (std::uint64_t target : targets) {
    if (target > args.maxTriangles) break;
    if (target < args.minTriangles) continue;
    MeshData mesh = sphereGridOf(target, segmentsFor(target));
    struct Column {
      bool closed;
      std::uint32_t samples;
    };
    const Column columns[] = {{true, 1}, {false, 1}, {true, 4}};
    FrameCost cost[3];
    const int columnCount = args.closedOnly ? 1 : 3;
    for (int k = 0; k < columnCount; ++k) {
      mesh.closedSolid = columns[k].closed;
      auto r = makeRenderer(device, args, columns[k].samples, kUnlimited);
      auto part = addMesh(r->scene(), mesh);
      if (!part) check(part.error());
      check(r->finishUploads());
      Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
      cost[k] = frameCost(*r, camera, ViewStyle{}, args.seconds, args.frames);
    }
    std::printf("%9llu %5zu", static_cast<unsigned long long>(test::triangleCount(mesh)), mesh.faces.size());
    for (int k = 0; k < std::min(columnCount, 2); ++k) {
      const FrameCost& c = cost[k];
      std::printf(" | %6.1f %5.1f %6.1f %6.1f %7.1f", c.wallMs, 1000.0 / c.wallMs, c.cpuMs, c.busiestMs,
                  1000.0 / dedicatedMs(c, cores));
    }
    if (columnCount < 3) {
      std::printf("\n");
      continue;
    }
    std::printf(" | %6.1f %5.1f %7.1f\n", cost[2].wallMs, 1000.0 / cost[2].wallMs,
                1000.0 / dedicatedMs(cost[2], cores));
  }
}

void uploadThroughput(const Device& device, const Args& args) {
  std::printf("\n2. Upload throughput (vertices + indices + edges through the upload ring, best of 3)\n");
  std::printf("%24s %10s %10s %10s\n", "budget per frame", "MB", "seconds", "MB/s");
  MeshData mesh = sphereGridOf(std::min<std::uint64_t>(args.maxTriangles, 2000000), 64);
  for (std::uint64_t budget : {kUnlimited, std::uint64_t{16} << 20}) {
    auto r = makeRenderer(device, args, 0, budget);
    double best = 1e30;
    auto part = addMesh(r->scene(), mesh);
    if (!part) check(part.error());
    double mb = double(r->scene().pendingBytes()) / 1e6;
    // The first runs warm the device buffers and every page of the upload ring (first touches of
    // fresh host memory are page faults, not uploads); then the best of 3.
    int warm = 1 + static_cast<int>(std::min(40.0, std::ceil(3.0 * double(budget) / 1e6 / mb)));
    for (int run = 0; run < warm + 3; ++run) {
      if (run > 0) {
        r->scene().clear();
        part = addMesh(r->scene(), mesh);
        if (!part) check(part.error());
      }
      auto start = Clock::now();
      check(r->finishUploads());  // upload-only frames until done, then waits for the device
      if (run >= warm) best = std::min(best, since(start));
    }
    std::printf("%24s %10.1f %10.3f %10.0f\n", budgetLabel(budget).c_str(), mb, best, mb / best);
  }
}

// One frame, start to finish: recording, uploads and drawing, waited for (not pipelined), so the
// frame that carries an upload is charged with all of it.
double timedFrameMs(Renderer& r, const Camera& camera) {
  auto start = Clock::now();
  draw(r, camera);
  check(r.waitIdle());
  return 1000.0 * since(start);
}

void streaming(const Device& device, const Args& args) {
  std::uint64_t base = std::min<std::uint64_t>(args.maxTriangles, 1000000);
  std::uint32_t segments = segmentsFor(base);
  MeshData mesh = sphereGridOf(base, segments);
  std::printf(
      "\n3. Frames while a re-tessellation streams in: %llu triangles, every face replaced by a new array\n"
      "   of the same size over new vertices (the picture and its drawing cost stay the same).\n"
      "   Each frame is waited for, so a frame is charged with its whole upload.\n",
      static_cast<unsigned long long>(test::triangleCount(mesh)));
  std::printf("%20s %7s %10s %10s %9s %11s %7s %13s\n", "budget per frame", "frames", "idle mean", "idle max",
              "mean ms", "longest ms", "MB", "max MB/frame");
  for (std::uint64_t budget : {std::uint64_t{16} << 20, std::uint64_t{4} << 20, kUnlimited}) {
    auto r = makeRenderer(device, args, 0, budget);
    auto part = addMesh(r->scene(), mesh);
    if (!part) check(part.error());
    check(r->finishUploads());
    Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
    Scene& scene = r->scene();
    double idleTotal = 0.0, idleMax = 0.0;
    const int idleFrames = 8;
    for (int i = 0; i < idleFrames + 2; ++i) {
      double ms = timedFrameMs(*r, camera);
      if (i < 2) continue;  // warm-up
      idleTotal += ms;
      idleMax = std::max(idleMax, ms);
    }

    // The progressive pipeline's two operations: append vertices, replace every face.
    std::uint32_t first = scene.appendVertices(mesh.vertices.data(), mesh.vertices.size());
    std::vector<std::uint32_t> indices;
    for (std::uint32_t f = 0; f < part->faceCount; ++f) {
      indices = mesh.faces[f].indices;
      for (std::uint32_t& i : indices) i += first;
      check(scene.setFaceIndices(part->face(f), indices.data(), indices.size()));
    }
    double mb = double(scene.pendingBytes()) / 1e6;
    int frames = 0;
    double longest = 0.0, total = 0.0, maxBytes = 0.0;
    while (scene.uploadsPending()) {
      double ms = timedFrameMs(*r, camera);
      longest = std::max(longest, ms);
      maxBytes = std::max(maxBytes, double(r->lastUploadStats().bytes) / 1e6);
      total += ms;
      ++frames;
    }
    std::printf("%20s %7d %10.1f %10.1f %9.1f %11.1f %7.1f %13.1f\n", budgetLabel(budget).c_str(), frames,
                idleTotal / idleFrames, idleMax, total / frames, longest, mb, maxBytes);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "cetview_render_bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--device") {
      args.device = next();
    } else if (a == "--width") {
      args.width = static_cast<std::uint32_t>(std::stoul(next()));
    } else if (a == "--height") {
      args.height = static_cast<std::uint32_t>(std::stoul(next()));
    } else if (a == "--min-triangles") {
      args.minTriangles = std::stoull(next());
    } else if (a == "--closed-only") {
      args.closedOnly = true;
    } else if (a == "--section") {
      args.section = std::stoi(next());
    } else if (a == "--max-triangles") {
      args.maxTriangles = std::stoull(next());
    } else if (a == "--frames") {
      args.frames = std::stoi(next());
    } else if (a == "--seconds") {
      args.seconds = std::stod(next());
    } else {
      std::fprintf(stderr,
                   "usage: cetview_render_bench [--device NAME] [--width W] [--height H] [--min-triangles N] "
                   "[--max-triangles N] [--seconds S | --frames N] [--section 1|2|3] "
                   "[--closed-only]\n");
      return 2;
    }
  }
  Session session;
  auto instance = createInstance(InstanceOptions{});
  if (!instance) check(instance.error());
  session.instance = std::move(*instance);
  DeviceOptions deviceOptions;
  deviceOptions.name = args.device;
  auto device = createDevice(session.instance, deviceOptions);
  if (!device) check(device.error());
  session.device = *device;
  std::printf("cetview_render_bench on %s\n", describeDevice(session.device).c_str());
  if (const char* threads = std::getenv("LP_NUM_THREADS")) std::printf("LP_NUM_THREADS=%s\n", threads);

  if (args.section == 0 || args.section == 1) frameTimes(session.device, args);
  if (args.section == 0 || args.section == 2) uploadThroughput(session.device, args);
  if (args.section == 0 || args.section == 3) streaming(session.device, args);
  return 0;
}
