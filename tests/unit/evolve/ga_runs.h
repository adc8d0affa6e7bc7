// The genetic tests' GA runs on the example tile set: measured at generation 3 with 2x2
// rules (a pattern that evolves in milliseconds), and a threshold (2) above the maximum
// fitness (1), so every generation up to the limit runs. Each case sets what it varies.
#pragma once

#include "runtime/evolve/genetic.h"

#include <cstdint>

namespace fgsg::rt::evolve::testing {

inline EvolveOptions untilGenerationLimit(int population, int parents, int maxGenerations, uint64_t seed) {
  EvolveOptions o;
  o.population = population;
  o.parents = parents;
  o.maxGenerations = maxGenerations;
  o.seed = seed;
  o.ruleSide = 2;
  o.generation = 3;
  o.threshold = 2;
  return o;
}

// The usual one: 30 individuals, the 8 best breeding, 15 generations.
inline EvolveOptions smallOptions() { return untilGenerationLimit(30, 8, 15, 11); }

}  // namespace fgsg::rt::evolve::testing
