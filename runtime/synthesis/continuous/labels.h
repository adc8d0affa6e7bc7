// Labels of continuous model synthesis (Merrell §4.5.1-4.5.5): the vertex figures that occur
// in the example. A label is the set of sectors (directions.h) of its own directions that
// lie inside the solid: the Boolean expression of half-spaces of the thesis, kept as a
// truth table. Labels are canonical — a direction the figure does not depend on is
// dropped — so equal figures found at different places of the example are one label, and
// a label fits an output vertex exactly when its directions are among the vertex's planes
// (§4.5.4).
//
// Two labels may sit at the ends of an output edge when they agree on the edge (§4.5.5):
// evaluated just off each end along the edge, around every wedge the edge's planes cut,
// they give the same inside/outside pattern (`edgePattern`).
#pragma once

#include "runtime/synthesis/continuous/example_solid.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

struct Label {
  uint32_t dirs = 0;            // the half-spaces it uses (bits over ExampleSolid::dirs)
  std::vector<uint32_t> in;     // sign masks (over `dirs`) of its inside sectors, sorted
  bool operator==(const Label& o) const { return dirs == o.dirs && in == o.in; }
  // Inside in the sector with these signs (bits outside `dirs` are ignored).
  bool inside(uint32_t signs) const;
  bool empty() const { return in.empty(); }
  bool full() const { return dirs == 0 && !in.empty(); }
};

struct LabelCatalog {
  std::vector<Label> labels;  // 0: empty space, 1: solid interior
  // Per label: the example has it somewhere above its lowest level (its ground plane,
  // the least y). A figure found only on that plane (a pier's foot) is where the example
  // stands on the ground; one found above it with a face looking down is a soffit (a
  // bridge deck's underside), which the example allows off the ground (§4.5.3 with the
  // ground as the bottom boundary only, Fig. 3.11).
  std::vector<uint8_t> raised;
  static constexpr int kEmpty = 0, kFull = 1;
};

// Every vertex figure of the example: of its interior and exterior, its faces, its edges
// and its vertices (§4.5.3). False when `timeUp` (asked at every edge and vertex) said
// yes first.
bool exampleLabels(const ExampleSolid& solid, LabelCatalog& out, const std::function<bool()>& timeUp);
// The same without a limit.
inline LabelCatalog exampleLabels(const ExampleSolid& solid) {
  LabelCatalog c;
  exampleLabels(solid, c, [] { return false; });
  return c;
}

// The inside/outside of `label` just off a vertex along `axis`, one bit per wedge of
// `wedges` (wedgesAround(axis, planes containing the axis)). None when the label uses a
// plane containing the axis that is not among the edge's planes `edgePlanes` (it cannot
// sit at a vertex with this edge).
std::optional<uint64_t> edgePattern(const Label& label, const std::vector<IVec3>& dirs, const IVec3& axis,
                                    uint32_t edgePlanes, const std::vector<DVec3>& wedges);

// Canonical form of a figure given as inside/outside per sector of `mask` (every sector
// of the central arrangement of those directions, once).
Label canonicalLabel(uint32_t mask, std::vector<std::pair<uint32_t, bool>> sectors);

}  // namespace fgsg::rt::synthesis::continuous
