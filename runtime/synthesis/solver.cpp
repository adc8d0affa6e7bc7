// Algorithm 3.1 (assign every cell from the catalog, propagate after each assignment) and
// Algorithm 3.4 (start from a trivial consistent model, then re-synthesize overlapping
// blocks shifted by half a block, reverting a block that fails). Both run through one
// routine, `runBlock`: whole-grid synthesis is the block that is the whole grid.
#include "runtime/memory_budget.h"
#include "runtime/synthesis/catalog.h"
#include "runtime/synthesis/random.h"
#include "runtime/synthesis/synthesis.h"

#include <algorithm>
#include <limits>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <queue>
#include <tuple>

namespace fgsg::rt::synthesis {

namespace {

using Clock = std::chrono::steady_clock;

enum class Order { kScanline, kMinEntropy, kGrow };

// Everything derived from the example and the options once per run.
struct Problem {
  const Example& ex;
  const SynthesisOptions& o;
  GridSize size;
  int k = 0, W = 0;                          // W: words per domain, paddedWordsFor(k)
  TransitionTable t;
  SiteGraph g;
  // Per cell: the labels borders/masks/symmetry allow, as an index into a table of the
  // few distinct sets (one per region and face combination, one per symmetry fixed point):
  // 4 bytes a cell rather than a domain's 16 or more.
  std::vector<Word> baseTable;
  std::vector<uint32_t> baseIndex;
  std::vector<std::vector<double>> weight;   // per region: label weights
  std::vector<Word> connectMask;             // labels of the connectivity constraint
  Clock::time_point start;
  Deadline deadline;  // timeLimitSeconds from the start
  uint64_t maxAssignments = 0;

  // Asked at every assignment; reads the clock about every 0.1 ms (runtime/deadline.h).
  bool timeUp() { return deadline.expired() || (o.deadline && o.deadline->expired()); }

  Problem(const Example& e, const SynthesisOptions& opt) : ex(e), o(opt) {}
  const Word* base(int64_t c) const { return &baseTable[size_t(baseIndex[size_t(c)]) * size_t(W)]; }
  const std::vector<double>& weights(int64_t c) const {
    return weight[o.weights.region.empty() ? 0 : o.weights.region[size_t(c)]];
  }
};

std::string cellText(const Cell& c) {
  return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z) + ")";
}

// Validates the options and compiles the problem; false with a message on bad options.
bool compile(Problem& P, std::string& error) {
  const Example& ex = P.ex;
  const SynthesisOptions& o = P.o;
  P.size = o.size;
  P.k = ex.labelCount();
  if (P.k == 0) { error = "the example has no labels"; return false; }
  if (P.k > 4096) { error = "the example has more than 4096 labels"; return false; }
  if (o.size.nx < 1 || o.size.ny < 1 || o.size.nz < 1) { error = "the output size must be at least 1x1x1"; return false; }
  if (o.size.count() > (int64_t(1) << 30)) { error = "the output has more than 2^30 cells"; return false; }
  if (ex.dims == 2 && o.size.nz > 1) {
    error = "the example is planar (no rules along z): the output needs nz = 1, got nz = " + std::to_string(o.size.nz);
    return false;
  }
  for (const auto& s : o.symmetry) {
    if (s.kind == SymmetrySpec::kRotate90 && o.size.nx != o.size.ny) { error = "rotate-90 symmetry needs a square grid (nx == ny)"; return false; }
    if ((s.kind == SymmetrySpec::kTranslateX || s.kind == SymmetrySpec::kTranslateY) && s.offset < 1) { error = "translation symmetry needs an offset >= 1"; return false; }
  }
  if (o.connectivity.enabled && (o.block[0] > 0 || o.block[1] > 0 || o.block[2] > 0)) {
    error = "the connectivity constraint grows the model from seeds over the whole grid: use it without blocks";
    return false;
  }
  if (!o.weights.empty()) {
    if (!o.weights.region.empty() && int64_t(o.weights.region.size()) != o.size.count()) { error = "per-position weights do not match the grid size"; return false; }
    for (const auto& f : o.weights.factor)
      if (int(f.size()) != P.k) { error = "per-position weights do not match the label count"; return false; }
    for (uint16_t r : o.weights.region)
      if (r >= o.weights.factor.size()) { error = "per-position weights name an unknown region"; return false; }
  }
  P.W = paddedWordsFor(P.k);
  P.t = buildTransitions(ex, P.W);
  P.g = makeGridGraph(o.size, o.periodic);

  // Symmetry links: one relation T_f per symmetry, a link p -> σ(p) per cell.
  std::vector<Link> links;
  std::vector<std::pair<int64_t, std::vector<int32_t>>> selfMaps;  // cells with σ(p) = p
  for (const auto& s : o.symmetry) {
    auto f = symmetryLabelMap(s, ex);
    if (int(f.size()) != P.k) { error = "the example's symmetry label map has the wrong size"; return false; }
    const int rel = P.t.addRelationPair(mapPairs(f, P.k));
    for (int64_t c = 0; c < o.size.count(); ++c) {
      const int64_t img = symmetryImage(s, o.size, c);
      if (img < 0) continue;
      if (img == c) selfMaps.push_back({c, f});
      // A mirror or half turn pairs each cell with its image; list each pair once.
      else if (s.kind == SymmetrySpec::kRotate90 || s.kind == SymmetrySpec::kTranslateX ||
               s.kind == SymmetrySpec::kTranslateY || c < img)
        links.push_back({int32_t(c), int32_t(img), rel});
    }
  }
  if (!links.empty() || !selfMaps.empty()) {
    std::vector<int> rev(static_cast<size_t>(P.t.relationCount()));
    for (int r = 0; r < P.t.relationCount(); ++r) rev[size_t(r)] = P.t.reverse(r);
    setLinks(P.g, links, rev);
  }

  // Per-region weights and allowed sets.
  const size_t regions = o.weights.empty() ? 1 : o.weights.factor.size();
  P.weight.assign(regions, std::vector<double>(size_t(P.k), 1.0));
  std::vector<Word> regionDom(regions * size_t(P.W), 0);
  for (size_t r = 0; r < regions; ++r)
    for (int b = 0; b < P.k; ++b) {
      const double f = o.weights.empty() ? 1.0 : o.weights.factor[r][size_t(b)];
      const double w = o.uniformWeights ? 1.0 : std::max(0.0, ex.labels[size_t(b)].weight);
      P.weight[r][size_t(b)] = w * f;
      if (f > 0) setBit(&regionDom[r * size_t(P.W)], b);
    }

  // Base domains: region ∩ borders ∩ symmetry fixed points.
  BorderSpec border = o.border ? *o.border : ex.border;
  P.baseIndex.resize(size_t(o.size.count()));
  // Per face: the labels its cells may hold (all when the face is unconstrained); the
  // second half of faceMask leaves out `only`, for the cells of a background-only region.
  std::vector<Word> faceMask(12 * size_t(P.W), ~Word(0));
  for (int f = 0; f < 6; ++f) {
    Word* m = &faceMask[size_t(f) * size_t(P.W)];
    Word* withoutOnly = &faceMask[size_t(6 + f) * size_t(P.W)];
    const int axis = f / 2;
    if (o.periodic[size_t(axis)] || (axis == 2 && ex.dims == 2)) continue;  // planar: no z faces
    const int32_t fixed = border.fixed[size_t(f)], out = border.outside[size_t(f)];
    std::vector<Word> one(static_cast<size_t>(P.W), 0);
    if (!border.only[size_t(f)].empty()) {
      for (int32_t l : border.only[size_t(f)])
        if (l >= 0 && l < P.k) setBit(one.data(), l);
      for (int w = 0; w < P.W; ++w) m[w] &= one[size_t(w)];
    }
    if (fixed >= 0 && fixed < P.k) {
      std::fill(one.begin(), one.end(), 0);
      setBit(one.data(), fixed);
      for (int w = 0; w < P.W; ++w) m[w] &= one[size_t(w)], withoutOnly[w] &= one[size_t(w)];
    }
    // The virtual outside cell lies across the face; this cell is at relation f from it
    // (xmin: the cell is at +x of the outside cell, relation +x = 0 = face xmin).
    if (out >= 0 && out < P.k)
      for (int w = 0; w < P.W; ++w) m[w] &= P.t.row(f, out)[w], withoutOnly[w] &= P.t.row(f, out)[w];
  }
  std::vector<uint8_t> backgroundOnly(regions, 0);
  for (size_t r = 0; r < regions; ++r) backgroundOnly[r] = backgroundOnlyRegion(o.weights, r, ex);
  // Face f of the border (xmin, xmax, ymin, ...) is the one slot f ^ 1 points through:
  // the site graph's face bits, in slot order, name the border faces a cell lies on.
  const size_t W = size_t(P.W);
  std::vector<uint32_t> entry(regions * 64, UINT32_MAX);  // (region, face bits) -> table index
  for (int64_t c = 0; c < o.size.count(); ++c) {
    const size_t r = o.weights.region.empty() ? 0 : o.weights.region[size_t(c)];
    const unsigned faces = P.g.face[size_t(c)];
    uint32_t& e = entry[r * 64 + faces];
    if (e == UINT32_MAX) {
      e = uint32_t(P.baseTable.size() / W);
      P.baseTable.insert(P.baseTable.end(), &regionDom[r * W], &regionDom[r * W] + W);
      Word* d = &P.baseTable[size_t(e) * W];
      const size_t half = backgroundOnly[r] ? 6 : 0;
      for (int f = 0; f < 6; ++f)
        if ((faces >> (f ^ 1)) & 1)
          for (size_t w = 0; w < W; ++w) d[w] &= faceMask[(half + size_t(f)) * W + w];
    }
    P.baseIndex[size_t(c)] = e;
  }
  for (const auto& [c, f] : selfMaps) {
    const uint32_t e = uint32_t(P.baseTable.size() / W);
    P.baseTable.insert(P.baseTable.end(), W, 0);
    std::copy_n(P.base(c), W, &P.baseTable[size_t(e) * W]);
    P.baseIndex[size_t(c)] = e;
    Word* d = &P.baseTable[size_t(e) * W];
    for (int b = 0; b < P.k; ++b)
      if (f[size_t(b)] != b) d[b >> 6] &= ~(Word(1) << (b & 63));
  }

  P.connectMask.assign(size_t(P.W), 0);
  if (o.connectivity.enabled) {
    bool any = false;
    for (int b = 0; b < P.k; ++b) {
      const bool on = o.connectivity.labels.empty() ? ex.labels[size_t(b)].connect
                                                    : (size_t(b) < o.connectivity.labels.size() && o.connectivity.labels[size_t(b)]);
      if (on) { setBit(P.connectMask.data(), b); any = true; }
    }
    if (!any) { error = "the connectivity constraint names no labels (mark labels `connect`)"; return false; }
    if (o.connectivity.seeds < 1) { error = "the connectivity constraint needs at least one seed"; return false; }
  }
  return true;
}

// NW = P.W words per domain, fixed at compile time so every domain loop unrolls.
template <int NW>
class Solver {
 public:
  Solver(Problem& P, LabelGrid& M, SynthesisStats& stats, uint64_t seed)
      : P_(P), M_(M), stats_(stats), cat_(P.t, P.g), rng_(seed),
        assigned_(size_t(P.size.count())) {}

  size_t bytes() const { return cat_.bytes(); }
  uint64_t pops() const { return cat_.pops(); }
  uint64_t supportMisses() const { return cat_.memoMisses(); }

  // Re-synthesizes `sites` (sorted) with every other cell fixed to its label in M. On
  // success M holds the new labels; on failure M is untouched and `fail` says why.
  bool runBlock(const std::vector<int32_t>& sites, bool trivial, Order order, SynthesisFailure& fail) {
    constexpr int W = NW;
    for (int32_t s : sites) {
      cat_.activate(s, P_.base(s));
      assigned_[size_t(s)] = 0;
    }
    bool ok = init(sites, fail) && assignAll(sites, trivial, order, fail);
    if (ok)
      for (int32_t s : sites) M_[s] = firstBit(cat_.domain(s), W);
    cat_.clearQueue();  // sites queued before init failed must not leak into the next block
    for (int32_t s : sites) cat_.deactivate(s);
    return ok;
  }

 private:
  bool failAt(int64_t site, SynthesisFailure& fail, SynthesisFailure::Kind kind = SynthesisFailure::kContradiction) {
    fail.kind = kind;
    fail.cell = M_.cell(site);
    fail.assignments = stats_.assignments;
    return false;
  }

  // Applies the fixed cells around the block to its domains (Algorithm 3.4 lines 12-17),
  // then propagates.
  bool init(const std::vector<int32_t>& sites, SynthesisFailure& fail) {
    constexpr int W = NW;
    const SiteGraph& g = P_.g;
    for (int32_t s : sites) {
      Word* d = cat_.domain(s);
      for (int slot = 0; slot < g.slots; ++slot) {
        const int32_t u = g.at(s, slot);
        if (u < 0 || cat_.active(u)) continue;
        const Word* r = P_.t.row(P_.t.reverse(slot), M_[u]);
        for (int w = 0; w < W; ++w) d[w] &= r[w];
      }
      if (g.hasLinks())
        for (uint32_t e = g.linkStart[size_t(s)]; e < g.linkStart[size_t(s) + 1]; ++e) {
          const int32_t u = g.linkSite[e];
          if (cat_.active(u)) continue;
          const Word* r = P_.t.row(P_.t.reverse(g.linkRelation[e]), M_[u]);
          for (int w = 0; w < W; ++w) d[w] &= r[w];
        }
      if (firstBit(d, W) < 0) return failAt(s, fail);
      cat_.push(s);
    }
    const int64_t bad = cat_.propagate();
    return bad < 0 || failAt(bad, fail);
  }

  bool limitsHit(SynthesisFailure& fail, int64_t site) {
    if (stats_.assignments >= P_.maxAssignments) return !failAt(site, fail, SynthesisFailure::kStepLimit);
    if (P_.timeUp()) return !failAt(site, fail, SynthesisFailure::kTimeLimit);
    return false;
  }

  int choose(int64_t site, bool trivial, const Word* restrictTo = nullptr) {
    const Word* d = cat_.domain(site);
    constexpr int W = NW;
    const auto& w = P_.weights(site);
    if (trivial) {
      // The trivial initial model: empty space where possible, else background, else the
      // most frequent label (deterministic: no random choice).
      if (P_.ex.emptyLabel >= 0 && testBit(d, P_.ex.emptyLabel)) return P_.ex.emptyLabel;
      int best = -1;
      double bestKey = -1;
      forEachBit(d, W, [&](int b) {
        double key = w[size_t(b)] + (P_.ex.labels[size_t(b)].background ? 1e300 : 0.0);
        if (key > bestKey) { bestKey = key; best = b; }
      });
      return best;
    }
    double sum = 0;
    int count = 0;
    forEachBit(d, W, [&](int b) {
      if (restrictTo && !testBit(restrictTo, b)) return;
      sum += w[size_t(b)];
      ++count;
    });
    if (count == 0) return -1;
    if (sum <= 0) {
      // Every remaining label has weight 0 (never seen in the example): uniform choice.
      uint64_t pick = rng_.below(uint64_t(count));
      int chosen = -1;
      forEachBit(d, W, [&](int b) {
        if (restrictTo && !testBit(restrictTo, b)) return;
        if (pick-- == 0) chosen = b;
      });
      return chosen;
    }
    double r = rng_.uniform() * sum;
    int chosen = -1, last = -1;
    forEachBit(d, W, [&](int b) {
      if (chosen >= 0 || (restrictTo && !testBit(restrictTo, b))) return;
      if (w[size_t(b)] > 0) last = b;
      r -= w[size_t(b)];
      if (r < 0 && w[size_t(b)] > 0) chosen = b;
    });
    return chosen >= 0 ? chosen : last;
  }

  // Assigns one site and propagates (Algorithm 3.1 lines 9-14).
  bool assignOne(int64_t s, bool trivial, SynthesisFailure& fail, const Word* restrictTo = nullptr) {
    if (limitsHit(fail, s)) return false;
    assigned_[size_t(s)] = 1;
    ++stats_.assignments;
    if (singleLabel<NW>(cat_.domain(s)) >= 0) return true;  // already decided by propagation
    const int b = choose(s, trivial, restrictTo);
    if (b < 0) return failAt(s, fail);
    cat_.assign(s, b);
    const int64_t bad = cat_.propagate();
    return bad < 0 || failAt(bad, fail);
  }

  bool assignAll(const std::vector<int32_t>& sites, bool trivial, Order order, SynthesisFailure& fail) {
    if (order == Order::kScanline || trivial) {
      for (int32_t s : sites)
        if (!assignOne(s, trivial, fail)) return false;
      return true;
    }
    if (order == Order::kMinEntropy) return assignMinEntropy(sites, fail);
    return assignGrowing(sites, fail);
  }

  // Local repair (the entropy pass's last resort): every active site within `radius`
  // grid steps of `bad` is reopened — its base domain narrowed by the sites around the
  // region — and propagation runs again from the region and its rim. Sites outside keep
  // what they have (narrowed by the old region at worst: fewer choices, never a wrong
  // model). Lists the reopened sites in `reopened`; false when the region cannot be made
  // consistent (propagation then stopped halfway: the caller takes it back).
  bool reopen(int64_t bad, int radius, std::vector<int32_t>& reopened) {
    const SiteGraph& g = P_.g;
    reopened.clear();
    const Cell b = M_.cell(bad);
    for (int z = std::max(0, b.z - radius); z <= std::min(P_.size.nz - 1, b.z + radius); ++z)
      for (int y = std::max(0, b.y - radius); y <= std::min(P_.size.ny - 1, b.y + radius); ++y)
        for (int x = std::max(0, b.x - radius); x <= std::min(P_.size.nx - 1, b.x + radius); ++x) {
          const int32_t c = int32_t(M_.index(x, y, z));
          if (!cat_.active(c)) continue;
          reopened.push_back(c);
          cat_.activate(c, P_.base(c));
          assigned_[size_t(c)] = 0;
        }
    for (int32_t c : reopened) {
      cat_.push(c);
      for (int slot = 0; slot < g.slots; ++slot)
        if (const int32_t u = g.at(c, slot); u >= 0) cat_.push(u);  // the rim narrows the region
    }
    return cat_.propagate() < 0;
  }

  // Minimum remaining labels first, ties to the lowest site (the scanline position):
  // random ties scatter decisions over the grid, and fronts that meet from afar contradict
  // each other (the bundled city: 70-90 % first-attempt success with random ties, 100 %
  // with these). A contradiction undoes the last decision and forbids its label at its
  // site; when that leaves the site nothing, the decision before it goes the same way
  // (chronological backtracking). Where the cause lies further back — pairwise
  // consistency cannot see that the four cells around a grid corner must agree, so such
  // contradictions surface late — 256 backtracks since the last repair give way to a
  // local repair (reopen): the Summer-like tile set at 100x100 went from 3/40 (random
  // ties) and 31 % (backtracking alone) to 100 % of first attempts. Stale heap entries
  // are skipped; every site an undo restores or opens again is pushed again.
  bool assignMinEntropy(const std::vector<int32_t>& sites, SynthesisFailure& fail) {
    using Entry = std::pair<int, int32_t>;  // (labels left, site)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    constexpr int W = NW;
    auto push = [&](int32_t c) {
      if (cat_.active(c) && !assigned_[size_t(c)]) heap.push({popcount(cat_.domain(c), W), c});
    };
    for (int32_t s : sites) push(s);
    struct Decision {
      int32_t site;
      int label;
      size_t trail;     // the catalog's trail before it
      size_t assigned;  // assignedOrder's size before it
    };
    std::vector<Decision> decisions;
    std::vector<int32_t> assignedOrder;
    // Sites assigned since assignedOrder had `size` entries are open again, back in the
    // heap (an undo pushes only the sites whose domain it restores).
    auto unassignDownTo = [&](size_t size) {
      while (assignedOrder.size() > size) {
        const int32_t c = assignedOrder.back();
        assignedOrder.pop_back();
        assigned_[size_t(c)] = 0;
        push(c);
      }
    };
    // Chronological backtracking mends a contradiction next to its cause; one whose cause
    // lies further back (many undone decisions for nothing) is repaired locally instead.
    constexpr uint64_t kBacktracksBeforeRepair = 256;
    constexpr int kMaxRepairRadius = 16;
    uint64_t repairs = 0, backtracksHere = 0;  // backtracks since the last repair
    size_t assignedAtRepair = 0;
    std::vector<int32_t> reopened;
    cat_.trackChanges(true);
    cat_.recordTrail(true, 4 * sites.size());  // about the changes of one pass
    bool ok = true;
    while (ok && !heap.empty()) {
      const auto [n, s] = heap.top();
      heap.pop();
      if (assigned_[size_t(s)] || n != popcount(cat_.domain(s), W)) continue;
      if (limitsHit(fail, s)) {
        ok = false;
        break;
      }
      const Decision d{s, -1, cat_.trailMark(), assignedOrder.size()};
      assigned_[size_t(s)] = 1;
      assignedOrder.push_back(s);
      ++stats_.assignments;
      if (singleLabel<NW>(cat_.domain(s)) >= 0) continue;  // decided by propagation
      cat_.changed().clear();
      const int b = choose(s, false);
      cat_.assign(s, b);
      int64_t bad = cat_.propagate();
      decisions.push_back({d.site, b, d.trail, d.assigned});
      while (bad >= 0) {
        if (decisions.empty() || backtracksHere >= kBacktracksBeforeRepair) {
          // Reopen the neighbourhood of the contradiction, wider each time it recurs,
          // from the last consistent state: before the latest decision (or, with none
          // left, right after the last repair) — the failed propagation stopped halfway.
          // The trail restarts: decisions before the repair are final.
          const size_t consistentTrail = decisions.empty() ? 0 : decisions.back().trail;
          const size_t consistentAssigned = decisions.empty() ? assignedAtRepair : decisions.back().assigned;
          cat_.undo(consistentTrail, push);
          unassignDownTo(consistentAssigned);
          bool repaired = false;
          for (int radius = 2; radius <= kMaxRepairRadius && !repaired && repairs < sites.size(); radius *= 2) {
            ++repairs;
            ++stats_.repairs;
            const size_t before = cat_.trailMark();
            repaired = reopen(bad, radius, reopened);
            // A failed try stopped its propagation halfway: take back what it narrowed
            // outside (the next, wider region resets the inside).
            if (!repaired) cat_.undo(before, [](int32_t) {});
          }
          if (!repaired) {
            ok = failAt(bad, fail);
            break;
          }
          decisions.clear();
          cat_.recordTrail(true, 4 * sites.size());
          for (int32_t c : reopened) push(c);
          assignedOrder.erase(std::remove_if(assignedOrder.begin(), assignedOrder.end(),
                                             [&](int32_t c) { return !assigned_[size_t(c)]; }),
                              assignedOrder.end());
          assignedAtRepair = assignedOrder.size();
          backtracksHere = 0;
          bad = -1;
          break;
        }
        ++backtracksHere;
        const Decision last = decisions.back();
        decisions.pop_back();
        ++stats_.backtracks;
        cat_.undo(last.trail, push);
        unassignDownTo(last.assigned);
        // Forbidden at the level before it: undone with that decision, if it comes to that.
        bad = cat_.exclude(last.site, last.label) ? cat_.propagate() : last.site;
        push(last.site);
      }
      for (int32_t c : cat_.changed()) push(c);
      cat_.changed().clear();
    }
    cat_.recordTrail(false);
    cat_.trackChanges(false);
    cat_.changed().clear();
    return ok;
  }

  // Connectivity (§4.6.2): connect labels are only given to cells next to a cell that
  // already carries one, growing from seeds; once growth stops, connect labels are removed
  // from every remaining cell.
  bool assignGrowing(const std::vector<int32_t>& sites, SynthesisFailure& fail) {
    constexpr int W = NW;
    const Word* conn = P_.connectMask.data();
    std::vector<int32_t> frontier;
    if (mark_.empty()) mark_.assign(size_t(P_.size.count()), 0);
    auto hasConnect = [&](const Word* d) {
      for (int w = 0; w < W; ++w)
        if (d[w] & conn[w]) return true;
      return false;
    };
    auto grow = [&](int32_t s) {
      if (!hasConnect(cat_.domain(s)) || popcount(cat_.domain(s), W) != 1) return;
      for (int slot = 0; slot < P_.g.slots; ++slot) {
        const int32_t u = P_.g.at(s, slot);
        if (u >= 0 && cat_.active(u) && !assigned_[size_t(u)] && !mark_[size_t(u)]) {
          mark_[size_t(u)] = 1;
          frontier.push_back(u);
        }
      }
    };
    bool ok = true;
    for (int seed = 0; ok && seed < P_.o.connectivity.seeds; ++seed) {
      int32_t pick = -1;
      uint64_t seen = 0;
      for (int32_t s : sites)  // reservoir sampling over cells that may hold a connect label
        if (!assigned_[size_t(s)] && hasConnect(cat_.domain(s)) && rng_.below(++seen) == 0) pick = s;
      if (pick < 0) break;
      ok = assignOne(pick, false, fail, conn);
      if (ok) grow(pick);
      while (ok && !frontier.empty()) {
        const size_t i = size_t(rng_.below(frontier.size()));
        const int32_t s = frontier[i];
        frontier[i] = frontier.back();
        frontier.pop_back();
        mark_[size_t(s)] = 0;
        if (assigned_[size_t(s)]) continue;
        ok = assignOne(s, false, fail);
        if (ok) grow(s);
      }
    }
    for (int32_t s : frontier) mark_[size_t(s)] = 0;
    if (!ok) return false;
    for (int32_t s : sites) {
      if (assigned_[size_t(s)]) continue;
      Word* d = cat_.domain(s);
      Word changed = 0, any = 0;
      for (int w = 0; w < W; ++w) {
        changed |= d[w] & conn[w];
        d[w] &= ~conn[w];
        any |= d[w];
      }
      if (!any) return failAt(s, fail);
      if (changed) cat_.push(s);
    }
    if (const int64_t bad = cat_.propagate(); bad >= 0) return failAt(bad, fail);
    for (int32_t s : sites)
      if (!assigned_[size_t(s)] && !assignOne(s, false, fail)) return false;
    return true;
  }

  Problem& P_;
  LabelGrid& M_;
  SynthesisStats& stats_;
  BitsetCatalog<NW> cat_;
  Rng rng_;
  SiteArray<uint8_t> assigned_;  // written when a site is activated
  std::vector<uint8_t> mark_;     // only for connectivity
};

void describeFailure(SynthesisFailure& f, const Problem& P) {
  std::string what;
  switch (f.kind) {
    case SynthesisFailure::kContradiction: what = "contradiction at cell " + cellText(f.cell) + " (no label fits there)"; break;
    case SynthesisFailure::kStepLimit: what = "step limit (" + std::to_string(P.maxAssignments) + " assignments) reached at cell " + cellText(f.cell); break;
    case SynthesisFailure::kTimeLimit: what = "time limit (" + std::to_string(P.o.timeLimitSeconds) + " s) reached at cell " + cellText(f.cell); break;
    default: return;
  }
  f.message = what + " after " + std::to_string(f.assignments) + " assignments";
  if (f.block >= 0)
    f.message += " in block #" + std::to_string(f.block) + " at " + cellText(f.blockOrigin) + " of size " +
                 std::to_string(f.blockSize.x) + "x" + std::to_string(f.blockSize.y) + "x" + std::to_string(f.blockSize.z);
  else
    f.message += " (whole-grid synthesis)";
}

template <int NW>
void run(Problem& P, SynthesisResult& R) {
  const SynthesisOptions& o = P.o;
  const GridSize n = o.size;
  const int64_t N = n.count();
  R.labels = LabelGrid(n, kUnassigned);
  const bool blocks = o.block[0] > 0 || o.block[1] > 0 || o.block[2] > 0;
  const Order order = o.connectivity.enabled ? Order::kGrow
                      : o.order == CellOrder::kMinEntropy ? Order::kMinEntropy : Order::kScanline;
  std::vector<int32_t> all(static_cast<size_t>(N));
  for (int64_t i = 0; i < N; ++i) all[size_t(i)] = int32_t(i);

  auto finish = [&](Solver<NW>& S) {
    R.stats.propagationSteps += S.pops();
    R.stats.supportMisses += S.supportMisses();
    R.stats.catalogBytes = std::max(R.stats.catalogBytes,
        S.bytes() + P.baseTable.size() * sizeof(Word) + P.baseIndex.size() * 4 + P.g.face.size() +
        P.g.linkSite.size() * 6 + size_t(P.t.relationCount()) * size_t(P.k) * size_t(P.W) * sizeof(Word));
  };

  if (!blocks) {
    for (int attempt = 0; attempt < std::max(1, o.attempts); ++attempt) {
      ++R.stats.attempts;
      Solver<NW> S(P, R.labels, R.stats, o.seed + uint64_t(attempt) * 0x9e3779b97f4a7c15ULL);
      SynthesisFailure f;
      const bool ok = S.runBlock(all, false, order, f);
      finish(S);
      if (ok) { R.ok = R.consistent = true; return; }
      describeFailure(f, P);
      R.failure = f;
      if (f.kind != SynthesisFailure::kContradiction) return;
    }
    return;
  }

  // Algorithm 3.4.
  Solver<NW> S(P, R.labels, R.stats, o.seed);
  SynthesisFailure f;
  if (!S.runBlock(all, true, Order::kScanline, f)) {
    describeFailure(f, P);
    if (f.kind == SynthesisFailure::kContradiction) {
      f.kind = SynthesisFailure::kNoInitialModel;
      f.message = "no trivial initial model (empty space) satisfies the constraints: " + f.message;
    }
    R.failure = f;
    finish(S);
    return;
  }
  R.consistent = true;
  int m[3], step[3];
  const int ext[3] = {n.nx, n.ny, n.nz};
  for (int a = 0; a < 3; ++a) {
    m[a] = o.block[size_t(a)] <= 0 || o.block[size_t(a)] > ext[a] ? ext[a] : o.block[size_t(a)];
    step[a] = std::max(1, m[a] / 2);
  }
  auto starts = [&](int a) {
    std::vector<int> s;
    for (int q = 0; q * step[a] < ext[a]; ++q) {
      if (q > 0 && (q - 1) * step[a] + m[a] >= ext[a]) break;  // the previous block reached the end
      s.push_back(q * step[a]);
    }
    return s;
  };
  const auto sx = starts(0), sy = starts(1), sz = starts(2);
  std::vector<int32_t> sites;
  std::vector<uint8_t> inSet(P.g.hasLinks() ? size_t(N) : 0, 0);
  int blockIndex = 0;
  for (int pass = 0; pass < std::max(1, o.blockPasses); ++pass)
    for (int qx : sx)
      for (int qy : sy)
        for (int qz : sz) {
          sites.clear();
          const int ex_ = std::min(ext[0], qx + m[0]), ey = std::min(ext[1], qy + m[1]), ez = std::min(ext[2], qz + m[2]);
          for (int z = qz; z < ez; ++z)
            for (int y = qy; y < ey; ++y)
              for (int x = qx; x < ex_; ++x) sites.push_back(int32_t(R.labels.index(x, y, z)));
          if (P.g.hasLinks()) {
            // A block modifies its symmetric images with it (else they would pin it).
            for (int32_t s : sites) inSet[size_t(s)] = 1;
            for (size_t i = 0; i < sites.size(); ++i)
              for (uint32_t e = P.g.linkStart[size_t(sites[i])]; e < P.g.linkStart[size_t(sites[i]) + 1]; ++e)
                if (int32_t u = P.g.linkSite[e]; !inSet[size_t(u)]) { inSet[size_t(u)] = 1; sites.push_back(u); }
            for (int32_t s : sites) inSet[size_t(s)] = 0;
            std::sort(sites.begin(), sites.end());
          }
          ++R.stats.blocks;
          bool done = false;
          for (int attempt = 0; attempt <= std::max(0, o.blockRetries) && !done; ++attempt) {
            if (attempt > 0) ++R.stats.blockRetries;
            SynthesisFailure bf;
            done = S.runBlock(sites, false, order, bf);
            if (done) break;
            bf.block = blockIndex;
            bf.blockOrigin = {qx, qy, qz};
            bf.blockSize = {ex_ - qx, ey - qy, ez - qz};
            describeFailure(bf, P);
            R.failure = bf;
            if (R.blockFailures.size() < 16) R.blockFailures.push_back(bf);
            if (bf.kind != SynthesisFailure::kContradiction) { finish(S); return; }  // a limit: stop, model stays consistent
          }
          if (!done) ++R.stats.blocksFailed;
          ++blockIndex;
        }
  finish(S);
  R.ok = true;
  if (R.stats.blocksFailed == 0) R.failure = SynthesisFailure{};
}

}  // namespace

SynthesisResult synthesize(const Example& ex, const SynthesisOptions& options) noexcept {
  SynthesisResult R;
  const auto t0 = Clock::now();
  try {
    Problem P(ex, options);
    P.start = t0;
    // A limit of 0 s is up at once (a Deadline reads 0 as "never").
    P.deadline = Deadline(t0, options.timeLimitSeconds > 0 ? options.timeLimitSeconds
                                                           : std::numeric_limits<double>::min());
    std::string error;
    R.pieces = ex.labels;
    // A grid that cannot fit is refused at once, not after minutes of setting it up.
    const uint64_t cells = uint64_t(std::max<int64_t>(0, options.size.count()));
    const uint64_t perCell = 24 + 16 * uint64_t(sizeof(Word)) * uint64_t(paddedWordsFor(std::max(1, ex.labelCount())));
    const uint64_t available = availableMemoryBytes();
    if (available > 0 && cells > available / perCell) {
      R.failure.kind = SynthesisFailure::kBadOptions;
      R.failure.message = "a grid of " + std::to_string(cells) + " cells needs about " +
                          formatMemorySize(cells * perCell) + " of memory (" + std::to_string(perCell) +
                          " bytes a cell), more than the " + formatMemorySize(available) + " this machine has";
      return R;
    }
    if (!compile(P, error)) {
      R.failure.kind = SynthesisFailure::kBadOptions;
      R.failure.message = error;
      return R;
    }
    for (int64_t c = 0; c < options.size.count(); ++c) {
      if (P.timeUp()) {
        R.failure.kind = SynthesisFailure::kTimeLimit;
        R.failure.message = "time limit (" + std::to_string(P.o.timeLimitSeconds) + " s) reached while setting up the grid";
        return R;
      }
      if (firstBit(P.base(c), P.W) < 0) {
        R.failure.kind = SynthesisFailure::kContradiction;
        R.failure.cell = LabelGrid(GridSize{options.size.nx, options.size.ny, 1}).cell(0);
        R.failure.cell = {int(c % options.size.nx), int((c / options.size.nx) % options.size.ny),
                          int(c / (int64_t(options.size.nx) * options.size.ny))};
        R.failure.message = "no label can stand at cell " + cellText(R.failure.cell) +
                            ": the border, mask and symmetry constraints exclude every label";
        return R;
      }
    }
    const uint64_t passes = uint64_t(std::max(1, options.blockPasses)) * uint64_t(std::max(1, options.attempts));
    P.maxAssignments = options.maxAssignments ? options.maxAssignments : 64ULL * uint64_t(options.size.count()) * passes + 1024;
    switch (P.W) {  // paddedWordsFor(k <= 4096)
      case 1: run<1>(P, R); break;
      case 2: run<2>(P, R); break;
      case 4: run<4>(P, R); break;
      case 8: run<8>(P, R); break;
      case 16: run<16>(P, R); break;
      case 32: run<32>(P, R); break;
      default: run<64>(P, R); break;
    }
  } catch (const std::bad_alloc&) {
    R.ok = R.consistent = false;
    R.failure.kind = SynthesisFailure::kBadOptions;
    R.failure.message = "out of memory for a grid of this size";
  }
  R.stats.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return R;
}

}  // namespace fgsg::rt::synthesis
