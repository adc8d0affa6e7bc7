// CityEngine's scatter(domain, nPoints, uniform | gaussian[, mean, stddev]) (op_scatter,
// issue #44): random points on a shape's surface, inside its solid or inside its scope
// box, each the origin of a new shape whose scope has size zero.
//
//   surface  on the faces of the shape's own geometry (every face of a box or polyhedron,
//            the one face of a polygon or a flat box), area-weighted; the point's scope is
//            turned so that its y is the face's normal, its x the parent's x laid onto the
//            face (the parent's z where x stands upright on it).
//   volume   inside a closed solid (a box with three sizes, a polyhedron whose every edge
//            is shared by two faces running opposite ways); CityEngine falls back to the
//            surface otherwise, and so does this. Axes as the parent's.
//   scope    inside the scope box. Axes as the parent's.
//
// gaussian: a normal distribution about the mean (the scope's centre, or the centre of its
// front +z, back -z, left -x, right +x, top +y or bottom -y side) with standard deviation
// `stddev` in metres, or, relative, stddev times the scope's size along each axis (an axis
// of size zero then has none: the points keep the mean's coordinate there). Where
// CityEngine's reference leaves it open, decided here: the distribution is restricted to
// the domain (points outside it are drawn again), so that every point lies in the domain:
// per axis by inverting the truncated normal's distribution (scope, volume's box), the
// solid and the surface by rejection against the normal's density.
//
// Each point draws only from the RandomStream it is given, so the same stream gives the
// same points in every engine.
#pragma once

#include "runtime/deadline.h"
#include "runtime/geometry.h"
#include "runtime/random.h"
#include "runtime/scope.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::cga {

enum class ScatterDomain : uint8_t { Surface = 0, Volume = 1, Scope = 2 };
enum class ScatterMean : uint8_t { Center = 0, Front, Back, Left, Right, Top, Bottom };

struct ScatterSpec {
  ScatterDomain domain = ScatterDomain::Surface;
  bool gaussian = false;
  ScatterMean mean = ScatterMean::Center;
  double stddev = 0.16;  // metres, or times the scope's size (relative)
  bool relative = true;
};

// Draws the points of one scatter on one shape: prepare() once, then next() per point.
class ScatterSampler {
 public:
  // False with the reason in `error` for a deviation that is not a positive number.
  bool prepare(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, const ScatterSpec& spec,
               std::string& error);
  // The domain points come from: a volume that is not a closed solid is its surface.
  ScatterDomain domain() const { return domain_; }
  // Whether there is anywhere to put a point (a surface without area has none).
  bool empty() const { return domain_ == ScatterDomain::Surface && triangles_.empty(); }
  // The next point's scope (size zero). False with `error` when a gaussian or a solid
  // rejects draw after draw (kMaxDraws for one point). Asks `deadline` at every draw
  // (throwing TimeLimitReached): a draw inside a solid tests every triangle, so a thin
  // solid of many triangles could otherwise run its kMaxDraws far past --max-seconds.
  bool next(RandomStream& rng, Scope& point, std::string& error, Deadline* deadline = nullptr);

  static constexpr uint32_t kMaxDraws = 1'000'000;

 private:
  struct Triangle {
    std::array<Vec3, 3> local;  // corners in the parent scope's frame (metres from P)
    Vec3 normal;                // the face's unit normal, world
  };
  double drawAxis(RandomStream& rng, int axis, double lo, double hi) const;
  bool insideSolid(const Vec3& local) const;
  double gaussianExponent(const Vec3& local) const;  // half the squared standard distance
  Scope pointScope(const Vec3& local, const Vec3* normal) const;

  Scope scope_;
  ScatterSpec spec_;
  ScatterDomain domain_ = ScatterDomain::Surface;
  Vec3 mean_ = Vec3::Zero();   // local
  Vec3 sigma_ = Vec3::Zero();  // per axis; 0: none (the mean's coordinate)
  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();  // the box points are drawn in (scope, volume)
  bool solidIsBox_ = false;
  std::vector<Triangle> triangles_;  // the surface, or the solid's boundary
  std::vector<double> cumulativeArea_;
  double closestExponent_ = 0.0;  // gaussian on the surface: the least exponent on it
};

}  // namespace fgsg::rt::cga
