#include "runtime/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <string>

namespace fgsg::rt {

std::optional<uint64_t> parseMemorySize(const std::string& text) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (...) {
    return std::nullopt;
  }
  if (!std::isdigit(static_cast<unsigned char>(text[0])) && text[0] != '.') return std::nullopt;
  std::string unit;
  for (size_t i = used; i < text.size(); ++i) unit += static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
  double scale = 1;
  if (!unit.empty()) {
    const char head = unit[0];
    const std::string tail = unit.substr(1);
    const char* units = "BKMGT";
    const char* at = std::strchr(units, head);
    if (!at) return std::nullopt;
    if (head == 'B' ? !tail.empty() : !(tail.empty() || tail == "B" || tail == "IB")) return std::nullopt;
    scale = std::pow(1024.0, double(at - units));
  }
  const double bytes = std::floor(value * scale);
  if (!(bytes >= 1) || bytes > std::ldexp(1.0, 62)) return std::nullopt;
  return static_cast<uint64_t>(bytes);
}

std::string formatMemorySize(uint64_t bytes) {
  static const char* const kUnits[] = {"B", "K", "M", "G", "T"};
  double v = double(bytes);
  int u = 0;
  while (v >= 1024 && u < 4) v /= 1024, ++u;
  char text[32];
  if (v == std::floor(v)) std::snprintf(text, sizeof text, "%.0f%s", v, kUnits[u]);
  else std::snprintf(text, sizeof text, "%.1f%s", v, kUnits[u]);
  return text;
}

namespace {

// cgroup v2's memory.max ("max" or a number); 0 when absent or unlimited.
uint64_t cgroupLimitBytes() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string word;
  if (!(in >> word) || word == "max") return 0;
  try {
    return std::stoull(word);
  } catch (...) {
    return 0;
  }
}

}  // namespace

uint64_t availableMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  uint64_t bytes = pages > 0 && size > 0 ? uint64_t(pages) * uint64_t(size) : 0;
  const uint64_t cgroup = cgroupLimitBytes();
  if (cgroup > 0 && (bytes == 0 || cgroup < bytes)) bytes = cgroup;
  return bytes;
}

uint64_t defaultMemoryBudget() {
  const uint64_t bytes = availableMemoryBytes();
  return bytes > 0 ? bytes / 2 : uint64_t(4) << 30;
}

uint64_t readerMemoryLimit(uint64_t maxMemoryBytes) {
  uint64_t limit = maxMemoryBytes ? maxMemoryBytes : defaultMemoryBudget();
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) limit = std::min<uint64_t>(limit, as.rlim_cur / 4 * 3);
  return limit;
}

uint64_t residentMemoryBytes() {
  // statm: total and resident size in pages. Read with stdio: no allocation that could
  // itself fail when memory is short.
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long long total = 0, resident = 0;
  const int n = std::fscanf(f, "%llu %llu", &total, &resident);
  std::fclose(f);
  const long size = sysconf(_SC_PAGE_SIZE);
  return n == 2 && size > 0 ? resident * uint64_t(size) : 0;
}

}  // namespace fgsg::rt
