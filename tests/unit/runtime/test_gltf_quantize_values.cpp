// fgsg run --quantize's vertex data (runtime/output/gltf_writer.cpp, GltfEncoding): texture
// coordinates at least as fine as 1/4096 of a tile or left floats, and values that are not
// finite left floats as the unquantized file writes them (never cast to integers), by hand
// on one baked quad.
#include "runtime/output/gltf_writer.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::output;

namespace {

constexpr int kGltfFloat = 5126, kGltfShort = 5122;

// The unit quad in the xy plane (normals +z unless given), one textured baked part.
Scene quantizeQuadScene(const std::vector<float>& uv, const std::vector<float>& normals = {}) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  if (normals.empty())
    m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  else
    m.normals.assign(normals.begin(), normals.end());
  m.texcoords.assign(uv.begin(), uv.end());
  m.indices = {0, 1, 2, 0, 2, 3};
  Scene scene;
  Material textured;
  textured.image = 0;
  scene.materials.push_back(textured);
  scene.images.push_back((std::filesystem::path(FGSG_SOURCE_DIR) / "tests/cga/trim_textured/assets/grid.png").string());
  StartNode start;
  start.info.name = "lot";
  GroupNode group;
  group.name = "Quad";
  BakedPart part;
  part.mesh = std::move(m);
  part.materials = {0};
  part.instances = 1;
  group.baked.push_back(std::move(part));
  group.instanceCount = 1;
  start.groups.push_back(std::move(group));
  start.instanceCount = 1;
  scene.starts.push_back(std::move(start));
  scene.bakedCount = 1;
  return scene;
}

struct QuantizeGlb {
  nlohmann::json json;
  std::string bin;
};

QuantizeGlb quantizeEncode(const Scene& scene, bool quantize) {
  std::string bytes, error;
  GltfEncoding encoding;
  encoding.quantize = quantize;
  REQUIRE(encodeGltf(scene, true, bytes, error, nullptr, encoding));
  uint32_t jsonLength = 0, binLength = 0;
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  std::memcpy(&binLength, bytes.data() + 20 + jsonLength, 4);
  return {nlohmann::json::parse(bytes.substr(20, jsonLength)), bytes.substr(28 + jsonLength, binLength)};
}

const nlohmann::json& quantizeAccessor(const QuantizeGlb& g, const char* attribute) {
  const int k = g.json["meshes"][0]["primitives"][0]["attributes"][attribute].get<int>();
  return g.json["accessors"][size_t(k)];
}

// The accessor's components as stored (integers as they are, floats as floats).
std::vector<double> quantizeValues(const QuantizeGlb& g, const nlohmann::json& a, int width) {
  const nlohmann::json& view = g.json["bufferViews"][a["bufferView"].get<size_t>()];
  const int type = a["componentType"].get<int>();
  const size_t size = type == kGltfFloat ? 4 : 2;
  const size_t stride = view.value("byteStride", size_t(width) * size);
  const size_t base = view.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
  std::vector<double> out;
  for (size_t v = 0; v < a["count"].get<size_t>(); ++v)
    for (int d = 0; d < width; ++d) {
      const char* at = g.bin.data() + base + v * stride + size_t(d) * size;
      if (type == kGltfFloat) {
        float x;
        std::memcpy(&x, at, 4);
        out.push_back(x);
      } else {
        int16_t x;
        std::memcpy(&x, at, 2);
        out.push_back(x);
      }
    }
  return out;
}

}  // namespace

// u 0 .. 3.3, v 0 .. 2.7: whole tiles off, they lie within +-2 tiles: 2^13 steps per tile
// (2 * 2^14 passes 32767); each decoded value within half a step, 2^-14, of the float's
// (v written flipped, 1 - v), up to whole tiles.
TEST_CASE("gltf quantize: texture coordinates in 1/8192 tile steps within 2 tiles", "[gltf][quantize]") {
  const std::vector<float> uv{0, 0, 3.3f, 0, 3.3f, 2.7f, 0, 2.7f};
  const QuantizeGlb g = quantizeEncode(quantizeQuadScene(uv), true);
  const nlohmann::json& a = quantizeAccessor(g, "TEXCOORD_0");
  REQUIRE(a["componentType"] == kGltfShort);
  const nlohmann::json& scale =
      g.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["scale"];
  CHECK(scale[0].get<double>() == std::ldexp(1.0, -13));
  const std::vector<double> q = quantizeValues(g, a, 2);
  REQUIRE(q.size() == 8);
  for (size_t k = 0; k < 8; ++k) {
    const double want = k % 2 ? 1.0 - uv[k] : uv[k];
    const double off = q[k] * std::ldexp(1.0, -13) - want;
    CHECK(std::abs(off - std::round(off)) <= std::ldexp(1.0, -14) + 1e-6);
  }
}

// Spanning 20 tiles (+-10 about the middle) would leave 2^11 steps per tile, 1/2048: too
// coarse (half a texel of a 1024-pixel texture): floats, as without quantizing, and no
// texture transform.
TEST_CASE("gltf quantize: texture coordinates spanning 20 tiles stay floats", "[gltf][quantize]") {
  const QuantizeGlb g = quantizeEncode(quantizeQuadScene({0, 0, 20, 0, 20, 1, 0, 1}), true);
  CHECK(quantizeAccessor(g, "TEXCOORD_0")["componentType"] == kGltfFloat);
  CHECK_FALSE(g.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"].contains("extensions"));
  CHECK(quantizeAccessor(g, "POSITION")["componentType"] == 5123);  // the rest still quantized
}

// A NaN texture coordinate: the unquantized file writes it as a float; quantizing leaves the
// accessor floats too (casting NaN to a 16-bit integer is undefined). A NaN normal (a flat
// quad's normals are left out: one NaN makes it not flat) is (0, 0, 1) in both files, as
// the writer repairs it; a NaN position is refused either way.
TEST_CASE("gltf quantize: values that are not finite stay floats", "[gltf][quantize]") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Scene badUv = quantizeQuadScene({0, 0, nan, 0, 1, 1, 0, 1});
  for (bool quantize : {false, true}) {
    const QuantizeGlb g = quantizeEncode(badUv, quantize);
    CHECK(quantizeAccessor(g, "TEXCOORD_0")["componentType"] == kGltfFloat);
    CHECK(std::isnan(quantizeValues(g, quantizeAccessor(g, "TEXCOORD_0"), 2)[2]));
  }
  const Scene badNormal = quantizeQuadScene({0, 0, 1, 0, 1, 1, 0, 1}, {0, 0, 1, nan, 0, 1, 0, 0, 1, 0, 0, 1});
  for (bool quantize : {false, true}) {  // a normal that is not finite: (0, 0, 1) in both
    const QuantizeGlb g = quantizeEncode(badNormal, quantize);
    const nlohmann::json& a = quantizeAccessor(g, "NORMAL");
    CHECK(a["componentType"] == (quantize ? kGltfShort : kGltfFloat));
    const std::vector<double> n = quantizeValues(g, a, 3);
    for (size_t k = 0; k < n.size(); ++k) CHECK(n[k] == (k % 3 == 2 ? (quantize ? 32767.0 : 1.0) : 0.0));
    CHECK(quantizeAccessor(g, "TEXCOORD_0")["componentType"] == (quantize ? kGltfShort : kGltfFloat));
  }
  Scene badPosition = quantizeQuadScene({0, 0, 1, 0, 1, 1, 0, 1});
  badPosition.starts[0].groups[0].baked[0].mesh.positions[4] = nan;
  std::string bytes, error;
  GltfEncoding encoding;
  encoding.quantize = true;
  CHECK_FALSE(encodeGltf(badPosition, true, bytes, error, nullptr, encoding));
  CHECK_THAT(error, Catch::Contains("not finite"));
}
