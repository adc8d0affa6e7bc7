// Subdiv: cuts a scope into consecutive slabs along one axis (CGA's split rule).
#include "runtime/cga/axis_names.h"
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

// Absolute sizes alone must add up to the scope length within this relative tolerance.
constexpr double kSumTol = 1e-9;

// How each kind of size turns into a length: absolute as given, floating and relative
// scaled by the factors that make the parts fill the scope.
struct LengthScales {
  double floating = 1.0;
  double relative = 0.0;
  double of(const SizeValue& s) const {
    switch (s.kind) {
      case SizeValue::Floating:
        return s.value * floating;
      case SizeValue::Relative:
        return s.value * relative;
      case SizeValue::Absolute:
        break;
    }
    return s.value;
  }
};

bool resolveScales(const std::vector<SizeValue>& sizes, int axis, double length,
                   LengthScales& scales, std::string& error) {
  double absolute = 0.0, floating = 0.0, relative = 0.0;
  for (const SizeValue& s : sizes) {
    if (!(s.value >= 0.0) || !std::isfinite(s.value)) {
      std::ostringstream m;
      m << "Subdiv along " << kAxisNames[axis] << ": size " << s.value
        << " must be a finite non-negative number";
      error = m.str();
      return false;
    }
    (s.kind == SizeValue::Absolute   ? absolute
     : s.kind == SizeValue::Floating ? floating
                                     : relative) += s.value;
  }
  const double tol = kSumTol * std::max(1.0, length);
  auto exceed = [&](double fixed, const char* what) {
    std::ostringstream m;
    m << "Subdiv along " << kAxisNames[axis] << ": " << what << " " << fixed
      << " exceed the scope length " << length;
    error = m.str();
    return false;
  };
  if (relative > 0.0) {
    // Floating sizes act as absolute ones; relative parts share what is left.
    const double rest = length - absolute - floating;
    if (rest < -tol)
      return exceed(absolute + floating,
                    floating > 0.0 ? "absolute and floating sizes" : "absolute sizes");
    scales.relative = std::max(rest, 0.0) / relative;
  } else if (floating > 0.0) {
    const double rest = length - absolute;
    if (rest < -tol) return exceed(absolute, "absolute sizes");
    scales.floating = std::max(rest, 0.0) / floating;
  } else if (std::abs(absolute - length) > tol) {
    std::ostringstream m;
    m << "Subdiv along " << kAxisNames[axis] << ": absolute sizes sum to " << absolute
      << " but the scope length is " << length
      << " (a relative size such as 1r or a floating size such as ~1 can absorb the difference)";
    error = m.str();
    return false;
  }
  return true;
}

}  // namespace

// `out` is replaced by the parts, one per size in order (zero-length parts included). Box,
// Edge and box-face geometry is shared by every part (no arena use); other polygons and
// polyhedra are clipped to each slab, and a part keeps the full slab as its scope even
// where its geometry covers less of it (CGA's behaviour). A part whose slab holds no area
// of the geometry is marked empty.
bool subdivide(const Scope& scope, const GeomRef& geom, int axis,
               const std::vector<SizeValue>& sizes, GeometryArena& arena, std::vector<Part>& out,
               std::string& error) {
  out.clear();
  if (axis < 0 || axis > 2) {
    error = "Subdiv: the axis must be X, Y or Z";
    return false;
  }
  if (sizes.empty()) {
    error = std::string("Subdiv along ") + kAxisNames[axis] + ": no sizes given";
    return false;
  }
  const double length = scope.S[axis];
  LengthScales scales;
  if (!resolveScales(sizes, axis, length, scales, error)) return false;

  // A scope of zero length along the axis keeps coordinate 0 there: nothing to clip.
  const bool shared = length <= 0.0 || isSlabInvariant(arena, geom);
  LocalGeometry whole;
  if (!shared) whole = loadGeometry(arena, geom);

  out.reserve(sizes.size());
  const Vec3 dir = scope.axes.col(axis);
  // One part is copied into place per size: cheaper than value-initialising each.
  Part part{scope, geom, false};
  double offset = 0.0;
  for (const SizeValue& s : sizes) {
    const double len = scales.of(s);
    part.scope.P = scope.P + dir * offset;
    part.scope.S[axis] = len;
    if (!shared) {
      const double lo = offset / length;
      const double hi = std::min((offset + len) / length, 1.0);
      LocalGeometry g = whole;
      const bool kept = clipToSlab(g, axis, lo, hi);
      if (kept) renormalise(g, axis, lo, hi);
      part.geom = kept ? storeGeometry(arena, g) : GeomRef{geom.kind, 0, 0};
      part.empty = !kept;
    }
    out.push_back(part);
    offset += len;
  }
  return true;
}

bool repeatPattern(const std::vector<SizeValue>& pattern, double length, int axis, std::vector<SizeValue>& sizes,
                   size_t& repeats, std::string& error) {
  double nominal = 0.0;
  bool floating = false;
  for (const SizeValue& s : pattern) {
    if (!(s.value >= 0.0) || !std::isfinite(s.value)) {
      std::ostringstream m;
      m << "Subdiv along " << kAxisNames[axis] << ": size " << s.value << " must be a finite non-negative number";
      error = m.str();
      return false;
    }
    nominal += s.value;
    floating |= s.kind == SizeValue::Floating;
  }
  if (!(nominal > 0.0)) {
    error = std::string("Subdiv along ") + kAxisNames[axis] + ": the repeated parts have no length";
    return false;
  }
  const double fits = length / nominal;
  const double tol = kSumTol * std::max(1.0, fits);
  const double count = floating ? std::max(1.0, std::round(fits)) : std::floor(fits + tol);
  if (!(count * pattern.size() <= double(1u << 24))) {
    std::ostringstream m;
    m << "Subdiv along " << kAxisNames[axis] << ": a pattern of length " << nominal << " repeats more than "
      << (1u << 24) << " parts on a length of " << length;
    error = m.str();
    return false;
  }
  repeats = static_cast<size_t>(count);
  sizes.clear();
  sizes.reserve(repeats * pattern.size() + 1);
  for (size_t r = 0; r < repeats; ++r) sizes.insert(sizes.end(), pattern.begin(), pattern.end());
  if (!floating) sizes.push_back({SizeValue::Absolute, std::max(0.0, length - count * nominal)});
  return true;
}

}  // namespace fgsg::rt::cga
