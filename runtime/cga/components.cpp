// Comp: splits a solid (box or polyhedron) or a polygon into its faces or edges, each with
// a scope of its own (CGA's component split).
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"
#include "runtime/cga/street_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fgsg::rt::cga {
namespace {

// A face whose normal is within this of the solid's +Y / -Y (|n.Y| >= 1 - tol) is top /
// bottom; every other face, sloped roof faces included, is a side face.
constexpr double kHorizontalTol = 1e-6;
// Relative to the solid's size: points closer than this are one edge end, heights closer
// than this are equal, normals and edges shorter than this are degenerate.
constexpr double kMergeTol = 1e-9;

enum FaceClass : unsigned {
  kTop = 1,
  kBottom = 2,
  kFront = 4,
  kBack = 8,
  kLeft = 16,
  kRight = 32,
  kSide = kFront | kBack | kLeft | kRight,
  kAllFaces = 63,
  // Besides its side, CityEngine's comp(f) classes by the angle between the face's normal
  // and the scope's xz plane: horizontal above 78.75 degrees (up or down), aslant from
  // 11.25 to 78.75 (a roof slope), vertical within 11.25 of it (a wall), nutant from
  // -11.25 to -78.75 (facing down, an overhang's underside).
  kVertical = 64,
  kAslant = 128,
  kHorizontal = 256,
  kNutant = 512,
};
// sin(11.25 degrees) and sin(78.75 degrees): CityEngine's bounds between those classes.
constexpr double kSinVertical = 0.19509032201612825, kSinHorizontal = 0.98078528040323043;
// An edge is top, bottom or side by its height along the scope's Y; on a roof (or any
// solid) it may also be an eave (level, the lowest edge of a sloped face), a ridge (level,
// where two sloped faces meet convex), a rake (sloped, along a vertical face or a sloped
// face's free border: a gable's edge), a hip (sloped, two sloped faces, convex) or a
// valley (the same, concave).
enum EdgeClass : unsigned {
  kTopEdge = 1, kBottomEdge = 2, kSideEdge = 4, kAllEdges = 7,
  kEave = 8, kRidge = 16, kRake = 32, kHip = 64, kValley = 128,
};

// What CityEngine's selectors say of a component (Part::faceClass of comp(e) and comp(v),
// and of comp(f)'s faces past their FaceClass bits): bits 0..9 the FaceClass of its normal
// in the scope's axes, then border / inside, the roof edge classes (EdgeClass shifted past
// those), and the directions of its normal in the world's axes (x east, y up, z south) and
// the object's (the start shape's), each as FaceClass's six sides.
enum ComponentClass : unsigned {
  kCompBorder = 1u << 10,
  kCompInside = 1u << 11,
  kCompRoofShift = 9,  // kEave (8) << 9 is bit 12 ... kValley (128) << 9 bit 16
  kCompWorldShift = 17,
  kCompObjectShift = 23,
  kCompSideBits = 63,  // FaceClass's top bottom front back left right
};
// street.front back left right: FaceClass's side bits past bit 31 (Part::faceClass is 64 bits).
constexpr unsigned kCompStreetShift = 29;
constexpr uint64_t kCompStreetBits = uint64_t(kSide) << kCompStreetShift;

struct Selector {
  bool edges = false;
  unsigned mask = 0;  // FaceClass or EdgeClass bits
  // CityEngine's comp(e) and comp(v): "e" aligns an edge's scope as CityEngine does (x
  // along it) where "edges" keeps fgsg's (y along it); "v" gives the vertices.
  bool cityEngineAxes = false;
  bool vertices = false;
};

bool parseSelector(const std::string& s, Selector& sel) {
  static const struct {
    const char* name;
    bool edges;
    unsigned mask;
  } kSelectors[] = {
      {"faces", false, kAllFaces},  {"f", false, kAllFaces},     {"sidefaces", false, kSide},
      {"top", false, kTop},         {"bottom", false, kBottom},
      {"vertical", false, kVertical}, {"aslant", false, kAslant},
      {"horizontal", false, kHorizontal}, {"nutant", false, kNutant},
      {"front", false, kFront},     {"back", false, kBack},
      {"left", false, kLeft},       {"right", false, kRight},
      {"edges", true, kAllEdges},   {"sideedges", true, kSideEdge},
      {"topedges", true, kTopEdge}, {"bottomedges", true, kBottomEdge},
      {"eaves", true, kEave},       {"ridges", true, kRidge},        {"rakes", true, kRake},
      {"hips", true, kHip},         {"valleys", true, kValley},
  };
  if (s == "e") {
    sel = {true, kAllEdges, true, false};
    return true;
  }
  if (s == "v" || s == "vertices") {
    sel = {false, 0, true, true};
    return true;
  }
  for (const auto& k : kSelectors)
    if (s == k.name) {
      sel = {k.edges, k.mask};
      return true;
    }
  return false;
}

// A face in world space with its unit outward normal.
struct WorldFace {
  Polygon3 pts;
  Vec3 normal;
};

std::vector<WorldFace> worldFaces(const Scope& scope, const GeomRef& geom,
                                  const GeometryArena& arena) {
  auto toWorld = [&](const Vec3& n) { return scope.toWorld(scope.S.cwiseProduct(n)); };
  std::vector<WorldFace> faces;
  if (geom.kind == GeomKind::Box) {
    // Normals come from the axes, so a flat box (a footprint) still has oriented faces.
    const Vec3 normals[6] = {scope.Z(), scope.X(), -scope.Z(), -scope.X(), scope.Y(), -scope.Y()};
    const std::vector<Polygon3>& box = unitBoxFaces();
    for (std::size_t i = 0; i < box.size(); ++i) {
      WorldFace f{{}, normals[i]};
      for (const Vec3& p : box[i]) f.pts.push_back(toWorld(p));
      faces.push_back(std::move(f));
    }
    return faces;
  }
  const LocalGeometry g = loadGeometry(arena, geom);
  for (const Polygon3& local : g.faces) {
    WorldFace f;
    for (const Vec3& p : local) f.pts.push_back(toWorld(p));
    const Vec3 n = newellNormal(f.pts);
    if (geom.kind == GeomKind::Polygon) {
      f.normal = scope.Z();
    } else if (n.norm() > kMergeTol * kMergeTol * (1.0 + scope.S.squaredNorm())) {
      f.normal = n.normalized();
    } else {
      continue;  // a degenerate face has no orientation
    }
    faces.push_back(std::move(f));
  }
  return faces;
}

unsigned classifyFace(const Vec3& worldNormal, const Scope& scope) {
  const Vec3 n = scope.axes.transpose() * worldNormal;  // in the solid's frame
  if (n.y() >= 1.0 - kHorizontalTol) return kTop | kHorizontal;
  if (n.y() <= -(1.0 - kHorizontalTol)) return kBottom | kHorizontal;
  const unsigned slope = std::abs(n.y()) > kSinHorizontal ? kHorizontal
                         : n.y() > kSinVertical            ? kAslant
                         : n.y() >= -kSinVertical          ? kVertical
                                                           : kNutant;
  if (std::abs(n.z()) >= std::abs(n.x())) return slope | (n.z() > 0 ? kFront : kBack);
  return slope | (n.x() > 0 ? kRight : kLeft);
}

// An edge's or a vertex's FaceClass bits by its normal `n` (the mean of its faces',
// unnormalised) in the frame `axes`: its slope as a face's, and the quadrant its largest
// component points into (op_comp: "classifying their directions into the corresponding
// quadrants"). A tie (a box's top edge leans 45 degrees between top and front, its top
// corner between three sides) goes to top / bottom, then front / back. No normal (the
// faces cancel): no class.
unsigned compClassifyByQuadrant(const Vec3& worldNormal, const Mat3& axes) {
  if (!(worldNormal.norm() > kMergeTol)) return 0;
  const Vec3 n = (axes.transpose() * worldNormal).normalized();
  constexpr double kTie = 1e-9;
  const unsigned slope = std::abs(n.y()) > kSinHorizontal ? kHorizontal
                         : n.y() > kSinVertical            ? kAslant
                         : n.y() >= -kSinVertical          ? kVertical
                                                           : kNutant;
  const double ax = std::abs(n.x()), ay = std::abs(n.y()), az = std::abs(n.z());
  if (ay >= std::max(ax, az) - kTie) return slope | (n.y() > 0 ? kTop : kBottom);
  if (az >= ax - kTie) return slope | (n.z() > 0 ? kFront : kBack);
  return slope | (n.x() > 0 ? kRight : kLeft);
}

// The world.* and object.* bits of a component whose normal is `worldNormal`: its sides
// (compClassifyByQuadrant's for an edge or a vertex, `quadrant`; classifyFace's for a face) in
// the world's axes and in the object's.
unsigned compWorldAndObjectClass(const Vec3& worldNormal, const Mat3& objectAxes, bool quadrant) {
  auto sides = [&](const Mat3& axes) {
    if (quadrant) return compClassifyByQuadrant(worldNormal, axes) & kCompSideBits;
    Scope frame;
    frame.axes = axes;
    return classifyFace(worldNormal, frame) & kCompSideBits;
  };
  return (sides(Mat3::Identity()) << kCompWorldShift) | (sides(objectAxes) << kCompObjectShift);
}

// The street.* bits of a component whose outward direction is `direction` (its normal;
// an edge's or a vertex's on a flat shape's border leans out along the shape's plane):
// by the lot's street widths where `streets` has them (street_edges.h; an edge's ends `a`
// and `b`), else the quadrant of its part level in the object system, whose front is the
// start lot's first edge (setback's street.front; CityEngine falls back to object.*
// without a street width); a tie goes to front / back. Within 11.25 degrees of straight
// up or down: none.
uint64_t compStreetClass(const Vec3& direction, const Mat3& objectAxes, const StreetEdges* streets,
                         const Vec3* a = nullptr, const Vec3* b = nullptr) {
  if (!(direction.norm() > kMergeTol)) return 0;
  const Vec3 n = (objectAxes.transpose() * direction).normalized();
  if (std::abs(n.y()) > kSinHorizontal) return 0;
  if (streets) {
    const unsigned s = streetSide(*streets, direction, a, b);
    return uint64_t((s & kStreetFront ? kFront : 0u) | (s & kStreetBack ? kBack : 0u) |
                    (s & kStreetLeft ? kLeft : 0u) | (s & kStreetRight ? kRight : 0u))
           << kCompStreetShift;
  }
  const unsigned side = std::abs(n.z()) >= std::abs(n.x()) - 1e-9 ? (n.z() > 0 ? kFront : kBack)
                                                                  : (n.x() > 0 ? kRight : kLeft);
  return uint64_t(side) << kCompStreetShift;
}

// The face's scope: Z its normal, X horizontal along the face (Y x Z of the solid, the
// direction of its bottom edge walked counter-clockwise) so Y = Z x X points up the face;
// for top and bottom faces X is the solid's X. The origin is the corner of the face's
// bounding rectangle so the normalised polygon lies in [0,1]^2.
Part facePart(const WorldFace& f, const Scope& solid, GeometryArena& arena, GeomRef& unitSquare) {
  const Vec3 z = f.normal;
  Vec3 x;
  if (std::abs(z.dot(solid.Y())) >= 1.0 - kHorizontalTol)
    x = (solid.X() - solid.X().dot(z) * z).normalized();
  else
    x = solid.Y().cross(z).normalized();
  const Vec3 y = z.cross(x);

  const Vec3& origin = f.pts.front();
  double umin = std::numeric_limits<double>::infinity(), vmin = umin;
  double umax = -umin, vmax = -umin;
  for (const Vec3& p : f.pts) {
    const double u = (p - origin).dot(x), v = (p - origin).dot(y);
    umin = std::min(umin, u), umax = std::max(umax, u);
    vmin = std::min(vmin, v), vmax = std::max(vmax, v);
  }
  Part part;
  part.scope.axes.col(0) = x;
  part.scope.axes.col(1) = y;
  part.scope.axes.col(2) = z;
  part.scope.P = origin + x * umin + y * vmin;
  part.scope.S = Vec3(umax - umin, vmax - vmin, 0.0);

  // Snapping to exact 0 / 1 keeps box faces exactly the unit square.
  constexpr double kSnap = 1e-12;
  auto normalised = [&](double c, double lo, double size) {
    if (size <= 0.0) return 0.0;
    const double t = (c - lo) / size;
    return std::abs(t) < kSnap ? 0.0 : std::abs(t - 1.0) < kSnap ? 1.0 : t;
  };
  Polygon3 poly;
  poly.reserve(f.pts.size());
  for (const Vec3& p : f.pts)
    poly.emplace_back(normalised((p - origin).dot(x), umin, part.scope.S.x()),
                      normalised((p - origin).dot(y), vmin, part.scope.S.y()), 0.0);
  if (isUnitSquare(poly.data(), poly.size())) {
    // Every face of a box is the unit square: store it once per call.
    if (unitSquare.count == 0) unitSquare = arena.addPolygon(poly);
    part.geom = unitSquare;
  } else {
    part.geom = arena.addPolygon(poly);
  }
  return part;
}

struct WorldEdge {
  Vec3 a, b;
  Vec3 normalSum = Vec3::Zero();
  std::array<int, 2> faces{-1, -1};  // the first two faces that share it
};

// Each edge once, in the order the faces first reach it, with the normals of the faces
// that share it summed.
std::vector<WorldEdge> uniqueEdges(const std::vector<WorldFace>& faces, double tol) {
  std::vector<WorldEdge> edges;
  auto same = [&](const Vec3& p, const Vec3& q) { return (p - q).norm() <= tol; };
  for (const WorldFace& f : faces) {
    const std::size_t n = f.pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& a = f.pts[i];
      const Vec3& b = f.pts[(i + 1) % n];
      if (same(a, b)) continue;
      auto it = std::find_if(edges.begin(), edges.end(), [&](const WorldEdge& e) {
        return (same(e.a, a) && same(e.b, b)) || (same(e.a, b) && same(e.b, a));
      });
      if (it == edges.end()) it = edges.insert(edges.end(), WorldEdge{a, b});
      it->normalSum += f.normal;
      const int face = int(&f - faces.data());
      if (it->faces[0] < 0) it->faces[0] = face;
      else if (it->faces[1] < 0) it->faces[1] = face;
    }
  }
  return edges;
}

// The edge's scope: Y along the edge from its lower end (horizontal edges keep the
// direction of the first face that walks them), Z the mean of the adjacent face normals
// made orthogonal to the edge, X = Y x Z; sx = sz = 0, sy = the edge's length.
Part edgePart(const WorldEdge& e, const Scope& solid, double tol) {
  Vec3 a = e.a, b = e.b;
  if ((b - a).dot(solid.Y()) < -tol) std::swap(a, b);
  const double len = (b - a).norm();
  const Vec3 y = (b - a) / len;
  Vec3 z = e.normalSum - e.normalSum.dot(y) * y;
  if (z.norm() <= kMergeTol) {
    // Opposite normals (a flat solid): any direction across the edge will do.
    z = y.unitOrthogonal();
  }
  z.normalize();
  Part part;
  part.scope.axes.col(0) = y.cross(z);
  part.scope.axes.col(1) = y;
  part.scope.axes.col(2) = z;
  part.scope.P = a;
  part.scope.S = Vec3(0.0, len, 0.0);
  part.geom = GeomRef{GeomKind::Edge, 0, 0};
  return part;
}

// CityEngine's comp(e) scope (op_comp): x along the edge as the first face walks it, z
// the mean of the adjacent face normals made orthogonal to it, y = z x x; sx = the
// edge's length, sy = sz = 0, the origin at the edge's first end.
Part cityEngineEdgePart(const WorldEdge& e) {
  const Vec3 x = (e.b - e.a).normalized();
  Vec3 z = e.normalSum - e.normalSum.dot(x) * x;
  if (z.norm() <= kMergeTol) z = x.unitOrthogonal();
  z.normalize();
  Part part;
  part.scope.axes.col(0) = x;
  part.scope.axes.col(1) = z.cross(x);
  part.scope.axes.col(2) = z;
  part.scope.P = e.a;
  part.scope.S = Vec3((e.b - e.a).norm(), 0.0, 0.0);
  part.geom = GeomRef{GeomKind::Edge, 0, 0};
  return part;
}

// CityEngine's comp(v): each vertex once, in the order the faces first reach it; its
// scope has no size, its origin at the vertex, z the mean of the normals of the faces
// around it and x along the first edge that leaves it (made orthogonal to z), y = z x x.
std::vector<Part> vertexParts(const std::vector<WorldFace>& faces, double tol, std::vector<Vec3>& normalSums) {
  struct Vertex {
    Vec3 p, out, normalSum = Vec3::Zero();
  };
  std::vector<Vertex> vertices;
  for (const WorldFace& f : faces) {
    const std::size_t n = f.pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& p = f.pts[i];
      auto it = std::find_if(vertices.begin(), vertices.end(),
                             [&](const Vertex& v) { return (v.p - p).norm() <= tol; });
      if (it == vertices.end()) {
        // Its first edge: to the next corner of this face that is not the same point.
        Vec3 out = Vec3::Zero();
        for (std::size_t k = 1; k < n && out.norm() <= tol; ++k) out = f.pts[(i + k) % n] - p;
        it = vertices.insert(vertices.end(), Vertex{p, out});
      }
      it->normalSum += f.normal;
    }
  }
  std::vector<Part> out;
  normalSums.clear();
  for (const Vertex& v : vertices) {
    normalSums.push_back(v.normalSum);
    Vec3 z = v.normalSum.norm() > kMergeTol ? v.normalSum.normalized() : Vec3(0.0, 1.0, 0.0);
    Vec3 x = v.out - v.out.dot(z) * z;
    x = x.norm() > kMergeTol ? x.normalized() : z.unitOrthogonal();
    Part part;
    part.scope.axes.col(0) = x;
    part.scope.axes.col(1) = z.cross(x);
    part.scope.axes.col(2) = z;
    part.scope.P = v.p;
    part.scope.S = Vec3::Zero();
    part.geom = GeomRef{GeomKind::Edge, 0, 0};
    out.push_back(part);
  }
  return out;
}

// The edge's roof class (EdgeClass) with `up` the roof's up, `origin` a point at height 0
// and ha, hb its ends' heights.
unsigned roofEdgeClass(const WorldEdge& e, const std::vector<WorldFace>& faces, const Vec3& up, const Vec3& origin,
                       double ha, double hb, double tol) {
  constexpr double kVertical = 1e-6;  // |n . up| of a vertical face (a gable end)
  auto sloped = [&](int face) {
    const double c = face < 0 ? 0.0 : faces[size_t(face)].normal.dot(up);
    return c > kVertical && c < 1.0 - kHorizontalTol;
  };
  auto vertical = [&](int face) { return face >= 0 && std::abs(faces[size_t(face)].normal.dot(up)) < kVertical; };
  // Convex when the second face bends away below the first face's plane.
  auto convex = [&] {
    const WorldFace& f = faces[size_t(e.faces[0])];
    double farthest = 0;
    for (const Vec3& p : faces[size_t(e.faces[1])].pts) {
      const double d = (p - e.a).dot(f.normal);
      if (std::abs(d) > std::abs(farthest)) farthest = d;
    }
    return farthest < 0;
  };
  const bool two = e.faces[1] >= 0;
  if (std::abs(ha - hb) <= tol) {
    // Level: an eave where a sloped face lies above it, a ridge where two meet convex.
    for (int face : e.faces) {
      if (!sloped(face)) continue;
      bool above = true;
      for (const Vec3& p : faces[size_t(face)].pts) above &= (p - origin).dot(up) >= ha - tol;
      if (above) return kEave;
    }
    if (two && sloped(e.faces[0]) && sloped(e.faces[1])) return convex() ? kRidge : kValley;
    // A single slope's highest edge (a shed's, against its upright back wall): a ridge
    // too, the mono-pitch ridge that roofers cap as they cap any other.
    for (int face : e.faces) {
      if (!sloped(face)) continue;
      bool below = true;
      for (const Vec3& p : faces[size_t(face)].pts) below &= (p - origin).dot(up) <= ha + tol;
      if (below) return kRidge;
    }
    return 0;
  }
  if (std::abs(ha - hb) >= (e.b - e.a).norm() * (1.0 - kHorizontalTol)) return 0;  // upright: a wall's corner
  // Along a gable wall, or an overhang's free border past it.
  if (vertical(e.faces[0]) || vertical(e.faces[1])) return kRake;
  if (!two) return sloped(e.faces[0]) ? unsigned(kRake) : 0u;
  if (!sloped(e.faces[0]) || !sloped(e.faces[1])) return 0;
  return convex() ? kHip : kValley;
}

}  // namespace

std::vector<std::vector<Vec3>> surfacePolygons(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  std::vector<std::vector<Vec3>> out;
  if (geom.kind == GeomKind::Edge) return out;
  const double tol = kMergeTol * (1.0 + scope.S.norm());
  int flatAxis = -1, flats = 0;
  if (geom.kind == GeomKind::Box)
    for (int a = 0; a < 3; ++a)
      if (!(scope.S[a] > tol)) flatAxis = a, ++flats;
  if (flats > 1) return out;  // a line or a point
  for (WorldFace& f : worldFaces(scope, geom, arena)) {
    if (flatAxis >= 0) {
      // A flat box: only its face looking along the positive axis it has no size in.
      if (!(f.normal.dot(scope.axes.col(flatAxis)) > 0.5)) continue;
    } else if (geom.kind != GeomKind::Polygon && (classifyFace(f.normal, scope) & kBottom)) {
      continue;
    }
    if (newellNormal(f.pts).dot(f.normal) < 0) std::reverse(f.pts.begin(), f.pts.end());
    out.push_back(std::move(f.pts));
  }
  return out;
}

unsigned faceSelectorMask(const std::string& name) {
  if (name == "side") return kSide;
  if (name == "all") return kAllFaces | kHorizontal | kNutant | kVertical | kAslant;
  Selector sel;
  return parseSelector(name, sel) && !sel.edges ? sel.mask : 0;
}

namespace {

// The world.* / object.* selectors (fgsg's names; `.cga`'s world.up is worldUp), border and
// inside: the bits they take of any component.
uint64_t compFrameSelectorMask(const std::string& name) {
  static const struct {
    const char* name;
    uint64_t mask;
  } kFrameLabels[] = {
      {"streetFront", uint64_t(kFront) << kCompStreetShift}, {"streetBack", uint64_t(kBack) << kCompStreetShift},
      {"streetLeft", uint64_t(kLeft) << kCompStreetShift},   {"streetRight", uint64_t(kRight) << kCompStreetShift},
      {"streetSide", uint64_t(kLeft | kRight) << kCompStreetShift},
      {"worldUp", kTop << kCompWorldShift},           {"worldDown", kBottom << kCompWorldShift},
      {"worldSouth", kFront << kCompWorldShift},      {"worldNorth", kBack << kCompWorldShift},
      {"worldEast", kRight << kCompWorldShift},       {"worldWest", kLeft << kCompWorldShift},
      {"worldSide", kSide << kCompWorldShift},        {"objectTop", kTop << kCompObjectShift},
      {"objectBottom", kBottom << kCompObjectShift},  {"objectFront", kFront << kCompObjectShift},
      {"objectBack", kBack << kCompObjectShift},      {"objectLeft", kLeft << kCompObjectShift},
      {"objectRight", kRight << kCompObjectShift},    {"objectSide", kSide << kCompObjectShift},
      {"border", kCompBorder},                        {"inside", kCompInside}};
  for (const auto& l : kFrameLabels)
    if (name == l.name) return l.mask;
  return 0;
}

}  // namespace

uint64_t componentSelectorMask(const std::string& component, const std::string& label) {
  Selector sel;
  if (!parseSelector(component, sel)) return 0;
  std::string name = label;  // a merged part's ("all=") takes what the part takes
  if (!name.empty() && name.back() == '=') name.pop_back();
  const bool fgsgEdges = sel.edges && !sel.cityEngineAxes;  // Comp("edges"): fgsg's edge classes
  if (const uint64_t frame = compFrameSelectorMask(name); frame && !fgsgEdges) return frame;
  if (!(sel.edges || sel.cityEngineAxes)) return faceSelectorMask(name);
  static const struct {
    const char* name;
    unsigned mask;
  } kEdgeLabels[] = {{"all", ~0u},        {"eave", kEave},     {"eaves", kEave},   {"ridge", kRidge},
                     {"ridges", kRidge},  {"hip", kHip},       {"hips", kHip},     {"valley", kValley},
                     {"valleys", kValley}, {"gable", kRake},   {"rake", kRake},    {"rakes", kRake}};
  for (const auto& l : kEdgeLabels)
    if (name == l.name) return sel.cityEngineAxes ? l.mask == ~0u ? ~0u : l.mask << kCompRoofShift : l.mask;
  if (!sel.cityEngineAxes) return 0;  // fgsg's Comp("edges"): the roof classes only
  // comp(e) and comp(v): the scope's sides and slopes as comp(f)'s; `side` all but the
  // horizontal ones (op_comp: "Selects all but the horizontal components").
  if (name == "side") return kVertical | kAslant | kNutant;
  return faceSelectorMask(name);
}

Part mergedComponents(const std::vector<Part>& parts) {
  Part merged = parts.front();
  const Mat3& axes = merged.scope.axes;
  const Vec3 origin = merged.scope.P;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Part& p : parts)
    for (const Vec3& end : {p.scope.P, p.scope.toWorld(p.scope.S.cwiseProduct(Vec3::UnitX()))}) {
      const Vec3 local = axes.transpose() * (end - origin);
      lo = lo.cwiseMin(local), hi = hi.cwiseMax(local);
    }
  merged.scope.P = merged.scope.toWorld(lo);
  merged.scope.S = hi - lo;
  merged.geom = GeomRef{GeomKind::Edge, 0, 0};
  return merged;
}

Part mergedFaces(const std::vector<Part>& parts, GeometryArena& arena) {
  if (parts.size() == 1) return parts.front();
  std::vector<Polygon3> world;
  for (const Part& p : parts)
    for (WorldFace& f : worldFaces(p.scope, p.geom, arena)) world.push_back(std::move(f.pts));
  Part merged = parts.front();
  const std::vector<Polygon3> unit = fitScopeAroundWorldFaces(merged.scope, merged.scope.axes, world, merged.scope);
  merged.geom = arena.addPolyhedron(unit);
  return merged;
}

// `out` is replaced by the selected components, in the order of the solid's faces (a box:
// front, right, back, left, top, bottom) or of first appearance of its edges. A polygon
// is a solid with one face: its own; its edges are its boundary.
bool components(const Scope& scope, const GeomRef& geom, const std::string& selector,
                GeometryArena& arena, std::vector<Part>& out, std::string& error, const Mat3& objectAxes,
                uint64_t wantedClasses, const StreetEdges* streets) {
  out.clear();
  Selector sel;
  if (!parseSelector(selector, sel)) {
    error = "Comp: unknown selector \"" + selector +
            "\" (expected faces, sidefaces, vertical, aslant, horizontal, nutant, top, bottom, front, back, left, right, edges, "
            "sideedges, topedges, bottomedges, eaves, ridges, rakes, hips, valleys, e or v)";
    return false;
  }
  if (geom.kind == GeomKind::Edge) {
    error = "Comp(\"" + selector + "\"): an edge has no faces or edges";
    return false;
  }
  const std::vector<WorldFace> faces = worldFaces(scope, geom, arena);
  const double tol = kMergeTol * (1.0 + scope.S.norm());
  const bool wantsBorder = (wantedClasses & (kCompBorder | kCompInside)) != 0;
  // The world.* / object.* bits only where a label asks for them (comp(f) runs on every lot).
  const bool wantsFrames = ((wantedClasses & ~kCompStreetBits) >> kCompWorldShift) != 0;
  const bool wantsStreet = (wantedClasses & kCompStreetBits) != 0;
  auto frameClass = [&](const Vec3& normal, bool quadrant) {
    return wantsFrames ? compWorldAndObjectClass(normal, objectAxes, quadrant) : 0u;
  };
  auto edgeClass = [&](const WorldEdge& e) {
    const double ha = (e.a - scope.P).dot(scope.Y()), hb = (e.b - scope.P).dot(scope.Y());
    return roofEdgeClass(e, faces, scope.Y(), scope.P, ha, hb, tol);
  };
  // An edge or a vertex: classed by the mean of its faces' normals; border when it is (or
  // ends) an edge of one face only (op_comp), inside otherwise.
  // `outward`: the unit directions out of the shape along its border edges' faces at the
  // component (street.* only).
  // `a` and `b`: an edge's ends (street.* by the lot edge it lies on).
  auto edgeOrVertexClass = [&](const Vec3& normalSum, bool border, const Vec3& outward, const Vec3* a = nullptr,
                               const Vec3* b = nullptr) {
    return compClassifyByQuadrant(normalSum, scope.axes) | (border ? kCompBorder : kCompInside) |
           frameClass(normalSum, true) |
           (wantsStreet ? compStreetClass(normalSum.normalized() + outward, objectAxes, streets, a, b) : uint64_t{0});
  };
  // A border edge's outward direction in its face's plane (the face walks it counter-clockwise).
  auto borderOutward = [&](const WorldEdge& e) -> Vec3 {
    if (e.faces[1] >= 0 || e.faces[0] < 0) return Vec3::Zero();
    const Vec3 out = (e.b - e.a).cross(faces[size_t(e.faces[0])].normal);
    return out.norm() > kMergeTol ? Vec3(out.normalized()) : Vec3::Zero();
  };
  if (sel.vertices) {
    std::vector<Vec3> normalSums;
    out = vertexParts(faces, tol, normalSums);
    std::vector<WorldEdge> edges;
    if (wantsBorder || wantsStreet) edges = uniqueEdges(faces, tol);
    for (size_t i = 0; i < out.size(); ++i) {
      bool border = false;
      Vec3 outward = Vec3::Zero();
      for (const WorldEdge& e : edges)
        if (e.faces[1] < 0 && ((e.a - out[i].scope.P).norm() <= tol || (e.b - out[i].scope.P).norm() <= tol))
          border = true, outward += borderOutward(e);
      out[i].faceClass = edgeOrVertexClass(normalSums[i], border, outward);
    }
    return true;
  }
  if (sel.cityEngineAxes) {
    for (const WorldEdge& e : uniqueEdges(faces, tol)) {
      out.push_back(cityEngineEdgePart(e));
      out.back().faceClass = edgeOrVertexClass(e.normalSum, e.faces[1] < 0, borderOutward(e), &e.a, &e.b) |
                             (edgeClass(e) << kCompRoofShift);
    }
    return true;
  }

  if (!sel.edges) {
    // A face is border when one of its edges is no other face's; a box is closed.
    std::vector<char> borderFace(faces.size(), 0);
    if (wantsBorder && geom.kind != GeomKind::Box)
      for (const WorldEdge& e : uniqueEdges(faces, tol))
        if (e.faces[1] < 0 && e.faces[0] >= 0) borderFace[size_t(e.faces[0])] = 1;
    GeomRef unitSquare{GeomKind::Polygon, 0, 0};
    for (size_t i = 0; i < faces.size(); ++i)
      if (const unsigned cls = classifyFace(faces[i].normal, scope); cls & sel.mask) {
        out.push_back(facePart(faces[i], scope, arena, unitSquare));
        out.back().faceClass = cls | (borderFace[i] ? kCompBorder : kCompInside) |
                               frameClass(faces[i].normal, false) |
                               (wantsStreet ? compStreetClass(faces[i].normal, objectAxes, streets) : uint64_t{0});
      }
    return true;
  }

  double hmin = std::numeric_limits<double>::infinity(), hmax = -hmin;
  for (const WorldFace& f : faces)
    for (const Vec3& p : f.pts) {
      const double h = (p - scope.P).dot(scope.Y());
      hmin = std::min(hmin, h), hmax = std::max(hmax, h);
    }
  for (const WorldEdge& e : uniqueEdges(faces, tol)) {
    const double ha = (e.a - scope.P).dot(scope.Y()), hb = (e.b - scope.P).dot(scope.Y());
    unsigned cls = kSideEdge;
    if (std::abs(ha - hmax) <= tol && std::abs(hb - hmax) <= tol)
      cls = kTopEdge;
    else if (std::abs(ha - hmin) <= tol && std::abs(hb - hmin) <= tol)
      cls = kBottomEdge;
    cls |= edgeClass(e);
    if (cls & sel.mask) {
      out.push_back(edgePart(e, scope, tol));
      out.back().faceClass = cls;
    }
  }
  return true;
}

}  // namespace fgsg::rt::cga
