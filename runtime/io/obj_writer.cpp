#include "runtime/io/obj_writer.h"

#include "runtime/io/float_text.h"
#include "runtime/io/mesh_attributes.h"

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>
#include <vector>

namespace fgsg::rt::io {

namespace {

// The longest line: "v" and six floats of at most 15 characters each, or "f" and three
// corners of three 10-digit indices with separators.
constexpr size_t kMaxLine = 128;

char* putFloats(char* p, const float* v, int n) {
  for (int d = 0; d < n; ++d) {
    *p++ = ' ';
    p = putShortestFloat(p, v[d]);
  }
  return p;
}

char* putCorner(char* p, uint64_t index, bool withTexcoords, bool withNormals) {
  char digits[24];
  const size_t n = size_t(std::to_chars(digits, digits + sizeof digits, index).ptr - digits);
  *p++ = ' ';
  std::memcpy(p, digits, n), p += n;
  if (withTexcoords) *p++ = '/', std::memcpy(p, digits, n), p += n;  // v/vt, v/vt/vn
  if (withNormals) {
    *p++ = '/';
    if (!withTexcoords) *p++ = '/';  // v//vn
    std::memcpy(p, digits, n), p += n;
  }
  return p;
}

// Lines [0, count) made by `line(p, i)` (writes line i at p, returns its end), in order
// into `out`. Number formatting is most of an OBJ's cost, so large sections are
// formatted in blocks on all cores while finished blocks are written, in order, by one
// of them; at most a few blocks are held at a time.
template <typename Line>
void putLines(ByteSink& out, size_t count, Line line) {
  constexpr size_t kBlockLines = size_t(16) << 10;
  const size_t tokens = size_t(2) * size_t(tbb::this_task_arena::max_concurrency());
  if (count <= kBlockLines || tokens <= 2) {
    for (size_t i = 0; i < count; ++i) out.advance(line(out.room(kMaxLine), i));
    return;
  }
  struct Block {
    size_t first = 0, bytes = 0;
    std::unique_ptr<char[]> text;
  };
  // Block b uses slot b % tokens: with at most `tokens` blocks live and the output in
  // order, the block that used the slot before has been written.
  std::vector<Block> slots(tokens);
  size_t next = 0;
  tbb::parallel_pipeline(
      tokens,
      tbb::make_filter<void, Block*>(tbb::filter_mode::serial_in_order,
                                     [&](tbb::flow_control& fc) -> Block* {
                                       if (next >= count) {
                                         fc.stop();
                                         return nullptr;
                                       }
                                       Block& b = slots[(next / kBlockLines) % tokens];
                                       b.first = next;
                                       next += kBlockLines;
                                       return &b;
                                     }) &
          tbb::make_filter<Block*, Block*>(tbb::filter_mode::parallel,
                                           [&](Block* b) {
                                             if (!b->text) b->text = std::make_unique_for_overwrite<char[]>(kBlockLines * kMaxLine);
                                             char* p = b->text.get();
                                             const size_t last = std::min(count, b->first + kBlockLines);
                                             for (size_t i = b->first; i < last; ++i) p = line(p, i);
                                             b->bytes = size_t(p - b->text.get());
                                             return b;
                                           }) &
          tbb::make_filter<Block*, void>(tbb::filter_mode::serial_in_order,
                                         [&](Block* b) { out.append(b->text.get(), b->bytes); }));
}

// The material of texture index `texture`: one that names no texture is untextured (mtlText
// defines no material for it).
std::string materialName(const Mesh& mesh, int32_t texture) {
  return texture >= 0 && size_t(texture) < mesh.textures.size() ? "fgsg_texture_" + std::to_string(texture)
                                                                 : "fgsg_plain";
}

}  // namespace

std::string pathFrom(const std::string& folder, const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path relative = fs::relative(path, folder.empty() ? fs::path(".") : fs::path(folder), ec);
  if (!ec && !relative.empty()) return relative.generic_string();
  const fs::path absolute = fs::absolute(path, ec);
  return ec || absolute.empty() ? path : absolute.lexically_normal().generic_string();
}

void writeObj(const Mesh& mesh, ByteSink& out) { writeObj(mesh, out, std::string()); }

void writeObj(const Mesh& mesh, ByteSink& out, const std::string& mtlFileName) {
  const bool colored = hasColors(mesh);
  const bool withNormals = hasNormals(mesh);
  const bool withTexcoords = mesh.hasTexcoords();
  out.append("# fgsg\n");
  if (mesh.textured() && !mtlFileName.empty()) out.append("mtllib " + mtlFileName + "\n");
  putLines(out, mesh.vertexCount(), [&](char* p, size_t v) {
    *p++ = 'v';
    p = putFloats(p, &mesh.positions[3 * v], 3);
    if (colored) {
      const float rgb[3] = {clamp01(mesh.colors[3 * v]), clamp01(mesh.colors[3 * v + 1]),
                            clamp01(mesh.colors[3 * v + 2])};
      p = putFloats(p, rgb, 3);
    }
    *p++ = '\n';
    return p;
  });
  if (withTexcoords)
    putLines(out, mesh.vertexCount(), [&](char* p, size_t v) {
      *p++ = 'v', *p++ = 't';
      p = putFloats(p, &mesh.texcoords[2 * v], 2);
      *p++ = '\n';
      return p;
    });
  if (withNormals)
    putLines(out, mesh.vertexCount(), [&](char* p, size_t v) {
      *p++ = 'v', *p++ = 'n';
      p = putFloats(p, &mesh.normals[3 * v], 3);
      *p++ = '\n';
      return p;
    });
  const auto face = [&](char* p, size_t t) {
    *p++ = 'f';
    for (int k = 0; k < 3; ++k)
      p = putCorner(p, uint64_t(mesh.indices[3 * t + k]) + 1, withTexcoords, withNormals);  // OBJ counts from 1
    *p++ = '\n';
    return p;
  };
  // Line segments ("l a b") after the faces.
  const auto segments = [&] {
    putLines(out, mesh.lineCount(), [&](char* p, size_t l) {
      *p++ = 'l';
      for (int k = 0; k < 2; ++k) {
        *p++ = ' ';
        p = std::to_chars(p, p + 24, uint64_t(mesh.lines[2 * l + k]) + 1).ptr;
      }
      *p++ = '\n';
      return p;
    });
  };
  if (!mesh.textured()) {
    putLines(out, mesh.triangleCount(), face);
    segments();
    return;
  }
  // Run by run, each after its material (a run going on with the previous one's material
  // needs no usemtl). Every triangle goes out once and in order even if the runs break
  // Mesh's rules: the first run starts at triangle 0, each next one where the previous
  // one ended, and the last one ends at the last triangle.
  const size_t triangles = mesh.triangleCount();
  std::string current;
  size_t begin = 0;
  for (size_t r = 0; r < mesh.textureRuns.size(); ++r) {
    const size_t end =
        r + 1 == mesh.textureRuns.size() ? triangles : std::clamp<size_t>(mesh.runEnd(r), begin, triangles);
    if (end == begin) continue;
    const std::string material = materialName(mesh, mesh.textureRuns[r].texture);
    if (material != current) out.append("usemtl " + material + "\n"), current = material;
    putLines(out, end - begin, [&](char* p, size_t i) { return face(p, begin + i); });
    begin = end;
  }
  if (mesh.lineCount() && !current.empty() && current != "fgsg_plain") out.append("usemtl fgsg_plain\n");
  segments();
}

std::string mtlText(const Mesh& mesh, const std::string& mtlFolder) {
  std::string text = "# fgsg\n";
  // White: a face's colour is its image's, times its vertex colours where a reader applies them.
  const auto material = [&](const std::string& name) {
    text += "\nnewmtl " + name + "\nKd 1 1 1\nKa 0 0 0\nKs 0 0 0\nd 1\nillum 1\n";
  };
  material("fgsg_plain");
  for (size_t k = 0; k < mesh.textures.size(); ++k) {
    material(materialName(mesh, int32_t(k)));
    text += "map_Kd " + pathFrom(mtlFolder, mesh.textures[k]) + "\n";
  }
  return text;
}

}  // namespace fgsg::rt::io
