#include "runtime/texture/paint_mask.h"

#include "runtime/io/atomic_file.h"
#include "runtime/io/png_encode.h"

#include <algorithm>
#include <cmath>


namespace fgsg::rt::texture {
namespace {

// Pixels a triangle covers but the mask has not filled: 1 painted, 0 unpainted, below 0
// not covered by any triangle.
constexpr int8_t kUncovered = -1;

}  // namespace

MaskImage paintMask(const marching::MarchingSurface& surface, int size, const std::vector<Brush>& brushes) {
  const auto& mesh = surface.mesh();
  std::vector<int8_t> state(static_cast<size_t>(size) * size, kUncovered);
  for (int f = 0; f < static_cast<int>(mesh.faceCount()); ++f) {
    atlas::Vec2 uv[3];
    for (int k = 0; k < 3; ++k) {
      Vec3 corner = Vec3::Zero();
      corner[k] = 1;
      uv[k] = surface.texCoord({f, corner}) * size;  // pixel units, v up
    }
    const double area = (uv[1] - uv[0]).x() * (uv[2] - uv[0]).y() - (uv[1] - uv[0]).y() * (uv[2] - uv[0]).x();
    if (area == 0) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({uv[0].x(), uv[1].x(), uv[2].x()}))));
    const int x1 = std::min(size - 1, static_cast<int>(std::ceil(std::max({uv[0].x(), uv[1].x(), uv[2].x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({uv[0].y(), uv[1].y(), uv[2].y()}))));
    const int y1 = std::min(size - 1, static_cast<int>(std::ceil(std::max({uv[0].y(), uv[1].y(), uv[2].y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const atlas::Vec2 p(x + 0.5, y + 0.5);
        auto edge = [&](const atlas::Vec2& a, const atlas::Vec2& b) {
          return ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
        };
        const double b0 = edge(uv[1], uv[2]), b1 = edge(uv[2], uv[0]), b2 = edge(uv[0], uv[1]);
        if (b0 < 0 || b1 < 0 || b2 < 0) continue;
        const Vec3 point = surface::SurfacePoint{f, Vec3(b0, b1, b2)}.position(mesh);
        bool inside = false;
        for (const Brush& brush : brushes) inside |= brush.covers(point);
        int8_t& s = state[static_cast<size_t>(size - 1 - y) * size + x];  // row 0 at the top
        s = std::max<int8_t>(s, inside ? 1 : 0);
      }
  }
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int8_t> grown = state;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        if (state[static_cast<size_t>(y) * size + x] != kUncovered) continue;
        int8_t best = kUncovered;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < size && ny < size)
              best = std::max(best, state[static_cast<size_t>(ny) * size + nx]);
          }
        grown[static_cast<size_t>(y) * size + x] = best;
      }
    state.swap(grown);
  }
  MaskImage mask;
  mask.size = size;
  mask.grey.resize(state.size());
  for (size_t i = 0; i < state.size(); ++i) mask.grey[i] = state[i] == 1 ? 255 : 0;
  return mask;
}

bool writeMaskPng(const MaskImage& mask, const std::string& path, std::string& error) {
  std::string png;
  if (!io::encodePng(mask.size, mask.size, 1, mask.grey.data(), png)) {
    error = "cannot write '" + path + "': cannot encode the mask as PNG";
    return false;
  }
  return io::writeFileAtomically(path, png, error);
}

}  // namespace fgsg::rt::texture
