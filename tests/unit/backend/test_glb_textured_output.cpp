// The textured glTF path end to end, with the written .glb parsed (not searched for
// substrings): the sampler repeats and filters as a tiled facade needs, each image's
// bytes are the source file's, and the texture coordinates in the BIN chunk span the
// tiles the grammar asked for (v flipped, as glTF's v runs down).
#include "derive_helpers.h"

#include "runtime/assemble.h"
#include "runtime/io/byte_sink.h"
#include "runtime/io/glb_writer.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

using namespace fgsg;
using nlohmann::json;

namespace {

// glTF's sampler constants (the specification's GL enums).
constexpr int kRepeat = 10497, kLinear = 9729, kLinearMipmapLinear = 9987;

struct Glb {
  json gltf;
  std::string bin;
};

Glb parseGlb(const std::string& bytes) {
  Glb g;
  REQUIRE(bytes.size() >= 28);
  uint32_t magic = 0, jsonLength = 0, jsonType = 0, binLength = 0, binType = 0;
  std::memcpy(&magic, bytes.data(), 4);
  REQUIRE(magic == 0x46546C67u);  // "glTF"
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  std::memcpy(&jsonType, bytes.data() + 16, 4);
  REQUIRE(jsonType == 0x4E4F534Au);  // "JSON"
  g.gltf = json::parse(bytes.substr(20, jsonLength));
  const size_t binAt = 20 + jsonLength;
  REQUIRE(binAt + 8 <= bytes.size());
  std::memcpy(&binLength, bytes.data() + binAt, 4);
  std::memcpy(&binType, bytes.data() + binAt + 4, 4);
  REQUIRE(binType == 0x004E4942u);  // "BIN\0"
  g.bin = bytes.substr(binAt + 8, binLength);
  return g;
}

// The bytes a buffer view covers in the BIN chunk.
std::string viewBytes(const Glb& g, int view) {
  const json& v = g.gltf["bufferViews"].at(view);
  return g.bin.substr(v.value("byteOffset", size_t(0)), v["byteLength"].get<size_t>());
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A 10 x 6 wall split 4 | 6: the left piece tiled with bricks 2 wide and 3 high, the
// right with one window image per metre square.
Glb writtenFacade(std::vector<std::string>& sources) {
  rt::DeriveOptions o;
  o.assetDirs = {std::string(FGSG_SOURCE_DIR) + "/examples"};
  const auto r = test::deriveText(
      "Lot ~> S(10, 6, 0) Subdiv(\"X\", 4, 6){ Texture(\"textures/brick.png\", 2, 3) Brick "
      "| Texture(\"textures/window.png\", 1, 1) Glass };",
      o);
  REQUIRE(r.ok);
  sources = r.instances.textures;
  rt::AssetLibrary library;
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(rt::resolveAssets(r.instances, library, meshOf, error));
  const rt::Mesh mesh = rt::assembleInstances(r.instances, library, meshOf);
  std::string bytes;
  rt::io::StringSink sink(bytes);
  REQUIRE(rt::io::writeGlb(mesh, sink, error));
  REQUIRE(sink.flush());
  return parseGlb(bytes);
}

}  // namespace

TEST_CASE("a textured glb repeats its images with mipmapped linear filtering", "[texture][gltf]") {
  std::vector<std::string> sources;
  const Glb g = writtenFacade(sources);
  REQUIRE(g.gltf["samplers"].size() == 1);
  const json& sampler = g.gltf["samplers"][0];
  // Tiled textures run past [0, 1]: anything but REPEAT smears the image's edge.
  CHECK(sampler["wrapS"] == kRepeat);
  CHECK(sampler["wrapT"] == kRepeat);
  CHECK(sampler["magFilter"] == kLinear);
  CHECK(sampler["minFilter"] == kLinearMipmapLinear);
  REQUIRE(g.gltf["textures"].size() == 2);
  for (int t = 0; t < 2; ++t) {
    CHECK(g.gltf["textures"][t]["sampler"] == 0);
    CHECK(g.gltf["textures"][t]["source"] == t);
  }
  // Each material draws its own texture.
  std::vector<int> drawn;
  for (const json& m : g.gltf["materials"])
    if (m["pbrMetallicRoughness"].contains("baseColorTexture"))
      drawn.push_back(m["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<int>());
  CHECK(drawn == std::vector<int>{0, 1});
}

TEST_CASE("a textured glb embeds each image byte for byte", "[texture][gltf]") {
  std::vector<std::string> sources;
  const Glb g = writtenFacade(sources);
  REQUIRE(sources.size() == 2);
  CHECK(sources[0].size() >= 9);
  CHECK(sources[0].substr(sources[0].size() - 9) == "brick.png");
  CHECK(sources[1].substr(sources[1].size() - 10) == "window.png");
  REQUIRE(g.gltf["images"].size() == 2);
  for (size_t i = 0; i < 2; ++i) {
    const json& image = g.gltf["images"][i];
    CHECK(image["mimeType"] == "image/png");
    const std::string embedded = viewBytes(g, image["bufferView"].get<int>());
    const std::string file = readFile(sources[i]);
    CHECK(embedded.size() == file.size());
    CHECK(embedded == file);
  }
}

TEST_CASE("a textured glb's coordinates span the tiles, v flipped", "[texture][gltf]") {
  std::vector<std::string> sources;
  const Glb g = writtenFacade(sources);
  REQUIRE(g.gltf["meshes"][0]["primitives"].size() == 2);
  const json& primitive = g.gltf["meshes"][0]["primitives"][0];
  const int uvAccessor = primitive["attributes"]["TEXCOORD_0"].get<int>();
  const json& accessor = g.gltf["accessors"][uvAccessor];
  CHECK(accessor["type"] == "VEC2");
  CHECK(accessor["componentType"] == 5126);  // FLOAT
  // Two quads of four corners each.
  REQUIRE(accessor["count"] == 8);
  const std::string bytes = viewBytes(g, accessor["bufferView"].get<int>());
  REQUIRE(bytes.size() == 8 * 2 * sizeof(float));
  std::vector<float> uv(16);
  std::memcpy(uv.data(), bytes.data(), bytes.size());
  // Per image: the bricks' piece is 4 x 6 m in 2 x 3 m tiles: u 0..2, v 0..2, so
  // glTF's v = 1 - v runs -1..1; the window's piece is 6 x 6 m in 1 m tiles: 0..6, -5..1.
  const json& brickIndices = g.gltf["accessors"][primitive["indices"].get<int>()];
  const json& glassIndices = g.gltf["accessors"][g.gltf["meshes"][0]["primitives"][1]["indices"].get<int>()];
  CHECK(brickIndices["count"] == 6);
  CHECK(glassIndices["count"] == 6);
  CHECK(g.gltf["meshes"][0]["primitives"][0]["material"] == 0);
  CHECK(g.gltf["meshes"][0]["primitives"][1]["material"] == 1);
  float uLo[2] = {1e9f, 1e9f}, uHi[2] = {-1e9f, -1e9f}, vLo[2] = {1e9f, 1e9f}, vHi[2] = {-1e9f, -1e9f};
  for (int corner = 0; corner < 8; ++corner) {
    const int piece = corner / 4;  // the instances' vertices in derivation order
    uLo[piece] = std::min(uLo[piece], uv[2 * corner]), uHi[piece] = std::max(uHi[piece], uv[2 * corner]);
    vLo[piece] = std::min(vLo[piece], uv[2 * corner + 1]), vHi[piece] = std::max(vHi[piece], uv[2 * corner + 1]);
  }
  CHECK(uLo[0] == Approx(0).margin(1e-6));
  CHECK(uHi[0] == Approx(2));
  CHECK(vLo[0] == Approx(-1));
  CHECK(vHi[0] == Approx(1));
  CHECK(uLo[1] == Approx(0).margin(1e-6));
  CHECK(uHi[1] == Approx(6));
  CHECK(vLo[1] == Approx(-5));
  CHECK(vHi[1] == Approx(1));
}
