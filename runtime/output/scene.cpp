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

void appendQuantized(std::string& key, double value, double step) {
  const auto q = static_cast<int64_t>(std::llround(value / step));
  key.append(reinterpret_cast<const char*>(&q), sizeof q);
}

// The content key of an own geometry (and the whole tiles taken off its coordinates).
std::string geometryKey(const Mesh& m, std::array<float, 2>& shift) {
  std::string key;
  key.reserve(8 * (m.positions.size() + m.normals.size() + m.texcoords.size()) + 4 * m.indices.size() + 16);
  const uint64_t counts[2] = {m.vertexCount(), m.indices.size()};
  key.append(reinterpret_cast<const char*>(counts), sizeof counts);
  for (float x : m.positions) appendQuantized(key, x, kPositionStep);
  for (float x : m.normals) appendQuantized(key, x, kNormalStep);
  shift = {0, 0};
  if (m.hasTexcoords()) {
    float lo[2] = {INFINITY, INFINITY};
    for (size_t k = 0; k < m.texcoords.size(); ++k) lo[k % 2] = std::min(lo[k % 2], m.texcoords[k]);
    shift = {std::floor(lo[0]), std::floor(lo[1])};
    for (size_t k = 0; k < m.texcoords.size(); ++k) appendQuantized(key, m.texcoords[k] - shift[k % 2], kTexcoordStep);
  }
  key.append(reinterpret_cast<const char*>(m.indices.data()), m.indices.size() * sizeof(uint32_t));
  return key;
}

// The axis along which every vertex of `m` is at 0 (a face's own geometry), or -1.
int flatAxis(const Mesh& m) {
  for (int d = 2; d >= 0; --d) {
    bool flat = true;
    for (size_t v = 0; v < m.vertexCount() && flat; ++v) flat = m.positions[3 * v + d] == 0.0f;
    if (flat) return d;
  }
  return -1;
}

struct Builder {
  const SceneInput& in;
  const InstanceList& list;
  Scene scene;
  std::vector<uint32_t> sharedOf;  // per instance: Scene::meshes index, or kNone (baked)
  std::vector<TrsFit> fitOf;
  std::vector<Trs> trsOf;
  std::unordered_map<std::string, uint32_t> imageIndex;

  explicit Builder(const SceneInput& input) : in(input), list(*input.list) {}

  uint32_t image(const std::string& path) {
    const auto [it, added] = imageIndex.emplace(path, uint32_t(scene.images.size()));
    if (added) scene.images.push_back(path);
    return it->second;
  }

  std::map<std::tuple<float, float, float, int32_t, bool>, uint32_t> materialIndex;

  std::unordered_map<std::string, int> materialNames;  // -> how many materials took it

  uint32_t material(const Material& m) {
    const auto [it, added] = materialIndex.emplace(std::make_tuple(m.color[0], m.color[1], m.color[2], m.image, m.vertexColors),
                                                   uint32_t(scene.materials.size()));
    if (added) {
      scene.materials.push_back(m);
      scene.materials.back().name = uniqueName(m);
    }
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

  // Which instances can share a mesh, and which mesh: rigidly placed, not bent, drawing
  // neither line segments nor images of their own.
  void findShared() {
    const size_t n = list.instances.size();
    sharedOf.assign(n, kNone);
    fitOf.assign(n, TrsFit::Degenerate);
    trsOf.resize(n);
    if (in.instancing == Instancing::Off) return;
    std::unordered_map<int, uint32_t> ofAsset;
    std::unordered_map<std::string, uint32_t> ofGeometry;
    for (size_t i = 0; i < n; ++i) {
      const Instance& inst = list.instances[i];
      const Mesh* m = drawnMesh(inst, in);
      if (!m || inst.curve != kNone || m->textured() || !m->lines.empty() || m->indices.empty()) continue;
      if (inst.texture != kNone && (!m->hasTexcoords() || inst.texture >= list.textures.size())) continue;
      fitOf[i] = decomposeTrs(inst.transform, trsOf[i], flatAxis(*m));
      if (fitOf[i] != TrsFit::Rigid && fitOf[i] != TrsFit::Mirrored) continue;
      uint32_t shared;
      if (inst.geometry == kNone) {
        const auto [it, added] = ofAsset.emplace((*in.meshOf)[inst.asset], uint32_t(scene.meshes.size()));
        if (added) scene.meshes.push_back({m, list.assets[inst.asset], list.assets[inst.asset], {0, 0}, 0});
        shared = it->second;
      } else {
        std::array<float, 2> shift;
        const auto [it, added] = ofGeometry.emplace(geometryKey(*m, shift), uint32_t(scene.meshes.size()));
        if (added) scene.meshes.push_back({m, list.symbols[inst.symbol] + " piece", list.assets[inst.asset], shift, 0});
        shared = it->second;
      }
      ++scene.meshes[shared].uses;
      sharedOf[i] = shared;
    }
    // A shape's own geometry that no other leaf repeats is no asset: it is baked.
    for (size_t i = 0; i < n; ++i)
      if (sharedOf[i] != kNone && list.instances[i].geometry != kNone && scene.meshes[sharedOf[i]].uses < 2)
        sharedOf[i] = kNone;
  }

  std::string groupName(size_t i) const {
    const Instance& inst = list.instances[i];
    switch (in.groupBy) {
      case GroupBy::None: return "";
      case GroupBy::Symbol: return inst.symbol < list.symbols.size() ? list.symbols[inst.symbol] : "?";
      case GroupBy::Rule:
      case GroupBy::Label: {
        const uint32_t rule = i < list.origins.size() ? list.origins[i].rule : kNone;
        return rule < in.ruleGroups.size() ? in.ruleGroups[rule] : "axiom";
      }
    }
    return "";
  }

  Material materialOf(const Instance& inst) {
    Material m;
    m.color = inst.color;
    if (inst.texture != kNone) m.image = int32_t(image(list.textures[inst.texture]));
    return m;
  }

  // The instances `which` assembled as the flattened output would, into world space.
  Mesh bake(const std::vector<uint32_t>& which) {
    InstanceList sub;
    sub.assets = list.assets;
    sub.symbols = list.symbols;
    sub.textures = list.textures;
    for (uint32_t i : which) {
      Instance inst = list.instances[i];
      inst.firstParam = inst.paramCount = 0;
      if (inst.geometry != kNone) {
        sub.geometries.push_back(list.geometries.at(inst.geometry));
        inst.geometry = uint32_t(sub.geometries.size() - 1);
      }
      if (inst.curve != kNone) {
        sub.curves.push_back(list.curves.at(inst.curve));
        inst.curve = uint32_t(sub.curves.size() - 1);
      }
      sub.instances.push_back(inst);
    }
    return assembleInstances(sub, *in.library, *in.meshOf);
  }

  // Whether the group's colours vary per instance (see kMaxBakedColors): then its parts
  // carry their colours per vertex (baked) or per instance (_COLOR_0), under white
  // materials, instead of a material per colour.
  bool colorsVary(const std::vector<uint32_t>& members) const {
    std::vector<std::array<float, 3>> colors;
    for (uint32_t i : members) {
      const auto& c = list.instances[i].color;
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
    for (uint32_t i : members) {
      if (sharedOf[i] == kNone) {
        baked.push_back(i);
        continue;
      }
      const Instance& inst = list.instances[i];
      const bool mirrored = fitOf[i] == TrsFit::Mirrored;
      Material look = materialOf(inst);
      if (vary) look.color = {1, 1, 1}, look.vertexColors = true;
      const uint32_t mat = material(look);
      const auto [it, added] = partOf.emplace(std::make_tuple(sharedOf[i], mat, mirrored), parts.size());
      if (added) parts.push_back({mirrored, InstancedPart{sharedOf[i], mat, {}, {}, {}}});
      InstancedPart& p = parts[it->second].second;
      p.instances.push_back(i);
      p.trs.push_back(trsOf[i]);
      p.colors.push_back(inst.color);
    }
    for (auto& [mirrored, p] : parts) {
      bool keep = true;
      if (in.instancing == Instancing::Auto) {
        // Counting the shared mesh's own bytes in full, as if this part alone wrote it.
        const Mesh& m = *scene.meshes[p.mesh].mesh;
        const size_t meshBytes = m.vertexCount() * (m.hasTexcoords() ? 32 : 24) + m.indices.size() * 4;
        keep = !mirrored && p.instances.size() * kInstanceBytes + kInstancedNodeBytes + meshBytes + kSharedMeshBytes <
                                p.instances.size() * meshBytes;
      }
      if (!keep) {
        baked.insert(baked.end(), p.instances.begin(), p.instances.end());
        continue;
      }
      (mirrored ? scene.mirroredCount : scene.instancedCount) += p.instances.size();
      (mirrored ? g.mirrored : g.instanced).push_back(std::move(p));
    }
    std::sort(baked.begin(), baked.end());  // in placement order, as flattened
    scene.bakedCount += baked.size();
    bakeParts(baked, vary, g);
    return g;
  }

  // One baked part per colour (textured stretches with their images), or where the
  // group's colours vary one part coloured per vertex.
  void bakeParts(const std::vector<uint32_t>& baked, bool vary, GroupNode& g) {
    if (baked.empty()) return;
    for (uint32_t i : baked) {
      const std::string& asset = list.assets[list.instances[i].asset];
      auto at = std::find_if(g.bakedAssets.begin(), g.bakedAssets.end(), [&](const auto& a) { return a.first == asset; });
      if (at == g.bakedAssets.end()) g.bakedAssets.push_back({asset, 1});
      else ++at->second;
    }
    std::vector<std::array<float, 3>> colors;
    std::vector<std::vector<uint32_t>> byColor;
    if (vary)
      byColor.assign(1, baked);
    else
      for (uint32_t i : baked) {
        const auto& c = list.instances[i].color;
        const size_t k = std::find(colors.begin(), colors.end(), c) - colors.begin();
        if (k == colors.size()) colors.push_back(c), byColor.emplace_back();
        byColor[k].push_back(i);
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
        base.color = colors[k];
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
    std::vector<std::string> names;
    std::unordered_map<std::string, size_t> groupOf;
    std::vector<std::vector<uint32_t>> members;
    for (uint32_t i = begin; i < end; ++i) {
      std::string name = groupName(i);
      const auto [it, added] = groupOf.emplace(name, names.size());
      if (added) names.push_back(std::move(name)), members.emplace_back();
      members[it->second].push_back(i);
    }
    for (size_t k = 0; k < names.size(); ++k) s.groups.push_back(buildGroup(names[k], members[k]));
    return s;
  }

  void build() {
    scene.groupBy = in.groupBy;
    scene.instancing = in.instancing;
    findShared();
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
