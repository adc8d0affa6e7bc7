// The indirection pointers of §4 (Fig. 2a): every background texel next to a chart
// points to where the surface continues beyond that chart's border — the inner-border
// texel of another chart closest in 3D to the mean of the chart's texels around it.
// A texel next to two charts (charts packed with a one-texel gutter) holds one pointer
// for each, so a march from either side finds its own.
#pragma once

#include "runtime/marching/image_triangles.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace fgsg::rt::marching {

struct IndirectionPointer {
  int32_t chart = -1;   // the chart whose border this continues (a neighbouring texel's)
  // Texel index (x + y * size) of the inner-border texel the march jumps to, or -1: no
  // other chart within reach, the surface's own boundary (an open mesh).
  int32_t target = -1;
};

// A target counts when it is at most this many texel lengths (3D, source's plus
// target's) from the mean point: across a seam the two borders' texel centres lie
// within about one texel of each other on either side.
constexpr double kSeamReachTexels = 2.0;
// Border texels of the pointer's own chart closer than this in the image are the same
// side of the border and never a target; farther ones are, so that a chart cut open
// along a seam of its own (an unrolled cylinder) continues across it.
constexpr int kOwnSideTexels = 8;

struct PointerLayout {
  std::vector<uint8_t> count;              // per texel: how many pointers it holds
  std::vector<IndirectionPointer> pointers; // all texels' pointers in texel order, charts ascending
};

// The distinct charts of the texels around background texel (x, y) (8-neighbours;
// `chart` per texel, -1 for none), ascending: the charts it holds pointers for.
int chartsAround(const std::vector<int32_t>& chart, int size, int x, int y, std::array<int, 8>& found);

// `face`, `chart` and `position` are per texel: the covering face (-1: background), its
// chart and the surface point at the texel's centre.
PointerLayout findIndirectionPointers(const std::vector<ImageTriangle>& triangles, int size,
                                      const std::vector<int32_t>& face, const std::vector<int32_t>& chart,
                                      const std::vector<Eigen::Vector3f>& position);

}  // namespace fgsg::rt::marching
