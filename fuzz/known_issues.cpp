#include "fuzz/known_issues.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>

namespace fgsg::fuzz {
namespace {

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Reads the next whitespace-separated token from `text` at `pos`, skipping `#` comments.
std::string_view nextToken(std::string_view text, size_t& pos) {
  while (pos < text.size()) {
    if (isSpace(text[pos])) {
      ++pos;
    } else if (text[pos] == '#') {
      while (pos < text.size() && text[pos] != '\n') ++pos;
    } else {
      break;
    }
  }
  const size_t begin = pos;
  while (pos < text.size() && !isSpace(text[pos])) ++pos;
  return text.substr(begin, pos - begin);
}

// The token as a count; -1 for anything that is not a plain non-negative integer, and a
// huge value for one too long to hold.
long long asCount(std::string_view token) {
  if (token.empty() || token.size() > 15) return token.empty() ? -1 : (1LL << 60);
  for (char c : token)
    if (!isDigit(c)) return -1;
  return std::atoll(std::string(token).c_str());
}

}  // namespace

bool filtersOn() {
  static const bool on = [] {
    const char* all = std::getenv("FGSG_FUZZ_ALL_INPUTS");
    return !(all && std::string(all) == "1");
  }();
  return on;
}

bool hasOverflowingParallelCount(std::string_view text) {
  if (!filtersOn()) return false;
  for (size_t at = text.find("parallel"); at != std::string_view::npos;
       at = text.find("parallel", at + 1)) {
    size_t p = at + 8;
    while (p < text.size() && !isDigit(text[p]) && p < at + 64) ++p;
    size_t digits = 0;
    while (p + digits < text.size() && (isDigit(text[p + digits]) || text[p + digits] == '.')) ++digits;
    if (digits >= 10 || text.substr(p, 16).find_first_of("eE") != std::string_view::npos) return true;
  }
  return false;
}

bool namesDeviceFile(std::string_view text) {
  return filtersOn() && text.find("/dev") != std::string_view::npos;
}

bool hasHugeNumber(std::string_view text) {
  if (!filtersOn()) return false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (!isDigit(text[i]) || (i > 0 && (std::isalpha(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_')))
      continue;
    size_t intDigits = 0;
    while (i < text.size() && isDigit(text[i])) ++i, ++intDigits;
    if (intDigits > 6) return true;
    while (i < text.size() && (isDigit(text[i]) || text[i] == '.')) ++i;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      size_t j = i + 1;
      if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
      size_t expDigits = 0;
      int exponent = 0;
      while (j < text.size() && isDigit(text[j])) exponent = exponent * 10 + (text[j++] - '0'), ++expDigits;
      if (expDigits > 2 || exponent >= 6) return true;
      i = j;
    }
  }
  return false;
}

bool hasImpossibleMeshCounts(std::string_view text) {
  if (!filtersOn()) return false;
  size_t pos = 0;
  const std::string_view magic = nextToken(text, pos);
  if (magic.size() >= 3 && magic.substr(magic.size() - 3) == "OFF") {
    // [ST][C][N][4]OFF, then vertex, face and edge counts.
    const long long nv = asCount(nextToken(text, pos));
    const long long nf = asCount(nextToken(text, pos));
    if (nv < 0 || nf < 0) return true;  // negative or malformed counts
    // Every vertex and face needs at least two characters.
    if (nv > static_cast<long long>(text.size()) || nf > static_cast<long long>(text.size())) return true;
    // A face line with a negative corner count (repro 09): a line of four or more tokens
    // whose first is a negative integer (vertex lines hold three coordinates).
    for (size_t nl = text.find('\n', pos); nl != std::string_view::npos; nl = text.find('\n', nl + 1)) {
      const size_t end = std::min(text.find('\n', nl + 1), text.size());
      std::string_view line = text.substr(nl + 1, end - nl - 1);
      size_t q = 0;
      const std::string_view first = nextToken(line, q);
      if (first.size() < 2 || first[0] != '-' || asCount(first.substr(1)) < 0) continue;
      int tokens = 1;
      while (!nextToken(line, q).empty()) ++tokens;
      if (tokens >= 4) return true;
    }
    return false;
  }
  if (magic == "ply") {
    // "element NAME COUNT" lines: binary bodies make any count possible to claim.
    for (size_t at = text.find("element"); at != std::string_view::npos; at = text.find("element", at + 1)) {
      size_t p = at + 7;
      nextToken(text, p);
      const long long n = asCount(nextToken(text, p));
      if (n < 0 || n > static_cast<long long>(text.size())) return true;
    }
  }
  return false;
}

bool hasObjCornerWithoutVertex(std::string_view text) {
  if (!filtersOn()) return false;
  for (size_t lineStart = 0; lineStart < text.size();) {
    size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string_view::npos) lineEnd = text.size();
    const std::string_view line = text.substr(lineStart, lineEnd - lineStart);
    size_t q = 0;
    if (nextToken(line, q) == "f") {
      // Any corner whose vertex field is empty or not a number.
      for (std::string_view corner = nextToken(line, q); !corner.empty(); corner = nextToken(line, q)) {
        const char c = corner[0];
        if (!(isDigit(c) || ((c == '-' || c == '+') && corner.size() > 1 && isDigit(corner[1])))) return true;
      }
    }
    lineStart = lineEnd + 1;
  }
  return false;
}

bool hasUnreadablePlyVersion(std::string_view text) {
  if (!filtersOn() || text.substr(0, 3) != "ply") return false;
  const size_t at = text.find("format");
  if (at == std::string_view::npos) return false;
  size_t pos = at + 6;
  nextToken(text, pos);  // ascii / binary_little_endian / binary_big_endian
  const size_t lineEnd = text.find('\n', at);
  const size_t versionAt = text.find_first_not_of(" \t", pos);
  return versionAt == std::string_view::npos || versionAt >= lineEnd ||
         text.substr(versionAt, 4).find("1.0") != 0 ||
         (versionAt + 3 < text.size() && !isSpace(text[versionAt + 3]));
}

}  // namespace fgsg::fuzz
