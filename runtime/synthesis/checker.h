// An independent consistency checker for synthesized models: it re-reads the adjacency
// constraint from the example itself (eq. 3.1 scanned over the example grid when there is
// one, else the example's rule pairs) and checks every neighbouring pair, border, symmetry,
// mask and connectivity constraint directly on the labels. It shares no code with the
// solver's catalog, transition tables or site graph, so a solver bug cannot hide itself.
#pragma once

#include "runtime/synthesis/constraints.h"
#include "runtime/synthesis/example.h"
#include "runtime/synthesis/label_grid.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis {

struct CheckSpec {
  std::array<bool, 3> periodic{false, false, false};
  std::optional<BorderSpec> border;       // unset: the example's own border
  std::vector<SymmetrySpec> symmetry;
  const PositionWeights* weights = nullptr;  // labels with factor 0 must not appear
  ConnectivitySpec connectivity;
};

struct Violation {
  Cell cell;
  std::string what;
};

// Empty when the model satisfies everything. Stops after `maxViolations`.
std::vector<Violation> checkModel(const LabelGrid& model, const Example& ex, const CheckSpec& spec,
                                  size_t maxViolations = 32);

// Number of 6-connected groups of cells whose label is marked in `connect` (per label).
int countConnectedGroups(const LabelGrid& model, const std::vector<uint8_t>& connect,
                         std::array<bool, 3> periodic);

}  // namespace fgsg::rt::synthesis
