// From a label grid to pieces to place: for each cell whose piece has an asset, the asset
// name, its quarter turns about the up axis, mirroring and the cell's box. The grammar
// interpreter and the CLI turn these into instances.
#pragma once

#include "runtime/instances.h"
#include "runtime/synthesis/example.h"
#include "runtime/synthesis/label_grid.h"

#include <array>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis {

struct PlacementFrame {
  std::array<double, 3> origin{0, 0, 0};    // world position of the grid's corner
  std::array<double, 3> cellSize{1, 1, 1};  // along grid x, y, z
  // true: grid z is world +Y and grid y is world -Z (the y-up convention of scopes and
  // glTF); false: grid axes are world axes.
  bool yUp = true;
};

struct PiecePlacement {
  int64_t cell = 0;
  Cell at;
  int32_t label = 0;
  std::string asset;
  int rotation = 0;       // quarter turns counter-clockwise about the up axis
  bool mirrored = false;  // mirrored in grid x before turning
  std::array<double, 3> boxMin{}, boxMax{};  // the cell in world space (axis-aligned)
  std::array<float, 3> color{0.8f, 0.8f, 0.8f};
  std::array<double, 16> transform{};  // column-major: unit box [0,1]^3 -> world
};

std::vector<PiecePlacement> piecePlacements(const LabelGrid& labels, const Example& ex,
                                            const PlacementFrame& frame);

// Appends the placements to an instance list (assets and a symbol `symbol` interned).
void appendInstances(const std::vector<PiecePlacement>& placements, const std::string& symbol,
                     InstanceList& out);

}  // namespace fgsg::rt::synthesis
