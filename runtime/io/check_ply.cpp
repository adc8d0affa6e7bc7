#include "runtime/io/check_ply.h"

#include "runtime/io/quoted_text.h"

#include <charconv>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <vector>

namespace fgsg::rt::io {

namespace {

// Size in bytes of a PLY scalar type, or 0 when the name is not one.
int typeSize(std::string_view t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
      t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

bool typeSigned(std::string_view t) {
  return t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" ||
         t == "int32";
}

struct Property {
  int size = 0;          // scalar, or the items of a list
  int countSize = 0;     // a list's length field; 0 for a scalar
  bool countSigned = false;
  std::string name;
};

struct Element {
  std::string name;
  long long count = 0;
  size_t line = 0;
  std::vector<Property> properties;
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// Reads a list length of `size` bytes at p in the file's byte order.
long long readCount(const char* p, int size, bool isSigned, bool bigEndian) {
  unsigned char b[8] = {};
  for (int i = 0; i < size; ++i) b[i] = static_cast<unsigned char>(p[bigEndian ? size - 1 - i : i]);
  uint64_t u = 0;
  for (int i = size - 1; i >= 0; --i) u = (u << 8) | b[i];
  if (isSigned && size < 8 && (u >> (8 * size - 1)) & 1) return (long long)u - (1LL << (8 * size));
  return (long long)u;
}

}  // namespace

bool checkPlyStructure(const std::string& path, std::string_view bytes, std::string& error) {
  const auto at = [&](size_t line) { return path + ":" + std::to_string(line) + ": "; };
  std::vector<Element> elements;
  std::string format;
  size_t pos = 0, line = 0;
  bool ended = false;
  while (!ended && pos < bytes.size()) {
    ++line;
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    // The header is text. A control byte (a form feed, NUL) splits or ends words for
    // OpenMesh's reader where this check does not, and it then loops forever on the
    // header; bytes from 0x80 (UTF-8 in comments and names) split nothing.
    for (size_t i = pos; i < end; ++i) {
      const auto c = static_cast<unsigned char>(bytes[i]);
      if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
        char code[8];
        std::snprintf(code, sizeof code, "0x%02x", c);
        error = at(line) + "the PLY header holds the control byte " + code + ", which is not text";
        return false;
      }
    }
    const auto tokens = split(bytes.substr(pos, end - pos));
    pos = end + 1;
    if (line == 1) {
      if (tokens.size() != 1 || tokens[0] != "ply") {
        error = at(1) + "cannot read the file: a PLY file starts with the line 'ply'";
        return false;
      }
      continue;
    }
    if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
    if (tokens[0] == "end_header") {
      ended = true;
    } else if (tokens[0] == "format") {
      // OpenMesh's reader hangs on a format line without its version: require all of it.
      format = tokens.size() >= 2 ? std::string(tokens[1]) : std::string();
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") {
        error = at(line) + "unknown PLY format '" + format + "' (ascii, binary_little_endian or binary_big_endian)";
        return false;
      }
      if (tokens.size() != 3 || tokens[2] != "1.0") {
        error = at(line) + "the format line must read 'format " + format + " 1.0' (PLY version 1.0)";
        return false;
      }
    } else if (tokens[0] == "element" && tokens.size() == 3) {
      Element e;
      e.name = std::string(tokens[1]);
      e.line = line;
      const auto [p, ec] =
          std::from_chars(tokens[2].data(), tokens[2].data() + tokens[2].size(), e.count);
      if (ec != std::errc() || p != tokens[2].data() + tokens[2].size() || e.count < 0) {
        error = at(line) + "element '" + e.name + "' has the count " + quoteText(tokens[2]) +
                " (not a whole number of at least 0)";
        return false;
      }
      elements.push_back(std::move(e));
    } else if (tokens[0] == "property" && !elements.empty()) {
      Property prop;
      const bool list = tokens.size() == 5 && tokens[1] == "list";
      if (list) {
        prop.countSize = typeSize(tokens[2]);
        prop.countSigned = typeSigned(tokens[2]);
        prop.size = typeSize(tokens[3]);
        prop.name = std::string(tokens[4]);
      } else if (tokens.size() == 3) {
        prop.size = typeSize(tokens[1]);
        prop.name = std::string(tokens[2]);
      }
      if (prop.size == 0 || (list && prop.countSize == 0)) {
        error = at(line) + "cannot read the property line (unknown type or malformed)";
        return false;
      }
      elements.back().properties.push_back(std::move(prop));
    } else {
      error = at(line) + "cannot read the PLY header line (expected format, element, "
                         "property, comment or end_header)";
      return false;
    }
  }
  if (!ended) {
    error = path + ": the PLY header has no 'end_header' line";
    return false;
  }
  if (format.empty()) {
    error = path + ": the PLY header has no 'format' line";
    return false;
  }
  const size_t body = pos > bytes.size() ? bytes.size() : pos;
  const size_t left = bytes.size() - body;
  const bool binary = format != "ascii";

  // First the counts alone: each entry takes at least its fixed bytes (binary) or a
  // character and a separator per property (text).
  for (const Element& e : elements) {
    long double least = 0;
    for (const Property& p : e.properties) least += binary ? (p.countSize ? p.countSize : p.size) : 2;
    if ((long double)e.count * least > (long double)left + 1 ||
        e.count > std::numeric_limits<int>::max()) {
      error = at(e.line) + "the header declares " + std::to_string(e.count) + " " + e.name +
              " elements, more than the " + std::to_string(left) +
              " bytes after the header can hold";
      return false;
    }
  }

  // Then every list length, entry by entry.
  const bool bigEndian = format == "binary_big_endian";
  size_t p = body;
  for (const Element& e : elements)
    for (long long i = 0; i < e.count; ++i)
      for (const Property& prop : e.properties) {
        const auto endsInside = [&] {
          error = path + ": the file ends inside " + e.name + " element " + std::to_string(i) +
                  " (the header declares " + std::to_string(e.count) + ")";
          return false;
        };
        if (binary) {
          const size_t fixed = size_t(prop.countSize ? prop.countSize : prop.size);
          if (bytes.size() - p < fixed) return endsInside();
          if (!prop.countSize) {
            p += fixed;
            continue;
          }
          const long long n = readCount(bytes.data() + p, prop.countSize, prop.countSigned, bigEndian);
          p += fixed;
          if (n < 0 || (long double)n * prop.size > (long double)(bytes.size() - p)) {
            error = path + ": " + e.name + " element " + std::to_string(i) + " has a '" +
                    prop.name + "' list of " + std::to_string(n) +
                    " items, more than the rest of the file holds";
            return false;
          }
          p += size_t(n) * size_t(prop.size);
        } else {
          // Text: one token per scalar; a list is its length, then that many tokens.
          const auto token = [&](std::string_view& t) {
            const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
            while (p < bytes.size() && space(bytes[p])) ++p;
            const size_t start = p;
            while (p < bytes.size() && !space(bytes[p])) ++p;
            t = bytes.substr(start, p - start);
            return p > start;
          };
          std::string_view t;
          if (!token(t)) return endsInside();
          if (!prop.countSize) continue;
          long long n = 0;
          const auto [q, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
          if (ec != std::errc() || q != t.data() + t.size() || n < 0 ||
              (long double)n * 2 > (long double)(bytes.size() - p) + 1) {
            error = path + ": " + e.name + " element " + std::to_string(i) + " has a '" +
                    prop.name + "' list of " + quoteText(t) +
                    " items (not a whole number the rest of the file can hold)";
            return false;
          }
          for (long long k = 0; k < n; ++k)
            if (!token(t)) return endsInside();
        }
      }
  return true;
}

}  // namespace fgsg::rt::io
