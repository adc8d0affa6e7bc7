// Ornaments on a surface (Chan & Hui 2013 §5, §6.3): an evolved pattern laid on every
// face-let of a polycube around the mesh and carried onto the surface.
//
// For each face-let of the inverse poly-cube map (polycube_map.h) the pattern's n x n
// cells fill its unit square, row 0 at the top (b = 1), as on a flat panel. Each cell's
// ornament is the flat one of its allele (ornament.h: the cross-section blended along the
// locus between its rails, §2.4/§5.2), computed once per allele in tile units; a point
// (x, y, z) of it, in cell (row, column), sits at the face-let point
//   a = (column + x) / n,  b = (n - 1 - row + y) / n      (clamped to [0, 1])
// which the map carries to the surface point P with smooth normal N; the vertex is
//   P + N * z * w * s(P),
// w the cell's width in world units (the face-let's edge / n) and s(P) <= 1 the height
// limit of §6.3: with `maxHeight` given, s = min(1, maxHeight(P) / (height * w)), the
// ornament's top (the section's y = 1, `height` of the tile options) no higher than the
// offset surface allows there (Eq. 12's V(t)); so the ornament keeps its profile and
// flattens only where the surface leaves no room. In-plane, the rails and the section's
// width follow the face-let's parameterisation through the map — the paper's offset
// curves projected into texture space (§5.2, Eq. 10).
//
// Where the map jumps (a thin part of the surface, thinner than a polycube cell, seen from
// both sides by neighbouring face-let points), triangles with an edge longer than two cell
// widths are dropped rather than stretched across the gap (SurfaceOrnamentStats counts them).
//
// Where the map stretches a cell into a streak (§6.4: thin parts, a bunny's ears, an
// elephant's trunk; ornament_stretch.h measures a cell's stretch as the ratio of its
// longest to its shortest mapped side), the cell's ornament is left out when `maxStretch`
// is given and the cell's stretch exceeds it: a gap in the pattern rather than a streak
// the pattern never had (SurfaceOrnamentStats counts those cells).
//
// Each cell's ornament ends exactly on its cell's border where its locus does (ornament.h),
// and points on a border shared by two face-lets map to the same surface point, so
// neighbouring ornaments meet; a p4 pattern (§6.1) meets itself across face-lets however
// they are turned. Triangles face outward (the face-let's u x v is its outward normal).
#pragma once

#include "runtime/evolve/lsystem2d.h"
#include "runtime/evolve/ornament.h"
#include "runtime/evolve/ornament_stretch.h"
#include "runtime/evolve/polycube_map.h"
#include "runtime/evolve/tiles.h"
#include "runtime/mesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace fgsg::rt::evolve {

struct SurfaceOrnamentStats {
  size_t facelets = 0;
  size_t cells = 0;       // facelets x pattern cells
  size_t triangles = 0;
  double lowestScale = 1;  // the smallest s(P) the height limit applied
  size_t droppedTriangles = 0;  // spanning a jump of the map (an edge over 2 cell widths)
  StretchSummary stretch;        // every mapped cell's stretch
  StretchSummary emittedStretch;  // the stretch of the cells whose ornament was emitted
  size_t stretchedCells = 0;     // left out: stretched beyond maxStretch
};

// The stretch bound `fgsg evolve --max-stretch` applies unless told otherwise.
constexpr double kDefaultMaxStretch = 4.0;

// The most triangles one surface ornament may have (about 1 GB of mesh).
constexpr size_t kMaxSurfaceOrnamentTriangles = size_t(1) << 25;

// `maxHeight(point)`: the room above a surface point (world units), or empty for none.
// `maxStretch`: cells stretched more than this are left out; 0 for no limit.
// Throws std::invalid_argument for an empty pattern, symbols the tile set lacks, bad
// ornament options, a maxStretch neither 0 nor at least 1, or more than
// kMaxSurfaceOrnamentTriangles triangles.
// `shownFacelets` (§6.4, different L-systems on selected face-lets): when given, one flag
// per face-let of the map; the others get no ornament (their triangles are left out, their
// vertices stay). `triangleCell`, when given, receives the pattern cell (row-major) of
// every triangle of the result.
rt::Mesh surfaceOrnament(const TileSet& tiles, const AlleleGrid& pattern, const PolycubeMap& map,
                         const std::function<double(const MappedPoint&)>& maxHeight,
                         const OrnamentOptions& options = {}, SurfaceOrnamentStats* stats = nullptr,
                         double maxStretch = 0, const std::vector<char>* shownFacelets = nullptr,
                         std::vector<uint32_t>* triangleCell = nullptr);

// The face-lets whose outward normal is one of `directions` (0 +x, 1 -x, 2 +y, 3 -y, 4 +z,
// 5 -z): one flag per face-let of the map, for surfaceOrnament's shownFacelets.
std::vector<char> faceletsFacing(const PolycubeMap& map, const std::vector<int>& directions);

// The mesh's triangles parted by their cell's class (`cellClass[triangleCell[t]]`, classes
// 0 .. classCount - 1): one mesh per class with only the vertices its triangles use, in
// order, normals and texture coordinates kept. (Colour symmetry, colour_symmetry.h: a class
// a colour.)
std::vector<rt::Mesh> partOrnament(const rt::Mesh& mesh, const std::vector<uint32_t>& triangleCell,
                                   const std::vector<int>& cellClass, int classCount);

}  // namespace fgsg::rt::evolve
