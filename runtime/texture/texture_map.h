// A texture context (Buron et al. 2015, §4): a picture laid over the surface's texture
// space that a grammar reads as a number, `texture mask = "paint.png";` then
// `context.mask(texCoord)`. Painted masks, densities and scales all read the same way.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::texture {

// The largest texture read, per side and in texels all together (an 8192 x 8192 paint
// mask): decoding one briefly holds up to 8 bytes per texel (16-bit RGBA).
constexpr int kMaxTextureSide = 16384;
constexpr int64_t kMaxTexels = int64_t(1) << 26;

// A grey-level picture in [0, 1]. What a texel holds:
//  * 1 or 2 channels (grey, grey + alpha): the grey level;
//  * 3 or 4 channels (RGB, RGBA): the brightest of R, G and B, so paint of any colour at
//    full strength reads 1 and black reads 0;
//  * alpha is ignored in both cases;
//  * 8-bit images are divided by 255 and 16-bit ones by 65535; PGM/PPM by their maxval
//    (samples above it read 1).
class TextureMap {
 public:
  // Reads a PNG, JPEG, BMP or PGM/PPM (P5/P6, or plain P2/P3) file, 8 or 16 bits per
  // channel, 1 to 4 channels (the format by its first bytes), through the bounded input reader
  // (runtime/io/read_input.h) and the image reader (runtime/io/read_image.h). False and a message naming `path` when the
  // file is missing or unreadable, is not an image of these kinds, is corrupt or
  // truncated, is empty, or exceeds the limits above; the map is then unchanged.
  bool load(const std::string& path, std::string& error);

  // The value at texture coordinate (u, v): u runs right, v runs UP (v = 1 is the image's
  // top row), texel (i, j) (column i, row j from the top) is centred at
  // ((i + 0.5) / W, 1 - (j + 0.5) / H). Bilinear between the four nearest centres;
  // outside the centres (u or v beyond the half-texel border, or outside [0, 1]) the
  // border texels extend. A NaN coordinate, or a map never loaded, reads 0 — a grammar
  // testing a mask then sees "not painted" rather than an error.
  double sample(double u, double v) const;

  // Texel (column, row), row 0 at the top, in [0, 1]; both must lie inside the image.
  double texel(int column, int row) const {
    return values_[size_t(row) * size_t(width_) + size_t(column)] / full_;
  }
  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return values_.empty(); }
  // 8 or 16: the bits per channel of the file read (0 before a load).
  int bitsPerChannel() const { return bits_; }

 private:
  int width_ = 0, height_ = 0, bits_ = 0;
  double full_ = 1;  // the raw value that reads 1: 255, 65535 or a PGM/PPM's maxval
  std::vector<uint16_t> values_;  // row-major, row 0 at the top
};

}  // namespace fgsg::rt::texture
