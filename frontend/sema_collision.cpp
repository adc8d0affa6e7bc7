// Semantic analysis of `collision [all] [omit | cull] [mesh | centre R | center R | geodesic R |
// distance D];`
// (E030..E032): the first declaration sets SemaResult::collision*, later ones are errors.

#include "frontend/sema_analyzer.h"

#include <cmath>
#include <string>

namespace fgsg::frontend::sema_detail {

namespace {

const char* collisionMetricOf(const std::string& word) {
  if (word == "mesh") return "mesh";
  if (word == "centre" || word == "center") return "centre";
  if (word == "geodesic") return "geodesic";
  if (word == "distance") return "distance";
  return nullptr;
}

}  // namespace

// `collision [all] [omit | cull] [mesh | centre R | center R | geodesic R | distance D];`,
// words in any order. The radius R (clearance D) is a number or the name of a number const.
void Analyzer::collectCollision() {
  for (size_t i = 0; i < prog_.collisions.size(); ++i) {
    const CollisionDecl& d = prog_.collisions[i];
    if (i == 0) {
      checkCollisionDecl(d);
      continue;
    }
    SourceRange keyword = d.range;
    keyword.end = {keyword.begin.line, keyword.begin.col + 8};  // "collision"
    diags_.error("E032", keyword,
                 "only one `collision` declaration is allowed (the first is on line " +
                     std::to_string(prog_.collisions[0].range.begin.line) +
                     "); write all its settings in one: `collision all centre 0.3;`");
  }
}

// A radius written after `centre` / `geodesic` / `distance`: a number or a number const.
bool Analyzer::collisionRadius(const CollisionWord& w, double& radius) const {
  if (w.isNumber()) return radius = w.number, true;
  if (w.word == "all" || w.word == "omit" || w.word == "cull" || collisionMetricOf(w.word)) return false;
  auto c = res_.constants.find(w.word);
  if (c == res_.constants.end() || c->second.type != ValueType::Num) return false;
  radius = c->second.num;
  return true;
}

void Analyzer::checkCollisionDecl(const CollisionDecl& d) {
  res_.collisionDeclared = true;
  res_.collisionRange = d.range;
  if (d.words.empty()) {
    diags_.error("E030", d.range,
                 "`collision` needs a setting: all, omit, cull, mesh, centre R, geodesic R or "
                 "distance D (R a positive radius, D a positive clearance), e.g. `collision all "
                 "centre 0.3;`");
    return;
  }
  const CollisionWord* metric = nullptr;    // the first metric written
  const CollisionWord* strategy = nullptr;  // omit or cull, the first written
  bool all = false;
  for (size_t k = 0; k < d.words.size(); ++k) {
    const CollisionWord& w = d.words[k];
    if (w.isNumber()) {
      const CollisionWord* before = k > 0 ? &d.words[k - 1] : nullptr;
      diags_.error("E031", w.range,
                   std::string("a number in `collision` is the radius after 'centre', "
                               "'geodesic' or 'distance'") +
                       (before && (before->word == "all" || before->word == "mesh")
                            ? ", and '" + before->word + "' takes none"
                            : std::string()) +
                       ": `collision centre 0.3;`");
      continue;
    }
    if (w.word == "all") {
      if (all) diags_.error("E032", w.range, "'all' is written twice in this `collision` declaration");
      all = true;
      continue;
    }
    if (w.word == "omit" || w.word == "cull") {
      if (strategy)
        diags_.error("E032", w.range,
                     "two collision strategies, '" + strategy->word + "' and '" + w.word +
                         "': choose one (cull, the default, or omit)");
      else
        strategy = &w, res_.collisionOmit = w.word == "omit";
      continue;
    }
    const char* kind = collisionMetricOf(w.word);
    if (!kind) {
      diags_.error("E030", w.range,
                   "unknown collision setting '" + w.word +
                       "' (expected all, omit, cull, mesh, centre R, center R, geodesic R or "
                       "distance D)");
      continue;
    }
    if (metric)
      diags_.error("E032", w.range,
                   "two collision metrics, '" + metric->word + "' and '" + w.word +
                       "': choose one (mesh, centre R, geodesic R or distance D)");
    double radius = 0.0;
    if (std::string(kind) != "mesh") {
      const std::string noun = std::string(kind) == "distance" ? "clearance" : "radius";
      if (k + 1 >= d.words.size() || !collisionRadius(d.words[k + 1], radius)) {
        diags_.error("E031", w.range,
                     "'" + w.word + "' needs a " + noun + ": `collision " + w.word + " 0.3;`");
        continue;
      }
      const CollisionWord& r = d.words[++k];
      if (!(radius > 0) || !std::isfinite(radius)) {
        diags_.error("E031", r.range,
                     "the " + noun + " of '" + w.word + "' must be a positive number, got " +
                         formatNumber(radius));
        continue;
      }
    }
    if (metric) continue;
    metric = &w;
    res_.collisionMetric = kind;
    res_.collisionRadius = radius;
  }
  res_.collisionAll = all;
}

}  // namespace fgsg::frontend::sema_detail
