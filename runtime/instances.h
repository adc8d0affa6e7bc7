// The result of a derivation: every terminal instance placed by I / IC / IM (or drawn
// by a turtle F, or a CGA leaf shape's own geometry), with the asset, the 4x4 transform that maps the asset's unit box
// into world space, the symbol of the shape that placed it, and its parameters.
#pragma once

#include "runtime/mesh.h"

#include <array>
#include <compare>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt {

struct Instance {
  uint32_t asset = 0;           // index into InstanceList::assets
  uint32_t symbol = 0;          // index into InstanceList::symbols
  std::array<double, 16> transform{};  // column-major, unit box [0,1]^3 -> world
  std::array<float, 3> color{0.8f, 0.8f, 0.8f};
  uint32_t firstParam = 0;      // into InstanceList::params
  uint32_t paramCount = 0;
  // A smooth terminal (Buron et al. §6): index into InstanceList::curves of the marching
  // segment its unit box is bent along; UINT32_MAX: placed rigidly by `transform`.
  uint32_t curve = UINT32_MAX;
  // A leaf shape's own geometry (CGA): index into InstanceList::geometries, drawn instead
  // of the asset (then kOwnGeometryAsset) and mapped by `transform` like one.
  uint32_t geometry = UINT32_MAX;
  // Texture("img.png"): index into InstanceList::textures of the image drawn on it with the
  // mesh's texture coordinates; UINT32_MAX: none.
  uint32_t texture = UINT32_MAX;
};
static_assert(sizeof(Instance) == 168, "Instance grew: a million-segment L-system holds a million of them");

// Who placed an instance (InstanceList::origins): the rule whose successor placed it (an index into ir::Module::rules; UINT32_MAX:
// the axiom) and the placing shape's derivation depth, as the grammar's `depth` reads it
// there (UINT32_MAX: not known, as in an L-system's parallel rewriting).
struct InstanceOrigin {
  uint32_t rule = UINT32_MAX;
  uint32_t depth = UINT32_MAX;
};

// The asset name of instances that draw a shape's own geometry (Instance::geometry).
inline constexpr const char* kOwnGeometryAsset = "(own geometry)";

// The path of one marching segment as a smooth terminal follows it: the cubic Bezier
// from the segment's start to its end (control points in world space) and the surface
// normals at both ends. An instance on it is bent so that its unit box's X axis runs
// along the curve: a point at (x, y, z) of the straight scope (`transform`, whose X runs
// from control[0] to control[3]) goes to B(x) + y' Y(x) + z' Z(x) for the frame along
// the curve (runtime/marching/smooth_curves.h).
struct CurveSegment {
  std::array<std::array<double, 3>, 4> control{};
  std::array<double, 3> normal0{}, normal1{};
};

// A line of FGSG §4.4 (`Line`, `LineSeg`) as it ended, merges applied: its centreline,
// width, whether it merges, and the symbol whose successor started it. The line graph
// that `fgsg run --lines` exports; the output draws each as a swept tube.
struct LinePath {
  std::vector<std::array<double, 3>> points;
  double width = 0;
  bool merge = true;
  uint32_t symbol = 0;  // index into InstanceList::symbols
};

// A material's physically based factors besides its colour (CGA's material.roughness,
// .metallic, .opacity, .emissive and the texture layers but the colour map), written as glTF
// 2.0 PBR materials and in OBJ's .mtl. The default is what every material had before: fgsg's
// roughness 0.8, metallic 0, opaque, not emissive, no maps.
struct Finish {
  // CityEngine's texture layers by their uv set: 1 bumpmap, 2 dirtmap, 3 specularmap,
  // 4 opacitymap, 5 normalmap, 6 emissivemap, 7 occlusionmap, 8 roughnessmap, 9 metallicmap
  // (0, the colour map, is the projection's image: Instance::texture).
  static constexpr uint32_t kBumpMap = 1, kDirtMap = 2, kSpecularMap = 3, kOpacityMap = 4, kNormalMap = 5,
                            kEmissiveMap = 6, kOcclusionMap = 7, kRoughnessMap = 8, kMetallicMap = 9, kLayers = 10;
  float roughness = 0.8f, metallic = 0.0f, opacity = 1.0f;
  std::array<float, 3> emissive{0, 0, 0};  // CityEngine's default black
  // Per layer, an index into InstanceList::textures; UINT32_MAX: none.
  std::array<uint32_t, kLayers> maps{UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX,
                                     UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX};
  bool operator==(const Finish&) const = default;
  auto operator<=>(const Finish&) const = default;
};

// How a parameter's slots read: a number, a boolean (0/1), a string (an index into
// InstanceList::strings) or a vector (three slots).
enum class ParamKind : uint8_t { Number, Boolean, String, Vector };

struct InstanceList {
  std::vector<std::string> assets;   // asset names as written in the grammar
  std::vector<std::string> symbols;  // symbol names
  // A MeshArray (huge pages when large): an L-system's million turtle segments are
  // 170 MB of instances, and faulting that in 4 KiB pages was half the turtle's time.
  MeshArray<Instance> instances;
  std::vector<double> params;        // parameter slots of all instances
  // Per symbol, the kinds of its parameters; a symbol without an entry has plain numbers.
  std::vector<std::vector<ParamKind>> paramKinds;
  std::vector<std::string> strings;  // the texts string parameters refer to
  std::vector<CurveSegment> curves;  // smooth terminals' paths (Instance::curve)
  // Leaf shapes' own geometry (Instance::geometry), each in its shape's unit box. A
  // MeshArray too: the city's 52 000 leaf meshes are 10 MB of Mesh records, and faulting
  // them in 4 KiB pages as each leaf was pushed was a third of its derivation.
  MeshArray<Mesh> geometries;
  // The images of Texture commands (Instance::texture), as paths the derivation found.
  std::vector<std::string> textures;
  // Per instance, 1 + its index in `finishes` (0: the default Finish), beside `instances`
  // as `origins` is, and only as long as the last instance that has one: grammars without
  // Material(...) carry nothing. finishOf(i) reads it.
  std::vector<uint32_t> finishIndex;
  std::vector<Finish> finishes;
  const Finish* finishOf(size_t instance) const {
    const uint32_t k = instance < finishIndex.size() ? finishIndex[instance] : 0;
    return k && k <= finishes.size() ? &finishes[k - 1] : nullptr;
  }
  std::vector<LinePath> lines;  // the grammar's lines (Line/LineSeg), in the order they started
  // Per instance when DeriveOptions::recordOrigins asked (fgsg view's picking), else empty;
  // kept beside `instances` so that the million-instance runs do not carry it.
  std::vector<InstanceOrigin> origins;
  // The start shapes (a --lots lot, a seed derived apart, else the one axiom): start shape
  // k placed instances [startBounds[k], startBounds[k + 1]); the instances past the last
  // bound (lines, the surface) belong to none. Empty: not recorded (every instance is the
  // axiom's). Seeds that grow in one queue are one start shape.
  std::vector<uint32_t> startBounds;
};

}  // namespace fgsg::rt
