#include "runtime/atlas/chart_flattening.h"

#include "runtime/atlas/bounding_rectangle.h"
#include "runtime/atlas/chart_injectivity.h"
#include "runtime/atlas/chart_parametrization.h"
#include "runtime/atlas/uv_geometry.h"

#include <Eigen/Geometry>

#include <cmath>

namespace fgsg::rt::atlas {

namespace {

// A triangle whose flat area is below this fraction of its surface area (once the chart
// has equal area overall) has collapsed: as good as folded, and no texel would show it.
constexpr double kCollapsedAreaRatio = 1e-6;

}  // namespace

bool flattenChart(const surface::SurfaceMesh& mesh, const ChartMesh& chart, FlatChart& out) {
  std::vector<Vec2> uv;
  if (!parametrizeConformal(mesh, chart, uv)) return false;
  const size_t n = chart.triangles.size();
  auto flatTwiceArea = [&](size_t i) {
    const auto& t = chart.triangles[i];
    return twiceSignedArea(uv[t[0]], uv[t[1]], uv[t[2]]);
  };
  double flatArea = 0, surfaceArea = 0;
  for (size_t i = 0; i < n; ++i) {
    flatArea += 0.5 * flatTwiceArea(i);
    surfaceArea += mesh.faceAreas[chart.faces[i]];
  }
  if (!(std::abs(flatArea) > 0) || !(surfaceArea > 0)) return false;
  // Mirrored as a whole: turn it over (u -> -u) so it runs like the surface.
  if (flatArea < 0) {
    for (Vec2& p : uv) p.x() = -p.x();
    flatArea = -flatArea;
  }
  // Equal area: flat area per surface area is 1 in every chart.
  const double scale = std::sqrt(surfaceArea / flatArea);
  for (Vec2& p : uv) p *= scale;
  for (size_t i = 0; i < n; ++i)
    if (!(0.5 * flatTwiceArea(i) > kCollapsedAreaRatio * mesh.faceAreas[chart.faces[i]])) return false;
  if (!layoutIsInjective(chart, uv)) return false;

  // Turned to its smallest rectangle (that of the boundary, or of the lone triangle),
  // which the packer then aligns with the axes.
  std::vector<Vec2> outline;
  for (const auto& e : chart.boundaryEdges) outline.push_back(uv[e[0]]);
  const Eigen::Matrix2d turn = Eigen::Rotation2Dd(minimalRectangleAngle(outline)).toRotationMatrix();
  for (Vec2& p : uv) p = turn * p;
  out.faces = chart.faces;
  out.corners.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) out.corners[i][k] = uv[chart.triangles[i][k]];
  return true;
}

}  // namespace fgsg::rt::atlas
