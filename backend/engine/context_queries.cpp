// CityEngine's context queries (inside, overlaps, touches, minimumDistance, contextCount,
// contextCompare)
// and label(). CityEngine derives a model twice for them: first with every query giving
// its default (false, infinity, 0), keeping the labelled shapes and occluders that
// derivation makes, then again with the queries answered against those. fgsg does the
// same (interpreter.cpp runs the two Derivations): this file records in the first and
// answers in the second. Occluders are the labelled shapes, the leaves and the shapes a
// comp or offset runs on, tested only where their geometry is closed; an intra occlusion
// query skips the querying shape's own ancestors and descendants, as CityEngine does.
// Tree nodes are the derivation's random keys (a shape's, a split part's), the same in
// both derivations as long as they take the same path.
#include "backend/engine/derivation.h"
#include "ir/queries_asked.h"

#include <cmath>
#include <unordered_set>

namespace fgsg::backend {
namespace {

// CityEngine's neighbourhood for inter occlusion: start shapes within 1 m of the
// querying one's bounds (context queries look at every start shape).
constexpr double kOcclusionNeighbourhood = 1.0;

// contextCompare: values this close (metres, square metres) are equal and share a rank.
constexpr double kContextCompareTie = 1e-9;

// contextCompare's value of a shape's geometry, larger ranking first (north is -z).
double contextCompareKey(ir::ContextComparison c, const rt::cga::TriangleSoup& g) {
  switch (c) {
    case ir::ContextComparison::Northernmost: return -g.lo.z();
    case ir::ContextComparison::Southernmost: return g.hi.z();
    case ir::ContextComparison::Easternmost: return g.hi.x();
    case ir::ContextComparison::Westernmost: return -g.lo.x();
    case ir::ContextComparison::Highest: return g.hi.y();
    case ir::ContextComparison::Lowest: return -g.lo.y();
    case ir::ContextComparison::LargestArea:
    case ir::ContextComparison::SmallestArea: {
      double area = 0.0;
      for (const auto& t : g.triangles) area += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
      return c == ir::ContextComparison::LargestArea ? area : -area;
    }
  }
  return 0.0;
}

}  // namespace

bool usesContextQueries(const ir::Module& m) { return ir::anyQuery(m, ir::isContextQuery); }

void Derivation::recordContext() {
  contextMode_ = ContextMode::Record;
  recorded_ = std::make_shared<ContextWorld>();
}

void Derivation::answerContextFrom(std::shared_ptr<const ContextWorld> world) {
  contextMode_ = ContextMode::Answer;
  world_ = std::move(world);
  // Each start shape's context shapes: a query looks only at those of the lots it targets.
  shapesByStart_.clear();
  for (uint32_t i = 0; i < world_->shapes.size(); ++i) {
    const uint32_t start = world_->shapes[i].start;
    if (shapesByStart_.size() <= start) shapesByStart_.resize(start + 1);
    shapesByStart_[start].push_back(i);
  }
}

std::shared_ptr<const ContextWorld> Derivation::takeContextWorld() {
  if (recorded_) recorded_->parentOf = std::move(parentOf_);
  return std::move(recorded_);
}

void Derivation::enterStart(uint32_t start, uint64_t node, const rt::Scope& scope, const rt::GeomRef& geom) {
  currentStart_ = start;
  currentNode_ = node;
  if (contextMode_ != ContextMode::Record) return;
  const rt::cga::TriangleSoup s = rt::cga::shapeTriangles(scope, geom, arena_);
  if (recorded_->startBounds.size() <= start) recorded_->startBounds.resize(start + 1);
  recorded_->startBounds[start] = {s.lo, s.hi};
}

uint64_t Derivation::enterBody(Exec& ex) {
  const uint64_t outer = currentNode_;
  if (contextMode_ == ContextMode::Off) return outer;
  // A split or comp part is a shape of CityEngine's tree, a child of the running one.
  currentNode_ = rt::childKey(ex.key, 0x6000000000000000ull | ex.bodyCount++);
  parentOf_[currentNode_] = outer;
  return outer;
}

// CityEngine's label() "creates a labeled shape", a copy of the running one: a child of
// it in the tree, so that the shapes the rule creates next (siblings) see it and its
// ancestors do not.
void Derivation::label(const std::string& name, const State& st) {
  if (contextMode_ != ContextMode::Record) return;
  const uint64_t node = rt::childKey(currentNode_, 0x5000000000000000ull | labelCount_++);
  parentOf_[node] = currentNode_;
  recorded_->shapes.push_back({currentStart_, name, node, st.scope, rt::cga::shapeTriangles(st.scope, st.geom, arena_)});
}

void Derivation::noteOccluder(const State& st, uint64_t node) {
  if (contextMode_ != ContextMode::Record) return;
  rt::cga::TriangleSoup soup = rt::cga::shapeTriangles(st.scope, st.geom, arena_);
  if (!soup.closed) return;  // only closed geometry occludes
  recorded_->shapes.push_back({currentStart_, std::string(), node, st.scope, std::move(soup)});
}

double Derivation::context(ir::Query q, uint32_t target, const std::string& label, const rt::Scope& scope,
                           const rt::GeomRef& geom, ir::Loc) {
  const bool occlusion = q == ir::Query::ContextInside || q == ir::Query::ContextOverlaps ||
                         q == ir::Query::ContextTouches;
  const double none = q == ir::Query::ContextMinimumDistance ? INFINITY : 0.0;
  // The first derivation (and an empty label of minimumDistance or contextCount) gives
  // CityEngine's defaults.
  if (!world_ || (!occlusion && label.empty())) return none;
  const auto t = static_cast<ir::ContextTarget>(target & 3);  // contextCompare's comparison above
  auto near = [&](uint32_t start) {
    if (!occlusion) return true;
    const auto& b = world_->startBounds;
    if (start >= b.size() || currentStart_ >= b.size()) return true;
    const double d = kOcclusionNeighbourhood;
    return !((b[start].second.array() + d < b[currentStart_].first.array()).any() ||
             (b[currentStart_].second.array() + d < b[start].first.array()).any());
  };
  // Calls `take` on the context shapes of the targeted start shapes until it returns true.
  auto visit = [&](auto&& take) {
    for (uint32_t start = 0; start < shapesByStart_.size(); ++start) {
      const bool own = start == currentStart_;
      if ((t == ir::ContextTarget::Intra && !own) || (t == ir::ContextTarget::Inter && own) || (!own && !near(start)))
        continue;
      for (uint32_t i : shapesByStart_[start])
        if (take(world_->shapes[i])) return;
    }
  };
  if (q == ir::Query::ContextCount) {
    double n = 0;
    visit([&](const ContextShape& s) {
      if (s.label == label) ++n;
      return false;
    });
    return n;
  }
  if (q == ir::Query::ContextCompare) {
    // The rank: how many labelled shapes come strictly before this shape's geometry (0-based;
    // equal values share the lowest rank, as CityEngine's reference says).
    const auto c = static_cast<ir::ContextComparison>(target >> 2);
    const double mine = contextCompareKey(c, rt::cga::shapeTriangles(scope, geom, arena_));
    double rank = 0;
    visit([&](const ContextShape& s) {
      if (s.label == label && contextCompareKey(c, s.geometry) > mine + kContextCompareTie) ++rank;
      return false;
    });
    return rank;
  }
  if (q == ir::Query::ContextMinimumDistance) {
    double best = INFINITY;
    visit([&](const ContextShape& s) {
      if (s.label == label) best = std::min(best, rt::cga::scopeDistance(scope, s.scope));
      return false;
    });
    return best;
  }
  // The querying shape and its ancestors (this derivation's tree) ...
  std::unordered_set<uint64_t> ancestors;
  for (uint64_t n = currentNode_;;) {
    ancestors.insert(n);
    auto up = parentOf_.find(n);
    if (up == parentOf_.end()) break;
    n = up->second;
  }
  // ... and whether an occluder descends from it (the first derivation's tree).
  auto descends = [&](uint64_t node) {
    for (uint64_t n = node;;) {
      if (n == currentNode_) return true;
      auto up = world_->parentOf.find(n);
      if (up == world_->parentOf.end()) return false;
      n = up->second;
    }
  };
  const rt::cga::Contact test = q == ir::Query::ContextInside     ? rt::cga::Contact::Inside
                                : q == ir::Query::ContextOverlaps ? rt::cga::Contact::Overlaps
                                                                  : rt::cga::Contact::Touches;
  const rt::cga::TriangleSoup me = rt::cga::shapeTriangles(scope, geom, arena_);
  bool found = false;
  visit([&](const ContextShape& s) {
    if (!s.geometry.closed || (!label.empty() && s.label != label)) return false;
    if (s.start == currentStart_ && (ancestors.count(s.node) || descends(s.node))) return false;
    return found = rt::cga::contact(test, me, s.geometry);
  });
  return found ? 1.0 : 0.0;
}

}  // namespace fgsg::backend
