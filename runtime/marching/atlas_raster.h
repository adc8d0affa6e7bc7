// Which face covers each texel of a geometry image. A texel belongs to the face whose
// image triangle holds its centre; failing that (conservative rasterization, so that a
// chart thinner than a texel is not lost) to the closest face whose triangle overlaps the
// texel's square — unless that would put the texel next to another chart's texel, since
// the band of indirection texels between charts (§4) must survive.
#pragma once

#include "runtime/marching/image_triangles.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt::marching {

struct AtlasRaster {
  std::vector<int32_t> face;        // per texel (x + y * size, y up): the covering face or -1
  size_t conservativeTexels = 0;    // covered although their centre lies in no triangle
};

// Texel (x, y) covers [x, x+1] x [y, y+1] in image units. Ties between faces holding a
// centre on their shared edge go to the lower face number, so the result does not
// depend on thread scheduling.
AtlasRaster rasterizeAtlas(const std::vector<ImageTriangle>& triangles, int size);

}  // namespace fgsg::rt::marching
