// CityEngine's primitive operations: the shape's geometry replaced by a quad, a cube, a
// cylinder, a sphere or a disk in its scope. Without sizes the primitive fills the scope
// (a zero size taken as the mean of the others, as i() does); with sizes it stands on the
// scope's y = 0, centred in x and z.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::cga {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A solid's faces turned to face away from its centre (they are convex solids).
std::vector<Polygon3> outward(std::vector<Polygon3> faces, const Vec3& centre) {
  for (Polygon3& f : faces) {
    Vec3 c = Vec3::Zero();
    for (const Vec3& p : f) c += p;
    c /= double(f.size());
    if (newellNormal(f).dot(c - centre) < 0) std::reverse(f.begin(), f.end());
  }
  return faces;
}

}  // namespace

bool primitive(const Scope& scope, const std::string& kind, const std::vector<double>& args, GeometryArena& arena,
               Part& out, std::string& error) {
  for (double a : args)
    if (!std::isfinite(a) || a < 0) {
      error = kind + ": its arguments must be finite numbers >= 0";
      return false;
    }
  // The box the primitive fills, in scope units from the scope's origin.
  Vec3 size = scope.S;
  double nonZero = 0;
  int count = 0;
  for (int k = 0; k < 3; ++k)
    if (size[k] > 0) nonZero += size[k], ++count;
  const bool flat = kind == "PrimitiveQuad" || kind == "PrimitiveDisk";
  for (int k = 0; k < 3; ++k)
    if (!(size[k] > 0) && !(flat && k == 1)) size[k] = count ? nonZero / count : 1.0;
  Vec3 origin = Vec3::Zero();
  auto standCentred = [&](double w, double h, double d) {
    origin = Vec3((size.x() - w) / 2, 0.0, (size.z() - d) / 2);
    size = Vec3(w, h, d);
  };
  int sides = 16;
  if (kind == "PrimitiveQuad") {
    if (args.size() == 2) standCentred(args[0], 0.0, args[1]);
  } else if (kind == "PrimitiveCube") {
    if (args.size() == 3) standCentred(args[0], args[1], args[2]);
  } else if (kind == "PrimitiveCylinder" || kind == "PrimitiveDisk") {
    if (!args.empty()) sides = static_cast<int>(std::lround(args[0]));
    if (kind == "PrimitiveCylinder" && args.size() == 3) standCentred(2 * args[1], args[2], 2 * args[1]);
    if (kind == "PrimitiveDisk" && args.size() == 2) standCentred(2 * args[1], 0.0, 2 * args[1]);
  } else if (kind == "PrimitiveSphere") {
    if (args.size() == 3) standCentred(2 * args[2], 2 * args[2], 2 * args[2]);
  } else {
    error = "unknown primitive '" + kind + "'";
    return false;
  }
  if (sides < 3 || sides > 4096) {
    error = kind + ": takes 3 to 4096 sides, got " + std::to_string(sides);
    return false;
  }
  if (kind == "PrimitiveQuad" || kind == "PrimitiveDisk") {
    // A polygon on the scope's xz plane facing up, as Footprint makes it.
    std::vector<Vec2> corners;
    if (kind == "PrimitiveQuad") {
      corners = {{0, 0}, {size.x(), 0}, {size.x(), size.z()}, {0, size.z()}};
    } else {
      for (int k = 0; k < sides; ++k) {
        const double a = 2 * kPi * k / sides;
        corners.emplace_back(size.x() / 2 * (1 + std::cos(a)), size.z() / 2 * (1 + std::sin(a)));
      }
    }
    Scope at = scope;
    at.P = scope.toWorld(origin);
    return footprint(at, corners, {}, arena, out, error);
  }
  out = Part{};
  out.scope = scope;
  out.scope.P = scope.toWorld(origin);
  out.scope.S = size;
  if (kind == "PrimitiveCube") return true;  // the scope box itself
  std::vector<Polygon3> faces;
  if (kind == "PrimitiveCylinder") {
    Polygon3 bottom, top;
    for (int k = 0; k < sides; ++k) {
      const double a0 = 2 * kPi * k / sides, a1 = 2 * kPi * (k + 1) / sides;
      const Vec3 p0(0.5 + 0.5 * std::cos(a0), 0, 0.5 + 0.5 * std::sin(a0));
      const Vec3 p1(0.5 + 0.5 * std::cos(a1), 0, 0.5 + 0.5 * std::sin(a1));
      bottom.push_back(p0);
      top.push_back(p0 + Vec3(0, 1, 0));
      faces.push_back({p0, p1, p1 + Vec3(0, 1, 0), p0 + Vec3(0, 1, 0)});
    }
    faces.push_back(bottom);
    faces.push_back(top);
  } else {  // a UV sphere: latitudes bands, longitudes segments; triangles at the poles
    const int lat = args.size() >= 2 ? static_cast<int>(std::lround(args[0])) : 8;
    const int lon = args.size() >= 2 ? static_cast<int>(std::lround(args[1])) : 16;
    if (lat < 2 || lon < 3 || lat > 1024 || lon > 1024) {
      error = "PrimitiveSphere: takes 2 to 1024 latitudes and 3 to 1024 longitudes";
      return false;
    }
    auto point = [&](int i, int j) {
      const double theta = kPi * i / lat, phi = 2 * kPi * j / lon;
      return Vec3(0.5 + 0.5 * std::sin(theta) * std::cos(phi), 0.5 + 0.5 * std::cos(theta),
                  0.5 + 0.5 * std::sin(theta) * std::sin(phi));
    };
    for (int i = 0; i < lat; ++i)
      for (int j = 0; j < lon; ++j) {
        Polygon3 f{point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)};
        if (i == 0) f.erase(f.begin() + 3);       // the north pole: one corner
        if (i == lat - 1) f.erase(f.begin() + 1);  // the south pole
        faces.push_back(f);
      }
  }
  out.geom = arena.addPolyhedron(outward(std::move(faces), Vec3(0.5, 0.5, 0.5)));
  return true;
}

}  // namespace fgsg::rt::cga
