#include "runtime/output/start_extras.h"

#include <cmath>
#include <cstdint>

namespace fgsg::rt::output {

namespace {

using nlohmann::json;

// A number as JSON as the reports file writes it: a whole one without a fraction ("12",
// not "12.0"), one that is not finite as null.
json number(double x) {
  if (!std::isfinite(x)) return nullptr;
  if (x == std::trunc(x) && std::abs(x) < 9007199254740992.0) return int64_t(x);  // 2^53
  return x;
}

json reportValue(const ReportValue& v) {
  switch (v.kind) {
    case ReportValue::Kind::Number: return number(v.number);
    case ReportValue::Kind::Boolean: return v.number != 0;
    case ReportValue::Kind::String: return v.text;
  }
  return nullptr;
}

json collection(const ReportCollection& c) {
  json values = json::array();
  for (const ReportValue& v : c.values) values.push_back(reportValue(v));
  json out = {{"values", std::move(values)}, {"count", c.values.size()}};
  if (c.numeric) {
    out["sum"] = number(c.sum);
    out["average"] = number(c.average);
    out["min"] = number(c.min);
    out["max"] = number(c.max);
    out["nnz"] = c.nonZero;
  }
  if (!c.stringCounts.empty()) {
    json strings = json::object();
    for (const auto& [text, count] : c.stringCounts) strings[text] = count;
    out["strings"] = std::move(strings);
  }
  return out;
}

json attrValue(const StartAttr& a) {
  switch (a.kind) {
    case StartAttr::Kind::Number: return number(a.number[0]);
    case StartAttr::Kind::Boolean: return a.number[0] != 0;
    case StartAttr::Kind::String: return a.text;
    case StartAttr::Kind::Vector: return json::array({number(a.number[0]), number(a.number[1]), number(a.number[2])});
  }
  return nullptr;
}

}  // namespace

json startExtras(const StartNode& s) {
  json extras = {{"start", s.index}, {"instances", s.instanceCount}};
  json properties = json::object();
  for (const auto& [key, value] : s.info.numbers) properties[key] = number(value);
  for (const auto& [key, value] : s.info.strings) properties[key] = value;
  if (!properties.empty()) extras["properties"] = std::move(properties);
  if (!s.info.attrs.empty()) {
    json attrs = json::object();
    for (const StartAttr& a : s.info.attrs) attrs[a.name] = attrValue(a);
    extras["attrs"] = std::move(attrs);
  }
  if (!s.info.reports.empty()) {
    json reports = json::object();
    for (const ReportCollection& c : s.info.reports) reports[c.key] = collection(c);
    extras["reports"] = std::move(reports);
  }
  return extras;
}

}  // namespace fgsg::rt::output
