#include "runtime/io/write_reports.h"

#include "runtime/io/json_text.h"

#include <algorithm>

namespace fgsg::rt::io {
namespace {

void appendValue(std::string& out, const ReportValue& v) {
  switch (v.kind) {
    case ReportValue::Kind::Number: appendJsonNumber(out, v.number); break;
    case ReportValue::Kind::Boolean: out += v.number != 0 ? "true" : "false"; break;
    case ReportValue::Kind::String: appendJsonString(out, v.text); break;
  }
}

void appendCollections(std::string& out, const std::vector<ReportCollection>& collections) {
  out += '{';
  for (size_t k = 0; k < collections.size(); ++k) {
    const ReportCollection& c = collections[k];
    if (k) out += ',';
    appendJsonString(out, c.key);
    out += ":{\"values\":[";
    for (size_t i = 0; i < c.values.size(); ++i) {
      if (i) out += ',';
      appendValue(out, c.values[i]);
    }
    out += "],\"count\":" + std::to_string(c.values.size());
    if (c.numeric) {
      out += ",\"sum\":";
      appendJsonNumber(out, c.sum);
      out += ",\"average\":";
      appendJsonNumber(out, c.average);
      out += ",\"min\":";
      appendJsonNumber(out, c.min);
      out += ",\"max\":";
      appendJsonNumber(out, c.max);
      out += ",\"nnz\":" + std::to_string(c.nonZero);
    }
    if (!c.stringCounts.empty()) {
      out += ",\"strings\":{";
      for (size_t i = 0; i < c.stringCounts.size(); ++i) {
        if (i) out += ',';
        appendJsonString(out, c.stringCounts[i].first);
        out += ':' + std::to_string(c.stringCounts[i].second);
      }
      out += '}';
    }
    out += '}';
  }
  out += '}';
}

}  // namespace

std::string encodeReportsJson(const DeriveResult& result, const std::vector<Lot>& lots) {
  const auto& bounds = result.instances.startBounds;
  const size_t starts = std::max<size_t>({lots.size(), bounds.size() > 1 ? bounds.size() - 1 : 1, 1});
  const auto perStart = collectReports(result.reports, starts);
  std::string out = "{\"format\":\"fgsg-reports\",\"version\":1,\"starts\":[\n";
  for (size_t s = 0; s < starts; ++s) {
    out += "{\"start\":" + std::to_string(s);
    if (s < lots.size()) {
      const Lot& lot = lots[s];
      out += std::string(",\"lot\":{\"") + (lot.isFace ? "face" : "feature") + "\":" + std::to_string(lot.feature) +
             ",\"part\":" + std::to_string(lot.part) + ",\"id\":";
      appendJsonString(out, lot.id);
      out += '}';
    }
    out += ",\"reports\":";
    appendCollections(out, perStart[s]);
    out += s + 1 < starts ? "},\n" : "}\n";
  }
  out += "],\n\"all\":";
  appendCollections(out, collectAllReports(result.reports));
  out += "}\n";
  return out;
}

bool stageReportsJson(const DeriveResult& result, const std::vector<Lot>& lots, const std::string& path,
                      OutputTransaction& outputs, std::string& error) {
  return outputs.stage(path, encodeReportsJson(result, lots), error);
}

}  // namespace fgsg::rt::io
