// The output as a scene, built once from a derivation's instance list for the writers
// that keep structure (glTF with nodes; the flattened writers of runtime/io take the one
// assembled mesh instead): a node per start shape (a lot, a seed, the axiom) named after
// it, under it a node per group (symbol, rule, label, or none), and in a group
//  * instanced parts: a mesh shared by every instance that places it rigidly (an asset, or
//    a CGA leaf's own geometry that several leaves repeat), with a transform (Trs) each;
//  * mirrored instances of shared meshes, a node each (a matrix with a negative scale);
//  * baked parts: everything else (bent terminals, sheared or flattened placements, own
//    geometry used once, line segments, assets with images of their own) assembled into
//    world space as the flattened output would, one part per material.
// Materials are colours (and images) deduplicated over the whole scene.
#pragma once

#include "runtime/assets.h"
#include "runtime/instances.h"
#include "runtime/mesh.h"
#include "runtime/output/trs.h"
#include "runtime/reports.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::rt::output {

enum class GroupBy : uint8_t { None, Symbol, Rule, Label };
// Off: everything baked; Auto: instanced where that makes the file smaller; On: every
// rigid repeat instanced (EXT_mesh_gpu_instancing); Nodes: as On, but each instance a
// node of its own placing the shared mesh (core glTF, which readers without the
// extension — Blender 3.4 — import as linked duplicates).
enum class Instancing : uint8_t { Off, Auto, On, Nodes };

// A grammar attr's value as a start shape derived with it (its default, --set, the lot's
// property of its name).
struct StartAttr {
  enum class Kind : uint8_t { Number, Boolean, String, Vector };
  std::string name;
  Kind kind = Kind::Number;
  std::array<double, 3> number{};  // Number and Boolean (0/1) in [0]; Vector x y z
  std::string text;                // String
};

// What names a start shape and what it carries (a lot's feature id and properties, the
// attrs' values, the reports collected under it); the glTF writer puts them in the start
// node's extras.
struct StartInfo {
  std::string name;
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::string>> strings;
  std::vector<StartAttr> attrs;           // in declaration order
  std::vector<ReportCollection> reports;  // by key (runtime/reports.h)
};

struct SceneInput {
  const InstanceList* list = nullptr;
  const AssetLibrary* library = nullptr;
  const std::vector<int>* meshOf = nullptr;  // resolveAssets
  // Per start shape of list->startBounds (missing ones are named "start N").
  std::vector<StartInfo> starts;
  // GroupBy::Rule / Label: per rule (ir::Module::rules), its group's name; instances no rule
  // placed (the axiom's) go to "axiom". Needs list->origins.
  std::vector<std::string> ruleGroups;
  GroupBy groupBy = GroupBy::Symbol;
  Instancing instancing = Instancing::Auto;
};

// A mesh several instances share, in its unit box (asset space).
struct SharedMesh {
  const Mesh* mesh = nullptr;  // the library's asset or the first of equal own geometries
  std::string name;
  std::string asset;  // InstanceList::assets' name (kOwnGeometryAsset for a leaf's geometry)
  std::array<float, 2> uvShift{0, 0};  // whole texture tiles taken off its coordinates
  size_t uses = 0;                     // instances placing it, in the whole scene
};

// A glTF PBR material (double-sided): base colour factor, and
// image (index into Scene::images, -1: none; sampled with REPEAT); vertexColors: the
// colours vary (scene.cpp, kMaxBakedColors) and are per vertex (COLOR_0) or per instance
// (_COLOR_0), the factor white.
struct Material {
  std::array<float, 3> color{1, 1, 1};
  int32_t image = -1;
  bool vertexColors = false;
  // CGA's material attributes (rt::Finish): roughness, metallic, opacity (< 1: alpha
  // blended), the emissive colour, and the texture layers but the colour map, by their uv
  // set (Finish::kBumpMap ... kMetallicMap; index into Scene::images, -1: none). Each is
  // drawn with its own uv set where the shape has it, else with the base colour image's
  // coordinates, so only where there is one of the two.
  float roughness = 0.8f, metallic = 0.0f, opacity = 1.0f;
  std::array<float, 3> emissive{0, 0, 0};
  std::array<int32_t, Finish::kLayers> maps{-1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
  int32_t normalImage() const { return maps[Finish::kNormalMap]; }
  // Unique in the scene, no spaces (an OBJ's `usemtl` takes it): the image's file name
  // without extension, then the colour as rrggbb or "vertex_colors" ("brick_ffffff",
  // "d8c4a2"), with _2, _3, ... after a name taken by a colour that rounds alike.
  std::string name;
  bool operator==(const Material&) const = default;
};

struct InstancedPart {
  uint32_t mesh = 0;      // Scene::meshes
  uint32_t material = 0;  // Scene::materials
  std::vector<uint32_t> instances;  // indices into the instance list
  std::vector<Trs> trs;             // per instance
  std::vector<std::array<float, 3>> colors;  // per instance (written where the material's vertexColors)
};

struct BakedPart {
  Mesh mesh;                        // world space
  std::vector<uint32_t> materials;  // per image of mesh.textures, then the untextured one last
  size_t instances = 0;
};

struct GroupNode {
  std::string name;
  std::vector<InstancedPart> instanced;  // EXT_mesh_gpu_instancing
  std::vector<InstancedPart> mirrored;   // a node each
  std::vector<BakedPart> baked;
  std::vector<std::pair<std::string, size_t>> bakedAssets;  // how many baked instances per asset name
  size_t instanceCount = 0;
};

struct StartNode {
  StartInfo info;
  uint32_t index = 0;  // the start shape's number
  std::vector<GroupNode> groups;
  size_t instanceCount = 0;
};

struct Scene {
  std::vector<StartNode> starts;  // then, named "(surface and lines)", what no start shape placed
  std::vector<SharedMesh> meshes;
  std::vector<Material> materials;
  std::vector<std::string> images;  // paths
  GroupBy groupBy = GroupBy::Symbol;
  Instancing instancing = Instancing::Auto;
  size_t instancedCount = 0, mirroredCount = 0, bakedCount = 0;
};

// Builds the scene. May throw std::bad_alloc, and std::out_of_range as assembleInstances.
Scene buildScene(const SceneInput& in);

// What a start shape's subtree draws: its triangles (each instance's) and world bounds
// (lo > hi when it draws nothing).
struct StartSummary {
  size_t triangles = 0;
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
};
StartSummary summarizeStart(const Scene& scene, const StartNode& start);

// "symbol" -> GroupBy::Symbol etc.; false for an unknown name.
bool parseGroupBy(const std::string& name, GroupBy& out);
bool parseInstancing(const std::string& name, Instancing& out);

}  // namespace fgsg::rt::output
