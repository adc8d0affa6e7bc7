// Output files: atomic writes, mesh writers (round-tripped through OpenMesh, GLB parsed
// and checked by the Khronos validator) and the instance JSON.
#include "runtime/assemble.h"
#include "runtime/float_range.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/output_transaction.h"
#include "runtime/io/write_instances.h"
#include "runtime/io/write_mesh.h"

// OpenMesh requires its IO header before the mesh kernel.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <catch2/catch.hpp>

#include "scratch_files.h"
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace fgsg::rt;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) { return fgsg::test::scratchDir("writers", name); }
using fgsg::test::readFile;

// Two coloured cubes and a flattened one: sharp normals, several colours, 28 triangles.
Mesh sampleMesh() {
  InstanceList list;
  list.assets = {"cube"};
  const auto place = [&](std::array<double, 3> s, std::array<double, 3> t, std::array<float, 3> c) {
    Instance inst;
    inst.transform = {s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, t[0], t[1], t[2], 1};
    inst.color = c;
    list.instances.push_back(inst);
  };
  place({1, 1, 1}, {0, 0, 0}, {1, 0, 0});
  place({0.5, 2, 1}, {2, 0.25, -1}, {0.1f, 0.6f, 0.3f});
  place({3, 3, 0}, {-1, -1, -0.5}, {0.8f, 0.8f, 0.8f});
  AssetLibrary lib;
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(resolveAssets(list, lib, meshOf, error));
  return assembleInstances(list, lib, meshOf);
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

void checkReadBack(const Mesh& m, const fs::path& file, bool colorsAsBytes) {
  OMesh om;
  om.request_vertex_normals();
  om.request_vertex_colors();
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::VertexNormal | OpenMesh::IO::Options::VertexColor;
  REQUIRE(OpenMesh::IO::read_mesh(om, file.string(), opt));
  REQUIRE(om.n_vertices() == m.vertexCount());
  REQUIRE(om.n_faces() == m.triangleCount());
  CHECK(opt.check(OpenMesh::IO::Options::VertexNormal));
  CHECK(opt.check(OpenMesh::IO::Options::VertexColor));
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const auto vh = om.vertex_handle(int(v));
    for (int d = 0; d < 3; ++d) {
      CHECK(om.point(vh)[d] == m.positions[3 * v + d]);  // exact: shortest round-trip text
      CHECK(om.normal(vh)[d] == Approx(m.normals[3 * v + d]).margin(1e-6));
      const double expected = colorsAsBytes ? std::lround(m.colors[3 * v + d] * 255.0f) : m.colors[3 * v + d] * 255.0;
      CHECK(om.color(vh)[d] == Approx(expected).margin(colorsAsBytes ? 0 : 0.5));
    }
  }
  size_t t = 0;
  for (auto f : om.faces()) {
    std::vector<uint32_t> vs;
    for (auto v : f.vertices()) vs.push_back(uint32_t(v.idx()));
    // OpenMesh may start a face at another corner; the cyclic order must match.
    const uint32_t* want = &m.indices[3 * t++];
    const auto at = std::find(vs.begin(), vs.end(), want[0]) - vs.begin();
    CHECK(vs[at % 3] == want[0]);
    CHECK(vs[(at + 1) % 3] == want[1]);
    CHECK(vs[(at + 2) % 3] == want[2]);
  }
}

struct Glb {
  uint32_t magic = 0, version = 0, length = 0;
  nlohmann::json json;
  std::string bin;
};

Glb parseGlb(const std::string& bytes) {
  Glb g;
  REQUIRE(bytes.size() >= 20);
  std::memcpy(&g.magic, bytes.data(), 4);
  std::memcpy(&g.version, bytes.data() + 4, 4);
  std::memcpy(&g.length, bytes.data() + 8, 4);
  uint32_t jsonLength = 0, jsonType = 0;
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  std::memcpy(&jsonType, bytes.data() + 16, 4);
  REQUIRE(jsonType == 0x4E4F534Au);  // "JSON"
  REQUIRE(jsonLength % 4 == 0);
  g.json = nlohmann::json::parse(bytes.substr(20, jsonLength));
  const size_t binAt = 20 + jsonLength;
  if (binAt < bytes.size()) {
    uint32_t binLength = 0, binType = 0;
    std::memcpy(&binLength, bytes.data() + binAt, 4);
    std::memcpy(&binType, bytes.data() + binAt + 4, 4);
    REQUIRE(binType == 0x004E4942u);  // "BIN\0"
    g.bin = bytes.substr(binAt + 8, binLength);
  }
  return g;
}

// Runs the Khronos glTF validator; there is no silent skip when it is missing.
void requireValidGltf(const fs::path& file) {
  const fs::path root = FGSG_SOURCE_DIR;
  const fs::path validator = root / "tools/node/node_modules/gltf-validator";
  if (!fs::exists(validator))
    FAIL("the glTF validator is not installed: run scripts/install-node-packages.sh (it installs "
         "gltf-validator into tools/node/)");
  const fs::path report = file.string() + ".report.txt";
  const std::string cmd = "node '" + (root / "scripts/validate-gltf.js").string() + "' --strict '" +
                          file.string() + "' > '" + report.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  INFO(readFile(report));
  CHECK(rc == 0);
  CHECK_THAT(readFile(report), Catch::Contains(": 0 errors, 0 warnings"));
}

}  // namespace

TEST_CASE("atomic writes replace the whole file or nothing", "[writers]") {
  const fs::path dir = scratchDir("atomic");
  std::string error;

  SECTION("a new file, then a replacement, and no temporary left over") {
    REQUIRE(io::writeFileAtomically((dir / "out.txt").string(), "first", error));
    REQUIRE(io::writeFileAtomically((dir / "out.txt").string(), "second", error));
    CHECK(readFile(dir / "out.txt") == "second");
    CHECK(filesIn(dir) == std::vector<std::string>{"out.txt"});
  }
  SECTION("a missing directory is an error and leaves no file") {
    const fs::path target = dir / "no_such_dir" / "out.glb";
    CHECK_FALSE(io::writeFileAtomically(target.string(), "bytes", error));
    CHECK_THAT(error, Catch::Contains("no_such_dir/out.glb"));
    CHECK_THAT(error, Catch::Contains("No such file or directory"));
    CHECK_FALSE(fs::exists(target));
    CHECK(filesIn(dir).empty());
  }
  SECTION("a failed rename removes the temporary and keeps the target") {
    fs::create_directories(dir / "taken" / "child");  // a non-empty directory cannot be replaced
    CHECK_FALSE(io::writeFileAtomically((dir / "taken").string(), "bytes", error));
    CHECK_THAT(error, Catch::Contains("cannot replace"));
    CHECK_THAT(error, Catch::Contains("Is a directory"));
    CHECK(filesIn(dir) == std::vector<std::string>{"taken"});
    CHECK(fs::is_directory(dir / "taken" / "child"));
  }
}

TEST_CASE("mesh writers choose the format by extension", "[writers]") {
  const fs::path dir = scratchDir("ext");
  const Mesh m = sampleMesh();
  std::string error;
  CHECK_FALSE(io::writeMesh(m, (dir / "out.stl").string(), error));
  CHECK_THAT(error, Catch::Contains("unsupported mesh format '.stl'"));
  CHECK_THAT(error, Catch::Contains(".glb, .obj, .ply"));
  CHECK_FALSE(io::writeMesh(m, (dir / "out").string(), error));
  CHECK_THAT(error, Catch::Contains("no file extension"));
  CHECK(filesIn(dir).empty());
  CHECK(io::writeMesh(m, (dir / "UPPER.OBJ").string(), error));
}

TEST_CASE("OBJ and PLY read back identically with OpenMesh", "[writers]") {
  const fs::path dir = scratchDir("roundtrip");
  const Mesh m = sampleMesh();
  REQUIRE(m.triangleCount() == 28);
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "out.obj").string(), error));
  REQUIRE(io::writeMesh(m, (dir / "out.ply").string(), error));
  checkReadBack(m, dir / "out.obj", false);
  checkReadBack(m, dir / "out.ply", true);

  const std::string obj = readFile(dir / "out.obj");
  CHECK_THAT(obj, Catch::Contains("\nvn 0 0 1\n"));
  CHECK_THAT(obj, Catch::Contains("\nf 1//1 2//2 3//3\n"));
  const std::string ply = readFile(dir / "out.ply");
  CHECK(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  const size_t header = ply.find("end_header\n") + 11;
  // x y z nx ny nz as float, r g b as uchar; faces: a count byte and three uint32.
  CHECK(ply.size() == header + m.vertexCount() * 27 + m.triangleCount() * 13);
}

TEST_CASE("GLB has the expected layout and passes the glTF validator", "[writers][gltf]") {
  const fs::path dir = scratchDir("glb");
  const Mesh m = sampleMesh();
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "out.glb").string(), error));
  const std::string bytes = readFile(dir / "out.glb");
  const Glb g = parseGlb(bytes);
  CHECK(g.magic == 0x46546C67u);  // "glTF"
  CHECK(g.version == 2);
  CHECK(g.length == bytes.size());
  const auto& j = g.json;
  CHECK(j["asset"]["version"] == "2.0");
  CHECK(j["asset"]["generator"] == "fgsg");
  REQUIRE(j["meshes"].size() == 1);
  REQUIRE(j["meshes"][0]["primitives"].size() == 1);
  const auto& prim = j["meshes"][0]["primitives"][0];
  const auto& acc = j["accessors"];
  const auto& pos = acc[prim["attributes"]["POSITION"].get<int>()];
  CHECK(pos["count"] == m.vertexCount());
  CHECK(pos["componentType"] == 5126);
  const auto lo = m.boundsMin(), hi = m.boundsMax();
  for (int d = 0; d < 3; ++d) {
    CHECK(pos["min"][d].get<double>() == lo[d]);
    CHECK(pos["max"][d].get<double>() == hi[d]);
  }
  CHECK(acc[prim["attributes"]["NORMAL"].get<int>()]["count"] == m.vertexCount());
  const auto& color = acc[prim["attributes"]["COLOR_0"].get<int>()];
  CHECK(color["count"] == m.vertexCount());
  CHECK(color["type"] == "VEC3");
  CHECK(color["componentType"] == 5126);
  const auto& idx = acc[prim["indices"].get<int>()];
  CHECK(idx["count"] == m.indices.size());
  CHECK(idx["componentType"] == 5125);
  CHECK(j["materials"][0]["doubleSided"] == true);
  CHECK(j["buffers"][0]["byteLength"] == m.vertexCount() * 36 + m.indices.size() * 4);
  CHECK(g.bin.size() == m.vertexCount() * 36 + m.indices.size() * 4);
  // The index data is stored verbatim at the end of the buffer.
  CHECK(std::memcmp(g.bin.data() + m.vertexCount() * 36, m.indices.data(), m.indices.size() * 4) == 0);
  requireValidGltf(dir / "out.glb");
}

TEST_CASE("an empty mesh still gives valid files", "[writers][gltf]") {
  const fs::path dir = scratchDir("empty");
  const Mesh empty;
  std::string error;
  for (const char* name : {"empty.glb", "empty.obj", "empty.ply"}) REQUIRE(io::writeMesh(empty, (dir / name).string(), error));
  const Glb g = parseGlb(readFile(dir / "empty.glb"));
  CHECK_FALSE(g.json.contains("meshes"));
  CHECK(g.json["scenes"].size() == 1);
  requireValidGltf(dir / "empty.glb");
  CHECK_THAT(readFile(dir / "empty.ply"), Catch::Contains("element vertex 0\n"));
  CHECK_THAT(readFile(dir / "empty.ply"), Catch::Contains("element face 0\n"));
}

TEST_CASE("mesh bytes are deterministic", "[writers]") {
  const Mesh a = sampleMesh(), b = sampleMesh();
  for (const char* ext : {".glb", ".obj", ".ply"}) {
    std::string x, y, error;
    REQUIRE(io::encodeMesh(a, ext, x, error));
    REQUIRE(io::encodeMesh(b, ext, y, error));
    CHECK(x == y);
  }
}

TEST_CASE("instance JSON is exact and parses back", "[writers]") {
  InstanceList list;
  list.assets = {"torus", "wall.obj"};
  list.symbols = {"B", "say \"hi\"\\\n"};
  list.params = {1.5, 0.1, 1.0 / 3.0};
  Instance a;
  a.asset = 0;
  a.symbol = 1;
  a.transform = {0.1, 0, 0, 0, 0, 1.0 / 3.0, 0, 0, 0, 0, 1e-300, 0, 1e20, -2.5, 3, 1};
  a.firstParam = 0;
  a.paramCount = 3;
  Instance b;
  b.asset = 1;
  b.color = {1.0f, 0.5f, 0.0f};
  list.instances = {a, b};

  const std::string text = io::encodeInstancesJson(list);
  CHECK(text == io::encodeInstancesJson(list));
  const auto j = nlohmann::json::parse(text);
  CHECK(j["format"] == "fgsg-instances");
  CHECK(j["version"] == 1);
  CHECK(j["assets"] == nlohmann::json({"torus", "wall.obj"}));
  CHECK(j["symbols"][1] == "say \"hi\"\\\n");
  REQUIRE(j["instances"].size() == 2);
  const auto& i0 = j["instances"][0];
  CHECK(i0["asset"] == "torus");
  CHECK(i0["symbol"] == "say \"hi\"\\\n");
  for (int k = 0; k < 16; ++k) CHECK(i0["transform"][k].get<double>() == a.transform[k]);  // exact
  for (int k = 0; k < 3; ++k) CHECK(i0["params"][k].get<double>() == list.params[k]);
  CHECK(i0["color"][0].get<float>() == 0.8f);
  CHECK_THAT(text, Catch::Contains("\"color\":[0.8,0.8,0.8]"));  // floats print as floats
  CHECK(j["instances"][1]["params"].empty());
  CHECK(j["instances"][1]["asset"] == "wall.obj");

  const fs::path dir = scratchDir("json");
  std::string error;
  REQUIRE(io::writeInstancesJson(list, (dir / "out.json").string(), error));
  CHECK(readFile(dir / "out.json") == text);
  CHECK_FALSE(io::writeInstancesJson(list, (dir / "missing" / "out.json").string(), error));
  CHECK(filesIn(dir) == std::vector<std::string>{"out.json"});
}

// ---- output safety: temporaries, transactions, what may reach a file -------------------

TEST_CASE("a link planted at the old predictable temp name is never written through", "[writers][outputs]") {
  const fs::path dir = scratchDir("planted_link");
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "precious";
  // Before: every writer used PATH.tmp.<pid>, opened with O_TRUNC and following links.
  const fs::path target = dir / "out.glb";
  fs::create_symlink(victim, target.string() + ".tmp." + std::to_string(::getpid()));
  std::string error;
  REQUIRE(io::writeMesh(sampleMesh(), target.string(), error));
  CHECK(readFile(victim) == "precious");
  CHECK(fs::is_symlink(target.string() + ".tmp." + std::to_string(::getpid())));
  CHECK(fs::is_regular_file(fs::symlink_status(target)));
  CHECK(filesIn(dir).size() == 3);  // the victim, the planted link, the output: no temporary
}

TEST_CASE("temporaries are new files with random names, created exclusively", "[writers][outputs]") {
  const fs::path dir = scratchDir("unique");
  std::string a, b;
  const int fa = io::createUniqueFile((dir / "x.tmp.").string(), a);
  const int fb = io::createUniqueFile((dir / "x.tmp.").string(), b);
  REQUIRE(fa >= 0);
  REQUIRE(fb >= 0);
  ::close(fa);
  ::close(fb);
  CHECK(a != b);
  CHECK(a.size() == (dir / "x.tmp.").string().size() + 8);
  std::string error;
  CHECK_FALSE(io::createUniqueFile((dir / "missing" / "x.tmp.").string(), a) >= 0);
}

TEST_CASE("a transaction replaces all its files or none", "[writers][outputs]") {
  const fs::path dir = scratchDir("transaction");
  std::ofstream(dir / "mesh.obj") << "old mesh";
  std::string error;
  SECTION("one output that cannot be written keeps the others' old contents") {
    {
      io::OutputTransaction outputs;
      REQUIRE(io::stageMesh(sampleMesh(), (dir / "mesh.obj").string(), outputs, error));
      CHECK_FALSE(outputs.stage((dir / "missing" / "instances.json").string(), "{}", error));
      CHECK_THAT(error, Catch::Contains("missing/instances.json"));
    }  // dropped without commit
    CHECK(readFile(dir / "mesh.obj") == "old mesh");
    CHECK(filesIn(dir) == std::vector<std::string>{"mesh.obj"});
  }
  SECTION("a folder in the way is found when staging, before anything is replaced") {
    fs::create_directories(dir / "busy.json");
    io::OutputTransaction outputs;
    REQUIRE(outputs.stage((dir / "mesh.obj").string(), "new mesh", error));
    CHECK_FALSE(outputs.stage((dir / "busy.json").string(), "{}", error));
    CHECK_THAT(error, Catch::Contains("Is a directory"));
    outputs.abandon();
    CHECK(readFile(dir / "mesh.obj") == "old mesh");
    CHECK(filesIn(dir) == std::vector<std::string>{"busy.json", "mesh.obj"});
  }
  SECTION("all staged: commit replaces every file") {
    io::OutputTransaction outputs;
    REQUIRE(outputs.stage((dir / "mesh.obj").string(), "new mesh", error));
    REQUIRE(outputs.stage((dir / "instances.json").string(), "{}", error));
    CHECK(readFile(dir / "mesh.obj") == "old mesh");  // nothing replaced before commit
    REQUIRE(outputs.commit(error));
    CHECK(readFile(dir / "mesh.obj") == "new mesh");
    CHECK(readFile(dir / "instances.json") == "{}");
    CHECK(filesIn(dir) == std::vector<std::string>{"instances.json", "mesh.obj"});
  }
}

TEST_CASE("threads writing the same path all succeed and leave one whole result", "[writers][outputs]") {
  const fs::path dir = scratchDir("threads");
  const std::string target = (dir / "same.txt").string();
  constexpr int kThreads = 8;
  std::vector<std::string> contents;
  for (int t = 0; t < kThreads; ++t) contents.push_back(std::string(100000 + t, char('a' + t)));
  std::vector<int> ok(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 20; ++round) {
        std::string error;
        ok[t] += io::writeFileAtomically(target, contents[t], error);
        std::string distinct;
        ok[t] += io::writeFileAtomically((dir / ("own" + std::to_string(t))).string(), contents[t], distinct);
      }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) CHECK(ok[t] == 40);
  const std::string final = readFile(target);
  CHECK(std::find(contents.begin(), contents.end(), final) != contents.end());
  for (int t = 0; t < kThreads; ++t) CHECK(readFile(dir / ("own" + std::to_string(t))) == contents[t]);
  CHECK(filesIn(dir).size() == kThreads + 1);
}

TEST_CASE("non-finite vertices and transforms never reach a file", "[writers][outputs]") {
  const fs::path dir = scratchDir("non_finite");
  Mesh m = sampleMesh();
  m.positions[4] = INFINITY;
  std::string bytes, error;
  for (const char* ext : {".glb", ".obj", ".ply"}) {
    CHECK_FALSE(io::encodeMesh(m, ext, bytes, error));
    CHECK_THAT(error, Catch::Contains("vertex 1 is not finite"));
  }
  std::ofstream(dir / "old.glb") << "old";
  CHECK_FALSE(io::writeMesh(m, (dir / "old.glb").string(), error));
  CHECK_THAT(error, Catch::Contains("old.glb"));
  CHECK(readFile(dir / "old.glb") == "old");

  InstanceList list;
  list.assets = {"cube"};
  list.symbols = {"A", "B"};
  Instance fine, huge;
  fine.transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  huge = fine;
  huge.symbol = 1;
  huge.transform[12] = -INFINITY;
  list.instances = {fine, huge};
  CHECK_FALSE(io::writeInstancesJson(list, (dir / "i.json").string(), error));
  CHECK_THAT(error, Catch::Contains("instance 1 (symbol 'B')"));
  CHECK(filesIn(dir) == std::vector<std::string>{"old.glb"});
}

TEST_CASE("an instance whose vertices would overflow a float is detected", "[writers][outputs]") {
  Mat4 t = Mat4::Identity();
  CHECK(unitBoxFitsFloat(t));
  t(0, 0) = 1e38;
  CHECK(unitBoxFitsFloat(t));
  t(0, 3) = 3e38;  // 1e38 + 3e38 is past FLT_MAX
  CHECK_FALSE(unitBoxFitsFloat(t));
  CHECK(unitBoxReach(t) == Approx(4e38));
  t(0, 3) = NAN;
  CHECK_FALSE(unitBoxFitsFloat(t));
  CHECK_FALSE(unitBoxClearlyFitsFloat(t));
  t(0, 3) = 0;
  t(1, 2) = NAN;  // in the linear part
  CHECK_FALSE(unitBoxFitsFloat(t));
  CHECK_FALSE(unitBoxClearlyFitsFloat(t));
}

TEST_CASE("the quick float-range bound agrees with the corners", "[writers][outputs]") {
  // Random affine maps over many scales: whenever the quick test passes, the exact reach
  // (over the eight corners) is within float range, and the bound is the reach itself.
  uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1.0p-53;
  };
  int clear = 0, unclear = 0;
  for (int i = 0; i < 20000; ++i) {
    Mat4 t = Mat4::Identity();
    const double scale = std::pow(10.0, 10 * next() + 29);  // 1e29 .. 1e39, around the limit
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) t(r, c) = (2 * next() - 1) * scale;
    if (unitBoxClearlyFitsFloat(t)) {
      ++clear;
      REQUIRE(unitBoxReach(t) < 0.5000001 * double(FLT_MAX));
    } else {
      ++unclear;
      CHECK(unitBoxReach(t) >= 0.4999999 * double(FLT_MAX));
    }
  }
  CHECK(clear > 1000);
  CHECK(unclear > 1000);
}

// ---- texture coordinates -----------------------------------------------------------------

namespace {

// OpenMesh reads a written file's texture coordinates back at the vertices they were
// written for.
void checkTexcoordsReadBack(const fs::path& file, const Mesh& m) {
  OMesh om;
  om.request_vertex_texcoords2D();
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::VertexTexCoord;
  REQUIRE(OpenMesh::IO::read_mesh(om, file.string(), opt));
  REQUIRE(opt.check(OpenMesh::IO::Options::VertexTexCoord));
  REQUIRE(om.n_vertices() == m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const auto t = om.texcoord2D(om.vertex_handle(int(v)));
    CHECK(t[0] == m.texcoords[2 * v]);
    CHECK(t[1] == m.texcoords[2 * v + 1]);
  }
}

// Bark, a leaf and a cube (which has no texture coordinates: it gets (0, 0)).
Mesh texturedMesh() {
  InstanceList list;
  list.assets = {"bark", "leaf", "cube"};
  for (uint32_t a = 0; a < 3; ++a) {
    Instance inst;
    inst.asset = a;
    inst.transform = {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0.5, 0, 1.5 * a, 0, 0, 1};
    list.instances.push_back(inst);
  }
  AssetLibrary lib;
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(resolveAssets(list, lib, meshOf, error));
  Mesh m = assembleInstances(list, lib, meshOf);
  REQUIRE(m.hasTexcoords());
  return m;
}

std::vector<std::string> linesStartingWith(const std::string& text, const std::string& prefix) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) lines.push_back(line);
  return lines;
}

}  // namespace

TEST_CASE("GLB carries texture coordinates as TEXCOORD_0 with v flipped and validates",
          "[writers][gltf][texcoords]") {
  const fs::path dir = scratchDir("glb_uv");
  const Mesh m = texturedMesh();
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "uv.glb").string(), error));
  const Glb g = parseGlb(readFile(dir / "uv.glb"));
  const auto& prim = g.json["meshes"][0]["primitives"][0];
  REQUIRE(prim["attributes"].contains("TEXCOORD_0"));
  const auto& uv = g.json["accessors"][prim["attributes"]["TEXCOORD_0"].get<int>()];
  CHECK(uv["type"] == "VEC2");
  CHECK(uv["componentType"] == 5126);
  REQUIRE(uv["count"] == m.vertexCount());
  const auto& view = g.json["bufferViews"][uv["bufferView"].get<int>()];
  REQUIRE(view["byteLength"] == m.vertexCount() * 8);
  std::vector<float> stored(2 * m.vertexCount());
  std::memcpy(stored.data(), g.bin.data() + view.value("byteOffset", 0) + uv.value("byteOffset", 0),
              stored.size() * sizeof(float));
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    CHECK(stored[2 * v] == m.texcoords[2 * v]);
    CHECK(stored[2 * v + 1] == 1.0f - m.texcoords[2 * v + 1]);  // glTF's v runs down
  }
  CHECK(g.bin.size() == m.vertexCount() * 44 + m.indices.size() * 4);
  requireValidGltf(dir / "uv.glb");
}

TEST_CASE("GLB textures repeat and filter linearly with mipmaps", "[writers][gltf][texcoords]") {
  // A facade tiles its bricks: coordinates past 1 must wrap (REPEAT, 10497), not stretch
  // the edge texels (CLAMP_TO_EDGE, 33071, which the validator accepts as well).
  const fs::path dir = scratchDir("glb_sampler");
  Mesh m = texturedMesh();
  m.textures = {(fs::path(FGSG_SOURCE_DIR) / "examples/textures/brick.png").string()};
  m.addTextureRun(0, 0);
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "tiled.glb").string(), error));
  const Glb g = parseGlb(readFile(dir / "tiled.glb"));
  REQUIRE(g.json["samplers"].size() == 1);
  const auto& sampler = g.json["samplers"][0];
  CHECK(sampler["wrapS"] == 10497);
  CHECK(sampler["wrapT"] == 10497);
  CHECK(sampler["magFilter"] == 9729);  // LINEAR
  CHECK(sampler["minFilter"] == 9987);  // LINEAR_MIPMAP_LINEAR
  REQUIRE(g.json["textures"].size() == 1);
  CHECK(g.json["textures"][0]["sampler"] == 0);
  CHECK(g.json["textures"][0]["source"] == 0);
  const int material = g.json["meshes"][0]["primitives"][0]["material"].get<int>();
  CHECK(g.json["materials"][material]["pbrMetallicRoughness"]["baseColorTexture"]["index"] == 0);
  requireValidGltf(dir / "tiled.glb");
}

TEST_CASE("OBJ writes vt lines and v/vt/vn corners", "[writers][texcoords]") {
  const fs::path dir = scratchDir("obj_uv");
  const Mesh m = texturedMesh();
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "uv.obj").string(), error));
  const std::string obj = readFile(dir / "uv.obj");
  const auto vt = linesStartingWith(obj, "vt ");
  REQUIRE(vt.size() == m.vertexCount());
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    std::istringstream line(vt[v].substr(3));
    float u = -1, tv = -1;
    line >> u >> tv;
    CHECK(u == m.texcoords[2 * v]);  // exact: shortest round-trip text
    CHECK(tv == m.texcoords[2 * v + 1]);
  }
  const auto f = linesStartingWith(obj, "f ");
  REQUIRE(f.size() == m.triangleCount());
  const auto corner = [](uint32_t i) {
    const std::string n = std::to_string(i + 1);
    return n + "/" + n + "/" + n;
  };
  CHECK(f[0] == "f " + corner(m.indices[0]) + " " + corner(m.indices[1]) + " " + corner(m.indices[2]));
  checkTexcoordsReadBack(dir / "uv.obj", m);
}

TEST_CASE("PLY writes u v per vertex", "[writers][texcoords]") {
  const fs::path dir = scratchDir("ply_uv");
  const Mesh m = texturedMesh();
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "uv.ply").string(), error));
  const std::string ply = readFile(dir / "uv.ply");
  CHECK_THAT(ply, Catch::Contains("property float nz\nproperty float u\nproperty float v\n"
                                  "property uchar red\n"));
  const size_t header = ply.find("end_header\n") + 11;
  CHECK(ply.size() == header + m.vertexCount() * 35 + m.triangleCount() * 13);
  checkTexcoordsReadBack(dir / "uv.ply", m);
}

TEST_CASE("meshes without texture coordinates write none", "[writers][texcoords]") {
  const Mesh m = sampleMesh();
  REQUIRE(m.texcoords.empty());
  std::string glb, obj, ply, error;
  REQUIRE(io::encodeMesh(m, ".glb", glb, error));
  REQUIRE(io::encodeMesh(m, ".obj", obj, error));
  REQUIRE(io::encodeMesh(m, ".ply", ply, error));
  CHECK_FALSE(parseGlb(glb).json["meshes"][0]["primitives"][0]["attributes"].contains("TEXCOORD_0"));
  CHECK(linesStartingWith(obj, "vt").empty());
  CHECK_THAT(ply, !Catch::Contains("property float u\n"));
  // A texture coordinate that is not finite never reaches a file.
  Mesh bad = texturedMesh();
  bad.texcoords[7] = NAN;
  for (const char* ext : {".glb", ".obj", ".ply"}) {
    CHECK_FALSE(io::encodeMesh(bad, ext, glb, error));
    CHECK_THAT(error, Catch::Contains("texture coordinate of vertex 3 is not finite"));
  }
}

namespace {

// Two cubes and three lines (asset "line", turtle segments "lines"): one from (5, 0, 0) 2
// long along Y, one turned to run along X from (0, 4, 0), and one scaled to no length
// (dropped by the assembler).
Mesh meshWithLines() {
  InstanceList list;
  list.assets = {"cube", "line"};
  const auto place = [&](uint32_t asset, std::array<double, 16> t) {
    Instance inst;
    inst.asset = asset;
    inst.transform = t;
    inst.color = {0.2f, 0.4f, 0.6f};
    list.instances.push_back(inst);
  };
  place(0, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  place(1, {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1});
  place(1, {0, -1, 0, 0, 3, 0, 0, 0, 0, 0, 1, 0, 0, 4, 0, 1});  // Y turned onto X
  place(1, {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 9, 9, 9, 1});   // no length
  place(0, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1});
  AssetLibrary lib;
  std::vector<int> meshOf;
  std::string error;
  REQUIRE(resolveAssets(list, lib, meshOf, error));
  return assembleInstances(list, lib, meshOf);
}

std::array<float, 3> vertexAt(const Mesh& m, uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

}  // namespace

TEST_CASE("line segments are assembled in instance order and zero-length ones dropped", "[writers][lines]") {
  const Mesh m = meshWithLines();
  REQUIRE(m.lineCount() == 2);
  CHECK(m.triangleCount() == 24);
  CHECK(m.vertexCount() == 24 + 24 + 4);
  CHECK(vertexAt(m, m.lines[0]) == std::array<float, 3>{5, 0, 0});
  CHECK(vertexAt(m, m.lines[1]) == std::array<float, 3>{5, 2, 0});
  CHECK(vertexAt(m, m.lines[2]) == std::array<float, 3>{0, 4, 0});
  CHECK(vertexAt(m, m.lines[3]) == std::array<float, 3>{3, 4, 0});
  // The second cube's vertices come after the lines' (list order).
  CHECK(*std::max_element(m.indices.begin(), m.indices.end()) == m.vertexCount() - 1);
  CHECK(m.lines[0] == 24);
}

TEST_CASE("GLB writes line segments as a LINES primitive and validates", "[writers][lines][gltf]") {
  const fs::path dir = scratchDir("glb_lines");
  const Mesh m = meshWithLines();
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "lines.glb").string(), error));
  const Glb g = parseGlb(readFile(dir / "lines.glb"));
  const auto& prims = g.json["meshes"][0]["primitives"];
  REQUIRE(prims.size() == 2);
  CHECK(prims[0]["mode"] == 4);
  CHECK(prims[1]["mode"] == 1);
  CHECK(prims[1]["attributes"] == prims[0]["attributes"]);
  const auto& acc = g.json["accessors"][prims[1]["indices"].get<int>()];
  CHECK(acc["count"] == 4);
  // The line indices are the last bytes of the BIN chunk.
  REQUIRE(g.bin.size() >= 16);
  CHECK(std::memcmp(g.bin.data() + g.bin.size() - 16, m.lines.data(), 16) == 0);
  requireValidGltf(dir / "lines.glb");

  Mesh linesOnly;
  linesOnly.positions = m.positions;
  linesOnly.normals = m.normals;
  linesOnly.colors = m.colors;
  linesOnly.lines = m.lines;
  REQUIRE(io::writeMesh(linesOnly, (dir / "only.glb").string(), error));
  const Glb only = parseGlb(readFile(dir / "only.glb"));
  REQUIRE(only.json["meshes"][0]["primitives"].size() == 1);
  CHECK(only.json["meshes"][0]["primitives"][0]["mode"] == 1);
  requireValidGltf(dir / "only.glb");
}

TEST_CASE("OBJ writes l lines and PLY an edge element", "[writers][lines]") {
  const fs::path dir = scratchDir("obj_ply_lines");
  const Mesh m = meshWithLines();
  std::string error;
  REQUIRE(io::writeMesh(m, (dir / "lines.obj").string(), error));
  REQUIRE(io::writeMesh(m, (dir / "lines.ply").string(), error));
  const std::string obj = readFile(dir / "lines.obj");
  CHECK_THAT(obj, Catch::EndsWith("\nl 25 26\nl 27 28\n"));  // after the faces, counted from 1
  const std::string ply = readFile(dir / "lines.ply");
  CHECK_THAT(ply, Catch::Contains("property list uchar uint vertex_indices\nelement edge 2\n"
                                  "property uint vertex1\nproperty uint vertex2\nend_header\n"));
  const size_t header = ply.find("end_header\n") + 11;
  REQUIRE(ply.size() == header + m.vertexCount() * 27 + m.triangleCount() * 13 + 2 * 8);
  CHECK(std::memcmp(ply.data() + ply.size() - 16, m.lines.data(), 16) == 0);
  checkReadBack(m, dir / "lines.ply", true);  // OpenMesh still reads the triangles
}
