// Corners that are not square (#46): bricks up the convex vertical edges of a hexagonal
// tower (faces 120 degrees apart inside) and of a wedge (60 degrees), where the two walls'
// layers of bricks meet outside the edge. Each course's bricks are mitred outwards: a
// brick of either wall runs to the plane through the edge that halves the dihedral angle,
// so the two meet on it with no gap and no overlap, and no brick stands out of its
// wall's layer. Everything here is measured from the cells' solids (Cell::solid), not
// from the occupancy maps: coverage of each wall sampled 1e-4 m above it, coverage of the
// kite outside each edge where both layers' outer faces meet (area d^2 tan(phi / 2), phi
// the angle between the walls' normals, worked by hand below), and the volume every two
// cells share (joints included, as laid), computed by clipping one solid by the other's
// face planes.
#include "runtime/cells/base_mesh_file.h"
#include "runtime/cells/base_mesh_pieces.h"
#include "runtime/cells/cellular_texture.h"
#include "runtime/cells/generators.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;

namespace {

// An upright prism over the convex polygon `footprint` (counter-clockwise from above),
// `height` high, z up: its walls labelled "wall", its top "top", open at the bottom.
LabelledMesh mitreCornerPrism(const std::vector<Vec2>& footprint, double height) {
  std::vector<LabelledPolygon> pieces;
  const size_t n = footprint.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = footprint[k], b = footprint[(k + 1) % n];
    pieces.push_back({"wall", {Vec3(a.x(), a.y(), 0), Vec3(b.x(), b.y(), 0), Vec3(b.x(), b.y(), height),
                               Vec3(a.x(), a.y(), height)}});
  }
  LabelledPolygon top{"top", {}};
  for (const Vec2& p : footprint) top.points.push_back(Vec3(p.x(), p.y(), height));
  pieces.push_back(top);
  return labelledMeshFromPolygons(pieces);
}

std::vector<Vec2> mitreCornerRegularPolygon(int sides, double circumradius) {
  std::vector<Vec2> p;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    p.push_back(circumradius * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

// Whether p lies in the convex solid (its face planes, within tol).
bool mitreCornerInside(const SolidFaces& s, const Vec3& p, double tol) {
  for (const std::vector<Vec3>& f : s) {
    Vec3 n = Vec3::Zero();
    for (size_t i = 0; i < f.size(); ++i) n += f[i].cross(f[(i + 1) % f.size()]);
    if (n.norm() < 1e-15) continue;
    if (n.normalized().dot(p - f[0]) > tol) return false;
  }
  return true;
}

bool mitreCornerCovered(const std::vector<SolidFaces>& solids, const Vec3& p) {
  for (const SolidFaces& s : solids)
    if (mitreCornerInside(s, p, 1e-9)) return true;
  return false;
}

double mitreCornerVolume(const SolidFaces& s) {
  if (s.empty()) return 0;
  Vec3 c = Vec3::Zero();
  int count = 0;
  for (const auto& f : s)
    for (const Vec3& p : f) c += p, ++count;
  c /= count;
  double v = 0;
  for (const auto& f : s)
    for (size_t i = 1; i + 1 < f.size(); ++i) v += (f[0] - c).dot((f[i] - c).cross(f[i + 1] - c)) / 6;
  return v;
}

// The largest volume two cells share: one's solid clipped by every face plane of the other.
double mitreCornerWorstOverlap(const std::vector<SolidFaces>& solids) {
  std::vector<std::pair<Vec3, Vec3>> box;
  for (const SolidFaces& s : solids) {
    Vec3 lo = s[0][0], hi = s[0][0];
    for (const auto& f : s)
      for (const Vec3& p : f) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    box.emplace_back(lo, hi);
  }
  double worst = 0;
  for (size_t i = 0; i < solids.size(); ++i)
    for (size_t j = i + 1; j < solids.size(); ++j) {
      if ((box[i].first.array() >= box[j].second.array()).any() || (box[j].first.array() >= box[i].second.array()).any())
        continue;
      SolidFaces s = solids[i];
      for (const auto& f : solids[j]) {
        Vec3 n = Vec3::Zero();
        for (size_t k = 0; k < f.size(); ++k) n += f[k].cross(f[(k + 1) % f.size()]);
        n.normalize();
        s = clipSolid(s, n, n.dot(f[0]), 1e-12);
        if (s.empty()) break;
      }
      worst = std::max(worst, mitreCornerVolume(s));
    }
  return worst;
}

struct MitreCornerFigures {
  double wallCoverage = 1;  // the worst wall's
  double kiteCoverage = 1;  // the worst edge's, all courses
  double kiteArea = 0;      // sampled, per unit height, the first edge's
  double standOut = 0;      // how far the farthest edge-cell corner lies outside its layers
  double overlap = 0;       // the largest volume two cells share
  int mitred = 0;           // edge cells with a mitre
  int edgeCells = 0;
  double ringCoverage = 1;  // of the rim's layer round the top (`rim` only)
  double ringArea = 0;      // sampled
};

// Bricks (0.2 x 0.1, 0.1 deep) on the prism's walls and vertical edges, and with `rim` on
// the edges round its top; the figures above.
MitreCornerFigures mitreCornerLay(const LabelledMesh& lm, double height, bool rim = false) {
  const double d = 0.1;
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
  const FeatureMesh& fm = tex.features();
  auto isWall = [&](int f) { return f >= 0 && fm.faces[size_t(f)].labels.front() == "wall"; };
  for (FeatureRef f : tex.order()) {
    if (f.kind == FeatureKind::Edge) {
      const FeatureEdge& e = fm.edges[size_t(f.index)];
      if ((isWall(e.leftFace) || rim) && (isWall(e.rightFace) || rim)) layBricks(tex, f, BrickSize{0.2, 0.1, d});
    } else if (f.kind == FeatureKind::Face && isWall(f.index)) {
      layBricks(tex, f, BrickSize{0.2, 0.1, d});
    }
  }
  std::vector<SolidFaces> solids;
  for (const Cell& c : tex.cells()) solids.push_back(c.solid());
  MitreCornerFigures out;
  // Each wall sampled every 1 cm at 1e-4 m above it (a rectangle: its triangles' box).
  for (size_t fi = 0; fi < fm.faces.size(); ++fi) {
    const FeatureFace& face = fm.faces[fi];
    if (!isWall(int(fi))) continue;
    Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (int t : face.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3 q = lm.mesh.vertices[size_t(lm.mesh.faces[size_t(t)][k])] - face.origin;
        lo = lo.cwiseMin(Vec2(q.dot(face.uAxis), q.dot(face.vAxis)));
        hi = hi.cwiseMax(Vec2(q.dot(face.uAxis), q.dot(face.vAxis)));
      }
    long inside = 0, covered = 0;
    for (double u = lo.x() + 0.005; u < hi.x(); u += 0.01)
      for (double v = lo.y() + 0.005; v < hi.y(); v += 0.01) {
        ++inside;
        covered += mitreCornerCovered(solids, face.origin + u * face.uAxis + v * face.vAxis + 1e-4 * face.normal);
      }
    out.wallCoverage = std::min(out.wallCoverage, double(covered) / double(inside));
  }
  // The kite outside each vertical edge: p (from the edge) with a . p <= 0 and n . p <= d
  // for both walls (a: into the wall, n: its normal), sampled every 2 mm across it at the
  // middle of every course.
  bool first = true;
  for (const FeatureEdge& e : fm.edges) {
    if (!isWall(e.leftFace) || !isWall(e.rightFace)) continue;
    const Vec3 o = e.points.front(), t = (e.points.back() - o).normalized();
    Vec3 n[2], a[2];
    for (int s = 0; s < 2; ++s) {
      const FeatureFace& f = fm.faces[size_t(s == 0 ? e.leftFace : e.rightFace)];
      n[s] = f.normal;
      Vec3 centre = Vec3::Zero();  // of its triangles' corners
      for (int tri : f.triangles)
        for (int k = 0; k < 3; ++k) centre += lm.mesh.vertices[size_t(lm.mesh.faces[size_t(tri)][k])] / (3.0 * double(f.triangles.size()));
      a[s] = (centre - o) - (centre - o).dot(t) * t - (centre - o).dot(n[s]) * n[s];
      a[s].normalize();
    }
    const Vec3 x = (n[0] + n[1]).normalized(), y = t.cross(x);
    const double reach = d / std::cos(0.5 * std::acos(n[0].dot(n[1]))) + 0.01, step = 0.002;
    long inside = 0, covered = 0;
    for (double z = 0.05; z < height; z += 0.1)
      for (double px = step / 2; px < reach; px += step)
        for (double py = -reach + step / 2; py < reach; py += step) {
          const Vec3 p = px * x + py * y;
          if (a[0].dot(p) > 0 || a[1].dot(p) > 0 || n[0].dot(p) > d || n[1].dot(p) > d) continue;
          ++inside;
          covered += mitreCornerCovered(solids, o + z * t + p);
        }
    if (first) out.kiteArea = double(inside) * step * step / std::round(height / 0.1);
    first = false;
    out.kiteCoverage = std::min(out.kiteCoverage, double(covered) / double(inside));
  }
  for (const Cell& c : tex.cells()) {
    if (c.feature.kind != FeatureKind::Edge) continue;
    ++out.edgeCells;
    out.mitred += c.cuts.empty() ? 0 : 1;
    const FeatureEdge& e = fm.edges[size_t(c.feature.index)];
    for (const auto& f : c.solid())
      for (const Vec3& p : f)
        for (int s : {e.leftFace, e.rightFace}) {
          const FeatureFace& face = fm.faces[size_t(s)];
          out.standOut = std::max(out.standOut, (p - face.origin).dot(face.normal) - d);
        }
  }
  out.overlap = mitreCornerWorstOverlap(solids);
  if (rim) {
    // The rim's layer: at half its height above the top, the points outside the walls by
    // at most d (the walls' layers grown up past the top, meeting on the mitres).
    const double step = 0.002, z = height + 0.5 * d;
    Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (const Vec3& p : lm.mesh.vertices) lo = lo.cwiseMin(p.head<2>()), hi = hi.cwiseMax(p.head<2>());
    long inside = 0, covered = 0;
    for (double x = lo.x() - 3 * d; x < hi.x() + 3 * d; x += step)
      for (double y = lo.y() - 3 * d; y < hi.y() + 3 * d; y += step) {
        const Vec3 p(x, y, z);
        double out = -INFINITY;
        for (size_t fi = 0; fi < fm.faces.size(); ++fi)
          if (isWall(int(fi))) out = std::max(out, (p - fm.faces[fi].origin).dot(fm.faces[fi].normal));
        if (out <= 0 || out > d) continue;
        ++inside;
        covered += mitreCornerCovered(solids, p);
      }
    out.ringArea = double(inside) * step * step;
    out.ringCoverage = double(covered) / double(inside);
  }
  return out;
}

// Each mitre of an edge cell halves the dihedral angle of its edge: unit, square to the
// edge, and the two walls' normals mirror images in it (m . nA = -m . nB), to 1e-9.
void mitreCornerCheckBisects(const CellularTexture& tex) {
  const FeatureMesh& fm = tex.features();
  for (const Cell& c : tex.cells()) {
    if (c.feature.kind != FeatureKind::Edge) continue;
    const FeatureEdge& e = fm.edges[size_t(c.feature.index)];
    if (fm.faces[size_t(e.leftFace)].labels.front() != "wall" || fm.faces[size_t(e.rightFace)].labels.front() != "wall")
      continue;  // not a corner between two walls
    const Vec3 t = (e.points.back() - e.points.front()).normalized();
    const Vec3 na = fm.faces[size_t(e.leftFace)].normal, nb = fm.faces[size_t(e.rightFace)].normal;
    for (const MitreCut& m : c.cuts) {
      CHECK(std::abs(m.normal.norm() - 1) < 1e-9);
      CHECK(std::abs(m.normal.dot(t)) < 1e-9);
      CHECK(std::abs(m.normal.dot(na) + m.normal.dot(nb)) < 1e-9);
      CHECK(std::abs(m.normal.dot(e.points.front()) - m.offset) < 1e-9);  // through the edge
    }
  }
}

}  // namespace

TEST_CASE("mitred corners: a hexagonal tower's bricks meet on the mitre planes", "[cells][mitre][corner]") {
  // Side 1, 1.2 high: 12 courses. The walls' normals 60 degrees apart: the kite outside an
  // edge is two right triangles with legs d and d tan 30: d^2 tan 30 = 0.0057735 m^2.
  const LabelledMesh lm = mitreCornerPrism(mitreCornerRegularPolygon(6, 1.0), 1.2);
  const MitreCornerFigures m = mitreCornerLay(lm, 1.2);
  INFO("walls " << m.wallCoverage << " kites " << m.kiteCoverage << " stand out " << m.standOut << " overlap "
                << m.overlap << " mitred " << m.mitred << " of " << m.edgeCells);
  CHECK(m.kiteArea == Approx(0.01 * std::tan(std::numbers::pi / 6)).epsilon(0.03));
  CHECK(m.wallCoverage >= 0.99);
  CHECK(m.wallCoverage > 0.9999);
  CHECK(m.kiteCoverage > 0.999);
  CHECK(m.standOut < 1e-9);
  CHECK(m.overlap < 1e-12);
  CHECK(m.mitred == 6 * 12 * 2);  // both walls at every edge in every course
  CHECK(m.edgeCells == m.mitred);
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
  for (FeatureRef f : tex.order())
    if (f.kind == FeatureKind::Edge) layBricks(tex, f, BrickSize{0.2, 0.1, 0.1});
  mitreCornerCheckBisects(tex);
}

TEST_CASE("mitred corners: a 60-degree wedge's bricks meet on the mitre planes", "[cells][mitre][corner]") {
  // An equilateral prism, side 2, 1.2 high: every vertical edge 60 degrees inside, the
  // normals 120 degrees apart; the kite d^2 tan 60 = 0.017321 m^2 reaching d / cos 60 =
  // 2d from the edge.
  const LabelledMesh lm = mitreCornerPrism({Vec2(0, 0), Vec2(2, 0), Vec2(1, std::sqrt(3.0))}, 1.2);
  const MitreCornerFigures m = mitreCornerLay(lm, 1.2);
  INFO("walls " << m.wallCoverage << " kites " << m.kiteCoverage << " stand out " << m.standOut << " overlap "
                << m.overlap << " mitred " << m.mitred << " of " << m.edgeCells);
  CHECK(m.kiteArea == Approx(0.01 * std::tan(std::numbers::pi / 3)).epsilon(0.03));
  CHECK(m.wallCoverage >= 0.99);
  CHECK(m.wallCoverage > 0.9999);
  CHECK(m.kiteCoverage > 0.999);
  CHECK(m.standOut < 1e-9);
  CHECK(m.overlap < 1e-12);
  CHECK(m.mitred == 3 * 12 * 2);
  CHECK(m.edgeCells == m.mitred);
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
  for (FeatureRef f : tex.order())
    if (f.kind == FeatureKind::Edge) layBricks(tex, f, BrickSize{0.2, 0.1, 0.1});
  mitreCornerCheckBisects(tex);
}

TEST_CASE("mitred corners: a hexagonal tower's top rim runs on to the mitres at its corners", "[cells][mitre][corner]") {
  // Bricks on the edges round the top too: each rim edge's row reaches past the corner to
  // the plane halving the two walls' angle, so the rim's layer (the hexagon grown by d, less
  // the hexagon: perimeter x d + 6 d^2 tan 30 = 0.6 + 0.034641 = 0.634641 m^2) is all covered;
  // rows ending square at the corners would leave the six kites of d^2 tan 30 bare (5.5 %).
  const LabelledMesh lm = mitreCornerPrism(mitreCornerRegularPolygon(6, 1.0), 1.2);
  const MitreCornerFigures m = mitreCornerLay(lm, 1.2, true);
  INFO("ring " << m.ringCoverage << " area " << m.ringArea << " walls " << m.wallCoverage << " kites "
               << m.kiteCoverage << " stand out " << m.standOut << " overlap " << m.overlap);
  CHECK(m.ringArea == Approx(0.6 + 0.06 * std::tan(std::numbers::pi / 6)).epsilon(0.01));
  CHECK(m.ringCoverage > 0.999);
  CHECK(m.wallCoverage > 0.9999);
  CHECK(m.kiteCoverage > 0.999);
  CHECK(m.standOut < 1e-9);
  CHECK(m.overlap < 1e-12);
  // The rim's mitres: plumb planes through a top corner, halving its two walls' angle.
  CellularTexture tex(lm.mesh, buildLabelledFeatureMesh(lm));
  const FeatureMesh& fm = tex.features();
  for (FeatureRef f : tex.order())
    if (f.kind == FeatureKind::Edge) layBricks(tex, f, BrickSize{0.2, 0.1, 0.1});
  int rimMitres = 0;
  for (const Cell& c : tex.cells()) {
    const FeatureEdge& e = fm.edges[size_t(c.feature.index)];
    if (std::abs(e.points.front().z() - 1.2) > 1e-12 || std::abs(e.points.back().z() - 1.2) > 1e-12) continue;
    for (const MitreCut& cut : c.cuts) {
      ++rimMitres;
      CHECK(std::abs(cut.normal.z()) < 1e-9);
      double bisects = INFINITY;  // |m x (nA - nB)| / |nA - nB| for the nearest pair of walls
      for (const FeatureFace& a : fm.faces)
        for (const FeatureFace& b : fm.faces)
          if (a.labels.front() == "wall" && b.labels.front() == "wall" && a.normal.dot(b.normal) > 0.4 &&
              a.normal.dot(b.normal) < 0.6)
            bisects = std::min(bisects, cut.normal.cross(a.normal - b.normal).norm() / (a.normal - b.normal).norm());
      CHECK(bisects < 1e-9);
      const double r = cut.offset;  // through a corner: the plane's distance from the axis is 0
      CHECK(std::abs(r) < 1e-9);
    }
  }
  CHECK(rimMitres == 2 * 6);  // both ends of every rim edge's row
}
