#include "cli/options.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace fgsg::cli {

std::vector<std::string> grammarDataDirs(const std::string& grammarFile) {
  const auto dir = std::filesystem::path(grammarFile).parent_path();
  return {(dir.empty() ? std::filesystem::path(".") : dir).string(), (dir / "assets").string()};
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool OptionReader::grammarFile(std::string& file) {
  if (!peek().empty() && peek()[0] == '-') return false;
  if (!file.empty()) throw UsageError{"more than one grammar file given ('" + file + "', '" + peek() + "')"};
  file = next();
  return true;
}

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

uint64_t OptionReader::unsignedValue(const std::string& flag, uint64_t lo, uint64_t hi) {
  std::string v = value(flag);
  char* end = nullptr;
  errno = 0;
  unsigned long long n = std::strtoull(v.c_str(), &end, 10);
  // strtoull skips blanks and accepts a sign: only plain digits are a whole number here.
  if (v.empty() || !std::isdigit(static_cast<unsigned char>(v[0])) || *end != '\0' || errno == ERANGE ||
      n < lo || n > hi)
    throw UsageError{flag + " expects a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + v + "'"};
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

void OptionReader::pointValue(const std::string& flag, double out[3]) {
  const std::string v = value(flag);
  auto bad = [&]() {
    return UsageError{flag + " expects a point x,y,z (three numbers separated by commas, e.g. " +
                      flag + " 0,0.5,1), got '" + v + "'"};
  };
  size_t from = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t comma = v.find(',', from);
    if ((k < 2) != (comma != std::string::npos)) throw bad();
    std::string part = v.substr(from, k < 2 ? comma - from : std::string::npos);
    const size_t first = part.find_first_not_of(" \t");
    const size_t last = part.find_last_not_of(" \t");
    if (first == std::string::npos) throw bad();
    part = part.substr(first, last - first + 1);
    char* end = nullptr;
    const double d = std::strtod(part.c_str(), &end);
    if (*end != '\0' || !std::isfinite(d)) throw bad();
    out[k] = d;
    from = comma + 1;
  }
}

}  // namespace fgsg::cli
