#include "live_tessellation.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "brep/measure.h"
#include "brep/tolerance.h"
#include "engine/types.h"

namespace cetview {

LiveTessellation::CreateResult LiveTessellation::create(std::unique_ptr<brep::Model> model,
                                                        engine::Scene& scene, const LiveOptions& options) {
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
  live->kept_ = options.kept;
  live->wake_ = options.wake;
  out.error = live->start();
  if (out.error.empty()) out.live = std::move(live);
  return out;
}

LiveTessellation::~LiveTessellation() {
  stop();
}

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
  auto created = brep::Tessellator::create(*model_, params, kept_ ? kept_->pool() : nullptr);
  if (!created.tessellator) return created.error;
  tess_ = std::move(created.tessellator);
  scene_.clear();
  heatParts_.clear();
  heatCapacity_.clear();
  heatInstances_.clear();
  heatShown_ = false;
  link_ = std::make_unique<ModelScene>(*model_, scene_);
  visible_.resize(model_->instances().size(), true);
  applyVisibility();
  target_ = 0;
  heldAt_ = 0;  // a new schedule: held, it stops at level 0
  problemsReady_ = false;
  stream::StreamOptions streamOptions;
  streamOptions.threads = threads_;
  streamOptions.onLevelPublished = wake_;
  streamOptions.kept = kept_;
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
  if (level != target_) problemsReady_ = false;
  target_ = level;
  producer_->setTargetLevel(held_ ? std::min(level, heldAt_) : level);
  consumer_->setShowLevel(level, *link_);
  return level;
}

void LiveTessellation::holdFinerLevels(bool hold) {
  held_ = hold;
  heldAt_ = std::min(target_, std::max(0, consumer_->completeLevel()));
  producer_->setTargetLevel(hold ? heldAt_ : target_);
}

std::string LiveTessellation::setAngle(double degrees) {
  double checked = 0;
  if (std::string e = brep::parseAngle(std::to_string(degrees), checked); !e.empty()) return e;
  angleDeg_ = checked;
  return start();
}

std::size_t LiveTessellation::poll(std::size_t byteBudget) {
  return consumer_->poll(byteBudget, *link_);
}

const std::vector<FaceProblem>* LiveTessellation::faceProblems() {
  if (!problemsReady_) {
    if (!producer_->idle() || consumer_->completeLevel() < target_) return nullptr;
    problems_ = collectFaceProblems(*tess_);
    problemsReady_ = true;
  }
  return &problems_;
}

double LiveTessellation::secondsSinceStart() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

engine::Color8 LiveTessellation::heatColor(double ratio) {
  const double t = std::clamp(ratio, 0.0, 1.0);
  // Green -> yellow -> red; beyond the tolerance stays full red.
  const double r = t < 0.5 ? 2.0 * t : 1.0;
  const double g = t < 0.5 ? 1.0 : 2.0 * (1.0 - t);
  return engine::Color8{static_cast<std::uint8_t>(std::lround(40 + 215 * r)),
                        static_cast<std::uint8_t>(std::lround(40 + 180 * g)), 40, 255};
}

std::uint32_t LiveTessellation::heatBin(double ratio) {
  // Bins 0 .. kHeatBins-2 split [0, 1); the last holds everything at or above the tolerance.
  if (!(ratio < 1.0)) return kHeatBins - 1;
  return std::min(kHeatBins - 2, static_cast<std::uint32_t>(std::max(0.0, ratio) * (kHeatBins - 1)));
}

void LiveTessellation::setInstanceVisible(std::uint32_t instance, bool visible) {
  visible_[instance] = visible;
  applyVisibility();
}

void LiveTessellation::applyVisibility() {
  for (std::uint32_t i = 0; i < visible_.size(); ++i) {
    (void)scene_.setInstanceVisible(link_->engineInstance(i), visible_[i] && !heatShown_);
    if (i < heatInstances_.size())
      (void)scene_.setInstanceVisible(heatInstances_[i], visible_[i] && heatShown_);
  }
}

bool LiveTessellation::showHeatMap(unsigned threads, double* worstRatio) {
  if (!producer_->idle() || consumer_->completeLevel() < target_) return false;
  const std::vector<std::vector<float>> deviation =
      brep::measureTriangles(*tess_, target_, std::max(1u, threads));
  const double tolerance = levelTolerance(target_);
  const brep::Model& m = *model_;
  heatParts_.resize(m.parts().size());
  heatCapacity_.resize(m.parts().size(), 0);
  heatInstances_.resize(m.instances().size());
  // One engine face per (model face, colour bin) in use. Not one face per bin over the whole part:
  // Mesa's lavapipe draws one indexed draw spanning the whole vertex array about ten times slower
  // than the same triangles in per-face draws (measured on the bottle: 300 ms against 25 ms).
  double worst = 0;
  std::vector<std::uint32_t> bins[kHeatBins];
  std::vector<std::uint32_t> groupIndices;                    // all groups' indices, back to back
  std::vector<std::pair<std::size_t, std::uint32_t>> groups;  // (end in groupIndices, bin)
  for (std::uint32_t p = 0; p < m.parts().size(); ++p) {
    const brep::PartInfo& part = m.parts()[p];
    groupIndices.clear();
    groups.clear();
    for (std::uint32_t f = part.firstFace; f < part.firstFace + part.faceCount; ++f) {
      const std::vector<std::uint32_t>& shown = link_->shownIndices(f);
      const std::vector<float>& d = deviation[f];
      const std::size_t triangles = shown.size() / 3;
      double faceWorst = 0;
      for (float x : d) faceWorst = std::max(faceWorst, static_cast<double>(x) / tolerance);
      worst = std::max(worst, faceWorst);
      for (auto& bin : bins) bin.clear();
      for (std::size_t t = 0; t < triangles; ++t) {
        // The face shows the measured level's triangles in the same order; should a face show
        // another level (none at this one), its triangles take the face's worst.
        const double ratio = d.size() == triangles ? static_cast<double>(d[t]) / tolerance : faceWorst;
        std::vector<std::uint32_t>& bin = bins[heatBin(ratio)];
        bin.insert(bin.end(), shown.begin() + static_cast<std::ptrdiff_t>(3 * t),
                   shown.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
      }
      for (std::uint32_t b = 0; b < kHeatBins; ++b) {
        if (bins[b].empty()) continue;
        groupIndices.insert(groupIndices.end(), bins[b].begin(), bins[b].end());
        groups.emplace_back(groupIndices.size(), b);
      }
    }
    const auto needed = static_cast<std::uint32_t>(groups.size());
    if (needed > heatCapacity_[p]) {
      // Parts cannot be removed: retire the old heat part (its instances stay hidden, its faces
      // empty) and make a larger one.
      if (heatCapacity_[p] > 0) {
        for (std::uint32_t k = 0; k < heatCapacity_[p]; ++k)
          (void)scene_.setFaceIndices(heatParts_[p].face(k), nullptr, 0);
        for (std::uint32_t i = 0; i < m.instances().size(); ++i) {
          if (m.instances()[i].part == p) (void)scene_.setInstanceVisible(heatInstances_[i], false);
        }
      }
      heatCapacity_[p] = std::max(needed, heatCapacity_[p] * 2);
      heatParts_[p] = scene_.addPart(heatCapacity_[p], 0, engine::kDefaultFaceColor, part.closed);
      for (std::uint32_t i = 0; i < m.instances().size(); ++i) {
        if (m.instances()[i].part != p) continue;
        auto id = scene_.addInstance(heatParts_[p].part, ModelScene::instanceTransform(m.instances()[i]));
        if (id) heatInstances_[i] = *id;
      }
    }
    std::size_t begin = 0;
    for (std::uint32_t k = 0; k < heatCapacity_[p]; ++k) {
      const engine::FaceId id = heatParts_[p].face(k);
      if (k < needed) {
        const auto [end, b] = groups[k];
        (void)scene_.setFaceIndices(id, groupIndices.data() + begin, end - begin);
        (void)scene_.setFaceColor(id, heatColor(b == kHeatBins - 1 ? 1.0 : (b + 0.5) / (kHeatBins - 1)));
        begin = end;
      } else {
        (void)scene_.setFaceIndices(id, nullptr, 0);
      }
    }
  }
  heatShown_ = true;
  applyVisibility();
  if (worstRatio) *worstRatio = worst;
  return true;
}

void LiveTessellation::hideHeatMap() {
  heatShown_ = false;
  applyVisibility();
}

}  // namespace cetview
