// --lots: a city block grown lot by lot. Each lot's footprint polygon is the axiom's
// shape (as Footprint makes it), with the lot's attribute values and a random stream of
// its own; a lot is derived to the end before the next starts, since its attrs hold
// only while its shapes are derived. Polygons carry no holes yet: a lot with a courtyard
// is built on its outer ring, and the run says so (R028).
#include "backend/engine/derivation.h"

#include "runtime/cga/cga.h"

namespace fgsg::backend {

void Derivation::deriveLots(uint64_t root) {
  const double noParams = 0;
  for (size_t k = 0; k < opt_.lots.size(); ++k) {
    const rt::Lot& lot = opt_.lots[k];
    if (!lot.holes.empty()) ++lotsWithHoles_;
    if (k < lotAttrs_.size()) eval_.setAttrSlots(lotAttrs_[k]);
    // x east, y north on the XZ plane with Y up: north is -Z, so a counter-clockwise
    // ring stays counter-clockwise seen from above.
    std::vector<double> xz;
    for (const Eigen::Vector2d& p : lot.outer) xz.push_back(p.x()), xz.push_back(-p.y());
    rt::cga::Part part;
    std::string error;
    if (!rt::cga::footprint(rt::Scope{}, xz.data(), xz.size(), arena_, part, error))
      throw DeriveError{{}, "R028", opt_.lotsName + ": lot " + std::to_string(k + 1) +
                                        (lot.id.empty() ? "" : " (id \"" + lot.id + "\")") + ": " + error};
    const auto index = static_cast<uint32_t>(k);
    execRoot(0, m_.axiom, part.scope, part.geom, rt::childKey(root, index), 0, index, &noParams, UINT32_MAX);
    deriveWaitingShapes();
  }
}

}  // namespace fgsg::backend
