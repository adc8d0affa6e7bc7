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

namespace {

// A red unit cube at x = +2 and a blue one at x = -2: which shows where tells the side seen.
Mesh redEastBlueWest() {
  Mesh red = coloured("cube", {1.0f, 0.0f, 0.0f}), blue = coloured("cube", {0.0f, 0.0f, 1.0f});
  for (size_t v = 0; v < red.vertexCount(); ++v) red.positions[3 * v] += 2;
  for (size_t v = 0; v < blue.vertexCount(); ++v) blue.positions[3 * v] -= 2;
  const uint32_t offset = uint32_t(red.vertexCount());
  red.positions.insert(red.positions.end(), blue.positions.begin(), blue.positions.end());
  red.normals.insert(red.normals.end(), blue.normals.begin(), blue.normals.end());
  red.colors.insert(red.colors.end(), blue.colors.begin(), blue.colors.end());
  for (uint32_t i : blue.indices) red.indices.push_back(i + offset);
  red.texcoords.clear();
  return red;
}

PreviewOptions orbit(double azimuth, double elevation, double distance = 0) {
  PreviewOptions opt{160, 120, 1};
  opt.camera.fit = false;
  opt.camera.azimuthDegrees = azimuth;
  opt.camera.elevationDegrees = elevation;
  opt.camera.distance = distance;
  return opt;
}

bool reddish(std::array<uint8_t, 3> p) { return p[0] > 60 && p[1] < 20 && p[2] < 20; }
bool bluish(std::array<uint8_t, 3> p) { return p[2] > 60 && p[0] < 20 && p[1] < 20; }

// Pixels of one colour, and their mean column.
struct Blob {
  int count = 0;
  double column = 0;
};
Blob blob(const Image& img, bool (*is)(std::array<uint8_t, 3>)) {
  Blob b;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (is(pixel(img, x, y))) ++b.count, b.column += x;
  if (b.count) b.column /= b.count;
  return b;
}

}  // namespace

TEST_CASE("an orbit camera shows the side its azimuth and elevation name", "[preview][camera]") {
  const Mesh pair = redEastBlueWest();
  SECTION("azimuth 0 looks from +X: the red cube hides the blue one") {
    const Image img = render::renderImage(pair, orbit(0, 0));
    CHECK(reddish(pixel(img, 80, 60)));
    CHECK(blob(img, bluish).count == 0);
    CHECK(blob(img, reddish).count > 500);
  }
  SECTION("azimuth 180 looks from -X: blue in front") {
    const Image img = render::renderImage(pair, orbit(180, 0));
    CHECK(bluish(pixel(img, 80, 60)));
    CHECK(blob(img, reddish).count == 0);
  }
  SECTION("azimuth 90 looks from +Z: +X on the right") {
    const Image img = render::renderImage(pair, orbit(90, 0));
    const Blob red = blob(img, reddish), blue = blob(img, bluish);
    REQUIRE(red.count > 200);
    CHECK(red.count == blue.count);  // seen square on, the two faces mirror each other
    CHECK(red.column > 100);
    CHECK(blue.column < 60);
    CHECK(red.column - 79.5 == Approx(79.5 - blue.column).margin(0.01));  // pixel centres: 79.5 is the middle
    CHECK(render::renderImage(pair, orbit(90 + 360, 0)).rgb == img.rgb);  // angles wrap
  }
  SECTION("azimuth 270 (or -90) looks from -Z: +X on the left") {
    const Image img = render::renderImage(pair, orbit(-90, 0));
    CHECK(blob(img, reddish).column < 60);
    CHECK(blob(img, bluish).column > 100);
  }
  SECTION("elevation 90 looks straight down, the picture's top away from the azimuth") {
    // From above with azimuth 90, +X is right as from the front; the cubes' tops (y = 1)
    // face the camera and both are lit alike.
    const Image img = render::renderImage(pair, orbit(90, 90));
    const Blob red = blob(img, reddish), blue = blob(img, bluish);
    CHECK(red.count == blue.count);
    CHECK(red.column > 100);
    CHECK(blue.column < 60);
    // Azimuth 0 from above turns the picture a quarter: the cubes stack vertically.
    const Image turned = render::renderImage(pair, orbit(0, 90));
    CHECK(std::abs(blob(turned, reddish).column - 79.5) < 1);
    CHECK(std::abs(blob(turned, bluish).column - 79.5) < 1);
  }
  SECTION("a larger distance shows the model smaller") {
    const int fitted = blob(render::renderImage(pair, orbit(90, 0)), reddish).count;
    const int far = blob(render::renderImage(pair, orbit(90, 0, 40)), reddish).count;
    const int farther = blob(render::renderImage(pair, orbit(90, 0, 80)), reddish).count;
    CHECK(far > 0);
    CHECK(far < fitted);
    // Perspective: twice as far, a quarter of the area (within the pixel rounding).
    CHECK(double(farther) == Approx(far / 4.0).epsilon(0.15));
  }
}

TEST_CASE("the orbit at the fitted view's angles draws the fitted picture", "[preview][camera]") {
  // The default framing is the orbit at kFitAzimuthDegrees / kFitElevationDegrees with the
  // fitted distance; the two directions differ only by rounding, so at most a few
  // pixels on an edge may differ.
  const Mesh torus = coloured("torus", {0.7f, 0.6f, 0.2f});
  const Image fit = render::renderImage(torus, {160, 120, 2});
  PreviewOptions same = orbit(render::kFitAzimuthDegrees, render::kFitElevationDegrees);
  same.samplesPerAxis = 2;
  const Image img = render::renderImage(torus, same);
  int differ = 0;
  for (size_t i = 0; i < fit.rgb.size(); ++i) differ += std::abs(int(fit.rgb[i]) - int(img.rgb[i])) > 2;
  CHECK(differ <= 10);
  // A flat pattern is still fitted from above, and the orbit ignores flatness.
  Mesh quad = coloured("quad", {0.2f, 0.4f, 0.9f});
  CHECK(render::renderImage(quad, {160, 120, 1}).rgb != render::renderImage(quad, orbit(90, 90)).rgb);
}

TEST_CASE("bad camera values are refused before anything is written", "[preview][camera]") {
  const fs::path dir = scratchDir("camera_bad");
  const Mesh cube = coloured("cube", {1, 1, 1});
  std::string error;
  CHECK_FALSE(render::renderPreview(cube, orbit(0, 91), (dir / "x.png").string(), error));
  CHECK(error == "cannot write '" + (dir / "x.png").string() +
                     "': the camera's elevation is 91, not between -90 and 90 degrees");
  CHECK_FALSE(render::renderPreview(cube, orbit(std::nan(""), 0), (dir / "x.png").string(), error));
  CHECK_THAT(error, Catch::EndsWith("the camera's azimuth is not a number, not a finite angle"));
  CHECK_FALSE(render::renderPreview(cube, orbit(0, 0, -1), (dir / "x.png").string(), error));
  CHECK_THAT(error, Catch::EndsWith("the camera's distance is -1, not a positive number of scene units"));
  CHECK(fs::is_empty(dir));
  CHECK(render::renderPreview(cube, orbit(0, -90, 5), (dir / "x.png").string(), error));
}
