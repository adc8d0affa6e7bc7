// A colour image laid over textured triangles (CGA's Texture, Mesh::textureRuns): what the
// preview samples and the glb writer embeds. PNG and JPEG only, the two formats glTF
// embeds, so a texture that previews is one that exports.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::texture {

// The largest colour texture read, in pixels (an 8192 x 8192 image): decoding one holds
// 3 bytes per pixel.
constexpr int64_t kMaxColorTexturePixels = int64_t(1) << 26;

// An 8-bit RGB picture; colours are the file's bytes / 255. No colour-space conversion:
// the sRGB values are used as they are, and the preview treats them as linear, as it does
// vertex colours. Alpha is ignored; grey images read as equal R, G and B.
class ColorTexture {
 public:
  // Reads a PNG or JPEG file through the bounded input reader (runtime/io/read_input.h) and
  // decodes it with the image reader (runtime/io/read_image.h). False and a message naming `path` when the file is missing
  // or unreadable, is not a PNG or JPEG, is corrupt or truncated, is empty, or has more
  // than kMaxColorTexturePixels pixels; the texture is then unchanged.
  bool load(const std::string& path, std::string& error);

  // The colour at texture coordinate (u, v), each channel in [0, 1]: u runs right, v runs
  // UP (v = 1 is the image's top row), pixel (i, j) (column i, row j from the top) is
  // centred at ((i + 0.5) / W, 1 - (j + 0.5) / H). Bilinear between the four nearest
  // centres, repeating in both directions (glTF's default REPEAT sampler: u + 1 reads as
  // u, and the last column blends into the first). A non-finite coordinate, or a texture
  // never loaded, reads black, so the fault shows rather than passing for untextured.
  std::array<float, 3> sample(double u, double v) const;

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return rgb_.empty(); }

  // A check for refusing a bad texture file up front, short of decoding it: the file is
  // readable, a PNG or JPEG by its first bytes, has a header that declares a size within
  // the limit, and is complete (io::checkImage: a truncated PNG is never embedded). False
  // and a message naming `path` otherwise.
  static bool probe(const std::string& path, std::string& error);

  // "image/png" or "image/jpeg" by the file's first bytes, nullptr for anything else.
  static const char* mimeType(const std::string& bytes);

 private:
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> rgb_;  // row-major from the top row, 3 bytes per pixel
};

}  // namespace fgsg::rt::texture
