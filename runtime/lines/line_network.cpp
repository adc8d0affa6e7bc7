#include "runtime/lines/line_network.h"

#include "runtime/lines/tube.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt {
namespace {

// Lengths and distances below these multiples of the coordinates' magnitude (at least 1)
// are rounding noise: a shorter segment has no direction, and two centrelines that cross
// exactly compute as ~1e-16 apart, which must still count for lines without width.
constexpr double kMinSegmentLength = 1e-12;
constexpr double kContactTolerance = 1e-9;

// A closest approach at a parameter below this (relative to the new segment's length) is
// at its start: a branch leaving its parent line, or a line moving away from another.
constexpr double kStartParameter = 1e-9;

// Segments whose directions' squared sine is below this are treated as parallel, where
// the closest points are not unique and the general formula divides by ~0.
constexpr double kParallelSine2 = 1e-12;

struct Closest {
  double s, t;  // parameters along p and q, in [0, 1]
  double distance2;
};

// Closest points of the segments p0 p1 and q0 q1 (p of positive length); of several (on
// parallel segments), the one nearest p0, so results do not depend on rounding order.
// When p0 == q1 (a chain's previous segment) then r == d2, so c == b and f == e bit for
// bit and s comes out exactly 0, however sharply the chain turns back.
Closest closestPoints(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), b = d1.dot(d2);
  const double c = d1.dot(r), f = d2.dot(r);
  double s, t;
  if (e <= 0) {  // q is a point
    s = std::clamp(-c / a, 0.0, 1.0);
    t = 0;
  } else {
    const double denom = a * e - b * b;
    if (denom > kParallelSine2 * a * e) {
      s = std::clamp((b * f - c * e) / denom, 0.0, 1.0);
    } else {
      // q's ends projected onto p's parameter: on their overlap with [0, 1] the distance
      // is constant, so take its start; without overlap, p's end nearer to q.
      const double lo = std::min(-c / a, (b - c) / a), hi = std::max(-c / a, (b - c) / a);
      s = hi < 0 ? 0.0 : lo > 1 ? 1.0 : std::max(0.0, lo);
    }
    t = (b * s + f) / e;
    if (t < 0) {
      t = 0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1) {
      t = 1;
      s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  return {s, t, (p0 + s * d1 - (q0 + t * d2)).squaredNorm()};
}

double magnitude(const Vec3& a, const Vec3& b) {
  return std::max({1.0, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
}

}  // namespace

LineCursor LineNetwork::start(const Vec3& start, const LineStyle& style, uint32_t owner) {
  Chain chain;
  chain.points.push_back(start);
  chain.style = style;
  if (!(std::isfinite(style.width) && style.width > 0)) chain.style.width = 0;
  chain.owner = owner;
  widest_ = std::max(widest_, chain.style.width);
  chains_.push_back(std::move(chain));
  journal_.push_back(Event::Chain);
  return {uint32_t(chains_.size() - 1), 0, false};
}

LineNetwork::Hit LineNetwork::firstHit(const Vec3& from, const Vec3& to, double halfWidth) {
  const double tolerance = kContactTolerance * magnitude(from, to);
  // Two segments that come within their widths have centres at most half of each length
  // plus both half widths apart, which this radius bounds.
  const double radius = longest_ + widest_ + 2 * tolerance;
  grid_.reserveRadius(radius);
  grid_.near(0.5 * (from + to), radius, nearby_);
  Hit hit;
  for (uint32_t id : nearby_) {  // ascending: on equal parameters the lower id stays
    const Segment& other = segments_[id];
    const Closest cp = closestPoints(from, to, other.a, other.b);
    const double reach = halfWidth + other.halfWidth + tolerance;
    if (cp.distance2 > reach * reach || cp.s < kStartParameter) continue;
    if (hit.segment == UINT32_MAX || cp.s < hit.s) {
      hit.segment = id;
      hit.s = cp.s;
      hit.onOther = other.a + cp.t * (other.b - other.a);
    }
  }
  return hit;
}

void LineNetwork::addSegment(uint32_t chain, const Vec3& to) {
  Chain& c = chains_[chain];
  const Vec3 from = c.points.back();
  // A join may lengthen the segment it clipped (a near miss reaches over to the other
  // line), so the search radius follows what is stored, not only what was asked for.
  longest_ = std::max(longest_, (to - from).norm());
  grid_.add(0.5 * (from + to));
  segments_.push_back({from, to, 0.5 * c.style.width, chain});
  c.points.push_back(to);
  journal_.push_back(Event::Segment);
}

SegmentOutcome LineNetwork::extend(LineCursor& cursor, const Vec3& to, Vec3* hitPoint) {
  if (!cursor.valid() || cursor.ended || cursor.chain >= chains_.size() ||
      cursor.point >= chains_[cursor.chain].points.size())
    return SegmentOutcome::Ended;
  const Chain& chain = chains_[cursor.chain];
  const Vec3 from = chain.points[cursor.point];
  const double minLength = kMinSegmentLength * magnitude(from, to);
  if (!from.allFinite() || !to.allFinite() || (to - from).norm() <= minLength) {
    if (hitPoint) *hitPoint = from;
    return SegmentOutcome::Added;
  }
  const bool fork = cursor.point + 1 != chain.points.size();
  const LineStyle style = chain.style;
  const uint32_t owner = chain.owner;

  longest_ = std::max(longest_, (to - from).norm());
  const Hit hit = firstHit(from, to, 0.5 * style.width);
  const bool met = hit.segment != UINT32_MAX;
  if (met) {
    cursor.ended = true;
    if (!style.merge) {
      if (hitPoint) *hitPoint = hit.onOther;
      return SegmentOutcome::Stopped;
    }
  }
  // The clipped segment is not tested again: it only moved onto the line it met.
  const Vec3 end = met ? hit.onOther : to;
  if (hitPoint) *hitPoint = end;
  // Joining right at the start leaves nothing to add; the line still ends there.
  if ((end - from).norm() <= minLength) return SegmentOutcome::Joined;
  if (fork) {
    Chain branch;
    branch.points.push_back(from);
    branch.style = style;
    branch.owner = owner;
    chains_.push_back(std::move(branch));
    journal_.push_back(Event::Chain);
    cursor.chain = uint32_t(chains_.size() - 1);
  }
  addSegment(cursor.chain, end);
  cursor.point = uint32_t(chains_[cursor.chain].points.size() - 1);
  return met ? SegmentOutcome::Joined : SegmentOutcome::Added;
}

// The longest segment and widest line are kept: a larger search radius only adds candidates.
void LineNetwork::rollback(size_t mark) {
  while (journal_.size() > mark) {
    if (journal_.back() == Event::Segment) {
      Chain& c = chains_[segments_.back().chain];
      c.points.pop_back();
      segments_.pop_back();
      grid_.removeLast();
    } else {
      chains_.pop_back();
    }
    journal_.pop_back();
  }
}

Mesh LineNetwork::sweep(uint32_t chain, int sides, int samplesPerSegment) const {
  const Chain& c = chains_[chain];
  return sweepTube(c.points, 0.5 * c.style.width, sides, samplesPerSegment);
}

}  // namespace fgsg::rt
