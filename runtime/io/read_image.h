// The one image reader of fgsg: texture contexts (texture/texture_map.h), colour textures
// (texture/color_texture.h, what Texture() embeds), image fields and synthesis examples and
// masks (synthesis/image_reader.h) all decode here, with the project's only copy of
// stb_image. The format is told by the file's first bytes, never by its name: PNG, JPEG,
// BMP and PGM/PPM, binary or plain text (pnm_reader.h). TGA is not read: it has no
// signature (any few bytes pass for one) and stb_image decodes a short one into
// uninitialised memory. Every file is checked complete before anything is decoded (PNG:
// every chunk present up to IEND, critical ones with a sound CRC; JPEG: the end-of-image
// marker after the scans; BMP and PGM/PPM: as many pixel bytes, or numbers, as the header
// declares), so a truncated image is an error, never pixels made up by the decoder.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::io {

enum class ImageFormat { Unknown, Png, Jpeg, Bmp, Pnm };

// By the signature at the start of `bytes`.
ImageFormat imageFormatOf(const std::string& bytes);
// "PNG", "JPEG", "BMP", "PGM/PPM"; "unknown".
const char* imageFormatName(ImageFormat format);

// The CRC a PNG chunk carries: of its type and data, the 4 + length bytes from byte
// chunkAt + 4 of `png` (which must hold them).
uint32_t pngChunkCrc(const std::string& png, size_t chunkAt, uint32_t length);
// "image/png" and "image/jpeg" (what glTF embeds); nullptr for the others.
const char* imageMimeType(ImageFormat format);

// The largest picture a caller takes, and the words its size message uses: "the image is
// 20000 x 1 texels, larger than the limit for textures (16384 per side, 67108864 in all)".
struct ImageLimits {
  int64_t maxPixels = int64_t(1) << 26;
  int64_t maxSide = int64_t(1) << 31;  // no limit per side unless lower
  const char* unit = "pixels";
  const char* purpose = "images";
};

// A picture, row-major from the top row, `channels` samples a pixel (1 grey, 2 grey +
// alpha, 3 RGB, 4 RGBA). 8-bit files fill `samples8`, 16-bit ones `samples16`; a sample
// reads 1 at `fullScale` (255, 65535, or a PGM/PPM's maxval).
struct Image {
  ImageFormat format = ImageFormat::Unknown;
  int width = 0, height = 0, channels = 0, bits = 0;
  uint32_t fullScale = 0;
  std::vector<uint8_t> samples8;
  std::vector<uint16_t> samples16;
  uint32_t sample(size_t i) const { return bits == 16 ? samples16[i] : samples8[i]; }
  // Sample `i` scaled to 0..255 (rounded).
  uint8_t sample8(size_t i) const {
    return bits == 8 && fullScale == 255 ? samples8[i] : uint8_t((sample(i) * 255u + fullScale / 2) / fullScale);
  }
};

// Checks `bytes` (the file `path`, read by read_input.h) without decoding it: a format
// above, a header that reads, a size within `limits`, and the whole file present. On
// success `header` has everything but the samples. False and "PATH: ..." otherwise.
bool checkImage(const std::string& path, const std::string& bytes, const ImageLimits& limits, Image& header,
                std::string& error);

// checkImage, then the samples. False and "PATH: ..." when the check or the decoding
// fails; `out` is then left empty.
bool decodeImage(const std::string& path, const std::string& bytes, const ImageLimits& limits, Image& out,
                 std::string& error);

}  // namespace fgsg::rt::io
