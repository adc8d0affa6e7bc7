// JSON text for the outputs written by hand (instances, reports): numbers as their
// shortest round-trip text, strings escaped. Header-only: both writers append to a
// std::string as they go.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace fgsg::rt::io {

// Shortest round-trip text; a float prints as the float it is (0.8f as 0.8, not as the
// double 0.800000011920929); NaN and infinities, which JSON cannot hold, as null.
template <typename T>
void appendJsonNumber(std::string& out, T v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

inline void appendJsonString(std::string& out, const std::string& s) {
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += char(c);  // UTF-8 passes through unchanged
        }
    }
  }
  out += '"';
}

}  // namespace fgsg::rt::io
