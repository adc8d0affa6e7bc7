#include "runtime/io/glb_writer.h"

#include "runtime/io/mesh_attributes.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace fgsg::rt::io {

namespace {

static_assert(std::endian::native == std::endian::little, "GLB stores the arrays' bytes as they are in memory");

using nlohmann::json;

// glTF's numeric codes.
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

// The BIN chunk's parts in file order; each is a whole number of 4-byte values, so no
// part needs padding.
struct Part {
  const char* attribute;  // nullptr: the indices
  size_t bytes;
};

std::vector<Part> binParts(const Mesh& mesh) {
  const size_t floatsPerVec3 = mesh.positions.size() * sizeof(float);
  std::vector<Part> parts = {{"POSITION", floatsPerVec3}};
  if (hasNormals(mesh)) parts.push_back({"NORMAL", floatsPerVec3});
  if (hasColors(mesh)) parts.push_back({"COLOR_0", floatsPerVec3});
  if (mesh.hasTexcoords()) parts.push_back({"TEXCOORD_0", mesh.texcoords.size() * sizeof(float)});
  parts.push_back({nullptr, mesh.indices.size() * sizeof(uint32_t)});
  return parts;
}

// Per-component bounds of the positions (glTF requires them for POSITION), as doubles
// like tinygltf's accessor stored them.
void positionBounds(const Mesh& mesh, json& acc) {
  std::array<double, 3> lo, hi;
  lo.fill(INFINITY);
  hi.fill(-INFINITY);
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    for (int d = 0; d < 3; ++d) {
      const double x = mesh.positions[3 * v + d];
      lo[d] = std::min(lo[d], x);
      hi[d] = std::max(hi[d], x);
    }
  acc["min"] = lo;
  acc["max"] = hi;
}

// Passes `values` through the sink's buffer in bounded chunks, transformed by `f(index,
// value)`: the colour clamp and the v flip need no copy of the whole array.
template <typename F>
void appendTransformed(ByteSink& out, std::span<const float> values, F f) {
  const size_t chunk = std::min<size_t>(out.bufferSize(), size_t(256) << 10) / sizeof(float);
  for (size_t at = 0; at < values.size(); at += chunk) {
    const size_t n = std::min(chunk, values.size() - at);
    char* dst = out.room(n * sizeof(float));
    for (size_t k = 0; k < n; ++k) {
      const float x = f(at + k, values[at + k]);
      std::memcpy(dst + k * sizeof(float), &x, sizeof x);
    }
    out.advance(dst + n * sizeof(float));
  }
}

void appendU32(ByteSink& out, uint32_t v) { out.append(&v, sizeof v); }

}  // namespace

std::string glbJson(const Mesh& mesh) {
  json j;
  j["asset"] = {{"generator", "fgsg"}, {"version", "2.0"}};
  j["scene"] = 0;
  // A scene without nodes for an empty mesh: valid glTF, while an empty buffer or a
  // primitive without vertices would not be. The name keeps the scene from being null.
  json scene = {{"name", "fgsg"}};
  if (!mesh.empty()) {
    json accessors = json::array(), views = json::array(), attributes = json::object();
    size_t offset = 0;
    for (const Part& part : binParts(mesh)) {
      json view = {{"buffer", 0}, {"byteLength", part.bytes}};
      if (offset > 0) view["byteOffset"] = offset;  // tinygltf leaves out the default 0
      view["target"] = part.attribute ? kArrayBuffer : kElementArrayBuffer;
      offset += part.bytes;
      json acc = {{"bufferView", int(views.size())}};
      views.push_back(std::move(view));
      if (!part.attribute) {
        acc["componentType"] = kUnsignedInt;
        acc["count"] = mesh.indices.size();
        acc["type"] = "SCALAR";
        accessors.push_back(std::move(acc));
        break;  // the indices are the last part
      }
      const bool uv = std::strcmp(part.attribute, "TEXCOORD_0") == 0;
      acc["componentType"] = kFloat;
      acc["count"] = mesh.vertexCount();
      acc["type"] = uv ? "VEC2" : "VEC3";
      if (std::strcmp(part.attribute, "POSITION") == 0) positionBounds(mesh, acc);
      attributes[part.attribute] = int(accessors.size());
      accessors.push_back(std::move(acc));
    }
    json primitive = {{"attributes", std::move(attributes)},
                      {"indices", int(accessors.size() - 1)},
                      {"material", 0},
                      {"mode", kTriangles}};
    j["accessors"] = std::move(accessors);
    j["bufferViews"] = std::move(views);
    j["buffers"] = json::array({json{{"byteLength", offset}}});
    // glTF's default material is metal; fgsg's is a rough, white, two-sided dielectric.
    j["materials"] = json::array({json{{"doubleSided", true},
                                       {"name", "default"},
                                       {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}}});
    j["meshes"] = json::array({json{{"name", "fgsg"}, {"primitives", json::array({std::move(primitive)})}}});
    j["nodes"] = json::array({json{{"mesh", 0}}});
    scene["nodes"] = json::array({0});
  }
  j["scenes"] = json::array({std::move(scene)});
  return j.dump();
}

bool writeGlb(const Mesh& mesh, ByteSink& out, std::string& error) {
  std::string text = glbJson(mesh);
  text.resize((text.size() + 3) & ~size_t(3), ' ');  // chunks are 4-byte aligned
  size_t bin = 0;
  if (!mesh.empty())
    for (const Part& part : binParts(mesh)) bin += part.bytes;
  const size_t total = 12 + 8 + text.size() + (bin ? 8 + bin : 0);
  if (total > std::numeric_limits<uint32_t>::max()) {
    error = "the GLB file would be " + std::to_string(total) + " bytes, past the format's 4 GiB limit";
    return false;
  }
  out.append("glTF", 4);
  appendU32(out, 2);
  appendU32(out, uint32_t(total));
  appendU32(out, uint32_t(text.size()));
  out.append("JSON", 4);
  out.append(text);
  if (!bin) return true;
  appendU32(out, uint32_t(bin));
  out.append("BIN\0", 4);
  out.append(mesh.positions.data(), mesh.positions.size() * sizeof(float));
  if (hasNormals(mesh)) out.append(mesh.normals.data(), mesh.normals.size() * sizeof(float));
  if (hasColors(mesh)) appendTransformed(out, mesh.colors, [](size_t, float c) { return clamp01(c); });
  // glTF puts the texture's origin at the top left (v down); the mesh's v is up.
  if (mesh.hasTexcoords())
    appendTransformed(out, mesh.texcoords, [](size_t i, float t) { return i % 2 ? 1.0f - t : t; });
  out.append(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
  return true;
}

}  // namespace fgsg::rt::io
