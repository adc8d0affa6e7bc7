// The catalog's propagation (single-label rows, memoised supports, removed-label deltas,
// decided neighbours skipped, a FIFO queue) reaches the same fixpoint as arc consistency
// computed the plain way, after every assignment of a random sequence.
#include "runtime/synthesis/catalog.h"
#include "runtime/synthesis/random.h"
#include "test_helpers.h"

using namespace synth_test;

namespace {

// Repeats "dom(u) &= support(d, dom(v))" over every edge until nothing changes; false as
// soon as a domain is empty.
bool naiveArcConsistency(const TransitionTable& t, const SiteGraph& g, std::vector<Word>& dom) {
  const int W = t.words();
  bool changed = true;
  while (changed) {
    changed = false;
    for (int64_t v = 0; v < g.siteCount; ++v)
      for (int d = 0; d < g.slots; ++d) {
        const int32_t u = g.at(v, d);
        if (u < 0) continue;
        std::vector<Word> sup(size_t(W), 0);
        forEachBit(&dom[size_t(v) * size_t(W)], W, [&](int b) {
          for (int i = 0; i < W; ++i) sup[size_t(i)] |= t.row(d, b)[i];
        });
        for (int i = 0; i < W; ++i) {
          Word& x = dom[size_t(u) * size_t(W) + size_t(i)];
          if ((x & sup[size_t(i)]) != x) { x &= sup[size_t(i)]; changed = true; }
        }
        if (firstBit(&dom[size_t(u) * size_t(W)], W) < 0) return false;
      }
  }
  return true;
}

// Starts from every label at each site except a few sites that lose labels at random
// (keep: probability that such a site keeps a label); returns the assignments made.
template <int NW>
int compareWithNaive(const Example& ex, GridSize size, uint64_t seed, double keep) {
  const TransitionTable t = buildTransitions(ex, NW);
  const SiteGraph g = makeGridGraph(size, {false, false, false});
  const int k = ex.labelCount();
  Rng rng(seed);
  BitsetCatalog<NW> cat(t, g);
  std::vector<Word> ref(size_t(g.siteCount) * NW, 0), base(NW);
  for (int64_t s = 0; s < g.siteCount; ++s) {
    std::fill(base.begin(), base.end(), 0);
    const bool thin = rng.uniform() < 0.1;
    for (int b = 0; b < k; ++b)
      if (!thin || rng.uniform() < keep) setBit(base.data(), b);
    if (firstBit(base.data(), NW) < 0) setBit(base.data(), int(rng.below(uint64_t(k))));
    cat.activate(s, base.data());
    std::copy(base.begin(), base.end(), ref.begin() + s * NW);
    cat.push(s);
  }
  auto same = [&] {
    for (int64_t s = 0; s < g.siteCount; ++s)
      for (int i = 0; i < NW; ++i)
        if (cat.domain(s)[i] != ref[size_t(s) * NW + size_t(i)]) return false;
    return true;
  };
  bool ok = cat.propagate() < 0;
  REQUIRE(ok == naiveArcConsistency(t, g, ref));
  if (ok) REQUIRE(same());
  int steps = 0;
  while (ok) {
    std::vector<int64_t> open;
    for (int64_t s = 0; s < g.siteCount; ++s)
      if (singleLabel<NW>(cat.domain(s)) < 0) open.push_back(s);
    if (open.empty()) break;
    const int64_t s = open[size_t(rng.below(open.size()))];
    std::vector<int> labels;
    forEachBit(cat.domain(s), NW, [&](int b) { labels.push_back(b); });
    const int b = labels[size_t(rng.below(labels.size()))];
    cat.assign(s, b);
    std::fill(ref.begin() + s * NW, ref.begin() + (s + 1) * NW, 0);
    setBit(&ref[size_t(s) * NW], b);
    ok = cat.propagate() < 0;
    INFO("step " << steps << " site " << s << " label " << b);
    REQUIRE(ok == naiveArcConsistency(t, g, ref));
    if (ok) REQUIRE(same());
    ++steps;
  }
  return steps;
}

// 100 labels with loose structure: label (a, b) with a following x and b following y + z
// up to random jumps, so rules are sparse but leave choices.
Example patternExample() {
  Example ex;
  LabelGrid grid(GridSize{30, 30, 8}, 0);
  Rng rng(7);
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x)
        grid.at(x, y, z) = int32_t((x + rng.below(2)) % 10 + 10 * ((y + z + rng.below(2)) % 10));
  for (int l = 0; l < 100; ++l) {
    Piece p;
    p.name = "p" + std::to_string(l);
    p.weight = -1;
    ex.labels.push_back(p);
  }
  ex.grid = grid;
  computeAdjacencyFromGrid(ex);
  return ex;
}

}  // namespace

TEST_CASE("catalog propagation equals naive arc consistency (k <= 64)", "[synthesis][catalog]") {
  Example castle = load("castle.txt");
  REQUIRE(paddedWordsFor(castle.labelCount()) == 1);
  int steps = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) steps += compareWithNaive<1>(castle, {7, 6, 4}, seed, 0.8);
  Example roads = load("roads.json");
  for (uint64_t seed = 1; seed <= 100; ++seed) steps += compareWithNaive<1>(roads, {9, 8, 1}, seed, 0.8);
  CHECK(steps > 50);
}

TEST_CASE("catalog propagation equals naive arc consistency (k = 100, two words)", "[synthesis][catalog]") {
  Example ex = patternExample();
  REQUIRE(paddedWordsFor(ex.labelCount()) == 2);
  int steps = 0;
  for (uint64_t seed = 1; seed <= 6; ++seed) steps += compareWithNaive<2>(ex, {8, 7, 5}, seed, 0.8);
  // Wider than the label count needs: the padding words stay empty.
  for (uint64_t seed = 1; seed <= 2; ++seed) steps += compareWithNaive<4>(ex, {6, 5, 4}, seed, 0.8);
  CHECK(steps > 20);
}

TEST_CASE("grid site graph computes the neighbours of every slot from coordinates", "[synthesis][catalog]") {
  // Computed neighbours (face bits, steps, wraps) against the plain coordinate rule.
  for (GridSize size : {GridSize{5, 4, 3}, GridSize{7, 3, 1}, GridSize{1, 2, 4}, GridSize{2, 2, 2}})
    for (int per = 0; per < 8; ++per) {
      const std::array<bool, 3> periodic{(per & 1) != 0, (per & 2) != 0, (per & 4) != 0};
      const SiteGraph g = makeGridGraph(size, periodic);
      CHECK(g.slots == (size.nz > 1 ? 6 : 4));
      const int n[3] = {size.nx, size.ny, size.nz};
      int64_t i = 0;
      for (int z = 0; z < size.nz; ++z)
        for (int y = 0; y < size.ny; ++y)
          for (int x = 0; x < size.nx; ++x, ++i)
            for (int d = 0; d < 6; ++d) {
              int q[3] = {x, y, z};
              const int axis = d / 2;
              q[axis] += d % 2 == 0 ? 1 : -1;
              int64_t expect = -1;
              if (d < g.slots && q[axis] >= 0 && q[axis] < n[axis]) expect = q[0] + int64_t(size.nx) * (q[1] + int64_t(size.ny) * q[2]);
              else if (d < g.slots && periodic[size_t(axis)] && n[axis] >= 2) {
                q[axis] = (q[axis] + n[axis]) % n[axis];
                expect = q[0] + int64_t(size.nx) * (q[1] + int64_t(size.ny) * q[2]);
              }
              CHECK(g.at(i, d) == expect);
            }
    }
}
