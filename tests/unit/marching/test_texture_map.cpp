// Texture contexts (runtime/texture/texture_map.h): what a texel reads for each kind of
// image, where texel centres lie (v up), bilinear sampling, clamping, and the errors.
#include "runtime/texture/texture_map.h"

#include "tests/unit/runtime/scratch_files.h"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using fgsg::rt::texture::TextureMap;
namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

// A binary PGM/PPM: samples big-endian when maxval > 255.
std::string pnm(char kind, int w, int h, int maxval, const std::vector<int>& samples) {
  std::string s = std::string("P") + kind + "\n" + std::to_string(w) + " " + std::to_string(h) + "\n" +
                  std::to_string(maxval) + "\n";
  for (int v : samples) {
    if (maxval > 255) s += char(v >> 8);
    s += char(v & 0xff);
  }
  return s;
}

// --- A 16-bit PNG, written by hand (stbi_write_png writes 8 bits only): zlib with
// stored (uncompressed) deflate blocks.
uint32_t crc32(const std::string& bytes) {
  uint32_t c = 0xffffffffu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return c ^ 0xffffffffu;
}

std::string bigEndian32(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  return bigEndian32(uint32_t(data.size())) + type + data + bigEndian32(crc32(type + data));
}

std::string storedZlib(const std::string& raw) {
  std::string z = "\x78\x01";
  size_t pos = 0;
  do {
    const size_t n = std::min<size_t>(raw.size() - pos, 65535);
    const bool last = pos + n == raw.size();
    z += char(last ? 1 : 0);
    z += char(n & 0xff);
    z += char(n >> 8);
    z += char(~n & 0xff);
    z += char((~n >> 8) & 0xff);
    z += raw.substr(pos, n);
    pos += n;
  } while (pos < raw.size());
  uint32_t a = 1, b = 0;
  for (unsigned char c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
  return z + bigEndian32((b << 16) | a);
}

// colourType: 0 grey, 2 RGB, 4 grey + alpha, 6 RGBA; samples row by row.
std::string png16(int w, int h, int colourType, const std::vector<int>& samples) {
  const int channels = colourType == 0 ? 1 : colourType == 2 ? 3 : colourType == 4 ? 2 : 4;
  std::string raw;
  for (int y = 0; y < h; ++y) {
    raw += char(0);  // filter: none
    for (int i = 0; i < w * channels; ++i) {
      const int v = samples[size_t(y) * w * channels + i];
      raw += char(v >> 8);
      raw += char(v & 0xff);
    }
  }
  const std::string ihdr = bigEndian32(uint32_t(w)) + bigEndian32(uint32_t(h)) + char(16) + char(colourType) +
                           char(0) + char(0) + char(0);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", storedZlib(raw)) +
         chunk("IEND", "");
}

// An 8-bit PNG through stb_image_write.
fs::path png8(const fs::path& dir, const std::string& name, int w, int h, int channels,
              const std::vector<unsigned char>& samples) {
  const fs::path p = dir / name;
  REQUIRE(stbi_write_png(p.c_str(), w, h, channels, samples.data(), w * channels) != 0);
  return p;
}

TextureMap loaded(const fs::path& p) {
  TextureMap map;
  std::string error;
  const bool ok = map.load(p.string(), error);
  INFO(error);
  REQUIRE(ok);
  return map;
}

std::string loadError(const fs::path& p) {
  TextureMap map;
  std::string error;
  CHECK_FALSE(map.load(p.string(), error));
  CHECK(map.empty());
  return error;
}

// The texture coordinate of texel (i, j)'s centre.
double centreU(const TextureMap& m, int i) { return (i + 0.5) / m.width(); }
double centreV(const TextureMap& m, int j) { return 1.0 - (j + 0.5) / m.height(); }

}  // namespace

TEST_CASE("an 8-bit grey texture reads its texels at their centres, v up", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "grey8");
  // 4 x 2, row 0 (the top, v = 1) first.
  const std::vector<unsigned char> grey = {0, 51, 102, 255,  //
                                           10, 20, 30, 40};
  const TextureMap m = loaded(png8(dir, "grey.png", 4, 2, 1, grey));
  REQUIRE(m.width() == 4);
  REQUIRE(m.height() == 2);
  CHECK(m.bitsPerChannel() == 8);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      CHECK(m.texel(i, j) == grey[size_t(j) * 4 + i] / 255.0);
      CHECK(m.sample(centreU(m, i), centreV(m, j)) == Approx(grey[size_t(j) * 4 + i] / 255.0).margin(1e-12));
    }
  // The top row is at v near 1, the bottom row at v near 0.
  CHECK(m.sample(0.875, 0.75) == Approx(1.0).margin(1e-12));
  CHECK(m.sample(0.875, 0.25) == Approx(40 / 255.0).margin(1e-12));
}

TEST_CASE("a texture samples bilinearly between texel centres", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "bilinear");
  const std::vector<unsigned char> grey = {0, 51, 102, 255,  //
                                           10, 20, 30, 40};
  const TextureMap m = loaded(png8(dir, "grey.png", 4, 2, 1, grey));
  // Halfway between columns 1 and 2 of the top row.
  CHECK(m.sample(0.5, 0.75) == Approx((51 + 102) / 2.0 / 255.0).margin(1e-12));
  // Halfway between rows 0 and 1 of column 0.
  CHECK(m.sample(0.125, 0.5) == Approx((0 + 10) / 2.0 / 255.0).margin(1e-12));
  // The middle of texels (1,0), (2,0), (1,1), (2,1).
  CHECK(m.sample(0.5, 0.5) == Approx((51 + 102 + 20 + 30) / 4.0 / 255.0).margin(1e-12));
  // A quarter of the way from column 2 to column 3 on the bottom row.
  CHECK(m.sample(0.625 + 0.0625, 0.25) == Approx((0.75 * 30 + 0.25 * 40) / 255.0).margin(1e-12));
}

TEST_CASE("a texture clamps at its border and reads 0 at NaN", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "clamp");
  const std::vector<unsigned char> grey = {0, 51, 102, 255,  //
                                           10, 20, 30, 40};
  const TextureMap m = loaded(png8(dir, "grey.png", 4, 2, 1, grey));
  // Beyond the outermost centres (inside [0, 1] and outside it) the border texel holds.
  CHECK(m.sample(0.0, 1.0) == Approx(0.0).margin(1e-12));           // top left
  CHECK(m.sample(-3.0, 7.0) == Approx(0.0).margin(1e-12));
  CHECK(m.sample(1.0, 1.0) == Approx(1.0).margin(1e-12));           // top right
  CHECK(m.sample(5.0, 1.5) == Approx(1.0).margin(1e-12));
  CHECK(m.sample(0.0, 0.0) == Approx(10 / 255.0).margin(1e-12));    // bottom left
  CHECK(m.sample(1.0, -2.0) == Approx(40 / 255.0).margin(1e-12));   // bottom right
  // Along the left edge, between the two rows' centres, still bilinear in v.
  CHECK(m.sample(-1.0, 0.5) == Approx(5 / 255.0).margin(1e-12));
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(m.sample(inf, -inf) == Approx(40 / 255.0).margin(1e-12));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(m.sample(nan, 0.5) == 0.0);
  CHECK(m.sample(0.5, nan) == 0.0);
  CHECK(TextureMap().sample(0.5, 0.5) == 0.0);
}

TEST_CASE("a one-texel texture reads its texel everywhere", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "single");
  const TextureMap m = loaded(png8(dir, "one.png", 1, 1, 1, {200}));
  for (double u : {-1.0, 0.0, 0.3, 1.0, 2.0})
    for (double v : {-1.0, 0.0, 0.7, 1.0, 2.0}) CHECK(m.sample(u, v) == 200 / 255.0);
}

TEST_CASE("colour textures read their brightest channel, alpha ignored", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "colour");
  const std::vector<unsigned char> rgb = {255, 0, 0, /**/ 10, 200, 30, /**/ 0, 0, 0, /**/ 7, 8, 9};
  const TextureMap m3 = loaded(png8(dir, "rgb.png", 2, 2, 3, rgb));
  CHECK(m3.texel(0, 0) == 1.0);
  CHECK(m3.texel(1, 0) == 200 / 255.0);
  CHECK(m3.texel(0, 1) == 0.0);
  CHECK(m3.texel(1, 1) == 9 / 255.0);
  // RGBA: a transparent texel still reads its colour.
  const std::vector<unsigned char> rgba = {0, 0, 255, 0, /**/ 40, 30, 20, 255};
  const TextureMap m4 = loaded(png8(dir, "rgba.png", 2, 1, 4, rgba));
  CHECK(m4.texel(0, 0) == 1.0);
  CHECK(m4.texel(1, 0) == 40 / 255.0);
  // Grey + alpha: the grey level.
  const std::vector<unsigned char> ga = {90, 0, /**/ 180, 255};
  const TextureMap m2 = loaded(png8(dir, "ga.png", 2, 1, 2, ga));
  CHECK(m2.texel(0, 0) == 90 / 255.0);
  CHECK(m2.texel(1, 0) == 180 / 255.0);
}

TEST_CASE("16-bit textures keep their 16 bits", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "sixteen");
  SECTION("a 16-bit grey PNG") {
    writeBytes(dir / "grey16.png", png16(3, 2, 0, {0, 1, 65535, 32768, 1000, 65534}));
    const TextureMap m = loaded(dir / "grey16.png");
    CHECK(m.bitsPerChannel() == 16);
    CHECK(m.texel(0, 0) == 0.0);
    CHECK(m.texel(1, 0) == 1 / 65535.0);
    CHECK(m.texel(2, 0) == 1.0);
    CHECK(m.texel(0, 1) == 32768 / 65535.0);
    CHECK(m.texel(1, 1) == 1000 / 65535.0);
    CHECK(m.texel(2, 1) == 65534 / 65535.0);
    CHECK(m.sample(centreU(m, 1), centreV(m, 1)) == Approx(1000 / 65535.0).margin(1e-12));
  }
  SECTION("a 16-bit RGBA PNG") {
    writeBytes(dir / "rgba16.png", png16(2, 1, 6, {300, 4464, 2, 0, /**/ 5, 6, 7, 65535}));
    const TextureMap m = loaded(dir / "rgba16.png");
    CHECK(m.bitsPerChannel() == 16);
    CHECK(m.texel(0, 0) == 4464 / 65535.0);  // the brightest of R, G, B
    CHECK(m.texel(1, 0) == 7 / 65535.0);     // alpha 65535 ignored
  }
  SECTION("a 16-bit PGM, scaled by its maxval") {
    writeBytes(dir / "grey16.pgm", pnm('5', 2, 2, 65535, {0, 65535, 12345, 300}));
    const TextureMap m = loaded(dir / "grey16.pgm");
    CHECK(m.bitsPerChannel() == 16);
    CHECK(m.texel(0, 0) == 0.0);
    CHECK(m.texel(1, 0) == 1.0);
    CHECK(m.texel(0, 1) == 12345 / 65535.0);
    CHECK(m.texel(1, 1) == 300 / 65535.0);
    writeBytes(dir / "grey12.pgm", pnm('5', 2, 1, 4095, {4095, 5000}));
    const TextureMap m12 = loaded(dir / "grey12.pgm");
    CHECK(m12.texel(0, 0) == 1.0);
    CHECK(m12.texel(1, 0) == 1.0);  // above maxval: full scale
  }
  SECTION("a PGM with comments in its header") {
    writeBytes(dir / "noted.pgm", std::string("P5\n# painted by hand\n2 # wide\n1\n255\n") + char(7) + char(250));
    const TextureMap m = loaded(dir / "noted.pgm");
    CHECK(m.texel(0, 0) == 7 / 255.0);
    CHECK(m.texel(1, 0) == 250 / 255.0);
  }
  SECTION("an 8-bit PPM with a small maxval") {
    writeBytes(dir / "rgb.ppm", pnm('6', 1, 1, 100, {20, 50, 10}));
    const TextureMap m = loaded(dir / "rgb.ppm");
    CHECK(m.bitsPerChannel() == 8);
    CHECK(m.texel(0, 0) == 50 / 100.0);
  }
}

TEST_CASE("a JPEG texture reads close to what was written", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "jpeg");
  // A flat image: JPEG keeps a flat block's level up to rounding.
  const std::vector<unsigned char> flat(16 * 16 * 3, 128);
  REQUIRE(stbi_write_jpg((dir / "flat.jpg").c_str(), 16, 16, 3, flat.data(), 100) != 0);
  const TextureMap m = loaded(dir / "flat.jpg");
  CHECK(m.width() == 16);
  CHECK(m.sample(0.3, 0.6) == Approx(128 / 255.0).margin(2 / 255.0));
}

TEST_CASE("texture errors name the file and say what is wrong", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "errors");
  const std::string missing = (dir / "missing.png").string();
  CHECK(loadError(missing) == missing + ": no such file");

  writeBytes(dir / "notes.png", "these are not pixels\n");
  std::string e = loadError(dir / "notes.png");
  CHECK(e.rfind((dir / "notes.png").string() + ": not an image fgsg reads (PNG, JPEG, BMP, PGM/PPM): ", 0) == 0);

  // A PNG cut off inside its pixel data, or before its IEND chunk: the header reads, and
  // the file is refused before the decoder could make up the missing pixels.
  std::string png = png16(8, 8, 0, std::vector<int>(64, 1234));
  writeBytes(dir / "cut16.png", png.substr(0, png.size() - 60));
  e = loadError(dir / "cut16.png");
  CHECK(e.rfind((dir / "cut16.png").string() + ": the PNG file is truncated: ", 0) == 0);
  const fs::path good8 = png8(dir, "good8.png", 8, 8, 1, std::vector<unsigned char>(64, 77));
  const std::string bytes8 = fgsg::test::readFile(good8);
  writeBytes(dir / "cut8.png", bytes8.substr(0, bytes8.size() - 12));
  e = loadError(dir / "cut8.png");
  CHECK(e.rfind((dir / "cut8.png").string() + ": the PNG file is truncated: it ends after ", 0) == 0);

  writeBytes(dir / "empty.pgm", pnm('5', 0, 0, 255, {}));
  CHECK(loadError(dir / "empty.pgm") == (dir / "empty.pgm").string() + ": the image is empty (0 x 0)");

  writeBytes(dir / "wide.pgm", pnm('5', 20000, 1, 255, {}));
  CHECK(loadError(dir / "wide.pgm") == (dir / "wide.pgm").string() +
                                           ": the image is 20000 x 1 texels, larger than the limit for "
                                           "textures (16384 per side, 67108864 in all)");
  // Within the side limit, beyond the texel limit: refused before any pixel is decoded.
  const std::string big = std::string("\x89PNG\r\n\x1a\n", 8) +
        chunk("IHDR", bigEndian32(16384) + bigEndian32(16384) + char(8) + char(0) + char(0) + char(0) + char(0));
  writeBytes(dir / "big.png", big);
  CHECK(loadError(dir / "big.png") == (dir / "big.png").string() +
                                         ": the image is 16384 x 16384 texels, larger than the limit for "
                                         "textures (16384 per side, 67108864 in all)");

  writeBytes(dir / "cut.pgm", pnm('5', 4, 4, 65535, std::vector<int>(15, 9)));
  CHECK(loadError(dir / "cut.pgm") ==
        (dir / "cut.pgm").string() + ": the PGM/PPM file is truncated: 30 bytes of samples, 32 needed");
  writeBytes(dir / "deep.pgm", pnm('5', 1, 1, 70000, {1}));
  CHECK(loadError(dir / "deep.pgm") ==
        (dir / "deep.pgm").string() + ": the PGM/PPM maxval is 70000, not between 1 and 65535");
  writeBytes(dir / "short.pgm", "P5\n4\n");
  CHECK(loadError(dir / "short.pgm") ==
        (dir / "short.pgm").string() + ": the PGM/PPM header lacks its width, height or maxval");
  writeBytes(dir / "unended.pgm", "P5 1 1 255");
  CHECK(loadError(dir / "unended.pgm") ==
        (dir / "unended.pgm").string() + ": the PGM/PPM header does not end in a blank after its maxval");

  CHECK(loadError(dir) == dir.string() + ": is a directory, not a texture image");
}

TEST_CASE("a failed texture load keeps the texture already loaded", "[texture]") {
  const auto dir = fgsg::test::scratchDir("texture", "keep");
  TextureMap m = loaded(png8(dir, "one.png", 1, 1, 1, {100}));
  std::string error;
  CHECK_FALSE(m.load((dir / "none.png").string(), error));
  CHECK(m.width() == 1);
  CHECK(m.texel(0, 0) == 100 / 255.0);
}

TEST_CASE("a plain (ASCII) PGM or PPM reads as its binary twin does", "[texture][pnm]") {
  const auto dir = fgsg::test::scratchDir("texture", "plain");
  SECTION("8-bit P2 with comments and ragged whitespace") {
    writeBytes(dir / "grey.pgm", "P2 # painted in a text editor\n3\t2\n# maxval next\n255\n"
                                 "0   128\n\n255 # end of row 1 is mid-line\r\n7\t\t8 9   \n");
    writeBytes(dir / "grey5.pgm", pnm('5', 3, 2, 255, {0, 128, 255, 7, 8, 9}));
    const TextureMap m = loaded(dir / "grey.pgm"), twin = loaded(dir / "grey5.pgm");
    CHECK(m.width() == 3);
    CHECK(m.height() == 2);
    CHECK(m.bitsPerChannel() == 8);
    const int expected[2][3] = {{0, 128, 255}, {7, 8, 9}};
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        CHECK(m.texel(i, j) == expected[j][i] / 255.0);
        CHECK(m.texel(i, j) == twin.texel(i, j));
      }
  }
  SECTION("16-bit P2 up to maxval 65535") {
    writeBytes(dir / "grey16.pgm", "P2\n2 2\n65535\n0 65535\n12345 300\n");
    const TextureMap m = loaded(dir / "grey16.pgm");
    CHECK(m.bitsPerChannel() == 16);
    CHECK(m.texel(0, 0) == 0.0);
    CHECK(m.texel(1, 0) == 1.0);
    CHECK(m.texel(0, 1) == 12345 / 65535.0);
    CHECK(m.texel(1, 1) == 300 / 65535.0);
  }
  SECTION("a small maxval scales the samples") {
    writeBytes(dir / "four.pgm", "P2 2 1 4 1 4");
    const TextureMap m = loaded(dir / "four.pgm");
    CHECK(m.texel(0, 0) == 0.25);
    CHECK(m.texel(1, 0) == 1.0);
  }
  SECTION("P3 colour, brightest channel as P6") {
    writeBytes(dir / "rgb.ppm", "P3\n1 1\n100\n20 50 10\n");
    CHECK(loaded(dir / "rgb.ppm").texel(0, 0) == 50 / 100.0);
  }
}

TEST_CASE("a broken plain PGM is refused with its line and sample", "[texture][pnm]") {
  const auto dir = fgsg::test::scratchDir("texture", "plain_errors");
  const auto error = [&](const std::string& name, const std::string& bytes) {
    writeBytes(dir / name, bytes);
    const std::string e = loadError(dir / name);
    CHECK(e.rfind((dir / name).string() + ": ", 0) == 0);
    return e.substr((dir / name).string().size() + 2);
  };
  CHECK(error("short.pgm", "P2\n2 2\n255\n1 2\n3\n") ==
        "the plain PGM/PPM file is truncated: it ends at line 6 after 3 of its 4 samples");
  CHECK(error("letter.pgm", "P2\n2 1\n255\n1\nx\n") ==
        "the plain PGM/PPM file has 'x' at line 5 in sample 2 (row 1, column 2), which should be a decimal number");
  CHECK(error("glued.pgm", "P2\n2 1\n255\n12a 3\n") ==
        "the plain PGM/PPM file has 'a' at line 4 in sample 1 (row 1, column 1), which should be a decimal number");
  CHECK(error("minus.pgm", "P2\n1 2\n255\n0\n-4\n") ==
        "the plain PGM/PPM file has '-' at line 5 in sample 2 (row 2, column 1), which should be a decimal number");
  CHECK(error("bright.pgm", "P2\n2 1\n255\n255 256\n") ==
        "the plain PGM/PPM file's sample 2 (row 1, column 2) at line 4 is 256, above its maxval 255");
  CHECK(error("huge.pgm", "P2\n1 1\n65535\n99999999999\n") ==
        "the plain PGM/PPM file's sample 1 (row 1, column 1) at line 4 is above 10^8, above its maxval 65535");
  CHECK(error("long.pgm", "P2\n1 1\n255\n1 2\n") ==
        "the plain PGM/PPM file goes on after its 1 samples: '2' at line 4 (is its width or height wrong?)");
  CHECK(error("binary.pgm", std::string("P2\n1 1\n255\n") + char(0)) ==
        "the plain PGM/PPM file has byte 0x00 at line 4 in sample 1 (row 1, column 1), which should be a decimal number");
  CHECK(error("deep.pgm", "P2\n1 1\n70000\n1\n") == "the PGM/PPM maxval is 70000, not between 1 and 65535");
  CHECK(error("noheader.pgm", "P2\n4\n") == "the PGM/PPM header lacks its width, height or maxval");
}
