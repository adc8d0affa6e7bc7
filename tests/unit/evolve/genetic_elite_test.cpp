// The elite of the genetic algorithm (genetic.h, "selection"): how many may be kept, and
// that keeping them holds the best fitness. Both were surviving mutations of the mutation
// run (issue #51, docs/testing.md).
#include "runtime/evolve/genetic.h"
#include "tests/unit/evolve/ga_runs.h"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace fgsg::rt::evolve;

TEST_CASE("an elite as large as the population is refused", "[evolve]") {
  EvolveOptions o;
  o.population = 10;
  o.parents = 5;
  o.elite = 9;
  CHECK_NOTHROW(checkOptions(o));
  o.elite = 10;  // no slot left for a child: the GA would never change
  CHECK_THROWS_AS(checkOptions(o), std::invalid_argument);
}

TEST_CASE("the elite keep the best fitness from falling between generations", "[evolve]") {
  // Every child is a parent with every allele mutated (no crossover, rate 1), so only the
  // one elite carries the best L-system over; the threshold (above the maximum, 1) is
  // never reached, so all six generations run.
  EvolveOptions o = fgsg::rt::evolve::testing::untilGenerationLimit(8, 4, 6, 3);
  o.ruleSide = 3;  // as measured when the case was written (the default)
  o.elite = 1;
  o.crossoverRate = 0;
  o.mutationRate = 1;
  const EvolveResult r = evolve(exampleTileSet(), o);
  REQUIRE(r.history.size() == 7);
  for (size_t g = 1; g < r.history.size(); ++g) {
    INFO("generation " << g);
    CHECK(r.history[g].best >= r.history[g - 1].best);
  }
  CHECK(r.terms.fitness == r.history.back().best);
}
