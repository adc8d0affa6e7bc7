#include "cli/lsp/lsp_text.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace fgsg::cli::lsp {
namespace {

// The length in bytes of the UTF-8 sequence starting with `lead` (1 for a stray byte, so
// invalid text still advances).
size_t sequenceLength(unsigned char lead) {
  if (lead >= 0xF0 && lead < 0xF8) return 4;
  if (lead >= 0xE0) return lead < 0xF0 ? 3 : 1;
  if (lead >= 0xC0) return 2;
  return 1;
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

int utf16Units(const std::string& line, int codePoints) {
  int units = 0;
  size_t i = 0;
  for (int n = 0; n < codePoints; ++n) {
    if (i >= line.size()) {
      units += codePoints - n;
      break;
    }
    const size_t len = sequenceLength(static_cast<unsigned char>(line[i]));
    units += len == 4 ? 2 : 1;  // beyond the BMP: a surrogate pair
    i += len;
  }
  return units;
}

size_t byteAtUtf16(const std::string& line, int units) {
  size_t i = 0;
  for (int u = 0; u < units && i < line.size();) {
    const size_t len = sequenceLength(static_cast<unsigned char>(line[i]));
    u += len == 4 ? 2 : 1;
    i += len;
  }
  return std::min(i, line.size());
}

size_t offsetAt(const std::string& text, int line, int units) {
  size_t start = 0;
  for (int l = 0; l < line; ++l) {
    const size_t eol = text.find('\n', start);
    if (eol == std::string::npos) return text.size();
    start = eol + 1;
  }
  size_t eol = text.find('\n', start);
  if (eol == std::string::npos) eol = text.size();
  std::string content = text.substr(start, eol - start);
  if (!content.empty() && content.back() == '\r') content.pop_back();
  return start + byteAtUtf16(content, units);
}

std::string lineAt(const std::string& text, int line) {
  size_t start = 0;
  for (int l = 0; l < line; ++l) {
    const size_t eol = text.find('\n', start);
    if (eol == std::string::npos) return "";
    start = eol + 1;
  }
  size_t eol = text.find('\n', start);
  std::string out = text.substr(start, eol == std::string::npos ? std::string::npos : eol - start);
  if (!out.empty() && out.back() == '\r') out.pop_back();
  return out;
}

std::string pathOfUri(const std::string& uri) {
  const std::string scheme = "file://";
  if (uri.compare(0, scheme.size(), scheme) != 0) {
    const size_t slash = uri.find_last_of("/:");
    return slash == std::string::npos ? uri : uri.substr(slash + 1);
  }
  std::string path;
  size_t i = scheme.size();
  if (i < uri.size() && uri[i] != '/') i = uri.find('/', i);  // file://host/path: the host is dropped
  for (; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 && hexValue(uri[i + 2]) >= 0) {
      path += static_cast<char>(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2]));
      i += 2;
    } else {
      path += uri[i];
    }
  }
  return path;
}

std::string uriOfPath(const std::string& path) {
  std::error_code ec;
  std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  const std::string full = ec ? path : absolute.lexically_normal().string();
  static const char* kHex = "0123456789ABCDEF";
  std::string uri = "file://";
  for (unsigned char c : full) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      uri += static_cast<char>(c);
    } else {
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 15];
    }
  }
  return uri;
}

}  // namespace fgsg::cli::lsp
