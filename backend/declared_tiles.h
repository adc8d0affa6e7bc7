// A grammar's `tileset NAME { ... }` as a runtime tile set: checked by the same rules as a
// tile file (rt::evolve::validateTileSet), by Evolve when deriving and by `fgsg check`
// beforehand, so a bad tileset gives one message, at its item, from both.
#pragma once

#include "ir/ir.h"
#include "runtime/evolve/genetic.h"
#include "runtime/evolve/tiles.h"

#include <string>
#include <vector>

namespace fgsg::backend {

// The tile set, or false with `message` ("tileset 'ornament': loci[1].cubic[2]: point
// (1.5, 0.5) is outside the tile's unit square ...") and `at` the item it blames.
bool declaredTileSet(const ir::TileSetSpec& spec, rt::evolve::TileSet& out, std::string& message, ir::Loc& at);

// The GA settings the tileset gives (population, max_generations, threshold, weights,
// crossover, mutation, parents, elite) put into `options`; the others are left as they are,
// except that parents and elite not given are capped at the population.
void applyTileSetSettings(const ir::TileSetSpec& spec, rt::evolve::EvolveOptions& options);

// Chan & Hui §6.4's variation a tileset asks of Evolve: `faces "+z";` the face-let
// directions its pattern goes on (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; empty: every one),
// `colours L;` the L-system generation whose cells carry the colours of the colour symmetry
// (runtime/evolve/colour_symmetry.h; -1: no colours).
struct EvolveVariation {
  std::vector<int> faces;
  int colourLevel = -1;
};
EvolveVariation evolveVariation(const ir::TileSetSpec& spec);

}  // namespace fgsg::backend
