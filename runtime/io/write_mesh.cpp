#include "runtime/io/write_mesh.h"

#include "runtime/io/output_transaction.h"

// Debian links the tinygltf implementation as a shared library: only the declarations here.
#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <new>
#include <span>
#include <sstream>
#include <stdexcept>

namespace fgsg::rt::io {

namespace {

static_assert(std::endian::native == std::endian::little,
              "the GLB and PLY encoders copy little-endian values byte for byte");

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

bool encodeKnownFormat(const Mesh& mesh, const std::string& ext, const std::string& extension,
                       std::string& bytes, std::string& error) {
  if (ext == ".glb") return encodeGlb(mesh, bytes, error);
  if (ext == ".obj") {
    bytes = encodeObj(mesh);
    return true;
  }
  if (ext == ".ply") {
    bytes = encodePly(mesh);
    return true;
  }
  std::string list;
  for (const auto& e : knownExtensions()) list += (list.empty() ? "" : ", ") + e;
  error = (extension.empty() ? std::string("no file extension to choose a mesh format by")
                             : "unsupported mesh format '" + extension + "'") +
          " (supported: " + list + ")";
  return false;
}

}  // namespace

const std::vector<std::string>& supportedMeshExtensions() { return knownExtensions(); }

bool encodeMesh(const Mesh& mesh, const std::string& extension, std::string& bytes,
                std::string& error) {
  const std::string ext = lower(extension);
  if (std::find(supportedMeshExtensions().begin(), supportedMeshExtensions().end(), ext) !=
          supportedMeshExtensions().end() &&
      findNonFiniteVertex(mesh, error))
    return false;
  try {
    return encodeKnownFormat(mesh, ext, extension, bytes, error);
  } catch (const std::bad_alloc&) {
    bytes.clear();
    error = "out of memory while encoding " + std::to_string(mesh.triangleCount()) + " triangles";
    return false;
  } catch (const std::length_error&) {
    bytes.clear();
    error = "the encoded mesh would be too large (" + std::to_string(mesh.triangleCount()) + " triangles)";
    return false;
  }
}

bool stageMesh(const Mesh& mesh, const std::string& path, OutputTransaction& outputs, std::string& error) {
  std::string bytes;
  if (!encodeMesh(mesh, std::filesystem::path(path).extension().string(), bytes, error)) {
    error = "cannot write '" + path + "': " + error;
    return false;
  }
  return outputs.stage(path, bytes, error);
}

bool writeMesh(const Mesh& mesh, const std::string& path, std::string& error) {
  OutputTransaction one;
  return stageMesh(mesh, path, one, error) && one.commit(error);
}

}  // namespace fgsg::rt::io
