#include "runtime/reports.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

namespace fgsg::rt {

std::string reportValueText(const ReportValue& v) {
  switch (v.kind) {
    case ReportValue::Kind::Boolean: return v.number != 0 ? "true" : "false";
    case ReportValue::Kind::String: return v.text;
    case ReportValue::Kind::Number: break;
  }
  if (std::isnan(v.number)) return "nan";
  if (std::isinf(v.number)) return v.number > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v.number);
  return std::string(buf, r.ptr);
}

namespace {

// Adds one value to a collection's statistics.
void add(ReportCollection& c, const ReportValue& v, std::map<std::string, uint64_t>& strings) {
  c.values.push_back(v);
  if (v.kind == ReportValue::Kind::String) {
    ++strings[v.text];
    return;
  }
  const double x = v.number;
  c.min = c.numeric == 0 || x < c.min ? x : c.min;
  c.max = c.numeric == 0 || x > c.max ? x : c.max;
  c.sum += x;
  ++c.numeric;
  if (x != 0) ++c.nonZero;
}

// The collections of `reports`, sorted by key.
std::vector<ReportCollection> collect(const std::vector<Report>& reports) {
  std::map<std::string, std::pair<ReportCollection, std::map<std::string, uint64_t>>> byKey;
  for (const Report& r : reports) {
    auto& [c, strings] = byKey[r.key];
    c.key = r.key;
    add(c, r.value, strings);
  }
  std::vector<ReportCollection> out;
  out.reserve(byKey.size());
  for (auto& [key, entry] : byKey) {
    ReportCollection& c = entry.first;
    if (c.numeric) c.average = c.sum / double(c.numeric);
    c.stringCounts.assign(entry.second.begin(), entry.second.end());
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

std::vector<std::vector<ReportCollection>> collectReports(const std::vector<Report>& reports, size_t starts) {
  std::vector<std::vector<ReportCollection>> out(starts);
  if (starts == 0) return out;
  std::vector<std::vector<Report>> byStart(starts);
  for (const Report& r : reports) byStart[std::min<size_t>(r.start, starts - 1)].push_back(r);
  for (size_t s = 0; s < starts; ++s) out[s] = collect(byStart[s]);
  return out;
}

std::vector<ReportCollection> collectAllReports(const std::vector<Report>& reports) {
  return collect(reports);
}

}  // namespace fgsg::rt
