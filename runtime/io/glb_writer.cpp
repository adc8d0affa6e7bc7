#include "runtime/io/glb_writer.h"

#include "runtime/io/glb_container.h"

#include "runtime/io/mesh_attributes.h"

#include "runtime/io/read_image.h"
#include "runtime/io/read_input.h"
#include "runtime/texture/color_texture.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <span>

namespace fgsg::rt::io {

namespace {

static_assert(std::endian::native == std::endian::little, "GLB stores the arrays' bytes as they are in memory");

using nlohmann::json;

using namespace gltf;  // glTF's numeric codes, padded4

// The BIN chunk's parts in file order; each is a whole number of 4-byte values, so no
// part needs padding.
// The vertex attributes, then the triangles' indices and the line segments' (each only
// when there are some: glTF allows no empty buffer view).
struct Part {
  const char* attribute;  // nullptr: indices
  size_t bytes;
  bool lines = false;     // indices: of the line segments
};

std::vector<Part> binParts(const Mesh& mesh) {
  const size_t floatsPerVec3 = mesh.positions.size() * sizeof(float);
  std::vector<Part> parts = {{"POSITION", floatsPerVec3}};
  if (hasNormals(mesh)) parts.push_back({"NORMAL", floatsPerVec3});
  if (hasColors(mesh)) parts.push_back({"COLOR_0", floatsPerVec3});
  if (mesh.hasTexcoords()) parts.push_back({"TEXCOORD_0", mesh.texcoords.size() * sizeof(float)});
  if (!mesh.indices.empty()) parts.push_back({nullptr, mesh.indices.size() * sizeof(uint32_t)});
  if (!mesh.lines.empty()) parts.push_back({nullptr, mesh.lines.size() * sizeof(uint32_t), true});
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


// A textured mesh's triangles by image: the untextured ones (-1) first, then each image
// in Mesh::textures order; each group one primitive with one material.
struct TriangleGroup {
  int32_t texture;
  size_t triangles = 0;
};

std::vector<TriangleGroup> triangleGroups(const Mesh& mesh) {
  std::vector<TriangleGroup> groups;
  for (int32_t t = -1; t < int32_t(mesh.textures.size()); ++t) {
    size_t count = 0;
    for (size_t r = 0; r < mesh.textureRuns.size(); ++r)
      if (mesh.textureRuns[r].texture == t) count += mesh.runEnd(r) - mesh.textureRuns[r].firstTriangle;
    if (count) groups.push_back({t, count});
  }
  return groups;
}

json plainMaterial() {
  // glTF's default material is metal; fgsg's is a rough, white, two-sided dielectric.
  return {{"doubleSided", true},
          {"name", "default"},
          {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}};
}

// The material of image `texture`: its picture times the vertex colours.
json texturedMaterial(const Mesh& mesh, int32_t texture) {
  json m = plainMaterial();
  m["name"] = std::filesystem::path(mesh.textures[size_t(texture)]).stem().string();
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", texture}};
  return m;
}

}  // namespace

bool readImages(const Mesh& mesh, std::vector<EmbeddedImage>& images, std::string& error) {
  images.clear();
  if (!mesh.textured()) return true;
  for (const std::string& path : mesh.textures) {
    EmbeddedImage image;
    if (!readInputFile(path, "a texture image", image.bytes, error)) return false;
    image.mimeType = texture::ColorTexture::mimeType(image.bytes);
    if (!image.mimeType) {
      error = "the texture '" + path + "' is not a PNG or JPEG image (glTF embeds only those)";
      return false;
    }
    // Embedded as it is, so it must be whole (the file may have changed since Texture()
    // probed it): a truncated PNG would be a broken model in every viewer.
    Image header;
    if (!checkImage(path, image.bytes, ImageLimits{texture::kMaxColorTexturePixels}, header, error)) {
      error = "the texture '" + path + "' cannot be embedded: " + withoutPath(error, path);
      return false;
    }
    images.push_back(std::move(image));
  }
  return true;
}

std::string glbJson(const Mesh& mesh, const std::vector<EmbeddedImage>& images) {
  json j;
  j["asset"] = {{"generator", "fgsg"}, {"version", "2.0"}};
  j["scene"] = 0;
  // A scene without nodes for an empty mesh: valid glTF, while an empty buffer or a
  // primitive without vertices would not be. The name keeps the scene from being null.
  json scene = {{"name", "fgsg"}};
  if (!mesh.empty()) {
    json accessors = json::array(), views = json::array(), attributes = json::object();
    size_t offset = 0;
    int triangleView = -1, lineView = -1;
    for (const Part& part : binParts(mesh)) {
      json view = {{"buffer", 0}, {"byteLength", part.bytes}};
      if (offset > 0) view["byteOffset"] = offset;  // tinygltf leaves out the default 0
      view["target"] = part.attribute ? kArrayBuffer : kElementArrayBuffer;
      offset += part.bytes;
      json acc = {{"bufferView", int(views.size())}};
      views.push_back(std::move(view));
      if (!part.attribute) {  // the primitives below make the indices' accessors
        (part.lines ? lineView : triangleView) = int(views.size() - 1);
        continue;
      }
      const bool uv = std::strcmp(part.attribute, "TEXCOORD_0") == 0;
      acc["componentType"] = kFloat;
      acc["count"] = mesh.vertexCount();
      acc["type"] = uv ? "VEC2" : "VEC3";
      if (std::strcmp(part.attribute, "POSITION") == 0) positionBounds(mesh, acc);
      attributes[part.attribute] = int(accessors.size());
      accessors.push_back(std::move(acc));
    }
    json primitives = json::array(), materials = json::array();
    const auto indexAccessor = [&](int view, size_t count, size_t first) {
      json acc = {{"bufferView", view}, {"componentType", kUnsignedInt}, {"count", count}, {"type", "SCALAR"}};
      if (first) acc["byteOffset"] = first * sizeof(uint32_t);
      accessors.push_back(std::move(acc));
      return int(accessors.size() - 1);
    };
    int plainIndex = -1;  // the plain material's index, once there is one
    if (!mesh.textured()) {
      materials.push_back(plainMaterial());
      plainIndex = 0;
      if (triangleView >= 0)
        primitives.push_back({{"attributes", attributes},
                              {"indices", indexAccessor(triangleView, mesh.indices.size(), 0)},
                              {"material", 0},
                              {"mode", kTriangles}});
    } else {
      // One primitive per image over its stretch of the indices (written grouped), all
      // sharing the vertex accessors; the images follow the indices in the BIN chunk.
      const int indexView = triangleView;
      size_t firstIndex = 0;
      const std::vector<TriangleGroup> groups = triangleGroups(mesh);
      const int plain = groups.front().texture < 0 ? 1 : 0;  // the plain material, when used, is first
      if (plain) materials.push_back(plainMaterial()), plainIndex = 0;
      for (const TriangleGroup& g : groups) {
        primitives.push_back({{"attributes", attributes},
                              {"indices", indexAccessor(indexView, 3 * g.triangles, firstIndex)},
                              {"material", plain + g.texture},
                              {"mode", kTriangles}});
        firstIndex += 3 * g.triangles;
      }
      json jsonImages = json::array(), textures = json::array();
      for (size_t t = 0; t < mesh.textures.size(); ++t) {
        const size_t bytes = t < images.size() ? images[t].bytes.size() : 0;
        views.push_back({{"buffer", 0}, {"byteLength", bytes}, {"byteOffset", offset}});
        offset += padded4(bytes);
        jsonImages.push_back({{"bufferView", int(views.size() - 1)},
                              {"mimeType", t < images.size() ? images[t].mimeType : "image/png"}});
        textures.push_back({{"sampler", 0}, {"source", int(t)}});
        materials.push_back(texturedMaterial(mesh, int32_t(t)));
      }
      j["images"] = std::move(jsonImages);
      j["textures"] = std::move(textures);
      // Linear filtering with mipmaps; the images repeat (a facade tiles its bricks).
      j["samplers"] = json::array({json{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
    }
    // The line segments: one more primitive over the same vertices, plain.
    if (lineView >= 0) {
      if (plainIndex < 0) materials.push_back(plainMaterial()), plainIndex = int(materials.size() - 1);
      primitives.push_back({{"attributes", attributes},
                            {"indices", indexAccessor(lineView, mesh.lines.size(), 0)},
                            {"material", plainIndex},
                            {"mode", kLines}});
    }
    j["accessors"] = std::move(accessors);
    j["bufferViews"] = std::move(views);
    j["buffers"] = json::array({json{{"byteLength", offset}}});
    j["materials"] = std::move(materials);
    j["meshes"] = json::array({json{{"name", "fgsg"}, {"primitives", std::move(primitives)}}});
    j["nodes"] = json::array({json{{"mesh", 0}}});
    scene["nodes"] = json::array({0});
  }
  j["scenes"] = json::array({std::move(scene)});
  return j.dump();
}

bool writeGlb(const Mesh& mesh, ByteSink& out, std::string& error) {
  std::vector<EmbeddedImage> images;
  if (!readImages(mesh, images, error)) return false;
  std::string text = glbJson(mesh, images);
  size_t bin = 0;
  if (!mesh.empty())
    for (const Part& part : binParts(mesh)) bin += part.bytes;
  for (const EmbeddedImage& image : images) bin += padded4(image.bytes.size());
  std::string prefix;
  if (!glbPrefix(text, bin, prefix, error)) return false;
  out.append(prefix);
  if (!bin) return true;
  out.append(mesh.positions.data(), mesh.positions.size() * sizeof(float));
  if (hasNormals(mesh)) out.append(mesh.normals.data(), mesh.normals.size() * sizeof(float));
  if (hasColors(mesh)) appendTransformed(out, mesh.colors, [](size_t, float c) { return clamp01(c); });
  // glTF puts the texture's origin at the top left (v down); the mesh's v is up.
  if (mesh.hasTexcoords())
    appendTransformed(out, mesh.texcoords, [](size_t i, float t) { return i % 2 ? 1.0f - t : t; });
  if (!mesh.textured())
    out.append(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
  else
    for (const TriangleGroup& g : triangleGroups(mesh))
      for (size_t r = 0; r < mesh.textureRuns.size(); ++r)
        if (mesh.textureRuns[r].texture == g.texture) {
          const size_t first = mesh.textureRuns[r].firstTriangle;
          out.append(&mesh.indices[3 * first], 3 * (mesh.runEnd(r) - first) * sizeof(uint32_t));
        }
  out.append(mesh.lines.data(), mesh.lines.size() * sizeof(uint32_t));
  for (const EmbeddedImage& image : images) {
    out.append(image.bytes);
    out.append("\0\0\0", padded4(image.bytes.size()) - image.bytes.size());
  }
  return true;
}

}  // namespace fgsg::rt::io
