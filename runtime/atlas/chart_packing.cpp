#include "runtime/atlas/chart_packing.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace fgsg::rt::atlas {

namespace {

struct Extent {
  Vec2 lo, hi;
  Vec2 size() const { return hi - lo; }
};

// Texels a chart's content spans at `scale` texels per unit: its extent rounded up,
// strictly larger than the extent so rounding cannot push a corner into the next texel.
// Anything wider than any image is capped (it cannot fit anyway) before it overflows.
int contentTexels(double extent, double scale) {
  return int(std::min(std::floor(extent * scale + 1e-6), double(1 << 30))) + 1;
}

struct Placement {
  int x = 0, y = 0;  // the box's lower left texel within the packing area
  bool rotated = false;
};

// The skyline: the top of what is packed, as segments left to right covering the width.
class Skyline {
 public:
  Skyline(int width, int height) : width_(width), height_(height), segments_{{0, 0, width}} {}

  // The lowest place (then the leftmost) a w x h box fits; false when none.
  bool find(int w, int h, int& bestX, int& bestY) const {
    bool found = false;
    for (size_t i = 0; i < segments_.size(); ++i) {
      const int x = segments_[i].x;
      if (x + w > width_) break;
      int y = 0;
      for (size_t j = i; j < segments_.size() && segments_[j].x < x + w; ++j)
        y = std::max(y, segments_[j].y);
      if (y + h > height_) continue;
      if (!found || y < bestY || (y == bestY && x < bestX)) {
        bestX = x, bestY = y;
        found = true;
      }
    }
    return found;
  }

  // Raises the skyline over [x, x + w) to y + h.
  void place(int x, int y, int w, int h) {
    std::vector<Segment> next;
    next.reserve(segments_.size() + 2);
    bool placed = false;
    auto placeOnce = [&] {
      if (!placed) push(next, {x, y + h, w});
      placed = true;
    };
    for (const Segment& s : segments_) {
      const int end = s.x + s.width;
      if (end <= x) {  // wholly left of the box
        push(next, s);
      } else if (s.x >= x + w) {  // wholly right
        placeOnce();
        push(next, s);
      } else {  // under the box: what sticks out on either side stays
        if (s.x < x) push(next, {s.x, s.y, x - s.x});
        placeOnce();
        if (end > x + w) push(next, {x + w, s.y, end - (x + w)});
      }
    }
    placeOnce();
    segments_ = std::move(next);
  }

 private:
  struct Segment {
    int x, y, width;
  };
  // Appends, merging with the last segment when both are as high.
  static void push(std::vector<Segment>& v, const Segment& s) {
    if (!v.empty() && v.back().y == s.y && v.back().x + v.back().width == s.x)
      v.back().width += s.width;
    else
      v.push_back(s);
  }
  int width_, height_;
  std::vector<Segment> segments_;
};

struct Packer {
  std::vector<Extent> extents;
  int area;    // side of the packing area in texels: the resolution less one border gutter
  int gutter;
  bool allowRotation;

  // Packs at `scale`; false when something does not fit.
  bool pack(double scale, std::vector<Placement>& placements) const {
    const int n = int(extents.size());
    std::vector<std::array<int, 2>> box(n);  // width, height in texels, gutter included
    for (int i = 0; i < n; ++i) {
      const Vec2 s = extents[i].size();
      box[i] = {contentTexels(s.x(), scale) + gutter, contentTexels(s.y(), scale) + gutter};
    }
    // Tallest first; with rotation, lying down (height the shorter side).
    auto height = [&](int i) { return allowRotation ? std::min(box[i][0], box[i][1]) : box[i][1]; };
    auto width = [&](int i) { return allowRotation ? std::max(box[i][0], box[i][1]) : box[i][0]; };
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      if (height(a) != height(b)) return height(a) > height(b);
      if (width(a) != width(b)) return width(a) > width(b);
      return a < b;
    });
    placements.assign(n, {});
    Skyline skyline(area, area);
    for (int i : order) {
      int x = 0, y = 0, rx = 0, ry = 0;
      const bool upright = skyline.find(box[i][0], box[i][1], x, y);
      const bool turned = allowRotation && box[i][0] != box[i][1] &&
                          skyline.find(box[i][1], box[i][0], rx, ry);
      if (!upright && !turned) return false;
      // Turned when that leaves a lower top (then: lower, then further left).
      const bool useTurned =
          turned && (!upright || std::make_tuple(ry + box[i][0], ry, rx) < std::make_tuple(y + box[i][1], y, x));
      if (useTurned) {
        placements[i] = {rx, ry, true};
        skyline.place(rx, ry, box[i][1], box[i][0]);
      } else {
        placements[i] = {x, y, false};
        skyline.place(x, y, box[i][0], box[i][1]);
      }
    }
    return true;
  }
};

}  // namespace

bool checkAtlasOptions(const AtlasOptions& options, std::string& error) {
  if (options.gutterTexels < 1) {
    error = "atlas: the gutter must be at least one texel (indirection pixels live there), not " +
            std::to_string(options.gutterTexels);
    return false;
  }
  if (options.resolution < 2 * options.gutterTexels + 1 || options.resolution > (1 << 20)) {
    error = "atlas: a resolution of " + std::to_string(options.resolution) +
            " texels cannot hold a chart with a gutter of " + std::to_string(options.gutterTexels) +
            " texels (at least " + std::to_string(2 * options.gutterTexels + 1) +
            ", at most 1048576)";
    return false;
  }
  if (!(options.maxNormalDeviation > 0 && options.maxNormalDeviation <= 180)) {
    error = "atlas: the maximal normal deviation must be within (0, 180] degrees, not " +
            std::to_string(options.maxNormalDeviation);
    return false;
  }
  return true;
}

bool packCharts(const std::vector<FlatChart>& charts, size_t faceCount, const AtlasOptions& options,
                bool allowRotation, Atlas& out, std::string& error) {
  out = Atlas{};
  if (!checkAtlasOptions(options, error)) return false;
  Packer packer;
  packer.area = options.resolution - options.gutterTexels;
  packer.gutter = options.gutterTexels;
  packer.allowRotation = allowRotation;
  double areaSum = 0;
  for (const FlatChart& c : charts) {
    Extent e{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
    for (const auto& t : c.corners)
      for (const Vec2& p : t) e.lo = e.lo.cwiseMin(p), e.hi = e.hi.cwiseMax(p);
    packer.extents.push_back(e);
    areaSum += e.size().x() * e.size().y();
  }

  std::vector<Placement> placements;
  if (!packer.pack(0.0, placements)) {
    error = "atlas: " + std::to_string(charts.size()) + " charts do not fit into a " +
            std::to_string(options.resolution) + "x" + std::to_string(options.resolution) +
            " geometry image with a gutter of " + std::to_string(options.gutterTexels) +
            " texels, even at one texel each: use a larger resolution (or, for a generated "
            "atlas, a larger normal deviation)";
    return false;
  }
  // The boxes hold more than the charts' extents, so at `high` the area alone is exceeded.
  double low = 0, high = packer.area / std::sqrt(std::max(areaSum, 1e-300));
  for (int i = 0; i < 64 && high - low > 1e-9 * high; ++i) {
    const double mid = 0.5 * (low + high);
    std::vector<Placement> trial;
    if (packer.pack(mid, trial)) {
      low = mid;
      placements = std::move(trial);
    } else {
      high = mid;
    }
  }
  const double scale = low;  // the placements are the ones packed at `low`

  out.resolution = options.resolution;
  out.chartCount = int(charts.size());
  out.faceChart.assign(faceCount, -1);
  out.cornerUV.assign(faceCount, {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()});
  const double texel = 1.0 / options.resolution;
  for (size_t c = 0; c < charts.size(); ++c) {
    const Extent& e = packer.extents[c];
    const Placement& p = placements[c];
    // Turned a quarter counter-clockwise: (x, y) -> (-y, x), moved back to the origin.
    const Vec2 size = p.rotated ? Vec2(e.size().y(), e.size().x()) : e.size();
    const Vec2 content(contentTexels(size.x(), scale), contentTexels(size.y(), scale));
    // Centred in its whole texels, so rounding leaves the chart inside them.
    const Vec2 origin = Vec2(options.gutterTexels + p.x, options.gutterTexels + p.y) +
                        0.5 * (content - scale * size);
    for (size_t i = 0; i < charts[c].faces.size(); ++i) {
      const int f = charts[c].faces[i];
      out.faceChart[f] = int(c);
      for (int k = 0; k < 3; ++k) {
        const Vec2& q = charts[c].corners[i][k];
        const Vec2 local = p.rotated ? Vec2(e.hi.y() - q.y(), q.x() - e.lo.x()) : Vec2(q - e.lo);
        out.cornerUV[f][k] = (origin + scale * local) * texel;
      }
    }
  }
  return true;
}

}  // namespace fgsg::rt::atlas
