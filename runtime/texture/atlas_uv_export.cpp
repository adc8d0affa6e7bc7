#include "runtime/texture/atlas_uv_export.h"

#include "runtime/io/atomic_file.h"

#include <charconv>
#include <map>
#include <utility>

namespace fgsg::rt::texture {

namespace {

void putNumber(std::string& out, double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  out.append(text, end);
}

}  // namespace

std::string atlasUvObj(const marching::MarchingSurface& surface) {
  const auto& mesh = surface.mesh();
  std::string out = "# fgsg atlas --export-uv: the surface with the texture coordinates its contexts are read at\n";
  for (const Vec3& p : mesh.vertices) {
    out += "v ";
    putNumber(out, p.x());
    out += ' ';
    putNumber(out, p.y());
    out += ' ';
    putNumber(out, p.z());
    out += '\n';
  }
  // One vt per (vertex, coordinate): corners inside a chart share it, seams split it.
  std::map<std::pair<int, std::pair<double, double>>, size_t> vtOf;
  std::vector<std::array<size_t, 3>> faceVt(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      Vec3 corner = Vec3::Zero();
      corner[k] = 1;
      const atlas::Vec2 uv = surface.texCoord({int(f), corner});
      const auto [at, added] = vtOf.emplace(std::pair{mesh.faces[f][k], std::pair{uv.x(), uv.y()}}, vtOf.size() + 1);
      if (added) {
        out += "vt ";
        putNumber(out, uv.x());
        out += ' ';
        putNumber(out, uv.y());
        out += '\n';
      }
      faceVt[f][k] = at->second;
    }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    out += 'f';
    for (int k = 0; k < 3; ++k)
      out += ' ' + std::to_string(mesh.faces[f][k] + 1) + '/' + std::to_string(faceVt[f][k]);
    out += '\n';
  }
  return out;
}

bool writeAtlasUvObj(const marching::MarchingSurface& surface, const std::string& path, std::string& error) {
  return io::writeFileAtomically(path, atlasUvObj(surface), error);
}

}  // namespace fgsg::rt::texture
