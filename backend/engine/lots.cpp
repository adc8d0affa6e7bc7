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
    if (((k + 1) & k) == 0) reserveForLots(k + 1, opt_.lots.size());  // after lots 1, 2, 4, 8 ...
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
    std::vector<std::vector<rt::Vec3>> holes;
    for (const auto& hole : streetLot_->holes) {
      holes.emplace_back();
      for (const Eigen::Vector2d& p : hole) holes.back().emplace_back(p.x(), 0.0, -p.y());
    }
    streetEdges_ = rt::cga::streetEdgesOfLot(ring, streetLot_->streetWidth, objectFrame().Z(), holes);
    streetEdgesKnown_ = true;
  }
  return &streetEdges_;
}

const rt::Scope& Derivation::pivotFrame(const rt::Scope& scope) {
  const rt::Scope* pivot = frames_.pivot(scope.pivot);
  return pivot ? *pivot : objectFrame();
}

// After `done` of the `lots` lots (1, 2, 4, 8 ...), room for the rest at the average lot so
// far: the output lists then grow without being copied over and over (the copies were 5 %
// of the city block's time). A list with room for the rest and a tenth more is left as it
// is; one without gets a quarter more, so that a first lot smaller than most no longer
// leaves the lists a few per cent short at the end, copied whole (and their new pages
// faulted in: a tenth of the city's derivation). Untouched room costs no memory, but only
// what fits well within the memory budget is asked for; a larger city grows as before.
void Derivation::reserveForLots(size_t done, size_t lots) {
  const auto room = [&](size_t sofar, double margin) {
    return sofar + size_t(double(sofar) / double(done) * double(lots - done) * margin);
  };
  const double bytes = double(room(out_.instances.size(), 1.25)) * sizeof(rt::Instance) +
                       double(room(out_.params.size(), 1.25)) * sizeof(double) +
                       double(room(out_.geometries.size(), 1.25)) * sizeof(rt::Mesh) +
                       double(room(textures_.projectionCount(), 1.25)) * sizeof(rt::cga::UvProjection);
  if (!(bytes <= 0.25 * double(memoryBudget_))) return;
  const auto grow = [&](auto& list) {
    if (list.capacity() < room(list.size(), 1.1)) list.reserve(room(list.size(), 1.25));
  };
  grow(out_.instances);
  grow(out_.params);
  grow(out_.geometries);
  textures_.reserveLists(grow);
}

}  // namespace fgsg::backend
