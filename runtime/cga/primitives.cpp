// CityEngine's primitive operations: the shape's geometry replaced by a quad, a cube, a
// cylinder, a sphere or a disk in its scope. Without sizes the primitive fills the scope
// (a zero size taken as the mean of the others, as i() does); with sizes it stands on the
// scope's y = 0, centred in x and z. The quad and the disk lie in the scope's xz plane,
// facing +y, unless exactly one scope size is zero: then in the plane of the other two,
// facing along the zero size's axis (CityEngine: "with respect to the plane defined by the
// valued scope sizes"), centred in it when sizes are given.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fgsg::rt::cga {
namespace {

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

// A primitive called with a number of arguments it has no form for.
bool primitiveArity(const std::string& kind, const char* forms, size_t got, std::string& error) {
  error = kind + ": takes " + forms + ", got " + std::to_string(got);
  return false;
}

}  // namespace

bool primitive(const Scope& scope, const std::string& kind, const std::vector<double>& args, GeometryArena& arena,
               Part& out, std::string& error) {
  for (double a : args)
    if (!std::isfinite(a) || a < 0) {
      error = kind + ": its arguments must be finite numbers >= 0";
      return false;
    }
  const bool flat = kind == "PrimitiveQuad" || kind == "PrimitiveDisk";
  // The axis a flat primitive faces along: y, or the one zero size's.
  int normalAxis = 1, zeros = 0;
  for (int k = 0; k < 3; ++k)
    if (!(scope.S[k] > 0)) ++zeros, normalAxis = k;
  if (!flat || zeros != 1) normalAxis = 1;
  // The box the primitive fills, in scope units from the scope's origin.
  Vec3 size = scope.S;
  double nonZero = 0;
  int count = 0;
  for (int k = 0; k < 3; ++k)
    if (size[k] > 0) nonZero += size[k], ++count;
  for (int k = 0; k < 3; ++k)
    if (!(size[k] > 0) && !(flat && k == normalAxis)) size[k] = count ? nonZero / count : 1.0;
  if (flat) size[normalAxis] = 0.0;
  // The flat primitive's in-plane axes, as a right-handed turn of (x, y, z) that takes y to
  // the normal: u after it, v before it (x and z for a normal along y).
  const int uAxis = (normalAxis + 2) % 3, vAxis = (normalAxis + 1) % 3;
  Vec3 origin = Vec3::Zero();
  auto standCentred = [&](double w, double h, double d) {
    origin = Vec3((size.x() - w) / 2, 0.0, (size.z() - d) / 2);
    size = Vec3(w, h, d);
  };
  auto centreInPlane = [&](double w, double l) {  // width along the plane's first axis (x, y), length the second
    const int first = std::min(uAxis, vAxis), second = std::max(uAxis, vAxis);
    origin = Vec3::Zero();
    origin[first] = (size[first] - w) / 2;
    origin[second] = (size[second] - l) / 2;
    size[first] = w;
    size[second] = l;
  };
  int sides = 16;
  if (kind == "PrimitiveQuad") {
    if (args.size() == 2) centreInPlane(args[0], args[1]);
    else if (!args.empty()) return primitiveArity(kind, "0 or 2 arguments (width, length)", args.size(), error);
  } else if (kind == "PrimitiveCube") {
    if (args.size() == 3) standCentred(args[0], args[1], args[2]);
    else if (!args.empty()) return primitiveArity(kind, "0 or 3 arguments (width, height, depth)", args.size(), error);
  } else if (kind == "PrimitiveCylinder") {
    if (args.size() == 2) return primitiveArity(kind, "0, 1 or 3 arguments (sides, radius, height)", args.size(), error);
    if (!args.empty()) sides = static_cast<int>(std::lround(args[0]));
    if (args.size() == 3) standCentred(2 * args[1], args[2], 2 * args[1]);
  } else if (kind == "PrimitiveDisk") {
    if (!args.empty()) sides = static_cast<int>(std::lround(args[0]));
    if (args.size() == 2) centreInPlane(2 * args[1], 2 * args[1]);
  } else if (kind == "PrimitiveSphere") {
    if (args.size() == 1) return primitiveArity(kind, "0, 2 or 3 arguments (sides, divisions, radius)", args.size(), error);
    if (args.size() == 3) standCentred(2 * args[2], 2 * args[2], 2 * args[2]);
  } else {
    error = "unknown primitive '" + kind + "'";
    return false;
  }
  if (sides < 3 || sides > 4096) {
    error = kind + ": takes 3 to 4096 sides, got " + std::to_string(sides);
    return false;
  }
  if (flat) {
    // A polygon in the (u, v) plane facing the normal axis, as Footprint makes it in a scope
    // whose x, y, z are u, the normal and v.
    const double w = size[uAxis], d = size[vAxis];
    std::vector<Vec2> corners;
    if (kind == "PrimitiveQuad") {
      corners = {{0, 0}, {w, 0}, {w, d}, {0, d}};
    } else {
      for (int k = 0; k < sides; ++k) {
        const double a = 2 * std::numbers::pi * k / sides;
        corners.emplace_back(w / 2 * (1 + std::cos(a)), d / 2 * (1 + std::sin(a)));
      }
    }
    Scope at = scope;
    at.P = scope.toWorld(origin);
    at.axes.col(0) = scope.axes.col(uAxis);
    at.axes.col(1) = scope.axes.col(normalAxis);
    at.axes.col(2) = scope.axes.col(vAxis);
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
      const double a0 = 2 * std::numbers::pi * k / sides, a1 = 2 * std::numbers::pi * (k + 1) / sides;
      const Vec3 p0(0.5 + 0.5 * std::cos(a0), 0, 0.5 + 0.5 * std::sin(a0));
      const Vec3 p1(0.5 + 0.5 * std::cos(a1), 0, 0.5 + 0.5 * std::sin(a1));
      bottom.push_back(p0);
      top.push_back(p0 + Vec3(0, 1, 0));
      faces.push_back({p0, p1, p1 + Vec3(0, 1, 0), p0 + Vec3(0, 1, 0)});
    }
    faces.push_back(bottom);
    faces.push_back(top);
  } else {
    // A UV sphere (CityEngine's parameters): `sides` segments around each latitude circle,
    // `divisions` bands from pole to pole along each meridian; triangles at the poles.
    const int around = args.size() >= 2 ? static_cast<int>(std::lround(args[0])) : 16;
    const int bands = args.size() >= 2 ? static_cast<int>(std::lround(args[1])) : 16;
    if (around < 3 || bands < 3 || around > 1024 || bands > 1024) {
      error = "PrimitiveSphere: takes 3 to 1024 sides and 3 to 1024 divisions, got " + std::to_string(around) +
              " and " + std::to_string(bands);
      return false;
    }
    auto point = [&](int i, int j) {
      const double theta = std::numbers::pi * i / bands, phi = 2 * std::numbers::pi * j / around;
      return Vec3(0.5 + 0.5 * std::sin(theta) * std::cos(phi), 0.5 + 0.5 * std::cos(theta),
                  0.5 + 0.5 * std::sin(theta) * std::sin(phi));
    };
    for (int i = 0; i < bands; ++i)
      for (int j = 0; j < around; ++j) {
        Polygon3 f{point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)};
        if (i == 0) f.erase(f.begin() + 3);          // the north pole: one corner
        if (i == bands - 1) f.erase(f.begin() + 1);  // the south pole
        faces.push_back(f);
      }
  }
  out.geom = arena.addPolyhedron(outward(std::move(faces), Vec3(0.5, 0.5, 0.5)));
  return true;
}

}  // namespace fgsg::rt::cga
