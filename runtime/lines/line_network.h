// Linear structures (FGSG §4.4, Fig. 10): lines grown segment by segment, where a line
// that runs into another one is clipped to end on it (merge) or stops short (no merge),
// instead of leaving the gap that deleting the colliding segment would.
//
// `Line(width, merge)` starts a chain at the scope's position; every later `LineSeg()` in
// that shape or its descendants extends it to the scope's new position. Two shapes that
// extend a line from the same point make a branch: the second one forks a new chain.
#pragma once

#include "runtime/point_grid.h"
#include "runtime/mesh.h"
#include "runtime/scope.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt {

struct LineStyle {
  double width = 0.05;  // diameter of the tube; negative or not finite counts as 0
  bool merge = true;    // join a line it runs into (else stop before it)
  // An asset drawn along the line instead of the tube, one instance per segment bent
  // along the smoothed line (an index into the output's assets; UINT32_MAX: the tube).
  uint32_t asset = UINT32_MAX;
};

// Where a shape stands on a line: the chain it extends and the index of its last point.
// A shape copies its cursor to the shapes it derives; extend() moves it.
struct LineCursor {
  uint32_t chain = UINT32_MAX;
  uint32_t point = 0;
  bool ended = false;  // this line joined or stopped: later extends add nothing
  bool valid() const { return chain != UINT32_MAX; }
};

enum class SegmentOutcome {
  Added,    // the segment was kept whole (or was of zero length and ignored)
  Joined,   // merge line: it met another line and now ends on that line's centreline
  Stopped,  // non-merge line: it would have met another line, so it was dropped
  Ended,    // the cursor's line had already joined or stopped (or the cursor is invalid)
};

class LineNetwork {
 public:
  // A new chain of one point at `start`; `owner` is an opaque tag (the interpreter passes
  // the symbol id).
  LineCursor start(const Vec3& start, const LineStyle& style, uint32_t owner);

  // Extends the line at `cursor` to `to` and moves the cursor to the new end.
  //  - At the chain's last point the chain grows. Anywhere else (a second shape extending
  //    from the same point) a new chain with the same style and owner forks off there,
  //    and the cursor moves to it.
  //  - A segment shorter than rounding noise, or with a non-finite end, is ignored (Added).
  //  - The segment meets another one when their closest points are within the mean of
  //    their widths. Of all such segments the one met first along the new segment wins
  //    (smallest parameter, then lowest segment id). Not counted: any segment whose
  //    closest approach is at the new segment's start, which covers the chain's own
  //    previous segment, a branch's parent line and a line moving away from another.
  //  - Joined: the new segment ends at the closest point on the other's centreline (a
  //    crossing is clipped there; a near miss is extended onto it). Stopped: nothing is
  //    added. Either way the cursor is ended; a sibling cursor at the same point may still
  //    extend (after Stopped) or fork (after Joined) the chain.
  // `*hitPoint`, when given, receives where the line now ends (Added, Joined) or the point
  // on the other line it ran into (Stopped); it is left alone on Ended.
  SegmentOutcome extend(LineCursor& cursor, const Vec3& to, Vec3* hitPoint = nullptr);

  // Undo for all-or-nothing placement: rollback(mark()) removes every chain, point and
  // segment added after the mark. Cursors obtained after the mark must be dropped.
  size_t mark() const { return journal_.size(); }
  void rollback(size_t mark);

  size_t chainCount() const { return chains_.size(); }
  size_t segmentCount() const { return segments_.size(); }
  const std::vector<Vec3>& points(uint32_t chain) const { return chains_[chain].points; }
  LineStyle style(uint32_t chain) const { return chains_[chain].style; }
  uint32_t owner(uint32_t chain) const { return chains_[chain].owner; }

  // A smooth closed tube of diameter width around the chain (see sweepTube): empty for a
  // chain of fewer than two points or without width.
  Mesh sweep(uint32_t chain, int sides = 8, int samplesPerSegment = 4) const;

 private:
  struct Chain {
    std::vector<Vec3> points;
    LineStyle style;
    uint32_t owner = 0;
  };
  struct Segment {
    Vec3 a, b;
    double halfWidth;
    uint32_t chain;
  };
  struct Hit {
    uint32_t segment = UINT32_MAX;
    double s = 0;  // parameter along the new segment
    Vec3 onOther;  // closest point on the other segment's centreline
  };
  enum class Event : uint8_t { Chain, Segment };

  Hit firstHit(const Vec3& from, const Vec3& to, double halfWidth);
  void addSegment(uint32_t chain, const Vec3& to);

  std::vector<Chain> chains_;
  std::vector<Segment> segments_;  // by id, in the order they were added
  PointGrid grid_;               // segment centres, ids as in segments_
  std::vector<Event> journal_;     // what was added, in order: rollback pops it
  double longest_ = 0;             // longest segment tested or stored so far
  double widest_ = 0;              // widest line so far
  std::vector<uint32_t> nearby_;   // scratch for grid queries
};

}  // namespace fgsg::rt
