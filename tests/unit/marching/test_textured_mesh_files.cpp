// Mesh files with texture coordinates (read_textured_mesh.h through loadSurface): OBJ, PLY
// and glTF written here, their coordinates back per corner exactly, seams welded into a
// connected surface, repair keeping coordinates with their faces, hostile files refused
// with a message.
#include "runtime/atlas/atlas.h"
#include "runtime/surface/load_surface.h"

#include "../runtime/scratch_files.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>
#include <map>

using namespace fgsg::rt;
using atlas::Vec2;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) { return fgsg::test::scratchDir("textured-mesh", name); }

void writeBytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// Two unit squares side by side in z = 0 (vertices 1..6 as OBJ numbers them: 1 2 3 along
// y = 0, 4 5 6 along y = 1), each square its own UV chart: the edge 2-5 between them is a
// seam, where assimp gives each side vertices of its own.
const char* const kSeamObj = R"(v 0 0 0
v 1 0 0
v 2 0 0
v 0 1 0
v 1 1 0
v 2 1 0
vt 0 0
vt 0.25 0
vt 0.25 0.25
vt 0 0.25
vt 0.5 0.5
vt 0.75 0.5
vt 0.75 0.75
vt 0.5 0.75
f 1/1 2/2 5/3
f 1/1 5/3 4/4
f 2/5 3/6 6/7
f 2/5 6/7 5/8
)";

// What kSeamObj's faces are, corner by corner: position and texture coordinate.
struct Corner {
  Vec3 position;
  Vec2 uv;
};
const std::array<std::array<Corner, 3>, 4> kSeamCorners = {{
    {{{Vec3(0, 0, 0), Vec2(0, 0)}, {Vec3(1, 0, 0), Vec2(0.25, 0)}, {Vec3(1, 1, 0), Vec2(0.25, 0.25)}}},
    {{{Vec3(0, 0, 0), Vec2(0, 0)}, {Vec3(1, 1, 0), Vec2(0.25, 0.25)}, {Vec3(0, 1, 0), Vec2(0, 0.25)}}},
    {{{Vec3(1, 0, 0), Vec2(0.5, 0.5)}, {Vec3(2, 0, 0), Vec2(0.75, 0.5)}, {Vec3(2, 1, 0), Vec2(0.75, 0.75)}}},
    {{{Vec3(1, 0, 0), Vec2(0.5, 0.5)}, {Vec3(2, 1, 0), Vec2(0.75, 0.75)}, {Vec3(1, 1, 0), Vec2(0.5, 0.75)}}},
}};

surface::SurfaceMesh load(const fs::path& path, const surface::SurfaceLoadOptions& options = {}) {
  surface::SurfaceMesh mesh;
  std::string error;
  INFO(error);
  REQUIRE(surface::loadSurface(path.string(), mesh, error, options));
  return mesh;
}

std::string loadError(const fs::path& path) {
  surface::SurfaceMesh mesh;
  std::string error;
  REQUIRE_FALSE(surface::loadSurface(path.string(), mesh, error));
  REQUIRE(mesh.faces.empty());
  return error;
}

void requireSeamCorners(const surface::SurfaceMesh& mesh) {
  REQUIRE(mesh.faces.size() == 4);
  REQUIRE(mesh.textureUV.size() == 4);
  REQUIRE(mesh.vertices.size() == 6);  // the seam's split vertices welded back
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) {
      INFO("face " << f << " corner " << k);
      REQUIRE(mesh.vertices[mesh.faces[f][k]] == kSeamCorners[f][k].position);
      REQUIRE(mesh.textureUV[f][k] == kSeamCorners[f][k].uv);
    }
  // Across the seam the faces are neighbours: one connected surface.
  REQUIRE(mesh.neighbours[0][1] == 3);  // face 0's edge from (1, 0) to (1, 1)
  REQUIRE(mesh.neighbours[3][2] == 0);  // face 3's edge from (1, 1) to (1, 0)
}

void appendFloats(std::string& bin, std::initializer_list<float> values) {
  for (float v : values) bin.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// kSeamObj as glTF: 8 vertices (the seam split, as glTF must), 4 triangles; `bufferUri`
// names the binary buffer (written next to it when it is "seam.bin").
void writeSeamGltf(const fs::path& dir, const std::string& bufferUri, const std::string& byteLength = "") {
  std::string bin;
  const float positions[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  for (const auto& p : positions) appendFloats(bin, {p[0], p[1], p[2]});
  // glTF's v runs down from the image's top: these are 1 - v of kSeamObj's coordinates.
  const float uvs[8][2] = {{0, 1}, {0.25f, 1}, {0.25f, 0.75f}, {0, 0.75f},
                           {0.5f, 0.5f}, {0.75f, 0.5f}, {0.75f, 0.25f}, {0.5f, 0.25f}};
  for (const auto& t : uvs) appendFloats(bin, {t[0], t[1]});
  const uint16_t indices[12] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
  if (bufferUri == "seam.bin") writeBytes(dir / "seam.bin", bin);
  const std::string length = byteLength.empty() ? std::to_string(bin.size()) : byteLength;
  writeBytes(dir / "seam.gltf", R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}],
  "buffers": [{"uri": ")" + bufferUri + R"(", "byteLength": )" + length + R"(}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 96},
    {"buffer": 0, "byteOffset": 96, "byteLength": 64},
    {"buffer": 0, "byteOffset": 160, "byteLength": 24}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3", "min": [0, 0, 0], "max": [2, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 8, "type": "VEC2"},
    {"bufferView": 2, "componentType": 5123, "count": 12, "type": "SCALAR"}]
})");
}

// kSeamObj as COLLADA, placed by `matrix` (16 numbers, row by row).
void writeSeamDae(const fs::path& path, const std::string& matrix) {
  writeBytes(path, R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="seam" name="seam">
      <mesh>
        <source id="seam-positions">
          <float_array id="seam-positions-array" count="18">0 0 0 1 0 0 2 0 0 0 1 0 1 1 0 2 1 0</float_array>
          <technique_common><accessor source="#seam-positions-array" count="6" stride="3">
            <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
          </accessor></technique_common>
        </source>
        <source id="seam-uv">
          <float_array id="seam-uv-array" count="16">0 0 0.25 0 0.25 0.25 0 0.25 0.5 0.5 0.75 0.5 0.75 0.75 0.5 0.75</float_array>
          <technique_common><accessor source="#seam-uv-array" count="8" stride="2">
            <param name="S" type="float"/><param name="T" type="float"/>
          </accessor></technique_common>
        </source>
        <vertices id="seam-vertices"><input semantic="POSITION" source="#seam-positions"/></vertices>
        <triangles count="4">
          <input semantic="VERTEX" source="#seam-vertices" offset="0"/>
          <input semantic="TEXCOORD" source="#seam-uv" offset="1" set="0"/>
          <p>0 0 1 1 4 2  0 0 4 2 3 3  1 4 2 5 5 6  1 4 5 6 4 7</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="seam-node" name="seam-node">
        <matrix>)" + matrix + R"(</matrix>
        <instance_geometry url="#seam"/>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
)");
}

}  // namespace

TEST_CASE("OBJ texture coordinates come back per corner, the seam welded", "[textured mesh]") {
  const fs::path dir = scratchDir("obj");
  writeBytes(dir / "seam.obj", kSeamObj);
  requireSeamCorners(load(dir / "seam.obj"));
}

TEST_CASE("OBJ quads with texture coordinates are split like other polygons", "[textured mesh]") {
  const fs::path dir = scratchDir("obj-quads");
  std::string obj = kSeamObj;
  obj = obj.substr(0, obj.find("f ")) + "f 1/1 2/2 5/3 4/4\nf 2/5 3/6 6/7 5/8\n";
  writeBytes(dir / "quads.obj", obj);
  requireSeamCorners(load(dir / "quads.obj"));  // fans from the first corner: the same faces
}

TEST_CASE("OBJ without texture coordinates has none", "[textured mesh]") {
  const fs::path dir = scratchDir("obj-plain");
  writeBytes(dir / "plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n");
  const surface::SurfaceMesh mesh = load(dir / "plain.obj");
  REQUIRE(mesh.faces.size() == 1);
  REQUIRE(mesh.textureUV.empty());
}

TEST_CASE("PLY per-vertex texture coordinates under each of their names", "[textured mesh]") {
  for (const auto& [u, v] : {std::pair{"u", "v"}, std::pair{"s", "t"}, std::pair{"texture_u", "texture_v"}}) {
    INFO(u << " " << v);
    const fs::path dir = scratchDir(std::string("ply-") + u);
    writeBytes(dir / "square.ply", std::string("ply\nformat ascii 1.0\nelement vertex 4\n") +
                                       "property float x\nproperty float y\nproperty float z\n" +
                                       "property float " + u + "\nproperty float " + v +
                                       "\nelement face 2\nproperty list uchar int vertex_indices\n"
                                       "end_header\n0 0 0 0 0\n1 0 0 0.5 0\n1 1 0 0.5 0.25\n"
                                       "0 1 0 0 0.25\n3 0 1 2\n3 0 2 3\n");
    const surface::SurfaceMesh mesh = load(dir / "square.ply");
    REQUIRE(mesh.faces.size() == 2);
    REQUIRE(mesh.textureUV.size() == 2);
    for (int f = 0; f < 2; ++f)
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.vertices[mesh.faces[f][k]];
        REQUIRE(mesh.textureUV[f][k] == Vec2(0.5 * p.x(), 0.25 * p.y()));
      }
  }
}

TEST_CASE("glTF TEXCOORD_0 comes back per corner with v turned up, the seam welded", "[textured mesh]") {
  const fs::path dir = scratchDir("gltf");
  writeSeamGltf(dir, "seam.bin");
  requireSeamCorners(load(dir / "seam.gltf"));
}

TEST_CASE("COLLADA texture coordinates come back per corner, the seam welded", "[textured mesh]") {
  const fs::path dir = scratchDir("dae");
  writeSeamDae(dir / "seam.dae", "1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1");
  requireSeamCorners(load(dir / "seam.dae"));
}

TEST_CASE("a node that mirrors its mesh keeps the faces counter-clockwise", "[textured mesh]") {
  // x -> -x, moved by 3: each face's corners come back in the order 0, 2, 1, each with
  // its own coordinate, so the faces still face +z.
  const fs::path dir = scratchDir("dae-mirror");
  writeSeamDae(dir / "mirror.dae", "-1 0 0 3  0 1 0 0  0 0 1 0  0 0 0 1");
  const surface::SurfaceMesh mesh = load(dir / "mirror.dae");
  REQUIRE(mesh.faces.size() == 4);
  for (int f = 0; f < 4; ++f) {
    REQUIRE(mesh.faceNormals[f].isApprox(Vec3(0, 0, 1)));
    for (int k = 0; k < 3; ++k) {
      const Corner& c = kSeamCorners[f][k == 0 ? 0 : 3 - k];
      REQUIRE(mesh.vertices[mesh.faces[f][k]] == Vec3(3 - c.position.x(), c.position.y(), c.position.z()));
      REQUIRE(mesh.textureUV[f][k] == c.uv);
    }
  }
  // The texture now runs clockwise over the surface: mirrored, and said so.
  atlas::Atlas a;
  std::string error;
  REQUIRE_FALSE(atlas::atlasFromTextureUV(mesh, {}, a, error));
  REQUIRE(error.rfind("texture coordinates are mirrored: 2 of 2 charts run clockwise", 0) == 0);
}

TEST_CASE("overlapping texture coordinates in a file get the located error", "[textured mesh]") {
  const fs::path dir = scratchDir("obj-overlap");
  std::string obj = kSeamObj;
  // The right square's chart moved onto the left one's.
  obj.replace(obj.find("vt 0.5 0.5"), std::strlen("vt 0.5 0.5\nvt 0.75 0.5\nvt 0.75 0.75\nvt 0.5 0.75"),
              "vt 0.125 0\nvt 0.375 0\nvt 0.375 0.25\nvt 0.125 0.25");
  writeBytes(dir / "overlap.obj", obj);
  const surface::SurfaceMesh mesh = load(dir / "overlap.obj");
  atlas::Atlas a;
  std::string error;
  REQUIRE_FALSE(atlas::atlasFromTextureUV(mesh, {}, a, error));
  REQUIRE(error.rfind("texture coordinates overlap: faces 0 and 2 cover the same place in UV space", 0) == 0);
}

TEST_CASE("repair keeps texture coordinates with their faces", "[textured mesh]") {
  const fs::path dir = scratchDir("obj-repair");
  std::string obj = kSeamObj;
  // Face 3 turned over and a duplicate of face 0 added: repair turns one, drops the other.
  obj.replace(obj.find("f 2/5 6/7 5/8"), std::strlen("f 2/5 6/7 5/8"), "f 2/5 5/8 6/7");
  obj += "f 1/1 2/2 5/3\n";
  writeBytes(dir / "broken.obj", obj);
  REQUIRE(loadError(dir / "broken.obj").find("hint: --repair-surface fixes this") != std::string::npos);
  surface::SurfaceLoadOptions repair;
  repair.repair = true;
  const surface::SurfaceMesh mesh = load(dir / "broken.obj", repair);
  REQUIRE(mesh.faces.size() == 4);
  // Whatever corner each face now starts at, every corner keeps its own coordinate.
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[mesh.faces[f][k]];
      const Vec2& uv = mesh.textureUV[f][k];
      const bool right = f >= 2;
      REQUIRE(uv == (right ? Vec2(0.5 + 0.25 * (p.x() - 1), 0.5 + 0.25 * p.y()) : Vec2(0.25 * p.x(), 0.25 * p.y())));
    }
  atlas::Atlas a;
  std::string error;
  INFO(error);
  REQUIRE(atlas::atlasFromTextureUV(mesh, {}, a, error));
  REQUIRE(a.chartCount == 2);
}

TEST_CASE("broken and hostile textured files are refused with a message", "[textured mesh]") {
  const fs::path dir = scratchDir("hostile");
  SECTION("a glTF buffer that is a device") {
    writeSeamGltf(dir, "/dev/zero", "184");
    const std::string error = loadError(dir / "seam.gltf");
    REQUIRE(error.rfind((dir / "seam.gltf").string() + ": cannot read the file", 0) == 0);
  }
  SECTION("a glTF buffer larger than any input file") {
    writeSeamGltf(dir, "/dev/zero", "1000000000000");
    REQUIRE(loadError(dir / "seam.gltf") == (dir / "seam.gltf").string() +
                                                 ": buffers[0]: byteLength 1000000000000 is larger than an input "
                                                 "file may be (268435456 bytes)");
  }
  SECTION("a glTF buffer that is missing") {
    writeSeamGltf(dir, "missing.bin");
    REQUIRE(loadError(dir / "seam.gltf").rfind((dir / "seam.gltf").string() + ": cannot read the file", 0) == 0);
  }
  SECTION("a glTF buffer shorter than its accessors") {
    writeSeamGltf(dir, "seam.bin");
    std::string bin = fgsg::test::readFile(dir / "seam.bin");
    writeBytes(dir / "seam.bin", bin.substr(0, 100));
    REQUIRE(loadError(dir / "seam.gltf").rfind((dir / "seam.gltf").string() + ": cannot read the file", 0) == 0);
  }
  SECTION("a .glb of garbage") {
    writeBytes(dir / "junk.glb", std::string("glTF\x02\0\0\0\xff\xff\xff\x7f", 12) + std::string(64, '\x55'));
    REQUIRE(loadError(dir / "junk.glb") == (dir / "junk.glb").string() +
                                               ": the binary glTF file is truncated: its header declares "
                                               "2147483647 bytes, the file has 76");
  }
  SECTION("an OBJ texture coordinate that is not a number") {
    std::string obj = kSeamObj;
    obj.replace(obj.find("vt 0.25 0\n"), std::strlen("vt 0.25 0\n"), "vt nan 0\n");
    writeBytes(dir / "nan.obj", obj);
    REQUIRE(loadError(dir / "nan.obj") ==
            (dir / "nan.obj").string() + ":8: texture coordinate 'nan' is not a finite number");
  }
  SECTION("an OBJ face naming a texture coordinate that does not exist") {
    std::string obj = kSeamObj;
    obj.replace(obj.find("f 1/1 2/2 5/3"), std::strlen("f 1/1 2/2 5/3"), "f 1/1 2/99 5/3");
    writeBytes(dir / "index.obj", obj);
    REQUIRE(loadError(dir / "index.obj") ==
            (dir / "index.obj").string() +
                ":15: face corner '2/99' names texture coordinate '99', but there are 8 (counting from 1)");
  }
}
