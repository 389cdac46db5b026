#include "live_tessellation.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "brep/measure.h"
#include "brep/tolerance.h"

namespace cetview {

LiveTessellation::CreateResult LiveTessellation::create(std::unique_ptr<brep::Model> model, engine::Scene& scene,
                                                        const LiveOptions& options) {
  CreateResult out;
  if (!model) {
    out.error = "no model";
    return out;
  }
  std::unique_ptr<LiveTessellation> live(new LiveTessellation(std::move(model), scene));
  const double diagonal = live->model_->bounds().diagonal();
  live->diagonal_ = diagonal > 0 && std::isfinite(diagonal) ? diagonal : 1.0;
  live->requested_ = options.chordalAbsolute > 0 ? options.chordalAbsolute : 1e-3 * live->diagonal_;
  // The slider never goes finer than the schedule's end: that is the finest level planned.
  live->finestAbsolute_ = std::min(options.finestRelative * live->diagonal_, live->requested_);
  live->angleDeg_ = options.angleDeg;
  live->threads_ = std::max(1u, options.threads);
  out.error = live->start();
  if (out.error.empty()) out.live = std::move(live);
  return out;
}

LiveTessellation::~LiveTessellation() { stop(); }

void LiveTessellation::stop() {
  consumer_.reset();
  producer_.reset();  // cancels and joins the workers before the tessellator goes
  tess_.reset();
  link_.reset();
}

std::string LiveTessellation::start() {
  stop();
  brep::MeshParams params;
  params.chordal.value = finestAbsolute_;
  params.chordal.relative = false;
  params.angleDeg = angleDeg_;
  auto created = brep::Tessellator::create(*model_, params);
  if (!created.tessellator) return created.error;
  tess_ = std::move(created.tessellator);
  scene_.clear();
  link_ = std::make_unique<ModelScene>(*model_, scene_);
  target_ = 0;
  stream::StreamOptions streamOptions;
  streamOptions.threads = threads_;
  started_ = std::chrono::steady_clock::now();
  producer_ = std::make_unique<stream::ProgressiveStream>(*tess_, 0, streamOptions);
  consumer_ = std::make_unique<stream::StreamConsumer>(*producer_, model_->faces().size());
  setDeflection(requested_);
  return {};
}

int LiveTessellation::setDeflection(double absolute) {
  requested_ = std::max(absolute, finestAbsolute_);
  const auto& schedule = tess_->schedule();
  int level = tess_->lastLevel();
  for (std::size_t k = 0; k < schedule.size(); ++k) {
    if (schedule[k].chordal <= requested_ * (1.0 + 1e-9)) {
      level = static_cast<int>(k);
      break;
    }
  }
  target_ = level;
  producer_->setTargetLevel(level);
  consumer_->setShowLevel(level, *link_);
  return level;
}

std::string LiveTessellation::setAngle(double degrees) {
  double checked = 0;
  if (std::string e = brep::parseAngle(std::to_string(degrees), checked); !e.empty()) return e;
  angleDeg_ = checked;
  return start();
}

void LiveTessellation::poll(std::size_t byteBudget) { consumer_->poll(byteBudget, *link_); }

double LiveTessellation::secondsSinceStart() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

std::vector<double> LiveTessellation::measureDeviationRatios(unsigned threads) {
  if (!producer_->idle() || consumer_->completeLevel() < target_) return {};
  const std::vector<brep::FaceQuality> quality = brep::measureFaces(*tess_, target_, std::max(1u, threads));
  const double tolerance = levelTolerance(target_);
  std::vector<double> ratios(quality.size());
  for (std::size_t f = 0; f < quality.size(); ++f) ratios[f] = quality[f].maxDeviation / tolerance;
  return ratios;
}

engine::Color8 LiveTessellation::heatColor(double ratio) {
  const double t = std::clamp(ratio, 0.0, 1.0);
  // Green -> yellow -> red; beyond the tolerance stays full red.
  const double r = t < 0.5 ? 2.0 * t : 1.0;
  const double g = t < 0.5 ? 1.0 : 2.0 * (1.0 - t);
  return engine::Color8{static_cast<std::uint8_t>(std::lround(40 + 215 * r)),
                        static_cast<std::uint8_t>(std::lround(40 + 180 * g)), 40, 255};
}

void LiveTessellation::applyHeatColors(const std::vector<double>& ratios) {
  for (std::uint32_t f = 0; f < ratios.size() && f < model_->faces().size(); ++f) {
    (void)scene_.setFaceColor(link_->engineFace(f), heatColor(ratios[f]));
  }
  for (std::uint32_t i = 0; i < model_->instances().size(); ++i) {
    (void)scene_.setInstanceColor(link_->engineInstance(i), std::nullopt);
  }
}

void LiveTessellation::restoreFaceColors() {
  const auto& faces = model_->faces();
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    (void)scene_.setFaceColor(link_->engineFace(f), toColor8(faces[f].color));
  }
  const auto& instances = model_->instances();
  for (std::uint32_t i = 0; i < instances.size(); ++i) {
    if (instances[i].hasColor) (void)scene_.setInstanceColor(link_->engineInstance(i), toColor8(instances[i].color));
  }
}

}  // namespace cetview
