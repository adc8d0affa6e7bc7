// The Embree preview: framing (3/4 perspective, top-down orthographic for flat
// patterns), shading of vertex colours and textures, determinism and the PNG file.
#include "runtime/assets.h"
#include "runtime/io/png_encode.h"
#include "runtime/render/preview.h"

#include <catch2/catch.hpp>

#include "scratch_files.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fgsg::rt;
using render::Image;
using render::PreviewOptions;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) { return fgsg::test::scratchDir("preview", name); }
using fgsg::test::readFile;

std::array<uint8_t, 3> pixel(const Image& img, int x, int y) {
  const uint8_t* p = &img.rgb[3 * (size_t(y) * img.width + x)];
  return {p[0], p[1], p[2]};
}

Mesh coloured(const char* primitive, std::array<float, 3> rgb) {
  Mesh m;
  REQUIRE(makeBuiltinPrimitive(primitive, m));
  for (size_t v = 0; v < m.vertexCount(); ++v) m.colors.insert(m.colors.end(), rgb.begin(), rgb.end());
  return m;
}

// How many pixels of the outermost rows and columns differ from the background.
int borderForeground(const Image& img, const Image& bg) {
  int n = 0;
  for (int x = 0; x < img.width; ++x)
    n += (pixel(img, x, 0) != pixel(bg, x, 0)) + (pixel(img, x, img.height - 1) != pixel(bg, x, img.height - 1));
  for (int y = 0; y < img.height; ++y)
    n += (pixel(img, 0, y) != pixel(bg, 0, y)) + (pixel(img, img.width - 1, y) != pixel(bg, img.width - 1, y));
  return n;
}

// A unit quad in the XY plane (seen from above), its texture coordinates 0..1 along X and
// Y, textured all over with the image at `texturePath`.
Mesh texturedQuad(const std::string& texturePath) {
  Mesh m;
  for (float y : {0.0f, 1.0f})
    for (float x : {0.0f, 1.0f}) {
      m.positions.insert(m.positions.end(), {x, y, 0.0f});
      m.normals.insert(m.normals.end(), {0.0f, 0.0f, 1.0f});
      m.texcoords.insert(m.texcoords.end(), {x, y});
    }
  m.indices.insert(m.indices.end(), {0, 1, 3, 0, 3, 2});
  m.textures = {texturePath};
  m.textureRuns = {TextureRun{0, 0}};
  return m;
}

// A 4 x 2 image, its left half red and its right half blue: wide enough that the middle
// of each half lies away from where repeat blends the two across the edges.
std::string writeRedBluePng(const fs::path& path) {
  const std::array<uint8_t, 3> red{255, 0, 0}, blue{0, 0, 255};
  std::vector<uint8_t> rgb;
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 4; ++column) {
      const auto& c = column < 2 ? red : blue;
      rgb.insert(rgb.end(), c.begin(), c.end());
    }
  std::string png;
  REQUIRE(io::encodePng(4, 2, 3, rgb.data(), png));
  std::ofstream(path, std::ios::binary) << png;
  return path.string();
}

}  // namespace

TEST_CASE("a cube is framed in the middle of the picture", "[preview]") {
  const PreviewOptions opt{200, 150, 2};
  const Image bg = render::renderImage(Mesh{}, opt);
  const Image img = render::renderImage(coloured("cube", {0.9f, 0.1f, 0.1f}), opt);
  REQUIRE(img.width == 200);
  REQUIRE(img.height == 150);
  REQUIRE(img.rgb.size() == 200u * 150u * 3u);
  const auto centre = pixel(img, 100, 75);
  CHECK(centre != pixel(bg, 100, 75));
  CHECK(centre[0] > 2 * centre[1]);  // the red vertex colour shows
  for (auto [x, y] : {std::pair{0, 0}, {199, 0}, {0, 149}, {199, 149}}) CHECK(pixel(img, x, y) == pixel(bg, x, y));
  CHECK(borderForeground(img, bg) == 0);  // the whole cube fits
  // Faces turned differently get different brightness.
  CHECK(pixel(img, 100, 40) != pixel(img, 80, 100));
}

TEST_CASE("a flat pattern is seen from above and fills the view", "[preview]") {
  const PreviewOptions opt{160, 120, 2};
  const Image bg = render::renderImage(Mesh{}, opt);
  Mesh quad = coloured("quad", {0.2f, 0.4f, 0.9f});
  for (size_t v = 0; v < quad.vertexCount(); ++v) quad.positions[3 * v] *= 2;  // 2 x 1 plate
  const Image img = render::renderImage(quad, opt);
  // The 2:1 plate is wider than the 4:3 picture: it spans the width up to the margin.
  CHECK(pixel(img, 80, 60) != pixel(bg, 80, 60));
  CHECK(pixel(img, 10, 60) != pixel(bg, 10, 60));
  CHECK(pixel(img, 150, 60) != pixel(bg, 150, 60));
  CHECK(pixel(img, 80, 5) == pixel(bg, 80, 5));
  CHECK(pixel(img, 80, 115) == pixel(bg, 80, 115));
  CHECK(borderForeground(img, bg) == 0);
  // Seen head-on the plate is evenly lit.
  CHECK(pixel(img, 40, 60) == pixel(img, 120, 60));
}

TEST_CASE("previews are deterministic PNG files", "[preview]") {
  const fs::path dir = scratchDir("png");
  const Mesh torus = coloured("torus", {0.7f, 0.6f, 0.2f});
  std::string error, warning;
  REQUIRE(render::renderPreview(torus, {}, (dir / "a.png").string(), error, &warning));
  REQUIRE(render::renderPreview(torus, {}, (dir / "b.png").string(), error));
  CHECK(warning.empty());
  const std::string a = readFile(dir / "a.png");
  CHECK(a.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  CHECK(a == readFile(dir / "b.png"));
  // 800 x 600 by default: the IHDR chunk holds the size big-endian.
  CHECK(a.substr(16, 8) == std::string("\0\0\x03\x20\0\0\x02\x58", 8));
}

TEST_CASE("an empty mesh gives the background and a warning", "[preview]") {
  const fs::path dir = scratchDir("empty");
  std::string error, warning;
  REQUIRE(render::renderPreview(Mesh{}, {64, 48, 1}, (dir / "empty.png").string(), error, &warning));
  CHECK_THAT(warning, Catch::Contains("empty"));
  CHECK(fs::file_size(dir / "empty.png") > 0);
}

TEST_CASE("bad preview sizes and paths are errors", "[preview]") {
  const fs::path dir = scratchDir("bad");
  const Mesh cube = coloured("cube", {1, 1, 1});
  std::string error;
  CHECK_FALSE(render::renderPreview(cube, {0, 10, 1}, (dir / "x.png").string(), error));
  CHECK_THAT(error, Catch::Contains("out of range"));
  CHECK_FALSE(render::renderPreview(cube, {16, 16, 1}, (dir / "missing" / "x.png").string(), error));
  CHECK_THAT(error, Catch::Contains("No such file or directory"));
  CHECK(fs::is_empty(dir));
}

TEST_CASE("textured triangles show their image times the vertex colours", "[preview]") {
  const fs::path dir = scratchDir("textured");
  const PreviewOptions opt{64, 48, 2};
  const Mesh quad = texturedQuad(writeRedBluePng(dir / "red_blue.png"));
  const Image img = render::renderImage(quad, opt);
  // Seen from above, the quad's x = 0.25 and 0.75 fall on pixel columns 20 and 43.
  const auto left = pixel(img, 20, 24), right = pixel(img, 43, 24);
  CHECK(left[0] > 4 * left[2]);
  CHECK(left[0] > 4 * left[1]);
  CHECK(right[2] > 4 * right[0]);
  CHECK(right[2] > 4 * right[1]);

  // Vertex colours scale the image: green vertices leave nothing of the red or the blue.
  Mesh green = quad;
  for (size_t v = 0; v < green.vertexCount(); ++v)
    green.colors.insert(green.colors.end(), {0.0f, 1.0f, 0.0f});
  const Image dark = render::renderImage(green, opt);
  CHECK(pixel(dark, 20, 24) == std::array<uint8_t, 3>{0, 0, 0});
}

TEST_CASE("a texture that cannot be loaded leaves vertex colours and a warning", "[preview]") {
  const fs::path dir = scratchDir("missing_texture");
  const PreviewOptions opt{64, 48, 2};
  Mesh quad = texturedQuad((dir / "missing.png").string());
  Mesh plain = quad;
  plain.textures.clear();
  plain.textureRuns.clear();
  CHECK(render::renderImage(quad, opt).rgb == render::renderImage(plain, opt).rgb);
  std::string error, warning;
  REQUIRE(render::renderPreview(quad, opt, (dir / "a.png").string(), error, &warning));
  CHECK_THAT(warning, Catch::Contains("missing.png"));
}
