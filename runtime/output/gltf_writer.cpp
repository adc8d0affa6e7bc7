#include "runtime/output/gltf_writer.h"

#include "runtime/io/glb_container.h"
#include "runtime/io/glb_writer.h"
#include "runtime/io/mesh_attributes.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>

namespace fgsg::rt::output {

namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little endian");

using nlohmann::json;

using namespace io::gltf;  // glTF's numeric codes, padded4, the GLB container
constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? uint8_t(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

class Writer {
 public:
  explicit Writer(const Scene& scene) : scene_(scene) {}

  bool write(bool binary, std::string& bytes, std::string& error);

 private:
  // A buffer view over `count` values of T appended to the BIN chunk.
  template <class T>
  int view(const T* data, size_t count, int target) {
    bin_.resize(padded4(bin_.size()), '\0');
    json v = {{"buffer", 0}, {"byteLength", count * sizeof(T)}, {"byteOffset", bin_.size()}};
    if (target) v["target"] = target;
    bin_.append(reinterpret_cast<const char*>(data), count * sizeof(T));
    views_.push_back(std::move(v));
    return int(views_.size() - 1);
  }
  int accessor(int view, size_t count, int componentType, const char* type, size_t byteOffset = 0) {
    json a = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (byteOffset) a["byteOffset"] = byteOffset;
    accessors_.push_back(std::move(a));
    return int(accessors_.size() - 1);
  }
  int positions(const float* p, size_t vertices);
  int normals(const Mesh& m);
  int texcoords(const Mesh& m, std::array<float, 2> shift);
  json sharedAttributes(uint32_t mesh);
  int sharedMesh(uint32_t mesh, uint32_t material);
  int instancedNode(const InstancedPart& part);
  int mirroredNode(const InstancedPart& part, size_t k);
  int bakedMesh(const GroupNode& g, const std::string& name, bool& wrote);
  int groupNode(const GroupNode& g, json node);
  int startNode(const StartNode& s);
  json materialJson(const Material& m, size_t index) const;
  bool verticesFinite(std::string& error) const;

  const Scene& scene_;
  std::string bin_;
  json views_ = json::array(), accessors_ = json::array(), meshes_ = json::array(), nodes_ = json::array();
  std::map<uint32_t, json> sharedAttributes_;                  // per shared mesh, its vertex accessors
  std::map<uint32_t, int> sharedIndices_;                      // ... and its indices' accessor
  std::map<std::pair<uint32_t, uint32_t>, int> sharedMeshes_;  // (shared mesh, material) -> glTF mesh
  std::map<uint32_t, int> materialOut_;  // Scene::materials index -> the file's (only those used)
  json materials_ = json::array();
  bool instancing_ = false;

  int material(uint32_t k) {
    const auto [it, added] = materialOut_.emplace(k, int(materials_.size()));
    if (added) materials_.push_back(materialJson(scene_.materials[k], materials_.size()));
    return it->second;
  }
};

int Writer::positions(const float* p, size_t vertices) {
  const int a = accessor(view(p, 3 * vertices, kArrayBuffer), vertices, kFloat, "VEC3");
  std::array<double, 3> lo, hi;
  lo.fill(INFINITY), hi.fill(-INFINITY);
  for (size_t v = 0; v < vertices; ++v)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], double(p[3 * v + d])), hi[d] = std::max(hi[d], double(p[3 * v + d]));
  accessors_[a]["min"] = lo;
  accessors_[a]["max"] = hi;
  return a;
}

// Unit normals (glTF requires them): a vanished one as the flattened output writes it.
int Writer::normals(const Mesh& m) {
  std::vector<float> n(m.normals.begin(), m.normals.end());
  for (size_t v = 0; v < n.size(); v += 3) {
    const double len = std::sqrt(double(n[v]) * n[v] + double(n[v + 1]) * n[v + 1] + double(n[v + 2]) * n[v + 2]);
    if (!(len > 0) || !std::isfinite(len))
      n[v] = 0, n[v + 1] = 0, n[v + 2] = 1;
    else if (std::abs(len - 1) > 1e-6)
      for (int d = 0; d < 3; ++d) n[v + d] = float(n[v + d] / len);
  }
  return accessor(view(n.data(), n.size(), kArrayBuffer), m.vertexCount(), kFloat, "VEC3");
}

// v flipped (glTF's runs down); whole tiles taken off.
int Writer::texcoords(const Mesh& m, std::array<float, 2> shift) {
  std::vector<float> t(m.texcoords.size());
  for (size_t k = 0; k < t.size(); ++k) {
    const float x = m.texcoords[k] - shift[k % 2];
    t[k] = k % 2 ? 1.0f - x : x;
  }
  return accessor(view(t.data(), t.size(), kArrayBuffer), m.vertexCount(), kFloat, "VEC2");
}

json Writer::sharedAttributes(uint32_t mesh) {
  auto it = sharedAttributes_.find(mesh);
  if (it != sharedAttributes_.end()) return it->second;
  const SharedMesh& s = scene_.meshes[mesh];
  const Mesh& m = *s.mesh;
  json attributes = {{"POSITION", positions(m.positions.data(), m.vertexCount())}};
  if (io::hasNormals(m)) attributes["NORMAL"] = normals(m);
  if (m.hasTexcoords()) attributes["TEXCOORD_0"] = texcoords(m, s.uvShift);
  sharedIndices_[mesh] = accessor(view(m.indices.data(), m.indices.size(), kElementArrayBuffer), m.indices.size(),
                                  kUnsignedInt, "SCALAR");
  return sharedAttributes_[mesh] = attributes;
}

int Writer::sharedMesh(uint32_t mesh, uint32_t material) {
  const auto at = sharedMeshes_.find({mesh, material});
  if (at != sharedMeshes_.end()) return at->second;
  json attributes = sharedAttributes(mesh);
  json primitive = {{"attributes", attributes}, {"indices", sharedIndices_[mesh]}, {"material", this->material(material)}, {"mode", kTriangles}};
  meshes_.push_back({{"name", scene_.meshes[mesh].name}, {"primitives", json::array({primitive})}});
  return sharedMeshes_[{mesh, material}] = int(meshes_.size() - 1);
}

int Writer::instancedNode(const InstancedPart& part) {
  const size_t n = part.instances.size();
  // One view per part: translations, rotations, scales, colours, one after another.
  std::vector<float> data;
  data.reserve(13 * n);
  for (const Trs& t : part.trs)
    for (double x : t.translation) data.push_back(float(x));
  for (const Trs& t : part.trs) {
    // Rounded to floats, renormalised there so that the quaternion stays a unit one.
    std::array<float, 4> q;
    double len = 0;
    for (int k = 0; k < 4; ++k) q[k] = float(t.rotation[k]), len += double(q[k]) * q[k];
    len = std::sqrt(len);
    for (float x : q) data.push_back(float(x / len));
  }
  for (const Trs& t : part.trs)
    for (double x : t.scale) data.push_back(float(x));
  for (const auto& c : part.colors)
    for (float x : c) data.push_back(io::clamp01(x));
  const int v = view(data.data(), data.size(), 0);
  json attributes = {{"TRANSLATION", accessor(v, n, kFloat, "VEC3")},
                     {"ROTATION", accessor(v, n, kFloat, "VEC4", 12 * n)},
                     {"SCALE", accessor(v, n, kFloat, "VEC3", 28 * n)},
                     {"_COLOR_0", accessor(v, n, kFloat, "VEC3", 40 * n)}};
  instancing_ = true;
  nodes_.push_back({{"name", scene_.meshes[part.mesh].name},
                    {"mesh", sharedMesh(part.mesh, part.material)},
                    {"extensions", {{kInstancing, {{"attributes", attributes}}}}},
                    {"extras", {{"asset", scene_.meshes[part.mesh].asset}, {"instances", n}}}});
  return int(nodes_.size() - 1);
}

int Writer::mirroredNode(const InstancedPart& part, size_t k) {
  const Trs& t = part.trs[k];
  nodes_.push_back({{"name", scene_.meshes[part.mesh].name},
                    {"mesh", sharedMesh(part.mesh, part.material)},
                    {"extras", {{"asset", scene_.meshes[part.mesh].asset}}},
                    {"translation", t.translation},
                    {"rotation", t.rotation},
                    {"scale", t.scale}});
  return int(nodes_.size() - 1);
}

// The group's baked parts as one glTF mesh: per part its own vertices, a primitive per
// image (untextured last) and one for its line segments.
int Writer::bakedMesh(const GroupNode& g, const std::string& name, bool& wrote) {
  json primitives = json::array();
  for (const BakedPart& part : g.baked) {
    const Mesh& m = part.mesh;
    const Material& untextured = scene_.materials[part.materials.back()];
    json attributes = {{"POSITION", positions(m.positions.data(), m.vertexCount())}};
    if (io::hasNormals(m)) attributes["NORMAL"] = normals(m);
    if (m.hasTexcoords()) attributes["TEXCOORD_0"] = texcoords(m, {0, 0});
    if (untextured.vertexColors && io::hasColors(m)) {
      std::vector<float> c(m.colors.begin(), m.colors.end());
      for (float& x : c) x = io::clamp01(x);
      attributes["COLOR_0"] = accessor(view(c.data(), c.size(), kArrayBuffer), m.vertexCount(), kFloat, "VEC3");
    }
    // The triangles grouped by image, as runs say; untextured ones (-1) last.
    std::vector<uint32_t> indices;
    indices.reserve(m.indices.size());
    std::vector<std::pair<uint32_t, size_t>> groups;  // (material, index count)
    const auto add = [&](int32_t image) {
      const size_t before = indices.size();
      if (!m.textured()) {
        if (image < 0) indices.insert(indices.end(), m.indices.begin(), m.indices.end());
      } else {
        for (size_t r = 0; r < m.textureRuns.size(); ++r)
          if (m.textureRuns[r].texture == image)
            indices.insert(indices.end(), m.indices.begin() + 3 * m.textureRuns[r].firstTriangle,
                           m.indices.begin() + 3 * m.runEnd(r));
      }
      if (indices.size() > before)
        groups.push_back({part.materials[image < 0 ? part.materials.size() - 1 : size_t(image)], indices.size() - before});
    };
    for (int32_t t = 0; t < int32_t(m.textures.size()); ++t) add(t);
    add(-1);
    if (!indices.empty()) {
      const int v = view(indices.data(), indices.size(), kElementArrayBuffer);
      size_t first = 0;
      for (const auto& [material, count] : groups) {
        primitives.push_back({{"attributes", attributes},
                              {"indices", accessor(v, count, kUnsignedInt, "SCALAR", 4 * first)},
                              {"material", this->material(material)},
                              {"mode", kTriangles}});
        first += count;
      }
    }
    if (!m.lines.empty()) {
      const int v = view(m.lines.data(), m.lines.size(), kElementArrayBuffer);
      primitives.push_back({{"attributes", attributes},
                            {"indices", accessor(v, m.lines.size(), kUnsignedInt, "SCALAR")},
                            {"material", material(part.materials.back())},
                            {"mode", kLines}});
    }
  }
  wrote = !primitives.empty();
  if (!wrote) return -1;
  meshes_.push_back({{"name", name}, {"primitives", std::move(primitives)}});
  return int(meshes_.size() - 1);
}

// The group's node (`node` holds its name and extras): its baked mesh, and a child per
// instanced part and per mirrored instance.
int Writer::groupNode(const GroupNode& g, json node) {
  json children = json::array();
  for (const InstancedPart& p : g.instanced) children.push_back(instancedNode(p));
  for (const InstancedPart& p : g.mirrored)
    for (size_t k = 0; k < p.instances.size(); ++k) children.push_back(mirroredNode(p, k));
  bool baked = false;
  const int mesh = bakedMesh(g, node.value("name", std::string("baked")), baked);
  if (baked) node["mesh"] = mesh;
  if (!g.bakedAssets.empty()) {
    json counts = json::object();
    for (const auto& [asset, count] : g.bakedAssets) counts[asset] = count;
    node["extras"]["baked"] = std::move(counts);
  }
  if (!children.empty()) node["children"] = std::move(children);
  nodes_.push_back(std::move(node));
  return int(nodes_.size() - 1);
}

int Writer::startNode(const StartNode& s) {
  json extras = {{"start", s.index}, {"instances", s.instanceCount}};
  json properties = json::object();
  for (const auto& [key, value] : s.info.numbers) properties[key] = value;
  for (const auto& [key, value] : s.info.strings) properties[key] = value;
  if (!properties.empty()) extras["properties"] = std::move(properties);
  json node = {{"name", s.info.name}, {"extras", std::move(extras)}};
  if (scene_.groupBy == GroupBy::None) {
    // No group level: the one group's contents are the start node's own.
    if (s.groups.empty()) {
      nodes_.push_back(std::move(node));
      return int(nodes_.size() - 1);
    }
    return groupNode(s.groups.front(), std::move(node));
  }
  json children = json::array();
  for (const GroupNode& g : s.groups)
    children.push_back(groupNode(g, {{"name", g.name}, {"extras", {{"instances", g.instanceCount}}}}));
  if (!children.empty()) node["children"] = std::move(children);
  nodes_.push_back(std::move(node));
  return int(nodes_.size() - 1);
}

json Writer::materialJson(const Material& m, size_t index) const {
  json pbr = {{"metallicFactor", 0.0}, {"roughnessFactor", 0.8}};
  if (!m.vertexColors && m.color != std::array<float, 3>{1, 1, 1})
    pbr["baseColorFactor"] = {io::clamp01(m.color[0]), io::clamp01(m.color[1]), io::clamp01(m.color[2]), 1.0f};
  std::string name = "material " + std::to_string(index);
  if (m.image >= 0) {
    pbr["baseColorTexture"] = {{"index", m.image}};
    name = std::filesystem::path(scene_.images[size_t(m.image)]).stem().string() + " " + std::to_string(index);
  }
  return {{"doubleSided", true}, {"name", name}, {"pbrMetallicRoughness", std::move(pbr)}};
}

bool Writer::verticesFinite(std::string& error) const {
  const auto finite = [](const Mesh& m) {
    return std::all_of(m.positions.begin(), m.positions.end(), [](float x) { return std::isfinite(x); });
  };
  for (const SharedMesh& s : scene_.meshes)
    if (!finite(*s.mesh)) return error = "the mesh '" + s.name + "' has a vertex that is not finite", false;
  for (const StartNode& s : scene_.starts)
    for (const GroupNode& g : s.groups)
      for (const BakedPart& p : g.baked)
        if (!finite(p.mesh)) return error = "a vertex of '" + s.info.name + "' is not finite", false;
  return true;
}

bool Writer::write(bool binary, std::string& bytes, std::string& error) {
  if (!verticesFinite(error)) return false;
  json j;
  j["asset"] = {{"generator", "fgsg"}, {"version", "2.0"}};
  j["scene"] = 0;
  json roots = json::array();
  for (const StartNode& s : scene_.starts) roots.push_back(startNode(s));
  // The images after the geometry, each whole.
  if (!scene_.images.empty()) {
    Mesh holder;  // io::readImages reads a mesh's images
    holder.textures = scene_.images;
    holder.textureRuns.push_back({0, 0});
    std::vector<io::EmbeddedImage> images;
    if (!io::readImages(holder, images, error)) return false;
    json jsonImages = json::array(), textures = json::array();
    for (size_t t = 0; t < images.size(); ++t) {
      jsonImages.push_back({{"bufferView", view(images[t].bytes.data(), images[t].bytes.size(), 0)},
                            {"mimeType", images[t].mimeType}});
      textures.push_back({{"sampler", 0}, {"source", int(t)}});
    }
    j["images"] = std::move(jsonImages);
    j["textures"] = std::move(textures);
    j["samplers"] = json::array({json{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
  }
  bin_.resize(padded4(bin_.size()), '\0');
  if (!accessors_.empty()) j["accessors"] = std::move(accessors_);
  if (!views_.empty()) j["bufferViews"] = std::move(views_);
  if (!bin_.empty()) {
    json buffer = {{"byteLength", bin_.size()}};
    if (!binary) buffer["uri"] = "data:application/octet-stream;base64," + base64(bin_);
    j["buffers"] = json::array({std::move(buffer)});
  }
  if (!materials_.empty()) j["materials"] = std::move(materials_);
  if (!meshes_.empty()) j["meshes"] = std::move(meshes_);
  if (!nodes_.empty()) j["nodes"] = std::move(nodes_);
  json scene = {{"name", "fgsg"}};
  if (!roots.empty()) scene["nodes"] = std::move(roots);
  j["scenes"] = json::array({std::move(scene)});
  if (instancing_) j["extensionsUsed"] = json::array({kInstancing});
  std::string text = j.dump();
  if (!binary) {
    bytes = std::move(text);
    bytes += '\n';
    return true;
  }
  if (!glbPrefix(text, bin_.size(), bytes, error)) return false;
  bytes += bin_;
  return true;
}

}  // namespace

bool encodeGltf(const Scene& scene, bool binary, std::string& bytes, std::string& error) {
  Writer w(scene);
  return w.write(binary, bytes, error);
}

bool stageGltf(const Scene& scene, const std::string& path, io::OutputTransaction& outputs, std::string& error) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".glb" && ext != ".gltf") {
    error = path + ": a scene is written as glTF (.glb or .gltf)";
    return false;
  }
  std::string bytes;
  if (!encodeGltf(scene, ext == ".glb", bytes, error)) {
    error = path + ": " + error;
    return false;
  }
  return outputs.stage(path, bytes, error);
}

}  // namespace fgsg::rt::output
