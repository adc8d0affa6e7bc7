#include "runtime/evolve/surface_ornament.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fgsg::rt::evolve {
namespace {

// A triangle with an edge longer than this many cell widths spans a jump of the map (a
// line from neighbouring face-let points hitting opposite sides of a thin part): the
// ornament's own edges are a small fraction of a cell.
constexpr double kMaxEdgeInCells = 2.0;

}  // namespace

rt::Mesh surfaceOrnament(const TileSet& tiles, const AlleleGrid& pattern, const PolycubeMap& map,
                         const std::function<double(const MappedPoint&)>& maxHeight, const OrnamentOptions& options,
                         SurfaceOrnamentStats* stats, double maxStretch, const std::vector<char>* shownFacelets,
                         std::vector<uint32_t>* triangleCell) {
  const int n = pattern.side;
  if (!(maxStretch == 0 || (maxStretch >= 1 && std::isfinite(maxStretch))))
    throw std::invalid_argument("surfaceOrnament: the stretch limit must be 0 (none) or a ratio of at least 1, got " +
                                std::to_string(maxStretch));
  if (n <= 0 || pattern.cells.size() != size_t(n) * size_t(n))
    throw std::invalid_argument("surfaceOrnament: an empty pattern");
  for (const Allele& a : pattern.cells)
    if (a.symbol >= tiles.symbolCount() || a.turns > 3)
      throw std::invalid_argument("surfaceOrnament: the pattern has symbol " + std::to_string(a.symbol) +
                                  ", the tile set " + std::to_string(tiles.symbolCount()));

  // Each allele's flat ornament once, in tile units; then where each cell's vertices and
  // indices go in one face-let's block (the same layout on every face-let).
  std::vector<std::optional<OrnamentGrid>> grids(size_t(tiles.symbolCount()) * 4);
  struct CellBlock {
    const OrnamentGrid* grid;
    size_t firstVertex, firstIndex;
  };
  std::vector<CellBlock> cells(pattern.cells.size());
  size_t vertices = 0, indices = 0;
  for (size_t c = 0; c < pattern.cells.size(); ++c) {
    const Allele a = pattern.cells[c];
    auto& g = grids[size_t(a.index())];
    if (!g) g = ornamentGrid(tiles, a, options);
    cells[c] = {&*g, vertices, indices};
    vertices += g->t.size() * g->r.size();
    indices += 6 * (g->t.size() - 1) * (g->r.size() - 1);
  }
  const std::vector<Facelet>& facelets = map.facelets();
  if (shownFacelets && shownFacelets->size() != facelets.size())
    throw std::invalid_argument("surfaceOrnament: " + std::to_string(shownFacelets->size()) +
                                " face-let flags for " + std::to_string(facelets.size()) + " face-lets");
  const size_t triangles = facelets.size() * indices / 3;
  if (triangles > kMaxSurfaceOrnamentTriangles)
    throw std::invalid_argument("surfaceOrnament: " + std::to_string(triangles) + " triangles (" +
                                std::to_string(facelets.size()) + " face-lets x " + std::to_string(indices / 3) +
                                "), more than the " + std::to_string(kMaxSurfaceOrnamentTriangles) + " allowed");

  rt::Mesh mesh;
  mesh.positions.resize(3 * facelets.size() * vertices);
  mesh.texcoords.resize(2 * facelets.size() * vertices);
  mesh.indices.resize(facelets.size() * indices);
  std::vector<double> lowest(facelets.size(), 1.0);
  const size_t perFacelet = pattern.cells.size();
  std::vector<double> stretch(facelets.size() * perFacelet);
  std::vector<size_t> stretchedTriangles(facelets.size(), 0), hiddenTriangles(facelets.size(), 0);
  std::vector<uint32_t> cellOfTriangle(triangleCell ? mesh.indices.size() / 3 : 0);
  tbb::parallel_for(size_t(0), facelets.size(), [&](size_t f) {
    const double w = facelets[f].u.norm() / n;  // a cell's width on this face-let
    const size_t vBase = f * vertices, iBase = f * indices;
    faceletStretch(map, f, n, stretch.data() + f * perFacelet);
    const bool hidden = shownFacelets && !(*shownFacelets)[f];
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) {
        const size_t c = size_t(row) * size_t(n) + size_t(col);
        const CellBlock& cell = cells[c];
        // Its vertices are still placed (on the surface, so the ornament's box stays true).
        const bool tooStretched = maxStretch > 0 && stretch[f * perFacelet + c] > maxStretch;
        const OrnamentGrid& g = *cell.grid;
        const size_t nt = g.t.size(), nr = g.r.size();
        for (size_t i = 0; i < nt; ++i)
          for (size_t j = 0; j < nr; ++j) {
            const auto& p = g.at(i, j);
            const double a = std::clamp((col + p[0]) / n, 0.0, 1.0);
            const double b = std::clamp((n - 1 - row + p[1]) / n, 0.0, 1.0);
            const MappedPoint m = map.map(f, a, b);
            double s = 1;
            if (maxHeight && options.height > 0) s = std::clamp(maxHeight(m) / (options.height * w), 0.0, 1.0);
            lowest[f] = std::min(lowest[f], s);
            const Vec3 at = m.position + m.normal * (p[2] * w * s);
            const size_t v = vBase + cell.firstVertex + i * nr + j;
            for (int k = 0; k < 3; ++k) mesh.positions[3 * v + size_t(k)] = float(at[k]);
            mesh.texcoords[2 * v] = float(g.r[j]);
            mesh.texcoords[2 * v + 1] = float(g.t[i]);
          }
        // As ornamentMesh: counter-clockwise seen from the side the section rises to. A
        // triangle spanning a jump of the map is marked (all corners alike) and dropped.
        size_t k = iBase + cell.firstIndex;
        const size_t first = vBase + cell.firstVertex;
        const double longest = kMaxEdgeInCells * w;
        auto jumps = [&](uint32_t p, uint32_t q) {
          double d2 = 0;
          for (size_t c = 0; c < 3; ++c) {
            const double e = double(mesh.positions[3 * size_t(p) + c]) - double(mesh.positions[3 * size_t(q) + c]);
            d2 += e * e;
          }
          return d2 > longest * longest;
        };
        if (tooStretched) stretchedTriangles[f] += 2 * (nt - 1) * (nr - 1);
        else if (hidden) hiddenTriangles[f] += 2 * (nt - 1) * (nr - 1);
        if (triangleCell)
          std::fill_n(cellOfTriangle.begin() + std::ptrdiff_t(k / 3), 2 * (nt - 1) * (nr - 1), uint32_t(c));
        for (size_t i = 0; i + 1 < nt; ++i)
          for (size_t j = 0; j + 1 < nr; ++j) {
            const auto a = uint32_t(first + i * nr + j), b = a + 1, c = uint32_t(a + nr), d = c + 1;
            for (const std::array<uint32_t, 3> t : {std::array{a, b, c}, std::array{b, d, c}}) {
              const bool drop =
                  tooStretched || hidden || jumps(t[0], t[1]) || jumps(t[1], t[2]) || jumps(t[2], t[0]);
              for (const uint32_t v : t) mesh.indices[k++] = drop ? t[0] : v;
            }
          }
      }
  });
  // Keep the triangles that were not marked, in order.
  size_t kept = 0;
  for (size_t t = 0; t < mesh.indices.size(); t += 3)
    if (mesh.indices[t] != mesh.indices[t + 1] || mesh.indices[t] != mesh.indices[t + 2]) {
      if (triangleCell) triangleCell->push_back(cellOfTriangle[t / 3]);
      for (size_t c = 0; c < 3; ++c) mesh.indices[kept++] = mesh.indices[t + c];
    }
  size_t leftOut = 0;
  for (const size_t t : stretchedTriangles) leftOut += t;
  for (const size_t t : hiddenTriangles) leftOut += t;
  const size_t dropped = (mesh.indices.size() - kept) / 3 - leftOut;
  mesh.indices.resize(kept);
  mesh.computeNormals();
  if (stats) {
    stats->facelets = facelets.size();
    stats->cells = facelets.size() * pattern.cells.size();
    stats->triangles = mesh.triangleCount();
    stats->lowestScale = lowest.empty() ? 1.0 : *std::min_element(lowest.begin(), lowest.end());
    stats->droppedTriangles = dropped;
    std::vector<double> emitted;
    for (const double r : stretch)
      if (!(maxStretch > 0 && r > maxStretch)) emitted.push_back(r);
    stats->stretchedCells = stretch.size() - emitted.size();
    stats->emittedStretch = summarizeStretch(std::move(emitted));
    stats->stretch = summarizeStretch(std::move(stretch));
  }
  return mesh;
}

std::vector<char> faceletsFacing(const PolycubeMap& map, const std::vector<int>& directions) {
  std::vector<char> shown;
  shown.reserve(map.facelets().size());
  for (const Facelet& f : map.facelets()) {
    const int direction = 2 * f.axis + (f.sign > 0 ? 0 : 1);
    shown.push_back(std::find(directions.begin(), directions.end(), direction) != directions.end() ? 1 : 0);
  }
  return shown;
}

std::vector<rt::Mesh> partOrnament(const rt::Mesh& mesh, const std::vector<uint32_t>& triangleCell,
                                   const std::vector<int>& cellClass, int classCount) {
  if (triangleCell.size() != mesh.triangleCount())
    throw std::invalid_argument("partOrnament: a cell for each of the mesh's triangles is needed");
  std::vector<rt::Mesh> parts(size_t(std::max(classCount, 0)));
  // Per part, the new number of each vertex it uses (UINT32_MAX: not yet).
  std::vector<std::vector<uint32_t>> renumber(parts.size());
  const bool withNormals = mesh.normals.size() == mesh.positions.size(), withUv = mesh.hasTexcoords();
  for (size_t t = 0; t < triangleCell.size(); ++t) {
    const int cls = triangleCell[t] < cellClass.size() ? cellClass[triangleCell[t]] : -1;
    if (cls < 0 || cls >= classCount)
      throw std::invalid_argument("partOrnament: triangle " + std::to_string(t) + " has no class");
    rt::Mesh& part = parts[size_t(cls)];
    std::vector<uint32_t>& number = renumber[size_t(cls)];
    if (number.empty()) number.assign(mesh.vertexCount(), UINT32_MAX);
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t v = mesh.indices[3 * t + k];
      if (number[v] == UINT32_MAX) {
        number[v] = uint32_t(part.vertexCount());
        for (size_t d = 0; d < 3; ++d) part.positions.push_back(mesh.positions[3 * size_t(v) + d]);
        if (withNormals)
          for (size_t d = 0; d < 3; ++d) part.normals.push_back(mesh.normals[3 * size_t(v) + d]);
        if (withUv)
          for (size_t d = 0; d < 2; ++d) part.texcoords.push_back(mesh.texcoords[2 * size_t(v) + d]);
      }
      part.indices.push_back(number[v]);
    }
  }
  return parts;
}

}  // namespace fgsg::rt::evolve
