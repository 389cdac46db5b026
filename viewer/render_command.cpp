// `cetview render MODEL -o OUT.png [--levels] ...`: headless capture of the model as it sharpens.
// The same progressive pipeline as the window: worker threads stream face levels into rings, the
// render loop drains them into the engine's Scene, and a frame is captured when the model is
// complete at a level (every face reached it and every upload landed).
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "brep/model.h"
#include "brep/tessellator.h"
#include "brep/tolerance.h"
#include "commands.h"
#include "device_loss.h"
#include "engine/camera.h"
#include "engine/context.h"
#include "engine/image.h"
#include "engine/renderer.h"
#include "engine/warm_up.h"
#include "face_problems.h"
#include "model_scene.h"
#include "progress_bar.h"
#include "stream/progressive_stream.h"
#include "stream/stream_consumer.h"
#include "stream/stream_threads.h"
#include "terminal_load.h"

namespace cetview {
namespace {

struct RenderCli {
  std::string model;
  std::string output;
  bool levels = false;
  std::string size = "1280x720";
  std::string view = "iso";
  std::string projection = "perspective";
  std::string deflection = "0.1%";
  std::string angle = "20";
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::string device;
  std::string display = "shaded-edges";
  bool validate = false;
};

bool parseSize(const std::string& text, std::uint32_t& w, std::uint32_t& h) {
  unsigned a = 0, b = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%u%c%u%c", &a, &x, &b, &extra) != 3 || (x != 'x' && x != 'X')) return false;
  if (a < 16 || b < 16 || a > 16384 || b > 16384) return false;
  w = a, h = b;
  return true;
}

std::string levelPath(const std::string& output, int level) {
  const std::size_t dot = output.rfind('.');
  const std::size_t slash = output.rfind('/');
  const bool hasExt = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = hasExt ? output.substr(0, dot) : output;
  const std::string ext = hasExt ? output.substr(dot) : ".png";
  return stem + "-L" + std::to_string(level) + ext;
}

struct Session {
  engine::Instance instance;
  engine::Device device;
  std::unique_ptr<engine::Renderer> renderer;
  ~Session() {
    renderer.reset();
    if (device.device) engine::destroyDevice(device);
    if (instance.instance) engine::destroyInstance(instance);
  }
};

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "cetview render: %s\n", message.c_str());
  return code;
}

int runRender(const RenderCli& cli) {
  std::uint32_t width = 0, height = 0;
  if (!parseSize(cli.size, width, height)) return fail(2, "--size '" + cli.size + "' must be WxH, 16 to 16384 each");
  const auto view = engine::parseStandardView(cli.view);
  if (!view) return fail(2, "--view '" + cli.view + "' must be iso, front, back, left, right, top or bottom");
  engine::Projection projection;
  if (cli.projection == "perspective") {
    projection = engine::Projection::kPerspective;
  } else if (cli.projection == "orthographic") {
    projection = engine::Projection::kOrthographic;
  } else {
    return fail(2, "--projection must be perspective or orthographic");
  }
  engine::ViewStyle style;
  if (cli.display == "shaded") {
    style.mode = engine::DisplayMode::kShaded;
  } else if (cli.display == "shaded-edges") {
    style.mode = engine::DisplayMode::kShadedWithEdges;
  } else if (cli.display == "wireframe") {
    style.mode = engine::DisplayMode::kWireframe;
  } else {
    return fail(2, "--display must be shaded, shaded-edges or wireframe");
  }
  brep::MeshParams params;
  if (std::string e = brep::parseDeflection(cli.deflection, params.chordal); !e.empty()) return fail(2, e);
  if (std::string e = brep::parseAngle(cli.angle, params.angleDeg); !e.empty()) return fail(2, e);
  if (cli.threads < 1 || cli.threads > 256) return fail(2, "--threads must be 1 to 256");

  // The tessellation threads start while the model loads (asleep until it has).
  stream::StreamThreads kept(cli.threads);
  brep::LoadResult loaded = loadWithProgressBar(cli.model, "render");
  if (!loaded) return fail(2, loaded.error);
  const auto loadedAt = std::chrono::steady_clock::now();
  const brep::Model& model = *loaded.model;
  if (std::string e = checkDisplayable(model); !e.empty()) return fail(2, cli.model + ": " + e);
  auto created = brep::Tessellator::create(model, params, kept.pool());
  if (!created.tessellator) return fail(2, created.error);
  brep::Tessellator& tess = *created.tessellator;
  // The workers start at once: level 0 tessellates while Vulkan starts up (lavapipe's pipeline
  // compilation alone takes about as long as the first level of a large model).
  const int last = tess.lastLevel();
  stream::StreamOptions streamOptions;
  streamOptions.threads = cli.threads;
  streamOptions.kept = &kept;
  stream::ProgressiveStream producer(tess, last, streamOptions);
  stream::StreamConsumer consumer(producer, model.faces().size());

  Session session;
  engine::InstanceOptions instanceOptions;
  instanceOptions.validation = cli.validate;
  auto instance = engine::createInstance(instanceOptions);
  if (!instance) return fail(1, instance.error().message);
  session.instance = std::move(*instance);
  engine::DeviceOptions deviceOptions;
  deviceOptions.name = cli.device;
  auto device = engine::createDevice(session.instance, deviceOptions);
  if (!device) return fail(1, device.error().message);
  session.device = *device;
  auto renderer = engine::Renderer::createHeadless(session.device, {width, height});
  if (!renderer) return fail(1, engineErrorLine(renderer.error()));
  session.renderer = std::move(*renderer);
  engine::Renderer& r = *session.renderer;
  // lavapipe compiles the pipelines' code at their first draw: here, while level 0 is being made.
  if (auto s = engine::warmUp(r); !s) return fail(1, engineErrorLine(s.error()));

  ModelScene link(model, r.scene());
  int next = cli.levels ? 0 : last;
  consumer.setShowLevel(next, link);
  // Fitted to the triangles' box at the first capture, as the window refits its first complete
  // level: the B-rep's box takes a B-spline face's poles, which can reach far beyond its surface (a
  // torus written as rational arcs of 120 degrees: a box 1.5 times as wide, the torus off its
  // centre), and it can miss instances. Every later level is captured from the same camera.
  std::optional<engine::Camera> camera;

  std::uint64_t pictures = 0;  // captured so far
  ProgressBar bar("render " + cli.model);
  const auto deadline = loadedAt + std::chrono::hours(2);
  while (next <= last) {
    consumer.poll(std::size_t{64} << 20, link);
    const stream::StreamProgress p = producer.progress();
    bar.update(static_cast<std::size_t>(std::max(0, p.lastCompleteLevel + 1)) * p.faceCount + p.facesDoneInLevel,
               static_cast<std::size_t>(last + 1) * p.faceCount,
               "level " + std::to_string(std::max(0, p.levelInProgress)) + "/" + std::to_string(last));
    if (consumer.completeLevel() < next) {
      if (std::chrono::steady_clock::now() > deadline) return fail(1, "tessellation did not finish in 2 hours");
      producer.waitForLevel(next, std::chrono::milliseconds(1));  // the progress bar moves meanwhile
      continue;
    }
    simulateDeviceLossIfRequested(r, pictures++);
    if (auto s = r.finishUploads(); !s) return fail(1, engineErrorLine(s.error()));
    if (!camera) {
      const engine::Bounds triangles = r.scene().bounds();
      camera = engine::standardView(*view, triangles.empty() ? link.bounds() : triangles, r.aspect(), projection);
    }
    auto image = r.capture(*camera, style);
    if (!image) return fail(1, engineErrorLine(image.error()));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - loadedAt).count();
    const stream::LevelStat& stat = consumer.levelStats()[static_cast<std::size_t>(next)];
    if (cli.levels) {
      const std::string path = levelPath(cli.output, next);
      if (auto s = engine::writePng(*image, path); !s) return fail(1, s.error().message);
      std::printf("{\"level\":%d,\"ms\":%.1f,\"triangles\":%llu,\"tolerance\":%.6g,\"faces\":%zu,\"png\":\"%s\"}\n", next,
                  ms, static_cast<unsigned long long>(stat.triangles), stat.chordal, model.faces().size(),
                  path.c_str());
      std::fflush(stdout);
    }
    if (next == last) {
      // Every face reached the last level and the stream is idle: the reports are settled.
      printFaceProblems(stderr, "cetview render", model, collectFaceProblems(tess));
      if (auto s = engine::writePng(*image, cli.output); !s) return fail(1, s.error().message);
      if (!cli.levels) {
        std::printf("render: %s: %zu faces, %llu triangles, deflection %.6g in %.1f ms on %s -> %s\n", cli.model.c_str(),
                    model.faces().size(), static_cast<unsigned long long>(stat.triangles), stat.chordal, ms,
                    session.device.name.c_str(), cli.output.c_str());
      }
    }
    ++next;
    if (next <= last) consumer.setShowLevel(next, link);
  }
  if (cli.validate && session.instance.log->count() > 0) {
    return fail(1, "the validation layer reported " + std::to_string(session.instance.log->count()) + " problem(s)");
  }
  return 0;
}

}  // namespace

Command renderCommand() {
  auto cli = std::make_shared<RenderCli>();
  Command cmd{"render", "Headless capture of MODEL (a file or 'demo') to a PNG"};
  cmd.required("model", &cli->model, "STEP, IGES or .brep file, or 'demo'")
      .required("-o,--output", &cli->output, "Output PNG")
      .option("--levels", &cli->levels, "Also write OUT-L0.png, OUT-L1.png, ... and one JSON line per level")
      .withDefault("--size", &cli->size, "Image size WxH")
      .withDefault("--view", &cli->view, "iso, front, back, left, right, top or bottom")
      .withDefault("--projection", &cli->projection, "perspective or orthographic")
      .withDefault("--deflection", &cli->deflection, "Chordal deflection: relative '0.1%' or absolute")
      .withDefault("--angle", &cli->angle, "Angular deflection in degrees")
      .withDefault("--threads", &cli->threads, "Tessellation threads")
      .option("--device", &cli->device, "Vulkan device: a substring of its name")
      .withDefault("--display", &cli->display, "shaded, shaded-edges or wireframe")
      .option("--validate", &cli->validate, "Enable the Vulkan validation layer; any report is an error");
  cmd.run = [cli] { return runRender(*cli); };
  return cmd;
}

}  // namespace cetview
