// CityEngine's shape state that does not fit into rt::Scope: setPivot's pivot and
// comp(f)'s trim planes, kept per start shape. A scope names its frame by rt::Scope::pivot
// (1 + its index; 0: the object system and no trim planes); a frame never changes once
// made, so the shapes that share it (a part and everything it creates) share it safely.
#pragma once

#include "backend/interp/eval.h"
#include "runtime/cga/trim_planes.h"
#include "runtime/scope.h"

#include <cstdint>
#include <vector>

namespace fgsg::backend {

class ShapeFrames {
 public:
  void clear() { frames_.clear(); }
  // The pivot setPivot gave frame `frame` (or a shape before it); null: none.
  const rt::Scope* pivot(uint16_t frame) const {
    return frame == 0 || !frames_[frame - 1].hasPivot ? nullptr : &frames_[frame - 1].pivot;
  }
  // The trim planes of frame `frame`: those of every comp(f) the shape came through.
  const std::vector<rt::cga::TrimPlane>& trimPlanes(uint16_t frame) const {
    static const std::vector<rt::cga::TrimPlane> none;
    return frame == 0 ? none : frames_[frame - 1].trimPlanes;
  }
  // Those of frame `frame` the trim attribute `trimBits` (rt::Scope::trim) turns on:
  // vertical ones unless set off, horizontal ones only when set on.
  std::vector<rt::cga::TrimPlane> enabledTrimPlanes(uint16_t frame, uint8_t trimBits) const {
    std::vector<rt::cga::TrimPlane> planes;
    for (const rt::cga::TrimPlane& p : trimPlanes(frame))
      if (p.horizontal ? (trimBits & 2) != 0 : (trimBits & 1) == 0) planes.push_back(p);
    return planes;
  }
  // A new frame: frame `from` with the pivot set / these trim planes added (R002 at `at`
  // past 65 535 frames for one start shape, the most a scope can name).
  uint16_t withPivot(uint16_t from, const rt::Scope& pivot, ir::Loc at) {
    Frame f = copyOf(from);
    f.hasPivot = true;
    f.pivot = pivot;
    return add(std::move(f), at);
  }
  uint16_t withTrimPlanes(uint16_t from, const std::vector<rt::cga::TrimPlane>& planes, ir::Loc at) {
    Frame f = copyOf(from);
    f.trimPlanes.insert(f.trimPlanes.end(), planes.begin(), planes.end());
    return add(std::move(f), at);
  }

 private:
  struct Frame {
    bool hasPivot = false;
    rt::Scope pivot;
    std::vector<rt::cga::TrimPlane> trimPlanes;
  };
  Frame copyOf(uint16_t frame) const { return frame == 0 ? Frame{} : frames_[frame - 1]; }
  uint16_t add(Frame f, ir::Loc at) {
    if (frames_.size() >= UINT16_MAX)
      throw DeriveError{at, "R002", "more than 65535 pivots (setPivot) and trim-plane sets (comp(f)) for one start shape"};
    frames_.push_back(std::move(f));
    return static_cast<uint16_t>(frames_.size());
  }
  std::vector<Frame> frames_;
};

}  // namespace fgsg::backend
