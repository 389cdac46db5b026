// `cetview [view] [MODEL]`: the interactive window. GLFW window and Vulkan engine (through
// window_glue), ImGui panels, mouse/keyboard camera, live tolerance sliders over the progressive
// stream (live_tessellation), screenshots, and --frames/--screenshot/--script so tests and demos
// drive it without a person.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "background_load.h"
#include "brep/model.h"
#include "brep/tolerance.h"
#include "camera_controller.h"
#include "commands.h"
#include "device_loss.h"
#include "engine/camera.h"
#include "engine/image.h"
#include "engine/renderer.h"
#include "frame_pacing.h"
#include "live_tessellation.h"
#include "open_dialog.h"
#include "stream/stream_threads.h"
#include "view_script.h"
#include "window_glue.h"

namespace cetview {
namespace {

constexpr std::size_t kPollBytesPerFrame = std::size_t{32} << 20;
constexpr float kTransitionSeconds = 0.35f;
constexpr double kFinestRelative = 1e-4;  // the chordal slider's finest stop: 0.01% of the diagonal
// Panel layout (pixels from the window's corners); the window tests look for panels there.
constexpr float kPanelWidth = 300.0f;
constexpr float kMargin = 8.0f;
constexpr float kMenuHeight = 24.0f;
constexpr float kFitMargin = 1.5f;  // the panels cover the window's sides

struct ViewCli {
  std::string model = "demo";
  std::string size = "1280x800";
  std::string deflection = "0.1%";
  std::string angle = "20";
  unsigned threads =
      std::max(1u, std::thread::hardware_concurrency() > 1 ? std::thread::hardware_concurrency() - 1 : 1u);
  std::string device;
  std::string view = "iso";
  std::string projection = "perspective";
  std::string display = "shaded-edges";
  bool validate = false;
  bool noVsync = false;
  int frames = 0;
  std::string screenshot;
  std::string script;
};

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "cetview view: %s\n", message.c_str());
  return code;
}

bool parseSize(const std::string& text, int& w, int& h) {
  unsigned a = 0, b = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%u%c%u%c", &a, &x, &b, &extra) != 3 || (x != 'x' && x != 'X')) return false;
  if (a < 200 || b < 150 || a > 16384 || b > 16384) return false;
  w = static_cast<int>(a), h = static_cast<int>(b);
  return true;
}

std::optional<engine::DisplayMode> parseDisplay(const std::string& s) {
  if (s == "shaded") return engine::DisplayMode::kShaded;
  if (s == "shaded-edges") return engine::DisplayMode::kShadedWithEdges;
  if (s == "wireframe") return engine::DisplayMode::kWireframe;
  return std::nullopt;
}

std::optional<engine::Projection> parseProjection(const std::string& s) {
  if (s == "perspective") return engine::Projection::kPerspective;
  if (s == "orthographic" || s == "ortho") return engine::Projection::kOrthographic;
  return std::nullopt;
}

std::optional<bool> parseOnOff(const std::string& s) {
  if (s == "on" || s == "1" || s == "true") return true;
  if (s == "off" || s == "0" || s == "false") return false;
  return std::nullopt;
}

// Resident set size of this process in MiB (Linux /proc), 0 when unknown.
double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  unsigned long long pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return static_cast<double>(resident) * 4096.0 / (1024.0 * 1024.0);
}

ImVec4 toImVec4(engine::Color8 c) {
  return ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
}
engine::Color8 fromFloat3(const float* c) {
  auto b = [](float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return engine::Color8{b(c[0]), b(c[1]), b(c[2]), 255};
}

// The assembly tree: instances grouped by their assembly path.
struct TreeNode {
  std::string name;
  std::vector<std::unique_ptr<TreeNode>> children;
  std::vector<std::uint32_t> instances;  // model instance ids directly here
};

class Viewer {
 public:
  Viewer(const ViewCli& cli, WindowGlue& glue)
      : cli_(cli), glue_(glue), r_(glue.renderer()), kept_(cli.threads) {}

  int run();

 private:
  // Opening runs in two steps: the file loads on a thread of its own (BackgroundLoad) while the
  // window goes on showing the current model, and the loaded model replaces it once done.
  void startOpen(const std::string& path);
  void cancelOpen();
  // Picks up a finished load: returns false when the run must end (the command line's model
  // failed to load; a file opened later that fails is reported and the window goes on).
  bool finishOpen();
  std::string showModel(std::unique_ptr<brep::Model> model);
  void drawLoadingPanel();
  std::string browseDirectory() const;  // where File > Open starts
  void waitForLoads();  // at exit: cancels the load in progress and waits for every load
  void buildTree();
  void fitOrView(bool animate);
  glm::vec2 viewport() const;

  void handleInput();
  void drawMenu();
  void drawTessellationPanel();
  void drawProgressPanel();
  void drawDisplayPanel();
  void drawModelPanel();
  void drawStatsPanel();
  void drawTreeNode(const TreeNode& node);
  void setInstancesVisible(const TreeNode& node, bool visible);
  bool anyVisible(const TreeNode& node) const;
  void updateHeatMap();
  // Prints faces that newly have a problem report (once per face and model) to stderr.
  void reportFaceProblems();
  void setDeflection(double absolute);
  void setAngle(double degrees);

  // Script: returns false on a bad command (the run fails with exit code 2).
  bool stepScript();
  std::string screenshotName() const;

  const ViewCli& cli_;
  WindowGlue& glue_;
  engine::Renderer& r_;
  // The tessellation threads, started with the window and kept for every model it opens (before
  // live_: they outlive its stream).
  stream::StreamThreads kept_;
  std::unique_ptr<LiveTessellation> live_;                  // null until the first model has loaded
  std::unique_ptr<BackgroundLoad> loading_;                 // the load in progress, if any
  std::vector<std::unique_ptr<BackgroundLoad>> abandoned_;  // cancelled loads still running out
  bool commandLineLoad_ = true;  // the load in progress is the command line's model
  double loadSeconds_ = 0;       // how long the open model took to load
  std::string loadError_;        // the command line's model failed to load: the run ends with it
  brep::MeshParams initialParams_;
  CameraController camera_;
  engine::StandardView initialView_ = engine::StandardView::kIso;
  engine::Camera openCamera_;  // the camera as the model opened
  bool refitPending_ = false;  // fit the first complete level's triangles
  engine::ViewStyle style_;
  bool heatMap_ = false;
  int heatLevel_ = -1;  // the level the heat colours were measured at (-1: none shown)
  double heatWorst_ = 0;
  std::unique_ptr<TreeNode> tree_;

  // Panels.
  bool showTessellation_ = true, showProgress_ = true, showDisplay_ = true, showModel_ = true,
       showStats_ = true;
  bool absoluteUnits_ = false;
  float angleSlider_ = 20.0f;
  OpenDialog openDialog_;
  std::vector<bool> problemPrinted_;  // per face of the open model
  std::string status_;  // one line shown in the stats panel (errors of open, screenshot)

  // Frame timing.
  std::deque<double> frameTimes_;  // seconds, the last 60
  double lastFrameMs_ = 0;
  std::uint64_t frame_ = 0;
  std::uint64_t modelFrames_ = 0;  // frames drawn with a model open (--frames counts these)

  // Requests.
  std::string pendingOpen_;
  std::string pendingScreenshot_;
  bool quit_ = false;

  // Script.
  std::vector<ScriptCommand> script_;
  std::size_t scriptNext_ = 0;
  int waitFrames_ = 0;
  int waitLevel_ = -2;  // -2: not waiting; -1: the slider's level; else that level
  std::chrono::steady_clock::time_point waitUntil_{};  // 'wait seconds': the script idles until then
  bool waitingSeconds_ = false;
  std::uint64_t framesWhileWaitingSeconds_ = 0;
  int exitCode_ = 0;

  // Redraw on change: a frame is drawn when something it shows may have changed; otherwise the
  // loop sleeps in glfwWaitEventsTimeout, leaving the cores to the tessellation workers (and the
  // battery alone when the model is still).
  bool frameNeeded();
  std::uint64_t seenEvents_ = ~std::uint64_t{0};
  int settleFrames_ = 0;  // frames still drawn after the last window event (ImGui settles over a few)
  FramePacing pacing_;    // frames for tessellation data: completed levels at once, others paced
  bool polledSinceFrame_ = false;  // records arrived since the last frame
  std::chrono::steady_clock::time_point lastDrawn_{};
};

glm::vec2 Viewer::viewport() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(glue_.window(), &w, &h);
  return glm::vec2(static_cast<float>(w), static_cast<float>(h));
}

void Viewer::startOpen(const std::string& path) {
  if (loading_) cancelOpen();
  if (live_) live_->holdFinerLevels(true);  // the cores go to the load; the model is about to go
  commandLineLoad_ = frame_ == 0 && !live_;
  loading_ = std::make_unique<BackgroundLoad>(path, [] { glfwPostEmptyEvent(); });
  glfwSetWindowTitle(glue_.window(), ("cetview - loading " + path).c_str());
}

void Viewer::cancelOpen() {
  if (!loading_) return;
  // The window is free at once; the load stops at its next check and is reaped when it has.
  loading_->cancel();
  status_ = "cancelled loading " + loading_->path();
  std::printf("cancelled: %s\n", loading_->path().c_str());
  std::fflush(stdout);
  abandoned_.push_back(std::move(loading_));
  if (live_) live_->holdFinerLevels(false);
  if (live_) glfwSetWindowTitle(glue_.window(), ("cetview - " + live_->model().source()).c_str());
}

bool Viewer::finishOpen() {
  abandoned_.erase(std::remove_if(abandoned_.begin(), abandoned_.end(),
                                  [](const std::unique_ptr<BackgroundLoad>& l) { return l->done(); }),
                   abandoned_.end());
  if (!loading_ || !loading_->done()) return true;
  const std::unique_ptr<BackgroundLoad> load = std::move(loading_);
  const double seconds = load->progress().seconds;
  brep::LoadResult loaded = load->take();
  std::string error = loaded ? showModel(std::move(loaded.model)) : loaded.error;
  if (error.empty()) {
    status_.clear();
    loadSeconds_ = seconds;
    return true;
  }
  if (commandLineLoad_) {
    loadError_ = error;  // as when the command line names a bad file: one line, exit code 2
    return false;
  }
  status_ = error;
  std::fprintf(stderr, "cetview view: %s\n", error.c_str());
  if (live_) live_->holdFinerLevels(false);
  glfwSetWindowTitle(glue_.window(), live_ ? ("cetview - " + live_->model().source()).c_str() : "cetview");
  return true;
}

void Viewer::waitForLoads() {
  if (loading_) cancelOpen();
  // Loads stop at OpenCASCADE's next check, but its STEP and IGES parser cannot be stopped: say
  // why the window is slow to close rather than hang without a word.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  auto running = [&] {
    return std::any_of(abandoned_.begin(), abandoned_.end(),
                       [](const std::unique_ptr<BackgroundLoad>& l) { return !l->done(); });
  };
  while (running() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (running())
    std::fprintf(stderr, "cetview view: waiting for OpenCASCADE to finish parsing the cancelled file\n");
  abandoned_.clear();  // joins
}

void Viewer::drawLoadingPanel() {
  const BackgroundLoad::Progress p = loading_->progress();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, kMenuHeight + kMargin), ImGuiCond_Always,
                          ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(440.0f, 0.0f), ImGuiCond_Always);
  ImGui::Begin("Loading", nullptr,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", loading_->path().c_str());
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "%s  %.0f%%", p.phase.c_str(), 100.0 * p.fraction);
  ImGui::ProgressBar(static_cast<float>(p.fraction), ImVec2(-1.0f, 0.0f), overlay);
  ImGui::Text("%.1f s", p.seconds);
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)")) cancelOpen();
  ImGui::End();
}

std::string Viewer::showModel(std::unique_ptr<brep::Model> model) {
  const std::string path = model->source();
  if (std::string e = checkDisplayable(*model); !e.empty()) return path + ": " + e;
  // The requested deflection: relative to this model's diagonal, or absolute as given.
  double absolute = 0;
  const double diagonal = model->bounds().diagonal();
  if (std::string e = brep::resolveDeflection(initialParams_.chordal, diagonal, absolute); !e.empty())
    return e;
  if (live_)
    absolute =
        live_->requestedDeflection() / live_->diagonal() * diagonal;  // keep the slider's relative position
  (void)r_.waitIdle();
  live_.reset();
  heatLevel_ = -1;
  LiveOptions options;
  options.finestRelative = kFinestRelative;
  options.chordalAbsolute = absolute;
  options.angleDeg = angleSlider_;
  options.threads = cli_.threads;
  options.kept = &kept_;
  options.wake = [] { glfwPostEmptyEvent(); };
  auto created = LiveTessellation::create(std::move(model), r_.scene(), options);
  if (!created.live) return created.error;
  live_ = std::move(created.live);
  problemPrinted_.assign(live_->model().faces().size(), false);
  buildTree();
  const glm::vec2 vp = viewport();
  const float aspect = vp.y > 0 ? vp.x / vp.y : 1.0f;
  camera_.setFitMargin(kFitMargin);
  camera_.reset(
      engine::standardView(initialView_, live_->modelScene().bounds(), aspect, camera_.camera().projection),
      live_->modelScene().bounds());
  camera_.viewStandard(initialView_, aspect, 0.0f);
  openCamera_ = camera_.camera();
  refitPending_ = true;
  pacing_.reset(std::chrono::steady_clock::now());
  glfwSetWindowTitle(glue_.window(), ("cetview - " + live_->model().source()).c_str());
  std::printf("opened: %s (%zu faces, %d levels down to %.6g)\n", live_->model().source().c_str(),
              live_->model().faces().size(), live_->lastLevel() + 1, live_->finestAbsolute());
  std::fflush(stdout);
  return {};
}

void Viewer::buildTree() {
  tree_ = std::make_unique<TreeNode>();
  tree_->name = live_->model().source();
  const auto& instances = live_->model().instances();
  for (std::uint32_t i = 0; i < instances.size(); ++i) {
    TreeNode* node = tree_.get();
    // The path names the assemblies above the instance; the instance itself is a leaf.
    for (const std::string& name : instances[i].path) {
      auto it = std::find_if(node->children.begin(), node->children.end(),
                             [&](const std::unique_ptr<TreeNode>& c) { return c->name == name; });
      if (it == node->children.end()) {
        node->children.push_back(std::make_unique<TreeNode>());
        node->children.back()->name = name;
        it = node->children.end() - 1;
      }
      node = it->get();
    }
    node->instances.push_back(i);
  }
}

void Viewer::setDeflection(double absolute) {
  live_->setDeflection(absolute);
}

void Viewer::setAngle(double degrees) {
  angleSlider_ = static_cast<float>(degrees);
  (void)r_.waitIdle();
  heatLevel_ = -1;
  if (std::string e = live_->setAngle(degrees); !e.empty()) status_ = e;
}

void Viewer::handleInput() {
  ImGuiIO& io = ImGui::GetIO();
  const glm::vec2 vp = viewport();
  const float aspect = vp.y > 0 ? vp.x / vp.y : 1.0f;
  if (!io.WantCaptureMouse) {
    // ImGui reports positions in window coordinates; the camera works in framebuffer pixels.
    const glm::vec2 scale(io.DisplayFramebufferScale.x, io.DisplayFramebufferScale.y);
    const glm::vec2 delta = glm::vec2(io.MouseDelta.x, io.MouseDelta.y) * scale;
    const glm::vec2 cursor = glm::vec2(io.MousePos.x, io.MousePos.y) * scale;
    const bool moved = delta.x != 0.0f || delta.y != 0.0f;
    if (moved && (ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                  (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift))) {
      camera_.pan(delta, vp);
    } else if (moved && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      camera_.orbit(delta);
    }
    if (io.MouseWheel != 0.0f) camera_.zoom(io.MouseWheel, cursor, vp);
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !camera_.rayHitsBounds(cursor, vp)) {
      camera_.fitAll(aspect, kTransitionSeconds);
    }
  }
  if (!io.WantCaptureKeyboard) {
    if (loading_ && ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) cancelOpen();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_O, false)) openDialog_.open(browseDirectory());
    if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) camera_.fitAll(aspect, kTransitionSeconds);
    const std::pair<int, engine::StandardView> keys[] = {
        {GLFW_KEY_0, engine::StandardView::kIso},   {GLFW_KEY_1, engine::StandardView::kFront},
        {GLFW_KEY_2, engine::StandardView::kBack},  {GLFW_KEY_3, engine::StandardView::kLeft},
        {GLFW_KEY_4, engine::StandardView::kRight}, {GLFW_KEY_5, engine::StandardView::kTop},
        {GLFW_KEY_6, engine::StandardView::kBottom}};
    for (const auto& [key, view] : keys) {
      if (ImGui::IsKeyPressed(key, false)) camera_.viewStandard(view, aspect, kTransitionSeconds);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) {
      camera_.setProjection(camera_.camera().projection == engine::Projection::kPerspective
                                ? engine::Projection::kOrthographic
                                : engine::Projection::kPerspective);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_D, false)) {
      style_.mode =
          style_.mode == engine::DisplayMode::kShaded ? engine::DisplayMode::kShadedWithEdges
          : style_.mode == engine::DisplayMode::kShadedWithEdges && glue_.device().features.fillModeNonSolid
              ? engine::DisplayMode::kWireframe
              : engine::DisplayMode::kShaded;
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) pendingScreenshot_ = screenshotName();
  }
}

std::string Viewer::screenshotName() const {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "cetview-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return name;
}

void Viewer::drawMenu() {
  const glm::vec2 vp = viewport();
  const float aspect = vp.y > 0 ? vp.x / vp.y : 1.0f;
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...", "Ctrl+O")) openDialog_.open(browseDirectory());
    if (ImGui::MenuItem("Open demo part")) pendingOpen_ = "demo";
    if (ImGui::MenuItem("Screenshot", "F12")) pendingScreenshot_ = screenshotName();
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) quit_ = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    const engine::StandardView views[] = {engine::StandardView::kIso,   engine::StandardView::kFront,
                                          engine::StandardView::kBack,  engine::StandardView::kLeft,
                                          engine::StandardView::kRight, engine::StandardView::kTop,
                                          engine::StandardView::kBottom};
    const char* shortcuts[] = {"0", "1", "2", "3", "4", "5", "6"};
    for (int i = 0; i < 7; ++i) {
      if (ImGui::MenuItem(engine::viewName(views[i]), shortcuts[i]))
        camera_.viewStandard(views[i], aspect, kTransitionSeconds);
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Fit all", "F")) camera_.fitAll(aspect, kTransitionSeconds);
    const bool ortho = camera_.camera().projection == engine::Projection::kOrthographic;
    if (ImGui::MenuItem("Orthographic", "P", ortho)) {
      camera_.setProjection(ortho ? engine::Projection::kPerspective : engine::Projection::kOrthographic);
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Panels")) {
    ImGui::MenuItem("Tessellation", nullptr, &showTessellation_);
    ImGui::MenuItem("Progress", nullptr, &showProgress_);
    ImGui::MenuItem("Display", nullptr, &showDisplay_);
    ImGui::MenuItem("Model", nullptr, &showModel_);
    ImGui::MenuItem("Stats", nullptr, &showStats_);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();

  if (std::optional<std::string> chosen = openDialog_.draw()) pendingOpen_ = *chosen;
}

std::string Viewer::browseDirectory() const {
  // The folder of the model shown (or being loaded), else the working directory.
  const std::string source = loading_ ? loading_->path() : live_ ? live_->model().source() : std::string();
  const auto slash = source.find_last_of('/');
  if (source == "demo" || slash == std::string::npos) return ".";
  return slash == 0 ? "/" : source.substr(0, slash);
}

void Viewer::drawTessellationPanel() {
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMenuHeight + kMargin), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 170.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Tessellation", &showTessellation_)) {
    ImGui::End();
    return;
  }
  const double diag = live_->diagonal();
  ImGui::TextUnformatted("Chordal deflection");
  ImGui::SameLine();
  if (ImGui::RadioButton("%", !absoluteUnits_)) absoluteUnits_ = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("abs", absoluteUnits_)) absoluteUnits_ = true;
  // Logarithmic slider from the coarsest level's tolerance down to the finest planned level.
  const double unit = absoluteUnits_ ? 1.0 : 100.0 / diag;
  float value = static_cast<float>(live_->requestedDeflection() * unit);
  const float lo = static_cast<float>(live_->finestAbsolute() * unit);
  const float hi =
      static_cast<float>(std::max(live_->coarsestAbsolute(), live_->finestAbsolute() * 2) * unit);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderFloat("##chordal", &value, lo, hi, absoluteUnits_ ? "%.5g" : "%.4f %%",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    setDeflection(static_cast<double>(value) / unit);
  }
  const int target = live_->targetLevel();
  const double tol = live_->levelTolerance(target);
  ImGui::Text("level %d of %d: %.4g (%.4f%%)", target, live_->lastLevel(), tol, 100.0 * tol / diag);
  ImGui::Text("shown: level %d complete", live_->consumer().completeLevel());
  ImGui::TextUnformatted("Angular deflection (degrees)");
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##angle", &angleSlider_, 2.0f, 60.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp);
  // A new angle re-plans the schedule: restart once the drag ends, not at every step of it.
  if (ImGui::IsItemDeactivatedAfterEdit()) setAngle(angleSlider_);
  ImGui::End();
}

void Viewer::drawProgressPanel() {
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMenuHeight + 2 * kMargin + 170.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 245.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Progress", &showProgress_)) {
    ImGui::End();
    return;
  }
  const stream::StreamProgress p = live_->progress();
  const auto& stats = live_->consumer().levelStats();
  const int shownLevels = std::max(live_->targetLevel(), live_->consumer().completeLevel());
  for (int k = 0; k <= shownLevels; ++k) {
    float fraction = 0.0f;
    if (k < static_cast<int>(stats.size())) {
      fraction = 1.0f;
    } else if (k == p.levelInProgress && p.faceCount > 0) {
      fraction = static_cast<float>(p.facesDoneInLevel) / static_cast<float>(p.faceCount);
    }
    char overlay[128];
    if (k < static_cast<int>(stats.size())) {
      // Each level's own time (since the previous one completed) and the cumulative time.
      const stream::LevelStat& st = stats[static_cast<std::size_t>(k)];
      const double own = k == 0 ? st.ms : st.ms - stats[static_cast<std::size_t>(k - 1)].ms;
      std::snprintf(overlay, sizeof overlay, "L%d  %.0f ms (at %.0f)  %llu tris", k, own, st.ms,
                    static_cast<unsigned long long>(st.triangles));
    } else {
      std::snprintf(overlay, sizeof overlay, "L%d  %.4g", k, live_->levelTolerance(k));
    }
    ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), overlay);
  }
  ImGui::Text("faces done: %u / %u (level %d)", p.levelInProgress >= 0 ? p.facesDoneInLevel : p.faceCount,
              p.faceCount, p.levelInProgress >= 0 ? p.levelInProgress : p.lastCompleteLevel);
  ImGui::Text("triangles shown: %llu", static_cast<unsigned long long>(live_->consumer().shownTriangles()));
  if (!stats.empty()) {
    ImGui::Text("first frame: %.1f ms", stats[0].ms);
  } else {
    ImGui::Text("first frame: waiting (%.1f s)", live_->secondsSinceStart());
  }
  ImGui::End();
}

void Viewer::drawDisplayPanel() {
  const glm::vec2 vp = viewport();
  ImGui::SetNextWindowPos(ImVec2(vp.x - kPanelWidth - kMargin, kMenuHeight + kMargin),
                          ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 200.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Display", &showDisplay_)) {
    ImGui::End();
    return;
  }
  int mode = static_cast<int>(style_.mode == engine::DisplayMode::kShaded            ? 0
                              : style_.mode == engine::DisplayMode::kShadedWithEdges ? 1
                                                                                     : 2);
  ImGui::RadioButton("shaded", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("+ edges", &mode, 1);
  if (glue_.device().features.fillModeNonSolid) {
    ImGui::SameLine();
    ImGui::RadioButton("wireframe", &mode, 2);
  }
  style_.mode = mode == 0   ? engine::DisplayMode::kShaded
                : mode == 1 ? engine::DisplayMode::kShadedWithEdges
                            : engine::DisplayMode::kWireframe;
  ImGui::Checkbox("file colours", &style_.fileColors);
  if (ImGui::Checkbox("deviation heat map", &heatMap_) && !heatMap_) {
    live_->hideHeatMap();
    heatLevel_ = -1;
  }
  if (heatMap_) {
    if (heatLevel_ < 0 || heatLevel_ != live_->targetLevel()) {
      ImGui::TextUnformatted("measuring when the level completes...");
    } else {
      ImGui::Text("worst triangle: %.2f x tolerance", heatWorst_);
    }
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float w = ImGui::GetContentRegionAvail().x;
    for (int i = 0; i < 32; ++i) {
      const engine::Color8 c = LiveTessellation::heatColor(i / 31.0);
      draw->AddRectFilled(ImVec2(at.x + w * i / 32.0f, at.y),
                          ImVec2(at.x + w * (i + 1) / 32.0f, at.y + 10.0f), IM_COL32(c.r, c.g, c.b, 255));
    }
    ImGui::Dummy(ImVec2(w, 12.0f));
    ImGui::TextUnformatted("0                 deviation / tolerance               1");
  }
  bool ortho = camera_.camera().projection == engine::Projection::kOrthographic;
  if (ImGui::Checkbox("orthographic", &ortho)) {
    camera_.setProjection(ortho ? engine::Projection::kOrthographic : engine::Projection::kPerspective);
  }
  float top[3] = {style_.backgroundTop.r / 255.0f, style_.backgroundTop.g / 255.0f,
                  style_.backgroundTop.b / 255.0f};
  float bottom[3] = {style_.backgroundBottom.r / 255.0f, style_.backgroundBottom.g / 255.0f,
                     style_.backgroundBottom.b / 255.0f};
  if (ImGui::ColorEdit3("background top", top, ImGuiColorEditFlags_NoInputs))
    style_.backgroundTop = fromFloat3(top);
  if (ImGui::ColorEdit3("background bottom", bottom, ImGuiColorEditFlags_NoInputs)) {
    style_.backgroundBottom = fromFloat3(bottom);
  }
  (void)toImVec4;
  ImGui::End();
}

bool Viewer::anyVisible(const TreeNode& node) const {
  for (std::uint32_t i : node.instances) {
    if (live_->instanceVisible(i)) return true;
  }
  for (const auto& c : node.children) {
    if (anyVisible(*c)) return true;
  }
  return false;
}

void Viewer::setInstancesVisible(const TreeNode& node, bool visible) {
  for (std::uint32_t i : node.instances) live_->setInstanceVisible(i, visible);
  for (const auto& c : node.children) setInstancesVisible(*c, visible);
}

void Viewer::drawTreeNode(const TreeNode& node) {
  ImGui::PushID(&node);
  bool visible = anyVisible(node);
  if (ImGui::Checkbox("##v", &visible)) setInstancesVisible(node, visible);
  ImGui::SameLine();
  const bool open =
      ImGui::TreeNodeEx(node.name.empty() ? "(unnamed)" : node.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
  if (open) {
    for (const auto& c : node.children) drawTreeNode(*c);
    const auto& instances = live_->model().instances();
    const auto& parts = live_->model().parts();
    for (std::uint32_t i : node.instances) {
      ImGui::PushID(static_cast<int>(i));
      bool v = live_->instanceVisible(i);
      if (ImGui::Checkbox("##i", &v)) live_->setInstanceVisible(i, v);
      ImGui::SameLine();
      const brep::PartInfo& part = parts[instances[i].part];
      const std::string& name = !instances[i].name.empty() ? instances[i].name : part.name;
      ImGui::Text("%s (%u faces)", name.empty() ? "(unnamed)" : name.c_str(), part.faceCount);
      ImGui::PopID();
    }
    ImGui::TreePop();
  }
  ImGui::PopID();
}

void Viewer::drawModelPanel() {
  const glm::vec2 vp = viewport();
  ImGui::SetNextWindowPos(ImVec2(vp.x - kPanelWidth - kMargin, kMenuHeight + 2 * kMargin + 200.0f),
                          ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 190.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Model", &showModel_)) {
    ImGui::End();
    return;
  }
  const brep::Model& m = live_->model();
  ImGui::TextWrapped("%s", m.source().c_str());
  ImGui::Text("%zu faces, %zu parts, %zu instances", m.faces().size(), m.parts().size(),
              m.instances().size());
  ImGui::Text("loaded in %.2f s", loadSeconds_);
  const brep::Bounds b = m.bounds();
  if (!b.empty()) {
    ImGui::Text("min %.4g %.4g %.4g", b.min[0], b.min[1], b.min[2]);
    ImGui::Text("max %.4g %.4g %.4g", b.max[0], b.max[1], b.max[2]);
    ImGui::Text("size %.4g x %.4g x %.4g", b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]);
  }
  if (const std::vector<FaceProblem>* problems = live_->faceProblems(); problems && !problems->empty()) {
    const std::string header = "Faces with problems (" + std::to_string(problems->size()) + ")###problems";
    if (ImGui::CollapsingHeader(header.c_str())) {
      constexpr std::size_t kShown = 200;
      for (std::size_t i = 0; i < problems->size() && i < kShown; ++i)
        ImGui::TextWrapped("%s", describeFaceProblem(m, (*problems)[i]).c_str());
      if (problems->size() > kShown) ImGui::Text("... and %zu more", problems->size() - kShown);
    }
  }
  ImGui::Separator();
  if (tree_) drawTreeNode(*tree_);
  ImGui::End();
}

void Viewer::reportFaceProblems() {
  const std::vector<FaceProblem>* problems = live_->faceProblems();
  if (!problems) return;
  std::vector<FaceProblem> fresh;
  for (const FaceProblem& p : *problems) {
    if (problemPrinted_[p.face]) continue;
    problemPrinted_[p.face] = true;
    fresh.push_back(p);
  }
  printFaceProblems(stderr, "cetview view", live_->model(), fresh);
}

void Viewer::drawStatsPanel() {
  const glm::vec2 vp = viewport();
  ImGui::SetNextWindowPos(ImVec2(kMargin, vp.y - 120.0f - kMargin), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 120.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Stats", &showStats_)) {
    ImGui::End();
    return;
  }
  double sum = 0;
  for (double t : frameTimes_) sum += t;
  const double fps = sum > 0 ? static_cast<double>(frameTimes_.size()) / sum : 0;
  ImGui::Text("%.1f fps, frame %.2f ms", fps, lastFrameMs_);
  ImGui::TextWrapped("%s", glue_.device().name.c_str());
  ImGui::Text("memory: %.0f MiB resident", residentMiB());
  ImGui::Text("scene: %u vertices, %llu triangles", r_.scene().vertexCount(),
              static_cast<unsigned long long>(r_.committedTriangles()));
  if (ImGui::Button("Screenshot")) pendingScreenshot_ = screenshotName();
  if (!status_.empty()) {
    ImGui::SameLine();
    ImGui::TextWrapped("%s", status_.c_str());
  }
  ImGui::End();
}

void Viewer::updateHeatMap() {
  if (!heatMap_ || heatLevel_ == live_->targetLevel()) return;
  // The slider moved: show the model itself until the new level is complete and measured.
  if (live_->heatMapShown()) live_->hideHeatMap();
  if (live_->showHeatMap(cli_.threads, &heatWorst_)) heatLevel_ = live_->targetLevel();
}

bool Viewer::frameNeeded() {
  constexpr int kSettleFrames = 3;
  const auto now = std::chrono::steady_clock::now();
  const std::uint64_t events = glue_.inputEvents();
  if (events != seenEvents_) seenEvents_ = events, settleFrames_ = kSettleFrames;
  if (settleFrames_ > 0) {
    --settleFrames_;
    return true;
  }
  if (live_ && pacing_.due(now, live_->consumer().completeLevel(),
                           polledSinceFrame_ || r_.scene().uploadsPending(), r_.scene().uploadsPending()))
    return true;
  const bool scriptBusy = waitFrames_ > 0 || waitLevel_ != -2 || (waitingSeconds_ && now >= waitUntil_) ||
                          (!waitingSeconds_ && scriptNext_ < script_.size());
  // While a file or the model's levels load, the progress panels' clocks move even when nothing
  // has finished.
  const bool progressTick =
      (loading_ || (live_ && !live_->idle())) && now - lastDrawn_ > std::chrono::milliseconds(250);
  // The heat map is measured on a drawn frame once the workers are done (updateHeatMap), which
  // may be after the frame that showed the level complete.
  const bool heatMapDue = live_ && heatMap_ && heatLevel_ != live_->targetLevel() && live_->idle();
  return frame_ < kSettleFrames || camera_.animating() || scriptBusy || cli_.frames > 0 ||
         !pendingScreenshot_.empty() || !pendingOpen_.empty() || quit_ || progressTick || heatMapDue;
}

bool Viewer::stepScript() {
  if (waitFrames_ > 0) {
    --waitFrames_;
    return true;
  }
  if (waitingSeconds_) {
    if (std::chrono::steady_clock::now() < waitUntil_) return true;
    waitingSeconds_ = false;
  }
  if (waitLevel_ != -2) {
    if (loading_) return true;  // the level of the model being opened
    if (!live_) {
      waitLevel_ = -2;
      std::fprintf(stderr, "cetview view: %s: 'wait level' with no model open\n", cli_.script.c_str());
      exitCode_ = 2;
      quit_ = true;
      return false;
    }
    const int level = waitLevel_ == -1 ? live_->targetLevel() : std::min(waitLevel_, live_->lastLevel());
    if (live_->consumer().completeLevel() < level || r_.scene().uploadsPending()) return true;
    if (heatMap_ && heatLevel_ != live_->targetLevel()) return true;
    waitLevel_ = -2;
  }
  if (camera_.animating() || !pendingOpen_.empty() || !pendingScreenshot_.empty()) return true;
  if (scriptNext_ >= script_.size()) return true;
  {
    // A load in progress holds every command but those that do not need its model.
    const ScriptCommand& next = script_[scriptNext_];
    const bool independent =
        next.name == "cancel" || next.name == "quit" || (next.name == "wait" && next.args[0] != "level");
    if (loading_ && !independent) return true;
  }
  const ScriptCommand& c = script_[scriptNext_++];
  const glm::vec2 vp = viewport();
  const float aspect = vp.y > 0 ? vp.x / vp.y : 1.0f;
  const std::string where = cli_.script + ":" + std::to_string(c.line) + ": ";
  auto bad = [&](const std::string& why) {
    std::fprintf(stderr, "cetview view: %s%s\n", where.c_str(), why.c_str());
    exitCode_ = 2;
    quit_ = true;
    return false;
  };
  auto number = [&](const std::string& s, double& out) {
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
  };
  double a = 0, b = 0;
  if (!live_ && (c.name == "deflection" || c.name == "angle" || c.name == "heatmap"))
    return bad("'" + c.name + "' with no model open");
  if (c.name == "deflection") {
    brep::Deflection d;
    if (std::string e = brep::parseDeflection(c.args[0], d); !e.empty()) return bad(e);
    setDeflection(d.relative ? d.value * live_->diagonal() : d.value);
  } else if (c.name == "angle") {
    double deg = 0;
    if (std::string e = brep::parseAngle(c.args[0], deg); !e.empty()) return bad(e);
    setAngle(deg);
  } else if (c.name == "view") {
    const auto v = engine::parseStandardView(c.args[0]);
    if (!v) return bad("unknown view '" + c.args[0] + "'");
    camera_.viewStandard(*v, aspect, kTransitionSeconds);
  } else if (c.name == "projection") {
    const auto p = parseProjection(c.args[0]);
    if (!p) return bad("projection must be perspective or orthographic");
    camera_.setProjection(*p);
  } else if (c.name == "display") {
    const auto m = parseDisplay(c.args[0]);
    if (!m) return bad("display must be shaded, shaded-edges or wireframe");
    style_.mode = *m;
  } else if (c.name == "colors" || c.name == "heatmap") {
    const auto on = parseOnOff(c.args[0]);
    if (!on) return bad("'" + c.name + "' takes on or off");
    if (c.name == "colors") {
      style_.fileColors = *on;
    } else {
      if (heatMap_ && !*on) {
        live_->hideHeatMap();
        heatLevel_ = -1;
      }
      heatMap_ = *on;
    }
  } else if (c.name == "fit") {
    camera_.fitAll(aspect, kTransitionSeconds);
  } else if (c.name == "panel") {
    const auto on = parseOnOff(c.args[1]);
    bool* panel = c.args[0] == "tessellation" ? &showTessellation_
                  : c.args[0] == "progress"   ? &showProgress_
                  : c.args[0] == "display"    ? &showDisplay_
                  : c.args[0] == "model"      ? &showModel_
                  : c.args[0] == "stats"      ? &showStats_
                                              : nullptr;
    if (!panel || !on) return bad("panel tessellation|progress|display|model|stats on|off");
    *panel = *on;
  } else if (c.name == "orbit" || c.name == "pan") {
    if (!number(c.args[0], a) || !number(c.args[1], b))
      return bad("'" + c.name + "' takes two numbers (pixels)");
    if (c.name == "orbit") {
      camera_.orbit(glm::vec2(static_cast<float>(a), static_cast<float>(b)));
    } else {
      camera_.pan(glm::vec2(static_cast<float>(a), static_cast<float>(b)), vp);
    }
  } else if (c.name == "zoom") {
    if (!number(c.args[0], a)) return bad("'zoom' takes a number of wheel steps");
    camera_.zoom(static_cast<float>(a), vp * 0.5f, vp);
  } else if (c.name == "wait") {
    if (c.args[0] == "frames") {
      if (!number(c.args[1], a) || a < 0 || a > 1e6) return bad("'wait frames' takes 0 to 1000000");
      waitFrames_ = static_cast<int>(a);
    } else if (c.args[0] == "seconds") {
      if (!number(c.args[1], a) || a < 0 || a > 3600) return bad("'wait seconds' takes 0 to 3600");
      waitingSeconds_ = true;
      waitUntil_ = std::chrono::steady_clock::now() + std::chrono::microseconds(static_cast<long long>(a * 1e6));
    } else if (c.args[1] == "target") {
      waitLevel_ = -1;
    } else {
      if (!number(c.args[1], a) || a < 0 || a > 64)
        return bad("'wait level' takes a level number or 'target'");
      waitLevel_ = static_cast<int>(a);
    }
  } else if (c.name == "screenshot") {
    pendingScreenshot_ = c.args[0];
  } else if (c.name == "open") {
    pendingOpen_ = c.args[0];
  } else if (c.name == "quit") {
    quit_ = true;
  } else if (c.name == "cancel") {
    cancelOpen();
  } else if (c.name == "browse") {
    openDialog_.open(c.args[0]);
  }
  return true;
}

int Viewer::run() {
  if (!parseProjection(cli_.projection)) return fail(2, "--projection must be perspective or orthographic");
  const auto view = engine::parseStandardView(cli_.view);
  if (!view)
    return fail(2, "--view '" + cli_.view + "' must be iso, front, back, left, right, top or bottom");
  initialView_ = *view;
  const auto display = parseDisplay(cli_.display);
  if (!display) return fail(2, "--display must be shaded, shaded-edges or wireframe");
  style_.mode = *display;
  if (std::string e = brep::parseDeflection(cli_.deflection, initialParams_.chordal); !e.empty())
    return fail(2, e);
  if (std::string e = brep::parseAngle(cli_.angle, initialParams_.angleDeg); !e.empty()) return fail(2, e);
  angleSlider_ = static_cast<float>(initialParams_.angleDeg);
  if (cli_.frames < 0) return fail(2, "--frames must be 0 (no limit) or more");
  if (!cli_.script.empty()) {
    ScriptParse parsed = loadScript(cli_.script);
    if (!parsed.error.empty()) return fail(2, parsed.error);
    script_ = std::move(parsed.commands);
  }
  {
    engine::Camera start;
    start.projection = *parseProjection(cli_.projection);
    camera_.reset(start, engine::Bounds{});
  }
  startOpen(cli_.model);

  // Files dropped onto the window open on the next frame.
  glfwSetWindowUserPointer(glue_.window(), this);
  glfwSetDropCallback(glue_.window(), [](GLFWwindow* w, int count, const char** paths) {
    if (count > 0) static_cast<Viewer*>(glfwGetWindowUserPointer(w))->pendingOpen_ = paths[0];
  });

  auto previous = std::chrono::steady_clock::now();
  int extraFrames = 0;  // frames spent retrying a screenshot of a skipped (out-of-date) frame
  bool slept = false;   // the last pass drew nothing
  while (true) {
    if (slept) {
      // Wakes on any window event; while the model loads, soon enough to pick up what arrives.
      // A finished load and a completed level post an event.
      glfwWaitEventsTimeout(live_ && !live_->idle() ? 0.004 : loading_ ? 0.05 : 0.1);
    } else {
      glfwPollEvents();
    }
    if (glfwWindowShouldClose(glue_.window())) quit_ = true;

    if (!pendingOpen_.empty()) {
      const std::string path = std::move(pendingOpen_);
      pendingOpen_.clear();
      startOpen(path);
    }
    if (!finishOpen()) return fail(2, loadError_);
    if (live_) {
      if (live_->poll(kPollBytesPerFrame) > 0) polledSinceFrame_ = true;
      reportFaceProblems();
    }
    if (!frameNeeded()) {
      slept = true;
      continue;
    }
    const auto now = std::chrono::steady_clock::now();
    // After a sleep the time since the last frame is no frame time.
    const double dt = slept ? 0.0 : std::chrono::duration<double>(now - previous).count();
    previous = now;
    if (!slept) {
      lastFrameMs_ = dt * 1000.0;
      frameTimes_.push_back(dt);
      if (frameTimes_.size() > 60) frameTimes_.pop_front();
    }
    slept = false;
    lastDrawn_ = now;
    if (waitingSeconds_) ++framesWhileWaitingSeconds_;
    // The triangles' box once they exist (a file's B-rep box can miss instances), else the model's.
    const engine::Bounds sceneBounds = r_.scene().bounds();
    if (live_) camera_.setBounds(sceneBounds.empty() ? live_->modelScene().bounds() : sceneBounds);
    if (refitPending_ && live_ && live_->consumer().completeLevel() >= 0 && !sceneBounds.empty()) {
      // The first complete level: fit it, unless someone has moved the camera already.
      refitPending_ = false;
      const engine::Camera& c = camera_.camera();
      if (!camera_.animating() && c.target == openCamera_.target && c.direction == openCamera_.direction &&
          c.distance == openCamera_.distance && c.orthoHeight == openCamera_.orthoHeight) {
        const glm::vec2 vp = viewport();
        camera_.viewStandard(initialView_, vp.y > 0 ? vp.x / vp.y : 1.0f, 0.0f);
      }
    }
    camera_.update(static_cast<float>(dt));
    if (live_) updateHeatMap();

    glue_.newImGuiFrame();
    drawMenu();
    if (live_) {
      if (showTessellation_) drawTessellationPanel();
      if (showProgress_) drawProgressPanel();
      if (showDisplay_) drawDisplayPanel();
      if (showModel_) drawModelPanel();
    }
    if (showStats_) drawStatsPanel();
    if (loading_) drawLoadingPanel();
    handleInput();
    if (!script_.empty()) stepScript();
    glue_.finishImGuiFrame();

    // --frames counts the frames that show a model: those drawn while the first one loads do not.
    const bool lastFrame =
        quit_ || (cli_.frames > 0 && live_ && modelFrames_ + 1 >= static_cast<std::uint64_t>(cli_.frames));
    std::string shot = pendingScreenshot_;
    if (lastFrame && !cli_.screenshot.empty()) shot = cli_.screenshot;
    engine::ViewStyle style = style_;
    if (heatMap_) style.fileColors = true;  // the heat colours are face colours
    simulateDeviceLossIfRequested(r_, frame_);
    if (!shot.empty()) {
      auto image = r_.capture(camera_.camera(), style);
      if (image) {
        if (auto s = engine::writePng(*image, shot); !s) {
          status_ = s.error().message;
          if (lastFrame) return fail(1, status_);
        } else {
          status_ = "saved " + shot;
          std::printf("screenshot: %s (%ux%u)\n", shot.c_str(), image->width, image->height);
          std::fflush(stdout);
        }
        pendingScreenshot_.clear();
      } else if (image.error().code == engine::ErrorCode::kUnsupported && extraFrames < 30 &&
                 image.error().message.find("skipped") != std::string::npos) {
        ++extraFrames;  // an out-of-date frame: try again on the next one
        continue;
      } else if (image.error().code == engine::ErrorCode::kDeviceLost) {
        return fail(1, engineErrorLine(image.error()));
      } else {
        pendingScreenshot_.clear();
        status_ = image.error().message;
        if (lastFrame) return fail(1, "screenshot: " + status_);
      }
    } else {
      auto status = r_.drawFrame(camera_.camera(), style);
      if (!status) return fail(1, engineErrorLine(status.error()));
    }
    if (live_) {
      pacing_.drawn(now, live_->consumer().completeLevel(), r_.scene().uploadsPending());
      ++modelFrames_;
    }
    polledSinceFrame_ = false;
    ++frame_;
    if (lastFrame) break;
  }
  if (auto s = r_.waitIdle(); !s) return fail(1, engineErrorLine(s.error()));
  waitForLoads();
  if (exitCode_ != 0) return exitCode_;
  if (live_) {
    // One line for scripts and tests: what the window showed at the end.
    const auto& stats = live_->consumer().levelStats();
    const int target = live_->targetLevel();
    const unsigned long long levelTriangles =
        target < static_cast<int>(stats.size()) ? stats[static_cast<std::size_t>(target)].triangles : 0;
    std::printf(
        "{\"frames\":%llu,\"frames_while_waiting_seconds\":%llu,\"target_level\":%d,\"complete_level\":%d,\"tolerance\":%.6g,"
        "\"shown_triangles\":%llu,\"level_triangles\":%llu}\n",
        static_cast<unsigned long long>(frame_), static_cast<unsigned long long>(framesWhileWaitingSeconds_), target,
        live_->consumer().completeLevel(),
        live_->levelTolerance(target), static_cast<unsigned long long>(live_->consumer().shownTriangles()),
        levelTriangles);
  } else {
    std::printf("{\"frames\":%llu,\"model\":null}\n", static_cast<unsigned long long>(frame_));
  }
  if (cli_.validate && glue_.validationCount() > 0) {
    return fail(1,
                "the validation layer reported " + std::to_string(glue_.validationCount()) + " problem(s)");
  }
  return 0;
}

int runView(const ViewCli& cli) {
  int width = 0, height = 0;
  if (!parseSize(cli.size, width, height))
    return fail(2, "--size '" + cli.size + "' must be WxH, at least 200x150");
  if (cli.threads < 1 || cli.threads > 256) return fail(2, "--threads must be 1 to 256");
  WindowOptions options;
  options.width = width;
  options.height = height;
  options.device = cli.device;
  options.validate = cli.validate;
  options.vsync = !cli.noVsync;
  auto created = WindowGlue::create(options);
  if (!created.glue) return fail(1, created.error);
  Viewer viewer(cli, *created.glue);
  return viewer.run();
}

}  // namespace

Command viewCommand() {
  auto cli = std::make_shared<ViewCli>();
  Command cmd{"view", "Open MODEL (default: the demo part) in a window"};
  cmd.withDefault("model", &cli->model, "STEP, IGES or .brep file, or 'demo'")
      .withDefault("--size", &cli->size, "Window size WxH")
      .withDefault("--deflection", &cli->deflection,
                   "Initial chordal deflection: relative '0.1%' or absolute")
      .withDefault("--angle", &cli->angle, "Initial angular deflection in degrees")
      .withDefault("--threads", &cli->threads, "Tessellation threads")
      .option("--device", &cli->device, "Vulkan device: a substring of its name")
      .withDefault("--view", &cli->view, "iso, front, back, left, right, top or bottom")
      .withDefault("--projection", &cli->projection, "perspective or orthographic")
      .withDefault("--display", &cli->display, "shaded, shaded-edges or wireframe")
      .option("--validate", &cli->validate, "Enable the Vulkan validation layer; any report fails the run")
      .option("--no-vsync", &cli->noVsync, "Present without waiting for vertical blank where possible")
      .option("--frames", &cli->frames, "Quit after N frames (0: run until closed)")
      .option("--screenshot", &cli->screenshot, "Save the last frame (panels included) to this PNG")
      .option("--script", &cli->script, "Replay commands from this file (see viewer/view_script.h)");
  cmd.run = [cli] { return runView(*cli); };
  return cmd;
}

}  // namespace cetview
