// Repeat: tiles a scope with equal tiles along one, two or three axes (CGA's repeat split).
#include "runtime/cga/axis_names.h"
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <array>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

// floor(L / s) is taken with this slack so that 10 / (10 / 3) gives 3, not 2.
constexpr double kCountSlack = 1e-9;
// A guard against a tile size that would produce an absurd number of shapes.
constexpr double kMaxTiles = 1u << 24;

struct Grid {
  std::array<std::size_t, 3> count{1, 1, 1};
  Vec3 tile = Vec3::Zero();  // tile length per axis
};

bool resolveGrid(const Scope& scope, unsigned axesMask, const std::vector<double>& sizes,
                 Grid& grid, std::string& error) {
  if (axesMask == 0 || axesMask > 7) {
    error = "Repeat: the axes must be a combination of X, Y and Z";
    return false;
  }
  const std::size_t needed = (axesMask & 1) + ((axesMask >> 1) & 1) + ((axesMask >> 2) & 1);
  if (sizes.size() != needed) {
    std::ostringstream m;
    m << "Repeat: " << needed << (needed == 1 ? " axis needs " : " axes need ") << needed
      << (needed == 1 ? " size" : " sizes") << ", got " << sizes.size();
    error = m.str();
    return false;
  }
  std::size_t next = 0;
  double total = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    grid.tile[axis] = scope.S[axis];
    if (!(axesMask & (1u << axis))) continue;
    const double s = sizes[next++];
    if (!(s > 0.0) || !std::isfinite(s)) {
      std::ostringstream m;
      m << "Repeat along " << kAxisNames[axis] << ": the tile size " << s << " must be positive";
      error = m.str();
      return false;
    }
    const double length = scope.S[axis];
    const double n = std::max(1.0, std::floor(length / s + kCountSlack));
    total *= n;
    if (!(total <= kMaxTiles)) {
      std::ostringstream m;
      m << "Repeat along " << kAxisNames[axis] << ": a tile size of " << s << " on a length of "
        << length << " gives more than " << kMaxTiles << " tiles";
      error = m.str();
      return false;
    }
    grid.count[axis] = static_cast<std::size_t>(n);
    grid.tile[axis] = length / n;
  }
  return true;
}

// Clips `g` to tile i of n along `axis` and maps the tile onto [0,1]; false if empty.
bool clipToTile(LocalGeometry& g, int axis, std::size_t i, std::size_t n) {
  if (n == 1) return true;
  const double lo = static_cast<double>(i) / n;
  const double hi = static_cast<double>(i + 1) / n;
  if (!clipToSlab(g, axis, lo, hi)) return false;
  renormalise(g, axis, lo, hi);
  return true;
}

}  // namespace

// `out` is replaced by the tiles, X fastest. Box, Edge and box-face geometry is shared by
// every tile (no arena use: the hot path). Other polygons and polyhedra are clipped tile
// by tile, outer axes first so each row is clipped once; a tile keeps its full scope even
// where the geometry covers part of it, and tiles with no area of the geometry are empty.
bool repeat(const Scope& scope, const GeomRef& geom, unsigned axesMask,
            const std::vector<double>& sizes, GeometryArena& arena, std::vector<Part>& out,
            std::string& error) {
  out.clear();
  Grid grid;
  if (!resolveGrid(scope, axesMask, sizes, grid, error)) return false;
  const std::size_t nx = grid.count[0], ny = grid.count[1], nz = grid.count[2];
  out.reserve(nx * ny * nz);

  Part tile{scope, geom, false};
  tile.scope.S = grid.tile;
  const Vec3 stepX = scope.X() * grid.tile.x();
  const Vec3 stepY = scope.Y() * grid.tile.y();
  const Vec3 stepZ = scope.Z() * grid.tile.z();

  // A single tile is the scope itself.
  if (nx * ny * nz == 1 || isSlabInvariant(arena, geom)) {
    for (std::size_t iz = 0; iz < nz; ++iz)
      for (std::size_t iy = 0; iy < ny; ++iy) {
        const Vec3 row =
            scope.P + stepZ * static_cast<double>(iz) + stepY * static_cast<double>(iy);
        for (std::size_t ix = 0; ix < nx; ++ix) {
          tile.scope.P = row + stepX * static_cast<double>(ix);
          out.push_back(tile);
        }
      }
    return true;
  }

  const LocalGeometry whole = loadGeometry(arena, geom);
  const GeomRef none{geom.kind, 0, 0};
  for (std::size_t iz = 0; iz < nz; ++iz) {
    LocalGeometry gz = whole;
    const bool hasZ = clipToTile(gz, 2, iz, nz);
    for (std::size_t iy = 0; iy < ny; ++iy) {
      LocalGeometry gy = hasZ ? gz : LocalGeometry{};
      const bool hasY = hasZ && clipToTile(gy, 1, iy, ny);
      const Vec3 row = scope.P + stepZ * static_cast<double>(iz) + stepY * static_cast<double>(iy);
      for (std::size_t ix = 0; ix < nx; ++ix) {
        Part& part = out.emplace_back(tile);
        part.scope.P = row + stepX * static_cast<double>(ix);
        LocalGeometry gx = hasY ? gy : LocalGeometry{};
        if (hasY && clipToTile(gx, 0, ix, nx)) {
          part.geom = storeGeometry(arena, gx);
        } else {
          part.geom = none;
          part.empty = true;
        }
      }
    }
  }
  return true;
}

}  // namespace fgsg::rt::cga
