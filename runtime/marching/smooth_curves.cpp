#include "runtime/marching/smooth_curves.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fgsg::rt::marching {

namespace {

// A sum of unit vectors shorter than this has no direction worth following.
constexpr double kVanishingTangent = 1e-9;

// One segment as seen from one of its nodes.
struct SegmentEnd {
  uint32_t segment = 0;
  bool outgoing = false;     // the segment starts at this node
  Vec3 away = Vec3::Zero();  // unit direction from this node to the segment's other node
  double length = 0;         // the segment's chord length
};

// A normal, normalised unless it is unit already (its bits then reach the curves as given).
Vec3 unitOrZero(const Vec3& v) {
  const double len = v.norm();
  if (std::abs(len - 1) <= 1e-14) return v;
  return len > 0 && std::isfinite(len) ? Vec3(v / len) : Vec3::Zero();
}

// (I - n n^T) v: v's part in the tangent plane of the unit normal n (v itself for n = 0).
Vec3 tangential(const Vec3& n, const Vec3& v) { return v - n * n.dot(v); }

// The sides (+1 / -1) of the segments at a node where growth does not pass through (all
// leave or all arrive): flips one segment at a time while that lengthens the sum of the
// sided tangential directions. Starts from the sides of the first segment's half-plane.
std::vector<int> sidesWithoutThroughGrowth(const std::vector<Vec3>& along) {
  const size_t k = along.size();
  std::vector<int> side(k, 1);
  for (size_t i = 1; i < k; ++i) side[i] = along[i].dot(along[0]) >= 0 ? 1 : -1;
  Vec3 sum = Vec3::Zero();
  for (size_t i = 0; i < k; ++i) sum += side[i] * along[i];
  // Each flip lengthens the sum strictly (by 4 |s a . (sum - s a)|), so this ends; the
  // margin and the pass limit only guard against rounding.
  for (size_t pass = 0; pass < 4 * k + 4; ++pass) {
    bool flipped = false;
    for (size_t i = 0; i < k; ++i) {
      const Vec3 own = side[i] * along[i];
      if (own.dot(sum - own) < -1e-12) {
        sum -= 2 * own;
        side[i] = -side[i];
        flipped = true;
      }
    }
    if (!flipped) break;
  }
  return side;
}

// The shared unit tangent at a node with normal n, given its segment ends and their
// sides (see smooth_curves.h).
Vec3 sharedTangent(const Vec3& n, const std::vector<SegmentEnd>& ends, const std::vector<int>& side) {
  Vec3 sum = Vec3::Zero();
  for (size_t i = 0; i < ends.size(); ++i) sum += side[i] * ends[i].away;
  const Vec3 t = tangential(n, sum);
  if (t.norm() > kVanishingTangent) return t.normalized();
  for (size_t i = 0; i < ends.size(); ++i) {  // a march turning straight back
    const Vec3 own = tangential(n, side[i] * ends[i].away);
    if (own.norm() > kVanishingTangent) return own.normalized();
  }
  // Every segment along the normal: any tangent direction is as good as another.
  return n.squaredNorm() > 0 ? Vec3(n.unitOrthogonal()) : Vec3(ends[0].away);
}

}  // namespace

std::vector<CurveSegment> smoothSegments(const std::vector<MarchNode>& nodes,
                                         const std::vector<MarchSegment>& segments) {
  std::vector<Vec3> normal(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) normal[i] = unitOrZero(nodes[i].normal);

  // The ends of the non-degenerate segments, grouped by node (in segment order).
  std::vector<std::vector<SegmentEnd>> endsAt(nodes.size());
  std::vector<CurveSegment> curves(segments.size());
  for (size_t s = 0; s < segments.size(); ++s) {
    const MarchSegment& seg = segments[s];
    if (seg.from >= nodes.size() || seg.to >= nodes.size())
      throw std::out_of_range("smoothSegments: segment " + std::to_string(s) + " joins nodes " +
                              std::to_string(seg.from) + " and " + std::to_string(seg.to) + ", but there are " +
                              std::to_string(nodes.size()) + " nodes");
    const Vec3& a = nodes[seg.from].position;
    const Vec3& b = nodes[seg.to].position;
    CurveSegment& c = curves[s];
    // Until a node moves them, the inner control points sit on the ends (a degenerate
    // segment keeps them there).
    for (int d = 0; d < 3; ++d) {
      c.control[0][d] = c.control[1][d] = a[d];
      c.control[2][d] = c.control[3][d] = b[d];
      c.normal0[d] = normal[seg.from][d];
      c.normal1[d] = normal[seg.to][d];
    }
    const double length = (b - a).norm();
    if (!(length > 0) || !std::isfinite(length)) continue;
    if (seg.smoothness != TerminalSmoothness::C1) {
      // A curve of its own, sharing no node's tangent (smooth_curves.h).
      const bool c0 = seg.smoothness == TerminalSmoothness::C0;
      const Vec3 inner1 = a + (c0 ? tangential(normal[seg.from], b - a) : Vec3(b - a)) / 3.0;
      const Vec3 inner2 = b - (c0 ? tangential(normal[seg.to], b - a) : Vec3(b - a)) / 3.0;
      for (int d = 0; d < 3; ++d) c.control[1][d] = inner1[d], c.control[2][d] = inner2[d];
      continue;
    }
    const Vec3 dir = (b - a) / length;
    endsAt[seg.from].push_back({uint32_t(s), true, dir, length});
    endsAt[seg.to].push_back({uint32_t(s), false, -dir, length});
  }

  std::vector<int> side;
  std::vector<Vec3> along;
  for (size_t node = 0; node < nodes.size(); ++node) {
    const std::vector<SegmentEnd>& ends = endsAt[node];
    if (ends.empty()) continue;
    const Vec3& n = normal[node];
    const bool anyIn = std::any_of(ends.begin(), ends.end(), [](const SegmentEnd& e) { return !e.outgoing; });
    const bool anyOut = std::any_of(ends.begin(), ends.end(), [](const SegmentEnd& e) { return e.outgoing; });
    if (anyIn && anyOut) {
      // Growth passes through: every segment in its direction of growth.
      side.assign(ends.size(), 1);
      for (size_t i = 0; i < ends.size(); ++i) side[i] = ends[i].outgoing ? 1 : -1;
    } else {
      along.resize(ends.size());
      for (size_t i = 0; i < ends.size(); ++i) along[i] = tangential(n, ends[i].away);
      side = sidesWithoutThroughGrowth(along);
    }
    const Vec3 t = sharedTangent(n, ends, side);

    double projections = 0, shortest = ends[0].length;
    for (const SegmentEnd& e : ends) {
      projections += std::abs(t.dot(e.away)) * e.length;
      shortest = std::min(shortest, e.length);
    }
    double handle = std::min(projections / double(ends.size()), shortest) / 3.0;
    if (!(handle > 0)) handle = shortest / 3.0;  // every segment across the tangent

    const Vec3 p = nodes[node].position;
    for (size_t i = 0; i < ends.size(); ++i) {
      const Vec3 inner = p + (side[i] * handle) * t;
      auto& control = curves[ends[i].segment].control[ends[i].outgoing ? 1 : 2];
      for (int d = 0; d < 3; ++d) control[d] = inner[d];
    }
  }
  return curves;
}

}  // namespace fgsg::rt::marching
