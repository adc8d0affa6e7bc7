// atlasFromTextureUV: the file's own layout, validated and re-packed. Painted textures
// are sampled with the file's coordinates and marching turns directions between charts
// as they lie, so the charts are only scaled (one factor for all) and moved.
#include "runtime/atlas/atlas.h"

#include "runtime/atlas/chart_packing.h"
#include "runtime/atlas/uv_geometry.h"
#include "runtime/atlas/uv_overlap.h"
#include "runtime/surface/load_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace fgsg::rt::atlas {

namespace {

// Overlaps shallower than this fraction of the layout's size are the rounding of
// coordinates stored as floats where two charts touch, not reuse of the same texels.
constexpr double kOverlapTolerance = 1e-6;
// Texture coordinates repeat a texture a few times at most; far beyond that they are
// garbage, and their extent would overflow the overlap search.
constexpr double kMaxCoordinate = 1e9;

std::string fmt(const Vec2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%g, %g)", p.x(), p.y());
  return buf;
}

// "faces 3, 17 and 20" (at most kMaxListedProblems, then "and N more").
std::string faceList(const std::vector<int>& faces) {
  std::string s = faces.size() == 1 ? "face " : "faces ";
  const size_t shown = std::min(faces.size(), surface::kMaxListedProblems);
  for (size_t i = 0; i < shown; ++i) {
    if (i > 0) s += i + 1 == shown && shown == faces.size() ? " and " : ", ";
    s += std::to_string(faces[i]);
  }
  if (shown < faces.size()) s += " and " + std::to_string(faces.size() - shown) + " more";
  return s;
}

struct Charts {
  int count = 0;
  std::vector<int> faceChart;
};

// Faces joined across an edge whose two ends have the same coordinates on both sides.
Charts textureCharts(const surface::SurfaceMesh& mesh) {
  const int nf = int(mesh.faces.size());
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.neighbours[f][k];
      if (g < f) continue;  // each edge once; -1: boundary
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      const int ga = mesh.cornerOf(g, a), gb = mesh.cornerOf(g, b);
      if (mesh.textureUV[f][k] == mesh.textureUV[g][ga] &&
          mesh.textureUV[f][(k + 1) % 3] == mesh.textureUV[g][gb]) {
        const int ra = find(f), rb = find(g);
        parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
  Charts charts;
  charts.faceChart.assign(nf, -1);
  for (int f = 0; f < nf; ++f) {  // numbered by their lowest face
    const int root = find(f);
    if (charts.faceChart[root] < 0) charts.faceChart[root] = charts.count++;
    charts.faceChart[f] = charts.faceChart[root];
  }
  return charts;
}

}  // namespace

bool atlasFromTextureUV(const surface::SurfaceMesh& mesh, const AtlasOptions& options, Atlas& out,
                        std::string& error) {
  out = Atlas{};
  if (!checkAtlasOptions(options, error)) return false;
  const size_t nf = mesh.faces.size();
  if (nf == 0) {
    error = "texture coordinates: the surface has no faces";
    return false;
  }
  if (mesh.textureUV.size() != nf) {
    error = mesh.textureUV.empty()
                ? "texture coordinates: the surface has none"
                : "texture coordinates: " + std::to_string(mesh.textureUV.size()) + " faces have them, but the surface has " +
                      std::to_string(nf);
    return false;
  }
  if (mesh.neighbours.size() != nf) {
    error = "texture coordinates: the surface's topology is not built (SurfaceMesh::buildTopology)";
    return false;
  }

  // Each check names the faces; later checks rely on the earlier ones passing.
  std::vector<int> bad;
  auto unusable = [](const Vec2& p) { return !p.allFinite() || p.cwiseAbs().maxCoeff() > kMaxCoordinate; };
  for (size_t f = 0; f < nf; ++f)
    if (std::any_of(mesh.textureUV[f].begin(), mesh.textureUV[f].end(), unusable)) bad.push_back(int(f));
  if (!bad.empty()) {
    error = "texture coordinates are not finite numbers (or beyond +-1e9) at " + faceList(bad) +
            " (first: " + fmt(*std::find_if(mesh.textureUV[bad[0]].begin(), mesh.textureUV[bad[0]].end(), unusable)) +
            ")";
    return false;
  }
  // Degenerate: as for surface faces, height under a tiny fraction of the longest edge.
  for (size_t f = 0; f < nf; ++f) {
    const auto& t = mesh.textureUV[f];
    const double longest = std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[1]).squaredNorm(),
                                     (t[0] - t[2]).squaredNorm()});
    if (!(std::abs(twiceSignedArea(t)) > surface::kDegenerateFaceTolerance * longest))
      bad.push_back(int(f));
  }
  if (!bad.empty()) {
    error = "texture coordinates are degenerate (a triangle without area in UV space) at " +
            faceList(bad) + ": the surface there cannot be told apart in a texture";
    return false;
  }

  const Charts charts = textureCharts(mesh);
  // Orientation: a chart runs the way most of its area runs; faces against it are mirrored,
  // and so is a chart running clockwise, where the surface's faces run counter-clockwise.
  std::vector<double> positive(charts.count, 0), negative(charts.count, 0);
  for (size_t f = 0; f < nf; ++f) {
    const double a = twiceSignedArea(mesh.textureUV[f]);
    (a > 0 ? positive : negative)[charts.faceChart[f]] += std::abs(a);
  }
  std::vector<int> mirroredCharts;  // by their lowest face
  std::vector<uint8_t> listed(charts.count, 0);
  for (size_t f = 0; f < nf; ++f) {
    const int c = charts.faceChart[f];
    const bool clockwise = twiceSignedArea(mesh.textureUV[f]) < 0;
    const bool chartClockwise = negative[c] > positive[c];
    if (clockwise != chartClockwise) bad.push_back(int(f));
    if (chartClockwise && !listed[c]) {
      listed[c] = 1;
      mirroredCharts.push_back(int(f));
    }
  }
  if (!bad.empty()) {
    error = "texture coordinates are mirrored at " + faceList(bad) +
            ": each runs against the rest of its chart (a flipped triangle in UV space)";
    return false;
  }
  if (!mirroredCharts.empty()) {
    error = "texture coordinates are mirrored: " + std::to_string(mirroredCharts.size()) + " of " +
            std::to_string(charts.count) + " charts run clockwise in UV space (the charts of " +
            faceList(mirroredCharts) +
            "); marching cannot turn directions across a mirrored chart, so mirror the UV "
            "layout (or the faces) in a modelling tool";
    return false;
  }

  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (const auto& t : mesh.textureUV)
    for (const Vec2& p : t) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const UVOverlap overlap = findUVOverlap(mesh.textureUV, kOverlapTolerance * (hi - lo).maxCoeff());
  if (overlap.found()) {
    error = "texture coordinates overlap: faces " + std::to_string(overlap.first) + " and " +
            std::to_string(overlap.second) + " cover the same place in UV space (near " +
            fmt(overlap.where) + ")";
    return false;
  }

  std::vector<FlatChart> flat(charts.count);
  for (size_t f = 0; f < nf; ++f) {
    FlatChart& c = flat[charts.faceChart[f]];
    c.faces.push_back(int(f));
    c.corners.push_back(mesh.textureUV[f]);
  }
  return packCharts(flat, nf, options, /*allowRotation=*/false, out, error);
}

}  // namespace fgsg::rt::atlas
