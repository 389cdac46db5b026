#include "face_problems.h"

namespace cetview {

std::vector<FaceProblem> collectFaceProblems(const brep::Tessellator& tessellator) {
  std::vector<FaceProblem> problems;
  const std::size_t faces = tessellator.model().faces().size();
  for (brep::FaceId f = 0; f < faces; ++f) {
    brep::FaceReport r = tessellator.report(f);
    if (r.status == brep::FaceStatus::kOk || r.status == brep::FaceStatus::kPending ||
        r.status == brep::FaceStatus::kCancelled)
      continue;
    problems.push_back({f, r.status, std::move(r.reason)});
  }
  return problems;
}

std::string describeFaceProblem(const brep::Model& model, const FaceProblem& problem) {
  std::string line = "face " + std::to_string(problem.face);
  if (model.parts().size() > 1) {
    const brep::PartInfo& part = model.parts()[model.faces()[problem.face].part];
    line += " (part " + (part.name.empty() ? std::to_string(model.faces()[problem.face].part) : part.name) + ")";
  }
  line += ": ";
  line += brep::faceStatusName(problem.status);
  if (!problem.reason.empty()) line += ": " + problem.reason;
  return line;
}

void printFaceProblems(std::FILE* out, const char* prefix, const brep::Model& model,
                       const std::vector<FaceProblem>& problems, std::size_t maxLines) {
  for (std::size_t i = 0; i < problems.size() && i < maxLines; ++i)
    std::fprintf(out, "%s: %s\n", prefix, describeFaceProblem(model, problems[i]).c_str());
  if (problems.size() > maxLines)
    std::fprintf(out, "%s: ... and %zu more faces repaired, meshed by the fallback or empty\n", prefix,
                 problems.size() - maxLines);
}

}  // namespace cetview
