// The window's live tessellation: one model, one Tessellator planned down to the finest deflection
// the slider allows, one ProgressiveStream and its StreamConsumer feeding an engine Scene through
// ModelScene. Every chordal slider position maps to a level of that one schedule, so moving the
// slider only retargets the stream (finer: refinement continues) and the consumer (coarser: stored
// levels show at once). An angle change restarts with a new Tessellator: the Scene is cleared and
// the model reappears coarse within a frame or two.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "brep/model.h"
#include "brep/tessellator.h"
#include "engine/scene.h"
#include "face_problems.h"
#include "model_scene.h"
#include "stream/progressive_stream.h"
#include "stream/stream_consumer.h"
#include "stream/stream_threads.h"

namespace cetview {

struct LiveOptions {
  double finestRelative = 1e-4;  // the slider's finest chordal deflection, fraction of the diagonal
  double chordalAbsolute = 0;    // initial deflection (model units); 0: 0.1% of the diagonal
  double angleDeg = 20.0;
  unsigned threads = 1;
  // Threads kept across models (the window's), or none: the tessellation starts its own.
  stream::StreamThreads* kept = nullptr;
  // Called from a tessellation thread when a level is complete (the window posts an empty event
  // so its loop, asleep between frames, shows the level at once).
  std::function<void()> wake;
};

class LiveTessellation {
 public:
  struct CreateResult {
    std::unique_ptr<LiveTessellation> live;  // null on error
    std::string error;
  };
  // Clears `scene`, adds the model to it and starts streaming towards options.chordalAbsolute.
  static CreateResult create(std::unique_ptr<brep::Model> model, engine::Scene& scene,
                             const LiveOptions& options);
  ~LiveTessellation();

  // Retargets to the coarsest level whose tolerance is at most `absolute` (the finest level when
  // none is). Returns that level.
  int setDeflection(double absolute);
  // Restarts with a new Tessellator at this angle (keeping the chordal deflection). Returns an
  // error line, empty on success.
  std::string setAngle(double degrees);
  // Applies up to `byteBudget` bytes of finished face levels to the Scene (never waits).
  std::size_t poll(std::size_t byteBudget);  // returns the bytes read

  // Deviation heat map (DESIGN.md's promise made visible): each shown triangle is measured
  // against the exact surface (brep::measureTriangles) and coloured by deviation / tolerance of the
  // shown level, green (0) through yellow to red (1 and above), in kHeatBins colour bins. Drawn as
  // extra engine parts (one face per model face and bin in use) that share the shown triangles'
  // vertices; the model's own instances are
  // hidden meanwhile. Returns false (nothing changed) until the stream is idle with every face at
  // targetLevel(); then `worstRatio` gets the largest ratio.
  static constexpr std::uint32_t kHeatBins = 16;
  bool showHeatMap(unsigned threads, double* worstRatio = nullptr);
  void hideHeatMap();
  bool heatMapShown() const { return heatShown_; }
  // The heat-map colour of a deviation ratio, and the bin a ratio falls into.
  static engine::Color8 heatColor(double ratio);
  static std::uint32_t heatBin(double ratio);
  // Instance visibility (the assembly tree), kept across heat map and angle restarts.
  void setInstanceVisible(std::uint32_t instance, bool visible);
  bool instanceVisible(std::uint32_t instance) const { return visible_[instance]; }

  const brep::Model& model() const { return *model_; }
  const ModelScene& modelScene() const { return *link_; }
  const brep::Tessellator& tessellator() const { return *tess_; }
  const stream::StreamConsumer& consumer() const { return *consumer_; }
  stream::StreamProgress progress() const { return producer_->progress(); }
  bool idle() const { return producer_->idle(); }
  // While another file loads, the levels finer than the one shown now wait (the cores go to the
  // load, and the model is about to be replaced); released, refinement goes on towards the target.
  // Level 0 is always finished.
  void holdFinerLevels(bool hold);
  bool holdingFinerLevels() const { return held_; }
  int targetLevel() const { return target_; }
  int lastLevel() const { return tess_->lastLevel(); }
  double levelTolerance(int level) const {
    return tess_->schedule()[static_cast<std::size_t>(level)].chordal;
  }
  double diagonal() const { return diagonal_; }
  double finestAbsolute() const { return finestAbsolute_; }
  double coarsestAbsolute() const { return levelTolerance(0); }
  double requestedDeflection() const { return requested_; }
  double angleDeg() const { return angleDeg_; }
  // Faces repaired, meshed by the fallback or left empty, once the stream is idle at the target
  // level (their reports are settled then); null while it works. Recomputed after each retarget.
  const std::vector<FaceProblem>* faceProblems();

  // Since the stream (re)started; the first complete level's time is the time to first frame.
  double secondsSinceStart() const;

 private:
  LiveTessellation(std::unique_ptr<brep::Model> model, engine::Scene& scene)
      : model_(std::move(model)), scene_(scene) {}
  std::string start();
  void stop();

  std::unique_ptr<brep::Model> model_;
  engine::Scene& scene_;
  std::unique_ptr<ModelScene> link_;
  std::unique_ptr<brep::Tessellator> tess_;
  std::unique_ptr<stream::ProgressiveStream> producer_;
  std::unique_ptr<stream::StreamConsumer> consumer_;
  std::chrono::steady_clock::time_point started_;
  double diagonal_ = 1, finestAbsolute_ = 0, requested_ = 0, angleDeg_ = 20;
  unsigned threads_ = 1;
  stream::StreamThreads* kept_ = nullptr;  // LiveOptions::kept
  std::function<void()> wake_;
  bool held_ = false;
  int heldAt_ = 0;  // the level the producer stops at while held
  int target_ = 0;
  std::vector<bool> visible_;                      // per model instance
  std::vector<engine::PartRange> heatParts_;       // per model part: one face per (face, bin) in use
  std::vector<std::uint32_t> heatCapacity_;        // per model part: faces of its heat part (0: none yet)
  std::vector<engine::InstanceId> heatInstances_;  // per model instance
  bool heatShown_ = false;
  std::vector<FaceProblem> problems_;
  bool problemsReady_ = false;
  void applyVisibility();
};

}  // namespace cetview
