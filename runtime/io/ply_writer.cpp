#include "runtime/io/ply_writer.h"

#include "runtime/io/mesh_attributes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace fgsg::rt::io {

static_assert(std::endian::native == std::endian::little, "PLY records copy little-endian values byte for byte");

void writePly(const Mesh& mesh, ByteSink& out) {
  const bool colored = hasColors(mesh);
  const bool withNormals = hasNormals(mesh);
  const bool withTexcoords = mesh.hasTexcoords();
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment fgsg\n";
  header += "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
  header += "property float x\nproperty float y\nproperty float z\n";
  if (withNormals) header += "property float nx\nproperty float ny\nproperty float nz\n";
  if (withTexcoords) header += "property float u\nproperty float v\n";  // v up
  if (colored) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  header += "element face " + std::to_string(mesh.triangleCount()) + "\n";
  header += "property list uchar uint vertex_indices\n";
  // Line segments as PLY's edge element (Blender's importer reads them as loose edges).
  if (mesh.lineCount())
    header += "element edge " + std::to_string(mesh.lineCount()) + "\nproperty uint vertex1\nproperty uint vertex2\n";
  header += "end_header\n";
  out.append(header);

  const size_t vertexBytes = 12 + (withNormals ? 12 : 0) + (withTexcoords ? 8 : 0) + (colored ? 3 : 0);
  // Records go into the buffer in batches: one room() check per batch, not per value.
  const size_t batch = std::min<size_t>(4096, out.bufferSize() / vertexBytes);
  for (size_t first = 0; first < mesh.vertexCount(); first += batch) {
    const size_t n = std::min(batch, mesh.vertexCount() - first);
    char* p = out.room(n * vertexBytes);
    for (size_t v = first; v < first + n; ++v) {
      std::memcpy(p, &mesh.positions[3 * v], 12), p += 12;
      if (withNormals) std::memcpy(p, &mesh.normals[3 * v], 12), p += 12;
      if (withTexcoords) std::memcpy(p, &mesh.texcoords[2 * v], 8), p += 8;
      if (colored)
        for (int d = 0; d < 3; ++d) *p++ = char((unsigned char)std::lround(clamp01(mesh.colors[3 * v + d]) * 255.0f));
    }
    out.advance(p);
  }
  const size_t faceBatch = std::min<size_t>(4096, out.bufferSize() / 13);
  for (size_t first = 0; first < mesh.triangleCount(); first += faceBatch) {
    const size_t n = std::min(faceBatch, mesh.triangleCount() - first);
    char* p = out.room(n * 13);
    for (size_t t = first; t < first + n; ++t) {
      *p++ = 3;
      std::memcpy(p, &mesh.indices[3 * t], 12), p += 12;
    }
    out.advance(p);
  }
  out.append(mesh.lines.data(), mesh.lines.size() * sizeof(uint32_t));
}

}  // namespace fgsg::rt::io
