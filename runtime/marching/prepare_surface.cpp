// MarchingSurface::prepare: which atlas a surface gets (its own texture coordinates when
// it has them, else a generated one) and the disk cache in front of building it.
#include "runtime/atlas/atlas.h"
#include "runtime/marching/image_cache.h"
#include "runtime/marching/marching_surface.h"

#include <chrono>

namespace fgsg::rt::marching {

std::shared_ptr<const MarchingSurface> MarchingSurface::prepare(const surface::SurfaceMesh& mesh,
                                                                const MarchingOptions& options, std::string& error,
                                                                PrepareStats* stats) {
  PrepareStats local;
  PrepareStats& s = stats ? *stats : local;
  s = PrepareStats{};
  s.meshUV = !mesh.textureUV.empty();
  std::string key, path;
  if (!options.cacheDir.empty()) {
    key = imageCacheKey(mesh, options);
    path = imageCachePath(options.cacheDir, key);
    std::string why;  // a missing or damaged file is simply built again
    if (auto cached = readImageCache(path, key, mesh, options, why)) {
      s.fromCache = true;
      s.charts = cached->atlas().chartCount;
      return cached;
    }
  }
  atlas::AtlasOptions layout;
  layout.resolution = options.resolution;
  atlas::Atlas a;
  const auto started = std::chrono::steady_clock::now();
  const bool laidOut = s.meshUV ? atlas::atlasFromTextureUV(mesh, layout, a, error)
                                : atlas::buildAtlas(mesh, layout, a, error);
  if (!laidOut) return nullptr;
  s.atlasSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  auto surface = fromAtlas(mesh, a, options, error, &s);
  if (!surface) return nullptr;
  s.charts = a.chartCount;
  if (!path.empty()) {
    std::string ignored;  // a cache that cannot be written costs the next run time, nothing else
    writeImageCache(path, key, *surface, ignored);
  }
  return surface;
}

}  // namespace fgsg::rt::marching
