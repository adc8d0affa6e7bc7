// PLY, binary little endian: per vertex x y z, then nx ny nz, u v (v up) and red green
// blue (uchar, the clamped colour times 255, rounded) when the mesh has them; per face a
// count byte 3 and three uint32 indices. Records are interleaved into the sink's buffer.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/mesh.h"

namespace fgsg::rt::io {

// The whole file into `out`; the caller checks out.ok().
void writePly(const Mesh& mesh, ByteSink& out);

}  // namespace fgsg::rt::io
