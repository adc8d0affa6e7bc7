#include "runtime/io/pnm_reader.h"

#include <algorithm>

namespace fgsg::rt::io {

namespace {

bool isBlank(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Blanks and '#' comments (to the end of their line), as the header allows between fields.
void skipBlanks(const std::string& b, size_t& pos) {
  while (pos < b.size()) {
    if (isBlank(b[pos])) {
      ++pos;
    } else if (b[pos] == '#') {
      while (pos < b.size() && b[pos] != '\n' && b[pos] != '\r') ++pos;
    } else {
      break;
    }
  }
}

// A decimal number after blanks; saturates above 10^8 (no int overflow on absurd sizes).
bool readNumber(const std::string& b, size_t& pos, long& value) {
  skipBlanks(b, pos);
  if (pos >= b.size() || !isDigit(b[pos])) return false;
  value = 0;
  for (; pos < b.size() && isDigit(b[pos]); ++pos)
    if (value <= 100000000) value = value * 10 + (b[pos] - '0');
  return true;
}

// The 1-based line of byte `pos`, for the messages of plain files.
size_t lineAt(const std::string& b, size_t pos) {
  return 1 + size_t(std::count(b.begin(), b.begin() + std::min(pos, b.size()), '\n'));
}

// A byte as a message shows it: quoted when printable, else in hex.
std::string shown(char c) {
  if (c > ' ' && c < 127) return std::string("'") + c + "'";
  static const char* hex = "0123456789abcdef";
  return std::string("byte 0x") + hex[(unsigned char)c >> 4] + hex[(unsigned char)c & 15];
}

// P2/P3: the samples as decimal text.
bool readPlainSamples(const std::string& b, const PnmHeader& header, std::vector<uint16_t>& samples,
                      std::string& error) {
  const size_t count = size_t(header.width) * size_t(header.height) * size_t(header.channels);
  samples.assign(count, 0);
  size_t pos = header.rasterOffset;
  for (size_t i = 0; i < count; ++i) {
    const auto which = [&] {  // for messages only: not built for every sample
      const size_t pixel = i / size_t(header.channels);
      return "sample " + std::to_string(i + 1) + " (row " + std::to_string(pixel / header.width + 1) + ", column " +
             std::to_string(pixel % header.width + 1) + ")";
    };
    skipBlanks(b, pos);
    if (pos >= b.size()) {
      error = "the plain PGM/PPM file is truncated: it ends at line " + std::to_string(lineAt(b, pos)) + " after " +
              std::to_string(i) + " of its " + std::to_string(count) + " samples";
      return false;
    }
    const size_t start = pos;
    long value = 0;
    if (!readNumber(b, pos, value) || (pos < b.size() && !isBlank(b[pos]) && b[pos] != '#')) {
      const size_t bad = pos < b.size() && start < pos ? pos : start;
      error = "the plain PGM/PPM file has " + shown(b[bad]) + " at line " + std::to_string(lineAt(b, bad)) +
              " in " + which() + ", which should be a decimal number";
      return false;
    }
    if (value > header.maxValue) {
      error = "the plain PGM/PPM file's " + which() + " at line " + std::to_string(lineAt(b, start)) + " is " +
              (value > 100000000 ? std::string("above 10^8") : std::to_string(value)) + ", above its maxval " +
              std::to_string(header.maxValue);
      return false;
    }
    samples[i] = uint16_t(value);
  }
  skipBlanks(b, pos);
  if (pos < b.size()) {
    error = "the plain PGM/PPM file goes on after its " + std::to_string(count) + " samples: " + shown(b[pos]) +
            " at line " + std::to_string(lineAt(b, pos)) + " (is its width or height wrong?)";
    return false;
  }
  return true;
}

}  // namespace

bool looksLikePnm(const std::string& bytes) {
  return bytes.size() >= 2 && bytes[0] == 'P' &&
         (bytes[1] == '2' || bytes[1] == '3' || bytes[1] == '5' || bytes[1] == '6');
}

bool readPnmHeader(const std::string& bytes, PnmHeader& header, std::string& error) {
  size_t pos = 2;
  long width = 0, height = 0, maxValue = 0;
  if (!readNumber(bytes, pos, width) || !readNumber(bytes, pos, height) || !readNumber(bytes, pos, maxValue)) {
    error = "the PGM/PPM header lacks its width, height or maxval";
    return false;
  }
  if (maxValue == 0 || maxValue > 65535) {
    error = "the PGM/PPM maxval is " + std::to_string(maxValue) + ", not between 1 and 65535";
    return false;
  }
  if (pos >= bytes.size() || !isBlank(bytes[pos])) {
    error = "the PGM/PPM header does not end in a blank after its maxval";
    return false;
  }
  header.channels = bytes[1] == '3' || bytes[1] == '6' ? 3 : 1;
  header.plain = bytes[1] == '2' || bytes[1] == '3';
  header.width = int(width);
  header.height = int(height);
  header.maxValue = int(maxValue);
  header.rasterOffset = pos + 1;
  return true;
}

bool readPnmSamples(const std::string& bytes, const PnmHeader& header, std::vector<uint16_t>& samples,
                    std::string& error) {
  if (header.plain) return readPlainSamples(bytes, header, samples, error);
  const size_t have = bytes.size() - std::min(bytes.size(), header.rasterOffset);
  if (have < header.rasterBytes()) {
    error = "the PGM/PPM file is truncated: " + std::to_string(have) + " bytes of samples, " +
            std::to_string(header.rasterBytes()) + " needed";
    return false;
  }
  const auto* raster = reinterpret_cast<const unsigned char*>(bytes.data()) + header.rasterOffset;
  const bool wide = header.maxValue > 255;
  samples.resize(size_t(header.width) * size_t(header.height) * size_t(header.channels));
  for (size_t i = 0; i < samples.size(); ++i) {
    const int value = wide ? (raster[2 * i] << 8) | raster[2 * i + 1] : raster[i];
    samples[i] = uint16_t(std::min(value, header.maxValue));
  }
  return true;
}

}  // namespace fgsg::rt::io
