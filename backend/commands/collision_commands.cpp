#include "backend/commands/collision_commands.h"

#include "backend/engine/derivation.h"
#include "runtime/insert_fit.h"

#include <cmath>
#include <string>

namespace fgsg::backend {

std::vector<ir::OpKind> CollisionCommands::kinds() const {
  using K = ir::OpKind;
  return {K::Instance, K::Lock, K::Line, K::LineSeg};
}

void CollisionCommands::prepare(bool grammarCollides) {
  const ir::Module& m = d_.module();
  testAll_ = m.collision.all || d_.options().collideAll;
  if (testAll_ || grammarCollides)
    placement_ = std::make_unique<CollisionPlacement>(d_.assets(), d_.output(), m.collision);
  if (placement_ && d_.surface() && m.collision.metric == ir::CollisionMetric::Geodesic)
    placement_->measureAlongSurface([this](const rt::Scope& a, const rt::Scope& b, double limit) {
      return d_.surface()->geodesicDistance(a, b, limit);
    });
}

void CollisionCommands::apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  switch (op.kind) {
    case ir::OpKind::Instance: {
      // A .cga i() whose shape goes on: the asset becomes the shape's geometry, and the leaf
      // that ends the shape outputs it (Derivation::outputLeaf), not this insert.
      if (d_.insertIsCarried(op)) {
        if (op.insertFit != ir::InsertFit::AlignSizeAndPosition) st.scope = d_.insertFitted(op, st.scope);
        st.geom = d_.carryInsert(op, st.scope);
        break;
      }
      // A .cga leaf after the insert (`i(a) Tree.`) takes the instance, without parameters.
      const bool leaf = op.recordAs != ir::Op::kPlacingSymbol;
      const uint32_t sym = leaf ? op.recordAs : d_.placingSymbol(ex);
      const uint32_t count = leaf || ex.symbol == UINT32_MAX ? 0 : d_.module().symbols[sym].slotCount;
      // Rejected: the rest of the production goes (cull), or only this instance (omit),
      // except inside a Lock set, which a collision anywhere removes whole.
      std::optional<rt::GeomRef> cut;  // what the shape's trim planes leave of the asset
      if (!placeChecked(op, st.scope, sym, ex.params, count, a, cut) && (!d_.module().collision.omit || d_.inLock()))
        ex.culled = ex.collided = true;
      // An asset that keeps its size sets the scope to its box, as CityEngine's i() does,
      // and the asset (as cut) becomes the shape's geometry, which geometry.*() then read.
      if (op.insertFit != ir::InsertFit::AlignSizeAndPosition) st.scope = d_.insertFitted(op, st.scope);
      if (d_.insertIsRead(op) && op.index < d_.module().assets.size() && !d_.placesNothing(op.index))
        st.geom = cut ? *cut : d_.insertedGeometry(op.index, op.zUp);
      break;
    }
    case ir::OpKind::Lock: lockedSet(op, st, ex, f); break;
    case ir::OpKind::Line: startLine(op, a, st, ex); break;
    default: extendLine(op, n > 0 ? a : nullptr, st, ex); break;
  }
}

// I, IC and IM. False when a collision rejected the instance: the caller culls the
// rest of its production.
bool CollisionCommands::placeChecked(const ir::Op& op, const rt::Scope& written, uint32_t symbol, const double* params,
                                     uint32_t paramCount, const double* args, std::optional<rt::GeomRef>& cut) {
  std::optional<rt::GeomRef>* read = d_.insertIsRead(op) ? &cut : nullptr;  // the cut only where it is read
  rt::Scope kept;  // the scope the asset fills, when it keeps its size (no copy otherwise)
  const rt::Scope& scope =
      op.insertFit == ir::InsertFit::AlignSizeAndPosition ? written : (kept = d_.insertFitted(op, written));
  if (!placement_) {
    d_.placeInstance(op.index, scope, symbol, params, paramCount, op.loc, op.zUp, read);
    return true;
  }
  rt::DeriveStats& stats = d_.stats();
  const rt::Mat4 t = rt::insertTransform(scope, op.zUp);
  if (!t.allFinite())  // placeInstance words the error
    d_.placeInstance(op.index, scope, symbol, params, paramCount, op.loc, op.zUp, read);
  if (op.mode == ir::InstanceMode::Merge) {
    const double maxDist = args[0], maxAngle = args[1];
    if (!(maxDist >= 0) || !(maxAngle >= 0) || !std::isfinite(maxDist) || !std::isfinite(maxAngle))
      throw DeriveError{op.loc, "R014",
                        "IM(\"" + d_.module().assets[op.index] + "\", maxDist, maxAngle): the thresholds must be "
                        "finite and not negative, got " + std::to_string(maxDist) + " and " +
                        std::to_string(maxAngle)};
    if (placement_->mergeInto(op.index, t, maxDist, maxAngle, scope)) {
      ++stats.merges;
      return true;
    }
    d_.placeInstance(op.index, scope, symbol, params, paramCount, op.loc, op.zUp, read);
    placement_->placedMergeable(op.index, t, scope);
    return true;
  }
  if (op.mode == ir::InstanceMode::Collide || testAll_) {
    ++stats.collisionTests;
    if (!placement_->fits(op.index, t, scope)) {
      ++stats.collisions;
      return false;
    }
  }
  d_.placeInstance(op.index, scope, symbol, params, paramCount, op.loc, op.zUp, read);
  return true;
}

// Lock{ A | B | ... }: the parts and everything derived from them are placed as one
// unit, depth-first; a collision anywhere in the set removes all of it and culls the
// rest of the production.
void CollisionCommands::lockedSet(const ir::Op& op, State& st, Exec& ex, Frame& f) {
  const CollisionPlacement::Transaction undo = placement_->begin(lines_);
  const size_t occluders = d_.occluders().size();
  d_.enterLock();
  for (size_t k = 0; k < op.bodies.size(); ++k) {
    d_.runBody(op, k, st.scope, st.geom, st, ex, f);
    if (ex.culled) break;
  }
  d_.leaveLock();
  if (ex.collided) {
    placement_->rollback(undo, lines_);
    d_.occluders().truncate(occluders);
    ++d_.stats().locksRemoved;
    // collision omit: the set is gone and the production goes on.
    if (d_.module().collision.omit) ex.culled = ex.collided = false;
  }
}

// Line(width, merge): a new line starts at the scope's origin.
void CollisionCommands::startLine(const ir::Op& op, const double* a, State& st, Exec& ex) {
  const double width = a[0];
  const bool merge = a[1] != 0.0;
  if (!(width > 0) || !std::isfinite(width))
    throw DeriveError{op.loc, "R014",
                      "Line(width, merge): the width must be a positive number, got " + std::to_string(width)};
  if (!st.scope.P.allFinite()) throw DeriveError{op.loc, "R005", "this line's start point is not finite"};
  st.line = lines_.start(st.scope.P, {width, merge, op.asset}, d_.placingSymbol(ex));
}

// LineSeg(length?): moves `length` along the scope's X first (on a surface as T(length,
// 0, 0) does, along the surface), then extends the line to the scope's origin. Reaching
// another line ends this one there: the rest of the production (which would continue it)
// is culled.
void CollisionCommands::extendLine(const ir::Op& op, const double* length, State& st, Exec& ex) {
  if (length) {
    if (d_.surface())
      d_.surface()->translate(st.scope, *length, 0, 0, &d_.deadline());
    else
      st.scope.P += *length * st.scope.X();
  }
  if (!st.line.valid())
    throw DeriveError{op.loc, "R014",
                      "LineSeg outside a line: start one with Line(width) in this successor or in "
                      "one that created this shape"};
  if (!st.scope.P.allFinite())
    throw DeriveError{op.loc, "R005", "this line segment's end is not finite (a parameter became NaN or infinite)"};
  rt::DeriveStats& stats = d_.stats();
  rt::Vec3 end;
  const size_t before = lines_.segmentCount();  // a zero-length step adds nothing
  const rt::SegmentOutcome outcome = lines_.extend(st.line, st.scope.P, &end);
  stats.lineSegments += lines_.segmentCount() - before;
  switch (outcome) {
    case rt::SegmentOutcome::Added: break;
    case rt::SegmentOutcome::Joined:
      ++stats.linesJoined;
      st.scope.P = end;
      ex.culled = true;
      break;
    case rt::SegmentOutcome::Stopped:
      ++stats.linesJoined;
      ex.culled = ex.collided = true;
      break;
    case rt::SegmentOutcome::Ended: ex.culled = true; break;
  }
}

}  // namespace fgsg::backend
