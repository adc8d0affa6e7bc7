#include "runtime/synthesis/continuous/labels.h"

#include "runtime/synthesis/continuous/inside_test.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fgsg::rt::synthesis::continuous {

bool Label::inside(uint32_t signs) const { return std::binary_search(in.begin(), in.end(), signs & dirs); }

Label canonicalLabel(uint32_t mask, std::vector<std::pair<uint32_t, bool>> sectors) {
  // Drop a direction while the figure is the same on both sides of it in every sector
  // pair that differs only there.
  for (bool dropped = true; dropped;) {
    dropped = false;
    for (uint32_t m = mask; m; m &= m - 1) {
      const uint32_t bit = m & (~m + 1);
      std::map<uint32_t, bool> merged;
      bool consistent = true;
      for (const auto& [s, v] : sectors) {
        auto [it, added] = merged.emplace(s & ~bit, v);
        if (!added && it->second != v) { consistent = false; break; }
      }
      if (!consistent) continue;
      mask &= ~bit;
      sectors.assign(merged.begin(), merged.end());
      dropped = true;
      break;
    }
  }
  Label l;
  l.dirs = mask;
  for (const auto& [s, v] : sectors)
    if (v) l.in.push_back(s & mask);
  std::sort(l.in.begin(), l.in.end());
  l.in.erase(std::unique(l.in.begin(), l.in.end()), l.in.end());
  return l;
}

namespace {

// The figure of the solid at p with the planes of `mask` through it: each sector tested
// a small step away from p.
Label figureAt(const ExampleSolid& s, const InsideTest& solid, const DVec3& p, uint32_t mask, double step) {
  std::vector<std::pair<uint32_t, bool>> table;
  for (const Sector& sec : sectorsOf(s.dirs, mask)) {
    const DVec3 q{p[0] + step * sec.direction[0], p[1] + step * sec.direction[1], p[2] + step * sec.direction[2]};
    table.push_back({sec.signs, solid.inside(q)});
  }
  return canonicalLabel(mask, std::move(table));
}

}  // namespace

bool exampleLabels(const ExampleSolid& s, LabelCatalog& c, const std::function<bool()>& timeUp) {
  c = LabelCatalog{};
  // The ground plane: the example's least y; a point a little above it is raised.
  double ground = 0;
  for (size_t v = 0; v < s.vertices.size(); ++v) ground = v == 0 ? s.vertices[v][1] : std::min(ground, s.vertices[v][1]);
  const double aboveGround = ground + 1e-9 * std::max(1.0, s.diagonal);
  auto add = [&](const Label& l, bool raised) {
    const auto it = std::find(c.labels.begin(), c.labels.end(), l);
    if (it == c.labels.end()) {
      c.labels.push_back(l);
      c.raised.push_back(raised);
    } else {
      c.raised[size_t(it - c.labels.begin())] |= uint8_t(raised);
    }
  };
  add(Label{0, {}}, true);   // outside
  add(Label{0, {0}}, true);  // inside
  // Faces: the half-space behind the outward normal; raised unless the face lies on the
  // ground plane (its interior is above it when one corner is).
  for (size_t f = 0; f < s.polygons.size(); ++f) {
    const uint32_t bit = 1u << s.polygonDirection[f];
    bool raised = false;
    for (int v : s.polygons[f]) raised |= s.vertices[size_t(v)][1] > aboveGround;
    add(Label{bit, {s.polygonAlong[f] ? 0u : bit}}, raised);
  }
  // The step off a point: well inside its neighbourhood (a tenth of the distance to the
  // nearest other vertex, at most 1e-3 of the example's size).
  const NearestVertex vertices(s);
  const InsideTest solid(s);
  auto stepAt = [&](const DVec3& p, int skip) {  // skip: p's own vertex, -1 for none
    const double nearest = std::min(s.diagonal, vertices.distance(p, skip));
    return std::min(1e-3 * s.diagonal, 0.1 * nearest);
  };
  // Edges: the two faces' half-spaces at the edge's midpoint.
  std::vector<uint32_t> vertexMask(s.vertices.size(), 0);
  std::map<std::pair<int, int>, uint32_t> edgeMask;
  for (size_t f = 0; f < s.polygons.size(); ++f) {
    const auto& poly = s.polygons[f];
    const uint32_t bit = 1u << s.polygonDirection[f];
    for (size_t i = 0; i < poly.size(); ++i) {
      const int a = poly[i], b = poly[(i + 1) % poly.size()];
      vertexMask[size_t(a)] |= bit;
      edgeMask[{std::min(a, b), std::max(a, b)}] |= bit;
    }
  }
  for (const auto& [e, mask] : edgeMask) {
    if (timeUp()) return false;
    const DVec3 &a = s.vertices[size_t(e.first)], &b = s.vertices[size_t(e.second)];
    const DVec3 mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
    add(figureAt(s, solid, mid, mask, stepAt(mid, -1)), mid[1] > aboveGround);
  }
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    if (timeUp()) return false;
    if (vertexMask[v])
      add(figureAt(s, solid, s.vertices[v], vertexMask[v], stepAt(s.vertices[v], int(v))), s.vertices[v][1] > aboveGround);
  }
  return true;
}

std::optional<uint64_t> edgePattern(const Label& label, const std::vector<IVec3>& dirs, const IVec3& axis,
                                    uint32_t edgePlanes, const std::vector<DVec3>& wedges) {
  for (uint32_t m = label.dirs; m; m &= m - 1) {
    const int e = __builtin_ctz(m);
    if (dot(dirs[size_t(e)], axis) == 0 && !((edgePlanes >> e) & 1)) return std::nullopt;
  }
  uint64_t bits = 0;
  for (size_t w = 0; w < wedges.size(); ++w) {
    const auto signs = signMaskNear(dirs, label.dirs, axis, wedges[w]);
    if (!signs) return std::nullopt;
    if (label.inside(*signs)) bits |= uint64_t(1) << w;
  }
  return bits;
}

}  // namespace fgsg::rt::synthesis::continuous
