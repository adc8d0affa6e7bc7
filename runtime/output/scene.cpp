#include "runtime/output/scene.h"

#include "runtime/assemble.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <tuple>
#include <unordered_map>

namespace fgsg::rt::output {

namespace {

constexpr uint32_t kNone = UINT32_MAX;
// Own geometries are equal when their unit-box positions agree to 2^-20 (a micrometre on a
// 1 m piece), normals to 2^-16 and texture coordinates, whole tiles taken off, to 2^-12 of
// a tile: the leaves of a facade repeat up to rounding, not bit for bit.
constexpr double kPositionStep = 1.0 / (1 << 20), kNormalStep = 1.0 / (1 << 16), kTexcoordStep = 1.0 / (1 << 12);
// Per-vertex variation: a group (one start shape's instances of one symbol, rule or
// label) whose instances carry more distinct colours than this — colours computed per
// shape, as `Color(P.rgb)` from a picture or `Color(Rand(...), ...)` — keeps them per
// vertex (COLOR_0, baked) and per instance (_COLOR_0, instanced) under white materials;
// any other group has a material per colour and no vertex colours.
constexpr size_t kMaxBakedColors = 64;
// What one instance of EXT_mesh_gpu_instancing costs in the file (translation, rotation,
// scale, colour), and what an instanced node costs once (its node, mesh and accessors in
// the JSON): --instancing auto instances a part only where that is smaller than baking.
constexpr size_t kInstanceBytes = 52, kInstancedNodeBytes = 600;
// The JSON of a shared mesh's accessors and views, written once.
constexpr size_t kSharedMeshBytes = 700;

// The mesh an instance draws, or nullptr when its asset is not bound.
const Mesh* drawnMesh(const Instance& inst, const SceneInput& in) {
  if (inst.geometry != kNone) return inst.geometry < in.list->geometries.size() ? &in.list->geometries[inst.geometry] : nullptr;
  const std::vector<int>& meshOf = *in.meshOf;
  if (inst.asset >= meshOf.size() || meshOf[inst.asset] < 0) return nullptr;
  return &in.library->mesh(meshOf[inst.asset]);
}

// std::llround(x), inline where x is well within int64_t (a vertex's coordinate in steps):
// truncated, then rounded half away from zero as llround does; x - t is exact there.
int64_t roundHalfAway(double x) {
  if (!(std::abs(x) < 0x1p52)) return static_cast<int64_t>(std::llround(x));
  auto t = static_cast<int64_t>(x);
  const double rest = x - double(t);
  if (rest >= 0.5) ++t;
  else if (rest <= -0.5) --t;
  return t;
}

// An own geometry's content as compared: its positions, normals and texture coordinates
// quantized (the steps are powers of two: multiplying by their inverse divides exactly),
// the whole tiles taken off the coordinates; its indices. Equal contents are one shared
// mesh.
int64_t quantizedPosition(float x) { return roundHalfAway(x * (1 / kPositionStep)); }
int64_t quantizedNormal(float x) { return roundHalfAway(x * (1 / kNormalStep)); }
int64_t quantizedTexcoord(float x, float tileShift) { return roundHalfAway((x - tileShift) * (1 / kTexcoordStep)); }

// The whole tiles below a geometry's texture coordinates (u, v), taken off them.
std::array<float, 2> tileShift(const Mesh& m) {
  if (!m.hasTexcoords()) return {0, 0};
  float lo[2] = {INFINITY, INFINITY};
  for (size_t k = 0; k < m.texcoords.size(); ++k) lo[k % 2] = std::min(lo[k % 2], m.texcoords[k]);
  return {std::floor(lo[0]), std::floor(lo[1])};
}

bool sameBits(const float* a, const float* b, size_t n) { return n == 0 || std::memcmp(a, b, n * sizeof(float)) == 0; }

// An own geometry's quantized content and its hash.
struct GeometryKey {
  std::vector<int64_t> values;  // quantized positions, normals, texture coordinates
  std::array<float, 2> shift{0, 0};
  uint64_t hash = 0;
};

// FNV-1a over 64-bit words: a collision costs only a comparison more.
uint64_t mixHash(uint64_t h, uint64_t v) { return (h ^ v) * 0x100000001B3ull; }

// Keys own geometries one after another. The pieces of a facade are mostly one unit quad
// that differs only in its texture coordinates, so the last geometry's quantized
// positions and normals (and their part of the hash) are reused where this one's are the
// same bits: only the coordinates and indices are quantized and hashed anew.
class GeometryKeyer {
 public:
  void operator()(const Mesh& m, GeometryKey& key) {
    const bool same = shapeValid_ && m.positions.size() == positionCount_ &&
                      m.normals.size() + m.positions.size() == shapeBits_.size() &&
                      sameBits(m.positions.data(), shapeBits_.data(), m.positions.size()) &&
                      sameBits(m.normals.data(), shapeBits_.data() + positionCount_, m.normals.size());
    if (!same) keyShape(m);
    key.values.clear();
    key.values.reserve(shapeValues_.size() + m.texcoords.size());
    key.values.insert(key.values.end(), shapeValues_.begin(), shapeValues_.end());
    uint64_t h = mixHash(shapeHash_, m.texcoords.size());
    key.shift = tileShift(m);
    if (m.hasTexcoords())
      for (size_t k = 0; k < m.texcoords.size(); ++k) {
        const int64_t v = quantizedTexcoord(m.texcoords[k], key.shift[k % 2]);
        key.values.push_back(v);
        h = mixHash(h, uint64_t(v));
      }
    h = mixHash(h, m.indices.size());
    for (uint32_t i : m.indices) h = mixHash(h, i);
    key.hash = h;
  }

 private:
  void keyShape(const Mesh& m) {
    positionCount_ = m.positions.size();
    shapeBits_.assign(m.positions.begin(), m.positions.end());
    shapeBits_.insert(shapeBits_.end(), m.normals.begin(), m.normals.end());
    shapeValues_.clear();
    for (float x : m.positions) shapeValues_.push_back(quantizedPosition(x));
    for (float x : m.normals) shapeValues_.push_back(quantizedNormal(x));
    uint64_t h = mixHash(mixHash(0xCBF29CE484222325ull, m.positions.size()), m.normals.size());
    for (int64_t v : shapeValues_) h = mixHash(h, uint64_t(v));
    shapeHash_ = h;
    shapeValid_ = true;
  }

  std::vector<float> shapeBits_;      // the last shape's positions, then its normals
  size_t positionCount_ = 0;
  std::vector<int64_t> shapeValues_;  // ... quantized
  uint64_t shapeHash_ = 0;
  bool shapeValid_ = false;
};

// Whether `m`, keyed as `key`, has the content of `other`. Only a geometry that hashes
// alike is compared, mostly an equal one: its values are quantized here rather than
// kept for every geometry keyed (tens of megabytes for a city's walls), and its
// positions and normals not at all where they are `m`'s bits.
bool sameGeometry(const Mesh& m, const GeometryKey& key, const Mesh& other) {
  if (m.positions.size() != other.positions.size() || m.normals.size() != other.normals.size() ||
      m.texcoords.size() != other.texcoords.size() || m.indices != other.indices)
    return false;
  const int64_t* value = key.values.data();
  if (sameBits(m.positions.data(), other.positions.data(), m.positions.size())) {
    value += m.positions.size();
  } else {
    for (float x : other.positions)
      if (quantizedPosition(x) != *value++) return false;
  }
  if (sameBits(m.normals.data(), other.normals.data(), m.normals.size())) {
    value += m.normals.size();
  } else {
    for (float x : other.normals)
      if (quantizedNormal(x) != *value++) return false;
  }
  if (!other.hasTexcoords()) return true;
  const std::array<float, 2> shift = tileShift(other);
  for (size_t k = 0; k < other.texcoords.size(); ++k)
    if (quantizedTexcoord(other.texcoords[k], shift[k % 2]) != *value++) return false;
  return true;
}

// The shared meshes of own geometries by their contents' hashes: open addressing with
// linear probing, so that looking one up allocates nothing; geometries that only hash
// alike lie one after another along the probe, each compared in full.
class OwnGeometryTable {
 public:
  // The shared mesh whose content `same(mesh)` says is the key's, found among those of
  // `hash`; else `added`, recorded under `hash`.
  template <class Same>
  uint32_t findOrAdd(uint64_t hash, uint32_t added, const Same& same) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    const size_t mask = slots_.size() - 1;
    const auto tag = uint32_t(hash >> 32);
    for (size_t at = slotOf(hash) & mask;; at = (at + 1) & mask) {
      Slot& s = slots_[at];
      if (s.mesh == kNone) {
        s = {uint32_t(hash), tag, added};
        ++used_;
        return added;
      }
      if (s.tag == tag && s.low == uint32_t(hash) && same(s.mesh)) return s.mesh;
    }
  }

 private:
  struct Slot {
    uint32_t low = 0, tag = 0;  // the hash's halves
    uint32_t mesh = kNone;
  };
  static size_t slotOf(uint64_t hash) { return size_t(hash ^ (hash >> 29) ^ (hash >> 47)); }
  static uint64_t hashOf(const Slot& s) { return uint64_t(s.tag) << 32 | s.low; }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(std::max<size_t>(1024, 2 * old.size()), Slot{});
    const size_t mask = slots_.size() - 1;
    for (const Slot& s : old) {
      if (s.mesh == kNone) continue;
      size_t at = slotOf(hashOf(s)) & mask;
      while (slots_[at].mesh != kNone) at = (at + 1) & mask;
      slots_[at] = s;
    }
  }
  std::vector<Slot> slots_;
  size_t used_ = 0;
};

// The axis along which every vertex of `m` is at 0 (a face's own geometry), or -1.
int flatAxis(const Mesh& m) {
  for (int d = 2; d >= 0; --d) {
    bool flat = true;
    for (size_t v = 0; v < m.vertexCount() && flat; ++v) flat = m.positions[3 * v + d] == 0.0f;
    if (flat) return d;
  }
  return -1;
}

// decomposeTrs of one transform after another, the last one's rotation and scale reused
// when the linear part (and last row, and flat axis) is the same bit for bit: the
// decomposition reads only those and the translation, which it copies. Instances placed
// one after another mostly share their orientation and size (a grid, a facade's row).
class TrsDecomposer {
 public:
  TrsFit operator()(const std::array<double, 16>& m, Trs& trs, int flatAxis) {
    const bool same = valid_ && flatAxis == flatAxis_ && std::memcmp(m.data(), last_.data(), 12 * sizeof(double)) == 0 &&
                      std::memcmp(&m[15], &last_[15], sizeof(double)) == 0 && std::isfinite(m[12]) &&
                      std::isfinite(m[13]) && std::isfinite(m[14]);
    if (!same) {
      fit_ = decomposeTrs(m, trs_, flatAxis);
      last_ = m, flatAxis_ = flatAxis, valid_ = true;
    }
    if (fit_ == TrsFit::Rigid || fit_ == TrsFit::Mirrored) {
      trs.rotation = trs_.rotation, trs.scale = trs_.scale;
      trs.translation = {m[12], m[13], m[14]};
    }
    return fit_;
  }

 private:
  std::array<double, 16> last_{};
  Trs trs_;
  TrsFit fit_ = TrsFit::Degenerate;
  int flatAxis_ = -1;
  bool valid_ = false;
};

struct Builder {
  const SceneInput& in;
  const InstanceList& list;
  Scene scene;
  std::vector<uint32_t> sharedOf;  // per instance: Scene::meshes index, or kNone (baked)
  std::vector<TrsFit> fitOf;
  // The transforms of the instances with a mesh to share (trsAt: per instance, its index
  // there), written as they are found: not a default Trs first for every instance.
  std::vector<Trs> trsOf;
  std::vector<uint32_t> trsAt;
  std::unordered_map<std::string, uint32_t> imageIndex;
  std::vector<uint32_t> imageOfTexture;  // per InstanceList::textures entry: its image, or kNone before first use
  // Per instance: its group's number (groupIds), the same for instances whose groups are
  // named alike.
  std::vector<uint32_t> groupOf;
  std::vector<std::string> groupNames;  // by group number
  std::vector<uint32_t> localOf;        // buildStart's, kept between starts (all kNone)

  explicit Builder(const SceneInput& input) : in(input), list(*input.list) {}

  uint32_t image(const std::string& path) {
    const auto [it, added] = imageIndex.emplace(path, uint32_t(scene.images.size()));
    if (added) scene.images.push_back(path);
    return it->second;
  }

  using MaterialKey = std::tuple<std::array<float, 3>, int32_t, bool, float, float, float, std::array<float, 3>,
                                 std::array<int32_t, Finish::kLayers>>;
  std::map<MaterialKey, uint32_t> materialIndex;
  // The last material asked for: instances after one another mostly share theirs.
  Material lastMaterial;
  uint32_t lastMaterialIndex = kNone;

  std::unordered_map<std::string, int> materialNames;  // -> how many materials took it

  uint32_t material(const Material& m) {
    if (lastMaterialIndex != kNone && m.color == lastMaterial.color && m.image == lastMaterial.image &&
        m.vertexColors == lastMaterial.vertexColors && m.roughness == lastMaterial.roughness &&
        m.metallic == lastMaterial.metallic && m.opacity == lastMaterial.opacity && m.emissive == lastMaterial.emissive &&
        m.maps == lastMaterial.maps)
      return lastMaterialIndex;
    const auto [it, added] = materialIndex.emplace(
        MaterialKey{m.color, m.image, m.vertexColors, m.roughness, m.metallic, m.opacity, m.emissive, m.maps},
        uint32_t(scene.materials.size()));
    if (added) {
      scene.materials.push_back(m);
      scene.materials.back().name = uniqueName(m);
    }
    lastMaterial = m;
    lastMaterialIndex = it->second;
    return it->second;
  }

  std::string uniqueName(const Material& m) {
    std::string name;
    if (m.image >= 0) {
      for (char c : std::filesystem::path(scene.images[size_t(m.image)]).stem().string())
        name += std::isspace(static_cast<unsigned char>(c)) ? '_' : c;
      name += '_';
    }
    if (m.vertexColors) {
      name += "vertex_colors";
    } else {
      char hex[8];
      const auto byte = [](float c) { return int(std::lround(255.0 * (std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f))); };
      std::snprintf(hex, sizeof hex, "%02x%02x%02x", byte(m.color[0]), byte(m.color[1]), byte(m.color[2]));
      name += hex;
    }
    const int taken = ++materialNames[name];
    if (taken == 1) return name;
    std::string again = name + "_" + std::to_string(taken);
    ++materialNames[again];  // a later colour cannot round to a name with a suffix
    return again;
  }

  // A mesh that instances may share, as the instances are read: a library asset, or an
  // own geometry (the first of equal ones), which becomes a shared mesh only if another
  // leaf repeats it (most of a city's walls do not: building their meshes would cost
  // more than finding them).
  struct MeshCandidate {
    const Mesh* mesh = nullptr;
    uint32_t asset = 0, symbol = 0;  // the first instance's
    bool own = false;
    std::array<float, 2> uvShift{0, 0};
    size_t uses = 0;
  };

  // Which instances can share a mesh, and which mesh: rigidly placed, not bent, drawing
  // neither line segments nor images of their own, without uv sets 1..9.
  void findShared() {
    const size_t n = list.instances.size();
    sharedOf.assign(n, kNone);
    fitOf.assign(n, TrsFit::Degenerate);
    if (in.instancing == Instancing::Off) return;
    trsAt.assign(n, kNone);
    trsOf.reserve(n);
    std::vector<MeshCandidate> candidates;  // sharedOf's numbers until the end
    candidates.reserve(in.meshOf->size() + list.geometries.size());
    // Per library mesh: its candidate, and the axis it is flat along (-2: not yet known).
    std::vector<uint32_t> ofAsset;
    std::vector<int> flatOfAsset;
    // Own geometries by their content's hash.
    OwnGeometryTable ofGeometry;
    GeometryKey key;
    GeometryKeyer keyOf;
    TrsDecomposer decompose;
    for (size_t i = 0; i < n; ++i) {
      const Instance& inst = list.instances[i];
      const Mesh* m = drawnMesh(inst, in);
      if (!m || inst.curve != kNone || m->textured() || !m->lines.empty() || m->indices.empty()) continue;
      // A leaf with CGA's uv sets 1..9 is baked: the shared meshes' keys know set 0 only.
      if (!m->uvSets.empty()) continue;
      if (inst.texture != kNone && (!m->hasTexcoords() || inst.texture >= list.textures.size())) continue;
      const int library = inst.geometry == kNone ? (*in.meshOf)[inst.asset] : -1;
      if (library >= 0 && size_t(library) >= ofAsset.size())
        ofAsset.resize(size_t(library) + 1, kNone), flatOfAsset.resize(size_t(library) + 1, -2);
      int flat;
      if (library < 0) flat = flatAxis(*m);
      else if ((flat = flatOfAsset[size_t(library)]) == -2) flat = flatOfAsset[size_t(library)] = flatAxis(*m);
      Trs trs;
      fitOf[i] = decompose(inst.transform, trs, flat);
      if (fitOf[i] != TrsFit::Rigid && fitOf[i] != TrsFit::Mirrored) continue;
      const auto added = uint32_t(candidates.size());
      uint32_t shared;
      if (library >= 0) {
        uint32_t& of = ofAsset[size_t(library)];
        if (of == kNone) of = added;
        shared = of;
      } else {
        keyOf(*m, key);
        shared = ofGeometry.findOrAdd(key.hash, added,
                                      [&](uint32_t other) { return sameGeometry(*m, key, *candidates[other].mesh); });
      }
      if (shared == added)
        candidates.push_back({m, inst.asset, inst.symbol, library < 0, library < 0 ? key.shift : std::array<float, 2>{0, 0}, 0});
      ++candidates[shared].uses;
      sharedOf[i] = shared;
      trsAt[i] = uint32_t(trsOf.size());
      trsOf.push_back(trs);
    }
    // The shared meshes in order of first use: every asset, and each own geometry that
    // another leaf repeats (one no other repeats is no asset: it is baked).
    std::vector<uint32_t> meshOfCandidate(candidates.size(), kNone);
    for (size_t k = 0; k < candidates.size(); ++k) {
      const MeshCandidate& c = candidates[k];
      if (c.own && c.uses < 2) continue;
      meshOfCandidate[k] = uint32_t(scene.meshes.size());
      const std::string& asset = list.assets[c.asset];
      scene.meshes.push_back({c.mesh, c.own ? list.symbols[c.symbol] + " piece" : asset, asset, c.uvShift, c.uses});
    }
    for (uint32_t& shared : sharedOf)
      if (shared != kNone) shared = meshOfCandidate[shared];
  }

  // Each instance's group (groupOf), numbered by name in order of first use: the symbol's
  // ("?" past the list's symbols), or its rule's group ("axiom" for none), or one "".
  void groupInstances() {
    const size_t n = list.instances.size();
    groupOf.assign(n, 0);
    if (in.groupBy == GroupBy::None) {
      groupNames = {""};
      return;
    }
    const bool bySymbol = in.groupBy == GroupBy::Symbol;
    const size_t keys = bySymbol ? list.symbols.size() : in.ruleGroups.size();
    std::vector<uint32_t> ofKey(keys + 1, kNone);  // the last: "?" or "axiom"
    std::unordered_map<std::string, uint32_t> byName;
    for (size_t i = 0; i < n; ++i) {
      size_t k;
      if (bySymbol) {
        k = std::min<size_t>(list.instances[i].symbol, keys);
      } else {
        const uint32_t rule = i < list.origins.size() ? list.origins[i].rule : kNone;
        k = std::min<size_t>(rule, keys);
      }
      if (ofKey[k] == kNone) {
        static const std::string fallback[2] = {"axiom", "?"};  // by rule, by symbol
        const std::string& name = k < keys ? (bySymbol ? list.symbols[k] : in.ruleGroups[k]) : fallback[bySymbol];
        const auto [it, added] = byName.emplace(name, uint32_t(groupNames.size()));
        if (added) groupNames.push_back(name);
        ofKey[k] = it->second;
      }
      groupOf[i] = ofKey[k];
    }
  }

  // The scene's image of InstanceList::textures entry `texture`.
  int32_t imageOf(uint32_t texture) {
    if (imageOfTexture.size() <= texture) imageOfTexture.resize(size_t(texture) + 1, kNone);
    uint32_t& img = imageOfTexture[texture];
    if (img == kNone) img = image(list.textures[texture]);
    return int32_t(img);
  }

  // A material's finish: instance i's (InstanceList::finishOf), the default where none.
  void applyFinish(Material& m, const Finish* f) {
    if (!f) return;
    m.roughness = f->roughness, m.metallic = f->metallic, m.opacity = f->opacity, m.emissive = f->emissive;
    for (uint32_t layer = 1; layer < Finish::kLayers; ++layer)
      if (f->maps[layer] != kNone && f->maps[layer] < list.textures.size()) m.maps[layer] = imageOf(f->maps[layer]);
  }

  Material materialOf(uint32_t i) {
    const Instance& inst = list.instances[i];
    Material m;
    m.color = inst.color;
    if (inst.texture != kNone) m.image = imageOf(inst.texture);
    applyFinish(m, list.finishOf(i));
    return m;
  }

  // The instances `which` assembled as the flattened output would, into world space.
  Mesh bake(const std::vector<uint32_t>& which) {
    Mesh out;
    assembleSelected(list, which, *in.library, *in.meshOf, out);
    return out;
  }

  // Whether the group's colours vary per instance (see kMaxBakedColors): then its parts
  // carry their colours per vertex (baked) or per instance (_COLOR_0), under white
  // materials, instead of a material per colour.
  bool colorsVary(const std::vector<uint32_t>& members) const {
    std::vector<std::array<float, 3>> colors;
    for (uint32_t i : members) {
      const auto& c = list.instances[i].color;
      if (!colors.empty() && c == colors.back()) continue;  // runs of one colour: no search
      if (std::find(colors.begin(), colors.end(), c) != colors.end()) continue;
      if (colors.size() == kMaxBakedColors) return true;
      colors.push_back(c);
    }
    return false;
  }

  GroupNode buildGroup(std::string name, const std::vector<uint32_t>& members) {
    GroupNode g;
    g.name = std::move(name);
    g.instanceCount = members.size();
    // (A node per instance has no colour of its own but its material's.)
    const bool vary = colorsVary(members) && in.instancing != Instancing::Nodes;
    std::vector<uint32_t> baked;
    std::map<std::tuple<uint32_t, uint32_t, bool>, size_t> partOf;  // (mesh, material, mirrored)
    std::vector<std::pair<bool, InstancedPart>> parts;
    std::tuple<uint32_t, uint32_t, bool> lastKey{kNone, kNone, false};  // and its part: runs of alike instances
    uint32_t lastPart = 0;
    // Each member's part first (kNone: baked), counted, so that the parts' arrays are
    // allocated once: a million cubes are 80 MB of transforms.
    std::vector<uint32_t> partOfMember(members.size(), kNone);
    std::vector<size_t> counts;
    for (size_t k = 0; k < members.size(); ++k) {
      const uint32_t i = members[k];
      if (sharedOf[i] == kNone) continue;
      const bool mirrored = fitOf[i] == TrsFit::Mirrored;
      Material look = materialOf(i);
      if (vary) look.color = {1, 1, 1}, look.vertexColors = true;
      const uint32_t mat = material(look);
      const auto key = std::make_tuple(sharedOf[i], mat, mirrored);
      if (key != lastKey) {
        const auto [it, added] = partOf.emplace(key, parts.size());
        if (added) parts.push_back({mirrored, InstancedPart{sharedOf[i], mat, {}, {}, {}}}), counts.push_back(0);
        lastKey = key, lastPart = uint32_t(it->second);
      }
      partOfMember[k] = lastPart;
      ++counts[lastPart];
    }
    // Which parts stay instanced (by their counts alone), so that only those get arrays:
    // a city's facades have thousands of small parts that --instancing auto bakes.
    std::vector<uint8_t> keep(parts.size(), 1);
    for (size_t k = 0; k < parts.size(); ++k) {
      const auto& [mirrored, p] = parts[k];
      if (in.instancing == Instancing::Auto) {
        // Counting the shared mesh's own bytes in full, as if this part alone wrote it.
        const Mesh& m = *scene.meshes[p.mesh].mesh;
        const size_t meshBytes = m.vertexCount() * (m.hasTexcoords() ? 32 : 24) + m.indices.size() * 4;
        keep[k] = !mirrored && counts[k] * kInstanceBytes + kInstancedNodeBytes + meshBytes + kSharedMeshBytes <
                                   counts[k] * meshBytes;
      }
      if (!keep[k]) continue;
      parts[k].second.instances.reserve(counts[k]);
      parts[k].second.trs.reserve(counts[k]);
      parts[k].second.colors.reserve(counts[k]);
    }
    // The members of baked parts join the baked ones, in placement order (members are).
    for (size_t k = 0; k < members.size(); ++k) {
      const uint32_t i = members[k];
      if (partOfMember[k] == kNone || !keep[partOfMember[k]]) {
        baked.push_back(i);
        continue;
      }
      InstancedPart& p = parts[partOfMember[k]].second;
      p.instances.push_back(i);
      p.trs.push_back(trsOf[trsAt[i]]);
      p.colors.push_back(list.instances[i].color);
    }
    for (size_t k = 0; k < parts.size(); ++k) {
      if (!keep[k]) continue;
      auto& [mirrored, p] = parts[k];
      (mirrored ? scene.mirroredCount : scene.instancedCount) += p.instances.size();
      (mirrored ? g.mirrored : g.instanced).push_back(std::move(p));
    }
    if (!std::is_sorted(baked.begin(), baked.end())) std::sort(baked.begin(), baked.end());  // as flattened
    scene.bakedCount += baked.size();
    bakeParts(baked, vary, g);
    return g;
  }

  // One baked part per colour (textured stretches with their images), or where the
  // group's colours vary one part coloured per vertex.
  void bakeParts(const std::vector<uint32_t>& baked, bool vary, GroupNode& g) {
    if (baked.empty()) return;
    // Counted by asset number, named after: the names are unique, the order of first use kept.
    std::vector<std::pair<uint32_t, size_t>> perAsset;
    for (uint32_t i : baked) {
      const uint32_t asset = list.instances[i].asset;
      auto at = std::find_if(perAsset.begin(), perAsset.end(), [&](const auto& a) { return a.first == asset; });
      if (at == perAsset.end()) perAsset.push_back({asset, 1});
      else ++at->second;
    }
    for (const auto& [asset, count] : perAsset) {
      const std::string& name = list.assets[asset];
      auto at = std::find_if(g.bakedAssets.begin(), g.bakedAssets.end(), [&](const auto& a) { return a.first == name; });
      if (at == g.bakedAssets.end()) g.bakedAssets.push_back({name, count});
      else at->second += count;
    }
    // By colour (one where they vary) and finish (InstanceList::finishIndex, 0: default).
    using Look = std::pair<std::array<float, 3>, uint32_t>;
    std::vector<Look> looks;
    std::vector<std::vector<uint32_t>> byColor;
    for (size_t last = 0; uint32_t i : baked) {
      const Look c{vary ? std::array<float, 3>{1, 1, 1} : list.instances[i].color,
                   i < list.finishIndex.size() ? list.finishIndex[i] : 0};
      const size_t k = last < looks.size() && c == looks[last] ? last
                                                                : size_t(std::find(looks.begin(), looks.end(), c) - looks.begin());
      if (k == looks.size()) looks.push_back(c), byColor.emplace_back();
      byColor[k].push_back(i);
      last = k;
    }
    const bool perVertex = vary;
    for (size_t k = 0; k < byColor.size(); ++k) {
      BakedPart part;
      part.mesh = bake(byColor[k]);
      part.instances = byColor[k].size();
      if (part.mesh.empty()) continue;
      Material base;
      if (perVertex)
        base.vertexColors = true;
      else
        base.color = looks[k].first;
      applyFinish(base, list.finishOf(byColor[k].front()));
      for (const std::string& path : part.mesh.textures) {
        Material m = base;
        m.image = int32_t(image(path));
        part.materials.push_back(material(m));
      }
      part.materials.push_back(material(base));
      g.baked.push_back(std::move(part));
    }
  }

  StartNode buildStart(StartInfo info, uint32_t index, uint32_t begin, uint32_t end) {
    StartNode s;
    s.info = std::move(info);
    s.index = index;
    s.instanceCount = end - begin;
    // The start's groups in order of first use (localOf: group number -> the start's).
    std::vector<uint32_t> used;
    std::vector<std::vector<uint32_t>> members;
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t g = groupOf[i];
      if (localOf[g] == kNone) localOf[g] = uint32_t(used.size()), used.push_back(g), members.emplace_back();
      members[localOf[g]].push_back(i);
    }
    for (uint32_t g : used) localOf[g] = kNone;
    s.groups.reserve(used.size());
    for (size_t k = 0; k < used.size(); ++k) s.groups.push_back(buildGroup(groupNames[used[k]], members[k]));
    return s;
  }

  void build() {
    scene.groupBy = in.groupBy;
    scene.instancing = in.instancing;
    findShared();
    groupInstances();
    localOf.assign(groupNames.size(), kNone);
    const auto n = uint32_t(list.instances.size());
    std::vector<uint32_t> bounds = list.startBounds;
    if (bounds.size() < 2) bounds = {0, n};
    for (uint32_t& b : bounds) b = std::min(b, n);  // an assembly cut short keeps the first instances
    for (size_t k = 0; k + 1 < bounds.size(); ++k) {
      StartInfo info = k < in.starts.size() ? in.starts[k] : StartInfo{"start " + std::to_string(k), {}, {}, {}, {}};
      scene.starts.push_back(buildStart(std::move(info), uint32_t(k), bounds[k], bounds[k + 1]));
    }
    if (bounds.back() < n)
      scene.starts.push_back(buildStart(StartInfo{"(surface and lines)", {}, {}, {}, {}}, uint32_t(bounds.size() - 1),
                                        bounds.back(), n));
  }
};

}  // namespace

Scene buildScene(const SceneInput& in) {
  Builder b(in);
  b.build();
  return std::move(b.scene);
}

StartSummary summarizeStart(const Scene& scene, const StartNode& start) {
  StartSummary sum;
  const auto add = [&](const float* p, const std::array<double, 16>* m) {
    double w[3];
    for (int d = 0; d < 3; ++d)
      w[d] = m ? (*m)[d] * p[0] + (*m)[4 + d] * p[1] + (*m)[8 + d] * p[2] + (*m)[12 + d] : double(p[d]);
    for (int d = 0; d < 3; ++d) sum.lo[d] = std::min(sum.lo[d], w[d]), sum.hi[d] = std::max(sum.hi[d], w[d]);
  };
  for (const GroupNode& g : start.groups) {
    for (const BakedPart& p : g.baked) {
      sum.triangles += p.mesh.triangleCount();
      for (size_t v = 0; v < p.mesh.vertexCount(); ++v) add(&p.mesh.positions[3 * v], nullptr);
    }
    for (const auto* parts : {&g.instanced, &g.mirrored})
      for (const InstancedPart& p : *parts) {
        const Mesh& m = *scene.meshes[p.mesh].mesh;
        sum.triangles += m.triangleCount() * p.trs.size();
        for (const Trs& t : p.trs) {
          const std::array<double, 16> matrix = composeTrs(t);
          for (size_t v = 0; v < m.vertexCount(); ++v) add(&m.positions[3 * v], &matrix);
        }
      }
  }
  return sum;
}

bool parseGroupBy(const std::string& name, GroupBy& out) {
  if (name == "none") return out = GroupBy::None, true;
  if (name == "symbol") return out = GroupBy::Symbol, true;
  if (name == "rule") return out = GroupBy::Rule, true;
  if (name == "label") return out = GroupBy::Label, true;
  return false;
}

bool parseInstancing(const std::string& name, Instancing& out) {
  if (name == "off") return out = Instancing::Off, true;
  if (name == "auto") return out = Instancing::Auto, true;
  if (name == "on") return out = Instancing::On, true;
  if (name == "nodes") return out = Instancing::Nodes, true;
  return false;
}

}  // namespace fgsg::rt::output
