// The limits that end a derivation (--max-depth, --max-shapes, --max-seconds,
// --max-memory) and their messages, which name the rule that ran away.
#include "backend/engine/derivation.h"

#include "runtime/memory_budget.h"

#include <string>

namespace fgsg::backend {

// The depth limit cuts the derivation tree: deeper shapes stay terminal and the rest
// of the tree is still derived. Named: the rule that created the shape.
void Derivation::depthLimit(const ir::Symbol& sym, uint32_t creator) {
  ++stats_.terminals;
  if (depthLimitHit_ || depthBoundIsGrammars_) return;  // the grammar's own bound is its design
  depthLimitHit_ = true;
  const ir::Rule* r = creator == UINT32_MAX ? nullptr : &m_.rules[creator];
  depthWarning_ = {false, "R004", r ? r->loc.line : 0, r ? r->loc.col : 0,
                   "depth limit " + std::to_string(opt_.maxDepth) + " (--max-depth) reached: " +
                       (r ? "rule '" + r->label + "' keeps creating '" + sym.name + "'"
                          : std::string("the axiom")) +
                       "; shapes at that depth stay terminal"};
}

// The most applied rule, named for a limit message, and where it is (`axiomAt` when
// no rule was applied).
std::pair<std::string, ir::Loc> Derivation::runaway(ir::Loc axiomAt) const {
  uint32_t worst = 0;
  uint64_t uses = 0;
  for (uint32_t rule = 0; rule < ruleUses_.size(); ++rule)
    if (ruleUses_[rule] > uses) worst = rule, uses = ruleUses_[rule];
  if (uses == 0) return {"the axiom", axiomAt};
  return {"rule '" + m_.rules[worst].label + "' (applied " + std::to_string(uses) + " times)",
          m_.rules[worst].loc};
}

void Derivation::shapeLimit(const ir::Op& op) { throw shapeLimitReached(op.loc); }

// --max-shapes reached, named after the runaway rule (`axiomAt` when none was applied).
LimitReached Derivation::shapeLimitReached(ir::Loc axiomAt) const {
  const auto [who, loc] = runaway(axiomAt);
  return {"derivation stopped at " + std::to_string(opt_.maxShapes) + " shapes (--max-shapes): " + who +
              " ran away; the shapes derived so far are kept",
          loc};
}

LimitReached Derivation::timeLimit() const {
  return {"derivation stopped after " + std::to_string(opt_.maxSeconds) +
              " s (--max-seconds); the shapes derived so far are kept",
          {}};
}

// --max-seconds and --max-memory, asked at every unit of work (a rewrite, a module):
// the deadline reads the clock about every 0.1 ms, the memory is read every 10 ms.
std::optional<LimitReached> Derivation::limitsReached() {
  if (deadline_.expired()) return timeLimit();
  if (deadline_.lastRead() - memoryCheckedAt_ >= std::chrono::milliseconds(10)) return memoryLimit();
  return std::nullopt;
}

void Derivation::pollLimits() {
  if (auto limit = limitsReached()) throw *limit;
}

// The same, reading the clock now: for callers that are already rare (every 4096
// directly derived shapes, a parallel step).
void Derivation::checkTime() {
  if (deadline_.expiredNow()) throw timeLimit();
  if (deadline_.lastRead() - memoryCheckedAt_ >= std::chrono::milliseconds(10))
    if (auto limit = memoryLimit()) throw *limit;
}

// What the derivation holds: resident memory, plus the mesh and file the instances
// placed so far will become (counted once per instance, as they come).
std::optional<LimitReached> Derivation::memoryLimit() {
  memoryCheckedAt_ = deadline_.lastRead();
  for (; instancesCounted_ < out_.instances.size(); ++instancesCounted_)
    instanceBytes_ += assetOutputBytes(out_.instances[instancesCounted_].asset);
  const uint64_t held = rt::residentMemoryBytes() + instanceBytes_;
  if (held <= memoryBudget_) return std::nullopt;
  const auto [who, loc] = runaway(ir::Loc{});
  return LimitReached{"derivation stopped at " + rt::formatMemorySize(held) + " of memory (--max-memory " +
                          rt::formatMemorySize(memoryBudget_) + ", with the instances' mesh to come): " + who +
                          " ran away; the shapes derived so far are kept",
                      loc};
}

uint64_t Derivation::assetOutputBytes(uint32_t asset) {
  while (assetBytes_.size() <= asset && assetBytes_.size() < out_.assets.size()) {
    std::string error;
    const int index = assets_.resolve(out_.assets[assetBytes_.size()], error);
    const rt::Mesh* mesh = index >= 0 ? &assets_.mesh(index) : nullptr;
    assetBytes_.push_back(mesh ? rt::outputBytes(mesh->vertexCount(), mesh->triangleCount()) : 0);
  }
  return asset < assetBytes_.size() ? assetBytes_[asset] : 0;
}

}  // namespace fgsg::backend
