#include "runtime/marching/geometry_image.h"

#include "runtime/marching/atlas_raster.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <array>
#include <cmath>

namespace fgsg::rt::marching {

namespace {

// Segments this much shorter than the coarse cells that check them need few lookups;
// finer cells are visited only along a chart's border.
constexpr double kCellsPerSegment = 4;

}  // namespace

GeometryImage GeometryImage::build(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles,
                                   int size) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  GeometryImage img;
  const auto started = Clock::now();
  AtlasRaster raster = rasterizeAtlas(triangles, size);
  const auto rasterized = Clock::now();
  img.texels_.size = size;
  img.texels_.face = std::move(raster.face);
  img.derive(mesh, triangles);  // chart_ and position_ (no pointers yet)
  const auto located = Clock::now();
  PointerLayout layout = findIndirectionPointers(triangles, size, img.texels_.face, img.chart_, img.position_);
  img.texels_.pointerCount = std::move(layout.count);
  img.texels_.pointers = std::move(layout.pointers);
  const auto pointed = Clock::now();
  img.texels_.kind.assign(size_t(size) * size, uint8_t(TexelKind::Background));
  for (size_t i = 0; i < img.texels_.kind.size(); ++i)
    if (img.texels_.face[i] >= 0)
      img.texels_.kind[i] = uint8_t(TexelKind::Inner);
    else if (img.texels_.pointerCount[i] > 0)
      img.texels_.kind[i] = uint8_t(TexelKind::Indirection);
  img.derive(mesh, triangles);
  img.stats_.conservativeTexels = raster.conservativeTexels;
  img.stats_.rasterSeconds = seconds(started, rasterized);
  img.stats_.pointSeconds = seconds(rasterized, located);
  img.stats_.pointerSeconds = seconds(located, pointed);
  img.stats_.levelSeconds = seconds(pointed, Clock::now());
  return img;
}

bool GeometryImage::restore(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles,
                            Texels texels, GeometryImage& out, std::string& error) {
  const int n = texels.size;
  if (n < kMinImageResolution || n > kMaxImageResolution) {
    error = "image size " + std::to_string(n) + " is out of range";
    return false;
  }
  const size_t count = size_t(n) * n;
  if (texels.kind.size() != count || texels.face.size() != count || texels.pointerCount.size() != count) {
    error = "texel arrays do not match the image size";
    return false;
  }
  std::vector<int32_t> chart(count, -1);
  for (size_t i = 0; i < count; ++i) {
    const uint8_t k = texels.kind[i];
    const int f = texels.face[i];
    if (k > uint8_t(TexelKind::Indirection)) {
      error = "texel " + std::to_string(i) + " has an unknown kind";
      return false;
    }
    if ((k == uint8_t(TexelKind::Inner)) != (f >= 0) || f >= int(triangles.size()) || f < -1) {
      error = "texel " + std::to_string(i) + " has a face that does not fit its kind";
      return false;
    }
    if (f >= 0) chart[i] = triangles[f].chart;
  }
  size_t expected = 0;
  for (uint8_t c : texels.pointerCount) expected += c;
  if (expected != texels.pointers.size()) {
    error = "pointer counts do not add up";
    return false;
  }
  size_t next = 0;
  std::array<int, 8> found;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const size_t i = size_t(y) * n + x;
      const int around = chart[i] >= 0 ? 0 : chartsAround(chart, n, x, y, found);
      const bool indirection = texels.kind[i] == uint8_t(TexelKind::Indirection);
      if (indirection != (around > 0) || texels.pointerCount[i] != around) {
        error = "texel (" + std::to_string(x) + ", " + std::to_string(y) + ") does not border the charts its pointers say";
        return false;
      }
      for (int k = 0; k < around; ++k, ++next) {
        const IndirectionPointer& p = texels.pointers[next];
        if (p.chart != found[k] || p.target < -1 || p.target >= int(count) ||
            (p.target >= 0 && chart[p.target] < 0)) {
          error = "texel (" + std::to_string(x) + ", " + std::to_string(y) + ") has a pointer out of range";
          return false;
        }
      }
    }
  out = GeometryImage();
  out.texels_ = std::move(texels);
  out.derive(mesh, triangles);
  return true;
}

void GeometryImage::derive(const surface::SurfaceMesh& mesh, const std::vector<ImageTriangle>& triangles) {
  const int n = texels_.size;
  const size_t count = size_t(n) * n;
  if (chart_.size() != count) {
    chart_.assign(count, -1);
    position_.assign(count, Eigen::Vector3f::Zero());
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 16), [&](const auto& rows) {
      for (int y = rows.begin(); y < rows.end(); ++y)
        for (int x = 0; x < n; ++x) {
          const size_t i = size_t(y) * n + x;
          const int f = texels_.face[i];
          if (f < 0) continue;
          chart_[i] = triangles[f].chart;
          const Vec3 b = triangles[f].closestBary(Vec2(x + 0.5, y + 0.5));
          const auto& v = mesh.faces[f];
          position_[i] = (b[0] * mesh.vertices[v[0]] + b[1] * mesh.vertices[v[1]] + b[2] * mesh.vertices[v[2]])
                             .cast<float>();
        }
    });
  }
  if (texels_.kind.size() != count) return;  // build(): pointers come next

  pointerStart_.assign(count + 1, 0);
  for (size_t i = 0; i < count; ++i) pointerStart_[i + 1] = pointerStart_[i] + texels_.pointerCount[i];

  levels_.clear();
  const std::vector<int32_t>* finer = &chart_;
  for (int finerSize = n; finerSize > 1;) {
    const int s = (finerSize + 1) / 2;
    std::vector<int32_t> level(size_t(s) * s, kEmptyCell);
    for (int cy = 0; cy < s; ++cy)
      for (int cx = 0; cx < s; ++cx) {
        int value = 0;
        bool first = true;
        for (int k = 0; k < 4; ++k) {
          const int fx = 2 * cx + (k & 1), fy = 2 * cy + (k >> 1);
          const int child = fx < finerSize && fy < finerSize ? (*finer)[size_t(fy) * finerSize + fx] : kEmptyCell;
          if (first) value = child, first = false;
          else if (child != value) value = kMixedCell;
        }
        level[size_t(cy) * s + cx] = value;
      }
    levels_.push_back(std::move(level));
    finer = &levels_.back();
    finerSize = s;
  }

  stats_ = ImageStats{};
  for (size_t i = 0; i < count; ++i) {
    stats_.innerTexels += texels_.kind[i] == uint8_t(TexelKind::Inner);
    stats_.indirectionTexels += texels_.kind[i] == uint8_t(TexelKind::Indirection);
  }
  stats_.pointers = texels_.pointers.size();
  for (const auto& p : texels_.pointers) stats_.boundaryPointers += p.target < 0;
}

int GeometryImage::texelAt(const Vec2& p) const {
  const int n = texels_.size;
  const int x = std::clamp(int(std::floor(p.x())), 0, n - 1), y = std::clamp(int(std::floor(p.y())), 0, n - 1);
  return index(x, y);
}

int GeometryImage::levelSize(int level) const {
  int s = texels_.size;
  for (int k = 0; k < level; ++k) s = (s + 1) / 2;
  return s;
}

int GeometryImage::cell(int level, int cx, int cy) const {
  if (level == 0) return chart_[size_t(cy) * texels_.size + cx];
  return levels_[level - 1][size_t(cy) * levelSize(level) + cx];
}

bool GeometryImage::segmentInChart(const Vec2& a, const Vec2& b, int chart) const {
  if (chart < 0 || !a.allFinite() || !b.allFinite()) return false;
  const double n = texels_.size;
  if (a.minCoeff() < 0 || b.minCoeff() < 0 || a.maxCoeff() >= n || b.maxCoeff() >= n) return false;
  const double length = (b - a).norm();
  int level = 0;
  while (level + 1 < levelCount() && double(1 << (level + 1)) * kCellsPerSegment <= length) ++level;
  return segmentInCells(level, a, b, chart);
}

// The cells of `level` the segment passes through, in order (Amanatides and Woo's grid
// walk); a mixed cell is looked into one level finer along the part of the segment in it.
bool GeometryImage::segmentInCells(int level, const Vec2& a, const Vec2& b, int chart) const {
  const double cellSize = double(1 << level);
  const int s = levelSize(level);
  const Vec2 from = a / cellSize, to = b / cellSize, d = to - from;
  int cx = std::clamp(int(std::floor(from.x())), 0, s - 1), cy = std::clamp(int(std::floor(from.y())), 0, s - 1);
  const int endX = std::clamp(int(std::floor(to.x())), 0, s - 1), endY = std::clamp(int(std::floor(to.y())), 0, s - 1);
  const int stepX = d.x() > 0 ? 1 : -1, stepY = d.y() > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double deltaX = d.x() != 0 ? 1 / std::abs(d.x()) : inf, deltaY = d.y() != 0 ? 1 / std::abs(d.y()) : inf;
  double nextX = d.x() != 0 ? ((stepX > 0 ? cx + 1 : cx) - from.x()) / d.x() : inf;
  double nextY = d.y() != 0 ? ((stepY > 0 ? cy + 1 : cy) - from.y()) / d.y() : inf;
  double t0 = 0;
  for (int guard = 0; guard < 4 * (s + 2); ++guard) {
    const double t1 = std::min({nextX, nextY, 1.0});
    const int value = cell(level, cx, cy);
    if (value != chart) {
      if (value != kMixedCell || level == 0) return false;
      if (!segmentInCells(level - 1, a + t0 * (b - a), a + t1 * (b - a), chart)) return false;
    }
    if (cx == endX && cy == endY) return true;
    if (t1 >= 1) return true;
    if (nextX < nextY) {
      cx += stepX;
      t0 = nextX;
      nextX += deltaX;
    } else {
      cy += stepY;
      t0 = nextY;
      nextY += deltaY;
    }
    if (cx < 0 || cy < 0 || cx >= s || cy >= s) return false;
  }
  return false;
}

}  // namespace fgsg::rt::marching
