#include "runtime/io/write_mesh.h"

#include "runtime/io/glb_writer.h"
#include "runtime/io/obj_writer.h"
#include "runtime/io/output_transaction.h"
#include "runtime/io/ply_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <system_error>

namespace fgsg::rt::io {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

const std::vector<std::string>& knownExtensions() {
  static const std::vector<std::string> exts = {".glb", ".obj", ".ply"};
  return exts;
}

bool findNonFiniteVertex(const Mesh& mesh, std::string& error) {
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    if (std::isfinite(mesh.positions[i])) continue;
    const size_t v = i / 3;
    error = "vertex " + std::to_string(v) + " is not finite (" + std::to_string(mesh.positions[3 * v]) + ", " +
            std::to_string(mesh.positions[3 * v + 1]) + ", " + std::to_string(mesh.positions[3 * v + 2]) +
            "): mesh files store 32-bit floats, up to about 3.4e38";
    return true;
  }
  for (size_t i = 0; mesh.hasTexcoords() && i < mesh.texcoords.size(); ++i)
    if (!std::isfinite(mesh.texcoords[i])) {
      error = "the texture coordinate of vertex " + std::to_string(i / 2) + " is not finite";
      return true;
    }
  return false;
}

// What can be checked before a byte is written: a format for the extension (`ext`, lower
// case) and vertices a 32-bit float file can hold.
bool checkEncodable(const Mesh& mesh, const std::string& extension, std::string& ext, std::string& error) {
  ext = lower(extension);
  if (std::find(knownExtensions().begin(), knownExtensions().end(), ext) == knownExtensions().end()) {
    std::string list;
    for (const auto& e : knownExtensions()) list += (list.empty() ? "" : ", ") + e;
    error = (extension.empty() ? std::string("no file extension to choose a mesh format by")
                               : "unsupported mesh format '" + extension + "'") +
            " (supported: " + list + ")";
    return false;
  }
  return !findNonFiniteVertex(mesh, error);
}

// Streams the mesh as `ext` (checked) into `out`, an OBJ naming `mtlFileName` as its
// materials file (none when empty); the caller checks out.ok() for the writes themselves.
bool encodeInto(const Mesh& mesh, const std::string& ext, ByteSink& out, std::string& error,
                const std::string& mtlFileName = std::string()) {
  try {
    if (ext == ".glb") return writeGlb(mesh, out, error);
    if (ext == ".obj") writeObj(mesh, out, mtlFileName);
    if (ext == ".ply") writePly(mesh, out);
    return true;
  } catch (const std::bad_alloc&) {
    error = "out of memory while encoding " + std::to_string(mesh.triangleCount()) + " triangles";
    return false;
  } catch (const std::length_error&) {
    error = "the encoded mesh would be too large (" + std::to_string(mesh.triangleCount()) + " triangles)";
    return false;
  }
}

}  // namespace

const std::vector<std::string>& supportedMeshExtensions() { return knownExtensions(); }

bool encodeMesh(const Mesh& mesh, const std::string& extension, ByteSink& out, std::string& error) {
  std::string ext;
  if (!checkEncodable(mesh, extension, ext, error) || !encodeInto(mesh, ext, out, error)) return false;
  if (out.flush()) return true;
  error = "cannot write the encoded mesh";
  return false;
}

bool encodeMesh(const Mesh& mesh, const std::string& extension, std::string& bytes,
                std::string& error) {
  bytes.clear();
  bool ok = false;
  try {
    StringSink sink(bytes);
    ok = encodeMesh(mesh, extension, sink, error);
  } catch (const std::bad_alloc&) {  // the string outgrew memory
    error = "out of memory while encoding " + std::to_string(mesh.triangleCount()) + " triangles";
  } catch (const std::length_error&) {
    error = "the encoded mesh would be too large (" + std::to_string(mesh.triangleCount()) + " triangles)";
  }
  if (!ok) bytes.clear();
  return ok;
}

bool stageMesh(const Mesh& mesh, const std::string& path, OutputTransaction& outputs, std::string& error) {
  std::string ext;
  if (!checkEncodable(mesh, std::filesystem::path(path).extension().string(), ext, error)) {
    error = "cannot write '" + path + "': " + error;
    return false;
  }
  // A textured OBJ's materials go beside it in their own file, staged first so that commit
  // renames it first: a new OBJ never appears without the materials it names.
  std::string mtlFileName;
  if (ext == ".obj" && mesh.textured()) {
    const std::filesystem::path mtlPath = std::filesystem::path(path).replace_extension(".mtl");
    std::error_code ec;
    const std::filesystem::path mtlFolder = std::filesystem::absolute(mtlPath, ec).parent_path();
    mtlFileName = mtlPath.filename().string();
    if (!outputs.stage(mtlPath.string(), mtlText(mesh, mtlFolder.string()), error)) return false;
  }
  // Straight into the temporary file: no copy of the encoded mesh is held in memory.
  const auto encode = [&](ByteSink& out, std::string& encodeError) {
    return encodeInto(mesh, ext, out, encodeError, mtlFileName);
  };
  return outputs.stage(path, encode, error);
}

bool writeMesh(const Mesh& mesh, const std::string& path, std::string& error) {
  OutputTransaction one;
  return stageMesh(mesh, path, one, error) && one.commit(error);
}

}  // namespace fgsg::rt::io
