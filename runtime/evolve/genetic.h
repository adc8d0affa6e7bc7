// The genetic algorithm of Chan & Hui 2013 (§4.1, Fig. 4) over 2D L-systems.
//
//   TileSet tiles = readTileFile("tiles.json");
//   EvolveOptions o;  o.ruleSide = 3;  o.generation = 4;  o.p4 = true;  o.seed = 7;
//   o.progress = [](const GenerationStats& s) { std::printf("%d %.3f %.3f\n", s.generation, s.best, s.mean); };
//   EvolveResult r = evolve(tiles, o);
//   std::string text = formatLSystem(r.best, tiles.letters());   // {...}
//   AlleleGrid pattern = expand(r.best, o.generation);
//
// The genome is the L-system's string: every rule, then the axiom, each row by row
// (LSystem2D::allele). One rule per symbol (our reading of "the number of rules equal to
// the number of alleles": the paper's own examples, {ABAA.ABBA.A} with 8 alleles, have
// one rule per letter; rotated alleles use the turned rule, lsystem2d.h).
//
//  initialisation (§4.1.1): every allele of every rule and of the axiom drawn uniformly
//    from the tile set's alleles (Eq. 2).
//  two-point crossover (§4.1.2): two cut points 0 <= i < j <= length; the children swap
//    the alleles in [i, j). The paper's example swaps the first rule:
//    {AAAB.ABAB.BABB} x {ABBB.ABAB.ABAA} -> {ABBB.ABAB.BABB}, {AAAB.ABAB.ABAA} (i=0, j=4).
//  mutation (§4.1.2): an allele is replaced by another allele of the tile set, drawn
//    uniformly from those that differ from it; each position mutates with probability
//    mutationRate. The paper's example mutates the axiom's four positions:
//    {ABAB.ABBB.BAAA} -> {ABAB.ABBB.ABBB} (with alleles A and B only).
//  selection (§4.1, "genetic operators are performed on the best parents"): truncation
//    selection. The `parents` fittest L-systems are the parents; the `elite` fittest
//    pass unchanged into the next population; every other child is the first child of a
//    crossover (with probability crossoverRate; otherwise a copy) of two parents drawn
//    uniformly (distinct when there are two or more), then mutated.
//  fitness (§4.1.3, Eq. 6): fitness.h, measured on generation `generation` of each
//    L-system. With p4 on, the p4 term joins Eq. 6 (fitness.h).
//  termination (Fig. 4): when the best fitness reaches `threshold` (>=, so a threshold of
//    1 can be met; the paper says "higher than") and, with p4 on, the best pattern has the
//    p4 signature (f_p4 = 1); or after `maxGenerations` generations; or when the
//    deadline expires (checked between generations and before each evaluation).
//
// Reproducible: every random draw comes from a counter-based stream (runtime/random.h)
// keyed by the seed, the GA generation and the individual's slot, and fitness ties are
// broken by slot, so a seed gives the same run on any number of threads. Fitness is
// evaluated in parallel (TBB).
#pragma once

#include "runtime/deadline.h"
#include "runtime/evolve/fitness.h"
#include "runtime/evolve/lsystem2d.h"
#include "runtime/evolve/tiles.h"
#include "runtime/random.h"

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace fgsg::rt::evolve {

struct GenerationStats {
  int generation = 0;   // 0: the initial population
  double best = 0;      // best fitness in the population
  double mean = 0;      // mean fitness
  double bestP4 = 1;    // f_p4 of the best (1 when p4 is off)
  double seconds = 0;   // since evolve() started
};

struct EvolveOptions {
  int ruleSide = 3;            // k: every rule is k x k
  int axiomSide = 1;           // the axiom is axiomSide x axiomSide
  int generation = 4;          // the L-system generation whose pattern is measured (§6.2)
  int population = 100;
  int maxGenerations = 200;    // GA generation limit
  double threshold = 0.7;      // stop when the best fitness reaches it (see docs/evolve.md)
  int parents = 20;            // the best `parents` breed
  int elite = 2;               // the best `elite` survive unchanged
  double crossoverRate = 0.9;  // probability that a child comes from a crossover
  double mutationRate = 0.1;   // per allele of a child
  FitnessWeights weights;      // a = b = c = 1, d = 3
  bool p4 = false;             // the §6.1 constraint
  uint64_t seed = 1;
  size_t maxCells = size_t(1) << 22;  // refuse patterns larger than this (cells)
  // Called after every generation is evaluated (generation 0 included), on the calling
  // thread. May be empty.
  std::function<void(const GenerationStats&)> progress;
  // Optional clock (runtime/deadline.h): asked between generations, and by the workers
  // (Deadline::passed) before each evaluation. A generation cut short is dropped.
  Deadline* deadline = nullptr;
};

enum class StopReason { kThreshold, kGenerationLimit, kDeadline };

struct EvolveResult {
  LSystem2D best;                        // the fittest L-system of the last full generation
  FitnessTerms terms;                    // its measures
  std::vector<GenerationStats> history;  // one entry per generation, 0 first
  StopReason stop = StopReason::kGenerationLimit;
  bool converged = false;                // stopped because the threshold (and p4) was met
  int generations = 0;                   // GA generations after the initial population
};

// Throws std::invalid_argument naming the first bad option.
void checkOptions(const EvolveOptions& o);

// Runs the GA. Throws std::invalid_argument for bad options or tile sets, and
// rt::TimeLimitReached when the deadline expires before the first population has been
// evaluated (there is no result yet).
EvolveResult evolve(const TileSet& tiles, const EvolveOptions& options);

// --- the operators, for tests and for callers who build their own loop ---

// Random L-system: `symbols` rules of ruleSide^2 and an axiom of axiomSide^2 alleles, each
// drawn uniformly from `alleles`.
LSystem2D randomLSystem(int symbols, int ruleSide, int axiomSide, std::span<const Allele> alleles,
                        RandomStream& random);

// Two-point crossover with cut points first < last: the children swap the alleles at
// positions [first, last) of the string (LSystem2D::allele). The parents must have the
// same shape (rule count and sizes, axiom size); throws std::invalid_argument otherwise
// or for cut points outside 0 <= first < last <= length.
std::pair<LSystem2D, LSystem2D> crossover(const LSystem2D& a, const LSystem2D& b, size_t first, size_t last);
// The same with cut points drawn uniformly among all pairs 0 <= first < last <= length.
std::pair<LSystem2D, LSystem2D> crossover(const LSystem2D& a, const LSystem2D& b, RandomStream& random);

// Replaces the allele at each position by another of `alleles`, drawn uniformly among
// those different from it (unchanged when there is no other).
void mutateAt(LSystem2D& ls, std::span<const size_t> positions, std::span<const Allele> alleles, RandomStream& random);
// Mutates each position with probability `rate`; returns how many positions mutated.
size_t mutate(LSystem2D& ls, std::span<const Allele> alleles, double rate, RandomStream& random);

// Slots of the `count` best fitness values, best first; equal values in slot order.
std::vector<size_t> bestSlots(std::span<const double> fitness, size_t count);

}  // namespace fgsg::rt::evolve
