#include "runtime/io/obj_writer.h"

#include "runtime/io/mesh_attributes.h"

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace fgsg::rt::io {

namespace {

// The longest line: "v" and six floats of at most 15 characters each, or "f" and three
// corners of three 10-digit indices with separators.
constexpr size_t kMaxLine = 128;

char* putFloats(char* p, const float* v, int n) {
  for (int d = 0; d < n; ++d) {
    *p++ = ' ';
    p = std::to_chars(p, p + 16, v[d]).ptr;
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

}  // namespace

void writeObj(const Mesh& mesh, ByteSink& out) {
  const bool colored = hasColors(mesh);
  const bool withNormals = hasNormals(mesh);
  const bool withTexcoords = mesh.hasTexcoords();
  out.append("# fgsg\n");
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
  putLines(out, mesh.triangleCount(), [&](char* p, size_t t) {
    *p++ = 'f';
    for (int k = 0; k < 3; ++k)
      p = putCorner(p, uint64_t(mesh.indices[3 * t + k]) + 1, withTexcoords, withNormals);  // OBJ counts from 1
    *p++ = '\n';
    return p;
  });
}

}  // namespace fgsg::rt::io
