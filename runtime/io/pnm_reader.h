// Binary PGM and PPM files (Netpbm P5, P6), read here rather than by stb_image: its
// version 2.27 reads 16-bit samples in the wrong byte order (Netpbm's are big-endian),
// decodes a truncated file into uninitialised memory and ignores the maxval.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::io {

struct PnmHeader {
  int width = 0, height = 0, channels = 0;  // channels: 1 (P5) or 3 (P6)
  int maxValue = 0;                         // full scale; samples of 1 byte up to 255, else 2
  size_t rasterOffset = 0;                  // where the samples start
  size_t rasterBytes() const {
    return size_t(width) * size_t(height) * size_t(channels) * (maxValue > 255 ? 2 : 1);
  }
};

// True when `bytes` starts with a binary PGM/PPM magic number ("P5" or "P6").
bool looksLikePnm(const std::string& bytes);

// Parses the header of a file looksLikePnm accepted: width, height and maxval as decimal
// numbers between blanks and '#' comments, then exactly one blank. False and a message
// (without the file's name) when a number is missing, the maxval is 0 or above 65535, or
// the blank after it is missing. Absurd sizes saturate (above 10^8) for the caller to
// refuse.
bool readPnmHeader(const std::string& bytes, PnmHeader& header, std::string& error);

// The width x height x channels samples, row by row from the top, each at most maxval
// (larger ones are clamped to it). False and a message when the file is too short.
bool readPnmSamples(const std::string& bytes, const PnmHeader& header, std::vector<uint16_t>& samples,
                    std::string& error);

}  // namespace fgsg::rt::io
