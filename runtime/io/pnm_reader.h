// PGM and PPM files, binary (Netpbm P5, P6) and plain text (P2, P3, what a script or a
// text editor writes), read here rather than by stb_image: its version 2.27 reads 16-bit
// samples in the wrong byte order (Netpbm's are big-endian), decodes a truncated file
// into uninitialised memory, ignores the maxval and reads no plain format.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::io {

struct PnmHeader {
  int width = 0, height = 0, channels = 0;  // channels: 1 (P2, P5) or 3 (P3, P6)
  int maxValue = 0;                         // full scale; samples of 1 byte up to 255, else 2
  bool plain = false;                       // P2, P3: samples as decimal text
  size_t rasterOffset = 0;                  // where the samples start
  // Binary files only: the bytes the samples take.
  size_t rasterBytes() const {
    return size_t(width) * size_t(height) * size_t(channels) * (maxValue > 255 ? 2 : 1);
  }
};

// True when `bytes` starts with a PGM/PPM magic number ("P2", "P3", "P5" or "P6").
bool looksLikePnm(const std::string& bytes);

// Parses the header of a file looksLikePnm accepted: width, height and maxval as decimal
// numbers between blanks and '#' comments, then exactly one blank. False and a message
// (without the file's name) when a number is missing, the maxval is 0 or above 65535, or
// the blank after it is missing. Absurd sizes saturate (above 10^8) for the caller to
// refuse.
bool readPnmHeader(const std::string& bytes, PnmHeader& header, std::string& error);

// The width x height x channels samples, row by row from the top, each at most maxval.
// Binary: larger ones are clamped to it; false and a message when the file is too short.
// Plain: decimal numbers between blanks and '#' comments; false and a message naming the
// line (and the sample's row and column) when one is missing, is not a number, exceeds
// the maxval, or when anything but blanks and comments follows the last.
bool readPnmSamples(const std::string& bytes, const PnmHeader& header, std::vector<uint16_t>& samples,
                    std::string& error);

}  // namespace fgsg::rt::io
