#include "runtime/synthesis/continuous/directions.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fgsg::rt::synthesis::continuous {

namespace {

DVec3 toD(const IVec3& a) { return {double(a[0]), double(a[1]), double(a[2])}; }
double norm(const DVec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
DVec3 normalized(const DVec3& v) {
  const double n = norm(v);
  return {v[0] / n, v[1] / n, v[2] / n};
}
DVec3 crossd(const DVec3& a, const DVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

IVec3 canonicalDirection(IVec3 a) {
  const int64_t g = std::gcd(std::gcd(std::abs(a[0]), std::abs(a[1])), std::abs(a[2]));
  if (g == 0) return a;
  for (auto& c : a) c /= g;
  const int64_t first = a[0] != 0 ? a[0] : a[1] != 0 ? a[1] : a[2];
  if (first < 0)
    for (auto& c : a) c = -c;
  return a;
}

std::optional<IVec3> snapToIntegerDirection(const DVec3& n, int maxComponent, double toleranceRadians) {
  const DVec3 u = normalized(n);
  const double biggest = std::max({std::abs(u[0]), std::abs(u[1]), std::abs(u[2])});
  for (int m = 1; m <= maxComponent; ++m) {
    // Scale so the largest component is m, round, and measure the angle.
    IVec3 a{};
    for (int i = 0; i < 3; ++i) a[size_t(i)] = int64_t(std::llround(u[size_t(i)] / biggest * m));
    if (isZero(a)) continue;
    const DVec3 v = normalized(toD(a));
    const double c = std::clamp(v[0] * u[0] + v[1] * u[1] + v[2] * u[2], -1.0, 1.0);
    if (std::acos(c) <= toleranceRadians) return canonicalDirection(a);
  }
  return std::nullopt;
}

std::vector<DVec3> wedgesAround(const IVec3& axis, const std::vector<IVec3>& around) {
  const DVec3 w = normalized(toD(axis));
  // A basis (b1, b2) of the plane perpendicular to the axis.
  const DVec3 helper = std::abs(w[0]) < 0.6 ? DVec3{1, 0, 0} : DVec3{0, 1, 0};
  const DVec3 b1 = normalized(crossd(w, helper));
  const DVec3 b2 = crossd(w, b1);
  if (around.empty()) return {b1};
  std::vector<double> angles;
  constexpr double kPi = 3.14159265358979323846;
  for (const IVec3& a : around) {
    const double n1 = dotd(a, b1), n2 = dotd(a, b2);
    double phi = std::atan2(n2, n1) + kPi / 2;  // the plane's trace: perpendicular to its normal
    for (int k = 0; k < 2; ++k, phi += kPi) angles.push_back(std::fmod(phi + 4 * kPi, 2 * kPi));
  }
  std::sort(angles.begin(), angles.end());
  std::vector<DVec3> out;
  for (size_t i = 0; i < angles.size(); ++i) {
    const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * kPi;
    const double mid = 0.5 * (angles[i] + next);
    if (next - angles[i] < 1e-12) continue;  // the same trace twice
    const double c = std::cos(mid), s = std::sin(mid);
    out.push_back({c * b1[0] + s * b2[0], c * b1[1] + s * b2[1], c * b1[2] + s * b2[2]});
  }
  return out;
}

std::optional<uint32_t> signMaskNear(const std::vector<IVec3>& dirs, uint32_t mask, const IVec3& axis, const DVec3& r) {
  uint32_t signs = 0;
  for (uint32_t m = mask; m; m &= m - 1) {
    const int e = __builtin_ctz(m);
    const int64_t s = dot(dirs[size_t(e)], axis);
    if (s > 0) {
      signs |= 1u << e;
    } else if (s == 0) {
      const double t = dotd(dirs[size_t(e)], r);
      // Wedge directions sit mid-way between traces; anything this small lies on one.
      if (std::abs(t) < 1e-9) return std::nullopt;
      if (t > 0) signs |= 1u << e;
    }
  }
  return signs;
}

std::vector<Sector> sectorsOf(const std::vector<IVec3>& dirs, uint32_t mask) {
  std::vector<int> list;
  for (uint32_t m = mask; m; m &= m - 1) list.push_back(__builtin_ctz(m));
  std::vector<Sector> out;
  if (list.empty()) return {Sector{0, {1, 0, 0}}};
  if (list.size() == 1) {
    const DVec3 a = normalized(toD(dirs[size_t(list[0])]));
    return {Sector{1u << list[0], a}, Sector{0, {-a[0], -a[1], -a[2]}}};
  }
  auto known = [&](uint32_t s) {
    return std::any_of(out.begin(), out.end(), [&](const Sector& x) { return x.signs == s; });
  };
  for (size_t i = 0; i < list.size(); ++i)
    for (size_t j = i + 1; j < list.size(); ++j) {
      const IVec3 u = cross(dirs[size_t(list[i])], dirs[size_t(list[j])]);
      for (int side = 0; side < 2; ++side) {
        const IVec3 U = side == 0 ? u : IVec3{-u[0], -u[1], -u[2]};
        std::vector<IVec3> around;
        for (int e : list)
          if (dot(dirs[size_t(e)], U) == 0) around.push_back(dirs[size_t(e)]);
        const DVec3 un = normalized(toD(U));
        for (const DVec3& r : wedgesAround(U, around)) {
          const auto signs = signMaskNear(dirs, mask, U, r);
          if (!signs || known(*signs)) continue;
          // A real direction in the sector: the vertex direction tilted towards the wedge,
          // little enough that no plane off the vertex changes sign.
          DVec3 d{};
          for (double delta = 0.5; delta > 1e-12; delta *= 0.5) {
            d = normalized({un[0] + delta * r[0], un[1] + delta * r[1], un[2] + delta * r[2]});
            bool same = true;
            for (int e : list) {
              const double t = dotd(dirs[size_t(e)], d);
              const bool positive = (*signs >> e) & 1;
              if (std::abs(t) < 1e-12 || (t > 0) != positive) { same = false; break; }
            }
            if (same) break;
          }
          out.push_back({*signs, d});
        }
      }
    }
  return out;
}

}  // namespace fgsg::rt::synthesis::continuous
