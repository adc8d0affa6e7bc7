// setPivot(axisMap, cornerIndex) (CityEngine's op_setPivot): the shape's pivot put at a
// corner of its scope, its axes the scope's axes in the order axisMap names, turned so that
// all point into the scope; the scope becomes the pivot's frame around the same box and the
// geometry stays where it is in the world (docs/cga.md).
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <algorithm>
#include <utility>

namespace fgsg::rt::cga {
namespace {

// The scope axis each pivot axis (x, y, z) lies along at corner 0, per axisMap: xyz keeps
// them; yzx: x along the scope's z, y along its x, z along its y; zxy: x along y, y along
// z, z along x (the reference's cyclic orders).
constexpr int kPivotAxisOrder[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};

// Corner k of the scope's unit box: 0..3 around the bottom (y = 0) from the origin, along
// x first (0 (0,0,0), 1 (1,0,0), 2 (1,0,1), 3 (0,0,1)); 4..7 the same corners on top (y = 1).
constexpr int kPivotCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1},
                                    {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};

}  // namespace

bool setPivot(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int axisMap, int corner, Part& out,
              Scope& pivot, std::string& error) {
  if (axisMap < 0 || axisMap > 2 || corner < 0 || corner > 7) {
    error = "setPivot: the axis order is xyz, yzx or zxy and the corner index a whole number from 0 to 7";
    return false;
  }
  if (geom.kind == GeomKind::Edge) {
    error = "setPivot: expects a face or a solid, not an edge";
    return false;
  }
  const int* at = kPivotCorner[corner];
  // Each scope axis points into the box from the corner reversed where the corner lies at
  // its far end.
  double inward[3];
  for (int k = 0; k < 3; ++k) inward[k] = at[k] ? -1.0 : 1.0;
  // The pivot's axes: y along (plus or minus) the scope axis the order makes y; x and z the
  // other two, inward, swapped where that is what keeps the frame right-handed (the
  // reference's pictures: at every corner but 0 the y axis keeps its line).
  int along[3] = {kPivotAxisOrder[axisMap][0], kPivotAxisOrder[axisMap][1], kPivotAxisOrder[axisMap][2]};
  Mat3 axes;
  for (int i = 0; i < 3; ++i) axes.col(i) = inward[along[i]] * scope.axes.col(along[i]);
  if (axes.determinant() < 0) {
    std::swap(along[0], along[2]);
    axes.col(0) = inward[along[0]] * scope.axes.col(along[0]);
    axes.col(2) = inward[along[2]] * scope.axes.col(along[2]);
  }
  pivot = scope;
  pivot.P = scope.P + scope.axes * scope.S.cwiseProduct(Vec3(at[0], at[1], at[2]));
  pivot.axes = axes;
  out = Part{scope, geom, false, 0};
  out.scope.P = pivot.P;
  out.scope.axes = axes;
  for (int i = 0; i < 3; ++i) out.scope.S[i] = scope.S[along[i]];
  if (geom.kind == GeomKind::Box) return true;  // the same box: still the scope box
  // The geometry's unit-box coordinates in the new scope: each new coordinate is the old
  // one along the same line, counted from the other end where the axis was reversed (0 on
  // an axis without size, as everywhere).
  LocalGeometry local = loadGeometry(arena, geom);
  for (Polygon3& face : local.faces) {
    for (Vec3& u : face) {
      const Vec3 old = u;
      for (int i = 0; i < 3; ++i)
        u[i] = out.scope.S[i] > 0 ? (inward[along[i]] > 0 ? old[along[i]] : 1.0 - old[along[i]]) : 0.0;
    }
    // Faces are stored counter-clockwise in the scope's own axes; from a mirrored scope
    // (mirrorScope) to the right-handed pivot frame that order turns over.
    if (scope.axes.determinant() < 0) std::reverse(face.begin(), face.end());
  }
  // fgsg's polygon lies in its scope's XY plane facing +Z: it stays one while the new z is
  // the old one; else it is a one-face mesh (as a `.cga` lot is).
  if (local.kind == GeomKind::Polygon && !(along[2] == 2 && inward[2] > 0))
    local.kind = GeomKind::Polyhedron;
  out.geom = storeGeometry(arena, local);
  return true;
}

}  // namespace fgsg::rt::cga
