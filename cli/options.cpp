#include "cli/options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace fgsg::cli {

std::string OptionReader::flag() {
  std::string a = next();
  hasPending_ = false;
  auto eq = a.find('=');
  if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
    pending_ = a.substr(eq + 1);
    hasPending_ = true;
    a = a.substr(0, eq);
  }
  return a;
}

std::string OptionReader::value(const std::string& flag) {
  if (hasPending_) {
    hasPending_ = false;
    return pending_;
  }
  if (done()) throw UsageError{flag + " needs a value"};
  return next();
}

uint64_t OptionReader::unsignedValue(const std::string& flag) {
  std::string v = value(flag);
  char* end = nullptr;
  errno = 0;
  unsigned long long n = std::strtoull(v.c_str(), &end, 10);
  if (v.empty() || v[0] == '-' || *end != '\0' || errno == ERANGE)
    throw UsageError{flag + " expects a whole number >= 0, got '" + v + "'"};
  return n;
}

double OptionReader::numberValue(const std::string& flag) {
  std::string v = value(flag);
  char* end = nullptr;
  double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(d))
    throw UsageError{flag + " expects a number, got '" + v + "'"};
  return d;
}

}  // namespace fgsg::cli
