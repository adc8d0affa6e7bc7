#include "runtime/io/read_off.h"

#include "runtime/io/quoted_text.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace fgsg::rt::io {

namespace {

// Hands out the text line by line, comments removed, skipping lines with nothing left.
class OffLines {
 public:
  explicit OffLines(std::string_view text) : text_(text) {}

  // The tokens of the next line that has any; false at the end of the text.
  bool next(std::vector<std::string_view>& tokens) {
    tokens.clear();
    while (tokens.empty()) {
      if (pos_ >= text_.size()) return false;
      ++line_;
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view content = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      if (const size_t hash = content.find('#'); hash != std::string_view::npos)
        content = content.substr(0, hash);
      size_t i = 0;
      while (i < content.size()) {
        while (i < content.size() && isSpace(content[i])) ++i;
        const size_t start = i;
        while (i < content.size() && !isSpace(content[i])) ++i;
        if (i > start) tokens.push_back(content.substr(start, i - start));
      }
    }
    return true;
  }
  size_t line() const { return line_; }
  size_t bytesLeft() const { return pos_ >= text_.size() ? 0 : text_.size() - pos_; }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
  std::string_view text_;
  size_t pos_ = 0, line_ = 0;
};

bool parseInteger(std::string_view token, long long& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

bool parseNumber(std::string_view token, double& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

// The keyword's parts: [ST][C][N][4][n]OFF, optionally followed by BINARY.
struct Keyword {
  bool homogeneous = false;  // 4: a fourth coordinate w divides the others
  bool anyDimension = false;  // n: the dimension follows the keyword
};

bool parseKeyword(std::string_view word, Keyword& k) {
  if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return false;
  word.remove_suffix(3);
  for (std::string_view prefix : {"ST", "C", "N", "4", "n"})
    if (word.substr(0, prefix.size()) == prefix) {
      if (prefix == "4") k.homogeneous = true;
      if (prefix == "n") k.anyDimension = true;
      word.remove_prefix(prefix.size());
    }
  return word.empty();
}

}  // namespace

bool parseOff(const std::string& path, std::string_view text, MeshFileContent& out,
              std::string& error, Deadline* deadline) {
  OffLines lines(text);
  std::vector<std::string_view> tokens;
  const auto at = [&](size_t line) { return path + ":" + std::to_string(line) + ": "; };

  Keyword keyword;
  if (!lines.next(tokens) || !parseKeyword(tokens[0], keyword)) {
    error = at(lines.line() ? lines.line() : 1) +
            "cannot read the file: it does not start with an OFF keyword (OFF, COFF, NOFF, "
            "4OFF, ...)" +
            (tokens.empty() ? std::string() : ", found " + quoteText(tokens[0]));
    return false;
  }
  size_t next = 1;  // the counts may follow the keyword on its line
  if (next < tokens.size() && tokens[next] == "BINARY") {
    error = at(lines.line()) + "binary OFF is not supported (save the mesh as text OFF or PLY)";
    return false;
  }
  long long dimension = 3;
  if (keyword.anyDimension) {
    if (next == tokens.size()) {
      lines.next(tokens);  // none left: tokens stays empty
      next = 0;
    }
    if (next >= tokens.size() || !parseInteger(tokens[next], dimension) || dimension < 3 ||
        dimension > 16) {
      error = at(lines.line()) + "nOFF needs a dimension between 3 and 16 after the keyword";
      return false;
    }
    ++next;
  }
  const long long coordinates = dimension + (keyword.homogeneous ? 1 : 0);

  if (next == tokens.size()) {
    if (!lines.next(tokens)) {
      error = path + ": the file ends before the vertex and face counts";
      return false;
    }
    next = 0;
  }
  const size_t countLine = lines.line();
  long long counts[2];
  const char* const countName[2] = {"vertex", "face"};
  for (int i = 0; i < 2; ++i) {
    if (next + i >= tokens.size()) {
      error = at(countLine) + "expected the vertex, face and edge counts";
      return false;
    }
    const std::string_view t = tokens[next + i];
    if (!parseInteger(t, counts[i])) {
      error = at(countLine) + "the " + countName[i] + " count " + quoteText(t) +
              " is not a whole number";
      return false;
    }
    if (counts[i] < 0) {
      error = at(countLine) + "the " + countName[i] + " count " + std::to_string(counts[i]) +
              " is negative";
      return false;
    }
  }
  const long long nv = counts[0], nf = counts[1];
  // Each coordinate and each index takes at least a character and a separator; a face at
  // least three indices after its corner count. The last line may lack its newline.
  const long double need = (long double)nv * 2 * coordinates + (long double)nf * 8;
  if (need > (long double)lines.bytesLeft() + 1 || nv > std::numeric_limits<int>::max()) {
    error = at(countLine) + "the header declares " + std::to_string(nv) + " vertices and " +
            std::to_string(nf) + " faces, more than the " + std::to_string(lines.bytesLeft()) +
            " bytes after it can hold";
    return false;
  }

  out.vertices.reserve(size_t(nv));
  for (long long v = 0; v < nv; ++v) {
    if (deadline && deadline->expired()) {
      error = readStoppedMessage(path, *deadline);
      return false;
    }
    if (!lines.next(tokens)) {
      error = path + ": the file ends after " + std::to_string(v) + " of " + std::to_string(nv) +
              " vertices";
      return false;
    }
    if ((long long)tokens.size() < coordinates) {
      error = at(lines.line()) + "vertex " + std::to_string(v) + " has " +
              std::to_string(tokens.size()) + " coordinates, expected " +
              std::to_string(coordinates);
      return false;
    }
    double x[4] = {0, 0, 0, 1};
    for (long long c = 0; c < coordinates; ++c) {
      double value = 0;
      const std::string_view t = tokens[size_t(c)];
      if (!parseNumber(t, value)) {
        error = at(lines.line()) + "vertex coordinate " + quoteText(t) + " is not a number";
        return false;
      }
      if (!std::isfinite(value)) {
        error = at(lines.line()) + "vertex coordinate " + quoteText(t) +
                " is not a finite number";
        return false;
      }
      if (c < 3) x[c] = value;
      if (keyword.homogeneous && c == coordinates - 1) x[3] = value;
    }
    if (keyword.homogeneous) {
      if (x[3] == 0) {
        error = at(lines.line()) + "vertex " + std::to_string(v) +
                " has the homogeneous coordinate 0 (a point at infinity)";
        return false;
      }
      for (int c = 0; c < 3; ++c) x[c] /= x[3];
    }
    out.vertices.push_back({x[0], x[1], x[2]});
  }

  out.corners.reserve(size_t(nf) * 3);
  out.polygonStart.reserve(size_t(nf) + 1);
  for (long long f = 0; f < nf; ++f) {
    if (deadline && deadline->expired()) {
      error = readStoppedMessage(path, *deadline);
      return false;
    }
    if (!lines.next(tokens)) {
      error = path + ": the file ends after " + std::to_string(f) + " of " + std::to_string(nf) +
              " faces";
      return false;
    }
    long long k = 0;
    if (!parseInteger(tokens[0], k)) {
      error = at(lines.line()) + "face " + std::to_string(f) + ": the corner count '" +
              std::string(tokens[0]) + "' is not a whole number";
      return false;
    }
    if (k < 3) {
      error = at(lines.line()) + "face " + std::to_string(f) + " has " + std::to_string(k) +
              " corners (a face needs at least 3)";
      return false;
    }
    if (k > (long long)tokens.size() - 1) {
      error = at(lines.line()) + "face " + std::to_string(f) + " lists " + std::to_string(k) +
              " corners, but the line holds only " + std::to_string(tokens.size() - 1) +
              " numbers after the count";
      return false;
    }
    for (long long c = 1; c <= k; ++c) {
      long long v = 0;
      const std::string_view t = tokens[size_t(c)];
      if (!parseInteger(t, v)) {
        error = at(lines.line()) + "face " + std::to_string(f) + ": the vertex index '" +
                std::string(t) + "' is not a whole number";
        return false;
      }
      if (v < 0 || v >= nv) {
        error = at(lines.line()) + "face " + std::to_string(f) + " refers to vertex " +
                std::to_string(v) + ", but there are only " + std::to_string(nv) + " vertices";
        return false;
      }
      out.corners.push_back(int(v));
    }
    out.polygonStart.push_back(out.corners.size());
  }
  return true;
}

}  // namespace fgsg::rt::io
