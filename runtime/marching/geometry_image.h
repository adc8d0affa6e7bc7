// The indirection geometry image of Buron et al. §4: the atlas rasterized into N x N
// texels (texel (x, y) covers [x, x+1] x [y, y+1] in image units, the atlas's [0, 1]^2
// times N, y up). A texel is background, inner (a face of a chart covers it; its
// centre's closest point on that face is an exact surface point) or indirection (a
// background texel next to a chart, holding pointers to where the surface continues).
// Coarser levels (each halving the side) record which cells lie wholly inside one chart,
// so a long straight march can be checked in a few lookups. Read-only once built.
//
// Per texel it stores the kind, the face, the chart and the centre's surface point as
// floats (26 bytes a texel with the pointer index); the centre's barycentric coordinates
// are recomputed from the face when wanted (MarchingSurface::texelPoint), exactly and
// cheaply, rather than stored.
#pragma once

#include "runtime/marching/image_triangles.h"
#include "runtime/marching/indirection_pointers.h"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace fgsg::rt::marching {

enum class TexelKind : uint8_t { Background = 0, Inner = 1, Indirection = 2 };

struct ImageStats {
  size_t innerTexels = 0;
  size_t conservativeTexels = 0;  // inner although their centre lies in no triangle
  size_t indirectionTexels = 0;
  size_t pointers = 0;
  size_t boundaryPointers = 0;    // pointers without a target: the surface's own boundary
  // build()'s wall time by phase: rasterization, texel surface points, pointers (with
  // their kd-tree), the rest (coarse levels, indices).
  double rasterSeconds = 0, pointSeconds = 0, pointerSeconds = 0, levelSeconds = 0;
};

// What a geometry image is made of; everything else is derived from it (the disk cache
// stores exactly this).
struct ImageTexels {
  int size = 0;
  std::vector<uint8_t> kind;                // TexelKind per texel
  std::vector<int32_t> face;                // inner: the covering face, else -1
  std::vector<uint8_t> pointerCount;        // indirection: how many pointers (>= 1), else 0
  std::vector<IndirectionPointer> pointers; // in texel order
};

class GeometryImage {
 public:
  using Texels = ImageTexels;
  // A coarse cell's content (level >= 1): a chart number when every texel under it is an
  // inner texel of that chart, else one of these.
  static constexpr int kEmptyCell = -1;  // no inner texel under it
  static constexpr int kMixedCell = -2;

  // Rasterizes `triangles` (buildImageTriangles) into a size x size image.
  static GeometryImage build(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles,
                             int size);
  // The image made of stored `texels` (the disk cache): false with a message unless they
  // are consistent with each other and with `triangles` (kinds, faces and pointers in
  // range, indirection texels exactly the background texels next to a chart, one pointer
  // per chart around each).
  static bool restore(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles,
                      Texels texels, GeometryImage& out, std::string& error);

  int size() const { return texels_.size; }
  int index(int x, int y) const { return y * texels_.size + x; }
  // The texel holding image point p (clamped into the image).
  int texelAt(const Vec2& p) const;
  TexelKind kind(int t) const { return TexelKind(texels_.kind[t]); }
  int chart(int t) const { return chart_[t]; }  // inner: its chart, else -1
  int face(int t) const { return texels_.face[t]; }
  // Inner: the surface point at the texel's centre (the closest point of its face), as
  // floats (exact points are recomputed from the face where they matter).
  const Eigen::Vector3f& position(int t) const { return position_[t]; }
  std::span<const IndirectionPointer> pointers(int t) const {
    return {texels_.pointers.data() + pointerStart_[t], texels_.pointerCount[t]};
  }

  // Levels 0 (the texels) .. levelCount() - 1 (one cell).
  int levelCount() const { return int(levels_.size()) + 1; }
  int levelSize(int level) const;
  // Level 0: the texel's chart or kEmptyCell; coarser: a chart, kEmptyCell or kMixedCell.
  int cell(int level, int cx, int cy) const;
  // True when every texel the segment a-b passes through is an inner texel of `chart`
  // (checked on the coarsest cells that settle it).
  bool segmentInChart(const Vec2& a, const Vec2& b, int chart) const;

  const Texels& texels() const { return texels_; }
  const ImageStats& stats() const { return stats_; }

 private:
  void derive(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles);
  bool segmentInCells(int level, const Vec2& a, const Vec2& b, int chart) const;

  Texels texels_;
  std::vector<int32_t> chart_;
  std::vector<uint32_t> pointerStart_;
  std::vector<Eigen::Vector3f> position_;
  std::vector<std::vector<int32_t>> levels_;  // levels_[k - 1] is level k
  ImageStats stats_;
};

}  // namespace fgsg::rt::marching
