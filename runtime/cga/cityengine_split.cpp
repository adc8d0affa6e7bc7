// CityEngine's split sizing for the `.cga` dialect (rt::cga::cityEngineSizes): what is
// left empty and what is cut, instead of fgsg's "parts fill the scope" (R002).
#include "runtime/cga/axis_names.h"
#include "runtime/cga/cga.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::cga {
namespace {

// A part shorter than this (relative to the scope) is not generated: what a cut leaves
// of it is rounding.
constexpr double kMinPart = 1e-9;
// A repeat never writes out more parts than this (a 1 mm pattern on a 10 km scope).
constexpr double kMaxRepeats = 1u << 20;

}  // namespace

bool cityEngineSizes(const std::vector<SizeValue>& parts, double length, int axis, bool repeat,
                     std::vector<SizeValue>& sizes, std::vector<bool>& derived, size_t& patternLength,
                     std::string& error) {
  sizes.clear();
  derived.clear();
  patternLength = parts.size();
  for (const SizeValue& s : parts)
    if (!std::isfinite(s.value)) {
      std::ostringstream m;
      m << "split along " << kAxisNames[axis] << ": size " << s.value << " is not a finite number";
      error = m.str();
      return false;
    }
  length = std::max(length, 0.0);
  std::vector<SizeValue> all = parts;
  if (repeat) {
    double nominal = 0.0;
    bool floating = false;
    for (const SizeValue& s : parts) {
      nominal += std::max(s.value, 0.0);
      floating |= s.kind == SizeValue::Floating;
    }
    if (!(nominal > 0.0)) {
      error = std::string("split along ") + kAxisNames[axis] + ": the repeated parts have no length";
      return false;
    }
    const double fits = length / nominal;
    double n = floating ? std::max(1.0, std::round(fits)) : std::max(1.0, std::ceil(fits - kMinPart));
    if (n > kMaxRepeats) {
      std::ostringstream m;
      m << "split along " << kAxisNames[axis] << ": a pattern " << nominal << " long repeats more than "
        << kMaxRepeats << " times on " << length;
      error = m.str();
      return false;
    }
    all.clear();
    for (double k = 0; k < n; ++k) all.insert(all.end(), parts.begin(), parts.end());
  }
  double absolute = 0.0, floating = 0.0, relative = 0.0;
  for (const SizeValue& s : all) {
    if (s.value <= 0.0) continue;
    (s.kind == SizeValue::Absolute ? absolute : s.kind == SizeValue::Floating ? floating : relative) += s.value;
  }
  double floatScale = 1.0, relativeScale = 0.0;
  if (relative > 0.0) {
    relativeScale = std::max(length - absolute - floating, 0.0) / relative;
  } else if (floating > 0.0) {
    floatScale = std::max(length - absolute, 0.0) / floating;
  }
  double offset = 0.0;
  const double tiny = kMinPart * std::max(1.0, length);
  for (const SizeValue& s : all) {
    double len = s.value <= 0.0                      ? 0.0
                 : s.kind == SizeValue::Floating ? s.value * floatScale
                 : s.kind == SizeValue::Relative ? s.value * relativeScale
                                                 : s.value;
    len = std::min(len, length - offset);
    const bool keep = len > tiny;
    if (!keep) len = 0.0;
    sizes.push_back({SizeValue::Absolute, len});
    derived.push_back(keep);
    offset += len;
  }
  if (length - offset > tiny) {
    sizes.push_back({SizeValue::Absolute, length - offset});
    derived.push_back(false);
  } else if (!sizes.empty()) {
    // What rounding left: the last part that has length takes it, so the sizes add up.
    for (size_t k = sizes.size(); k-- > 0;)
      if (derived[k]) {
        sizes[k].value += length - offset;
        break;
      }
  }
  return true;
}

}  // namespace fgsg::rt::cga
