// Faces the tessellator could not mesh cleanly from their exact boundary (repaired, meshed by the
// fallback, or left empty), for the terminal and the Model panel: one bad face is reported by id and
// reason while the rest of the model shows.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "brep/tessellator.h"

namespace cetview {

struct FaceProblem {
  brep::FaceId face = 0;
  brep::FaceStatus status = brep::FaceStatus::kOk;
  std::string reason;
};

// In face order. Call only while nothing advances the tessellator (after run(), or while its
// progressive stream is idle).
std::vector<FaceProblem> collectFaceProblems(const brep::Tessellator& tessellator);

// "face 12 (part NAME): fallback: REASON", naming the part when the model has several.
std::string describeFaceProblem(const brep::Model& model, const FaceProblem& problem);

// Writes up to `maxLines` lines "PREFIX: face ..." to `out`, then one line counting the rest.
void printFaceProblems(std::FILE* out, const char* prefix, const brep::Model& model,
                       const std::vector<FaceProblem>& problems, std::size_t maxLines = 20);

}  // namespace cetview
