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

}  // namespace

bool looksLikePnm(const std::string& bytes) {
  return bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '5' || bytes[1] == '6');
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
  header.channels = bytes[1] == '6' ? 3 : 1;
  header.width = int(width);
  header.height = int(height);
  header.maxValue = int(maxValue);
  header.rasterOffset = pos + 1;
  return true;
}

bool readPnmSamples(const std::string& bytes, const PnmHeader& header, std::vector<uint16_t>& samples,
                    std::string& error) {
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
