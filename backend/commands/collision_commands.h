// Collision-tested instancing and what builds on it (FGSG §4.4): I under `collision all`
// and IC test the instance against everything placed so far and cull the rest of the
// production on a hit; IM merges an instance into a close, similar one; Lock{ A | B }
// places a set as one unit, removed whole on any collision; Line/LineSeg grow lines
// that end where they meet another. Owns the collision world and the line network.
#pragma once

#include "backend/commands/collision_placement.h"
#include "backend/commands/command_family.h"
#include "runtime/lines/line_network.h"

#include <memory>
#include <optional>

namespace fgsg::backend {

class Derivation;

class CollisionCommands final : public CommandFamily {
 public:
  explicit CollisionCommands(Derivation& derivation) : d_(derivation) {}

  std::vector<ir::OpKind> kinds() const override;
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

  // Before deriving: every I() is tested under `collision all` / --collide-all; the
  // collision world is built when that holds or `grammarCollides` (IC, IM, Lock).
  void prepare(bool grammarCollides);
  // Whether any instance can be tested, merged or locked: instances' order then matters.
  bool active() const { return placement_ != nullptr; }
  bool testsEveryInstance() const { return testAll_; }
  // Every instance placed (tested or not) is an obstacle for later ones.
  void placed(const rt::Scope& scope) {
    if (placement_) placement_->placed(scope);
  }
  const rt::LineNetwork& lines() const { return lines_; }

 private:
  bool placeChecked(const ir::Op& op, const rt::Scope& scope, uint32_t symbol, const double* params,
                    uint32_t paramCount, const double* args, std::optional<rt::GeomRef>& cut);
  void lockedSet(const ir::Op& op, State& st, Exec& ex, Frame& f);
  void startLine(const ir::Op& op, const double* a, State& st, Exec& ex);
  void extendLine(const ir::Op& op, const double* length, State& st, Exec& ex);

  Derivation& d_;
  std::unique_ptr<CollisionPlacement> placement_;  // null: the grammar never collides
  bool testAll_ = false;  // every I() is tested (`collision all;`, --collide-all)
  rt::LineNetwork lines_;
};

}  // namespace fgsg::backend
