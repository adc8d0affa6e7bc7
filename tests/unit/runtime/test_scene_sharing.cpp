// Which own geometries (CGA leaves' meshes) buildScene (runtime/output/scene.h) shares:
// those equal once their positions are quantized to 2^-20, normals to 2^-16 and texture
// coordinates, whole tiles taken off, to 2^-12 of a tile; a geometry no other repeats is
// baked. Instance lists built by hand, with the shared meshes, their uses and the parts
// counted out in full; among them more geometries than the lookup table first holds.
#include "runtime/output/scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::output;

namespace {

// The unit quad in z = 0 facing +z (or -z), with texture coordinates from (u, v) over one
// tile by one.
Mesh sharingQuad(float u, float v, float normalZ = 1) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.normals = {0, 0, normalZ, 0, 0, normalZ, 0, 0, normalZ, 0, 0, normalZ};
  m.texcoords = {u, v, u + 1, v, u + 1, v + 1, u, v + 1};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// One instance per geometry, in order, each scaled by 2 and moved along x.
InstanceList sharingList(MeshArray<Mesh> geometries) {
  InstanceList list;
  list.assets = {kOwnGeometryAsset};
  list.symbols = {"Wall"};
  for (size_t k = 0; k < geometries.size(); ++k) {
    Instance inst;
    inst.transform = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 3.0 * double(k), 0, 0, 1};
    inst.geometry = uint32_t(k);
    list.instances.push_back(inst);
  }
  list.geometries = std::move(geometries);
  return list;
}

Scene sharingScene(const InstanceList& list) {
  static const AssetLibrary library;
  static const std::vector<int> meshOf = {-1};
  SceneInput in;
  in.list = &list;
  in.library = &library;
  in.meshOf = &meshOf;
  in.instancing = Instancing::On;
  return buildScene(in);
}

}  // namespace

TEST_CASE("own geometries equal to rounding and whole tiles share a mesh, the rest is baked", "[output]") {
  Mesh nudged = sharingQuad(0.25f, 0.5f);
  nudged.positions[3] = 1 + 0x1p-23f;   // 2^-23 off: the same on the 2^-20 grid
  nudged.normals[2] = 1 - 0x1p-20f;     // the same on the 2^-16 grid
  Mesh reordered = sharingQuad(0.25f, 0.5f);
  reordered.indices = {0, 2, 3, 0, 1, 2};  // the same triangles, listed otherwise: not equal
  const InstanceList list = sharingList({
      sharingQuad(0.25f, 0.5f),        // 0: mesh 0
      sharingQuad(0.5f, 0.5f),         // 1: mesh 1 (half a tile along: not the same picture)
      nudged,                          // 2: mesh 0
      sharingQuad(3.25f, -1.5f),       // 3: mesh 0, three tiles along and two down
      sharingQuad(0.25f, 0.5f, -1),    // 4: facing -z, used once: baked
      reordered,                       // 5: used once: baked
      sharingQuad(-0.5f, 0.5f),        // 6: mesh 1, one tile back
      sharingQuad(0.25f, 0.5f + 0x1p-10f),  // 7: 2^-10 of a tile off, used once: baked
  });
  const Scene scene = sharingScene(list);
  // Only the repeated ones are shared meshes, in order of first use.
  REQUIRE(scene.meshes.size() == 2);
  const size_t first[2] = {0, 1};
  const size_t uses[2] = {3, 2};
  for (size_t k = 0; k < 2; ++k) {
    CHECK(scene.meshes[k].mesh == &list.geometries[first[k]]);
    CHECK(scene.meshes[k].uses == uses[k]);
    CHECK(scene.meshes[k].name == "Wall piece");
  }
  CHECK(scene.meshes[0].uvShift == std::array<float, 2>{0, 0});
  CHECK(scene.meshes[1].uvShift == std::array<float, 2>{0, 0});
  REQUIRE(scene.starts.size() == 1);
  REQUIRE(scene.starts[0].groups.size() == 1);
  const GroupNode& g = scene.starts[0].groups[0];
  REQUIRE(g.instanced.size() == 2);
  CHECK(g.instanced[0].mesh == 0);
  CHECK(g.instanced[0].instances == std::vector<uint32_t>{0, 2, 3});
  CHECK(g.instanced[1].mesh == 1);
  CHECK(g.instanced[1].instances == std::vector<uint32_t>{1, 6});
  CHECK(g.instanced[0].trs[2].translation == std::array<double, 3>{9, 0, 0});
  CHECK(g.instanced[0].trs[2].scale == std::array<double, 3>{2, 2, 2});
  CHECK(g.mirrored.empty());
  REQUIRE(g.baked.size() == 1);
  CHECK(g.baked[0].instances == 3);
  CHECK(g.baked[0].mesh.triangleCount() == 6);
  CHECK(scene.instancedCount == 5);
  CHECK(scene.bakedCount == 3);
}

TEST_CASE("own geometries are found again among more than the lookup first holds", "[output]") {
  // 1500 different pictures (2^-10 of a tile apart), then each again, one tile along, in
  // the opposite order; then a 1501st once.
  const size_t kinds = 1500;
  MeshArray<Mesh> geometries;
  for (size_t k = 0; k < kinds; ++k) geometries.push_back(sharingQuad(float(k) * 0x1p-11f, 0));
  for (size_t k = kinds; k-- > 0;) geometries.push_back(sharingQuad(1 + float(k) * 0x1p-11f, 0));
  geometries.push_back(sharingQuad(0.75f + 0x1p-12f, 0));
  const InstanceList list = sharingList(std::move(geometries));
  const Scene scene = sharingScene(list);
  REQUIRE(scene.meshes.size() == kinds);
  size_t twice = 0;
  for (size_t k = 0; k < kinds; ++k) twice += scene.meshes[k].mesh == &list.geometries[k] && scene.meshes[k].uses == 2;
  CHECK(twice == kinds);
  CHECK(scene.instancedCount == 2 * kinds);
  CHECK(scene.bakedCount == 1);
  // Instance kinds + j repeats geometry kinds - 1 - j.
  const GroupNode& g = scene.starts[0].groups[0];
  REQUIRE(g.instanced.size() == kinds);
  size_t paired = 0;
  for (const InstancedPart& p : g.instanced)
    paired += p.instances.size() == 2 && p.instances[1] == 2 * kinds - 1 - p.instances[0];
  CHECK(paired == kinds);
}
