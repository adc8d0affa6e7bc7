// examples/brick_building.fgsg's pattern tree in C++, for the cells tests and
// bench/cells.cpp: on every feature labelled "wall", bricks (BrickBond), and voussoirs
// (ArchBricks) on its arcs, in the texture's corners -> edges -> faces order.
#pragma once

#include "runtime/cells/cellular_texture.h"
#include "runtime/cells/generators.h"

#include <algorithm>
#include <string>
#include <vector>

namespace fgsg::test {

// The example's brick: 215 x 75 x 102.5 mm.
inline const rt::cells::BrickSize kBrickBuildingBrick{0.215, 0.075, 0.1025};

inline bool hasLabel(const std::vector<std::string>& labels, const char* label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

inline void layBrickBuilding(rt::cells::CellularTexture& tex,
                             const rt::cells::BrickSize& brick = kBrickBuildingBrick) {
  using namespace rt::cells;
  const FeatureMesh& fm = tex.features();
  for (FeatureRef f : tex.order()) {
    if (f.kind == FeatureKind::Face) {
      if (hasLabel(fm.faces[f.index].labels, "wall")) layBricks(tex, f, brick);
      continue;
    }
    const auto& labels = f.kind == FeatureKind::Edge ? fm.edges[f.index].labels : fm.corners[f.index].labels;
    if (!hasLabel(labels, "wall")) continue;
    if (f.kind == FeatureKind::Edge && fm.edges[f.index].shape == EdgeShape::Arc) layArchBricks(tex, f, brick);
    else layBricks(tex, f, brick);
  }
}

}  // namespace fgsg::test
