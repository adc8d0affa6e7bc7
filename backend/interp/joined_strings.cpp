#include "backend/interp/joined_strings.h"

#include "backend/interp/eval.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fgsg::backend {

std::string cityEngineNumberText(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == 0) return "0";  // -0 too
  char text[40];
  // Whole numbers below 2^53 exactly, without an exponent (1000000, not 1e+06).
  if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0) {
    std::snprintf(text, sizeof text, "%.0f", v);
    return text;
  }
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

std::string JoinedStrings::valueText(double v, ir::Type t) const {
  switch (t) {
    case ir::Type::Str: return text(v);
    case ir::Type::Bool: return v != 0 ? "true" : "false";
    default: return cityEngineNumberText(v);
  }
}

double JoinedStrings::join(double a, ir::Type ta, double b, ir::Type tb) {
  const std::string& left = valueText(a, ta);
  const std::string& right = valueText(b, tb);
  if (left.size() + right.size() > kMaxJoinedText)
    throw DeriveError{{}, "R020",
                      "a string joined with + would be " + std::to_string(left.size() + right.size()) +
                          " bytes, past the limit of 1 MiB: a rule that keeps joining a string ran away"};
  std::string s = left + right;
  for (; indexedModule_ < module_.size(); ++indexedModule_)
    ids_.emplace(module_[indexedModule_], static_cast<uint32_t>(indexedModule_));
  const auto [it, fresh] = ids_.emplace(std::move(s), static_cast<uint32_t>(module_.size() + joined_.size()));
  if (fresh) joined_.push_back(it->first);
  return it->second;
}

const std::string& JoinedStrings::text(double id) const {
  static const std::string kNone;
  if (!(id >= 0)) return kNone;
  const auto i = static_cast<size_t>(id);
  if (i < module_.size()) return module_[i];
  return i - module_.size() < joined_.size() ? joined_[i - module_.size()] : kNone;
}

}  // namespace fgsg::backend
