// --lots: a city block grown lot by lot. Each lot's footprint polygon is the axiom's
// shape (as Footprint makes it), with the lot's attribute values and a random stream of
// its own; a lot is derived to the end before the next starts, since its attrs hold
// only while its shapes are derived. A courtyard's hole is joined to the outline by a
// zero-width bridge (rt::cga::footprint).
#include "backend/engine/derivation.h"

#include "runtime/cga/cga.h"
#include "runtime/cga/ground_face.h"
#include "runtime/cga/street_edges.h"

namespace fgsg::backend {

void Derivation::deriveLots(uint64_t root) {
  const double noParams = 0;
  for (size_t k = 0; k < opt_.lots.size(); ++k) {
    const rt::Lot& lot = opt_.lots[k];
    if (k < lotAttrs_.size()) eval_.setAttrSlots(lotAttrs_[k]);
    // x east, y north on the XZ plane with Y up: north is -Z, so a counter-clockwise
    // ring stays counter-clockwise seen from above.
    auto onGround = [](const std::vector<Eigen::Vector2d>& ring) {
      std::vector<Eigen::Vector2d> xz;
      for (const Eigen::Vector2d& p : ring) xz.emplace_back(p.x(), -p.y());
      return xz;
    };
    std::vector<std::vector<Eigen::Vector2d>> holes;
    for (const auto& hole : lot.holes) holes.push_back(onGround(hole));
    rt::cga::Part part;
    std::string error;
    if (!rt::cga::footprint(rt::Scope{}, onGround(lot.outer), holes, arena_, part, error))
      throw DeriveError{{}, "R028", rt::lotName(opt_.lotsName, lot) + ": " + error};
    objectStartScope_ = part.scope;  // the lot's polygon: objectFrame() when asked
    objectStartGeom_ = part.geom;
    objectFrameKnown_ = false;
    streetLot_ = lot.streetWidth.empty() ? nullptr : &lot;
    streetEdgesKnown_ = false;
    frames_.clear();  // a lot is derived to the end before the next: its pivots go with it
    // A `.cga` grammar starts on CityEngine's initial shape: x along the first edge, y up.
    if (m_.cityEngineLots) rt::cga::polygonOnGround(part.scope, part.geom, arena_);
    const auto index = static_cast<uint32_t>(k);
    out_.startBounds.push_back(static_cast<uint32_t>(out_.instances.size()));
    enterStart(index, rt::childKey(root, index), part.scope, part.geom);
    execRoot(0, m_.axiom, part.scope, part.geom, rt::childKey(root, index), 0, index, &noParams, UINT32_MAX);
    deriveWaitingShapes();
    if (k == 0) reserveForLots(opt_.lots.size());
  }
}

const rt::Scope& Derivation::objectFrame() {
  if (!objectFrameKnown_) {
    objectFrame_ = rt::cga::initialShapeFrame(objectStartScope_, objectStartGeom_, arena_);
    objectFrameKnown_ = true;
  }
  return objectFrame_;
}

const rt::cga::StreetEdges* Derivation::streetEdges() {
  if (!streetLot_) return nullptr;
  if (!streetEdgesKnown_) {
    // The lot's ring as deriveLots lays it on the ground (x east, north at -z).
    std::vector<rt::Vec3> ring;
    for (const Eigen::Vector2d& p : streetLot_->outer) ring.emplace_back(p.x(), 0.0, -p.y());
    streetEdges_ = rt::cga::streetEdgesOfLot(ring, streetLot_->streetWidth, objectFrame().Z());
    streetEdgesKnown_ = true;
  }
  return &streetEdges_;
}

const rt::Scope& Derivation::pivotFrame(const rt::Scope& scope) {
  const rt::Scope* pivot = frames_.pivot(scope.pivot);
  return pivot ? *pivot : objectFrame();
}

// After the first lot, room for as many again per lot (and a tenth more): the output
// lists then grow without being copied over and over (the copies were 5 % of the city
// block's time). Only what fits well within the memory budget is asked for; a larger
// city grows as before.
void Derivation::reserveForLots(size_t lots) {
  const auto room = [lots](size_t firstLot) { return firstLot + firstLot * (lots - 1) / 10 * 11; };
  const double bytes = double(room(out_.instances.size())) * sizeof(rt::Instance) +
                       double(room(out_.params.size())) * sizeof(double) +
                       double(room(out_.geometries.size())) * sizeof(rt::Mesh);
  if (!(bytes <= 0.25 * double(memoryBudget_))) return;
  out_.instances.reserve(room(out_.instances.size()));
  out_.params.reserve(room(out_.params.size()));
  out_.geometries.reserve(room(out_.geometries.size()));
}

}  // namespace fgsg::backend
