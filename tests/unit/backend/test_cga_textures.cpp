// CGA's Texture: leaves below it get texture coordinates projected from the scope it ran
// in, so a facade's split pieces continue one brick pattern, and the assembled mesh says
// which triangles draw which image.
#include "derive_helpers.h"

#include "runtime/assemble.h"
#include "runtime/io/glb_writer.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace fgsg;
using Catch::Matchers::Contains;

namespace {

rt::DeriveOptions withExamples() {
  rt::DeriveOptions o;
  o.assetDirs = {std::string(FGSG_SOURCE_DIR) + "/examples"};
  return o;
}

// The result assembled, its asset files looked up in `assetDir` (none: built-ins only).
rt::Mesh assembled(const rt::DeriveResult& r, const std::filesystem::path& assetDir = {}) {
  REQUIRE(r.ok);
  rt::AssetLibrary library;
  if (!assetDir.empty()) library.addSearchDir(assetDir.string());
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(rt::resolveAssets(r.instances, library, meshOf, error));
  return rt::assembleInstances(r.instances, library, meshOf);
}

struct Range {
  double lo = 1e300, hi = -1e300;
  void add(double x) { lo = std::min(lo, x), hi = std::max(hi, x); }
};

// The u and v ranges of the texture coordinates of the vertices of instance `which`'s own mesh.
std::pair<Range, Range> uvRange(const rt::DeriveResult& r, size_t which) {
  const rt::Mesh& m = r.instances.geometries.at(r.instances.instances.at(which).geometry);
  REQUIRE(m.hasTexcoords());
  Range u, v;
  for (size_t i = 0; i < m.vertexCount(); ++i) u.add(m.texcoords[2 * i]), v.add(m.texcoords[2 * i + 1]);
  return {u, v};
}

}  // namespace

TEST_CASE("a textured facade is tiled in metres from the scope Texture ran in", "[cga][texture]") {
  // (The one-part Subdiv makes it a CGA grammar, whose leaves output their own geometry.)
  const auto r = test::deriveText("Lot ~> S(10, 6, 0) Texture(\"textures/brick.png\", 2, 3) Subdiv(\"X\", 1r){ Wall };",
                                  withExamples());
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 1);
  REQUIRE(r.instances.textures.size() == 1);
  CHECK_THAT(r.instances.textures[0], Contains("examples/textures/brick.png"));
  CHECK(r.instances.instances[0].texture == 0);
  const auto [u, v] = uvRange(r, 0);
  CHECK(u.lo == Approx(0).margin(1e-6));
  CHECK(u.hi == Approx(5));
  CHECK(v.lo == Approx(0).margin(1e-6));
  CHECK(v.hi == Approx(2));
  const rt::Mesh m = assembled(r);
  REQUIRE(m.textureRuns.size() == 1);
  CHECK(m.textureRuns[0].firstTriangle == 0);
  CHECK(m.textureRuns[0].texture == 0);
  for (float c : m.colors) CHECK(c == 1.0f);  // the image untinted
}

TEST_CASE("split pieces continue the pattern of the scope that set the texture up", "[cga][texture]") {
  const auto r = test::deriveText(
      "Lot ~> S(10, 6, 0) Texture(\"textures/brick.png\", 2, 3) Subdiv(\"X\", 4, 6){ A | B };", withExamples());
  REQUIRE(r.instances.instances.size() == 2);
  const auto [ua, va] = uvRange(r, 0);
  const auto [ub, vb] = uvRange(r, 1);
  CHECK(ua.lo == Approx(0).margin(1e-6));
  CHECK(ua.hi == Approx(2));
  CHECK(ub.lo == Approx(2));
  CHECK(ub.hi == Approx(5));
  CHECK(vb.hi == Approx(2));
}

TEST_CASE("each face of a textured box is projected on the plane it faces most", "[cga][texture]") {
  // One image over the scope (no tile sizes): 4 m across, 3 m up.
  const auto r =
      test::deriveText("Lot ~> S(4, 3, 2) Texture(\"textures/brick.png\") Subdiv(\"X\", 1r){ Mass };", withExamples());
  REQUIRE(r.instances.instances.size() == 1);
  const rt::Mesh& m = r.instances.geometries.at(r.instances.instances[0].geometry);
  int front = 0, top = 0, right = 0;
  for (size_t i = 0; i < m.vertexCount(); ++i) {
    const float* n = &m.normals[3 * i];
    const float* p = &m.positions[3 * i];
    const double u = m.texcoords[2 * i], v = m.texcoords[2 * i + 1];
    if (n[2] > 0.5f) {  // the front (+Z): the scope's XY plane, as CGA projects
      ++front;
      CHECK(u == Approx(p[0]).margin(1e-6));
      CHECK(v == Approx(p[1]).margin(1e-6));
    } else if (n[1] > 0.5f) {  // the top, seen from above: v runs against Z
      ++top;
      CHECK(u == Approx(p[0]).margin(1e-6));
      CHECK(v == Approx(-2.0 * p[2] / 3.0).margin(1e-6));
    } else if (n[0] > 0.5f) {  // the right side (+X), seen from the right: u runs against Z
      ++right;
      CHECK(u == Approx(-2.0 * p[2] / 4.0).margin(1e-6));
      CHECK(v == Approx(p[1]).margin(1e-6));
    }
  }
  CHECK(front == 4);
  CHECK(top == 4);
  CHECK(right == 4);
}

TEST_CASE("textured and plain leaves make texture runs and a glb with one primitive per image", "[cga][texture]") {
  const auto r = test::deriveText(
      "Lot ~> S(10, 6, 0) Subdiv(\"X\", 3, 4, 3){ Plain | Texture(\"textures/brick.png\", 2, 3) Color(1, 0.5, 0.5) Brick "
      "| Plain };",
      withExamples());
  const rt::Mesh m = assembled(r);
  REQUIRE(m.textureRuns.size() == 3);
  CHECK(m.textureRuns[0].texture == -1);
  CHECK(m.textureRuns[1].texture == 0);
  CHECK(m.textureRuns[1].firstTriangle == 2);
  CHECK(m.textureRuns[2].texture == -1);
  CHECK(m.textureRuns[2].firstTriangle == 4);
  CHECK(m.colors[3 * 4 + 1] == 0.5f);  // Color tints the image: the brick's first vertex
  std::vector<rt::io::EmbeddedImage> images;
  std::string error;
  REQUIRE(rt::io::readImages(m, images, error));
  REQUIRE(images.size() == 1);
  CHECK(std::string(images[0].mimeType) == "image/png");
  const std::string json = rt::io::glbJson(m, images);
  CHECK_THAT(json, Contains("\"baseColorTexture\":{\"index\":0}"));
  CHECK_THAT(json, Contains("\"mimeType\":\"image/png\""));
  CHECK_THAT(json, Contains("\"material\":1"));
  // The plain triangles (4) first, then the brick's (2): index counts 12 and 6.
  CHECK_THAT(json, Contains("\"count\":12"));
  CHECK_THAT(json, Contains("\"byteOffset\":48,\"componentType\":5125,\"count\":6"));
}

TEST_CASE("Texture none takes the image away again", "[cga][texture]") {
  const auto r = test::deriveText(
      "Lot ~> S(10, 6, 0) Texture(\"textures/brick.png\", 2, 3) Subdiv(\"X\", 4, 6){ A | Texture(\"none\") B };",
      withExamples());
  REQUIRE(r.instances.instances.size() == 2);
  CHECK(r.instances.instances[0].texture == 0);
  CHECK(r.instances.instances[1].texture == UINT32_MAX);
  CHECK(r.instances.textures.size() == 1);
}

TEST_CASE("a Texture whose image is missing or not a picture stops the derivation at it", "[cga][texture]") {
  const auto missing = test::deriveText("Lot ~> S(1, 1, 0)\n  Texture(\"textures/nope.png\") A;", withExamples());
  REQUIRE_FALSE(missing.ok);
  REQUIRE(!missing.messages.empty());
  CHECK(missing.messages[0].code == "R003");
  CHECK(missing.messages[0].line == 2);
  CHECK_THAT(missing.messages[0].message, Contains("nope.png"));
  const auto notImage = test::deriveText("Lot ~> S(1, 1, 0) Texture(\"city/lots.geojson\") A;", withExamples());
  REQUIRE_FALSE(notImage.ok);
  CHECK_THAT(notImage.messages[0].message, Contains("PNG or JPEG"));
  const auto badSize = test::deriveText("Lot ~> S(1, 1, 0) Texture(\"textures/brick.png\", 0, 1) A;", withExamples());
  REQUIRE_FALSE(badSize.ok);
  CHECK(badSize.messages[0].code == "R027");
}

TEST_CASE("an asset with texture coordinates draws the image by its own, one without keeps its colours", "[texture]") {
  // Not a CGA grammar (no split, no Extrude): only the assets are output.
  const auto r = test::deriveText(
      "Lot ~> S(2, 3, 1) Texture(\"textures/window.png\") [ I(\"leaf\") ] T(3, 0, 0) I(\"cube\");", withExamples());
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 2);
  CHECK(r.instances.instances[0].texture == 0);
  CHECK(r.instances.instances[0].color == std::array<float, 3>{1.0f, 1.0f, 1.0f});
  CHECK(r.instances.instances[1].texture == UINT32_MAX);
  const rt::Mesh m = assembled(r);
  REQUIRE(m.textureRuns.size() == 2);
  CHECK(m.textureRuns[0].texture == 0);
  CHECK(m.textureRuns[1].texture == -1);
  // The leaf's corners keep its [0,1]^2 coordinates.
  Range u, v;
  for (size_t i = 0; i < 4; ++i) u.add(m.texcoords[2 * i]), v.add(m.texcoords[2 * i + 1]);
  CHECK(u.lo == 0);
  CHECK(u.hi == 1);
  CHECK(v.hi == 1);
}

namespace {

// An OBJ asset with two faces, the first in a material with an image (its .mtl's map_Kd),
// written with the image into a fresh folder.
std::filesystem::path writeWindowAsset(const std::string& image) {
  const auto dir = std::filesystem::temp_directory_path() / ("fgsg_asset_materials_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(std::string(FGSG_SOURCE_DIR) + "/examples/textures/window.png", dir / "window.png",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "win.obj") << "mtllib win.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 -1\nv 1 0 -1\n"
                                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl glass\nf 1/1 2/2 3/3 4/4\n"
                                    "usemtl plain\nf 1/1 5/2 6/3 2/4\n";
  std::ofstream(dir / "win.mtl") << "newmtl glass\nKd 1 1 1\nmap_Kd " << image << "\nnewmtl plain\nKd 0.5 0.2 0.2\n";
  return dir;
}

rt::DeriveResult deriveWithAssets(const std::string& text, const std::filesystem::path& dir) {
  ir::Module m = test::compileText(text);
  rt::AssetLibrary assets;
  assets.addSearchDir(dir.string());
  rt::DeriveOptions o = withExamples();
  return backend::interpret(m, o, assets);
}

}  // namespace

TEST_CASE("an OBJ asset keeps the images of its own materials", "[texture]") {
  const auto dir = writeWindowAsset("window.png");
  const auto own = deriveWithAssets("Lot ~> S(2, 2, 2) I(\"win.obj\");", dir);
  REQUIRE(own.ok);
  CHECK(own.instances.instances[0].color == std::array<float, 3>{1.0f, 1.0f, 1.0f});  // untinted
  const rt::Mesh m = assembled(own, dir);
  REQUIRE(m.textures.size() == 1);
  CHECK(std::filesystem::path(m.textures[0]).filename() == "window.png");
  REQUIRE(m.textureRuns.size() == 2);
  CHECK(m.textureRuns[0].texture == 0);  // the glass quad: two triangles
  CHECK(m.textureRuns[1].firstTriangle == 2);
  CHECK(m.textureRuns[1].texture == -1);
  // Under a Texture, the asset's own image stays on its glass and the Texture's goes on the rest.
  const auto under = deriveWithAssets(
      "Lot ~> S(2, 2, 2) Texture(\"textures/brick.png\") [ I(\"win.obj\") ] Subdiv(\"X\", 1r){ Wall };", dir);
  const rt::Mesh both = assembled(under, dir);
  REQUIRE(both.textures.size() == 2);
  REQUIRE(both.textureRuns.size() >= 2);
  CHECK(std::filesystem::path(both.textures[size_t(both.textureRuns[0].texture)]).filename() == "window.png");
  CHECK(std::filesystem::path(both.textures[size_t(both.textureRuns[1].texture)]).filename() == "brick.png");
  // A material image that is missing is a located error at the I().
  const auto missing = deriveWithAssets("Lot ~> S(2, 2, 2) I(\"win.obj\");", writeWindowAsset("gone.png"));
  REQUIRE_FALSE(missing.ok);
  CHECK(missing.messages[0].code == "R003");
  CHECK_THAT(missing.messages[0].message, Contains("gone.png"));
  std::filesystem::remove_all(dir);
}
