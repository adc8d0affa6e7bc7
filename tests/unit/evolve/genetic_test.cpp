// The genetic algorithm (Chan & Hui 2013 §4.1): the paper's crossover and mutation
// examples, selection, reproducibility by seed and across thread counts, the p4
// constraint (§6.1), termination and the deadline.
#include "runtime/evolve/genetic.h"
#include "tests/unit/evolve/ga_runs.h"

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>

using namespace fgsg::rt::evolve;
using fgsg::rt::Deadline;
using fgsg::rt::RandomStream;
using fgsg::rt::evolve::testing::smallOptions;

namespace {

const std::string kAB = "AB";
const std::vector<Allele> kUpright{Allele{0, 0}, Allele{1, 0}};  // A and B, orientation 0 only

LSystem2D ab(const std::string& text) { return parseLSystem(text, kAB); }

bool sameEnds(std::array<Point2, 2> p, std::array<Point2, 2> q) {
  auto near = [](Point2 a, Point2 b) { return std::abs(a.x - b.x) < 1e-9 && std::abs(a.y - b.y) < 1e-9; };
  return (near(p[0], q[0]) && near(p[1], q[1])) || (near(p[0], q[1]) && near(p[1], q[0]));
}

// Independent of fitness.cpp: lay four copies of the pattern side by side (the pattern
// repeated by translation) and check that the 2m x 2m cells around the corner where they
// meet (m = floor(n/2)) turn into themselves under a quarter turn about that corner:
// the cell at (i, j) of the block, its locus turned, lands on the cell at (2m-1-j, i)
// with the same symbol and the same locus end points.
bool cornerFourFold(const TileSet& ts, const AlleleGrid& p) {
  const int n = p.side, m = n / 2;
  auto plane = [&](int r, int c) { return p.at(r % n, c % n); };
  for (int i = 0; i < 2 * m; ++i)
    for (int j = 0; j < 2 * m; ++j) {
      const Allele a = plane(n - m + i, n - m + j);
      const Allele b = plane(n - m + (2 * m - 1 - j), n - m + i);
      const std::array<Point2, 2> ea = ts.endpoints(a);
      if (a.symbol != b.symbol || !sameEnds({turnInTile(ea[0], 1), turnInTile(ea[1], 1)}, ts.endpoints(b)))
        return false;
    }
  return true;
}

}  // namespace

TEST_CASE("§4.1.2 two-point crossover: the paper's example", "[evolve][genetic]") {
  const LSystem2D a = ab("{AAAB.ABAB.BABB}"), b = ab("{ABBB.ABAB.ABAA}");
  // The paper underlines the first rule: cut points 0 and 4.
  const auto [c1, c2] = crossover(a, b, 0, 4);
  CHECK(formatLSystem(c1, kAB) == "{ABBB.ABAB.BABB}");
  CHECK(formatLSystem(c2, kAB) == "{AAAB.ABAB.ABAA}");
  // Only positions 1 and 2 of the rule differ, so cutting at 1 and 3 gives the same.
  CHECK(crossover(a, b, 1, 3) == crossover(a, b, 0, 4));
  // A segment reaching into the axiom.
  CHECK(formatLSystem(crossover(a, b, 7, 10).first, kAB) == "{AAAB.ABAB.ABBB}");
  CHECK_THROWS_AS(crossover(a, b, 3, 3), std::invalid_argument);
  CHECK_THROWS_AS(crossover(a, b, 0, 13), std::invalid_argument);
  CHECK_THROWS_AS(crossover(a, ab("{A.B.A}"), 0, 1), std::invalid_argument);

  // Random cut points: the children swap one contiguous run of positions.
  RandomStream random{fgsg::rt::rootKey(5), 0};
  const LSystem2D x = ab("{AAAA.AAAA.AAAA}"), y = ab("{BBBB.BBBB.BBBB}");
  for (int trial = 0; trial < 200; ++trial) {
    const auto [p, q] = crossover(x, y, random);
    int runs = 0, swapped = 0;
    bool inRun = false;
    for (size_t i = 0; i < p.length(); ++i) {
      CHECK(!(p.allele(i) == q.allele(i)));
      const bool s = p.allele(i).symbol == 1;
      swapped += s;
      if (s && !inRun) ++runs;
      inRun = s;
    }
    CHECK(runs == 1);
    CHECK(swapped >= 1);
  }
}

TEST_CASE("§4.1.2 mutation: the paper's example", "[evolve][genetic]") {
  // {ABAB.ABBB.BAAA} -> {ABAB.ABBB.ABBB}: the axiom's four positions mutated; with the
  // alleles A and B the replacement of each is the other one.
  LSystem2D ls = ab("{ABAB.ABBB.BAAA}");
  RandomStream random{fgsg::rt::rootKey(1), 0};
  const size_t positions[] = {8, 9, 10, 11};
  mutateAt(ls, positions, kUpright, random);
  CHECK(formatLSystem(ls, kAB) == "{ABAB.ABBB.ABBB}");

  // With all 8 alleles a mutated allele always changes, and draws among the 7 others.
  const std::vector<Allele> all = exampleTileSet().alleles();
  std::vector<int> seen(8, 0);
  for (int trial = 0; trial < 400; ++trial) {
    LSystem2D one = ab("{A.B.A}");
    const size_t at[] = {2};
    mutateAt(one, at, all, random);
    CHECK(!(one.axiom.at(0, 0) == Allele{0, 0}));
    ++seen[size_t(one.axiom.at(0, 0).index())];
  }
  CHECK(seen[0] == 0);
  for (int i = 1; i < 8; ++i) CHECK(seen[size_t(i)] > 20);

  // Rates: 0 changes nothing, 1 changes every position.
  LSystem2D r = ab("{ABAB.ABBB.BAAA}");
  CHECK(mutate(r, kUpright, 0.0, random) == 0);
  CHECK(formatLSystem(r, kAB) == "{ABAB.ABBB.BAAA}");
  CHECK(mutate(r, kUpright, 1.0, random) == 12);
  CHECK(formatLSystem(r, kAB) == "{BABA.BAAA.ABBB}");
}

TEST_CASE("selection takes the best, ties in slot order", "[evolve][genetic]") {
  const std::vector<double> f{0.2, 0.9, 0.5, 0.9, 0.1};
  CHECK(bestSlots(f, 3) == std::vector<size_t>{1, 3, 2});
  CHECK(bestSlots(f, 9) == std::vector<size_t>{1, 3, 2, 0, 4});
  // Random initialisation draws every position from the alleles.
  RandomStream random{fgsg::rt::rootKey(3), 0};
  const LSystem2D ls = randomLSystem(2, 3, 1, kUpright, random);
  CHECK(ls.rules.size() == 2);
  CHECK(ls.ruleSide() == 3);
  CHECK(ls.length() == 19);
  for (size_t i = 0; i < ls.length(); ++i) CHECK(ls.allele(i).turns == 0);
}

TEST_CASE("the GA is reproducible by seed and the same on 1 and 4 threads", "[evolve][genetic]") {
  const TileSet tiles = exampleTileSet();
  const EvolveOptions o = smallOptions();
  EvolveResult one, four, again;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = evolve(tiles, o);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 4);
    four = evolve(tiles, o);
    again = evolve(tiles, o);
  }
  REQUIRE(one.history.size() == 16);
  CHECK(one.stop == StopReason::kGenerationLimit);
  CHECK_FALSE(one.converged);
  CHECK(one.generations == 15);
  for (const EvolveResult* r : {&four, &again}) {
    CHECK(r->best == one.best);
    REQUIRE(r->history.size() == one.history.size());
    for (size_t i = 0; i < one.history.size(); ++i) {
      CHECK(r->history[i].best == one.history[i].best);
      CHECK(r->history[i].mean == one.history[i].mean);
    }
  }
  // The elite survive: the best fitness never drops; the GA improves on the random start.
  for (size_t i = 1; i < one.history.size(); ++i) CHECK(one.history[i].best >= one.history[i - 1].best);
  CHECK(one.history.back().best > one.history.front().best);
  // The reported measures are those of the best L-system's pattern.
  const FitnessTerms t = PatternMeasure(tiles).evaluate(expand(one.best, o.generation), o.weights, false);
  CHECK(t.fitness == one.terms.fitness);
  CHECK(t.fitness == one.history.back().best);
  // Another seed, another run.
  EvolveOptions other = o;
  other.seed = 12;
  CHECK_FALSE(evolve(tiles, other).best == one.best);
}

TEST_CASE("the GA stops at the threshold and reports progress", "[evolve][genetic]") {
  const TileSet tiles = exampleTileSet();
  EvolveOptions o = smallOptions();
  o.maxGenerations = 200;
  o.threshold = 0.6;
  std::vector<GenerationStats> seen;
  o.progress = [&](const GenerationStats& s) { seen.push_back(s); };
  const EvolveResult r = evolve(tiles, o);
  CHECK(r.converged);
  CHECK(r.stop == StopReason::kThreshold);
  CHECK(r.terms.fitness >= 0.6);
  REQUIRE(seen.size() == r.history.size());
  for (size_t i = 0; i < seen.size(); ++i) {
    CHECK(seen[i].generation == int(i));
    CHECK(seen[i].best == r.history[i].best);
    CHECK(seen[i].mean <= seen[i].best);
  }
  // Every generation before the last was below the threshold.
  for (size_t i = 0; i + 1 < seen.size(); ++i) CHECK(seen[i].best < 0.6);
}

TEST_CASE("with the p4 constraint the result has the four-fold corner symmetry", "[evolve][genetic][p4]") {
  const TileSet tiles = exampleTileSet();
  struct Case {
    int ruleSide, generation;
    uint64_t seed;
  };
  for (const Case c : {Case{3, 3, 1}, Case{3, 4, 2}, Case{2, 4, 3}}) {
    CAPTURE(c.ruleSide, c.generation, c.seed);
    EvolveOptions o;
    o.ruleSide = c.ruleSide;
    o.generation = c.generation;
    o.p4 = true;
    o.seed = c.seed;
    const EvolveResult r = evolve(tiles, o);
    REQUIRE(r.converged);
    CHECK(r.terms.fP4 == 1);
    CHECK(r.terms.fitness >= o.threshold);
    const AlleleGrid pattern = expand(r.best, o.generation);
    CHECK(cornerFourFold(tiles, pattern));
    // The check can fail: the initial population's best is not p4.
    CHECK_FALSE(cornerFourFold(tiles, expand(parseLSystem("{AB90AB.BABA.A}", kAB), c.generation)));
  }
}

TEST_CASE("the deadline ends the run between generations", "[evolve][genetic]") {
  const TileSet tiles = exampleTileSet();
  EvolveOptions o = smallOptions();
  o.maxGenerations = 1000;
  Deadline deadline;  // never expires, until generation 3 replaces it by an expired one
  o.deadline = &deadline;
  o.progress = [&](const GenerationStats& s) {
    if (s.generation == 3) deadline = Deadline(Deadline::Clock::now() - std::chrono::seconds(1), 0.5);
  };
  const EvolveResult r = evolve(tiles, o);
  CHECK(r.stop == StopReason::kDeadline);
  CHECK_FALSE(r.converged);
  CHECK(r.generations == 3);
  CHECK(r.history.size() == 4);
  // Out of time before the first population is measured: no result at all.
  Deadline spent(Deadline::Clock::now() - std::chrono::seconds(1), 0.5);
  o.deadline = &spent;
  o.progress = nullptr;
  CHECK_THROWS_AS(evolve(tiles, o), fgsg::rt::TimeLimitReached);
}

TEST_CASE("bad options are refused with their name", "[evolve][genetic]") {
  const TileSet tiles = exampleTileSet();
  auto message = [&](auto change) {
    EvolveOptions o = smallOptions();
    change(o);
    try {
      evolve(tiles, o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message([](EvolveOptions& o) { o.population = 1; }) == "evolve: population must be >= 2, got 1");
  CHECK(message([](EvolveOptions& o) { o.parents = 31; }) == "evolve: parents must be 1..population (30), got 31");
  CHECK(message([](EvolveOptions& o) { o.mutationRate = 1.5; }).rfind("evolve: mutationRate must be in [0, 1]", 0) == 0);
  CHECK(message([](EvolveOptions& o) { o.generation = 30; }).find("has more than maxCells") != std::string::npos);
  CHECK(message([](EvolveOptions& o) { o.weights = FitnessWeights{0, 0, 0, 1}; }) ==
        "fitness weights a, b, c are all 0");
}
