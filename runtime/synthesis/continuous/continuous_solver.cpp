// Algorithm 4.1 steps 2-10: labels, their places and neighbours, then assignment in
// blocks with the discrete solver's catalog. See continuous.h.
#include "runtime/synthesis/catalog.h"
#include "runtime/synthesis/continuous/arrangement.h"
#include "runtime/synthesis/continuous/boundary_surface.h"
#include "runtime/synthesis/continuous/continuous.h"
#include "runtime/synthesis/continuous/labels.h"
#include "runtime/synthesis/continuous/mirror.h"
#include "runtime/synthesis/continuous/perturb.h"
#include "runtime/synthesis/random.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <new>
#include <tuple>

namespace fgsg::rt::synthesis::continuous {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kAutoBlock = 8;  // lattice units; the thesis: 10 x 10 x 10 or smaller succeeds
enum Place : uint8_t { kInside, kBoundary, kFloor };

// Everything the assignment needs, built once.
struct Problem {
  const ContinuousOptions& o;
  Arrangement A;
  std::vector<Label> labels;
  std::vector<uint8_t> raised;       // per label: found in the example above its ground plane
  int k = 0, W = 0;
  TransitionTable t;
  SiteGraph g;
  std::vector<Word> baseTable;       // distinct allowed sets
  std::vector<uint32_t> baseIndex;   // per vertex
  std::vector<uint8_t> place;        // per vertex: inside the box, on its sides, on the floor
  std::vector<double> weight;        // per label
  // Per relation and label: the label's solid reaches along such an edge (its pattern
  // there is not all outside): how growing (§4.6.2) spreads.
  std::vector<std::vector<uint8_t>> solidAlong;
  Deadline deadline;
  explicit Problem(const ContinuousOptions& opt) : o(opt), deadline(Deadline::after(opt.timeLimitSeconds)) {}
  const Word* base(int64_t v) const { return &baseTable[size_t(baseIndex[size_t(v)]) * size_t(W)]; }
  bool timeUp() { return deadline.expired() || (o.deadline && o.deadline->expired()); }
  // The same from any thread (reads the clock).
  bool timePassed() const { return deadline.passed() || (o.deadline && o.deadline->passed()); }
};

std::string timeLimitMessage(const ContinuousOptions& o) {
  return "stopped by the time limit (" + std::to_string(o.timeLimitSeconds) + " s)";
}

// Does the label's solid reach both sides of a plane of direction `i` through its vertex?
bool crosses(const std::vector<IVec3>& dirs, const Label& l, int i) {
  bool pos = false, neg = false;
  for (const Sector& s : sectorsOf(dirs, l.dirs | (1u << i)))
    if (l.inside(s.signs)) ((s.signs >> i) & 1 ? pos : neg) = true;
  return pos && neg;
}

// Does the label have a face looking down (an outward normal with a negative y)?
bool looksDown(const std::vector<IVec3>& dirs, const Label& l) {
  const auto sectors = sectorsOf(dirs, l.dirs);
  for (uint32_t m = l.dirs; m; m &= m - 1) {
    const int e = __builtin_ctz(m);
    const int64_t up = dirs[size_t(e)][1];
    if (up == 0) continue;
    for (const Sector& s : sectors) {
      if (!((s.signs >> e) & 1)) continue;
      const uint32_t other = s.signs & ~(1u << e);
      if (std::none_of(sectors.begin(), sectors.end(), [&](const Sector& t) { return t.signs == other; })) continue;
      const bool inAbove = l.inside(s.signs), inBelow = l.inside(other);
      // Solid on the +a side: the face's outward normal is -a, and the other way round.
      if (inAbove != inBelow && (inAbove ? -up : up) < 0) return true;
    }
  }
  return false;
}

// Is the label empty everywhere below its vertex (y < 0)?
bool emptyBelow(const std::vector<IVec3>& dirs, const Label& l, int yAxis) {
  for (const Sector& s : sectorsOf(dirs, l.dirs | (1u << yAxis)))
    if (!((s.signs >> yAxis) & 1) && l.inside(s.signs)) return false;
  return true;
}

// Is the vertex under a dark pixel of the mask (§4.6.3)?
bool masked(const Problem& P, size_t v) {
  const ContinuousOptions& o = P.o;
  if (o.mask.empty()) return false;
  const DVec3 p = P.A.position(v);
  const int i = std::clamp(int(p[0] / double(P.A.box[0]) * o.maskWidth), 0, o.maskWidth - 1);
  const int j = std::clamp(int(p[2] / double(P.A.box[2]) * o.maskHeight), 0, o.maskHeight - 1);
  return o.mask[size_t(j) * size_t(o.maskWidth) + size_t(i)] < 0.5f;
}

bool compile(Problem& P, const ExampleSolid& ex, ContinuousStats& stats, std::string& error) {
  const ContinuousOptions& o = P.o;
  if (!(o.spacing > 0) || !std::isfinite(o.spacing)) { error = "the spacing must be a positive number"; return false; }
  for (double s : o.size)
    if (!(s > 0) || !std::isfinite(s)) { error = "the size must be three positive numbers"; return false; }
  if (o.block < -1) { error = "the block size must be 0 (the whole box) or more"; return false; }
  if (!(o.fill >= 0 && o.fill <= 1)) { error = "fill must lie between 0 and 1"; return false; }
  if (o.growSeeds < 0) { error = "the seed count for growing must be 0 or more"; return false; }
  if (!o.mask.empty() && (o.maskWidth < 1 || o.maskHeight < 1 || o.mask.size() != size_t(o.maskWidth) * size_t(o.maskHeight))) {
    error = "the mask's size does not match its pixels";
    return false;
  }
  if (!(o.perturb >= 0) || !std::isfinite(o.perturb)) { error = "the perturbation must be 0 or more"; return false; }
  std::vector<int64_t> step(ex.dirs.size(), 1);
  uint32_t fixedDirs = 0;  // directions no label may cross (a width of one spacing too)
  // A plane step or fixed width: its direction's index, its step set; -1 with `error`.
  auto setStep = [&](const FixedWidth& f, const char* what) -> int {
    const IVec3 a = canonicalDirection(f.normal);
    const auto faces = ex.dirs.begin() + ex.faceDirections;
    const auto it = std::find(ex.dirs.begin(), faces, a);
    if (isZero(a) || it == faces) {
      error = std::string("a ") + what + " names the direction (" + std::to_string(f.normal[0]) + ", " +
              std::to_string(f.normal[1]) + ", " + std::to_string(f.normal[2]) + "), which no face of the example has";
      return -1;
    }
    if (f.planes < 1 || f.planes > 1000) {
      error = std::string("a ") + what + " is 1 to 1000 plane spacings";
      return -1;
    }
    step[size_t(it - ex.dirs.begin())] = f.planes;
    return int(it - ex.dirs.begin());
  };
  for (const FixedWidth& f : o.planeStep)
    if (setStep(f, "plane step") < 0) return false;
  for (const FixedWidth& f : o.fixedWidth) {
    const int i = setStep(f, "fixed width");
    if (i < 0) return false;
    fixedDirs |= 1u << i;
  }
  std::array<int64_t, 3> box{};
  for (int c = 0; c < 3; ++c) {
    const double cells = o.size[size_t(c)] / o.spacing;
    if (cells > 4096) { error = "the size is more than 4096 spacings along an axis"; return false; }
    box[size_t(c)] = std::max<int64_t>(2, int64_t(std::ceil(cells - 1e-9)));
    // The box's sides must be planes: round up to the axis direction's step.
    IVec3 axis{};
    axis[size_t(c)] = 1;
    const size_t ai = size_t(std::find(ex.dirs.begin(), ex.dirs.end(), axis) - ex.dirs.begin());
    box[size_t(c)] = (box[size_t(c)] + step[ai] - 1) / step[ai] * step[ai];
  }
  // The time limit, asked throughout: the arrangement of a large box alone takes seconds.
  auto timeLimit = [&] {
    error = timeLimitMessage(o);
    return false;
  };
  if (!buildArrangement(ex.dirs, step, box, o.maxVertices, P.A, error, [&] { return P.timePassed(); }))
    return P.timePassed() ? timeLimit() : false;
  LabelCatalog cat;
  if (!exampleLabels(ex, cat, [&] { return P.timeUp(); })) return timeLimit();
  P.labels = cat.labels;
  P.raised = cat.raised;
  P.k = int(P.labels.size());
  if (P.k > 4096) { error = "the example has more than 4096 distinct vertex figures"; return false; }
  P.W = paddedWordsFor(P.k);
  const size_t W = size_t(P.W);
  const Arrangement& A = P.A;

  // Allowed labels per vertex (§4.5.4): those whose half-spaces all have a plane through
  // it, less those crossing a fixed-width plane (§4.6.1); boundary vertices: empty space
  // (with onGround the floor holds solids: empty below, anything above; above the floor a
  // face may look down only in a figure the example has above its own ground plane).
  const int yAxis = int(std::find(ex.dirs.begin(), ex.dirs.end(), IVec3{0, 1, 0}) - ex.dirs.begin());
  P.place.resize(A.vertexCount());
  for (size_t v = 0; v < A.vertexCount(); ++v) {
    if ((v & 4095) == 0 && P.timeUp()) return timeLimit();
    const bool hidden = masked(P, v);
    P.place[v] = A.boundary[v] || hidden ? kBoundary : kInside;
    if (o.onGround && A.num[v][1] == 0 && !hidden) {
      bool side = false;
      for (int c : {0, 2}) side |= A.num[v][size_t(c)] == 0 || A.num[v][size_t(c)] == A.box[size_t(c)] * A.den[v];
      if (!side) P.place[v] = kFloor;
    }
  }
  // Symmetry: the mirror image of each label and vertex; a vertex that is its own image
  // may only hold labels that are their own images.
  std::vector<std::vector<int32_t>> labelImage(o.mirrorAxes.size()), vertexImage(o.mirrorAxes.size());
  std::vector<uint8_t> onMirror(A.vertexCount(), 0);
  for (size_t s = 0; s < o.mirrorAxes.size(); ++s) {
    const int axis = o.mirrorAxes[s];
    if (axis != 0 && axis != 2) { error = "a mirror is across x (0) or z (2)"; return false; }
    if (!mirrorLabels(A.dirs, P.labels, axis, labelImage[s], error) || !mirrorVertices(A, axis, vertexImage[s], error))
      return false;
    for (size_t v = 0; v < A.vertexCount(); ++v)
      if (vertexImage[s][v] == int32_t(v)) onMirror[v] |= uint8_t(1u << s);
  }
  std::map<std::tuple<uint32_t, uint8_t, uint8_t>, uint32_t> entry;
  P.baseIndex.resize(A.vertexCount());
  for (size_t v = 0; v < A.vertexCount(); ++v) {
    if ((v & 4095) == 0 && P.timeUp()) return timeLimit();
    const auto key = std::make_tuple(A.planes[v], P.place[v], onMirror[v]);
    auto [it, added] = entry.emplace(key, uint32_t(P.baseTable.size() / W));
    if (added) {
      P.baseTable.resize(P.baseTable.size() + W, 0);
      Word* d = &P.baseTable[size_t(it->second) * W];
      for (int b = 0; b < P.k; ++b) {
        const Label& l = P.labels[size_t(b)];
        if (P.place[v] == kBoundary ? b != LabelCatalog::kEmpty : (l.dirs & ~A.planes[v]) != 0) continue;
        bool ok = true;
        for (size_t i = 0; i < step.size() && ok; ++i)
          if (((fixedDirs & A.planes[v]) >> i) & 1 && crosses(A.dirs, l, int(i))) ok = false;
        if (ok && P.place[v] == kFloor) ok = emptyBelow(A.dirs, l, yAxis);
        if (ok && o.onGround && P.place[v] == kInside) ok = P.raised[size_t(b)] || !looksDown(A.dirs, l);
        for (size_t s = 0; s < o.mirrorAxes.size() && ok; ++s)
          if ((onMirror[v] >> s) & 1) ok = labelImage[s][size_t(b)] == b;
        if (ok) setBit(d, b);
      }
    }
    P.baseIndex[v] = it->second;
  }

  // Relations (§4.5.5): one per line direction and set of planes along the edge.
  P.t = TransitionTable(P.k, P.W);
  std::map<std::pair<int32_t, uint32_t>, int> relation;
  std::vector<Link> links;
  for (size_t v = 0; v < A.vertexCount(); ++v) {
    if ((v & 4095) == 0 && P.timeUp()) return timeLimit();
    for (uint32_t e = A.edgeStart[v]; e < A.edgeStart[v + 1]; ++e) {
      if (A.edgeLine[e] < 0) continue;  // each edge once, from the end it leaves along +line
      const int32_t line = A.edgeLine[e] - 1;
      const IVec3& d = A.lines[size_t(line)];
      uint32_t planes = 0;
      for (uint32_t m = A.planes[v]; m; m &= m - 1)
        if (dot(A.dirs[size_t(__builtin_ctz(m))], d) == 0) planes |= m & (~m + 1);
      auto [it, added] = relation.emplace(std::make_pair(line, planes), 0);
      if (added) {
        std::vector<IVec3> around;
        for (uint32_t m = planes; m; m &= m - 1) around.push_back(A.dirs[size_t(__builtin_ctz(m))]);
        const auto wedges = wedgesAround(d, around);
        const IVec3 back{-d[0], -d[1], -d[2]};
        std::vector<std::optional<uint64_t>> fwd(size_t(P.k)), bwd(size_t(P.k));
        for (int b = 0; b < P.k; ++b) {
          fwd[size_t(b)] = edgePattern(P.labels[size_t(b)], A.dirs, d, planes, wedges);
          bwd[size_t(b)] = edgePattern(P.labels[size_t(b)], A.dirs, back, planes, wedges);
        }
        std::vector<std::pair<int32_t, int32_t>> pairs;
        for (int b = 0; b < P.k; ++b)
          for (int c = 0; c < P.k; ++c)
            if (fwd[size_t(b)] && bwd[size_t(c)] && *fwd[size_t(b)] == *bwd[size_t(c)]) pairs.push_back({b, c});
        it->second = P.t.addRelationPair(pairs);
        P.solidAlong.resize(size_t(it->second) + 2);
        for (int b = 0; b < P.k; ++b) {
          P.solidAlong[size_t(it->second)].push_back(fwd[size_t(b)] && *fwd[size_t(b)] != 0);
          P.solidAlong[size_t(it->second) + 1].push_back(bwd[size_t(b)] && *bwd[size_t(b)] != 0);
        }
      }
      links.push_back({int32_t(v), A.edgeTo[e], it->second});
    }
  }
  for (size_t s = 0; s < o.mirrorAxes.size(); ++s) {
    std::vector<std::pair<int32_t, int32_t>> pairs;
    for (int b = 0; b < P.k; ++b)
      if (labelImage[s][size_t(b)] >= 0) pairs.push_back({b, labelImage[s][size_t(b)]});
    const int rel = P.t.addRelationPair(pairs);
    for (size_t v = 0; v < A.vertexCount(); ++v)
      if (int32_t(v) < vertexImage[s][v]) links.push_back({int32_t(v), vertexImage[s][v], rel});
  }
  P.solidAlong.resize(size_t(P.t.relationCount()), std::vector<uint8_t>(size_t(P.k), 0));  // mirrors do not grow
  if (P.t.relationCount() > 65535) { error = "too many kinds of edges"; return false; }
  P.g.siteCount = int64_t(A.vertexCount());
  P.g.slots = 0;
  P.g.face.assign(A.vertexCount(), 0x3f);  // no grid neighbours: every slot "on the border"
  std::vector<int> rev(size_t(P.t.relationCount()));
  for (int r = 0; r < P.t.relationCount(); ++r) rev[size_t(r)] = P.t.reverse(r);
  setLinks(P.g, links, rev);

  // Chance weights: empty space 1 - fill, the solid labels share fill.
  P.weight.assign(size_t(P.k), P.k > 1 ? o.fill / double(P.k - 1) : 0.0);
  P.weight[LabelCatalog::kEmpty] = 1 - o.fill;

  stats.exampleFaces = int(ex.polygons.size());
  stats.directions = ex.faceDirections;
  stats.labels = P.k;
  stats.relations = P.t.relationCount();
  stats.vertices = A.vertexCount();
  stats.edges = A.edgeCount();
  return true;
}

template <int NW>
class Assigner {
 public:
  Assigner(Problem& P, std::vector<int32_t>& M, ContinuousStats& stats)
      : P_(P), M_(M), stats_(stats), cat_(P.t, P.g), rng_(P.o.seed) {}

  // Re-synthesizes `sites` with every other vertex fixed; M changes only on success.
  bool runBlock(const std::vector<int32_t>& sites, std::string& why) {
    for (int32_t s : sites) cat_.activate(s, P_.base(s));
    bool ok = init(sites) && (P_.o.growSeeds > 0 ? grow(sites, why) : assign(sites, why));
    if (!ok && why.empty()) why = "no label fits";
    if (ok)
      for (int32_t s : sites) M_[size_t(s)] = firstBit(cat_.domain(s), NW);
    cat_.clearQueue();
    for (int32_t s : sites) cat_.deactivate(s);
    return ok;
  }

 private:
  bool init(const std::vector<int32_t>& sites) {
    const SiteGraph& g = P_.g;
    for (int32_t s : sites) {
      Word* d = cat_.domain(s);
      for (uint32_t e = g.linkStart[size_t(s)]; e < g.linkStart[size_t(s) + 1]; ++e) {
        const int32_t u = g.linkSite[e];
        if (cat_.active(u)) continue;
        const Word* r = P_.t.row(P_.t.reverse(g.linkRelation[e]), M_[size_t(u)]);
        for (int w = 0; w < NW; ++w) d[w] &= r[w];
      }
      if (firstBit(d, NW) < 0) return false;
      cat_.push(s);
    }
    return cat_.propagate() < 0;
  }

  // A label of the domain at random by weight; solidOnly: not empty space.
  int choose(const Word* d, bool solidOnly = false) {
    Word only[NW];
    for (int w = 0; w < NW; ++w) only[w] = d[w];
    if (solidOnly) only[0] &= ~Word(1);  // label 0 is empty space
    d = only;
    double sum = 0;
    forEachBit(d, NW, [&](int b) { sum += P_.weight[size_t(b)]; });
    int chosen = -1, last = -1;
    if (sum <= 0) {
      const int count = popcount(d, NW);
      if (count == 0) return -1;
      uint64_t pick = rng_.below(uint64_t(count));
      forEachBit(d, NW, [&](int b) { if (pick-- == 0) chosen = b; });
      return chosen;
    }
    double r = rng_.uniform() * sum;
    forEachBit(d, NW, [&](int b) {
      if (chosen >= 0) return;
      const double w = P_.weight[size_t(b)];
      if (w > 0) last = b;
      r -= w;
      if (r < 0 && w > 0) chosen = b;
    });
    return chosen >= 0 ? chosen : last;
  }

  bool assign(const std::vector<int32_t>& sites, std::string& why) {
    for (int32_t s : sites) {
      if (P_.timeUp()) { why = "the time limit"; return false; }
      ++stats_.assignments;
      if (singleLabel<NW>(cat_.domain(s)) >= 0) continue;
      const int b = choose(cat_.domain(s));
      if (b < 0) return false;
      cat_.assign(s, b);
      if (cat_.propagate() >= 0) return false;
    }
    return true;
  }

  // Connectivity (§4.6.2): seeds take solid labels; then a vertex is labelled only when
  // the solid of a labelled neighbour reaches it along their edge, at random among those
  // waiting; when nothing is waiting the next seed starts. The rest is empty space.
  bool grow(const std::vector<int32_t>& sites, std::string& why) {
    const SiteGraph& g = P_.g;
    if (assigned_.empty()) assigned_.assign(size_t(g.siteCount), 0);
    for (int32_t s : sites) assigned_[size_t(s)] = 0;
    std::vector<int32_t> waiting;
    std::vector<uint8_t> queued(size_t(g.siteCount), 0);
    auto label = [&](int32_t s, bool solidOnly) {
      if (P_.timeUp()) { why = "the time limit"; return false; }
      assigned_[size_t(s)] = 1;
      ++stats_.assignments;
      if (singleLabel<NW>(cat_.domain(s)) < 0) {
        const int b = choose(cat_.domain(s), solidOnly);
        if (b < 0) return false;
        cat_.assign(s, b);
        if (cat_.propagate() >= 0) return false;
      }
      const int b = singleLabel<NW>(cat_.domain(s));
      for (uint32_t e = g.linkStart[size_t(s)]; e < g.linkStart[size_t(s) + 1]; ++e) {
        const int32_t u = g.linkSite[e];
        if (cat_.active(u) && !assigned_[size_t(u)] && !queued[size_t(u)] && P_.solidAlong[g.linkRelation[e]][size_t(b)]) {
          queued[size_t(u)] = 1;
          waiting.push_back(u);
        }
      }
      return true;
    };
    for (int seed = 0; seed < P_.o.growSeeds; ++seed) {
      int32_t pick = -1;
      uint64_t seen = 0;
      for (int32_t s : sites) {  // reservoir sampling over vertices that may be solid
        if (assigned_[size_t(s)]) continue;
        Word solid = 0;
        const Word* d = cat_.domain(s);
        for (int w = 0; w < NW; ++w) solid |= w == 0 ? d[0] & ~Word(1) : d[w];
        if (solid && rng_.below(++seen) == 0) pick = s;
      }
      if (pick < 0) break;
      if (!label(pick, true)) return false;
      while (!waiting.empty()) {
        const size_t i = size_t(rng_.below(waiting.size()));
        const int32_t s = waiting[i];
        waiting[i] = waiting.back();
        waiting.pop_back();
        if (!assigned_[size_t(s)] && !label(s, false)) return false;
      }
    }
    for (int32_t s : sites) {
      if (assigned_[size_t(s)] || singleLabel<NW>(cat_.domain(s)) >= 0) continue;
      if (!testBit(cat_.domain(s), LabelCatalog::kEmpty)) return false;
      cat_.assign(s, LabelCatalog::kEmpty);
    }
    return cat_.propagate() < 0;
  }

  Problem& P_;
  std::vector<int32_t>& M_;
  ContinuousStats& stats_;
  BitsetCatalog<NW> cat_;
  Rng rng_;
  std::vector<uint8_t> assigned_;  // growing: labelled by grow() (not just narrowed to one)
};

// Blocks of `b` lattice units overlapping by half, in scanline order (Fig. 4.23).
std::vector<std::vector<int32_t>> blocksOf(const Problem& P, int block) {
  const Arrangement& A = P.A;
  std::vector<std::vector<int32_t>> blocks;
  std::vector<int32_t> interior;
  for (size_t v = 0; v < A.vertexCount(); ++v)
    if (P.place[v] != kBoundary) interior.push_back(int32_t(v));  // every vertex but the box's sides
  if (block == 0) {
    blocks.push_back(std::move(interior));
    return blocks;
  }
  const int64_t b = block, half = std::max<int64_t>(1, b / 2);
  std::array<std::vector<int64_t>, 3> origins;
  for (int c = 0; c < 3; ++c) {
    for (int64_t o = 0;; o += half) {
      origins[size_t(c)].push_back(o);
      if (o + b >= A.box[size_t(c)]) break;
    }
  }
  // Each vertex joins every block whose closed extent [o, o + b] holds it (up to two per
  // axis), in vertex order, so each block's sites come out sorted.
  const size_t nx = origins[0].size(), ny = origins[1].size(), nz = origins[2].size();
  std::vector<std::vector<int32_t>> byBlock(nx * ny * nz);
  for (int32_t v : interior) {
    size_t from[3], to[3];
    for (int c = 0; c < 3; ++c) {
      const int64_t n = A.num[size_t(v)][size_t(c)], d = A.den[size_t(v)];
      // Origins o = k * half with o <= n / d <= o + b.
      const int64_t kHi = n / (half * d);
      const int64_t kLo = std::max<int64_t>(0, (n - b * d + half * d - 1) / (half * d));
      from[c] = size_t(std::min<int64_t>(kLo, int64_t(origins[size_t(c)].size()) - 1));
      to[c] = size_t(std::min<int64_t>(kHi, int64_t(origins[size_t(c)].size()) - 1));
    }
    for (size_t z = from[2]; z <= to[2]; ++z)
      for (size_t y = from[1]; y <= to[1]; ++y)
        for (size_t x = from[0]; x <= to[0]; ++x) byBlock[(z * ny + y) * nx + x].push_back(v);
  }
  for (auto& sites : byBlock)
    if (!sites.empty()) blocks.push_back(std::move(sites));
  return blocks;
}

template <int NW>
bool assignAll(Problem& P, std::vector<int32_t>& M, ContinuousStats& stats, std::string& error) {
  Assigner<NW> a(P, M, stats);
  std::string why;
  // Runs every block of `block`: false when one failed all its tries (or time ran out).
  auto sweep = [&](int block, int passes, int retries) {
    const auto blocks = blocksOf(P, block);
    bool all = true;
    for (int pass = 0; pass < passes; ++pass)
      for (const auto& sites : blocks) {
        ++stats.blocks;
        bool ok = false;
        for (int attempt = 0; attempt <= retries && !ok && why != "the time limit"; ++attempt) {
          why.clear();
          ok = a.runBlock(sites, why);
        }
        if (why == "the time limit") return false;
        if (!ok) ++stats.blocksFailed, all = false;
      }
    return all;
  };
  // Growing and mirrors reach across the box: the whole box at once.
  const int block = P.o.growSeeds > 0 || !P.o.mirrorAxes.empty() ? 0 : P.o.block;
  bool ok = block > 0 ? sweep(block, std::max(1, P.o.passes), P.o.blockRetries) : sweep(0, 1, block == 0 ? P.o.blockRetries : 1);
  if (!ok && block < 0 && why != "the time limit") {
    // The whole box met a contradiction: it stays empty (always consistent), and blocks
    // grow the model instead (§4.5.6), one sweep (from the empty model a second one only
    // re-draws what the first made).
    stats.blocksFailed = 0;
    sweep(kAutoBlock, 1, P.o.blockRetries);
    ok = true;  // a block that failed was left as it was: still consistent
  }
  if (why == "the time limit") {
    error = timeLimitMessage(P.o);
    return false;
  }
  if (block == 0 && !ok) {
    error = P.o.growSeeds > 0 ? "growing from " + std::to_string(P.o.growSeeds) + " seed(s) met a contradiction in every try (" + why + "); try another seed"
                              : "the whole box could not be labelled consistently (" + why + "); try blocks (block > 0)";
    return false;
  }
  return true;
}

}  // namespace

ContinuousResult synthesizeContinuous(const ExampleSolid& ex, const ContinuousOptions& o) noexcept {
  ContinuousResult R;
  const auto start = Clock::now();
  try {
    Problem P(o);
    if (!compile(P, ex, R.stats, R.error)) return R;
    const auto compiled = Clock::now();
    R.stats.compileSeconds = std::chrono::duration<double>(compiled - start).count();
    std::vector<int32_t> M(P.A.vertexCount(), LabelCatalog::kEmpty);
    bool ok = false;
    switch (P.W) {
      case 1: ok = assignAll<1>(P, M, R.stats, R.error); break;
      case 2: ok = assignAll<2>(P, M, R.stats, R.error); break;
      case 4: ok = assignAll<4>(P, M, R.stats, R.error); break;
      case 8: ok = assignAll<8>(P, M, R.stats, R.error); break;
      case 16: ok = assignAll<16>(P, M, R.stats, R.error); break;
      case 32: ok = assignAll<32>(P, M, R.stats, R.error); break;
      default: ok = assignAll<64>(P, M, R.stats, R.error); break;
    }
    if (!ok) return R;
    const auto assigned = Clock::now();
    R.stats.assignSeconds = std::chrono::duration<double>(assigned - compiled).count();
    BoundarySurface surface = boundarySurface(P.A, P.labels, M, o.spacing);
    R.mesh = std::move(surface.mesh);
    R.faces = std::move(surface.faces);
    R.facePart = std::move(surface.facePart);
    if (o.perturb > 0) perturbParts(R.mesh, surface.vertexPart, R.faces, R.facePart, surface.parts, o.perturb, o.seed);
    R.stats.arrangementFaces = surface.polygons;
    R.stats.outputPolygons = R.faces.size();
    R.stats.parts = surface.parts;
    R.stats.triangles = R.mesh.triangleCount();
    R.ok = true;
    R.stats.surfaceSeconds = std::chrono::duration<double>(Clock::now() - assigned).count();
  } catch (const std::bad_alloc&) {
    R.error = "out of memory (use a larger spacing or a smaller size)";
  }
  R.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return R;
}

}  // namespace fgsg::rt::synthesis::continuous
