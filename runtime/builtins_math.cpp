#include "runtime/builtins_math.h"
#include "runtime/random.h"

#include "runtime/scope.h"

#include <cmath>

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

}  // namespace

extern "C" {

double fgsg_rt_sin_deg(double x) noexcept { return std::sin(x * kDegToRad); }
double fgsg_rt_cos_deg(double x) noexcept { return std::cos(x * kDegToRad); }
double fgsg_rt_tan_deg(double x) noexcept { return std::tan(x * kDegToRad); }
double fgsg_rt_asin_deg(double x) noexcept { return std::asin(x) / kDegToRad; }
double fgsg_rt_acos_deg(double x) noexcept { return std::acos(x) / kDegToRad; }
double fgsg_rt_atan_deg(double x) noexcept { return std::atan(x) / kDegToRad; }
double fgsg_rt_atan2_deg(double y, double x) noexcept { return std::atan2(y, x) / kDegToRad; }
double fgsg_rt_fmod(double x, double y) noexcept { return std::fmod(x, y); }
double fgsg_rt_pow(double x, double y) noexcept { return std::pow(x, y); }
double fgsg_rt_exp(double x) noexcept { return std::exp(x); }
double fgsg_rt_log(double x) noexcept { return std::log(x); }
double fgsg_rt_round(double x) noexcept { return std::round(x); }

double fgsg_rt_rand_scale(double lo, double hi, double u) noexcept { return lo + (hi - lo) * u; }

// Eigen's reductions, exactly as the interpreter computed them before they moved here.
double fgsg_rt_vec_length(double x, double y, double z) noexcept {
  return fgsg::rt::Vec3(x, y, z).norm();
}
double fgsg_rt_vec_dot(double ax, double ay, double az, double bx, double by, double bz) noexcept {
  return fgsg::rt::Vec3(ax, ay, az).dot(fgsg::rt::Vec3(bx, by, bz));
}

}  // extern "C"

extern "C" uint64_t fgsg_rt_child_key(uint64_t parent, uint64_t index) noexcept {
  return fgsg::rt::childKey(parent, index);
}

extern "C" void fgsg_rt_cos_sin_deg(double degrees, double* out) noexcept {
  fgsg::rt::cosSinDegrees(degrees, out[0], out[1]);
}
