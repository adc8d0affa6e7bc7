// libFuzzer target: the surface loader (OpenMesh's OFF/PLY/STL/OBJ readers behind our
// importer, validation, repair, topology) on arbitrary files. The format is guessed from
// the content, as a user's misnamed file would be read: "ply" -> .ply, a first word
// ending in OFF -> .off, "v"/"f"/"#" lines -> .obj, anything else -> .stl (binary STL
// takes any 84+ bytes). Findings: crashes, sanitizer reports, uncaught exceptions, a
// failure without a message, and a loaded surface that breaks its own invariants.
#include "runtime/surface/load_surface.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>
#include <string_view>
#include <unistd.h>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_mesh finding: %s\n", what.c_str());
  std::abort();
}

const char* guessExtension(std::string_view bytes) {
  size_t p = bytes.find_first_not_of(" \t\r\n");
  const std::string_view head = p == std::string_view::npos ? "" : bytes.substr(p, 16);
  const std::string_view word = head.substr(0, head.find_first_of(" \t\r\n"));
  if (word == "ply") return ".ply";
  if (word.size() >= 3 && word.size() <= 6 && word.substr(word.size() - 3) == "OFF") return ".off";
  if (word == "v" || word == "f" || word == "#" || word == "vn" || word == "o") return ".obj";
  return ".stl";
}

std::string scratchFolder() {
  char name[] = "/dev/shm/fgsg-fuzz-mesh-XXXXXX";
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
  SurfaceRepairReport report;
  const bool ok = loadSurface(path, mesh, error, options, &report);
  if (!ok) {
    if (error.empty()) finding("the load failed without a message");
    return 0;
  }
  if (mesh.faces.empty()) finding("a surface without faces loaded");
  const int n = static_cast<int>(mesh.vertices.size());
  for (const auto& f : mesh.faces)
    for (int v : f)
      if (v < 0 || v >= n) finding("a loaded face refers to vertex " + std::to_string(v));
  std::vector<std::string> problems;
  if (!validateSurface(mesh, problems)) finding("a loaded surface fails validation: " + problems.front());
  return 0;
}
