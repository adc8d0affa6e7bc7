// What CGA's report(key, value) and print(value) leave: every reported value with its
// key and start shape (a --lots lot, a seed derived apart, else the one axiom), in the
// order the derivation reported them, and every printed line with the place that printed
// it. As CityEngine's Reports shelf does, reports of one key within a start shape form a
// collection summed up by count, sum, average, minimum and maximum (collectReports); the
// JSON file (runtime/io/write_reports.h), Python and the C API read them from here.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::rt {

struct ReportValue {
  enum class Kind : uint8_t { Number, Boolean, String } kind = Kind::Number;
  double number = 0;  // Number; Boolean 0/1
  std::string text;   // String
};

struct Report {
  uint32_t start = 0;  // the start shape that reported it
  std::string key;
  ReportValue value;
};

struct PrintLine {
  uint32_t start = 0;
  int line = 0, col = 0;  // the Print command in the grammar
  std::string text;
};

// A value as print() writes it: the shortest text of a number that reads back as the same
// double ("0.1", "3", "1e+30"), true/false, a string as it is.
std::string reportValueText(const ReportValue& v);

// One key's values within a start shape (or across all of them), with CityEngine's
// statistics. Numbers and booleans (true as 1) are summed up; strings are counted by value.
struct ReportCollection {
  std::string key;
  std::vector<ReportValue> values;  // in the order reported
  uint64_t numeric = 0;             // numbers and booleans among the values
  double sum = 0, min = 0, max = 0, average = 0;  // over those (0 when there are none)
  uint64_t nonZero = 0;             // of those, the ones that are not 0 (CityEngine's NNZ)
  std::vector<std::pair<std::string, uint64_t>> stringCounts;  // each string value and how often, sorted
};

// The collections of each start shape (`starts` of them; reports of a start at or past it
// go to the last), each start's sorted by key (byte order, so "windows.open" sits by
// "windows.closed"). Sums run in reporting order, so every engine gives the same bits.
std::vector<std::vector<ReportCollection>> collectReports(const std::vector<Report>& reports, size_t starts);
// The collections of the whole derivation, every start shape's reports together.
std::vector<ReportCollection> collectAllReports(const std::vector<Report>& reports);

}  // namespace fgsg::rt
