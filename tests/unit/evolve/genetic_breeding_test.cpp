// How the genetic algorithm breeds a child (genetic.h, "two-point crossover" and
// "selection"): cut points uniform over every pair, the crossover rate, two distinct
// parents; and the threshold met with equality. Each case kills a mutation of
// tests/mutations/ga.txt that survived the first mutation run (issue #51, docs/testing.md);
// the comment above a check says which and why its value differs under it.
#include "runtime/evolve/genetic.h"
#include "tests/unit/evolve/ga_runs.h"

#include <catch2/catch.hpp>

#include <map>
#include <utility>

using namespace fgsg::rt::evolve;
using fgsg::rt::RandomStream;
using namespace fgsg::rt::evolve::testing;

namespace {

const std::string kAB = "AB";

// The options the cases below vary: 20 children of the two best parents, every child
// crossed, no mutation, no elite; one generation.
EvolveOptions breeding(uint64_t seed) {
  EvolveOptions o = untilGenerationLimit(20, 2, 1, seed);
  o.elite = 0;
  o.crossoverRate = 1;
  o.mutationRate = 0;
  return o;
}

}  // namespace

TEST_CASE("random crossover draws every pair of cut points equally often", "[evolve][genetic]") {
  // All A against all B: the first child holds B exactly at the swapped positions
  // [first, last), so each draw shows its cut points. n = 12 positions give 12 * 13 / 2 =
  // 78 pairs 0 <= first < last <= 12, each with probability 1/78: 39000 draws, 500 each
  // expected (standard deviation about 22).
  // Kills "size_t i = below(random, n)" (genetic.cpp: the first cut point never at the
  // end): a pair (a, 12) then comes only from i = a, j = 12, probability 1/12 * 1/12, and
  // every other pair from both orders, 2/144: about 271 and 542 draws, not 500.
  // "if (j > i) ++j" (cut points may coincide) throws from crossover(a, b, i, i).
  const LSystem2D x = parseLSystem("{AAAA.AAAA.AAAA}", kAB), y = parseLSystem("{BBBB.BBBB.BBBB}", kAB);
  const size_t n = x.length();
  REQUIRE(n == 12);
  RandomStream random{fgsg::rt::rootKey(9), 0};
  std::map<std::pair<size_t, size_t>, int> count;
  for (int draw = 0; draw < 39000; ++draw) {
    const LSystem2D child = crossover(x, y, random).first;
    size_t first = n, last = 0;
    for (size_t p = 0; p < n; ++p)
      if (child.allele(p).symbol == 1) first = std::min(first, p), last = p + 1;
    REQUIRE(first < last);
    ++count[{first, last}];
  }
  CHECK(count.size() == 78);
  for (const auto& [cuts, times] : count) {
    INFO("cut points " << cuts.first << ", " << cuts.second);
    CHECK(times > 400);
    CHECK(times < 600);
  }
}

TEST_CASE("the crossover rate: 1 crosses every child, 0 none", "[evolve][genetic]") {
  // Without mutation, a child that is not crossed copies a parent, so with rate 0 nothing
  // new is made and the best fitness of every generation is generation 0's; with rate 1
  // the crossed children of this seed improve it (0.515 -> 0.578, seen by running).
  // Kills "random.next() > o.crossoverRate" (the rate inverted, issue #51's survivor):
  // rate 1 then never crosses (next() < 1), so the best stays at generation 0's and the
  // rate-1 check fails; rate 0 crosses nearly always.
  EvolveOptions o = smallOptions();
  o.mutationRate = 0;
  o.crossoverRate = 0;
  const EvolveResult copies = evolve(exampleTileSet(), o);
  REQUIRE(copies.history.size() == 16);
  for (const GenerationStats& s : copies.history) CHECK(s.best == copies.history[0].best);
  o.crossoverRate = 1;
  const EvolveResult crossed = evolve(exampleTileSet(), o);
  REQUIRE(crossed.history.size() == 16);
  CHECK(crossed.history[0].best == copies.history[0].best);  // the same initial population
  CHECK(crossed.history.back().best > crossed.history[0].best + 0.05);
}

TEST_CASE("a child's two parents are distinct individuals", "[evolve][genetic]") {
  // Two parents, A and B (the two best of generation 0), no elite, every child crossed,
  // no mutation: each of the 20 children is the first child of crossover(A, B) or of
  // crossover(B, A). For seeds 20 and 28 none of them is as fit as A (the best falls:
  // 0.4896 -> 0.4792 and 0.5231 -> 0.5164, seen by running).
  // Kills "if (iq > ip) ++iq" (both parents the same slot): with parents = 2, iq is
  // below(1) = 0, so a child whose first parent is slot 0 (ip = 0, probability 1/2 each)
  // is crossover(A, A) = A; some child of 20 then copies A (all 20 drawing ip = 1 has
  // probability 2^-20), and the best cannot fall.
  for (uint64_t seed : {20u, 28u}) {
    INFO("seed " << seed);
    const EvolveResult r = evolve(exampleTileSet(), breeding(seed));
    REQUIRE(r.history.size() == 2);
    CHECK(r.history[1].best < r.history[0].best);
  }
}

TEST_CASE("a best fitness equal to the threshold ends the run", "[evolve][genetic]") {
  // The threshold is generation 0's best fitness itself (read from a run that stops at
  // generation 0): ">=" stops the second run at once, converged.
  // Kills "s.best > o.threshold" (equality does not stop): the run then goes on to a
  // later generation (one whose best exceeds the threshold, or the limit of 10).
  EvolveOptions o = breeding(11);
  o.maxGenerations = 0;
  const double best0 = evolve(exampleTileSet(), o).history[0].best;
  o.threshold = best0;
  o.maxGenerations = 10;
  const EvolveResult r = evolve(exampleTileSet(), o);
  CHECK(r.converged);
  CHECK(r.stop == StopReason::kThreshold);
  CHECK(r.generations == 0);
  CHECK(r.history.size() == 1);
  CHECK(r.terms.fitness == best0);
}
