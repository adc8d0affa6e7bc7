// The disk cache of prepared marching surfaces: an atlas and its geometry image's texels
// (ImageTexels; the rest is derived on reading), under a key made from everything they
// depend on. A file is written whole or not at all (io/atomic_file.h), and read back
// only when its header, key, length, checksum and every value agree with the mesh: a
// truncated, corrupt or foreign file is refused with the reason, and the caller builds
// the surface again.
#pragma once

#include "runtime/marching/marching_surface.h"

#include <cstdint>
#include <memory>
#include <string>

namespace fgsg::rt::marching {

// Bump when the format, the rasterization, the pointers or the atlas builders change:
// older files then miss (their key differs) instead of being read as current.
constexpr uint32_t kImageCacheVersion = 1;

// 32 hex digits from the mesh's vertices, faces and texture coordinates (bit for bit),
// options.resolution and kImageCacheVersion; options.cacheDir is left out (where a file
// is kept does not change what it holds).
std::string imageCacheKey(const surface::SurfaceMesh& mesh, const MarchingOptions& options);

// DIR/marching-KEY.fgsgimage
std::string imageCachePath(const std::string& cacheDir, const std::string& key);

// Writes `surface`'s atlas and image under `key` to `path`, creating its folder. False
// with a message when the file cannot be written (the target is then untouched).
bool writeImageCache(const std::string& path, const std::string& key, const MarchingSurface& surface,
                     std::string& error);

// The surface stored at `path` for `mesh` under `key`, or null with `why` it was not
// usable (missing, another key or version, truncated, corrupt, inconsistent).
std::shared_ptr<const MarchingSurface> readImageCache(const std::string& path, const std::string& key,
                                                      const surface::SurfaceMesh& mesh,
                                                      const MarchingOptions& options, std::string& why);

}  // namespace fgsg::rt::marching
