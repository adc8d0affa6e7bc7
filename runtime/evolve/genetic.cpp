#include "runtime/evolve/genetic.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace fgsg::rt::evolve {

namespace {

// Uniform in [0, n), n >= 1.
size_t below(RandomStream& random, size_t n) { return std::min(n - 1, size_t(random.next() * double(n))); }

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("evolve: " + what); }

void sameShape(const LSystem2D& a, const LSystem2D& b) {
  bool same = a.rules.size() == b.rules.size() && a.axiom.side == b.axiom.side;
  for (size_t i = 0; same && i < a.rules.size(); ++i) same = a.rules[i].side == b.rules[i].side;
  if (!same) throw std::invalid_argument("crossover: the two L-systems differ in rule count or array sizes");
}

// Keys: the initial population draws from childKey(root, 0), GA generation t from
// childKey(root, t); individual slot i from childKey(thatKey, i).
RandomStream streamFor(uint64_t root, int generation, size_t slot) {
  return RandomStream{childKey(childKey(root, uint64_t(generation)), uint64_t(slot)), 0};
}

}  // namespace

void checkOptions(const EvolveOptions& o) {
  if (o.ruleSide < 1 || o.ruleSide > 64) bad("ruleSide (k) must be 1..64, got " + std::to_string(o.ruleSide));
  if (o.axiomSide < 1 || o.axiomSide > 4096) bad("axiomSide must be 1..4096, got " + std::to_string(o.axiomSide));
  if (o.generation < 0) bad("generation must be >= 0, got " + std::to_string(o.generation));
  if (o.population < 2) bad("population must be >= 2, got " + std::to_string(o.population));
  if (o.maxGenerations < 0) bad("maxGenerations must be >= 0, got " + std::to_string(o.maxGenerations));
  if (o.parents < 1 || o.parents > o.population)
    bad("parents must be 1..population (" + std::to_string(o.population) + "), got " + std::to_string(o.parents));
  if (o.elite < 0 || o.elite >= o.population)
    bad("elite must be 0..population-1, got " + std::to_string(o.elite));
  if (!(o.crossoverRate >= 0 && o.crossoverRate <= 1))
    bad("crossoverRate must be in [0, 1], got " + std::to_string(o.crossoverRate));
  if (!(o.mutationRate >= 0 && o.mutationRate <= 1))
    bad("mutationRate must be in [0, 1], got " + std::to_string(o.mutationRate));
  if (!std::isfinite(o.threshold)) bad("threshold must be finite");
  if (o.p4) combineFitness(0, 0, 0, 0, o.weights);  // throws for bad weights
  else combineFitness(0, 0, 0, o.weights);
  // Pattern size: axiomSide * ruleSide^generation per side.
  double side = o.axiomSide;
  for (int g = 0; g < o.generation && o.ruleSide > 1 && side * side <= double(o.maxCells); ++g) side *= o.ruleSide;
  if (side * side > double(o.maxCells))
    bad("generation " + std::to_string(o.generation) + " with " + std::to_string(o.ruleSide) + "x" +
        std::to_string(o.ruleSide) + " rules and a " + std::to_string(o.axiomSide) + "x" + std::to_string(o.axiomSide) +
        " axiom has more than maxCells = " + std::to_string(o.maxCells) + " cells");
}

LSystem2D randomLSystem(int symbols, int ruleSide, int axiomSide, std::span<const Allele> alleles,
                        RandomStream& random) {
  if (alleles.empty()) throw std::invalid_argument("randomLSystem: no alleles");
  if (symbols < 1 || ruleSide < 1 || axiomSide < 1) throw std::invalid_argument("randomLSystem: empty shape");
  LSystem2D ls;
  ls.rules.assign(size_t(symbols), AlleleGrid(ruleSide));
  ls.axiom = AlleleGrid(axiomSide);
  for (AlleleGrid& r : ls.rules)
    for (Allele& a : r.cells) a = alleles[below(random, alleles.size())];
  for (Allele& a : ls.axiom.cells) a = alleles[below(random, alleles.size())];
  return ls;
}

std::pair<LSystem2D, LSystem2D> crossover(const LSystem2D& a, const LSystem2D& b, size_t first, size_t last) {
  sameShape(a, b);
  if (!(first < last && last <= a.length()))
    throw std::invalid_argument("crossover: cut points " + std::to_string(first) + ", " + std::to_string(last) +
                                " are not 0 <= first < last <= " + std::to_string(a.length()));
  std::pair<LSystem2D, LSystem2D> children{a, b};
  for (size_t p = first; p < last; ++p) std::swap(children.first.allele(p), children.second.allele(p));
  return children;
}

std::pair<LSystem2D, LSystem2D> crossover(const LSystem2D& a, const LSystem2D& b, RandomStream& random) {
  const size_t n = a.length();
  if (n == 0) throw std::invalid_argument("crossover: empty L-system");
  // Two distinct cut points of 0..n, uniformly.
  size_t i = below(random, n + 1), j = below(random, n);
  if (j >= i) ++j;
  if (j < i) std::swap(i, j);
  return crossover(a, b, i, j);
}

void mutateAt(LSystem2D& ls, std::span<const size_t> positions, std::span<const Allele> alleles, RandomStream& random) {
  for (size_t p : positions) {
    Allele& here = ls.allele(p);
    const size_t others = size_t(std::count_if(alleles.begin(), alleles.end(), [&](Allele a) { return !(a == here); }));
    if (others == 0) continue;
    size_t pick = below(random, others);
    for (Allele a : alleles)
      if (!(a == here) && pick-- == 0) {
        here = a;
        break;
      }
  }
}

size_t mutate(LSystem2D& ls, std::span<const Allele> alleles, double rate, RandomStream& random) {
  size_t mutated = 0;
  const size_t n = ls.length();
  for (size_t p = 0; p < n; ++p)
    if (random.next() < rate) {
      const size_t one[1] = {p};
      mutateAt(ls, one, alleles, random);
      ++mutated;
    }
  return mutated;
}

std::vector<size_t> bestSlots(std::span<const double> fitness, size_t count) {
  std::vector<size_t> order(fitness.size());
  std::iota(order.begin(), order.end(), size_t(0));
  count = std::min(count, order.size());
  std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(count), order.end(), [&](size_t x, size_t y) {
    return fitness[x] > fitness[y] || (fitness[x] == fitness[y] && x < y);
  });
  order.resize(count);
  return order;
}

EvolveResult evolve(const TileSet& tiles, const EvolveOptions& o) {
  checkOptions(o);
  const auto start = std::chrono::steady_clock::now();
  const PatternMeasure measure(tiles);  // validates the tile set
  const std::vector<Allele> alleles = tiles.alleles();
  const uint64_t root = rootKey(o.seed);
  const size_t P = size_t(o.population);
  Deadline* deadline = o.deadline;

  std::vector<LSystem2D> pop(P), next(P);
  std::vector<FitnessTerms> terms(P), nextTerms(P);
  std::atomic<bool> cut{false};

  auto evaluate = [&](const LSystem2D& ls) { return measure.evaluate(expand(ls, o.generation, o.maxCells), o.weights, o.p4); };

  // Generation 0.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, P), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (deadline && (cut.load(std::memory_order_relaxed) || deadline->passed())) {
        cut = true;
        return;
      }
      RandomStream random = streamFor(root, 0, i);
      pop[i] = randomLSystem(tiles.symbolCount(), o.ruleSide, o.axiomSide, alleles, random);
      terms[i] = evaluate(pop[i]);
    }
  });
  if (cut) throw TimeLimitReached{deadline->seconds()};

  EvolveResult result;
  std::vector<double> fitness(P);
  for (int t = 0;; ++t) {
    for (size_t i = 0; i < P; ++i) fitness[i] = terms[i].fitness;
    const std::vector<size_t> best = bestSlots(fitness, size_t(std::max(o.parents, o.elite)));
    double sum = 0;
    for (double f : fitness) sum += f;  // in slot order: the same on any thread count
    GenerationStats s;
    s.generation = t;
    s.best = fitness[best[0]];
    s.mean = sum / double(P);
    s.bestP4 = terms[best[0]].fP4;
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.history.push_back(s);
    result.best = pop[best[0]];
    result.terms = terms[best[0]];
    result.generations = t;
    if (o.progress) o.progress(s);

    if (s.best >= o.threshold && (!o.p4 || s.bestP4 == 1)) {
      result.stop = StopReason::kThreshold;
      result.converged = true;
      break;
    }
    if (t >= o.maxGenerations) {
      result.stop = StopReason::kGenerationLimit;
      break;
    }
    if (deadline && deadline->expiredNow()) {
      result.stop = StopReason::kDeadline;
      break;
    }

    // Generation t + 1: the elite survive, the rest are children of the best parents.
    const size_t elite = size_t(o.elite), parents = size_t(o.parents);
    for (size_t i = 0; i < elite; ++i) {
      next[i] = pop[best[i]];
      nextTerms[i] = terms[best[i]];
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(elite, P), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        if (deadline && (cut.load(std::memory_order_relaxed) || deadline->passed())) {
          cut = true;
          return;
        }
        RandomStream random = streamFor(root, t + 1, i);
        // Two parents among the best, distinct when there are two or more.
        const size_t ip = below(random, parents);
        size_t iq = ip;
        if (parents > 1) {
          iq = below(random, parents - 1);
          if (iq >= ip) ++iq;
        }
        const size_t p = best[ip], q = best[iq];
        if (random.next() < o.crossoverRate) next[i] = crossover(pop[p], pop[q], random).first;
        else next[i] = pop[p];
        mutate(next[i], alleles, o.mutationRate, random);
        nextTerms[i] = evaluate(next[i]);
      }
    });
    if (cut) {
      result.stop = StopReason::kDeadline;
      break;
    }
    std::swap(pop, next);
    std::swap(terms, nextTerms);
  }
  return result;
}

}  // namespace fgsg::rt::evolve
