// Colour textures (runtime/texture/color_texture.h): exact colours at pixel centres (v up),
// bilinear blending, repeat wrapping, and the PNG/JPEG-only loading and probing.
#include "runtime/texture/color_texture.h"

#include "runtime/io/png_encode.h"
#include "scratch_files.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using fgsg::rt::texture::ColorTexture;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) { return fgsg::test::scratchDir("color_texture", name); }

std::string writeBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
  return p.string();
}

std::string png(int w, int h, const std::vector<uint8_t>& rgb) {
  std::string bytes;
  REQUIRE(fgsg::rt::io::encodePng(w, h, 3, rgb.data(), bytes));
  return bytes;
}

// Top row red, green; bottom row blue, white-ish: four colours no channel mixes up.
const std::vector<uint8_t> kFourColours = {200, 0, 0, 0, 150, 0, 0, 0, 100, 10, 20, 30};

std::array<float, 3> colour(int pixel) {
  const uint8_t* c = &kFourColours[3 * size_t(pixel)];
  return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f};
}

ColorTexture loaded(const std::string& path) {
  ColorTexture t;
  std::string error;
  if (!t.load(path, error)) FAIL(error);
  return t;
}

}  // namespace

TEST_CASE("colour textures read their exact colours at pixel centres, v up", "[color_texture]") {
  const fs::path dir = scratchDir("centres");
  const ColorTexture t = loaded(writeBytes(dir / "four.png", png(2, 2, kFourColours)));
  CHECK(t.width() == 2);
  CHECK(t.height() == 2);
  CHECK(t.sample(0.25, 0.75) == colour(0));  // top left: v = 1 is the top row
  CHECK(t.sample(0.75, 0.75) == colour(1));
  CHECK(t.sample(0.25, 0.25) == colour(2));
  CHECK(t.sample(0.75, 0.25) == colour(3));
}

TEST_CASE("colour textures repeat in both directions", "[color_texture]") {
  const fs::path dir = scratchDir("repeat");
  const ColorTexture t = loaded(writeBytes(dir / "four.png", png(2, 2, kFourColours)));
  for (double u : {0.1, 0.25, 0.6, 0.9})
    for (double v : {0.2, 0.75, 0.95}) {
      CAPTURE(u, v);
      CHECK(t.sample(u + 1, v) == t.sample(u, v));
      CHECK(t.sample(u - 3, v + 2) == t.sample(u, v));
    }
  // Across the edge the last column blends into the first: u = 0 is their midpoint.
  const auto edge = t.sample(0.0, 0.75);
  for (int c = 0; c < 3; ++c) CHECK(edge[c] == Approx((colour(0)[c] + colour(1)[c]) / 2));
}

TEST_CASE("colour textures blend bilinearly between pixel centres", "[color_texture]") {
  const fs::path dir = scratchDir("bilinear");
  const ColorTexture t = loaded(writeBytes(dir / "four.png", png(2, 2, kFourColours)));
  const auto middle = t.sample(0.5, 0.5);
  const auto topMiddle = t.sample(0.5, 0.75);
  for (int c = 0; c < 3; ++c) {
    CHECK(middle[c] == Approx((colour(0)[c] + colour(1)[c] + colour(2)[c] + colour(3)[c]) / 4));
    CHECK(topMiddle[c] == Approx((colour(0)[c] + colour(1)[c]) / 2));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(t.sample(nan, 0.5) == std::array<float, 3>{0, 0, 0});
  CHECK(t.sample(0.5, INFINITY) == std::array<float, 3>{0, 0, 0});
  CHECK(ColorTexture().sample(0.5, 0.5) == std::array<float, 3>{0, 0, 0});
}

TEST_CASE("only PNG and JPEG files are colour textures", "[color_texture]") {
  const fs::path dir = scratchDir("formats");
  ColorTexture t;
  std::string error;
  // A BMP header: stb could decode it, but glTF cannot embed it.
  const std::string bmp = writeBytes(dir / "x.bmp", std::string("BM") + std::string(60, '\0'));
  CHECK_FALSE(t.load(bmp, error));
  CHECK_THAT(error, Catch::Contains("x.bmp") && Catch::Contains("not a PNG or JPEG"));
  CHECK_FALSE(ColorTexture::probe(bmp, error));
  CHECK_THAT(error, Catch::Contains("not a PNG or JPEG"));
  CHECK_FALSE(t.load(writeBytes(dir / "empty.png", ""), error));
  CHECK_THAT(error, Catch::Contains("empty.png"));
  CHECK(t.empty());

  CHECK(std::string(ColorTexture::mimeType(png(2, 2, kFourColours))) == "image/png");
  CHECK(std::string(ColorTexture::mimeType("\xFF\xD8\xFF\xE0rest")) == "image/jpeg");
  CHECK(ColorTexture::mimeType("BM....") == nullptr);
  CHECK(ColorTexture::mimeType("") == nullptr);
}

TEST_CASE("probing checks the kind, size and completeness of a texture file without decoding it", "[color_texture]") {
  const fs::path dir = scratchDir("probe");
  std::string error;
  const std::string good = png(2, 2, kFourColours);
  CHECK(ColorTexture::probe(writeBytes(dir / "good.png", good), error));
  CHECK_FALSE(ColorTexture::probe((dir / "missing.png").string(), error));
  CHECK_THAT(error, Catch::Contains("missing.png"));

  // A header declaring 16384 x 16384 pixels (the IHDR's width and height, big-endian).
  std::string huge = good;
  huge.replace(16, 8, std::string("\0\0\x40\0\0\0\x40\0", 8));
  const std::string hugePath = writeBytes(dir / "huge.png", huge);
  CHECK_FALSE(ColorTexture::probe(hugePath, error));
  CHECK_THAT(error, Catch::Contains("16384 x 16384") && Catch::Contains("limit"));
  ColorTexture t;
  CHECK_FALSE(t.load(hugePath, error));

  // A sound header on a cut-off file: the probe finds it (Texture() would embed it as it is).
  const std::string cut = writeBytes(dir / "cut.png", good.substr(0, 40));
  CHECK_FALSE(ColorTexture::probe(cut, error));
  CHECK_THAT(error, Catch::Contains("cut.png: the PNG file is truncated"));
  CHECK_FALSE(t.load(cut, error));
  CHECK_THAT(error, Catch::Contains("cut.png: the PNG file is truncated"));
  CHECK(t.empty());
}
