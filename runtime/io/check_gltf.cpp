#include "runtime/io/check_gltf.h"

#include "runtime/io/read_input.h"
#include "runtime/memory_budget.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <vector>

namespace fgsg::rt::io {

namespace {

using json = nlohmann::json;

// What reading one placed triangle or vertex costs on the reader's path: assimp's scene,
// the welded surface (faces, texture coordinates, the position map), then the surface's
// validation and topology. Generous estimates, to refuse absurd files, not to account.
constexpr uint64_t kBytesPerPlacedTriangle = 240;
constexpr uint64_t kBytesPerPlacedVertex = 120;
// assimp holds the JSON as a DOM, several times its text.
constexpr uint64_t kJsonDomFactor = 8;

uint64_t saturatingAdd(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }
uint64_t saturatingMul(uint64_t a, uint64_t b) { return b != 0 && a > UINT64_MAX / b ? UINT64_MAX : a * b; }

uint32_t littleEndian32(std::string_view b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
         uint32_t(uint8_t(b[at + 3])) << 24;
}

// A top-level array (glTF 2.0) or object keyed by ids (glTF 1.0) of entries.
class Collection {
 public:
  Collection(const json& root, const char* name) : name_(name) {
    const auto it = root.find(name);
    if (it == root.end()) return;
    if (it->is_array()) {
      for (const json& e : *it) items_.push_back(&e);
    } else if (it->is_object()) {
      for (auto e = it->begin(); e != it->end(); ++e) {
        ids_.emplace(e.key(), items_.size());
        keys_.push_back(e.key());
        items_.push_back(&e.value());
      }
    }
  }
  size_t size() const { return items_.size(); }
  const json& operator[](size_t i) const { return *items_[i]; }
  // "nodes[3]" or "nodes['root']".
  std::string where(size_t i) const {
    return std::string(name_) + (keys_.empty() ? "[" + std::to_string(i) + "]" : "['" + keys_[i] + "']");
  }
  // What a reference names: an index (2.0) or an id (1.0); nullopt if nothing.
  std::optional<size_t> resolve(const json& ref) const {
    if (ref.is_number_unsigned() || (ref.is_number_integer() && ref.get<int64_t>() >= 0)) {
      const uint64_t i = ref.get<uint64_t>();
      if (keys_.empty() && i < items_.size()) return size_t(i);
    } else if (ref.is_string()) {
      const auto it = ids_.find(ref.get<std::string>());
      if (it != ids_.end()) return it->second;
    }
    return std::nullopt;
  }
  std::string spell(size_t i) const { return keys_.empty() ? std::to_string(i) : "'" + keys_[i] + "'"; }

 private:
  const char* name_;
  std::vector<const json*> items_;
  std::vector<std::string> keys_;
  std::unordered_map<std::string, size_t> ids_;
};

std::string spellRef(const json& ref) { return ref.is_string() ? "'" + ref.get<std::string>() + "'" : ref.dump(); }

uint64_t number(const json& object, const char* key, uint64_t fallback = 0) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number()) return fallback;
  if (it->is_number_float()) {
    const double d = it->get<double>();
    return d <= 0 ? 0 : d >= 1.8e19 ? UINT64_MAX : uint64_t(d);
  }
  return it->is_number_unsigned() ? it->get<uint64_t>() : uint64_t(std::max<int64_t>(0, it->get<int64_t>()));
}

uint64_t componentBytes(uint64_t type) {
  switch (type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 4;  // unknown: assimp refuses it; count it as the largest
  }
}

uint64_t componentCount(const json& accessor) {
  const auto it = accessor.find("type");
  const std::string type = it != accessor.end() && it->is_string() ? it->get<std::string>() : "";
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 1;
}

class Checker {
 public:
  Checker(const std::string& path, const json& root, uint64_t binChunkBytes, bool glb)
      : path_(path), nodes_(root, "nodes"), meshes_(root, "meshes"), accessors_(root, "accessors"),
        views_(root, "bufferViews"), buffers_(root, "buffers"), scenes_(root, "scenes"),
        binChunkBytes_(binChunkBytes), glb_(glb) {}

  bool run(uint64_t jsonBytes, uint64_t memoryLimit, std::string& error) {
    if (!checkBuffers(error) || !checkAccessors(error) || !checkHierarchy(error) || !checkScenes(error))
      return false;
    return checkTotals(jsonBytes, memoryLimit, error);
  }

 private:
  const std::string& path_;
  Collection nodes_, meshes_, accessors_, views_, buffers_, scenes_;
  uint64_t binChunkBytes_;
  bool glb_;
  uint64_t bufferBytes_ = 0, accessorBytes_ = 0;

  bool fail(const std::string& where, const std::string& what, std::string& error) const {
    error = path_ + ": " + where + ": " + what;
    return false;
  }

  bool checkBuffers(std::string& error) {
    for (size_t b = 0; b < buffers_.size(); ++b) {
      const json& buffer = buffers_[b];
      const uint64_t length = number(buffer, "byteLength");
      if (length > kMaxInputBytes)
        return fail(buffers_.where(b), "byteLength " + std::to_string(length) + " is larger than an input file may be (" +
                                           std::to_string(kMaxInputBytes) + " bytes)",
                    error);
      // 2.0's binary chunk: the buffer without a uri.
      if (glb_ && !buffer.contains("uri") && length > binChunkBytes_)
        return fail(buffers_.where(b), "byteLength " + std::to_string(length) + " is larger than the file's binary chunk (" +
                                           std::to_string(binChunkBytes_) + " bytes)",
                    error);
      bufferBytes_ = saturatingAdd(bufferBytes_, length);
    }
    for (size_t v = 0; v < views_.size(); ++v) {
      const json& view = views_[v];
      const auto buffer = view.contains("buffer") ? buffers_.resolve(view["buffer"]) : std::nullopt;
      if (!buffer)
        return fail(views_.where(v) + ".buffer", "names no buffer (there are " + std::to_string(buffers_.size()) + ")",
                    error);
      const uint64_t end = saturatingAdd(number(view, "byteOffset"), number(view, "byteLength"));
      const uint64_t length = number(buffers_[*buffer], "byteLength");
      if (end > length)
        return fail(views_.where(v), "reaches byte " + std::to_string(end) + " of buffer " + buffers_.spell(*buffer) +
                                         ", which has " + std::to_string(length),
                    error);
    }
    return true;
  }

  bool checkAccessors(std::string& error) {
    for (size_t a = 0; a < accessors_.size(); ++a) {
      const json& accessor = accessors_[a];
      const uint64_t count = number(accessor, "count");
      const uint64_t element = componentBytes(number(accessor, "componentType")) * componentCount(accessor);
      const auto viewRef = accessor.find("bufferView");
      if (viewRef != accessor.end() && !viewRef->is_null()) {
        const auto view = views_.resolve(*viewRef);
        if (!view)
          return fail(accessors_.where(a) + ".bufferView", "names no buffer view (there are " +
                                                               std::to_string(views_.size()) + ")",
                      error);
        const uint64_t stride = std::max(number(views_[*view], "byteStride"), element);
        const uint64_t need =
            count == 0 ? 0 : saturatingAdd(number(accessor, "byteOffset"), saturatingAdd(saturatingMul(count - 1, stride), element));
        const uint64_t have = number(views_[*view], "byteLength");
        if (need > have)
          return fail(accessors_.where(a), std::to_string(count) + " elements of " + std::to_string(element) +
                                               " bytes need " + std::to_string(need) + " bytes of buffer view " +
                                               views_.spell(*view) + ", which has " + std::to_string(have),
                      error);
      }
      // Without a view (or sparse) the elements are made in memory: they count against the
      // limit; with one they are copied out of the buffer once.
      accessorBytes_ = saturatingAdd(accessorBytes_, saturatingMul(count, element));
      if (const auto sparse = accessor.find("sparse"); sparse != accessor.end() && sparse->is_object() &&
                                                        number(*sparse, "count") > count)
        return fail(accessors_.where(a) + ".sparse.count", std::to_string(number(*sparse, "count")) +
                                                               " replaced elements of " + std::to_string(count),
                    error);
    }
    return true;
  }

  // Every node has at most one parent, and no node is its own ancestor.
  bool checkHierarchy(std::string& error) {
    const size_t none = SIZE_MAX;
    std::vector<size_t> parent(nodes_.size(), none);
    for (size_t n = 0; n < nodes_.size(); ++n) {
      const auto children = nodes_[n].find("children");
      if (children == nodes_[n].end() || !children->is_array()) continue;
      for (size_t k = 0; k < children->size(); ++k) {
        const std::string where = nodes_.where(n) + ".children[" + std::to_string(k) + "]";
        const auto child = nodes_.resolve((*children)[k]);
        if (!child)
          return fail(where, "names no node " + spellRef((*children)[k]) + " (there are " +
                                 std::to_string(nodes_.size()) + ")",
                      error);
        if (*child == n)
          return fail(where, "node " + nodes_.spell(n) + " is its own child (the node hierarchy has a cycle)", error);
        if (parent[*child] == n)
          return fail(where, "node " + nodes_.spell(*child) + " is listed twice among the children of node " +
                                 nodes_.spell(n) + " (glTF nodes form trees: a node has at most one parent)",
                      error);
        if (parent[*child] != none)
          return fail(where, "node " + nodes_.spell(*child) + " is already a child of node " +
                                 nodes_.spell(parent[*child]) + " (glTF nodes form trees: a node has at most one parent)",
                      error);
        parent[*child] = n;
      }
    }
    // With one parent each, a cycle is a walk up that comes back to a node of the same walk.
    enum : uint8_t { Unseen, OnWalk, Done };
    std::vector<uint8_t> state(nodes_.size(), Unseen);
    std::vector<size_t> walk;
    for (size_t start = 0; start < nodes_.size(); ++start) {
      walk.clear();
      size_t n = start;
      for (; n != none && state[n] == Unseen; n = parent[n]) {
        state[n] = OnWalk;
        walk.push_back(n);
      }
      if (n != none && state[n] == OnWalk)
        return fail(nodes_.where(n), "node " + nodes_.spell(n) + " is its own ancestor (the node hierarchy has a cycle)",
                    error);
      for (size_t w : walk) state[w] = Done;
    }
    parents_ = std::move(parent);
    return true;
  }

  // Each scene lists roots, each once.
  bool checkScenes(std::string& error) {
    for (size_t s = 0; s < scenes_.size(); ++s) {
      const auto list = scenes_[s].find("nodes");
      if (list == scenes_[s].end() || !list->is_array()) continue;
      std::vector<bool> listed(nodes_.size(), false);
      for (size_t k = 0; k < list->size(); ++k) {
        const std::string where = scenes_.where(s) + ".nodes[" + std::to_string(k) + "]";
        const auto node = nodes_.resolve((*list)[k]);
        if (!node)
          return fail(where, "names no node " + spellRef((*list)[k]) + " (there are " + std::to_string(nodes_.size()) + ")",
                      error);
        if (listed[*node]) return fail(where, "node " + nodes_.spell(*node) + " is listed twice", error);
        if (parents_[*node] != SIZE_MAX)
          return fail(where, "node " + nodes_.spell(*node) + " is a child of node " + nodes_.spell(parents_[*node]) +
                                 ", not a root",
                      error);
        listed[*node] = true;
      }
    }
    return true;
  }

  // Triangles and vertices of one mesh, from its primitives' accessor counts.
  void meshSize(size_t m, uint64_t& triangles, uint64_t& vertices) const {
    triangles = vertices = 0;
    const auto primitives = meshes_[m].find("primitives");
    if (primitives == meshes_[m].end() || !primitives->is_array()) return;
    for (const json& p : *primitives) {
      if (!p.is_object()) continue;
      uint64_t positions = 0;
      if (const auto attributes = p.find("attributes"); attributes != p.end() && attributes->is_object())
        if (const auto position = attributes->find("POSITION"); position != attributes->end())
          if (const auto a = accessors_.resolve(*position)) positions = number(accessors_[*a], "count");
      uint64_t corners = positions;
      if (const auto indices = p.find("indices"); indices != p.end())
        if (const auto a = accessors_.resolve(*indices)) corners = number(accessors_[*a], "count");
      const uint64_t mode = number(p, "mode", 4);
      triangles = saturatingAdd(triangles, mode == 4 ? corners / 3 : (mode == 5 || mode == 6) && corners > 2 ? corners - 2 : 0);
      vertices = saturatingAdd(vertices, positions);
    }
  }

  // Every node places its meshes once (a forest: each node is reached at most once).
  bool checkTotals(uint64_t jsonBytes, uint64_t memoryLimit, std::string& error) const {
    std::vector<uint64_t> meshTriangles(meshes_.size()), meshVertices(meshes_.size());
    for (size_t m = 0; m < meshes_.size(); ++m) meshSize(m, meshTriangles[m], meshVertices[m]);
    uint64_t triangles = 0, vertices = 0;
    for (size_t n = 0; n < nodes_.size(); ++n) {
      std::vector<const json*> refs;
      if (const auto mesh = nodes_[n].find("mesh"); mesh != nodes_[n].end()) refs.push_back(&*mesh);
      if (const auto list = nodes_[n].find("meshes"); list != nodes_[n].end() && list->is_array())
        for (const json& r : *list) refs.push_back(&r);
      for (const json* r : refs) {
        const auto m = meshes_.resolve(*r);
        if (!m) return fail(nodes_.where(n), "names no mesh " + spellRef(*r) + " (there are " + std::to_string(meshes_.size()) + ")", error);
        triangles = saturatingAdd(triangles, meshTriangles[*m]);
        vertices = saturatingAdd(vertices, meshVertices[*m]);
      }
    }
    if (triangles > kMaxGltfTriangles) {
      error = path_ + ": its " + std::to_string(nodes_.size()) + " nodes place " + std::to_string(triangles) +
              " triangles, more than a surface may have (" + std::to_string(kMaxGltfTriangles) + ")";
      return false;
    }
    uint64_t need = saturatingMul(triangles, kBytesPerPlacedTriangle);
    need = saturatingAdd(need, saturatingMul(vertices, kBytesPerPlacedVertex));
    need = saturatingAdd(need, saturatingMul(accessorBytes_, 2));
    need = saturatingAdd(need, bufferBytes_);
    need = saturatingAdd(need, saturatingMul(jsonBytes, kJsonDomFactor));
    if (need > memoryLimit) {
      error = path_ + ": reading it would take about " + formatMemorySize(need) + " (" + std::to_string(triangles) +
              " triangles placed by " + std::to_string(nodes_.size()) + " nodes, " + formatMemorySize(bufferBytes_) +
              " of buffers), more than the memory limit of " + formatMemorySize(memoryLimit) + " (--max-memory)";
      return false;
    }
    return true;
  }

  std::vector<size_t> parents_;
};

}  // namespace

bool checkGltfBounds(const std::string& path, std::string_view bytes, uint64_t memoryLimit, std::string& error) {
  // .glb: a 12-byte header ("glTF", version, length), then the JSON (2.0: a chunk of type
  // JSON, then one of type BIN; 1.0: its content length and format, then the JSON).
  std::string_view text = bytes;
  uint64_t binChunk = 0;
  const bool glb = bytes.compare(0, 4, "glTF") == 0;
  if (glb) {
    if (bytes.size() < 20) {
      error = path + ": the binary glTF file is truncated: " + std::to_string(bytes.size()) + " bytes, shorter than its header";
      return false;
    }
    const uint32_t version = littleEndian32(bytes, 4), length = littleEndian32(bytes, 8), json = littleEndian32(bytes, 12);
    if (length > bytes.size()) {
      error = path + ": the binary glTF file is truncated: its header declares " + std::to_string(length) +
              " bytes, the file has " + std::to_string(bytes.size());
      return false;
    }
    const size_t start = 20;
    if (uint64_t(start) + json > length) {
      error = path + ": the binary glTF file's JSON (" + std::to_string(json) + " bytes) runs past its end";
      return false;
    }
    text = bytes.substr(start, json);
    if (version == 2) {
      const uint64_t next = start + (uint64_t(json) + 3) / 4 * 4;
      if (next + 8 <= length) binChunk = std::min<uint64_t>(littleEndian32(bytes, size_t(next)), length - next - 8);
    }
  }
  if (saturatingMul(text.size(), kJsonDomFactor) > memoryLimit) {
    error = path + ": its JSON of " + formatMemorySize(text.size()) + " would take more than the memory limit of " +
            formatMemorySize(memoryLimit) + " (--max-memory) to read";
    return false;
  }
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    std::string why = e.what();
    if (const size_t at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
    error = path + ": the glTF JSON does not parse: " + why;
    return false;
  }
  if (!root.is_object()) {
    error = path + ": the glTF JSON is not an object";
    return false;
  }
  return Checker(path, root, binChunk, glb).run(text.size(), memoryLimit, error);
}

}  // namespace fgsg::rt::io
