// libFuzzer target: the formats read through assimp (glTF .gltf/.glb, FBX, COLLADA, and
// OBJ or PLY with texture coordinates) behind the surface loader, with the pre-checks
// that bound what assimp expands (io/check_gltf.h, io/check_collada.h, io/check_fbx.h).
// The format is guessed from the content as a misnamed file would be read: "glTF" magic
// -> .glb, '{' -> .gltf, '<' -> .dae, "Kaydara FBX Binary" or "; FBX" -> .fbx, "ply" ->
// .ply, anything else -> .obj (assimp then reads those with `vt` lines). Findings:
// crashes, sanitizer reports, uncaught exceptions, an allocation past -malloc_limit_mb
// (the memory limit given to the reader is 256 MiB), a failure without a message naming
// the file, and a loaded surface that breaks its own invariants.
#include "runtime/surface/load_surface.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_assimp finding: %s\n", what.c_str());
  std::abort();
}

const char* guessExtension(std::string_view bytes) {
  if (bytes.substr(0, 4) == "glTF") return ".glb";
  if (bytes.substr(0, 18) == "Kaydara FBX Binary") return ".fbx";
  const size_t p = bytes.find_first_not_of(" \t\r\n");
  const std::string_view head = p == std::string_view::npos ? "" : bytes.substr(p, 16);
  if (head.substr(0, 1) == "{") return ".gltf";
  if (head.substr(0, 1) == "<") return ".dae";
  if (head.substr(0, 5) == "; FBX") return ".fbx";
  if (head.substr(0, 3) == "ply") return ".ply";
  return ".obj";
}

std::string scratchFolder() {
  char name[] = "/dev/shm/fgsg-fuzz-assimp-XXXXXX";
  if (!mkdtemp(name)) finding("cannot create a scratch folder in /dev/shm");
  return name;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg::rt::surface;
  if (size > 16384) return -1;  // long inputs only slow the search down
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);

  static const std::string folder = scratchFolder();
  const std::string path = folder + "/input" + guessExtension(bytes);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) finding("cannot write " + path);
  }
  SurfaceMesh mesh;
  std::string error;
  SurfaceLoadOptions options;
  options.repair = size > 0 && (data[size - 1] & 1);
  options.maxMemoryBytes = uint64_t(256) << 20;
  SurfaceRepairReport report;
  const bool ok = loadSurface(path, mesh, error, options, &report);
  if (!ok) {
    if (error.empty()) finding("the load failed without a message");
    if (error.rfind(path, 0) != 0) finding("a message that does not name the file: " + error);
    return 0;
  }
  if (mesh.faces.empty()) finding("a surface without faces loaded");
  const int n = static_cast<int>(mesh.vertices.size());
  for (const auto& f : mesh.faces)
    for (int v : f)
      if (v < 0 || v >= n) finding("a loaded face refers to vertex " + std::to_string(v));
  if (!mesh.textureUV.empty() && mesh.textureUV.size() != mesh.faces.size())
    finding("texture coordinates for " + std::to_string(mesh.textureUV.size()) + " of " +
            std::to_string(mesh.faces.size()) + " faces");
  std::vector<std::string> problems;
  if (!validateSurface(mesh, problems)) finding("a loaded surface fails validation: " + problems.front());
  return 0;
}
