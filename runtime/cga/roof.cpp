// Roof: a hipped, gable or pyramid roof solid on a rectangle.
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

constexpr double kPi = 3.14159265358979323846;

enum class RoofKind { Hipped, Gable, Pyramid };

bool parseKind(const std::string& s, RoofKind& kind) {
  if (s == "hipped")
    kind = RoofKind::Hipped;
  else if (s == "gable")
    kind = RoofKind::Gable;
  else if (s == "pyramid")
    kind = RoofKind::Pyramid;
  else
    return false;
  return true;
}

// The roof in scope units on the w x d rectangle (x along X, z along Z), height h. Every
// eave corner rises to one ridge end; a side face is an eave, the two ridge ends its corners
// rise to, and collapses to a triangle where both rise to the same end. Faces: front (+Z),
// right (+X), back (-Z), left (-X), bottom: the order of a box's faces.
std::vector<Polygon3> roofFaces(RoofKind kind, double w, double d, double h) {
  const Vec3 c[4] = {{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}};
  Vec3 ridge[4];  // the ridge end each corner rises to
  const bool alongX = w >= d;
  if (kind == RoofKind::Pyramid) {
    for (Vec3& r : ridge) r = Vec3(w / 2, h, d / 2);
  } else if (alongX) {
    // Hipped: the ridge stops d/2 before each end, where the hips meet; gable: it runs
    // the whole length.
    const double inset = kind == RoofKind::Hipped ? d / 2 : 0.0;
    ridge[0] = ridge[3] = Vec3(inset, h, d / 2);
    ridge[1] = ridge[2] = Vec3(w - inset, h, d / 2);
  } else {
    const double inset = kind == RoofKind::Hipped ? w / 2 : 0.0;
    ridge[0] = ridge[1] = Vec3(w / 2, h, inset);
    ridge[2] = ridge[3] = Vec3(w / 2, h, d - inset);
  }
  std::vector<Polygon3> faces;
  const int eaves[4][2] = {{3, 2}, {2, 1}, {1, 0}, {0, 3}};  // front, right, back, left
  for (const auto& e : eaves) {
    Polygon3 f = {c[e[0]], c[e[1]], ridge[e[1]]};
    if (!ridge[e[0]].isApprox(ridge[e[1]])) f.push_back(ridge[e[0]]);
    faces.push_back(std::move(f));
  }
  faces.push_back({c[0], c[1], c[2], c[3]});  // bottom
  return faces;
}

}  // namespace

// The rectangle is the scope's XZ rectangle for a box or a polyhedron (the scope's Y size
// is ignored: the roof stands on the scope's base) and, for a polygon, the polygon
// scope's XY rectangle with the roof rising along its normal (solidFrameOnPolygon). The
// slopes over the longer sides are at `angleDeg`, so h = (shorter side / 2) * tan(angle)
// for every kind; the hips of a hipped roof and the faces of a pyramid on a non-square
// rectangle follow from that height.
bool roof(const Scope& scope, const GeomRef& geom, const std::string& kindName, double angleDeg,
          GeometryArena& arena, Part& out, std::string& error) {
  RoofKind kind;
  if (!parseKind(kindName, kind)) {
    error = "Roof: unknown kind \"" + kindName + "\" (expected hipped, gable or pyramid)";
    return false;
  }
  if (!(angleDeg > 0.0 && angleDeg < 90.0)) {
    std::ostringstream m;
    m << "Roof: the angle " << angleDeg << " must lie strictly between 0 and 90 degrees";
    error = m.str();
    return false;
  }
  if (geom.kind == GeomKind::Edge) {
    error = "Roof: expects a footprint or a mass model, got an edge";
    return false;
  }
  out = Part{};
  out.scope = geom.kind == GeomKind::Polygon ? solidFrameOnPolygon(scope) : scope;
  const double w = out.scope.S.x(), d = out.scope.S.z();
  if (!(w > 0.0 && d > 0.0)) {
    std::ostringstream m;
    m << "Roof: the footprint " << w << " x " << d << " has no area";
    error = m.str();
    return false;
  }
  const double h = std::min(w, d) / 2 * std::tan(angleDeg * kPi / 180.0);
  out.scope.S.y() = h;

  std::vector<Polygon3> faces = roofFaces(kind, w, d, h);
  const Vec3 inv(1.0 / w, 1.0 / h, 1.0 / d);
  for (Polygon3& f : faces)
    for (Vec3& p : f) p = p.cwiseProduct(inv);
  out.geom = arena.addPolyhedron(faces);
  return true;
}

}  // namespace fgsg::rt::cga
