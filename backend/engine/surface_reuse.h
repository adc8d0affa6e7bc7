// A surface kept from one derivation for the next (#49): fgsg view derives the same
// compiled grammar with the same values again whenever a page moves a seed or paints a
// texture, and loading the surface, designing its fields and laying it out for marching
// took most of each such derivation (a second for the bunny). While a SurfaceReuseScope
// is alive on a thread, the derivations begun there take the surface from its
// SurfaceReuse (built and left there by the first). The caller starts a fresh one whenever
// anything the surface depends on may have changed: the grammar, its attributes, its seed.
#pragma once

#include <memory>
#include <mutex>

namespace fgsg::rt::marching {
class MarchingSurface;
}

namespace fgsg::backend {

class SurfaceWorld;
class SurfaceGeometryCache;

struct SurfaceReuse {
  std::mutex mutex;
  std::shared_ptr<const SurfaceWorld> world;
  std::shared_ptr<const rt::marching::MarchingSurface> marching;
  // Outlives this reuse (fgsg view keeps it across recompiles): a world built afresh takes
  // its mesh, frames and factorisation from here when they are the same (surface_geometry.h).
  SurfaceGeometryCache* geometries = nullptr;
};

class SurfaceReuseScope {
 public:
  explicit SurfaceReuseScope(SurfaceReuse& reuse);
  ~SurfaceReuseScope();
  SurfaceReuseScope(const SurfaceReuseScope&) = delete;
  SurfaceReuseScope& operator=(const SurfaceReuseScope&) = delete;
  // The reuse in effect on this thread, or null.
  static SurfaceReuse* current();

 private:
  SurfaceReuse* previous_;
};

}  // namespace fgsg::backend
