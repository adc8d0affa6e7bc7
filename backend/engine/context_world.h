// What CityEngine's context queries look at: the shapes a first derivation left (its
// labelled shapes and occluders) and its shape tree, kept for the second derivation that
// answers the queries (docs/cga.md, "Occlusion and context queries").
#pragma once

#include "ir/ir.h"
#include "runtime/cga/occlusion_geometry.h"
#include "runtime/scope.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace fgsg::backend {

struct ContextShape {
  uint32_t start = 0;     // its start shape (a --lots lot)
  std::string label;      // label("name")'s name; "" for an automatic occluder
  uint64_t node = 0;      // its place in the first derivation's shape tree
  rt::Scope scope;        // minimumDistance measures between scopes
  rt::cga::TriangleSoup geometry;  // the occlusion queries test closed ones
};

struct ContextWorld {
  std::vector<ContextShape> shapes;
  // Each node's parent in the first derivation's tree (a start shape's node has none).
  std::unordered_map<uint64_t, uint64_t> parentOf;
  // Each start shape's world bounds: the neighbourhood of inter occlusion queries.
  std::vector<std::pair<rt::Vec3, rt::Vec3>> startBounds;
};

// Whether the grammar asks any context query: then it is derived twice.
bool usesContextQueries(const ir::Module& m);

}  // namespace fgsg::backend
