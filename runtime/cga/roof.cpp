// Roof: a hipped, gable, pyramid, shed or ridge roof solid on a rectangle or on any footprint.
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/skeleton_roof.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace fgsg::rt::cga {
namespace {


enum class RoofKind { Hipped, Gable, Pyramid, Shed, Ridge };

bool parseKind(const std::string& s, RoofKind& kind) {
  if (s == "hipped")
    kind = RoofKind::Hipped;
  else if (s == "gable")
    kind = RoofKind::Gable;
  else if (s == "pyramid")
    kind = RoofKind::Pyramid;
  else if (s == "shed")
    kind = RoofKind::Shed;
  else if (s == "ridge")
    kind = RoofKind::Ridge;
  else
    return false;
  return true;
}

SkeletonRoofKind skeletonKind(RoofKind kind) {
  switch (kind) {
    case RoofKind::Hipped: return SkeletonRoofKind::Hipped;
    case RoofKind::Gable: return SkeletonRoofKind::Gable;
    case RoofKind::Pyramid: return SkeletonRoofKind::Pyramid;
    case RoofKind::Ridge: return SkeletonRoofKind::Ridge;
    case RoofKind::Shed: break;
  }
  return SkeletonRoofKind::Shed;
}

// The footprint a roof stands on, as (x, z) rings in the roof scope's units, when it is
// not the scope's whole rectangle: a polygon's own corners (at normalised (x, 0, 1 - y)
// of the solid frame), or a solid's bottom face; a courtyard's bridges split them into
// the outline and its holes. False: the rectangle.
bool footprintRings(const Scope& roofScope, const GeomRef& geom, const GeometryArena& arena,
                    std::vector<Vec2>& outer, std::vector<std::vector<Vec2>>& holes) {
  const double w = roofScope.S.x(), d = roofScope.S.z();
  Polygon3 ground;
  if (geom.kind == GeomKind::Polygon) {
    if (isUnitSquare(arena.polygon(geom), geom.count)) return false;
    for (uint32_t i = 0; i < geom.count; ++i) {
      const Vec3& p = arena.polygon(geom)[i];
      ground.emplace_back(p.x() * w, 0.0, (1.0 - p.y()) * d);
    }
  } else if (geom.kind == GeomKind::Polyhedron) {
    // An extruded prism's bottom: the one face lying flat at y = 0, looking down.
    for (const Polygon3& f : loadGeometry(arena, geom).faces) {
      bool flat = true;
      for (const Vec3& p : f) flat &= std::abs(p.y()) <= kPlaneTol;
      if (!flat || !(newellNormal(f).y() < 0)) continue;
      if (!ground.empty()) return false;  // several bottoms: stand on the rectangle
      for (const Vec3& p : f) ground.emplace_back(p.x() * w, 0.0, p.z() * d);
    }
  }
  if (ground.empty()) return false;
  const std::vector<Polygon3> rings = ringsOf(ground);
  auto plan = [](const Polygon3& ring) {
    std::vector<Vec2> xz;
    for (const Vec3& p : ring) xz.emplace_back(p.x(), p.z());
    return xz;
  };
  outer = plan(rings[0]);
  holes.clear();
  for (size_t r = 1; r < rings.size(); ++r) holes.push_back(plan(rings[r]));
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

// A box (or a solid with no single flat bottom) gives the scope's XZ rectangle, the
// scope's Y size ignored: the roof stands on the scope's base. A polygon gives its own
// corners, with the roof rising along its normal (solidFrameOnPolygon), and a solid its
// bottom face: those are roofed by the straight skeleton (skeleton_roof.h), so every
// sloped face of a hipped roof tilts by `angleDeg`. On the rectangle the slopes over the
// longer sides are at `angleDeg`, so h = (shorter side / 2) * tan(angle) for these kinds;
// the hips of a hipped roof and the faces of a pyramid on a non-square rectangle follow
// from that height. A shed rises from the first edge (the rectangle's back, -Z, edge). A
// ridge roof's ridge runs along the scope's x whichever side is longer (CityEngine's
// roofRidge: "parallel to the scope's x-axis"), h = (d / 2) * tan(angle) on the rectangle.
namespace {

// The roof's faces in the roof scope's units (y up from the footprint), `out.scope` the
// footprint's frame and `h` the roof's height: everything roof() does but the arena.
bool buildRoofFaces(const Scope& scope, const GeomRef& geom, const std::string& kindName, double angleDeg,
                    const GeometryArena& arena, Part& out, std::vector<Polygon3>& faces, double& h,
                    std::string& error, const Deadline* deadline, const RoofOptions& options) {
  RoofKind kind;
  if (!parseKind(kindName, kind)) {
    error = "Roof: unknown kind \"" + kindName + "\" (expected hipped, gable, pyramid, shed or ridge)";
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
  for (const double o : {options.overhang, options.gableOverhang})
    if (!(o >= 0.0 && std::isfinite(o))) {
      std::ostringstream m;
      m << "Roof: the overhang " << o << " must be a number of metres, 0 or more";
      error = m.str();
      return false;
    }
  const bool overhangs = options.overhang > 0.0 || options.gableOverhang > 0.0;
  if (overhangs && kind != RoofKind::Hipped && kind != RoofKind::Gable) {
    error = "Roof: a " + kindName + " roof has no overhang (hipped and gable roofs do)";
    return false;
  }
  if (options.edgeIndex >= 0 && kind != RoofKind::Shed && kind != RoofKind::Gable) {
    error = "Roof: only shed and gable roofs take an edge index (the edge a shed rises from, a gable's ridge runs along)";
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
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> holes;
  bool onPolygon = footprintRings(out.scope, geom, arena, outer, holes);
  // The rectangle's closed forms have no overhangs: an overhanging roof on it is built as
  // on any polygon (the same roof, its faces in the skeleton's order).
  if (!onPolygon && (kind == RoofKind::Shed || kind == RoofKind::Ridge || overhangs || options.edgeIndex >= 0))
    outer = {{0, 0}, {w, 0}, {w, d}, {0, d}}, onPolygon = true;
  if (kind == RoofKind::Shed && options.edgeIndex > 0) {
    const size_t first = size_t(options.edgeIndex) % outer.size();
    std::rotate(outer.begin(), outer.begin() + long(first), outer.end());
  }
  faces.clear();
  h = 0.0;
  if (!onPolygon) {
    h = std::min(w, d) / 2 * std::tan(angleDeg * std::numbers::pi / 180.0);
    faces = roofFaces(kind, w, d, h);
  } else if (!skeletonRoof(outer, holes, skeletonKind(kind), angleDeg, faces, h, error, nullptr, deadline,
                           RoofOverhang{options.overhang, options.gableOverhang,
                                        kind == RoofKind::Gable ? options.edgeIndex : -1})) {
    return false;
  }
  if (!(h > 0.0)) {
    error = "Roof: the roof has no height";
    return false;
  }
  return true;
}

}  // namespace

bool roof(const Scope& scope, const GeomRef& geom, const std::string& kindName, double angleDeg,
          GeometryArena& arena, Part& out, std::string& error, const Deadline* deadline,
          const RoofOptions& options) {
  std::vector<Polygon3> faces;
  double h = 0.0;
  if (!buildRoofFaces(scope, geom, kindName, angleDeg, arena, out, faces, h, error, deadline, options))
    return false;
  const double w = out.scope.S.x(), d = out.scope.S.z();
  const bool overhangs = options.overhang > 0.0 || options.gableOverhang > 0.0;
  // The scope spans the roof: the footprint's rectangle up to the ridge, or with overhangs
  // the box around every face (the eaves reach out and down past the footprint).
  Vec3 lo = Vec3::Zero(), hi(w, h, d);
  if (overhangs)
    for (const Polygon3& f : faces)
      for (const Vec3& p : f) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  out.scope.P += out.scope.axes * lo;
  out.scope.S = hi - lo;
  const Vec3 inv = out.scope.S.cwiseInverse();
  for (Polygon3& f : faces)
    for (Vec3& p : f) p = (p - lo).cwiseProduct(inv);
  out.geom = arena.addPolyhedron(faces);
  return true;
}

// Every height of a roof built at an angle is a horizontal distance times tan(angle): the
// straight skeleton's offset times, a shed's distance from its edge, a ridge roof's half
// depth, a pyramid's apex distance (gable tops move along ridges, which scale alike). So
// the roof built at 45 degrees (tan = 1) without overhangs stands exactly t_max high, the
// largest such distance, and atan(height / t_max) is the one angle whose roof stands
// `height` high: the angle form with that angle, overhangs and all. Overhangs hang below
// the footprint's plane and leave the ridge where it is: `height` is measured from the
// footprint (the eave line on the walls), not from the overhanging eaves.
bool roofByHeight(const Scope& scope, const GeomRef& geom, const std::string& kindName, double height,
                  GeometryArena& arena, Part& out, std::string& error, const Deadline* deadline,
                  const RoofOptions& options) {
  if (!(height > 0.0 && std::isfinite(height))) {
    std::ostringstream m;
    m << "Roof: the height " << height << " must be a number of metres more than 0";
    error = m.str();
    return false;
  }
  RoofOptions plain = options;
  plain.overhang = plain.gableOverhang = 0.0;
  Part probe;
  std::vector<Polygon3> faces;
  double height45 = 0.0;
  if (!buildRoofFaces(scope, geom, kindName, 45.0, arena, probe, faces, height45, error, deadline, plain))
    return false;
  // The roof divided by the tan(45 degrees) it was built with (1 - 1 ulp in doubles).
  const double tMax = height45 / std::tan(45.0 * std::numbers::pi / 180.0);
  const double angleDeg = std::atan(height / tMax) * 180.0 / std::numbers::pi;
  if (angleDeg >= 90.0) {  // atan of a ratio too great for doubles
    std::ostringstream m;
    m << "Roof: the height " << height << " is too great for a footprint whose roof planes meet " << tMax
      << " from its edges";
    error = m.str();
    return false;
  }
  return roof(scope, geom, kindName, angleDeg, arena, out, error, deadline, options);
}

}  // namespace fgsg::rt::cga
