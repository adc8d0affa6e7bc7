// A lot's rings checked (edges, areas, holes) and oriented, with located messages.
#include "runtime/io/lot_rings.h"

#include "runtime/planar.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace fgsg::rt {

namespace {

// Points closer than this (relative to the lot's coordinates) count as touching: 1 micron
// on a kilometre, far above rounding and far below any real gap between two walls.
constexpr double kRelativeTolerance = 1e-9;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Whether the open segments ab and cd cross at a single point inside both.
bool crossProperly(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double abc = cross(b - a, c - a), abd = cross(b - a, d - a);
  const double cda = cross(d - c, a - c), cdb = cross(d - c, b - c);
  return ((abc > 0 && abd < 0) || (abc < 0 && abd > 0)) && ((cda > 0 && cdb < 0) || (cda < 0 && cdb > 0));
}

double segmentDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  if (crossProperly(a, b, c, d)) return 0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                   pointSegmentDistance(d, a, b)});
}

// Crossing-number test; `p` is known not to lie on the ring.
bool inside(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& ring) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      in = !in;
  }
  return in;
}

// Builds the messages of one lot.
class Namer {
 public:
  explicit Namer(const LotMessages& messages) : m_(messages) {}

  // "lots.geojson: feature 3, ring 1 (hole 1)"; a hole is named even where rings are not.
  std::string ring(size_t r) const {
    return m_.namesRings || r > 0 ? m_.place + ", " + lotRingName(r) : m_.place;
  }

  // "point 4 (8.5, 47.3)", "corner 4 (1, 0, -2)": the file's index and coordinates.
  std::string point(const LotRing& ring, size_t i) const {
    std::ostringstream s;
    s << std::setprecision(12) << m_.pointNoun << " " << ring.index[i] << " (";
    for (int k = 0; k < m_.coordinates; ++k) s << (k > 0 ? ", " : "") << ring.file[i][k];
    s << ")";
    return s.str();
  }

  std::string edge(const LotRing& ring, size_t i) const {
    return "the edge from " + point(ring, i) + " to " + point(ring, (i + 1) % ring.xy.size());
  }

  const LotMessages& messages() const { return m_; }

 private:
  const LotMessages& m_;
};

struct LotRingError {
  std::string message;
};

[[noreturn]] void failRings(const std::string& message) { throw LotRingError{message}; }

struct Edge {
  size_t ring, i;
  double minX, maxX, minY, maxY;
};

// No two edges of the lot's rings touch or cross, except neighbours in a ring at their
// shared point. Edges sorted by their left end are compared only with those whose x
// ranges overlap theirs, which keeps ordinary lots near n log n.
void checkEdges(const std::vector<LotRing>& rings, const Namer& name, double tolerance) {
  std::vector<Edge> edges;
  for (size_t r = 0; r < rings.size(); ++r) {
    const std::vector<Eigen::Vector2d>& xy = rings[r].xy;
    for (size_t i = 0; i < xy.size(); ++i) {
      const Eigen::Vector2d& a = xy[i];
      const Eigen::Vector2d& b = xy[(i + 1) % xy.size()];
      edges.push_back({r, i, std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                       std::max(a.y(), b.y())});
    }
  }
  // Ties broken by ring and index, so that which of several faults is reported is fixed.
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return std::tie(a.minX, a.ring, a.i) < std::tie(b.minX, b.ring, b.i);
  });
  for (size_t u = 0; u < edges.size(); ++u)
    for (size_t v = u + 1; v < edges.size() && edges[v].minX <= edges[u].maxX + tolerance; ++v) {
      // The edge of the later ring (or the later edge of one ring) first in messages.
      const bool swap = std::tie(edges[u].ring, edges[u].i) < std::tie(edges[v].ring, edges[v].i);
      const Edge& e = swap ? edges[v] : edges[u];
      const Edge& f = swap ? edges[u] : edges[v];
      if (e.minY > f.maxY + tolerance || f.minY > e.maxY + tolerance) continue;
      const LotRing& re = rings[e.ring];
      const LotRing& rf = rings[f.ring];
      const size_t n = re.xy.size();
      const Eigen::Vector2d& a = re.xy[e.i];
      const Eigen::Vector2d& b = re.xy[(e.i + 1) % n];
      const Eigen::Vector2d& c = rf.xy[f.i];
      const Eigen::Vector2d& d = rf.xy[(f.i + 1) % rf.xy.size()];
      // Neighbours meet at their shared point. Two that fold back onto each other leave a
      // point on an edge that is no neighbour (or, in a triangle, zero area), found there.
      if (e.ring == f.ring && (e.i == (f.i + 1) % n || f.i == (e.i + 1) % n)) continue;
      if (segmentDistance(a, b, c, d) > tolerance) continue;
      const std::string where = name.ring(e.ring) + ": ";
      const std::string verb = crossProperly(a, b, c, d) ? " crosses " : " touches ";
      if (e.ring == f.ring) failRings(where + name.edge(re, e.i) + verb + name.edge(rf, f.i));
      failRings(where + name.edge(re, e.i) + verb + lotRingName(f.ring) + " at " + name.edge(rf, f.i));
    }
}

// Left for a ring without touching edges to be degenerate: all its points on one line (a
// figure eight has zero area too, but its edges cross, as found above).
void checkAreas(const std::vector<LotRing>& rings, const Namer& name, double tolerance) {
  for (size_t r = 0; r < rings.size(); ++r) {
    const LotRing& ring = rings[r];
    Eigen::AlignedBox2d box;
    for (const Eigen::Vector2d& q : ring.xy) box.extend(q);
    if (std::abs(twiceRingArea(ring.xy)) <= 2 * tolerance * box.sizes().maxCoeff())
      failRings(name.ring(r) + ": zero area" + name.messages().view + " (all its " + name.messages().pointNoun +
           "s on one line, from " + name.point(ring, 0) + ")");
  }
}

// The rings are sound on their own and no two touch: each hole lies wholly inside the
// outer ring or wholly outside, and likewise for two holes, as one point of it tells.
void checkHoles(const std::vector<LotRing>& rings, const Namer& name) {
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const LotRing& ring : rings) {
    Eigen::AlignedBox2d box;
    for (const Eigen::Vector2d& q : ring.xy) box.extend(q);
    boxes.push_back(box);
  }
  for (size_t h = 1; h < rings.size(); ++h)
    if (!inside(rings[h].xy[0], rings[0].xy))
      failRings(name.ring(h) + ": lies outside the outer ring (its " + name.point(rings[h], 0) + ")");
  for (size_t h = 1; h < rings.size(); ++h)
    for (size_t k = 1; k < rings.size(); ++k)
      if (h != k && boxes[k].contains(boxes[h]) && inside(rings[h].xy[0], rings[k].xy))
        failRings(name.ring(h) + ": lies inside " + lotRingName(k) + " (its " + name.point(rings[h], 0) +
             "); holes may not overlap");
}

}  // namespace

std::string lotRingName(size_t r) {
  return "ring " + std::to_string(r) + (r == 0 ? " (outer)" : " (hole " + std::to_string(r) + ")");
}

bool checkAndOrientRings(std::vector<LotRing>& rings, const LotMessages& messages, Lot& lot,
                         std::string& error) {
  const Namer name(messages);
  try {
    Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    double largest = 0;
    for (const LotRing& ring : rings)
      for (const Eigen::Vector2d& q : ring.xy) {
        lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
        largest = std::max(largest, q.cwiseAbs().maxCoeff());
      }
    const double tolerance = kRelativeTolerance * std::max(largest, (hi - lo).maxCoeff());
    checkEdges(rings, name, tolerance);
    checkAreas(rings, name, tolerance);
    checkHoles(rings, name);
  } catch (const LotRingError& e) {
    error = e.message;
    return false;
  }
  lot.outer.clear();
  lot.holes.clear();
  for (size_t r = 0; r < rings.size(); ++r) {
    std::vector<Eigen::Vector2d>& xy = rings[r].xy;
    // Outer rings counter-clockwise, holes clockwise, whatever the file had; the first
    // point stays first.
    if ((twiceRingArea(xy) > 0) != (r == 0)) std::reverse(xy.begin() + 1, xy.end());
    if (r == 0) lot.outer = std::move(xy);
    else lot.holes.push_back(std::move(xy));
  }
  return true;
}

}  // namespace fgsg::rt
