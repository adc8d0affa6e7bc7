// A grammar's `tileset NAME { ... }` as a runtime tile set: checked by the same rules as a
// tile file (rt::evolve::validateTileSet), by Evolve when deriving and by `fgsg check`
// beforehand, so a bad tileset gives one message, at its item, from both.
#pragma once

#include "ir/ir.h"
#include "runtime/evolve/genetic.h"
#include "runtime/evolve/tiles.h"

#include <string>

namespace fgsg::backend {

// The tile set, or false with `message` ("tileset 'ornament': loci[1].cubic[2]: point
// (1.5, 0.5) is outside the tile's unit square ...") and `at` the item it blames.
bool declaredTileSet(const ir::TileSetSpec& spec, rt::evolve::TileSet& out, std::string& message, ir::Loc& at);

// The GA settings the tileset gives (population, max_generations, threshold, weights,
// crossover, mutation, parents, elite) put into `options`; the others are left as they are,
// except that parents and elite not given are capped at the population.
void applyTileSetSettings(const ir::TileSetSpec& spec, rt::evolve::EvolveOptions& options);

}  // namespace fgsg::backend
