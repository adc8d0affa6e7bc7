#include "backend/commands/march_tally.h"

#include <algorithm>
#include <string>

namespace fgsg::backend {

void MarchTally::add(const MarchTally& o) {
  if (!hasFirst && o.hasFirst) first = o.first, hasFirst = true;
  marches += o.marches, steps += o.steps;
  conditionFailed += o.conditionFailed, atEdge += o.atEdge, tooLong += o.tooLong;
  candidates = std::max(candidates, o.candidates);
}

std::optional<rt::DeriveMessage> MarchTally::neverStarted() const {
  if (marches == 0 || steps > 0) return std::nullopt;
  std::string why;
  auto reason = [&why](uint64_t n, const std::string& text) {
    if (n == 0) return;
    why += (why.empty() ? "" : "; ") + text + " (" + std::to_string(n) + (n == 1 ? " march)" : " marches)");
  };
  reason(conditionFailed,
         "the condition was false at every destination tried, straight ahead and " + std::to_string(candidates) +
             " other directions (--march-candidates): every start lies where it fails; if it reads a texture "
             "context, the seeds (--seed-points, --seed-density) or the start all lie where the texture says no");
  reason(atEdge, "no point of the surface lay a step away in any direction tried (its open edge came first, or "
                 "it does not reach that far that way)");
  reason(tooLong, "the step is longer than the surface's bounding-box diagonal (a smaller length, or "
                  "--surface-size to scale the surface up)");
  return rt::DeriveMessage{false, "R030", first.line, first.col,
                           "no march ever started: all " + std::to_string(marches) +
                               " Marching steps stopped where they began, so nothing grew along the surface: " +
                               why};
}

}  // namespace fgsg::backend
