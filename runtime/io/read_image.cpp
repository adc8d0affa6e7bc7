#include "runtime/io/read_image.h"

#include "runtime/io/pnm_reader.h"

#include <algorithm>
#include <vector>

#include <zlib.h>
#include <cstdlib>

// The project's only stb_image implementation (read_image.h says why these formats).
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace fgsg::rt::io {

namespace {

std::string failureReason() {
  const char* why = stbi_failure_reason();
  return why ? why : "unknown error";
}

std::string sizeText(int64_t w, int64_t h) { return std::to_string(w) + " x " + std::to_string(h); }

const stbi_uc* data8(const std::string& bytes) { return reinterpret_cast<const stbi_uc*>(bytes.data()); }

uint32_t bigEndian32(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 | uint32_t(uint8_t(b[at + 2])) << 8 |
         uint32_t(uint8_t(b[at + 3]));
}
uint32_t littleEndian(const std::string& b, size_t at, int n) {
  uint32_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = v << 8 | uint8_t(b[at + size_t(i)]);
  return v;
}

// PNG: chunks (length, type, data, CRC) from the signature to IEND, all present; the
// critical ones (upper-case first letter: IHDR, PLTE, IDAT, IEND) with a sound CRC, as
// libpng requires. stb_image's inflater pads a short stream with zeros.
bool checkPngComplete(const std::string& b, std::string& why) {
  size_t at = 8;
  while (true) {
    if (at + 8 > b.size()) {
      why = "truncated: it ends after " + std::to_string(b.size()) + " bytes, before its IEND chunk";
      return false;
    }
    const uint32_t length = bigEndian32(b, at);
    const std::string type = b.substr(at + 4, 4);
    if (length > 0x7FFFFFFFu || at + 12 + uint64_t(length) > b.size()) {
      why = "truncated: its '" + type + "' chunk at byte " + std::to_string(at) + " declares " +
            std::to_string(length) + " bytes, the file has " + std::to_string(b.size() - std::min(b.size(), at + 12)) +
            " more";
      return false;
    }
    const bool critical = type[0] >= 'A' && type[0] <= 'Z';
    if (critical && pngChunkCrc(b, at, length) != bigEndian32(b, at + 8 + length)) {
      why = "damaged: its '" + type + "' chunk at byte " + std::to_string(at) + " fails its CRC check";
      return false;
    }
    at += 12 + size_t(length);
    if (type == "IEND") return true;
  }
}

// PNG image data (the IDAT chunks' zlib stream), inflated by zlib before stb_image sees it:
// stb_image 2.27 takes the distance codes 30 and 31, which deflate does not define, for a
// distance of 0 and copies bytes of its output buffer not yet written (a picture that
// differs on every run), pads a stream cut short with zeros, and grows its buffer to
// whatever the stream inflates to (4 GB from a few MB). The stream must inflate without an
// error, end, and inflate to no more than the rows of the header's size need (what stb
// reads of it; a quarter more and 64 KiB are allowed for writers that pad).
bool checkPngInflates(const std::string& b, std::string& why) {
  if (b.size() < 33) return true;  // no IHDR: stb_image has refused it already
  const uint64_t w = bigEndian32(b, 16), h = bigEndian32(b, 20);
  const int depth = uint8_t(b[24]), colour = uint8_t(b[25]), interlace = uint8_t(b[28]);
  const int channels = colour == 2 ? 3 : colour == 4 ? 2 : colour == 6 ? 4 : 1;
  const auto rows = [&](uint64_t pw, uint64_t ph) {
    return pw == 0 || ph == 0 ? 0 : ph * (1 + (pw * uint64_t(channels) * uint64_t(depth) + 7) / 8);
  };
  uint64_t need = 0;
  if (interlace == 1) {
    static const int x0[7] = {0, 4, 0, 2, 0, 1, 0}, y0[7] = {0, 0, 4, 0, 2, 0, 1}, dx[7] = {8, 8, 4, 4, 2, 2, 1},
                     dy[7] = {8, 8, 8, 4, 4, 2, 2};
    for (int p = 0; p < 7; ++p)
      need += rows((w + uint64_t(dx[p] - x0[p]) - 1) / uint64_t(dx[p]), (h + uint64_t(dy[p] - y0[p]) - 1) / uint64_t(dy[p]));
  } else {
    need = rows(w, h);
  }
  const uint64_t allowed = need + need / 4 + (uint64_t(64) << 10);
  z_stream z{};
  if (inflateInit(&z) != Z_OK) {
    why = "not checked: zlib cannot start";
    return false;
  }
  std::vector<unsigned char> out(size_t(64) << 10);
  uint64_t inflated = 0;
  int status = Z_OK;
  for (size_t at = 8; at + 12 <= b.size() && status != Z_STREAM_END;) {
    const uint32_t length = bigEndian32(b, at);
    const bool idat = b.compare(at + 4, 4, "IDAT") == 0;
    const size_t data = at + 8;
    at += 12 + size_t(length);  // checkPngComplete: every chunk lies within the file
    if (!idat) continue;
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(b.data() + data));
    z.avail_in = length;
    while (z.avail_in > 0 && status == Z_OK) {
      z.next_out = out.data();
      z.avail_out = uInt(out.size());
      status = inflate(&z, Z_NO_FLUSH);
      inflated += out.size() - z.avail_out;
      if (status == Z_BUF_ERROR) status = Z_OK;  // no progress possible: more input is needed
      if (inflated > allowed) {
        inflateEnd(&z);
        why = "damaged: its image data inflates to more than the " + std::to_string(need) + " bytes its " +
              std::to_string(w) + " x " + std::to_string(h) + " pixels need";
        return false;
      }
    }
    if (status != Z_OK && status != Z_STREAM_END) {
      why = std::string("damaged: its image data does not inflate (zlib: ") + (z.msg ? z.msg : "error") + ")";
      inflateEnd(&z);
      return false;
    }
  }
  inflateEnd(&z);
  if (status != Z_STREAM_END) {
    why = "truncated: its image data ends before its compressed stream does";
    return false;
  }
  return true;
}

// JPEG: the segments to the first scan, then the entropy-coded data (where 0xFF is always
// followed by 0x00 or a restart marker) and any further segments and scans, up to the
// end-of-image marker. stb_image decodes a cut-off scan as if zeros followed.
bool checkJpegComplete(const std::string& b, std::string& why) {
  const auto u8 = [&](size_t i) { return uint8_t(b[i]); };
  size_t at = 2;
  while (at + 1 < b.size()) {
    if (u8(at) != 0xFF) {
      why = "damaged: no marker at byte " + std::to_string(at);
      return false;
    }
    const uint8_t marker = u8(at + 1);
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0xD9) return true;  // end of image
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
      at += 2;
      continue;
    }
    if (at + 4 > b.size()) break;
    const size_t length = size_t(u8(at + 2)) << 8 | u8(at + 3);
    if (length < 2) {
      why = "damaged: a segment at byte " + std::to_string(at) + " declares " + std::to_string(length) + " bytes";
      return false;
    }
    at += 2 + length;
    if (marker != 0xDA) continue;
    // Scan data: up to the next marker that is neither stuffing nor a restart.
    while (at + 1 < b.size() &&
           !(u8(at) == 0xFF && u8(at + 1) != 0x00 && u8(at + 1) != 0xFF && !(u8(at + 1) >= 0xD0 && u8(at + 1) <= 0xD7)))
      ++at;
  }
  why = "truncated: it ends after " + std::to_string(b.size()) + " bytes, before its end-of-image marker";
  return false;
}

// JPEG Huffman tables (DHT segments), before stb_image reads any: a table declares how
// many codes it has of each length, and stb_image (2.27) writes that many entries into a
// table of 256 without checking (a 16-byte file writes 4 KB past it). Every DHT segment
// up to the end of the image is checked: at most 256 codes a table, all within the
// segment. The segments are walked as stb_image walks them (bytes between segments that
// are not a marker are skipped, as stb_image skips padding); structural problems are
// checkJpegComplete's to report.
bool checkJpegTables(const std::string& b, std::string& why) {
  const auto u8 = [&](size_t i) { return uint8_t(b[i]); };
  size_t at = 2;
  while (at + 1 < b.size()) {
    if (u8(at) != 0xFF) {
      ++at;
      continue;
    }
    const uint8_t marker = u8(at + 1);
    if (marker == 0xFF) {
      ++at;
      continue;
    }
    if (marker == 0xD9) return true;
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
      at += 2;
      continue;
    }
    if (at + 4 > b.size()) return true;
    const size_t length = size_t(u8(at + 2)) << 8 | u8(at + 3);
    if (length < 2) return true;
    const size_t end = std::min(b.size(), at + 2 + length);
    if (marker == 0xC4) {
      for (size_t t = at + 4; t < end;) {
        size_t codes = 0;
        for (size_t i = 0; i < 16 && t + 1 + i < end; ++i) codes += u8(t + 1 + i);
        if (codes > 256 || t + 17 + codes > end) {
          why = "damaged: its Huffman table at byte " + std::to_string(t) + " declares " + std::to_string(codes) +
                " codes" + (codes > 256 ? " (at most 256)" : ", more than its segment holds");
          return false;
        }
        t += 17 + codes;
      }
    }
    at += 2 + length;
    if (marker != 0xDA) continue;
    while (at + 1 < b.size() &&
           !(u8(at) == 0xFF && u8(at + 1) != 0x00 && u8(at + 1) != 0xFF && !(u8(at + 1) >= 0xD0 && u8(at + 1) <= 0xD7)))
      ++at;
  }
  return true;
}

// BMP: the pixel rows the header declares, from the pixel-data offset on (uncompressed
// and bit-field files; stb_image refuses the run-length ones). stb_image reads past the
// end as zeros.
bool checkBmpComplete(const std::string& b, std::string& why) {
  if (b.size() < 26) {
    why = "truncated: " + std::to_string(b.size()) + " bytes, shorter than a BMP header";
    return false;
  }
  const uint32_t offset = littleEndian(b, 10, 4), headerSize = littleEndian(b, 14, 4);
  int64_t w = 0, h = 0;
  uint32_t bpp = 0, compression = 0;
  if (headerSize == 12) {
    w = littleEndian(b, 18, 2);
    h = littleEndian(b, 20, 2);
    bpp = littleEndian(b, 24, 2);
  } else {
    if (b.size() < 34) {
      why = "truncated: " + std::to_string(b.size()) + " bytes, shorter than its BMP header";
      return false;
    }
    w = int32_t(littleEndian(b, 18, 4));
    h = int32_t(littleEndian(b, 22, 4));
    bpp = littleEndian(b, 28, 2);
    compression = littleEndian(b, 30, 4);
  }
  if (compression == 1 || compression == 2) return true;  // RLE: stb_image refuses it
  // Sizes are checked against the limits later; here only what the rows need.
  const int64_t rowBytes = (std::abs(w) * int64_t(bpp) + 31) / 32 * 4;
  const int64_t need = int64_t(offset) + rowBytes * std::abs(h);
  if (std::abs(w) <= (int64_t(1) << 31) && std::abs(h) <= (int64_t(1) << 31) && bpp <= 64 && need > int64_t(b.size())) {
    why = "truncated: its header declares " + std::to_string(need) + " bytes of header and pixels, the file has " +
          std::to_string(b.size());
    return false;
  }
  return true;
}

bool checkSize(const std::string& path, int64_t w, int64_t h, const ImageLimits& limits, std::string& error) {
  if (w <= 0 || h <= 0) {
    error = path + ": the image is empty (" + sizeText(w, h) + ")";
    return false;
  }
  if (w > limits.maxSide || h > limits.maxSide || w * h > limits.maxPixels) {
    const bool side = limits.maxSide < (int64_t(1) << 31);
    error = path + ": the image is " + sizeText(w, h) + " " + limits.unit + ", larger than the limit for " +
            limits.purpose + " (" + (side ? std::to_string(limits.maxSide) + " per side, " : std::string()) +
            std::to_string(limits.maxPixels) + " in all)";
    return false;
  }
  return true;
}

}  // namespace

uint32_t pngChunkCrc(const std::string& png, size_t chunkAt, uint32_t length) {
  return static_cast<uint32_t>(crc32_z(0, reinterpret_cast<const Bytef*>(png.data() + chunkAt + 4), 4 + size_t(length)));
}

ImageFormat imageFormatOf(const std::string& bytes) {
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) == 0) return ImageFormat::Png;
  if (bytes.compare(0, 3, "\xFF\xD8\xFF", 3) == 0) return ImageFormat::Jpeg;
  if (bytes.compare(0, 2, "BM", 2) == 0) return ImageFormat::Bmp;
  if (looksLikePnm(bytes)) return ImageFormat::Pnm;
  return ImageFormat::Unknown;
}

const char* imageFormatName(ImageFormat format) {
  switch (format) {
    case ImageFormat::Png: return "PNG";
    case ImageFormat::Jpeg: return "JPEG";
    case ImageFormat::Bmp: return "BMP";
    case ImageFormat::Pnm: return "PGM/PPM";
    case ImageFormat::Unknown: break;
  }
  return "unknown";
}

const char* imageMimeType(ImageFormat format) {
  return format == ImageFormat::Png ? "image/png" : format == ImageFormat::Jpeg ? "image/jpeg" : nullptr;
}

bool checkImage(const std::string& path, const std::string& bytes, const ImageLimits& limits, Image& header,
                std::string& error) {
  header = Image{};
  header.format = imageFormatOf(bytes);
  if (header.format == ImageFormat::Unknown) {
    error = path + ": not an image fgsg reads (PNG, JPEG, BMP, PGM/PPM): " +
            (bytes.empty() ? std::string("the file is empty") : "its first bytes are none of their signatures");
    return false;
  }
  const std::string format = imageFormatName(header.format);
  if (header.format == ImageFormat::Pnm) {
    PnmHeader pnm;
    std::string why;
    if (!readPnmHeader(bytes, pnm, why)) {
      error = path + ": " + why;
      return false;
    }
    if (!checkSize(path, pnm.width, pnm.height, limits, error)) return false;
    std::vector<uint16_t> samples;  // a plain file is complete only when every sample reads
    if (pnm.plain && !readPnmSamples(bytes, pnm, samples, why)) {
      error = path + ": " + why;
      return false;
    }
    if (!pnm.plain && bytes.size() - pnm.rasterOffset < pnm.rasterBytes()) {
      error = path + ": the PGM/PPM file is truncated: " + std::to_string(bytes.size() - pnm.rasterOffset) +
              " bytes of samples, " + std::to_string(pnm.rasterBytes()) + " needed";
      return false;
    }
    header.width = pnm.width;
    header.height = pnm.height;
    header.channels = pnm.channels;
    header.bits = pnm.maxValue > 255 ? 16 : 8;
    header.fullScale = uint32_t(pnm.maxValue);
    return true;
  }
  const int length = int(bytes.size());  // within the input cap, far below INT_MAX
  int w = 0, h = 0, channels = 0;
  std::string damaged;
  if (header.format == ImageFormat::Jpeg && !checkJpegTables(bytes, damaged)) {
    error = path + ": the JPEG file is " + damaged;
    return false;
  }
  if (!stbi_info_from_memory(data8(bytes), length, &w, &h, &channels)) {
    error = path + ": cannot read the " + format + " image's header: " + failureReason();
    return false;
  }
  if (!checkSize(path, w, h, limits, error)) return false;
  std::string why;
  const bool complete = header.format == ImageFormat::Png    ? checkPngComplete(bytes, why) && checkPngInflates(bytes, why)
                        : header.format == ImageFormat::Jpeg ? checkJpegComplete(bytes, why)
                                                             : checkBmpComplete(bytes, why);
  if (!complete) {
    error = path + ": the " + format + " file is " + why;
    return false;
  }
  header.width = w;
  header.height = h;
  header.channels = channels;
  header.bits = stbi_is_16_bit_from_memory(data8(bytes), length) ? 16 : 8;
  header.fullScale = header.bits == 16 ? 65535 : 255;
  return true;
}

bool decodeImage(const std::string& path, const std::string& bytes, const ImageLimits& limits, Image& out,
                 std::string& error) {
  Image image;
  if (!checkImage(path, bytes, limits, image, error)) {
    out = Image{};
    return false;
  }
  const size_t pixels = size_t(image.width) * size_t(image.height);
  if (image.format == ImageFormat::Pnm) {
    PnmHeader pnm;
    std::string why;
    std::vector<uint16_t> samples;
    if (!readPnmHeader(bytes, pnm, why) || !readPnmSamples(bytes, pnm, samples, why)) {
      error = path + ": " + why;
      out = Image{};
      return false;
    }
    if (image.bits == 16) image.samples16 = std::move(samples);
    else image.samples8.assign(samples.begin(), samples.end());
    out = std::move(image);
    return true;
  }
  const int length = int(bytes.size());
  int dw = 0, dh = 0, dn = 0;
  bool matches = false;
  if (image.bits == 16) {
    stbi_us* data = stbi_load_16_from_memory(data8(bytes), length, &dw, &dh, &dn, 0);
    if (!data) {
      error = path + ": cannot decode the 16-bit image: " + failureReason();
      out = Image{};
      return false;
    }
    matches = dw == image.width && dh == image.height && dn >= 1 && dn <= 4;
    if (matches) image.samples16.assign(data, data + pixels * size_t(dn));
    stbi_image_free(data);
  } else {
    stbi_uc* data = stbi_load_from_memory(data8(bytes), length, &dw, &dh, &dn, 0);
    if (!data) {
      error = path + ": cannot decode the image: " + failureReason();
      out = Image{};
      return false;
    }
    matches = dw == image.width && dh == image.height && dn >= 1 && dn <= 4;
    if (matches) image.samples8.assign(data, data + pixels * size_t(dn));
    stbi_image_free(data);
  }
  // The decoder must agree with the header the size was checked by.
  if (!matches) {
    error = path + ": the decoded image (" + sizeText(dw, dh) + ", " + std::to_string(dn) +
            " channels) does not match its header (" + sizeText(image.width, image.height) + ")";
    out = Image{};
    return false;
  }
  image.channels = dn;
  out = std::move(image);
  return true;
}

}  // namespace fgsg::rt::io
