// Coverage measured apart from the generators (#46): a face's share that cells cover,
// sampled on a square grid in the face's plane. A sample is on the face when it lies in
// one of the face's mesh triangles, and covered when the point just above it (1e-4 m
// along the face's normal) lies inside some cell's solid (its prism, less its mitre
// cuts), cells taken whole, their joints included as they are laid. Nothing here reads
// the occupancy maps, so a generator's own bookkeeping cannot vouch for itself.
// Cases: a gable end (the rakes), a hipped roof (the hips), a cross-gabled roof (its two
// valleys) and the brick building's arched door (the spandrels).
#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/base_mesh_pieces.h"
#include "runtime/cells/cellular_texture.h"
#include "runtime/cells/feature_param.h"
#include "runtime/cells/generators.h"
#include "tests/unit/cells/brick_building_tree.h"
#include "tests/unit/cells/house_pieces.h"

#include <catch2/catch.hpp>
#include <fcl/narrowphase/collision.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

namespace {

// Whether world point p lies in cell c (closed, within `tol`): inside its outline in the
// length-height plane, within its depth, and on the inner side of each mitre cut.
bool coverageCellHolds(const Cell& c, const Vec3& p, double tol) {
  const Vec3 q = c.axes.inverse() * (p - c.origin);
  if (q.z() < -tol || q.z() > c.size.z() + tol) return false;
  const Polygon2 o = c.outline();
  for (size_t i = 0; i < o.size(); ++i) {
    const Vec2 a = o[i], b = o[(i + 1) % o.size()];
    const Vec2 d = (b - a).normalized();
    if (d.x() * (q.y() - a.y()) - d.y() * (q.x() - a.x()) < -tol) return false;
  }
  for (const MitreCut& m : c.cuts)
    if (m.normal.dot(p) > m.offset + tol) return false;
  return true;
}

struct CoverageSamples {
  long inside = 0, covered = 0;
  double ratio() const { return inside > 0 ? double(covered) / double(inside) : 0; }
};

// The coverage of planar face f by `cells` within the (u, v) window [lo, hi] of the
// face's frame, sampled every `step` (sample centres).
CoverageSamples rasterCoverage(const surface::SurfaceMesh& mesh, const FeatureFace& face,
                               const std::vector<Cell>& cells, double step, Vec2 lo, Vec2 hi) {
  const Vec3 o = face.origin, u = face.uAxis, v = face.vAxis, n = face.normal;
  auto uv = [&](const Vec3& p) { return Vec2((p - o).dot(u), (p - o).dot(v)); };
  const int nu = int(std::ceil((hi.x() - lo.x()) / step)), nv = int(std::ceil((hi.y() - lo.y()) / step));
  std::vector<uint8_t> inside(size_t(nu) * size_t(nv), 0), covered(inside.size(), 0);
  auto sample = [&](int i, int j) { return Vec2(lo.x() + (i + 0.5) * step, lo.y() + (j + 0.5) * step); };
  auto range = [&](double a, double b, double origin, int count) {
    return std::pair<int, int>{std::max(0, int(std::floor((a - origin) / step - 0.5))),
                               std::min(count - 1, int(std::ceil((b - origin) / step - 0.5)))};
  };
  for (int t : face.triangles) {
    const Vec2 a = uv(mesh.vertices[mesh.faces[t][0]]), b = uv(mesh.vertices[mesh.faces[t][1]]),
               c = uv(mesh.vertices[mesh.faces[t][2]]);
    const Vec2 tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
    const auto [i0, i1] = range(tlo.x(), thi.x(), lo.x(), nu);
    const auto [j0, j1] = range(tlo.y(), thi.y(), lo.y(), nv);
    auto side = [](const Vec2& p, const Vec2& q, const Vec2& r) {
      return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    };
    const double area = side(a, b, c);
    if (std::abs(area) < 1e-15) continue;
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const Vec2 s = sample(i, j);
        const double k0 = side(a, b, s) / area, k1 = side(b, c, s) / area, k2 = side(c, a, s) / area;
        if (k0 >= -1e-12 && k1 >= -1e-12 && k2 >= -1e-12) inside[size_t(i) * size_t(nv) + size_t(j)] = 1;
      }
  }
  const double above = 1e-4;
  for (const Cell& c : cells) {
    double hlo = INFINITY, hhi = -INFINITY;
    Vec2 clo(INFINITY, INFINITY), chi(-INFINITY, -INFINITY);
    for (const Vec3& p : c.vertices()) {
      const double h = (p - o).dot(n);
      hlo = std::min(hlo, h), hhi = std::max(hhi, h);
      clo = clo.cwiseMin(uv(p)), chi = chi.cwiseMax(uv(p));
    }
    if (hlo > above + 1e-9 || hhi < above - 1e-9) continue;  // not in the face's layer
    const auto [i0, i1] = range(clo.x(), chi.x(), lo.x(), nu);
    const auto [j0, j1] = range(clo.y(), chi.y(), lo.y(), nv);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const size_t k = size_t(i) * size_t(nv) + size_t(j);
        if (!inside[k] || covered[k]) continue;
        const Vec2 s = sample(i, j);
        if (coverageCellHolds(c, o + s.x() * u + s.y() * v + above * n, 1e-9)) covered[k] = 1;
      }
  }
  CoverageSamples out;
  for (size_t k = 0; k < inside.size(); ++k) out.inside += inside[k], out.covered += covered[k];
  return out;
}

// ... over the whole face (its triangles' extent in the face's frame).
CoverageSamples rasterCoverage(const surface::SurfaceMesh& mesh, const FeatureFace& face,
                               const std::vector<Cell>& cells, double step) {
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (int t : face.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = mesh.vertices[mesh.faces[t][k]] - face.origin;
      const Vec2 q(d.dot(face.uAxis), d.dot(face.vAxis));
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
  return rasterCoverage(mesh, face, cells, step, lo, hi);
}

// Pairs of output cells (shrunk by a 0.01 joint) that FCL finds in contact, each cell
// as the FCL convex solid of its faces (Cell::solid: a mitred cell less its mitres).
int coverageFclContacts(const std::vector<Cell>& cells) {
  std::vector<fcl::CollisionObjectd> objects;
  std::vector<std::pair<Vec3, Vec3>> bounds;
  for (const Cell& cell : cells) {
    const Cell c = shrunk(cell, 0.01);
    auto v = std::make_shared<std::vector<Vec3>>();
    auto faces = std::make_shared<std::vector<int>>();
    const SolidFaces solid = c.solid();
    for (const std::vector<Vec3>& f : solid) {
      faces->push_back(int(f.size()));
      for (const Vec3& p : f) {
        int k = 0;
        while (k < int(v->size()) && ((*v)[size_t(k)] - p).norm() > 1e-12) ++k;
        if (k == int(v->size())) v->push_back(p);
        faces->push_back(k);
      }
    }
    Vec3 lo = v->front(), hi = v->front();
    for (const Vec3& p : *v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    bounds.emplace_back(lo, hi);
    objects.emplace_back(std::make_shared<fcl::Convexd>(v, int(solid.size()), faces), fcl::Transform3d::Identity());
  }
  int contacts = 0;
  for (size_t i = 0; i < objects.size(); ++i)
    for (size_t j = i + 1; j < objects.size(); ++j) {
      if ((bounds[i].first.array() > bounds[j].second.array()).any() ||
          (bounds[j].first.array() > bounds[i].second.array()).any())
        continue;
      fcl::CollisionRequestd request;
      fcl::CollisionResultd result;
      if (fcl::collide(&objects[i], &objects[j], request, result) > 0) ++contacts;
    }
  return contacts;
}

bool coverageHasLabel(const std::vector<std::string>& labels, const char* l) {
  return std::find(labels.begin(), labels.end(), l) != labels.end();
}

}  // namespace

TEST_CASE("coverage sampled apart from the generator: a gable end's rakes", "[cells][coverage]") {
  // The gable wall of a house 6 m wide, 3 m to the eaves, rakes at 30 degrees; bricks
  // 0.2 x 0.1 (clipped_cells_test.cpp's wall). Boxes only left a wedge (sqrt 3 / 2) h^2 per
  // rake per course: 0.987229 worked by hand.
  const double r3 = std::sqrt(3.0);
  const LabelledMesh lm = fgsg::test::gableWallMesh();
  FeatureOptions options;
  options.up = Vec3::UnitY();
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm, options), Vec3::UnitY());
  for (FeatureRef f : tex.order()) layBricks(tex, f, BrickSize{0.2, 0.1, 0.1});
  const CoverageSamples s = rasterCoverage(lm.mesh, tex.features().faces[0], tex.cells(), 0.01);
  // The samples' own count of the face: 23.196 m^2 at 1e-4 m^2 each, within the outline's
  // sampling error (perimeter 16 m x step / 2).
  CHECK(double(s.inside) * 1e-4 == Approx(18 + 3 * r3).margin(16 * 0.005));
  CHECK(s.ratio() >= 0.99);
  CHECK(s.ratio() > 1 - 1e-6);
}

TEST_CASE("coverage sampled apart from the generator: a hipped roof's tiles", "[cells][coverage]") {
  // The 7 x 4 house under a hipped roof (house_pieces.h, y up); tiles on the roof's
  // faces only, no ridge tiles: each face's rows clipped to its hips.
  const std::vector<LabelledPolygon> pieces = fgsg::test::hippedHousePieces();
  const LabelledMesh lm = labelledMeshFromPolygons(pieces);
  FeatureOptions options;
  options.up = Vec3::UnitY();
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm, options), Vec3::UnitY());
  const FeatureMesh& fm = tex.features();
  for (FeatureRef f : tex.order())
    if (f.kind == FeatureKind::Face && coverageHasLabel(fm.faces[f.index].labels, "roof"))
      layShingles(tex, f, TileSize{0.3, 0.2, 0.03});
  int roofs = 0;
  for (const FeatureFace& face : fm.faces) {
    if (!coverageHasLabel(face.labels, "roof")) continue;
    ++roofs;
    const CoverageSamples s = rasterCoverage(lm.mesh, face, tex.cells(), 0.01);
    CHECK(double(s.inside) * 1e-4 == Approx(face.area).epsilon(0.02));
    CHECK(s.ratio() > 0.9999);
  }
  CHECK(roofs == 4);
}

namespace {

// A cross-gabled roof (z up), 45-degree slopes: a main roof 8 m long (x from -2 to 6),
// its ridge along y = 2 at z = 2, and a wing 4 m wide (x from 0 to 4) running back from it
// to y = 8, its ridge along x = 2. The wing's slopes z = x and z = 4 - x meet the main
// roof's back slope z = 4 - y in two valleys, from the eaves at (0, 4, 0) and (4, 4, 0)
// up to the ridges' meeting point (2, 2, 2). No walls: only the roof's tiles are laid.
LabelledMesh crossGabledRoof() {
  const std::vector<LabelledPolygon> pieces{
      {"front", {Vec3(-2, 0, 0), Vec3(6, 0, 0), Vec3(6, 2, 2), Vec3(-2, 2, 2)}},
      {"back", {Vec3(2, 2, 2), Vec3(6, 2, 2), Vec3(6, 4, 0), Vec3(4, 4, 0)}},
      {"back", {Vec3(-2, 2, 2), Vec3(2, 2, 2), Vec3(0, 4, 0), Vec3(-2, 4, 0)}},
      {"wing", {Vec3(0, 4, 0), Vec3(2, 2, 2), Vec3(2, 8, 2), Vec3(0, 8, 0)}},
      {"wing", {Vec3(4, 4, 0), Vec3(4, 8, 0), Vec3(2, 8, 2), Vec3(2, 2, 2)}}};
  return labelledMeshFromPolygons(pieces);
}

}  // namespace

TEST_CASE("coverage sampled apart from the generator: a cross-gabled roof's valleys", "[cells][coverage][mitre]") {
  const LabelledMesh lm = crossGabledRoof();
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
  const FeatureMesh& fm = tex.features();
  REQUIRE(fm.faces.size() == 5);
  int valleys = 0;
  for (const FeatureEdge& e : fm.edges) valleys += e.fold == EdgeFold::Concave ? 1 : 0;
  REQUIRE(valleys == 2);
  // Tiles on every face, none on the edges: where the two faces' layers of tiles meet
  // over a valley, each face's tiles stop at the plane halfway between the faces.
  for (FeatureRef f : tex.order())
    if (f.kind == FeatureKind::Face) layShingles(tex, f, TileSize{0.3, 0.2, 0.03});
  // The faces' areas by hand, level projections times sqrt 2: the front 8 x 2 = 16, each
  // back piece a trapezoid of 6, each wing slope x from 0 to 2, y from 4 - x to 8: 10;
  // 48 in all (the main roof 8 x 4 and the wing 4 x 4).
  double total = 0;
  for (const FeatureFace& face : fm.faces) total += face.area;
  CHECK(total == Approx(48 * std::sqrt(2.0)).epsilon(1e-12));
  double worst = 1;
  for (const FeatureFace& face : fm.faces) {
    const CoverageSamples s = rasterCoverage(lm.mesh, face, tex.cells(), 0.01);
    INFO("face " << face.labels.front() << " area " << face.area << " coverage " << s.ratio());
    CHECK(double(s.inside) * 1e-4 == Approx(face.area).epsilon(0.02));
    worst = std::min(worst, s.ratio());
  }
  CHECK(worst >= 0.99);
  CHECK(worst > 0.9999);
  // The tiles beside the valleys are mitred: each keeps the side of the plane halving the
  // valley's dihedral angle nearer its own face, so no two touch (FCL, joints 0.01).
  int mitred = 0;
  auto above = [](const FeatureFace& f, const Vec3& p) { return (p - f.origin).dot(f.normal); };
  for (const Cell& c : tex.cells()) {
    if (c.cuts.empty()) continue;
    ++mitred;
    const int own = c.feature.index;
    for (const FeatureEdge& e : fm.edges) {
      if (e.fold != EdgeFold::Concave || (e.leftFace != own && e.rightFace != own)) continue;
      const FeatureFace& mine = fm.faces[size_t(own)];
      const FeatureFace& other = fm.faces[size_t(e.leftFace == own ? e.rightFace : e.leftFace)];
      for (const std::vector<Vec3>& f : c.solid())
        for (const Vec3& p : f) CHECK(above(mine, p) <= above(other, p) + 1e-9);
    }
  }
  CHECK(mitred >= 2 * 14);  // both sides of both valleys, a row every 0.2 m up 2.83 m
  CHECK(coverageFclContacts(tex.cells()) == 0);
}

TEST_CASE("coverage sampled apart from the generator: the brick building's arch spandrels", "[cells][coverage][arch]") {
  // clipped_cells_test.cpp's region: x in [2.1, 3.9] on the front wall (y = 0), from the
  // springing line z = 2.025 to 0.3 m above the crown; the door's opening is not face.
  const LabelledMesh lm = readBaseMeshObj(FGSG_SOURCE_DIR "/examples/assets/brick_building.obj");
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
  const FeatureMesh& fm = tex.features();
  fgsg::test::layBrickBuilding(tex);
  int front = -1;
  for (size_t i = 0; i < fm.faces.size(); ++i)
    if (coverageHasLabel(fm.faces[i].labels, "wall") && fm.faces[i].normal.dot(Vec3(0, -1, 0)) > 0.99) front = int(i);
  REQUIRE(front >= 0);
  const FeatureFace& face = fm.faces[size_t(front)];
  const Vec2 a = projectOnFace(face, Vec3(2.1, 0, 2.025)), b = projectOnFace(face, Vec3(3.9, 0, 2.925));
  const CoverageSamples s = rasterCoverage(lm.mesh, face, tex.cells(), 0.004, a.cwiseMin(b), a.cwiseMax(b));
  // The wall there: 1.8 x 0.9 less the 12-gon half circle of radius 0.6, 1.060951 m^2.
  CHECK(double(s.inside) * 0.004 * 0.004 == Approx(1.060951).margin(0.01));
  CHECK(s.ratio() > 0.9999);
}
