// The streaming mesh writers against the encoders they replaced: tinygltf's GLB (the
// oracle for the JSON and the chunk layout) and the former OBJ and PLY encoders, kept here
// verbatim, must give the same bytes for meshes with and without each attribute, empty,
// odd values and larger than the writers' buffer; the file written through the
// transaction equals encodeMesh's bytes; OBJ numbers read back as the same floats; and a
// write that fails midway leaves no file.
#include "runtime/io/byte_sink.h"
#include "runtime/io/glb_writer.h"
#include "runtime/io/output_transaction.h"
#include "runtime/io/stale_temps.h"
#include "runtime/io/write_mesh.h"

#include <catch2/catch.hpp>
// Debian links the tinygltf implementation as a shared library: only the declarations here.
#include <tiny_gltf.h>

#include "scratch_files.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <span>
#include <sstream>
#include <sys/resource.h>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace oracle {

// ---- the encoders before streaming (commit 14627e4), unchanged ----------------------

bool hasColors(const Mesh& m) { return !m.colors.empty() && m.colors.size() == m.positions.size(); }

float clamp01(float c) { return std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f; }

template <typename T>
void appendRaw(std::string& out, const T* data, size_t count) {
  out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

// Shortest text that reads back as the same float: exact and deterministic.
void appendFloat(std::string& out, float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void appendInteger(std::string& out, uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// ---- glTF 2.0 binary --------------------------------------------------------------

// Appends `bytes` to the buffer as a new tightly packed buffer view; returns its index.
int addBufferView(tinygltf::Model& model, const void* bytes, size_t size, int target) {
  auto& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), p, p + size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

// A float accessor of `width` components per element (VEC2 or VEC3), with its per-component
// bounds when asked (glTF requires them for POSITION).
int addFloatAccessor(tinygltf::Model& model, std::span<const float> values, int width, bool withBounds) {
  tinygltf::Accessor acc;
  acc.bufferView = addBufferView(model, values.data(), values.size() * sizeof(float),
                                 TINYGLTF_TARGET_ARRAY_BUFFER);
  acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  acc.type = width == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
  acc.count = values.size() / width;
  if (withBounds) {
    acc.minValues.assign(width, INFINITY);
    acc.maxValues.assign(width, -INFINITY);
    for (size_t i = 0; i < values.size(); ++i) {
      acc.minValues[i % width] = std::min(acc.minValues[i % width], double(values[i]));
      acc.maxValues[i % width] = std::max(acc.maxValues[i % width], double(values[i]));
    }
  }
  model.accessors.push_back(acc);
  return int(model.accessors.size() - 1);
}

int addVec3Accessor(tinygltf::Model& model, std::span<const float> values, bool withBounds) {
  return addFloatAccessor(model, values, 3, withBounds);
}

// glTF puts the texture's origin at the top left (v down); the mesh's v is up.
int addTexcoordAccessor(tinygltf::Model& model, std::span<const float> uvUp) {
  std::vector<float> uvDown(uvUp.begin(), uvUp.end());
  for (size_t i = 1; i < uvDown.size(); i += 2) uvDown[i] = 1.0f - uvDown[i];
  return addFloatAccessor(model, uvDown, 2, false);
}

bool encodeGlb(const Mesh& mesh, std::string& bytes, std::string& error) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "fgsg";
  tinygltf::Scene scene;
  scene.name = "fgsg";  // tinygltf writes a scene with no properties as null, which is invalid
  // An empty mesh gives a scene without nodes: valid glTF, while an empty buffer or a
  // primitive without vertices would not be.
  if (!mesh.empty()) {
    model.buffers.emplace_back();
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.attributes["POSITION"] = addVec3Accessor(model, mesh.positions, true);
    if (mesh.normals.size() == mesh.positions.size())
      prim.attributes["NORMAL"] = addVec3Accessor(model, mesh.normals, false);
    if (hasColors(mesh)) {
      std::vector<float> colors(mesh.colors.size());
      std::transform(mesh.colors.begin(), mesh.colors.end(), colors.begin(), clamp01);
      prim.attributes["COLOR_0"] = addVec3Accessor(model, colors, false);
    }
    if (mesh.hasTexcoords()) prim.attributes["TEXCOORD_0"] = addTexcoordAccessor(model, mesh.texcoords);
    tinygltf::Accessor idx;
    idx.bufferView = addBufferView(model, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t),
                                   TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    idx.type = TINYGLTF_TYPE_SCALAR;
    idx.count = mesh.indices.size();
    model.accessors.push_back(idx);
    prim.indices = int(model.accessors.size() - 1);

    tinygltf::Material material;
    material.name = "default";
    material.doubleSided = true;
    material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;  // glTF defaults to metal
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    model.materials.push_back(material);
    prim.material = 0;

    tinygltf::Mesh gm;
    gm.name = "fgsg";
    gm.primitives.push_back(prim);
    model.meshes.push_back(gm);
    tinygltf::Node node;
    node.mesh = 0;
    model.nodes.push_back(node);
    scene.nodes.push_back(0);
  }
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  // A stream that cannot grow (out of memory) only sets its badbit: without this check
  // the file would be cut short while its header declares the full length.
  if (!writer.WriteGltfSceneToStream(&model, out, false, true) || !out) {
    error = "cannot encode the mesh as glTF (out of memory?)";
    return false;
  }
  model = tinygltf::Model();  // the buffer's copy of the mesh is no longer needed
  bytes = std::move(out).str();
  // The GLB header's third word is the length of the whole file.
  uint32_t declared = 0;
  if (bytes.size() >= 12) std::memcpy(&declared, bytes.data() + 8, sizeof declared);
  if (bytes.size() < 12 || declared != bytes.size()) {
    error = "the glTF encoder produced " + std::to_string(bytes.size()) +
            " bytes while the file's header declares " + std::to_string(declared);
    bytes.clear();
    return false;
  }
  return true;
}

// ---- Wavefront OBJ ----------------------------------------------------------------

std::string encodeObj(const Mesh& mesh) {
  const bool colored = hasColors(mesh);
  const bool withNormals = mesh.normals.size() == mesh.positions.size();
  const bool withTexcoords = mesh.hasTexcoords();
  std::string out = "# fgsg\n";
  out.reserve(mesh.vertexCount() * (colored ? 110 : 80) + mesh.triangleCount() * 40);  // typical lines
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    out += 'v';
    for (int d = 0; d < 3; ++d) out += ' ', appendFloat(out, mesh.positions[3 * v + d]);
    // "v x y z r g b" is the common vertex colour extension (MeshLab, Blender, OpenMesh).
    if (colored)
      for (int d = 0; d < 3; ++d) out += ' ', appendFloat(out, clamp01(mesh.colors[3 * v + d]));
    out += '\n';
  }
  for (size_t v = 0; withTexcoords && v < mesh.vertexCount(); ++v) {
    out += "vt";  // OBJ's v is up, as the mesh's
    for (int d = 0; d < 2; ++d) out += ' ', appendFloat(out, mesh.texcoords[2 * v + d]);
    out += '\n';
  }
  for (size_t v = 0; withNormals && v < mesh.vertexCount(); ++v) {
    out += "vn";
    for (int d = 0; d < 3; ++d) out += ' ', appendFloat(out, mesh.normals[3 * v + d]);
    out += '\n';
  }
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      const uint64_t i = uint64_t(mesh.indices[3 * t + k]) + 1;  // OBJ counts from 1
      out += ' ', appendInteger(out, i);
      if (withTexcoords) out += '/', appendInteger(out, i);  // v/vt, v/vt/vn
      if (withNormals) out += withTexcoords ? "/" : "//", appendInteger(out, i);
    }
    out += '\n';
  }
  return out;
}

// ---- PLY, binary little endian ----------------------------------------------------

std::string encodePly(const Mesh& mesh) {
  const bool colored = hasColors(mesh);
  const bool withNormals = mesh.normals.size() == mesh.positions.size();
  const bool withTexcoords = mesh.hasTexcoords();
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment fgsg\n";
  out += "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
  out += "property float x\nproperty float y\nproperty float z\n";
  if (withNormals) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (withTexcoords) out += "property float u\nproperty float v\n";  // v up
  if (colored) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "element face " + std::to_string(mesh.triangleCount()) + "\n";
  out += "property list uchar uint vertex_indices\nend_header\n";
  const size_t vertexBytes = 12 + (withNormals ? 12 : 0) + (withTexcoords ? 8 : 0) + (colored ? 3 : 0);
  out.reserve(out.size() + mesh.vertexCount() * vertexBytes + mesh.triangleCount() * 13);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    appendRaw(out, &mesh.positions[3 * v], 3);
    if (withNormals) appendRaw(out, &mesh.normals[3 * v], 3);
    if (withTexcoords) appendRaw(out, &mesh.texcoords[2 * v], 2);
    if (colored) {
      unsigned char rgb[3];
      for (int d = 0; d < 3; ++d) rgb[d] = (unsigned char)std::lround(clamp01(mesh.colors[3 * v + d]) * 255.0f);
      appendRaw(out, rgb, 3);
    }
  }
  const unsigned char three = 3;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    appendRaw(out, &three, 1);
    appendRaw(out, &mesh.indices[3 * t], 3);
  }
  return out;
}

}  // namespace oracle

namespace {

fs::path scratchDir(const std::string& name) { return fgsg::test::scratchDir("write_bytes", name); }
using fgsg::test::readFile;

struct Attributes {
  bool normals = true, colors = true, texcoords = true;
};

// A random triangle soup whose values reach the corners of float: signed zeros, tiny and
// huge magnitudes, colours outside [0,1] and not finite (clamped), texture coordinates
// outside [0,1].
Mesh randomMesh(size_t vertices, size_t triangles, Attributes with, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const float specials[] = {0.0f, -0.0f, 1e-38f, -3e38f, 3.4028235e38f, 1.17549435e-38f, 1e-45f,
                            0.1f, 123456.7f, -1.5f};
  const auto value = [&](float scale) {
    const uint32_t pick = rng() % 16;
    if (pick < std::size(specials)) return specials[pick];
    return unit(rng) * scale;
  };
  Mesh m;
  m.positions.resize(3 * vertices);
  for (auto& x : m.positions) x = value(100.0f);
  if (with.normals) {
    m.normals.resize(3 * vertices);
    for (auto& x : m.normals) x = unit(rng);
  }
  if (with.colors) {
    m.colors.resize(3 * vertices);
    for (auto& x : m.colors) x = unit(rng) * 1.5f;
    if (vertices > 2) m.colors[4] = NAN, m.colors[5] = INFINITY, m.colors[6] = -INFINITY;
  }
  if (with.texcoords) {
    m.texcoords.resize(2 * vertices);
    for (auto& x : m.texcoords) x = unit(rng) * 2.0f;
  }
  m.indices.resize(3 * triangles);
  for (auto& i : m.indices) i = uint32_t(rng() % std::max<size_t>(vertices, 1));
  return m;
}

std::string oracleBytes(const Mesh& m, const std::string& ext) {
  std::string bytes, error;
  if (ext == ".glb") REQUIRE(oracle::encodeGlb(m, bytes, error));
  if (ext == ".obj") bytes = oracle::encodeObj(m);
  if (ext == ".ply") bytes = oracle::encodePly(m);
  return bytes;
}

// First differing byte, for a readable failure.
std::string firstDifference(const std::string& a, const std::string& b) {
  const auto at = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size()) + ", first difference at byte " +
         std::to_string(at.first - a.begin());
}

void requireOracleBytes(const Mesh& m, const std::string& what) {
  for (const std::string ext : {".glb", ".obj", ".ply"}) {
    std::string bytes, error;
    INFO(what << " " << ext);
    REQUIRE(io::encodeMesh(m, ext, bytes, error));
    const std::string want = oracleBytes(m, ext);
    INFO(firstDifference(bytes, want));
    CHECK(bytes == want);
    // The smallest staging buffer: every batch and chunk size adapts to it.
    std::string small;
    {
      io::StringSink sink(small, 4096);
      REQUIRE(io::encodeMesh(m, ext, sink, error));
    }
    CHECK(small == want);
  }
}

}  // namespace

TEST_CASE("the streaming writers give the bytes of the encoders they replaced", "[writers][gltf]") {
  SECTION("every combination of normals, colours and texture coordinates") {
    for (int bits = 0; bits < 8; ++bits) {
      const Attributes with{bool(bits & 1), bool(bits & 2), bool(bits & 4)};
      requireOracleBytes(randomMesh(61, 47, with, uint32_t(bits)), "attributes " + std::to_string(bits));
    }
  }
  SECTION("an empty mesh, and vertices without triangles") {
    requireOracleBytes(Mesh{}, "empty");
    requireOracleBytes(randomMesh(5, 0, {}, 1), "no triangles");
  }
  SECTION("arrays larger than the writers' buffer") {
    // 400k vertices: 17.6 MB of GLB vertex data and well over 4 MiB of every array.
    requireOracleBytes(randomMesh(400000, 700000, {}, 7), "large");
    requireOracleBytes(randomMesh(400000, 700000, {true, false, false}, 8), "large, normals only");
  }
  SECTION("the GLB JSON chunk is tinygltf's JSON") {
    const Mesh m = randomMesh(10, 4, {}, 3);
    std::string bytes, error;
    REQUIRE(oracle::encodeGlb(m, bytes, error));
    uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    std::string json = bytes.substr(20, jsonLength);
    json.erase(json.find_last_not_of(' ') + 1);
    CHECK(io::glbJson(m) == json);
  }
}

TEST_CASE("a mesh file written through the transaction holds encodeMesh's bytes", "[writers]") {
  const fs::path dir = scratchDir("streamed");
  const Mesh m = randomMesh(300000, 500000, {}, 11);
  for (const std::string ext : {".glb", ".obj", ".ply"}) {
    std::string bytes, error;
    REQUIRE(io::encodeMesh(m, ext, bytes, error));
    const fs::path file = dir / ("mesh" + ext);
    REQUIRE(io::writeMesh(m, file.string(), error));
    const std::string written = readFile(file);
    INFO(ext << ": " << firstDifference(written, bytes));
    CHECK(written == bytes);
  }
}

TEST_CASE("OBJ numbers read back as the same 32-bit floats", "[writers]") {
  // Random bit patterns: every exponent, subnormals, signed zeros.
  std::mt19937 rng(5);
  Mesh m = randomMesh(20000, 10, {}, 5);
  for (auto* a : {&m.positions, &m.normals, &m.texcoords})
    for (auto& x : *a) {
      do x = std::bit_cast<float>(uint32_t(rng()));
      while (!std::isfinite(x));
    }
  std::string obj, error;
  REQUIRE(io::encodeMesh(m, ".obj", obj, error));
  std::istringstream in(obj);
  size_t v = 0, vt = 0, vn = 0, mismatches = 0;
  for (std::string line; std::getline(in, line);) {
    if (line[0] != 'v') continue;
    std::vector<float> values;
    for (size_t at = line.find(' '); at != std::string::npos; at = line.find(' ', at + 1)) {
      float x = NAN;
      const auto r = std::from_chars(line.data() + at + 1, line.data() + line.size(), x);
      REQUIRE(r.ec == std::errc());
      values.push_back(x);
    }
    const auto same = [&](const float* want, size_t n) {
      for (size_t d = 0; d < n; ++d) mismatches += std::bit_cast<uint32_t>(values.at(d)) != std::bit_cast<uint32_t>(want[d]);
    };
    if (line.rfind("v ", 0) == 0) {
      REQUIRE(values.size() == 6);
      same(&m.positions[3 * v], 3);
      for (int d = 0; d < 3; ++d) {
        const float c = m.colors[3 * v + d];
        mismatches += values[3 + d] != (std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f);
      }
      ++v;
    } else if (line.rfind("vt ", 0) == 0) {
      same(&m.texcoords[2 * vt++], 2);
    } else if (line.rfind("vn ", 0) == 0) {
      same(&m.normals[3 * vn++], 3);
    }
  }
  CHECK(v == m.vertexCount());
  CHECK(vt == m.vertexCount());
  CHECK(vn == m.vertexCount());
  CHECK(mismatches == 0);
}

TEST_CASE("the byte sink keeps every byte in order across its buffer's edges", "[writers]") {
  std::string out, want;
  {
    io::StringSink sink(out, 4096);  // the smallest buffer, so that runs cross it often
    std::mt19937 rng(9);
    for (int i = 0; i < 3000; ++i) {
      const size_t n = rng() % 3 == 0 ? rng() % 9000 : rng() % 100;
      std::string run(n, '\0');
      for (auto& c : run) c = char(rng());
      if (n <= 4096 && rng() % 2) {  // formatted in place
        char* p = sink.room(n);
        std::memcpy(p, run.data(), n);
        sink.advance(p + n);
      } else {
        sink.append(run);
      }
      want += run;
    }
    REQUIRE(sink.flush());
  }
  CHECK(out == want);
}

TEST_CASE("a mesh write cut short leaves the old file and no temporary", "[writers][outputs]") {
  const fs::path dir = scratchDir("cut_short");
  const Mesh m = randomMesh(100000, 200000, {}, 13);
  // A 1 MiB file size limit: the writers stream, so the limit is met after several
  // buffers went out; write() then fails with EFBIG (SIGXFSZ ignored, as fgsg does).
  struct sigaction ignore {}, previous {};
  ignore.sa_handler = SIG_IGN;
  REQUIRE(::sigaction(SIGXFSZ, &ignore, &previous) == 0);
  rlimit old{};
  REQUIRE(::getrlimit(RLIMIT_FSIZE, &old) == 0);
  rlimit small = old;
  small.rlim_cur = 1 << 20;
  REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
  std::vector<std::string> errors;
  for (const std::string ext : {".glb", ".obj", ".ply"}) {
    const fs::path file = dir / ("old" + ext);
    { std::ofstream(file) << "old"; }
    std::string error;
    errors.push_back(io::writeMesh(m, file.string(), error) ? "written" : error);
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  ::sigaction(SIGXFSZ, &previous, nullptr);
  for (size_t i = 0; i < errors.size(); ++i) {
    const std::string ext = std::vector<std::string>{".glb", ".obj", ".ply"}[i];
    CHECK(errors[i] == "cannot write '" + (dir / ("old" + ext)).string() + "': File too large");
    CHECK(readFile(dir / ("old" + ext)) == "old");
  }
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.path().filename().string().find(".tmp.") == std::string::npos;
  CHECK(files == 3);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 3);

  SECTION("a missing folder is named and nothing is created") {
    std::string error;
    CHECK_FALSE(io::writeMesh(m, (dir / "missing" / "out.glb").string(), error));
    CHECK_THAT(error, Catch::Contains("missing/out.glb': No such file or directory"));
    CHECK_FALSE(fs::exists(dir / "missing"));
  }
}

TEST_CASE("an output's temporary name is told from other files", "[writers][outputs]") {
  using fgsg::rt::io::isOutputTemporary;
  // target + ".tmp." + 8 letters and digits, as createUniqueFile draws them
  CHECK(isOutputTemporary("city.glb.tmp.a1B2c3D4"));
  CHECK(isOutputTemporary("run.obj.tmp.00000000"));
  CHECK(isOutputTemporary("x.tmp.abcdefgh"));
  CHECK_FALSE(isOutputTemporary(".tmp.abcdefgh"));          // no target name
  CHECK_FALSE(isOutputTemporary("city.glb.tmp.a1B2c3D"));   // 7 characters
  CHECK_FALSE(isOutputTemporary("city.glb.tmp.a1B2c3D4e")); // 9 characters
  CHECK_FALSE(isOutputTemporary("city.glb.tmp.a1B2-3D4"));  // not a letter or digit
  CHECK_FALSE(isOutputTemporary("paint.png"));
  CHECK_FALSE(isOutputTemporary("notes.tmp.txt"));
}
